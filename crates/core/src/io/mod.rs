//! glTF 2.0 import, export and inspection; STL and OBJ export.
//!
//! [`import_gltf`] reads .glb and .gltf files (with their .bin and images given alongside)
//! into models, sketches and point clouds, defensively: every problem is a [`GltfError`]
//! sentence, nothing panics and nothing is fetched. [`write_glb`] writes one node per model
//! (positions, normals, indices, materials), sketches as line strips and point clouds as
//! points; control curves and sketches also go in node `extras` under `"sketchmesh"`
//! (documented in `docs/gltf-extras.md`), so nothing the user drew is lost and a file written
//! here imports with its curves editable. A model's key frames go out as morph targets
//! with a weights animation (`animation_write.rs`) and come back as key frames.
//! [`inspect_gltf`] reports a file's topology.
//!
//! [`write_stl`] (binary STL, for printing) and [`write_obj`] (OBJ and its MTL) write the
//! whole document or one model ([`ExportScope`]) in a [`crate::unit::Unit`]; they refuse
//! with an [`ExportError`] sentence when there is nothing to write.
//!
//! This module reads and writes the data types of [`crate::model`] and knows nothing of
//! editing: the `document` layer above calls it (the `import` op), never the other way round.
//!
//! Inside, the files point one way: `input.rs` (what the importer is given), `error.rs` and
//! `extras.rs` (the `"sketchmesh"` JSON) are used by the readers `parse.rs`, `resources.rs`,
//! `accessor.rs`, `scene.rs` and `weld.rs`, which `import.rs` (with `curves.rs`) and `info.rs`
//! drive; `glb.rs` (the container being written) is filled by `appearance_write.rs`,
//! `animation_write.rs` and `gltf_write.rs`. `stl.rs` and `obj.rs` share `export.rs` (which
//! models) and `export_error.rs`.

mod accessor;
mod animation_read;
mod animation_write;
mod appearance_write;
mod curves;
mod error;
mod export;
mod export_error;
mod extras;
mod glb;
mod gltf_write;
mod import;
mod info;
mod input;
mod obj;
mod parse;
mod resources;
mod scene;
mod stl;
mod transfer;
mod weld;

pub use error::GltfError;
pub use export::ExportScope;
pub use export_error::ExportError;
pub use extras::EXTRAS_VERSION;
pub use gltf_write::write_glb;
pub use import::{Imported, import_gltf};
pub use info::{Info, inspect_gltf};
pub use input::{ImportFile, ImportLimits};
pub use obj::{ObjFiles, write_obj};
pub use resources::referenced_files;
pub use stl::write_stl;
pub use transfer::{
    Previewed, TransferError, TransferSource, UncheckedImport, decode_changed, decode_imported,
    decode_imported_unchecked, decode_models, decode_moved, encode_changed, encode_imported,
    encode_models, encode_moved,
};

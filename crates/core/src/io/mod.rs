//! glTF 2.0 binary (.glb) export and inspection.
//!
//! [`write_glb`] writes one node per model (positions, normals, indices, one PBR material)
//! and one node holding every sketch as a line strip; control curves and sketches also go in
//! node `extras` under `"sketchmesh"` (documented in `docs/gltf-extras.md`), so nothing the
//! user drew is lost. [`inspect_glb`] reads a .glb (or .gltf JSON with embedded `data:` URIs)
//! and reports the topology of its triangles.

mod extras;
mod gltf_read;
mod gltf_write;
mod info;

pub use extras::EXTRAS_VERSION;
pub use gltf_read::GltfError;
pub use gltf_write::write_glb;
pub use info::{Info, inspect_glb};

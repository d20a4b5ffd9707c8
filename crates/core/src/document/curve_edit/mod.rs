//! FiberMesh curve editing on a document's models (Nealen's thesis §3.2.1–3.2.4): pull,
//! add, erase, type change and rub, and the operations that change a shape's topology and
//! leave curves behind (cut, tunnel, extrude, merge), each one undoable op.
//!
//! The algorithms live in [`crate::fibermesh`] and [`crate::mesh::remesh`]; this module
//! picks the model and the curves an op acts on, and settles the surface afterwards. Every
//! op recomputes its result from the op alone (the stroke, viewport and camera), so
//! `sketchmesh replay` reproduces it exactly; the app's live previews (see [`PullPreview`])
//! only show where the committed result will land.
//!
//! After an op the surface is re-optimized with a fresh factorization: the thesis remeshes
//! "after every sketch operation and on mouse release after a pull", so adding a curve and
//! pulling also remesh (curves stay edge chains). Erase, type change and rub keep the
//! topology: they change constraints only, and remeshing would move vertices the user did
//! not touch.

mod add;
mod constraints;
mod cut;
mod extrude;
mod merge;
mod oversketch;
mod pull;
mod settle;
mod shared;
mod tidy;
mod tunnel;

pub use add::add_curve_op;
pub use constraints::{curve_type_toggle, erase_op, rub_op, set_curve_type_op};
pub use cut::cut_op;
pub use extrude::extrude_op;
pub use merge::merge_op;
pub(super) use oversketch::oversketch_curve;
pub(super) use pull::PullPreview;
pub use pull::pull_op;
pub(super) use settle::remesh_only;
pub use shared::CURVE_PICK_RADIUS_PX;
pub(crate) use shared::screen_stroke;
pub(in crate::document) use shared::with_splits;
pub use tunnel::tunnel_op;

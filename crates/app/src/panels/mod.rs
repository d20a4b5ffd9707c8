//! Panels around the 3D view: the toolbar, the help window, the notes and the fall-off;
//! the curve handles drawn over it.

pub mod curve_handles;
pub mod falloff;
pub mod help;
pub mod notes;
pub mod toolbar;

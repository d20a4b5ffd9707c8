//! Panels around the 3D view: the toolbar, the help window, the notes, the fall-off, a
//! model's context menu and the progress line; the curve handles drawn over it.

pub mod context_menu;
pub mod curve_handles;
pub mod falloff;
pub mod help;
pub mod notes;
pub mod progress;
pub mod toolbar;

//! Panels around the 3D view: the toolbar, the help window, the notes and the fall-off.

pub mod falloff;
pub mod help;
pub mod notes;
pub mod toolbar;

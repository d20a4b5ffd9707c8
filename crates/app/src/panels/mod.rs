//! Panels around the 3D view: the toolbar, the help window and the notes.

pub mod help;
pub mod notes;
pub mod toolbar;

//! Panels around the 3D view: the toolbar, the help window, the notes, the fall-off, a
//! model's context menu and the progress line.

pub mod context_menu;
pub mod falloff;
pub mod help;
pub mod notes;
pub mod progress;
pub mod toolbar;

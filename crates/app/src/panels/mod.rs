//! Panels around the 3D view: the toolbar and the help window.

pub mod help;
pub mod toolbar;

//! Panels around the 3D view: the toolbar and its tools' buttons, the help window, the notes, the fall-off, a
//! model's context menu and the progress line.

pub mod context_menu;
pub mod falloff;
pub mod help;
pub mod intro;
pub mod notes;
pub mod progress;
pub mod readout;
pub mod tool_button;
pub mod toolbar;

/// The panels' state kept between frames.
#[derive(Default)]
pub struct PanelState {
    /// A model's context actions, open after a long press on it.
    pub context_menu: Option<context_menu::ContextMenu>,
    /// The fall-off panel's painted disc.
    pub falloff: falloff::FalloffPanel,
    /// Whether the help window is open.
    pub show_help: bool,
    /// The first visit's introduction.
    pub intro: intro::Intro,
}

//! What the user can ask of the app from the toolbar or the keyboard.

use egui::Key;

use crate::tools::{Mode, ToolOutput};

/// One thing the user asked for.
#[derive(Debug)]
pub enum Command {
    /// Undo the last operation.
    Undo,
    /// Redo the last undone operation.
    Redo,
    /// Frame everything.
    FrameAll,
    /// Back to the default view.
    ResetView,
    /// Keep the document and start an empty one.
    NewDocument,
    /// Show the documents kept in this browser.
    Documents,
    /// Pick glTF files to import.
    Import,
    /// Download the document as .glb.
    Export,
    /// Download the session as .sketchmesh.json.
    SaveSession,
    /// Switch to a tool.
    Mode(Mode),
    /// The active tool's panel asked for this.
    Tool(Box<ToolOutput>),
    /// Stop what runs: an import being read, an op computed, a replay, the gesture (Esc).
    Stop,
    /// A key the tool of this mode takes (see [`crate::tools::Tool::keys`]).
    ToolKey(Mode, Key),
    /// Show the wireframe, or stop.
    ToggleWireframe,
    /// Show the grid, or stop.
    ToggleGrid,
    /// Turn the Symmetry switch on or off (see [`crate::shared::SymmetrySwitch`]).
    ToggleSymmetry,
    /// Show the help, or close it.
    ToggleHelp,
}

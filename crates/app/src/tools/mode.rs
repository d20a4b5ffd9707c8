//! The tool modes: FiberMesh's five tools (sketch, deform, erase, type change, rub;
//! thesis §3.2), over-sketch, feature sketching, region editing, curve handles, optimize and moving
//! models, with their
//! toolbar labels and keys.

use egui::Key;

/// Which tool pointer gestures go to.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Mode {
    /// Draw shapes (closed strokes on empty canvas), curves on shapes, and ink.
    #[default]
    Sketch,
    /// Grab a control curve and drag it; the shape follows.
    Pull,
    /// Drag along control curves to remove them.
    Erase,
    /// Drag along control curves to switch them between smooth and sharp.
    CurveType,
    /// Rub back and forth near a control curve to smooth it.
    Rub,
    /// Redraw part of a model's outline.
    Oversketch,
    /// Better triangles or less noise on a model (Laplacian mesh optimization).
    Optimize,
    /// Sketch a ridge, bump, flattening or suggestive contours onto a model.
    Feature,
    /// Move a region drawn around a reference curve, with a fall-off (Bujans).
    Region,
    /// Curve handles and skeletons on any model or point cloud (Blanco).
    Handles,
    /// Bend by a control curve keeping the volume, and key poses (Zhou et al.).
    Pose,
    /// Select a model and move, turn or scale it; delete or duplicate it.
    Move,
}

impl Mode {
    /// Every mode, in toolbar order.
    pub const ALL: [Mode; 12] = [
        Mode::Sketch,
        Mode::Pull,
        Mode::Erase,
        Mode::CurveType,
        Mode::Rub,
        Mode::Oversketch,
        Mode::Feature,
        Mode::Region,
        Mode::Handles,
        Mode::Pose,
        Mode::Optimize,
        Mode::Move,
    ];

    /// The toolbar label.
    pub fn label(self) -> &'static str {
        match self {
            Mode::Sketch => "Sketch",
            Mode::Pull => "Pull",
            Mode::Erase => "Erase",
            Mode::CurveType => "Sharp",
            Mode::Rub => "Rub",
            Mode::Oversketch => "Over-sketch",
            Mode::Optimize => "Optimize",
            Mode::Feature => "Feature",
            Mode::Region => "Region",
            Mode::Handles => "Bend",
            Mode::Pose => "Pose",
            Mode::Move => "Move",
        }
    }

    /// The toolbar icon, shown before the label where the row has room: a glyph of the
    /// tool-icon font (`crate::fonts`; a test checks it is there).
    pub fn icon(self) -> &'static str {
        match self {
            Mode::Sketch => "✏",
            Mode::Pull => "✋",
            Mode::Erase => "✖",
            Mode::CurveType => "♦",
            Mode::Rub => "〰",
            Mode::Oversketch => "✒",
            Mode::Optimize => "✨",
            Mode::Feature => "🗻",
            Mode::Region => "⭕",
            Mode::Handles => "⤴",
            Mode::Pose => "🏃",
            Mode::Move => "↔",
        }
    }

    /// The key that selects it (without modifiers).
    pub fn key(self) -> Key {
        match self {
            Mode::Sketch => Key::S,
            Mode::Pull => Key::P,
            Mode::Erase => Key::E,
            Mode::CurveType => Key::T,
            Mode::Rub => Key::U,
            Mode::Oversketch => Key::O,
            Mode::Optimize => Key::M,
            Mode::Feature => Key::D,
            Mode::Region => Key::L,
            Mode::Handles => Key::J,
            Mode::Pose => Key::Q,
            Mode::Move => Key::V,
        }
    }

    /// What it does, for tooltips and the help window.
    pub fn hint(self) -> &'static str {
        match self {
            Mode::Sketch => {
                "Closed outline on empty canvas: a shape. On a shape: a curve (closed ones and strokes across a shape: tap to confirm)."
            }
            Mode::Pull => "Grab a control curve and drag it; the shape follows",
            Mode::Erase => "Drag along control curves to remove them",
            Mode::CurveType => "Drag along control curves to switch smooth (blue) and sharp (red)",
            Mode::Rub => "Rub back and forth near a control curve to smooth it",
            Mode::Oversketch => "Draw near an outline where you want it to be",
            Mode::Optimize => {
                "Tap a model: even out its triangles or smooth it, preview the amount, Apply"
            }
            Mode::Feature => {
                "Sketch on a model, then drag: a ridge or ravine, a bump or valley, flattening, suggestive contours"
            }
            Mode::Region => {
                "Draw a curve on a model and a loop around it, then drag: the region follows, fading out"
            }
            Mode::Handles => {
                "Draw along a part of any model or point cloud, then drag, twist or scale its dots"
            }
            Mode::Pose => {
                "Draw a curve along a model, then its new shape: it bends keeping its volume; key poses, play"
            }
            Mode::Move => "Tap a model, then drag it, its ring or its square: move, turn, scale",
        }
    }
}

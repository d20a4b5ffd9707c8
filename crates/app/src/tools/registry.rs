//! Every tool: its folder's module, and one registration line each, in toolbar order (by
//! [`Group`], which a test checks): the mode that selects it (its name in sessions and the
//! autosave, in snake case) and how to make it. The toolbar, the help, the shortcuts and
//! [`super::ToolSet`] read the tools from here.

use std::sync::OnceLock;

use super::icon::Icon;
use super::tool::{Group, Tool, ToolInfo};

// The tools' folders, `tools/<name>/mod.rs`.
#[path = "arrange/mod.rs"]
pub mod arrange;
#[path = "curve_stroke/mod.rs"]
pub mod curve_stroke;
#[path = "feature/mod.rs"]
pub mod feature;
#[path = "handles/mod.rs"]
pub mod handles;
#[path = "optimize/mod.rs"]
pub mod optimize;
#[path = "oversketch/mod.rs"]
pub mod oversketch;
#[path = "paint/mod.rs"]
pub mod paint;
#[path = "pose/mod.rs"]
pub mod pose;
#[path = "pull/mod.rs"]
pub mod pull;
#[path = "region/mod.rs"]
pub mod region;
#[path = "sketch/mod.rs"]
pub mod sketch;

/// Declares [`Mode`] (one variant a line, with its doc) and how each mode's tool is made.
macro_rules! register_tools {
    ($($(#[$doc:meta])* $mode:ident => $make:expr,)+) => {
        /// Which tool pointer gestures go to.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
        #[serde(rename_all = "snake_case")]
        pub enum Mode {
            $($(#[$doc])* $mode,)+
        }

        impl Mode {
            /// Every mode, in toolbar order.
            pub const ALL: [Mode; [$(stringify!($mode)),+].len()] = [$(Mode::$mode),+];

            /// A new tool for this mode, in its first stage.
            pub fn tool(self) -> Box<dyn Tool> {
                match self {
                    $(Mode::$mode => Box::new($make),)+
                }
            }
        }
    };
}

register_tools! {
    /// Draw shapes (closed strokes on empty canvas), curves on shapes, and ink.
    Sketch => sketch::SketchTool::default(),
    /// Drag along control curves to remove them.
    Erase => curve_stroke::CurveStrokeTool::new(curve_stroke::Kind::Erase),
    /// Drag along control curves to switch them between smooth and sharp.
    CurveType => curve_stroke::CurveStrokeTool::new(curve_stroke::Kind::CurveType),
    /// Rub back and forth near a control curve to smooth it.
    Rub => curve_stroke::CurveStrokeTool::new(curve_stroke::Kind::Rub),
    /// Grab a control curve and drag it; the shape follows.
    Pull => pull::PullTool::default(),
    /// Redraw part of a model's outline.
    Oversketch => oversketch::OversketchTool::default(),
    /// Sketch a ridge, bump, flattening or suggestive contours onto a model.
    Feature => feature::FeatureTool::default(),
    /// Move a region drawn around a reference curve, with a fall-off (Bujans).
    Region => region::RegionTool::default(),
    /// Curve handles and skeletons on any model or point cloud (Blanco).
    Handles => handles::HandlesTool::default(),
    /// Bend by a control curve keeping the volume, and key poses (Zhou et al.).
    Pose => pose::PoseTool::default(),
    /// Better triangles or less noise on a model (Laplacian mesh optimization).
    Optimize => optimize::OptimizeTool::default(),
    /// Paint colours on models, fill them, pick colours, set their material.
    Paint => paint::PaintTool::default(),
    /// Arrange models: select one and move, turn or scale it; delete or duplicate it. (Named
    /// `move` in sessions and autosaves from before the tool was called Arrange.)
    Move => arrange::ArrangeTool::default(),
}

impl Default for Mode {
    /// The first tool: sketching.
    fn default() -> Self {
        Mode::ALL[0]
    }
}

impl Mode {
    /// Its tool's name, icon, key and description.
    pub fn info(self) -> &'static ToolInfo {
        static INFOS: OnceLock<Vec<&'static ToolInfo>> = OnceLock::new();
        INFOS.get_or_init(|| Mode::ALL.map(|mode| mode.tool().info()).to_vec())[self as usize]
    }

    /// The toolbar label.
    pub fn label(self) -> &'static str {
        self.info().label
    }

    /// Draws its icon (see [`ToolInfo::icon`]).
    pub fn icon(self) -> Icon {
        self.info().icon
    }

    /// What it is for.
    pub fn group(self) -> Group {
        self.info().group
    }

    /// The key that selects it (without modifiers).
    pub fn key(self) -> egui::Key {
        self.info().key
    }

    /// What it does, for tooltips and the help window.
    pub fn hint(self) -> &'static str {
        self.info().about
    }
}

#[cfg(test)]
mod tests {
    use egui::Key;

    use super::*;

    /// The toolbar shows the groups in their order, each tool once in its group's run, every
    /// group with a tool; and exactly the tools that deform say when to choose them.
    #[test]
    fn tools_come_in_their_groups_in_order() {
        let groups: Vec<Group> = Mode::ALL.into_iter().map(Mode::group).collect();
        let mut runs = groups.clone();
        runs.dedup();
        assert_eq!(
            runs,
            Group::ALL,
            "the groups' runs in toolbar order: {groups:?}"
        );
        for mode in Mode::ALL {
            let info = mode.info();
            assert_eq!(
                info.when.is_some(),
                info.group.deforms(),
                "{mode:?}'s when line"
            );
            let words = [info.gestures.pen, info.gestures.finger, info.gestures.mouse];
            assert!(words.iter().all(|w| !w.is_empty()), "{mode:?}'s gestures");
        }
        let deforming = Mode::ALL.into_iter().filter(|m| m.group().deforms());
        assert_eq!(
            deforming.count(),
            6,
            "Pull, Over-sketch, Feature, Region, Bend, Pose"
        );
    }

    /// Sessions and autosaves name the arrange tool `move`, as they did before it was
    /// called Arrange.
    #[test]
    fn the_arrange_tool_keeps_its_stored_name() {
        assert_eq!(Mode::Move.label(), "Arrange");
        assert_eq!(
            serde_json::to_string(&Mode::Move).ok().as_deref(),
            Some("\"move\"")
        );
    }

    /// Every key that selects a tool selects only it: no two tools share one, and none is a
    /// key a tool or the app takes for something else (see `crate::shortcuts`).
    #[test]
    fn each_tool_has_a_key_of_its_own() {
        let tools: Vec<Box<dyn Tool>> = Mode::ALL.into_iter().map(Mode::tool).collect();
        let app = [
            Key::F,
            Key::R,
            Key::Home,
            Key::W,
            Key::G,
            Key::H,
            Key::F1,
            Key::Escape,
        ];
        let taken: Vec<Key> = (tools.iter())
            .flat_map(|tool| tool.keys().iter().chain(tool.keys_anywhere()))
            .chain(&app)
            .copied()
            .collect();
        for (k, mode) in Mode::ALL.into_iter().enumerate() {
            let key = mode.key();
            assert!(!taken.contains(&key), "{mode:?}'s key {key:?} is taken");
            let others = Mode::ALL[k + 1..].iter().filter(|m| m.key() == key);
            assert_eq!(others.count(), 0, "{mode:?} shares {key:?}");
            assert!(std::ptr::eq(tools[k].info(), mode.info()), "{mode:?}");
        }
    }
}

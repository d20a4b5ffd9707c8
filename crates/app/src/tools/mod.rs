//! Tools: small state machines that turn [`ToolEvent`]s into document operations.
//!
//! A tool never touches a mesh; it emits an [`Op`](sketchmesh_core::document::Op) for the
//! editor, so one gesture is one undo step and every edit replays from the session. A tool
//! whose op previews while it is drawn (pull, over-sketch) begins it as a gesture
//! ([`ToolOutput::Begin`]) and feeds it samples; the app runs it as it runs every edit.
//! [`ToolSet`] holds one tool per [`Mode`] (FiberMesh's five tools, over-sketch, feature
//! sketching, region editing, curve handles, posing and optimize) and routes events to the
//! active one.

pub mod arrange;
mod context;
pub mod curve_stroke;
pub mod draw;
pub mod feature;
pub mod handles;
pub mod mode;
pub mod optimize;
pub mod oversketch;
pub mod pose;
pub mod pull;
pub mod region;
pub mod sketch;
#[cfg(test)]
mod test_support;

use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::StrokePoint;
use sketchmesh_core::document::{Document, Edit};

pub use crate::input::router::{Hands, ToolEvent};
pub use context::{ToolOutput, ViewCtx};
pub use mode::Mode;

use arrange::ArrangeTool;
use curve_stroke::CurveStrokeTool;
use feature::FeatureTool;
use handles::HandlesTool;
pub use optimize::Mark;
use optimize::OptimizeTool;
pub use oversketch::OversketchSettings;
use oversketch::{HandlePreview, OversketchTool};
use pose::PoseTool;
use pull::PullTool;
use region::RegionTool;
use sketch::SketchTool;

/// Every tool, and which one gets the events.
#[derive(Debug, Default)]
pub struct ToolSet {
    mode: Mode,
    sketch: SketchTool,
    pull: PullTool,
    curve_stroke: CurveStrokeTool,
    oversketch: OversketchTool,
    optimize: OptimizeTool,
    feature: FeatureTool,
    region: RegionTool,
    handles: HandlesTool,
    pose: PoseTool,
    arrange: ArrangeTool,
}

impl ToolSet {
    /// The active mode.
    pub fn mode(&self) -> Mode {
        self.mode
    }

    /// Switches tools; a gesture in progress is dropped, a stroke waiting for a tap stays
    /// ink (returned for committing).
    pub fn set_mode(&mut self, mode: Mode) -> ToolOutput {
        if mode == self.mode {
            return ToolOutput::None;
        }
        let dropped = self.cancel();
        self.mode = mode;
        dropped
    }

    /// The over-sketch tool's settings, for the toolbar.
    pub fn oversketch_settings_mut(&mut self) -> &mut OversketchSettings {
        self.oversketch.settings_mut()
    }

    /// The sketch tool's options.
    pub fn sketch_ui(&mut self, ui: &mut egui::Ui) {
        self.sketch.settings_ui(ui);
    }

    /// The optimize tool's panel; what the user did there.
    pub fn optimize_ui(&mut self, ui: &mut egui::Ui) -> ToolOutput {
        self.optimize.settings_ui(ui)
    }

    /// The feature tool's panel; what the user did there.
    pub fn feature_ui(&mut self, ui: &mut egui::Ui) -> ToolOutput {
        self.feature.settings_ui(ui)
    }

    /// The region tool's panel; what the user did there.
    pub fn region_ui(&mut self, ui: &mut egui::Ui) -> ToolOutput {
        self.region.settings_ui(ui)
    }

    /// The region tool's profile panel, to draw, while it shows.
    pub fn region_profile(&self, viewport: glam::DVec2) -> Option<region::ProfileView> {
        match self.mode {
            Mode::Region => self.region.profile_view(viewport),
            _ => None,
        }
    }

    /// The region tool's handle axes as seen, to draw.
    pub fn region_handles(&self, camera: &Camera, viewport: glam::DVec2) -> Vec<region::AxisMark> {
        match self.mode {
            Mode::Region => self.region.handle_axes(camera, viewport),
            _ => Vec::new(),
        }
    }

    /// The handles tool's panel; what the user did there.
    pub fn handles_ui(&mut self, ui: &mut egui::Ui) -> ToolOutput {
        self.handles.settings_ui(ui)
    }

    /// The handles tool's selected control point, while it is the active tool.
    pub fn selected_handle_point(&self) -> Option<(u32, usize)> {
        match self.mode {
            Mode::Handles => self.handles.selected(),
            _ => None,
        }
    }

    /// The pose tool's panel (fall-off, keys, play); what the user did there.
    pub fn pose_ui(&mut self, ui: &mut egui::Ui, doc: &Document) -> ToolOutput {
        self.pose.settings_ui(ui, doc)
    }

    /// The pose tool's picked control curves in `doc` (or as an edit in progress moves
    /// them), to draw, each with whether it is the one redrawn.
    pub fn pose_curves(&self, doc: &Document, moved: pose::Moved) -> Vec<(Vec<glam::DVec3>, bool)> {
        match self.mode {
            Mode::Pose => self.pose.curves(doc, moved),
            _ => Vec::new(),
        }
    }

    /// The pose tool's spline control points, to draw, while it reshapes by them.
    pub fn pose_controls(&self, doc: &Document, moved: pose::Moved) -> Vec<glam::DVec3> {
        match self.mode {
            Mode::Pose => self.pose.controls(doc, moved),
            _ => Vec::new(),
        }
    }

    /// The move tool's panel; what the user did there.
    pub fn arrange_ui(&mut self, ui: &mut egui::Ui, doc: &Document) -> ToolOutput {
        self.arrange.settings_ui(ui, doc)
    }

    /// Deletes what the active tool has selected (the Delete key): the move tool's model, the
    /// bend tool's handle.
    pub fn delete_selected(&mut self, doc: &Document) -> ToolOutput {
        match self.mode {
            Mode::Move => self.arrange.delete(doc),
            Mode::Handles => self.handles.delete_selected(),
            _ => ToolOutput::None,
        }
    }

    /// The move tool's handles, to draw, with the one being dragged.
    pub fn gizmo(
        &self,
        doc: &Document,
        camera: &Camera,
        viewport: glam::DVec2,
    ) -> Option<(
        sketchmesh_core::document::Gizmo,
        Option<sketchmesh_core::document::GizmoHandle>,
    )> {
        match self.mode {
            Mode::Move => self.arrange.gizmo(doc, camera, viewport),
            _ => None,
        }
    }

    /// The edit in progress stepped: a tool waiting on what it finds takes it (the region
    /// tool's handles and profile panel).
    pub fn edit_stepped(&mut self, edit: &Edit) {
        self.region.found(edit);
    }

    /// The edit a tool's gesture began was refused: the tool starts over (the region tool
    /// keeps its reference curve when the curves were refused).
    pub fn gesture_refused(&mut self) {
        self.feature.cancel();
        self.region.refused();
        self.handles.cancel();
    }

    /// Confirms what the active tool holds open (Enter): an optimization's preview, a region's
    /// handles.
    pub fn confirm(&mut self) -> ToolOutput {
        match self.mode {
            Mode::Optimize => self.optimize.confirm(),
            Mode::Region => self.region.confirm(),
            _ => ToolOutput::None,
        }
    }

    /// Steps the active tool's amount by `factor` (`[` and `]`): the optimize tool's scale.
    pub fn nudge(&mut self, factor: f64) -> ToolOutput {
        match self.mode {
            Mode::Optimize => self.optimize.nudge(factor),
            _ => ToolOutput::None,
        }
    }

    /// The optimize tool's strokes do the next thing: lasso, paint the area, paint features
    /// (the B key).
    pub fn next_stroke_use(&mut self) {
        if self.mode == Mode::Optimize {
            self.optimize.next_stroke_use();
        }
    }

    /// What the active tool asks the user to do next, if anything.
    pub fn hint(&self, doc: &Document) -> Option<&'static str> {
        match self.mode {
            Mode::Oversketch => self.oversketch.hint(),
            Mode::Optimize => self.optimize.hint(),
            Mode::Feature => self.feature.hint(),
            Mode::Region => self.region.hint(),
            Mode::Handles => self.handles.hint(doc),
            Mode::Pose => self.pose.hint(),
            Mode::Move => self.arrange.hint(doc),
            _ => None,
        }
    }

    /// Drops any gesture in progress; see [`ToolSet::set_mode`].
    pub fn cancel(&mut self) -> ToolOutput {
        self.pull.cancel();
        self.curve_stroke.cancel();
        self.oversketch.cancel();
        self.optimize.cancel();
        self.feature.cancel();
        self.region.cancel();
        self.handles.cancel();
        self.pose.cancel();
        self.arrange.cancel();
        self.sketch.cancel()
    }

    /// Feeds one event to the active tool.
    pub fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        match self.mode {
            Mode::Sketch => self.sketch.on_event(event, view, doc),
            Mode::Pull => self.pull.on_event(event, view),
            Mode::Erase | Mode::CurveType | Mode::Rub => {
                self.curve_stroke.on_event(self.mode, event, view, doc)
            }
            Mode::Oversketch => self.oversketch.on_event(event, view, doc),
            Mode::Optimize => self.optimize.on_event(event, view, doc),
            Mode::Feature => self.feature.on_event(event, view, doc),
            Mode::Region => self.region.on_event(event, view, doc),
            Mode::Handles => self.handles.on_event(event, view, doc),
            Mode::Pose => self.pose.on_event(event, view, doc),
            Mode::Move => self.arrange.on_event(event, view, doc),
        }
    }

    /// Feeds two fingers to the active tool; only the move tool takes them (see
    /// [`ArrangeTool::on_hands`]).
    pub fn on_hands(&mut self, hands: &Hands, view: &ViewCtx, doc: &Document) -> ToolOutput {
        match self.mode {
            Mode::Move => self.arrange.on_hands(hands, view, doc),
            _ => ToolOutput::None,
        }
    }

    /// The stroke in progress of the active tool, for live display.
    pub fn preview(&self) -> Option<&[StrokePoint]> {
        match self.mode {
            Mode::Sketch => self.sketch.preview(),
            Mode::Pull => None,
            Mode::Optimize => self.optimize.preview(),
            Mode::Erase | Mode::CurveType | Mode::Rub => self.curve_stroke.preview(),
            Mode::Oversketch => self.oversketch.preview(),
            Mode::Feature => self.feature.preview(),
            Mode::Region => self.region.preview(),
            Mode::Handles => self.handles.preview(),
            Mode::Pose => self.pose.preview(),
            Mode::Move => None,
        }
    }

    /// Called every frame with the frame's clock (s): what a waiting stroke becomes when its
    /// tap is late, and how long until the next such moment.
    pub fn poll(&mut self, now: f64) -> (ToolOutput, Option<f64>) {
        match self.mode {
            Mode::Sketch => self.sketch.poll(now),
            _ => (ToolOutput::None, None),
        }
    }

    /// A sketch stroke waiting for a confirming tap, shown until then.
    pub fn waiting(&self) -> Option<(&[StrokePoint], &'static str)> {
        self.sketch.waiting()
    }

    /// The optimize tool's lasso and brush strokes, or the feature tool's region and sketch,
    /// while the view is the one each was drawn in.
    pub fn marks(&self, camera: &Camera) -> Vec<Mark> {
        match self.mode {
            Mode::Optimize => self.optimize.marks(camera),
            Mode::Feature => self.feature.marks(camera),
            Mode::Region => self.region.marks(camera),
            Mode::Pose => self.pose.marks(camera),
            _ => Vec::new(),
        }
    }

    /// The handle picked in manual over-sketch mode.
    pub fn handle(&self) -> Option<&HandlePreview> {
        match self.mode {
            Mode::Oversketch => self.oversketch.handle(),
            _ => None,
        }
    }
}

//! The region tool (Bujans' region editor, `003_…` §4): draw a reference curve on a model,
//! then a closed boundary around it, then drag: the region follows the pointer, fully at
//! the reference curve and fading to nothing at the boundary, with a live preview and the
//! fall-off shown on the model while it moves; release keeps it as one undo step.
//!
//! The `region_edit` edit opens as a gesture, unmoved, as soon as the boundary closes, so
//! the model shows the fall-off in gray levels before anything moves (Bujans §8); each
//! move of the drag revises its transform (the core finds the region once and only moves
//! it again), and release commits the last one. The fall-off's shape is picked in the
//! toolbar's second row, and revises the open edit too.
//!
//! With **Handles** picked instead of a drag, the curves get 3-axis handles ([`handles`]);
//! the edit stays open across handle drags, each revising the handles' transforms, until
//! Apply (or Enter) commits them as one undo step.

mod handles;
mod icon;
mod profile;

mod overlay;

use glam::DVec2;
use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::polyline::{
    BAUDEL_K, distance_to_polyline, oversketch_merge, oversketch_merge_closed,
};
use sketchmesh_core::curve::{StrokePoint, is_closed_loop};
use sketchmesh_core::document::{
    AreaInput, CLOSE_TOLERANCE_PX, Document, Edit, Op, RegionDrag, RegionEditInput, StrokeInput,
    dragged_region, model_under,
};
use sketchmesh_core::region_edit::Levels;

pub use handles::{AxisMark, Part};
use handles::{HandleSession, Pressed};
use profile::ProfileSession;
pub use profile::ProfileView;

use crate::input::router::ToolEvent;
use crate::tools::context::{ToolOutput, ViewCtx};
use crate::tools::draw::{DrawTool, is_tap, point};
use crate::tools::hint::{Device, Hint};
use crate::tools::tool::{Gestures, Group, Mark, Scene, Tool, ToolInfo};

/// The region tool's name, icon, key and description.
static INFO: ToolInfo = ToolInfo {
    label: "Region",
    icon: icon::draw,
    key: egui::Key::L,
    group: Group::Reshape,
    about: "Draw a curve on a model and a loop around it, then drag: the region follows, fading out",
    gestures: Gestures {
        pen: "Draw a curve, a loop around it, then drag",
        finger: "Draw a curve, a loop around it, then drag",
        mouse: "Left-drag a curve, a loop around it, then drag",
    },
    when: Some("To move, turn or scale an area with a soft edge you shape"),
};

/// The fall-off shapes offered: a label, a tooltip and the levels (weights from the boundary
/// to the reference curve).
const FALLOFFS: [(&str, &str, [f64; 5]); 4] = [
    (
        "Linear",
        "Moves in proportion to the closeness to the curve",
        [0.0, 0.25, 0.5, 0.75, 1.0],
    ),
    (
        "Smooth",
        "Eases in at the boundary and out at the curve",
        [0.0, 0.1, 0.5, 0.9, 1.0],
    ),
    (
        "Narrow",
        "Only the part near the curve moves much",
        [0.0, 0.0, 0.1, 0.4, 1.0],
    ),
    (
        "Broad",
        "Most of the region moves with the curve",
        [0.0, 0.6, 0.9, 1.0, 1.0],
    ),
];

/// An open stroke whose ends both lie this near (CSS px) the reference curve redraws that
/// part of it instead of being a boundary; the same for the boundary once it is drawn.
const OVERSKETCH_PX: f64 = 30.0;
/// A press this near (CSS px) the boundary, once the curves are drawn, starts redrawing it
/// rather than a drag.
const BOUNDARY_PX: f64 = 16.0;

/// What a drag does: moves the whole region, or works the handles on the curve.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum DragKind {
    Region(RegionDrag),
    Handles,
    Profile,
}

/// What a drag may do, as the toolbar offers it.
const DRAGS: [(DragKind, &str, &str); 5] = [
    (
        DragKind::Region(RegionDrag::Move),
        "Move",
        "The region follows the pointer",
    ),
    (
        DragKind::Region(RegionDrag::Turn),
        "Turn",
        "Drag sideways: the region turns about the curve's middle",
    ),
    (
        DragKind::Region(RegionDrag::Scale),
        "Scale",
        "Drag up to grow the region, down to shrink it",
    ),
    (
        DragKind::Handles,
        "Handles",
        "Handles on the curve: drag an axis near its handle to move, its middle to scale, its end to turn; tap the curve to add one",
    ),
    (
        DragKind::Profile,
        "Profile",
        "The region's cross-section across the curve in a panel: slide the plane, draw a new cross-section over it",
    ),
];

/// Where the tool is.
#[derive(Debug, Default)]
enum Stage {
    /// Drawing the reference curve.
    #[default]
    Reference,
    /// The reference curve is drawn; the next closed stroke is the boundary.
    Boundary(StrokeInput),
    /// Both curves are drawn: the next drag moves the region.
    Ready(RegionEditInput),
    /// Dragging from where the pointer went down.
    Dragging(RegionEditInput, DVec2, RegionDrag),
    /// A stroke from near the boundary is being drawn: it redraws part of the boundary.
    Redrawing(RegionEditInput),
    /// An area's lasso is being drawn.
    Lassoing(RegionEditInput),
    /// Working the handles (the edit open since the curves were drawn); whether a handle
    /// has been pressed yet.
    Handles(Box<HandleSession>, bool),
    /// Re-sketching the cross-section in the profile panel.
    Profile(Box<ProfileSession>),
}

/// The region tool's state: the curves, the fall-off and the drag.
#[derive(Debug)]
pub struct RegionTool {
    draw: DrawTool,
    /// The fall-off's levels and their handles.
    graph: LevelsGraph,
    /// Parts of the region with levels of their own (Bujans §5.4): each lasso as drawn and
    /// its levels.
    areas: Vec<(Vec<[f64; 3]>, LevelsGraph)>,
    /// The area whose levels the graph shows, or `None` for the whole region's.
    editing: Option<usize>,
    /// Whether the next stroke is an area's lasso.
    lassoing: bool,
    /// What a drag does.
    drag: DragKind,
    stage: Stage,
}

impl Default for RegionTool {
    fn default() -> Self {
        RegionTool {
            draw: DrawTool::default(),
            graph: LevelsGraph::new(&FALLOFFS[0].2),
            areas: Vec::new(),
            editing: None,
            lassoing: false,
            drag: DragKind::Region(RegionDrag::default()),
            stage: Stage::default(),
        }
    }
}

impl RegionTool {
    /// Feeds one event: strokes make the two curves, the drag after them the edit.
    pub fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        match std::mem::take(&mut self.stage) {
            Stage::Reference => self.reference(event, view, doc),
            Stage::Boundary(reference) => self.boundary(reference, event, view),
            Stage::Ready(input) => match (event, self.drag) {
                (ToolEvent::Begin(_), _) if self.lassoing => {
                    self.draw.capture(event, view);
                    self.stage = Stage::Lassoing(input);
                    ToolOutput::None
                }
                (ToolEvent::Begin(s), _) if on_boundary(&input, point(s, view).pos, view) => {
                    self.draw.capture(event, view);
                    self.stage = Stage::Redrawing(input);
                    ToolOutput::None
                }
                (ToolEvent::Begin(s), DragKind::Region(drag)) => {
                    self.stage = Stage::Dragging(input, point(s, view).pos, drag);
                    ToolOutput::None
                }
                _ => {
                    self.stage = Stage::Ready(input);
                    ToolOutput::None
                }
            },
            Stage::Dragging(input, from, drag) => match event {
                ToolEvent::Move(s) => {
                    let offset = point(s, view).pos - from;
                    let op = Op::RegionEdit(dragged_region(doc, &input, drag, offset));
                    self.stage = Stage::Dragging(input, from, drag);
                    ToolOutput::Revise(op)
                }
                ToolEvent::End(s) => {
                    let offset = point(s, view).pos - from;
                    let done = dragged_region(doc, &input, drag, offset);
                    ToolOutput::FinishWith(Op::RegionEdit(done))
                }
                ToolEvent::Cancel => ToolOutput::Cancel,
                ToolEvent::Begin(_) => {
                    self.stage = Stage::Dragging(input, from, drag);
                    ToolOutput::None
                }
            },
            Stage::Redrawing(input) => self.redraw_boundary(input, event, view),
            Stage::Lassoing(input) => self.lasso_area(input, event, view),
            Stage::Profile(session) => self.profile(session, event, view),
            Stage::Handles(session, begun) => match event {
                // Before a handle moves, the boundary may still be redrawn.
                ToolEvent::Begin(s)
                    if !session.moved()
                        && on_boundary(session.curves(), point(s, view).pos, view) =>
                {
                    self.draw.capture(event, view);
                    self.stage = Stage::Redrawing(session.curves().clone());
                    ToolOutput::None
                }
                _ => self.handles(session, begun, event, view),
            },
        }
    }

    /// The stroke redrawing part of the boundary: at its end, merged into the boundary
    /// (Baudel's merge around the loop), which the open edit then takes.
    fn redraw_boundary(
        &mut self,
        input: RegionEditInput,
        event: &ToolEvent,
        view: &ViewCtx,
    ) -> ToolOutput {
        let Some(stroke) = self.draw.capture(event, view) else {
            self.stage = match event {
                ToolEvent::Cancel => Stage::Ready(input),
                _ => Stage::Redrawing(input),
            };
            return ToolOutput::None;
        };
        let boundary: Vec<DVec2> = input
            .boundary
            .iter()
            .map(|&[x, y, _]| DVec2::new(x, y))
            .collect();
        let points: Vec<DVec2> = stroke.points().iter().map(|p| p.pos).collect();
        let near = |p: &DVec2| distance_to_polyline(*p, &closed(&boundary)) < OVERSKETCH_PX;
        if is_tap(&stroke) || !points.first().is_some_and(near) || !points.last().is_some_and(near)
        {
            let sentence = "To redraw the boundary, start and end the stroke on it.";
            return self.after_boundary(input, Some(sentence));
        }
        let merged = oversketch_merge_closed(&boundary, &points, BAUDEL_K);
        let input = RegionEditInput {
            boundary: merged.iter().map(|p| [p.x, p.y, 0.5]).collect(),
            ..input
        };
        self.after_boundary(input, None)
    }

    /// The stroke of an area's lasso: at its end, a new area with the levels the graph
    /// showed, which the graph then edits.
    fn lasso_area(
        &mut self,
        input: RegionEditInput,
        event: &ToolEvent,
        view: &ViewCtx,
    ) -> ToolOutput {
        let Some(stroke) = self.draw.capture(event, view) else {
            self.stage = match event {
                ToolEvent::Cancel => Stage::Ready(input),
                _ => Stage::Lassoing(input),
            };
            return ToolOutput::None;
        };
        self.lassoing = false;
        if is_tap(&stroke) || !is_closed_loop(&stroke.points(), CLOSE_TOLERANCE_PX) {
            self.stage = Stage::Ready(input);
            let sentence = "Draw the area as a closed loop over the region.";
            return ToolOutput::Refused(String::from(sentence));
        }
        let levels = self.graph().levels.clone();
        self.areas.push((stroke.stroke, LevelsGraph::new(&levels)));
        self.editing = Some(self.areas.len() - 1);
        let input = RegionEditInput {
            areas: self.areas_input(),
            ..input
        };
        self.stage = Stage::Ready(input.clone());
        ToolOutput::Revise(Op::RegionEdit(input))
    }

    /// The graph the toolbar shows: the area's being edited, or the whole region's.
    fn graph(&mut self) -> &mut LevelsGraph {
        match self.editing.and_then(|i| self.areas.get_mut(i)) {
            Some((_, graph)) => graph,
            None => &mut self.graph,
        }
    }

    /// The areas as the op holds them.
    fn areas_input(&self) -> Vec<AreaInput> {
        (self.areas.iter())
            .map(|(lasso, graph)| AreaInput {
                lasso: lasso.clone(),
                levels: graph.levels.clone(),
            })
            .collect()
    }

    /// The curves are set again: the edit shows them (and finds their region, which then
    /// gets handles or the profile panel when they are picked: see [`RegionTool::found`]),
    /// and `refusal` is said if there is one.
    fn after_boundary(&mut self, input: RegionEditInput, refusal: Option<&str>) -> ToolOutput {
        self.stage = Stage::Ready(input.clone());
        let output = ToolOutput::Revise(Op::RegionEdit(input));
        match refusal {
            Some(sentence) => ToolOutput::Refused(String::from(sentence)),
            None => output,
        }
    }

    /// An event while the handles are shown: a press takes an axis (beginning the gesture
    /// at the first) or adds a handle, a move drags, a release lets go; the gesture stays
    /// open for the next drag.
    fn handles(
        &mut self,
        mut session: Box<HandleSession>,
        begun: bool,
        event: &ToolEvent,
        view: &ViewCtx,
    ) -> ToolOutput {
        let size = DVec2::new(view.viewport.width().into(), view.viewport.height().into());
        let (output, begun) = match event {
            ToolEvent::Begin(s) => match session.press(point(s, view).pos, &view.camera, size) {
                Pressed::Axis => (ToolOutput::None, true),
                Pressed::Added => (ToolOutput::Revise(Op::RegionEdit(session.input())), true),
                Pressed::Nothing => (ToolOutput::None, begun),
            },
            ToolEvent::Move(s) if session.dragging() => {
                session.drag_to(point(s, view).pos);
                (ToolOutput::Revise(Op::RegionEdit(session.input())), begun)
            }
            ToolEvent::End(s) if session.dragging() => {
                session.drag_to(point(s, view).pos);
                session.release();
                (ToolOutput::Revise(Op::RegionEdit(session.input())), begun)
            }
            ToolEvent::Cancel => {
                session.release();
                (ToolOutput::None, begun)
            }
            _ => (ToolOutput::None, begun),
        };
        self.stage = Stage::Handles(session, begun);
        output
    }

    /// An event while the profile panel shows: a stroke drawn in the panel re-sketches the
    /// cross-section, and the open edit previews it; a press on the boundary redraws that.
    fn profile(
        &mut self,
        mut session: Box<ProfileSession>,
        event: &ToolEvent,
        view: &ViewCtx,
    ) -> ToolOutput {
        let size = DVec2::new(view.viewport.width().into(), view.viewport.height().into());
        if let ToolEvent::Begin(s) = event {
            let at = point(s, view).pos;
            if !session.drawn() && on_boundary(session.curves(), at, view) {
                self.draw.capture(event, view);
                self.stage = Stage::Redrawing(session.curves().clone());
                return ToolOutput::None;
            }
            if !session.in_panel(at, size) {
                self.stage = Stage::Profile(session);
                return ToolOutput::None;
            }
        }
        let output = match self.draw.capture(event, view) {
            Some(stroke) if !is_tap(&stroke) => {
                let points: Vec<DVec2> = stroke.points().iter().map(|p| p.pos).collect();
                if session.draw(&points, size) {
                    ToolOutput::Revise(Op::RegionEdit(session.input()))
                } else {
                    ToolOutput::None
                }
            }
            _ => ToolOutput::None,
        };
        self.stage = Stage::Profile(session);
        output
    }

    /// The profile panel's contents, for a view of `size`, while it shows.
    pub fn profile_view(&self, size: DVec2) -> Option<ProfileView> {
        match &self.stage {
            Stage::Profile(session) => Some(session.view(size)),
            _ => None,
        }
    }

    /// Applies the handles or the profile as they stand (Enter, or the panel's Apply): one
    /// undo step.
    pub fn confirm(&mut self) -> ToolOutput {
        match std::mem::take(&mut self.stage) {
            Stage::Handles(session, _) if session.moved() => ToolOutput::Finish,
            Stage::Profile(session) if session.drawn() => ToolOutput::Finish,
            Stage::Handles(..) | Stage::Profile(_) => ToolOutput::Cancel,
            stage => {
                self.stage = stage;
                ToolOutput::None
            }
        }
    }

    /// The handle axes to draw, while the handles are shown.
    pub fn handle_axes(&self, camera: &Camera, viewport: DVec2) -> Vec<AxisMark> {
        match &self.stage {
            Stage::Handles(session, _) => session.axes(camera, viewport),
            _ => Vec::new(),
        }
    }

    /// The open edit found the region of the curves drawn: with **Handles** or **Profile**
    /// picked, the handles or the profile panel show. The tool asks for nothing itself, so
    /// the region is found once, by the edit, in steps spread over frames.
    pub fn found(&mut self, edit: &Edit) {
        let (Stage::Ready(input), DragKind::Handles | DragKind::Profile) = (&self.stage, self.drag)
        else {
            return;
        };
        let Some(region) = edit.region_found_for(input) else {
            return;
        };
        let input = input.clone();
        self.stage = if self.drag == DragKind::Handles {
            let rail = region.rail().clone();
            Stage::Handles(Box::new(HandleSession::new(input, rail)), false)
        } else {
            Stage::Profile(Box::new(ProfileSession::new(input, region.clone())))
        };
    }

    /// A finished first stroke: the reference curve, which must start on a model.
    fn reference(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        let Some(input) = self.draw.capture(event, view) else {
            return ToolOutput::None;
        };
        if is_tap(&input) {
            return ToolOutput::None;
        }
        if model_under(doc, &input).is_none() {
            let sentence = "Start the reference curve on a model: it is the part that moves.";
            return ToolOutput::Refused(String::from(sentence));
        }
        self.stage = Stage::Boundary(input);
        ToolOutput::None
    }

    /// A finished second stroke: the boundary, which must be a closed loop, or an open stroke
    /// from near the reference curve to near it, which redraws that part of the curve
    /// (Baudel's merge, as Bujans over-sketches her curves).
    fn boundary(
        &mut self,
        reference: StrokeInput,
        event: &ToolEvent,
        view: &ViewCtx,
    ) -> ToolOutput {
        let Some(input) = self.draw.capture(event, view) else {
            self.stage = Stage::Boundary(reference);
            return ToolOutput::None;
        };
        if let Some(redrawn) = redrawn_curve(&reference, &input) {
            self.stage = Stage::Boundary(redrawn);
            return ToolOutput::None;
        }
        let closed = is_closed_loop(&input.points(), CLOSE_TOLERANCE_PX);
        if is_tap(&input) || !closed || input.camera != reference.camera {
            self.stage = Stage::Boundary(reference);
            let sentence = "Draw the boundary as a closed loop around the reference curve.";
            return ToolOutput::Refused(String::from(sentence));
        }
        let mut boundary = input.stroke;
        if boundary.len() > 1 && boundary.first() == boundary.last() {
            boundary.pop();
        }
        let input = RegionEditInput {
            viewport: reference.viewport,
            camera: reference.camera,
            reference: reference.stroke,
            boundary,
            levels: Some(self.graph.levels.clone()),
            areas: Vec::new(),
            transform: Some(glam::DMat4::IDENTITY.to_cols_array()),
            handles: None,
            profile: None,
            remesh: true,
        };
        // The edit opens at once, unmoved, so that its fall-off shows before any drag.
        self.after_boundary(input, None)
    }

    /// The open edit was refused. When it was refused for the curves themselves (the region
    /// was being found: a boundary that misses the reference curve, or a region that reaches
    /// the mesh's own edge), the reference curve stays and only the boundary is asked for
    /// again; otherwise the tool starts over.
    pub fn refused(&mut self) {
        let stage = std::mem::take(&mut self.stage);
        self.cancel();
        if let Stage::Ready(input) = stage {
            self.stage = Stage::Boundary(input.reference_input());
        }
    }

    /// Forgets the curves, their areas and the drag (the app cancels its edit).
    pub fn cancel(&mut self) {
        self.draw = DrawTool::Idle;
        self.stage = Stage::Reference;
        self.areas.clear();
        self.editing = None;
        self.lassoing = false;
    }

    /// The stroke being drawn, for live display.
    pub fn preview(&self) -> Option<&[StrokePoint]> {
        self.draw.preview()
    }

    /// The curves drawn so far, while the view is the one they were drawn in.
    pub fn marks(&self, camera: &Camera) -> Vec<Mark> {
        let mark = |points: Vec<StrokePoint>, features| Mark {
            points,
            radius: None,
            features,
        };
        match &self.stage {
            Stage::Boundary(reference) if reference.camera == *camera => {
                vec![mark(reference.points(), true)]
            }
            Stage::Ready(input) | Stage::Redrawing(input) | Stage::Lassoing(input)
                if input.camera == *camera =>
            {
                let mut marks = curve_marks(input);
                marks.extend(self.areas.iter().map(|(lasso, _)| {
                    Mark {
                        points: StrokeInput {
                            stroke: lasso.clone(),
                            ..input.reference_input()
                        }
                        .points(),
                        radius: None,
                        features: false,
                    }
                }));
                marks
            }
            // Until a handle moves the region, whose curves then stay where they were drawn.
            Stage::Handles(session, false) if session.input().camera == *camera => {
                curve_marks(&session.input())
            }
            Stage::Profile(session) if !session.drawn() && session.curves().camera == *camera => {
                curve_marks(session.curves())
            }
            _ => Vec::new(),
        }
    }

    /// What the tool asks the user to do next.
    pub fn hint(&self) -> &'static str {
        match self.stage {
            Stage::Reference => {
                "Draw a reference curve {with} on a model: the part that moves most"
            }
            Stage::Boundary(_) => {
                "Now draw a closed loop around it (outside stays), or redraw part of the curve"
            }
            Stage::Ready(_) if self.lassoing => {
                "Draw a loop over the part of the region whose fall-off to change"
            }
            Stage::Ready(_) => match self.drag {
                DragKind::Region(RegionDrag::Move) => {
                    "Drag: the region follows, fading out toward the boundary"
                }
                DragKind::Region(RegionDrag::Turn) => {
                    "Drag sideways: the region turns, fading out toward the boundary"
                }
                DragKind::Region(RegionDrag::Scale) => {
                    "Drag up or down: the region grows or shrinks, fading out"
                }
                DragKind::Handles | DragKind::Profile => "Finding the region on the model…",
            },
            Stage::Handles(_, false) => {
                "Drag a handle's axis: near the handle moves, its middle scales, its end turns; {tap} the curve to add a handle"
            }
            Stage::Handles(_, true) => {
                "Drag more handles, or Apply{enter} to keep the edit as one step"
            }
            Stage::Profile(ref session) if session.drawn() => {
                "Draw the cross-section again, or Apply{enter} to keep it; the slider moves the plane"
            }
            Stage::Profile(_) => {
                "Draw a new cross-section over the one in the panel (from it, back to it); the slider moves the plane"
            }
            Stage::Dragging(..) => "Let go to keep the move as one step",
            Stage::Redrawing(_) => "Let go: this part of the loop takes the new line",
            Stage::Lassoing(_) => "Close the loop, then let go",
        }
    }

    /// The panel: what a drag does, the fall-off's shape, Apply for the handles, and Clear.
    pub fn settings_ui(&mut self, ui: &mut egui::Ui) -> ToolOutput {
        let mut output = ToolOutput::None;
        for (drag, label, hint) in DRAGS {
            let button =
                egui::Button::selectable(self.drag == drag, label).min_size(egui::vec2(36.0, 36.0));
            if ui.add(button).on_hover_text(hint).clicked() && self.drag != drag {
                self.drag = drag;
                output = self.change_drag();
            }
        }
        ui.separator();
        let mut changed = false;
        for (label, hint, levels) in FALLOFFS {
            let button = egui::Button::selectable(self.graph().levels == levels, label)
                .min_size(egui::vec2(36.0, 36.0));
            if ui.add(button).on_hover_text(hint).clicked() {
                *self.graph() = LevelsGraph::new(&levels);
                changed = true;
            }
        }
        changed |= self.graph().ui(ui);
        changed |= self.areas_ui(ui);
        if changed {
            let (levels, areas) = (self.graph.levels.clone(), self.areas_input());
            match &mut self.stage {
                Stage::Ready(input) => {
                    input.levels = Some(levels);
                    input.areas = areas;
                    output = ToolOutput::Revise(Op::RegionEdit(input.clone()));
                }
                Stage::Handles(session, _) => {
                    session.set_falloff(&levels, areas);
                    output = ToolOutput::Revise(Op::RegionEdit(session.input()));
                }
                Stage::Profile(session) => {
                    session.set_falloff(&levels, areas);
                    output = ToolOutput::Revise(Op::RegionEdit(session.input()));
                }
                _ => {}
            }
        }
        if let Stage::Profile(session) = &mut self.stage {
            let mut at = session.at();
            let slider = egui::Slider::new(&mut at, 0.0..=1.0).text("Plane");
            if ui
                .add(slider)
                .on_hover_text("Where along the curve the cross-section is cut")
                .changed()
            {
                session.slide_to(at);
                output = ToolOutput::Revise(Op::RegionEdit(session.input()));
            }
        }
        let changes = match &self.stage {
            Stage::Handles(session, _) => Some(session.moved()),
            Stage::Profile(session) => Some(session.drawn()),
            _ => None,
        };
        if let Some(ready) = changes {
            let apply = egui::Button::new("Apply").min_size(egui::vec2(36.0, 36.0));
            if ui
                .add_enabled(ready, apply)
                .on_hover_text("Keep the edit as one step (Enter)")
                .clicked()
            {
                output = self.confirm();
            }
        }
        let drawn = !matches!(self.stage, Stage::Reference);
        if ui
            .add_enabled(drawn, egui::Button::new("Clear curves"))
            .on_hover_text("Draw a new reference curve and boundary")
            .clicked()
        {
            self.cancel();
            output = ToolOutput::Cancel;
        }
        output
    }

    /// The fall-off's areas: **Area** draws a new one (its levels are then the graph's),
    /// **Whole** goes back to the whole region's levels, **No areas** drops them. Whether the
    /// areas changed.
    fn areas_ui(&mut self, ui: &mut egui::Ui) -> bool {
        let ready = matches!(self.stage, Stage::Ready(_));
        let area = egui::Button::selectable(self.lassoing, "Area").min_size(egui::vec2(36.0, 36.0));
        if ui
            .add_enabled(ready, area)
            .on_hover_text(
                "Draw a loop over the region: the levels then set the fall-off inside it only",
            )
            .clicked()
        {
            self.lassoing = !self.lassoing;
        }
        if self.areas.is_empty() {
            return false;
        }
        let whole = egui::Button::selectable(self.editing.is_none(), "Whole")
            .min_size(egui::vec2(36.0, 36.0));
        if ui
            .add(whole)
            .on_hover_text("The levels set the fall-off of the whole region")
            .clicked()
        {
            self.editing = None;
        }
        let drop = ui.add(egui::Button::new("No areas").min_size(egui::vec2(36.0, 36.0)));
        if drop
            .on_hover_text("Drop the areas: one fall-off for the whole region")
            .clicked()
        {
            self.areas.clear();
            self.editing = None;
            return true;
        }
        false
    }

    /// The drag's kind changed: drawn curves get what it needs (handles, the profile panel,
    /// nothing), anything moved so far is dropped, and the open edit shows the curves
    /// unmoved.
    fn change_drag(&mut self) -> ToolOutput {
        let curves = match std::mem::take(&mut self.stage) {
            Stage::Ready(input) => input,
            Stage::Handles(session, _) => session.curves().clone(),
            Stage::Profile(session) => session.curves().clone(),
            stage => {
                self.stage = stage;
                return ToolOutput::None;
            }
        };
        self.after_boundary(curves, None)
    }
}

/// Whether a press at `at` (CSS px in the view) starts on `input`'s boundary, away from its
/// reference curve, in the view the curves were drawn in: a stroke from there redraws it.
fn on_boundary(input: &RegionEditInput, at: DVec2, view: &ViewCtx) -> bool {
    let points = |samples: &[[f64; 3]]| -> Vec<DVec2> {
        samples.iter().map(|&[x, y, _]| DVec2::new(x, y)).collect()
    };
    view.camera == input.camera
        && distance_to_polyline(at, &closed(&points(&input.boundary))) < BOUNDARY_PX
        && distance_to_polyline(at, &points(&input.reference)) > OVERSKETCH_PX
}

/// A loop's points with the first repeated at the end.
fn closed(points: &[DVec2]) -> Vec<DVec2> {
    points.iter().chain(points.first()).copied().collect()
}

/// The two curves of `input`, drawn.
fn curve_marks(input: &RegionEditInput) -> Vec<Mark> {
    let mark = |points: Vec<StrokePoint>, features| Mark {
        points,
        radius: None,
        features,
    };
    // The boundary is a loop: drawn back to its first point.
    let boundary = StrokeInput {
        stroke: (input.boundary.iter().chain(input.boundary.first()))
            .copied()
            .collect(),
        ..input.reference_input()
    };
    vec![
        mark(input.reference_input().points(), true),
        mark(boundary.points(), false),
    ]
}

/// `reference` with `stroke` merged into it, when the stroke is open and both its ends lie
/// within [`OVERSKETCH_PX`] of the curve.
fn redrawn_curve(reference: &StrokeInput, stroke: &StrokeInput) -> Option<StrokeInput> {
    let points = stroke.points();
    if is_tap(stroke) || is_closed_loop(&points, CLOSE_TOLERANCE_PX) {
        return None;
    }
    let curve: Vec<DVec2> = reference.points().iter().map(|p| p.pos).collect();
    let near = |p: Option<&StrokePoint>| {
        p.is_some_and(|p| distance_to_polyline(p.pos, &curve) < OVERSKETCH_PX)
    };
    if !near(points.first()) || !near(points.last()) {
        return None;
    }
    let stroke: Vec<DVec2> = points.iter().map(|p| p.pos).collect();
    let merged = oversketch_merge(&curve, &stroke, BAUDEL_K);
    Some(StrokeInput {
        stroke: merged.iter().map(|p| [p.x, p.y, 0.5]).collect(),
        ..reference.clone()
    })
}

/// Size of the levels graph in the toolbar, in points: touch-sized.
const GRAPH_SIZE: egui::Vec2 = egui::vec2(180.0, 44.0);

/// The fall-off's levels as the toolbar edits them, with the level handles (Bujans §5.3).
#[derive(Debug)]
struct LevelsGraph {
    /// Weights from the boundary to the reference curve.
    levels: Vec<f64>,
    /// The levels a handle anchors.
    pinned: Vec<bool>,
    /// The level being dragged.
    dragging: Option<usize>,
}

impl LevelsGraph {
    fn new(levels: &[f64]) -> Self {
        LevelsGraph {
            levels: levels.to_vec(),
            pinned: vec![false; levels.len()],
            dragging: None,
        }
    }

    /// The fall-off as a graph, the boundary on the left and the reference curve on the
    /// right, each level a dot at its weight: a tap on a dot anchors it (a ring) or lets it
    /// go; a drag moves the nearest level, and the others follow up to the anchored ones
    /// ([`Levels::dragged`]). Whether a weight changed.
    fn ui(&mut self, ui: &mut egui::Ui) -> bool {
        let (rect, response) = ui.allocate_exact_size(GRAPH_SIZE, egui::Sense::click_and_drag());
        let response = response.on_hover_text(
            "The fall-off from the boundary (left) to the curve (right): drag a dot up or down, tap one to anchor it",
        );
        let last = (self.levels.len() - 1) as f32;
        let inner = rect.shrink(8.0);
        let at = |i: usize, w: f64| {
            egui::pos2(
                inner.left() + inner.width() * i as f32 / last,
                inner.bottom() - inner.height() * w as f32,
            )
        };
        let nearest = |p: egui::Pos2| {
            let across = ((p.x - inner.left()) / inner.width()).clamp(0.0, 1.0);
            (across * last).round() as usize
        };
        let weight =
            |p: egui::Pos2| f64::from(((inner.bottom() - p.y) / inner.height()).clamp(0.0, 1.0));
        let mut changed = false;
        if let Some(pointer) = response.interact_pointer_pos() {
            if response.clicked() {
                let i = nearest(pointer);
                self.pinned[i] = !self.pinned[i];
            } else if response.drag_started() {
                self.dragging = Some(nearest(pointer));
            }
            if let Some(i) = self.dragging.filter(|_| response.dragged()) {
                let before = Levels::new(self.levels.clone()).unwrap_or_default();
                let after = before.dragged(i, weight(pointer), &self.pinned);
                changed = after != before;
                self.levels = after.weights().to_vec();
            }
        }
        if response.drag_stopped() {
            self.dragging = None;
        }
        let painter = ui.painter();
        let visuals = ui.visuals();
        painter.rect_filled(rect, 4.0, visuals.extreme_bg_color);
        let points: Vec<egui::Pos2> = (self.levels.iter().enumerate())
            .map(|(i, &w)| at(i, w))
            .collect();
        painter.add(egui::Shape::line(
            points.clone(),
            egui::Stroke::new(2.0, visuals.widgets.active.fg_stroke.color),
        ));
        for ((point, &w), &pinned) in points.iter().zip(&self.levels).zip(&self.pinned) {
            let gray = crate::overlay::falloff_gray(w);
            painter.circle_filled(*point, 6.0, egui::Color32::from_gray(gray));
            painter.circle_stroke(*point, 6.0, egui::Stroke::new(1.0, egui::Color32::GRAY));
            if pinned {
                let ring = egui::Stroke::new(2.0, egui::Color32::from_rgb(255, 200, 90));
                painter.circle_stroke(*point, 9.5, ring);
            }
        }
        changed
    }
}

impl Tool for RegionTool {
    fn info(&self) -> &'static ToolInfo {
        &INFO
    }

    fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        RegionTool::on_event(self, event, view, doc)
    }

    fn cancel(&mut self) -> ToolOutput {
        RegionTool::cancel(self);
        ToolOutput::None
    }

    fn panel(&mut self, ui: &mut egui::Ui, _doc: &Document) -> Option<ToolOutput> {
        Some(self.settings_ui(ui))
    }

    /// The handles' axes, and the profile panel in the view's lower right corner.
    fn overlay(&self, ui: &egui::Ui, scene: &Scene<'_>) {
        overlay::handles_ui(ui, scene, &self.handle_axes(&scene.camera, scene.size()));
        if let Some(view) = self.profile_view(scene.size()) {
            overlay::profile_ui(ui, scene, &view);
        }
    }

    fn hint(&self, _doc: &Document, device: Device) -> Hint {
        device.say(RegionTool::hint(self))
    }

    fn preview(&self) -> Option<&[StrokePoint]> {
        RegionTool::preview(self)
    }

    fn marks(&self, camera: &Camera) -> Vec<Mark> {
        RegionTool::marks(self, camera)
    }

    /// Enter applies the handles or the profile as they stand.
    fn keys(&self) -> &'static [egui::Key] {
        &[egui::Key::Enter]
    }

    fn on_key(&mut self, _key: egui::Key, _doc: &Document) -> ToolOutput {
        self.confirm()
    }

    fn edit_stepped(&mut self, edit: &Edit) {
        self.found(edit);
    }

    fn gesture_refused(&mut self) {
        self.refused();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::Phase;
    use crate::tools::test_support::{pen, shape, view};
    use sketchmesh_core::document::{Editor, Progress};

    /// Feeds a pen stroke through screen points; the last output that says something.
    /// What the app does with `opened`, the tool's op for the curves drawn: the edit begins
    /// and steps until its region is found, and the tool takes it.
    fn find_region(tool: &mut RegionTool, editor: &Editor, opened: ToolOutput) {
        let ToolOutput::Revise(op) = opened else {
            panic!("the loop opens the edit: {opened:?}")
        };
        let mut edit = editor.begin_gesture(op).unwrap();
        while edit.step().unwrap() == Progress::Working {}
        tool.found(&edit);
    }

    /// A horizontal line of `n` gaps of 4 px centred on `centre`: a reference curve.
    fn line_across(centre: DVec2, n: u32) -> Vec<DVec2> {
        (0..=n)
            .map(|i| centre + DVec2::new(4.0 * f64::from(i) - 2.0 * f64::from(n), 0.0))
            .collect()
    }

    /// A loop of 48 gaps around `centre`: a boundary.
    fn loop_around(centre: DVec2, radius: f64) -> Vec<DVec2> {
        (0..=48)
            .map(|i| {
                centre + radius * DVec2::from_angle(std::f64::consts::TAU * f64::from(i) / 48.0)
            })
            .collect()
    }

    fn stroke(tool: &mut RegionTool, doc: &Document, points: &[DVec2]) -> ToolOutput {
        let at = |phase, p: DVec2| pen(phase, p.x as f32, p.y as f32);
        let view = view();
        let mut said = tool.on_event(&ToolEvent::Begin(at(Phase::Down, points[0])), &view, doc);
        for &p in &points[1..] {
            let out = tool.on_event(&ToolEvent::Move(at(Phase::Move, p)), &view, doc);
            said = if out == ToolOutput::None { said } else { out };
        }
        let last = points[points.len() - 1];
        match tool.on_event(&ToolEvent::End(at(Phase::Up, last)), &view, doc) {
            ToolOutput::None => said,
            out => out,
        }
    }

    #[test]
    fn a_curve_a_loop_and_a_drag_make_one_region_edit() {
        let editor = shape();
        let doc = editor.document();
        // The shape's middle, in screen points.
        let centre = DVec2::new(400.0, 340.0);
        let mut tool = RegionTool::default();
        let line = line_across(centre, 20);
        assert_eq!(stroke(&mut tool, doc, &line), ToolOutput::None);
        assert!(tool.hint().contains("loop"));
        // An open stroke from near the curve to near it redraws that part (3 px lower, so
        // its transitions, 6 gaps long, leave the curve's ends).
        let redraw: Vec<DVec2> = (0..=10)
            .map(|i| centre + DVec2::new(4.0 * f64::from(i) - 20.0, 3.0))
            .collect();
        assert_eq!(stroke(&mut tool, doc, &redraw), ToolOutput::None);
        let open: Vec<DVec2> = (0..=20)
            .map(|i| centre + DVec2::new(4.0 * f64::from(i), 60.0))
            .collect();
        assert!(
            matches!(stroke(&mut tool, doc, &open), ToolOutput::Refused(_)),
            "an open boundary is refused"
        );
        let ring = loop_around(centre, 90.0);
        // The loop opens the edit, unmoved, so that its fall-off shows before the drag.
        let opened = stroke(&mut tool, doc, &ring);
        let ToolOutput::Revise(Op::RegionEdit(begun)) = opened else {
            panic!("{opened:?}")
        };
        assert_eq!(begun.transform, Some(glam::DMat4::IDENTITY.to_cols_array()));
        let marks = tool.marks(&view().camera);
        assert_eq!(marks.len(), 2);
        let drawn_loop = &marks[1].points;
        assert_eq!(
            drawn_loop.first().map(|p| p.pos),
            drawn_loop.last().map(|p| p.pos)
        );
        let drag = [centre, centre - DVec2::Y * 20.0, centre - DVec2::Y * 40.0];
        let at = |phase, p: DVec2| pen(phase, p.x as f32, p.y as f32);
        let pressed = tool.on_event(&ToolEvent::Begin(at(Phase::Down, drag[0])), &view(), doc);
        assert_eq!(pressed, ToolOutput::None);
        let revised = tool.on_event(&ToolEvent::Move(at(Phase::Move, drag[1])), &view(), doc);
        assert!(matches!(revised, ToolOutput::Revise(Op::RegionEdit(_))));
        let done = tool.on_event(&ToolEvent::End(at(Phase::Up, drag[2])), &view(), doc);
        let ToolOutput::FinishWith(Op::RegionEdit(done)) = done else {
            panic!("the release finishes the edit: {done:?}")
        };
        let moved = glam::DMat4::from_cols_array(&done.transform.unwrap())
            .w_axis
            .truncate();
        assert!(moved.y > 0.0, "dragged up, moved up: {moved}");
        assert_eq!(done.reference, begun.reference);
        let lowered = |y: f64| (y - 303.0).abs() < 0.5;
        assert!(
            done.reference.iter().any(|p| lowered(p[1])),
            "the redrawn part is in the op"
        );
        assert!(
            done.reference.iter().any(|p| (p[1] - 300.0).abs() < 0.5),
            "so is the rest"
        );
    }

    #[test]
    fn handles_drag_the_curve_in_one_open_edit_until_applied() {
        let editor = shape();
        let doc = editor.document();
        let centre = DVec2::new(400.0, 340.0);
        let mut tool = RegionTool {
            drag: DragKind::Handles,
            ..RegionTool::default()
        };
        let line = line_across(centre, 30);
        stroke(&mut tool, doc, &line);
        let ring = loop_around(centre, 110.0);
        // The loop opens the edit, unmoved; the handles show once it found the region.
        let opened = stroke(&mut tool, doc, &ring);
        let view = view();
        let size = DVec2::new(view.viewport.width().into(), view.viewport.height().into());
        assert!(tool.handle_axes(&view.camera, size).is_empty());
        assert!(tool.hint().contains("Finding"));
        find_region(&mut tool, &editor, opened);
        let axes = tool.handle_axes(&view.camera, size);
        assert!(axes.len() >= 6, "three handles with their axes: {axes:?}");
        assert!(tool.hint().contains("axis"));
        // Seen head-on, the middle handle's normal points at the viewer and is not offered;
        // its binormal (up the screen, across the curve) is pressed in its inner third and
        // dragged along it.
        assert!(!axes.iter().any(|m| m.handle == 1 && m.axis == 1));
        let binormal = *axes.iter().find(|m| m.handle == 1 && m.axis == 2).unwrap();
        let press = binormal.from.lerp(binormal.to, 0.15);
        let along = (binormal.to - binormal.from).normalize() * 30.0;
        let at = |phase, p: DVec2| {
            let p = p + DVec2::new(view.viewport.min.x.into(), view.viewport.min.y.into());
            pen(phase, p.x as f32, p.y as f32)
        };
        let pressed = tool.on_event(&ToolEvent::Begin(at(Phase::Down, press)), &view, doc);
        assert_eq!(pressed, ToolOutput::None);
        let moved = tool.on_event(&ToolEvent::Move(at(Phase::Move, press + along)), &view, doc);
        let ToolOutput::Revise(Op::RegionEdit(moved)) = moved else {
            panic!("{moved:?}")
        };
        let handles = moved.handles.unwrap();
        let lift = glam::DMat4::from_cols_array(&handles[1].transform)
            .w_axis
            .truncate();
        assert!(
            lift.length() > 0.0 && handles[0].transform == glam::DMat4::IDENTITY.to_cols_array()
        );
        let released = tool.on_event(&ToolEvent::End(at(Phase::Up, press + along)), &view, doc);
        assert!(
            matches!(released, ToolOutput::Revise(_)),
            "a release keeps the edit open"
        );
        // A tap on the curve between handles adds one; the second drag revises the same edit.
        let quarter = tool.handle_axes(&view.camera, size);
        let (a, b) = (
            quarter[0].from,
            quarter.iter().find(|m| m.handle == 1).unwrap().from,
        );
        let tap = a.lerp(b, 0.5);
        let added = tool.on_event(&ToolEvent::Begin(at(Phase::Down, tap)), &view, doc);
        let ToolOutput::Revise(Op::RegionEdit(added)) = added else {
            panic!("a tap on the curve adds a handle: {added:?}")
        };
        assert_eq!(added.handles.unwrap().len(), 4);
        tool.on_event(&ToolEvent::End(at(Phase::Up, tap)), &view, doc);
        assert_eq!(tool.confirm(), ToolOutput::Finish);
        assert!(tool.handle_axes(&view.camera, size).is_empty());
        assert!(tool.hint().contains("reference"));
    }

    #[test]
    fn a_stroke_from_the_boundary_to_it_redraws_that_part() {
        let editor = shape();
        let doc = editor.document();
        let centre = DVec2::new(400.0, 340.0);
        let mut tool = RegionTool::default();
        stroke(&mut tool, doc, &line_across(centre, 20));
        let ring = loop_around(centre, 90.0);
        let ToolOutput::Revise(Op::RegionEdit(first)) = stroke(&mut tool, doc, &ring) else {
            panic!("the loop opens the edit")
        };
        // From the ring's right side out by 25 px and back: the boundary bulges there.
        let bulge: Vec<DVec2> = (0..=20)
            .map(|i| {
                let a = -0.5 + f64::from(i) / 20.0;
                let r = 90.0 + 25.0 * (std::f64::consts::PI * f64::from(i) / 20.0).sin();
                centre + r * DVec2::from_angle(a)
            })
            .collect();
        let said = stroke(&mut tool, doc, &bulge);
        let ToolOutput::Revise(Op::RegionEdit(redrawn)) = said else {
            panic!("the stroke redraws the boundary: {said:?}")
        };
        assert_eq!(redrawn.reference, first.reference);
        let local = |p: DVec2| p - DVec2::new(0.0, 40.0);
        let tip = local(bulge[10]);
        assert!(
            redrawn
                .boundary
                .iter()
                .any(|&[x, y, _]| DVec2::new(x, y).distance(tip) < 1.0),
            "the bulge's tip is on the boundary"
        );
        let far = local(centre - DVec2::new(90.0, 0.0));
        assert!(
            redrawn
                .boundary
                .iter()
                .any(|&[x, y, _]| DVec2::new(x, y).distance(far) < 1.0),
            "the far side stays"
        );
        // With Area on, a loop over the region is an area of the fall-off, with the levels
        // the graph had; the graph then edits the area's.
        tool.lassoing = true;
        let patch: Vec<DVec2> = (0..=24)
            .map(|i| {
                centre
                    + DVec2::new(30.0, 0.0)
                    + 25.0 * DVec2::from_angle(std::f64::consts::TAU * f64::from(i) / 24.0)
            })
            .collect();
        let ToolOutput::Revise(Op::RegionEdit(with_area)) = stroke(&mut tool, doc, &patch) else {
            panic!("the loop is an area")
        };
        assert_eq!(with_area.areas.len(), 1);
        assert_eq!(with_area.areas[0].levels, FALLOFFS[0].2.to_vec());
        assert_eq!((tool.editing, tool.lassoing), (Some(0), false));
        assert_eq!(tool.marks(&view().camera).len(), 3);
        // A stroke from the boundary that ends elsewhere is refused; the boundary stays.
        let away: Vec<DVec2> = (0..=10)
            .map(|i| bulge[0] + DVec2::new(-5.0 * f64::from(i), 0.0))
            .collect();
        assert!(matches!(
            stroke(&mut tool, doc, &away),
            ToolOutput::Refused(_)
        ));
        assert_eq!(tool.marks(&view().camera).len(), 3);
    }

    #[test]
    fn a_stroke_in_the_profile_panel_resketches_the_cross_section() {
        let editor = shape();
        let doc = editor.document();
        let centre = DVec2::new(400.0, 340.0);
        let mut tool = RegionTool {
            drag: DragKind::Profile,
            ..RegionTool::default()
        };
        let line = line_across(centre, 30);
        stroke(&mut tool, doc, &line);
        let ring = loop_around(centre, 110.0);
        let opened = stroke(&mut tool, doc, &ring);
        let view = view();
        let size = DVec2::new(view.viewport.width().into(), view.viewport.height().into());
        assert!(
            tool.profile_view(size).is_none(),
            "not before the region is found"
        );
        find_region(&mut tool, &editor, opened);
        let panel = tool.profile_view(size).expect("the panel shows");
        assert!(panel.refusal.is_none(), "{:?}", panel.refusal);
        assert!(panel.section.len() > 5);
        // The cross-section runs across the panel, the arrow points up (out of the surface).
        assert!(panel.curve.1.y < panel.curve.0.y);
        // A bump drawn from a third of the way across to two thirds, 30 px up.
        let (a, b) = (
            panel.section[panel.section.len() / 3],
            panel.section[2 * panel.section.len() / 3],
        );
        let bump: Vec<DVec2> = (0..=20)
            .map(|i| {
                let t = f64::from(i) / 20.0;
                a.lerp(b, t) - DVec2::Y * 30.0 * (std::f64::consts::PI * t).sin()
                    + DVec2::new(view.viewport.min.x.into(), view.viewport.min.y.into())
            })
            .collect();
        let said = stroke(&mut tool, doc, &bump);
        let ToolOutput::Revise(Op::RegionEdit(op)) = said else {
            panic!("the stroke re-sketches the profile: {said:?}")
        };
        let profile = op.profile.expect("a profile op");
        assert_eq!((profile.at, op.transform, op.handles), (0.5, None, None));
        let top = profile.stroke.iter().map(|p| p[1]).fold(f64::MIN, f64::max);
        assert!(top > 0.0, "the bump rises out of the surface: {top}");
        assert!(tool.profile_view(size).unwrap().stroke.is_some());
        assert_eq!(tool.confirm(), ToolOutput::Finish);
    }

    #[test]
    fn a_refused_region_keeps_the_reference_curve_and_asks_for_the_boundary_again() {
        let editor = shape();
        let doc = editor.document();
        let centre = DVec2::new(400.0, 340.0);
        let mut tool = RegionTool::default();
        stroke(&mut tool, doc, &line_across(centre, 20));
        // A loop beside the curve, not around it: the edit it opens is refused as its region
        // is found.
        let beside = loop_around(centre + DVec2::new(0.0, 60.0), 20.0);
        let ToolOutput::Revise(op) = stroke(&mut tool, doc, &beside) else {
            panic!("the loop opens the edit")
        };
        let mut edit = editor.begin_gesture(op).unwrap();
        let refusal = loop {
            match edit.step() {
                Ok(Progress::Working) => {}
                Ok(done) => panic!("a loop beside the curve is refused, not {done:?}"),
                Err(why) => break why,
            }
        };
        assert!(refusal.to_string().contains("boundary"), "{refusal}");
        tool.refused();
        assert!(tool.hint().contains("loop"), "{:?}", tool.hint());
        let marks = tool.marks(&view().camera);
        assert_eq!(marks.len(), 1, "the reference curve stays");
        // A loop around it now opens the edit with the same reference curve.
        let ring = loop_around(centre, 90.0);
        let opened = stroke(&mut tool, doc, &ring);
        assert!(
            matches!(opened, ToolOutput::Revise(Op::RegionEdit(_))),
            "{opened:?}"
        );
        // A refusal once the region is moved starts over.
        find_region(&mut tool, &editor, opened);
        let at = |phase, p: DVec2| pen(phase, p.x as f32, p.y as f32);
        tool.on_event(&ToolEvent::Begin(at(Phase::Down, centre)), &view(), doc);
        tool.refused();
        assert!(tool.marks(&view().camera).is_empty());
    }

    #[test]
    fn a_reference_curve_off_the_models_is_refused() {
        let editor = shape();
        let mut tool = RegionTool::default();
        let far: Vec<DVec2> = (0..=10)
            .map(|i| DVec2::new(20.0 + 4.0 * f64::from(i), 60.0))
            .collect();
        let said = stroke(&mut tool, editor.document(), &far);
        assert!(matches!(said, ToolOutput::Refused(_)), "{said:?}");
        assert!(tool.hint().contains("reference"));
    }
}

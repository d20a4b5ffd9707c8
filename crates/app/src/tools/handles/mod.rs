//! The handles tool (Blanco's curve handles and skeletons): draw along a part of a model or a
//! point cloud to make a curve handle, then drag its control points: move (on the view plane
//! through the point), twist (sideways) or scale (up and down); tap two control points of
//! different handles to link them into a skeleton.
//!
//! A stroke that does not start on a control point is a new handle (`curve_handle`). A drag
//! that does begins a `handle_edit` gesture at pointer-down, each move revises it (the core
//! only rebuilds points from new frames) and release commits it: one undo step per drag.

mod draw;
mod icon;

use crate::ui_size::target_size;
use glam::{DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::StrokePoint;
use sketchmesh_core::document::{
    CurveHandleInput, DeleteHandleInput, Document, HandleEditInput, LinkHandlesInput, Op,
};
use sketchmesh_core::skeleton::HandleKind;

use crate::input::router::ToolEvent;
use crate::tools::context::{ToolOutput, ViewCtx};
use crate::tools::draw::{DrawTool, is_tap, point};
use crate::tools::hint::{Device, Hint};
use crate::tools::tool::{Gestures, Group, Scene, Tool, ToolInfo};

/// The bend tool's name, icon, key and description.
static INFO: ToolInfo = ToolInfo {
    label: "Bend",
    icon: icon::draw,
    key: egui::Key::J,
    group: Group::Reshape,
    about: "Draw along a part of any model or point cloud, then drag, twist or scale its dots",
    gestures: Gestures {
        pen: "Draw along a part, then drag its dots",
        finger: "Draw along a part, then drag its dots",
        mouse: "Left-drag along a part, then drag its dots",
    },
    when: Some("For scans and imported models, or to bend, twist or thicken a limb at joints"),
};

/// How near (CSS px) a pointer must go down to a control point to grab it: a fingertip.
pub const GRAB_PX: f64 = 22.0;

/// Degrees of twist per CSS px of sideways drag.
const TWIST_DEG_PER_PX: f64 = 0.5;

/// CSS px of upward drag that doubles the scale.
const PX_PER_DOUBLING: f64 = 150.0;

/// What a drag on a control point does.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DragUse {
    /// Moves the point on the view plane through it.
    #[default]
    Move,
    /// Twists about the curve (sideways).
    Twist,
    /// Scales across the curve (up: larger).
    Scale,
    /// Taps link control points of two handles.
    Link,
}

/// Where the tool is.
#[derive(Debug, Default)]
enum Stage {
    /// Drawing a stroke, or waiting for one.
    #[default]
    Idle,
    /// Dragging a control point.
    Dragging(Grab),
    /// A tap on a control point is under way (link, select): the rest of it is ignored.
    Tapped,
}

/// A control point being dragged: control point `point` of handle `handle`, at `at` in the
/// world, grabbed at `from` (viewport px) in the view of `camera` and `viewport`.
#[derive(Clone, Copy, Debug)]
struct Grab {
    handle: u32,
    point: usize,
    at: DVec3,
    from: DVec2,
    camera: Camera,
    viewport: DVec2,
}

/// The handles tool's state.
#[derive(Debug)]
pub struct HandlesTool {
    draw: DrawTool,
    kind: HandleKind,
    control_points: usize,
    is_rigid: bool,
    drag_use: DragUse,
    stage: Stage,
    /// The control point last tapped or dragged: linking starts from it, Delete removes its
    /// handle.
    selected: Option<(u32, usize)>,
}

impl Default for HandlesTool {
    fn default() -> Self {
        HandlesTool {
            draw: DrawTool::Idle,
            kind: HandleKind::Surface,
            control_points: 4,
            is_rigid: false,
            drag_use: DragUse::Move,
            stage: Stage::Idle,
            selected: None,
        }
    }
}

/// The control point of a handle of `doc` nearest `at` (viewport px) within [`GRAB_PX`].
pub fn control_point_at(
    doc: &Document,
    camera: &Camera,
    viewport: DVec2,
    at: DVec2,
) -> Option<(u32, usize, DVec3)> {
    let mut best: Option<(f64, u32, usize, DVec3)> = None;
    for handle in &doc.handles {
        for (k, &p) in handle.curve.points.iter().enumerate() {
            let Some(seen) = camera.screen_from_world(p, viewport) else {
                continue;
            };
            let d = seen.truncate().distance(at);
            if d <= GRAB_PX && best.is_none_or(|b| d < b.0) {
                best = Some((d, handle.id, k, p));
            }
        }
    }
    best.map(|(_, h, k, p)| (h, k, p))
}

impl HandlesTool {
    /// Feeds one event: strokes make handles, drags on control points edit them.
    pub fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        match std::mem::take(&mut self.stage) {
            Stage::Idle => self.idle(event, view, doc),
            Stage::Dragging(grab) => match event {
                ToolEvent::Move(s) => {
                    self.stage = Stage::Dragging(grab);
                    ToolOutput::Revise(self.edit(&grab, point(s, view).pos))
                }
                ToolEvent::End(s) => ToolOutput::FinishWith(self.edit(&grab, point(s, view).pos)),
                ToolEvent::Cancel => ToolOutput::Cancel,
                ToolEvent::Begin(_) => {
                    self.stage = Stage::Dragging(grab);
                    ToolOutput::None
                }
            },
            Stage::Tapped => {
                if matches!(event, ToolEvent::Move(_) | ToolEvent::Begin(_)) {
                    self.stage = Stage::Tapped;
                }
                ToolOutput::None
            }
        }
    }

    /// Waiting: a pointer down on a control point grabs (or, linking, taps) it; anything else
    /// draws a stroke that becomes a handle.
    fn idle(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        if let ToolEvent::Begin(s) = event
            && matches!(self.draw, DrawTool::Idle)
        {
            let size = view.viewport.size();
            let viewport = DVec2::new(size.x.into(), size.y.into());
            let from = point(s, view).pos;
            if let Some((handle, k, at)) = control_point_at(doc, &view.camera, viewport, from) {
                if self.drag_use == DragUse::Link {
                    self.stage = Stage::Tapped;
                    return self.link_to(handle, k);
                }
                self.selected = Some((handle, k));
                let grab = Grab {
                    handle,
                    point: k,
                    at,
                    from,
                    camera: view.camera,
                    viewport,
                };
                self.stage = Stage::Dragging(grab);
                return ToolOutput::Begin(self.edit(&grab, from));
            }
        }
        let Some(input) = self.draw.capture(event, view) else {
            return ToolOutput::None;
        };
        if is_tap(&input) {
            self.selected = None;
            return ToolOutput::None;
        }
        ToolOutput::Commit(Op::CurveHandle(CurveHandleInput {
            viewport: input.viewport,
            camera: input.camera,
            stroke: input.stroke,
            kind: self.kind,
            control_points: self.control_points,
            rigid: self.is_rigid,
        }))
    }

    /// A tap on a control point while linking: the first picks it, the second (on another
    /// handle) links the two.
    fn link_to(&mut self, handle: u32, k: usize) -> ToolOutput {
        match self.selected.take() {
            Some((first, j)) if first != handle => {
                ToolOutput::Commit(Op::LinkHandles(LinkHandlesInput {
                    a: (first, j),
                    b: (handle, k),
                }))
            }
            _ => {
                self.selected = Some((handle, k));
                ToolOutput::None
            }
        }
    }

    /// The edit of the grabbed control point for a drag from where it was grabbed to `to`
    /// (viewport px, y down).
    fn edit(&self, grab: &Grab, to: DVec2) -> Op {
        let offset = to - grab.from;
        let mut input = HandleEditInput {
            handle: grab.handle,
            point: grab.point,
            translate: None,
            twist_deg: None,
            scale: None,
            spread: 1,
        };
        match self.drag_use {
            DragUse::Move | DragUse::Link => {
                let moved = (grab.camera)
                    .point_on_plane_through(grab.at, to, grab.viewport)
                    .unwrap_or(grab.at);
                input.translate = Some((moved - grab.at).to_array());
            }
            DragUse::Twist => input.twist_deg = Some(offset.x * TWIST_DEG_PER_PX),
            DragUse::Scale => {
                let factor = (-offset.y / PX_PER_DOUBLING).exp2();
                input.scale = Some([factor, factor]);
            }
        }
        Op::HandleEdit(input)
    }

    /// Forgets the stroke and the drag (the app cancels its edit).
    pub fn cancel(&mut self) {
        self.draw = DrawTool::Idle;
        self.stage = Stage::Idle;
    }

    /// The stroke being drawn, for live display.
    pub fn preview(&self) -> Option<&[StrokePoint]> {
        self.draw.preview()
    }

    /// The selected control point (drawn highlighted).
    pub fn selected(&self) -> Option<(u32, usize)> {
        self.selected
    }

    /// What the tool asks the user to do next.
    pub fn hint(&self, doc: &Document) -> &'static str {
        match self.stage {
            Stage::Idle => {}
            Stage::Dragging(_) => return "Let go to keep the part where it is",
            Stage::Tapped => return "Lift to finish the tap",
        }
        match (self.drag_use, doc.handles.is_empty()) {
            (_, true) => {
                "Draw {with} along a part of a model or point cloud: it becomes a curve handle"
            }
            (DragUse::Link, _) if self.selected.is_some() => {
                "Now {tap} a dot of another handle to link them"
            }
            (DragUse::Link, _) => "{Tap} a dot of one handle, then a dot of another, to link them",
            (DragUse::Move, _) => {
                "Drag a handle's dot to bend the part; draw again for another handle"
            }
            (DragUse::Twist, _) => "Drag a handle's dot sideways to twist the part",
            (DragUse::Scale, _) => "Drag a handle's dot up to widen the part, down to narrow it",
        }
    }

    /// The panel: the kind of a new handle, its control points, rigid limbs, what a drag
    /// does, and Delete.
    pub fn settings_ui(&mut self, ui: &mut egui::Ui) -> ToolOutput {
        let size = target_size(ui);
        choice_ui(
            ui,
            &mut self.kind,
            [
                (
                    HandleKind::Surface,
                    "On surface",
                    "New handles lie on the surface under the stroke",
                ),
                (
                    HandleKind::Skeleton,
                    "Skeleton",
                    "New handles run inside, along the part's middle",
                ),
            ],
        );
        if ui
            .add(egui::Button::new("−").min_size(size))
            .on_hover_text("Fewer control points")
            .clicked()
        {
            self.control_points = (self.control_points - 1).max(2);
        }
        ui.label(format!("{} points", self.control_points));
        if ui
            .add(egui::Button::new("+").min_size(size))
            .on_hover_text("More control points")
            .clicked()
        {
            self.control_points = (self.control_points + 1).min(12);
        }
        let rigid = egui::Button::selectable(self.is_rigid, "Rigid").min_size(size);
        if ui
            .add(rigid)
            .on_hover_text("Straight limbs bent only at the control points")
            .clicked()
        {
            self.is_rigid = !self.is_rigid;
        }
        ui.separator();
        let drag_use = self.drag_use;
        choice_ui(
            ui,
            &mut self.drag_use,
            [
                (DragUse::Move, "Move", "Dragging a dot moves it"),
                (
                    DragUse::Twist,
                    "Twist",
                    "Dragging a dot sideways twists the part",
                ),
                (DragUse::Scale, "Scale", "Dragging a dot up widens the part"),
                (
                    DragUse::Link,
                    "Link",
                    "Tap dots of two handles to link them into a skeleton",
                ),
            ],
        );
        if self.drag_use != drag_use {
            self.selected = None;
        }
        let delete = ui.add_enabled(
            self.selected.is_some(),
            egui::Button::new("Delete handle").min_size(size),
        );
        if delete
            .on_hover_text("Remove the selected handle; the shape stays (Delete)")
            .clicked()
        {
            return self.delete_selected();
        }
        ToolOutput::None
    }

    /// Removes the selected handle (its button, or the Delete key).
    pub fn delete_selected(&mut self) -> ToolOutput {
        match self.selected.take() {
            Some((handle, _)) => ToolOutput::Commit(Op::DeleteHandle(DeleteHandleInput { handle })),
            None => ToolOutput::None,
        }
    }
}

/// Touch-sized buttons, one per choice, the current one selected; a press picks it.
fn choice_ui<T: Copy + PartialEq, const N: usize>(
    ui: &mut egui::Ui,
    current: &mut T,
    choices: [(T, &str, &str); N],
) {
    for (choice, label, hint) in choices {
        let button = egui::Button::selectable(*current == choice, label).min_size(target_size(ui));
        if ui.add(button).on_hover_text(hint).clicked() {
            *current = choice;
        }
    }
}

impl Tool for HandlesTool {
    fn info(&self) -> &'static ToolInfo {
        &INFO
    }

    fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        HandlesTool::on_event(self, event, view, doc)
    }

    fn cancel(&mut self) -> ToolOutput {
        HandlesTool::cancel(self);
        ToolOutput::None
    }

    fn panel(&mut self, ui: &mut egui::Ui, _doc: &Document) -> Option<ToolOutput> {
        Some(self.settings_ui(ui))
    }

    /// The curve handles, at the pose a drag previews.
    fn overlay(&self, ui: &egui::Ui, scene: &Scene<'_>) {
        let dragged = scene.edit.and_then(|edit| match edit.op() {
            Op::HandleEdit(input) => Some((input, edit.limited_move().unwrap_or(1.0))),
            _ => None,
        });
        let (viewport, camera) = (scene.viewport, &scene.camera);
        draw::curve_handles_ui(ui, viewport, scene.shown, camera, dragged, self.selected());
    }

    fn hint(&self, doc: &Document, device: Device) -> Hint {
        device.say(HandlesTool::hint(self, doc))
    }

    fn preview(&self) -> Option<&[StrokePoint]> {
        HandlesTool::preview(self)
    }

    /// Delete and Backspace delete the selected handle.
    fn keys(&self) -> &'static [egui::Key] {
        &[egui::Key::Delete, egui::Key::Backspace]
    }

    fn on_key(&mut self, _key: egui::Key, _doc: &Document) -> ToolOutput {
        self.delete_selected()
    }

    fn gesture_refused(&mut self) {
        HandlesTool::cancel(self);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_drag_up_doubles_the_scale_and_sideways_twists() {
        let mut tool = HandlesTool {
            drag_use: DragUse::Scale,
            ..HandlesTool::default()
        };
        let camera = Camera::default();
        let viewport = DVec2::new(800.0, 600.0);
        let centre = camera
            .screen_from_world(DVec3::ZERO, viewport)
            .unwrap()
            .truncate();
        let grab = Grab {
            handle: 0,
            point: 1,
            at: DVec3::ZERO,
            from: centre,
            camera,
            viewport,
        };
        let edit = |tool: &HandlesTool, offset: DVec2| match tool.edit(&grab, centre + offset) {
            Op::HandleEdit(input) => input,
            op => unreachable!("{op:?}"),
        };
        assert_eq!(edit(&tool, DVec2::new(0.0, -150.0)).scale, Some([2.0, 2.0]));
        tool.drag_use = DragUse::Twist;
        assert_eq!(edit(&tool, DVec2::new(90.0, 0.0)).twist_deg, Some(45.0));
        tool.drag_use = DragUse::Move;
        let t = DVec3::from(edit(&tool, DVec2::new(50.0, 0.0)).translate.unwrap());
        assert!(t.x > 0.0 && t.y.abs() < 1e-9, "{t}");
    }

    #[test]
    fn linking_takes_two_taps_on_different_handles() {
        let mut tool = HandlesTool {
            drag_use: DragUse::Link,
            ..HandlesTool::default()
        };
        assert_eq!(tool.link_to(0, 3), ToolOutput::None);
        assert_eq!(
            tool.link_to(0, 2),
            ToolOutput::None,
            "the same handle only re-selects"
        );
        let linked = tool.link_to(1, 0);
        assert_eq!(
            linked,
            ToolOutput::Commit(Op::LinkHandles(LinkHandlesInput {
                a: (0, 2),
                b: (1, 0)
            }))
        );
    }
}

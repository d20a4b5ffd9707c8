//! The move tool (issue 16): tap a model to select it; its handles (a ring to turn it, a
//! square to scale it, the inside of the ring or the model itself to move it) follow the
//! pen, a finger or the mouse with a live preview, and the release commits one `transform`
//! op. On a touch screen, two fingers on the selected model (or inside its ring) move, turn
//! and pinch-scale it at once, as a photo under two fingers ([`Gizmo::two_fingers`]);
//! elsewhere they navigate. Delete and Duplicate act on the selection, and Merge joins it
//! with the model it overlaps. With Symmetry on, Plane selects the symmetry plane instead:
//! its dot moves it, its ring turns it, and the release commits one `symmetry_plane` op.
//! The handles' geometry, and the matrix a drag makes, are core's ([`Gizmo`]).

mod icon;
mod mirror;

use glam::{DMat4, DVec2};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{
    Document, DuplicateInput, Gizmo, GizmoHandle, MergeInput, ModelInput, Op, PlaneInput,
    StrokeInput, TransformInput, model_under, overlapping_model,
};
use sketchmesh_core::model::MirrorPlane;

use crate::input::router::{Hands, ToolEvent};
use crate::tools::context::{ToolOutput, ViewCtx};
use crate::tools::draw::point;
use crate::tools::hint::{Device, Hint};
use crate::tools::tool::{Gestures, Group, Scene, Tool, ToolInfo};

/// The move tool's name, icon, key and description.
static INFO: ToolInfo = ToolInfo {
    label: "Arrange",
    icon: icon::draw,
    key: egui::Key::V,
    group: Group::Arrange,
    about: "Tap a model, then drag it, its ring or its square: move, turn, scale",
    gestures: Gestures {
        pen: "Tap a model, then drag it, its ring or its square",
        finger: "Tap a model; two fingers on it move, twist and pinch it",
        mouse: "Click a model, then drag it, its ring or its square",
    },
    when: None,
};

/// A press that moves less than this (px) before it lifts is a tap: it selects.
const TAP_RADIUS_PX: f64 = 10.0;

/// What holds the model in a drag.
#[derive(Clone, Copy, Debug)]
enum Grip {
    /// A handle (or the model, moving it), taken where the pointer went down.
    Handle(GizmoHandle, DVec2),
    /// Two fingers, where they went down.
    Fingers([DVec2; 2]),
}

/// What a drag moves: a model, or the symmetry plane as it was when taken.
#[derive(Clone, Copy, Debug)]
enum Target {
    Model(usize),
    Plane(MirrorPlane),
}

/// A drag of the selected model (or the plane) in progress.
#[derive(Clone, Copy, Debug)]
struct Drag {
    target: Target,
    grip: Grip,
    gizmo: Gizmo,
    camera: Camera,
    viewport: DVec2,
    matrix: DMat4,
}

impl Drag {
    /// The matrix the grip makes with the pointer at `to` (or the fingers at `fingers`).
    fn matrix_to(&self, to: To) -> DMat4 {
        match (self.grip, to) {
            (Grip::Handle(handle, from), To::Pointer(at)) => {
                (self.gizmo).drag(handle, &self.camera, self.viewport, from, at)
            }
            (Grip::Fingers(from), To::Fingers(at)) => {
                (self.gizmo).two_fingers(&self.camera, self.viewport, from, at)
            }
            _ => self.matrix,
        }
    }

    /// The op that puts the target where `matrix` takes it: a `transform` of the model, or
    /// the plane moved (kept where it was if the matrix is singular, which no drag makes).
    fn op(&self, matrix: DMat4) -> Op {
        match self.target {
            Target::Model(model) => transform(model, matrix),
            Target::Plane(plane) => Op::SymmetryPlane(PlaneInput {
                plane: plane.transformed(matrix).unwrap_or(plane),
            }),
        }
    }

    /// The handle being dragged, if a handle holds the model.
    fn handle(&self) -> Option<GizmoHandle> {
        match self.grip {
            Grip::Handle(handle, _) => Some(handle),
            Grip::Fingers(_) => None,
        }
    }
}

/// Where a drag's pointer or fingers are now.
#[derive(Clone, Copy, Debug)]
enum To {
    Pointer(DVec2),
    Fingers([DVec2; 2]),
}

/// The move tool's state.
#[derive(Clone, Debug, Default)]
pub struct ArrangeTool {
    /// The selected model's index, if any.
    selected: Option<usize>,
    /// Where a press that took no handle went down: it selects if it is a tap.
    press: Option<DVec2>,
    drag: Option<Drag>,
    /// Whether the symmetry plane is selected (Plane): its handles show instead of a model's.
    plane: bool,
    /// The view as last drawn (the overlay's): Duplicate places the copy toward its right.
    seen: std::cell::Cell<Camera>,
    /// Whether the view last drawn showed the symmetry plane (Symmetry on): Plane needs it.
    plane_shown: std::cell::Cell<bool>,
    /// Where the last drag of the plane left its ring, so that a turn does not move it.
    plane_pivot: Option<glam::DVec3>,
}

impl ArrangeTool {
    /// Feeds one event; see the module docs.
    pub fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        let size = view.viewport.size();
        let viewport = DVec2::new(size.x.into(), size.y.into());
        match event {
            ToolEvent::Begin(s) => {
                let at = point(s, view).pos;
                self.press = None;
                let Some(drag) = self.grab(doc, &view.camera, viewport, at) else {
                    self.press = Some(at);
                    return ToolOutput::None;
                };
                self.drag = Some(drag);
                ToolOutput::Begin(drag.op(DMat4::IDENTITY))
            }
            ToolEvent::Move(s) => self.drag_to(To::Pointer(point(s, view).pos)),
            ToolEvent::End(s) => {
                let at = point(s, view).pos;
                if let Some(drag) = self.drag.take() {
                    if let Grip::Handle(GizmoHandle::Move, from) = drag.grip
                        && at.distance(from) < TAP_RADIUS_PX
                    {
                        // A tap on the selected model: nothing moves.
                        return ToolOutput::Cancel;
                    }
                    let matrix = drag.matrix_to(To::Pointer(at));
                    if let Target::Plane(_) = drag.target {
                        self.plane_pivot = Some(matrix.transform_point3(drag.gizmo.pivot));
                    }
                    return ToolOutput::FinishWith(drag.op(matrix));
                }
                if let Some(down) = self.press.take()
                    && at.distance(down) < TAP_RADIUS_PX
                {
                    self.selected = model_at(doc, &view.camera, viewport, at);
                    self.plane = false;
                }
                ToolOutput::None
            }
            ToolEvent::Cancel => self.cancel(),
        }
    }

    /// Feeds two fingers the router offers or gives ([`Hands`]): on the selected model (or
    /// inside its ring) they take it, and the app gives them to the tool when this returns
    /// [`ToolOutput::Begin`]; see the module docs.
    pub fn on_hands(&mut self, hands: &Hands, view: &ViewCtx, doc: &Document) -> ToolOutput {
        let size = view.viewport.size();
        let viewport = DVec2::new(size.x.into(), size.y.into());
        let local = |p: egui::Pos2| {
            let l = p - view.viewport.min;
            DVec2::new(l.x.into(), l.y.into())
        };
        match *hands {
            Hands::Down(at) => {
                self.press = None;
                self.drag = None;
                let Some(drag) = self.two_finger_grab(doc, &view.camera, viewport, at.map(local))
                else {
                    return ToolOutput::None;
                };
                self.drag = Some(drag);
                ToolOutput::Begin(drag.op(DMat4::IDENTITY))
            }
            Hands::Move(at) => self.drag_to(To::Fingers(at.map(local))),
            Hands::Up => match self.drag.take() {
                Some(drag) if drag.matrix != DMat4::IDENTITY => {
                    ToolOutput::FinishWith(drag.op(drag.matrix))
                }
                Some(_) => ToolOutput::Cancel,
                None => ToolOutput::None,
            },
            Hands::Cancel => self.cancel(),
        }
    }

    /// The drag in progress moved on: its matrix, previewed.
    fn drag_to(&mut self, to: To) -> ToolOutput {
        match self.drag.as_mut() {
            Some(drag) => {
                drag.matrix = drag.matrix_to(to);
                ToolOutput::Revise(drag.op(drag.matrix))
            }
            None => ToolOutput::None,
        }
    }

    /// Two fingers down at `at` on the selected model (either finger over it, or their
    /// midpoint inside its ring), as a drag about to start.
    fn two_finger_grab(
        &self,
        doc: &Document,
        camera: &Camera,
        viewport: DVec2,
        at: [DVec2; 2],
    ) -> Option<Drag> {
        let model = self.selected.filter(|&i| i < doc.models.len())?;
        let gizmo = Gizmo::of(&doc.models[model], camera, viewport)?;
        let over = |p: DVec2| model_at(doc, camera, viewport, p) == Some(model);
        let inside_ring = (0.5 * (at[0] + at[1])).distance(gizmo.centre) <= gizmo.radius;
        (at.iter().any(|&p| over(p)) || inside_ring).then_some(Drag {
            target: Target::Model(model),
            grip: Grip::Fingers(at),
            gizmo,
            camera: *camera,
            viewport,
            matrix: DMat4::IDENTITY,
        })
    }

    /// The handle of the selected model under `at`, or the model itself (moving it), as a
    /// drag about to start; with the plane selected, its dot or ring.
    fn grab(&self, doc: &Document, camera: &Camera, viewport: DVec2, at: DVec2) -> Option<Drag> {
        if let Some((plane, gizmo)) = self.plane_gizmo(doc, camera, viewport) {
            let handle = gizmo.handle_at(at).filter(|&h| h != GizmoHandle::Scale)?;
            return Some(Drag {
                target: Target::Plane(plane),
                grip: Grip::Handle(handle, at),
                gizmo,
                camera: *camera,
                viewport,
                matrix: DMat4::IDENTITY,
            });
        }
        let model = self.selected.filter(|&i| i < doc.models.len())?;
        let gizmo = Gizmo::of(&doc.models[model], camera, viewport)?;
        let handle = gizmo.handle_at(at).or_else(|| {
            (model_at(doc, camera, viewport, at) == Some(model)).then_some(GizmoHandle::Move)
        })?;
        Some(Drag {
            target: Target::Model(model),
            grip: Grip::Handle(handle, at),
            gizmo,
            camera: *camera,
            viewport,
            matrix: DMat4::IDENTITY,
        })
    }

    /// Whether Plane is selected and the plane shown (Symmetry on): its handles then act.
    fn is_plane_picked(&self) -> bool {
        self.plane && self.plane_shown.get()
    }

    /// The symmetry plane and its handles, when Plane is selected and the plane shown.
    fn plane_gizmo(
        &self,
        doc: &Document,
        camera: &Camera,
        viewport: DVec2,
    ) -> Option<(MirrorPlane, Gizmo)> {
        if !self.is_plane_picked() {
            return None;
        }
        let plane = doc.symmetry.unwrap_or_default();
        let gizmo = Gizmo::of_plane(&plane, self.plane_pivot, doc, camera, viewport)?;
        Some((plane, gizmo))
    }

    /// Drops a drag in progress.
    pub fn cancel(&mut self) -> ToolOutput {
        self.press = None;
        match self.drag.take() {
            Some(_) => ToolOutput::Cancel,
            None => ToolOutput::None,
        }
    }

    /// The handles to draw: those of the selected model as it is shown (moved by the drag in
    /// progress), with the handle being dragged.
    pub fn gizmo(
        &self,
        doc: &Document,
        camera: &Camera,
        viewport: DVec2,
    ) -> Option<(Gizmo, Option<GizmoHandle>)> {
        if let Some(drag) = &self.drag {
            let moved = drag.matrix.transform_point3(drag.gizmo.pivot);
            let centre = camera.screen_from_world(moved, viewport)?.truncate();
            let scale = drag.matrix.transform_vector3(glam::DVec3::X).length();
            let gizmo = Gizmo {
                pivot: moved,
                centre,
                radius: drag.gizmo.radius * scale,
            };
            return Some((gizmo, drag.handle()));
        }
        if let Some((_, gizmo)) = self.plane_gizmo(doc, camera, viewport) {
            return Some((gizmo, None));
        }
        let model = self.selected.filter(|&i| i < doc.models.len())?;
        Some((Gizmo::of(&doc.models[model], camera, viewport)?, None))
    }

    /// What the tool asks the user to do next.
    pub fn hint(&self, doc: &Document, device: Device) -> Hint {
        let two_fingers = match device {
            Device::Mouse => "",
            Device::Pen | Device::Finger => "; or twist and pinch with two fingers",
        };
        if self.is_plane_picked() {
            return match self.drag {
                None => device.say(
                    "Drag the plane's dot to move it, its ring to turn it about the view's axis \
                     (turn the view to turn it another way)",
                ),
                Some(_) => device.say("Let go to keep the plane there"),
            };
        }
        match self.selected.filter(|&i| i < doc.models.len()) {
            None if self.plane_shown.get() => device.say(
                "{Tap} a model to move, turn or scale it, or Plane to move the symmetry plane",
            ),
            None => device.say("{Tap} a model to move, turn or scale it"),
            Some(_) if self.drag.is_none() => device.say(format!(
                "Drag the model to move it, the ring to turn it, the square to scale it{two_fingers}. \
                 To merge, move it into another until they overlap, then Merge"
            )),
            Some(_) => device.say("Let go to keep it there"),
        }
    }

    /// The panel: Delete, Duplicate and Merge for the selection, then Mirror, Mirrored
    /// duplicate and Symmetrize ([`mirror::symmetry_ui`]).
    pub fn settings_ui(&mut self, ui: &mut egui::Ui, doc: &Document) -> ToolOutput {
        let selected = self.selected.filter(|&i| i < doc.models.len());
        let size = egui::vec2(44.0, 44.0);
        let delete = ui.add_enabled(
            selected.is_some(),
            egui::Button::new("Delete").min_size(size),
        );
        if delete
            .on_hover_text("Delete the selected model (Delete)")
            .clicked()
        {
            return self.delete(doc);
        }
        let duplicate = ui.add_enabled(
            selected.is_some(),
            egui::Button::new("Duplicate").min_size(size),
        );
        if duplicate
            .on_hover_text("Add a copy beside the selected model")
            .clicked()
            && let Some(model) = selected
        {
            self.selected = Some(doc.models.len());
            // A copy beside, Symmetry on or off: "Mirrored duplicate" makes the twin.
            return ToolOutput::CommitAsMade(Op::Duplicate(DuplicateInput {
                model,
                beside: Some(self.seen.get().frame().right.to_array()),
            }));
        }
        let partner = selected.and_then(|model| Some((model, overlapping_model(doc, model)?)));
        let merge = ui.add_enabled(partner.is_some(), egui::Button::new("Merge").min_size(size));
        if merge
            .on_hover_text("Join the selected model with the one it overlaps")
            .on_disabled_hover_text("Move the selected model into another to merge them")
            .clicked()
            && let Some((model, other)) = partner
        {
            self.selected = Some(model.min(other));
            return ToolOutput::Commit(Op::Merge(MergeInput {
                models: [model, other],
            }));
        }
        ui.separator();
        let plane = ui.add_enabled(
            self.plane_shown.get(),
            egui::Button::selectable(self.plane, "Plane").min_size(size),
        );
        if plane
            .on_hover_text("Move or turn the symmetry plane with its handles")
            .on_disabled_hover_text("Turn Symmetry on to see the plane")
            .clicked()
        {
            self.plane ^= true;
            self.plane_pivot = None;
            self.selected = self.selected.filter(|_| !self.plane);
        }
        match mirror::symmetry_ui(ui, doc, selected, &self.seen.get(), size) {
            Some(picked) => {
                self.selected = Some(picked.select);
                picked.output
            }
            None => ToolOutput::None,
        }
    }

    /// Deletes the selected model, if any.
    pub fn delete(&mut self, doc: &Document) -> ToolOutput {
        match self.selected.take().filter(|&i| i < doc.models.len()) {
            Some(model) => ToolOutput::Commit(Op::Delete(ModelInput { model })),
            None => ToolOutput::None,
        }
    }
}

/// A `transform` op of `model` by `matrix`.
fn transform(model: usize, matrix: DMat4) -> Op {
    Op::Transform(TransformInput {
        model,
        matrix: matrix.to_cols_array(),
    })
}

/// The model nearest the eye under `at`, if any.
fn model_at(doc: &Document, camera: &Camera, viewport: DVec2, at: DVec2) -> Option<usize> {
    let tap = StrokeInput {
        viewport: viewport.to_array(),
        camera: *camera,
        stroke: vec![[at.x, at.y, 0.5]],
    };
    model_under(doc, &tap)
}

impl Tool for ArrangeTool {
    fn info(&self) -> &'static ToolInfo {
        &INFO
    }

    fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        ArrangeTool::on_event(self, event, view, doc)
    }

    fn on_hands(&mut self, hands: &Hands, view: &ViewCtx, doc: &Document) -> ToolOutput {
        ArrangeTool::on_hands(self, hands, view, doc)
    }

    fn cancel(&mut self) -> ToolOutput {
        ArrangeTool::cancel(self)
    }

    fn panel(&mut self, ui: &mut egui::Ui, doc: &Document) -> Option<ToolOutput> {
        Some(self.settings_ui(ui, doc))
    }

    /// The handles around the selected model: the ring that turns it, the square that
    /// scales it, a dot at its middle; the one being dragged is drawn brighter.
    fn overlay(&self, ui: &egui::Ui, scene: &Scene<'_>) {
        self.seen.set(scene.camera);
        self.plane_shown.set(scene.symmetry.is_some());
        let Some((gizmo, dragged)) = self.gizmo(scene.doc, &scene.camera, scene.size()) else {
            return;
        };
        let scales = match self.drag {
            Some(drag) => matches!(drag.target, Target::Model(_)),
            None => !self.plane,
        };
        let colour = |handle| match dragged == Some(handle) {
            true => egui::Color32::from_rgb(255, 214, 120),
            false => egui::Color32::from_rgb(240, 160, 60),
        };
        let painter = ui.painter();
        painter.circle_stroke(
            scene.at(gizmo.centre),
            gizmo.radius as f32,
            egui::Stroke::new(5.0, colour(GizmoHandle::Turn)),
        );
        painter.circle_filled(scene.at(gizmo.centre), 7.0, colour(GizmoHandle::Move));
        if scales {
            let size = egui::vec2(22.0, 22.0);
            let square = egui::Rect::from_center_size(scene.at(gizmo.scale_handle()), size);
            painter.rect_filled(square, 3.0, colour(GizmoHandle::Scale));
        }
    }

    fn hint(&self, doc: &Document, device: Device) -> Hint {
        ArrangeTool::hint(self, doc, device)
    }

    /// Delete and Backspace delete the selected model.
    fn keys(&self) -> &'static [egui::Key] {
        &[egui::Key::Delete, egui::Key::Backspace]
    }

    fn on_key(&mut self, _key: egui::Key, doc: &Document) -> ToolOutput {
        self.delete(doc)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::Phase;
    use crate::tools::test_support::{pen, shape, view};

    fn event(tool: &mut ArrangeTool, doc: &Document, event: ToolEvent) -> ToolOutput {
        tool.on_event(&event, &view(), doc)
    }

    fn tap(tool: &mut ArrangeTool, doc: &Document, x: f32, y: f32) -> ToolOutput {
        event(tool, doc, ToolEvent::Begin(pen(Phase::Down, x, y)));
        event(tool, doc, ToolEvent::End(pen(Phase::Up, x, y)))
    }

    #[test]
    fn a_tap_selects_and_a_drag_of_the_model_previews_then_commits_a_move() {
        let editor = shape();
        let doc = editor.document();
        let mut tool = ArrangeTool::default();
        assert!(
            tool.gizmo(doc, &Camera::default(), DVec2::new(800.0, 600.0))
                .is_none()
        );
        assert_eq!(tap(&mut tool, doc, 400.0, 340.0), ToolOutput::None);
        let (gizmo, dragged) = tool
            .gizmo(doc, &Camera::default(), DVec2::new(800.0, 600.0))
            .unwrap();
        assert!((gizmo.centre - DVec2::new(400.0, 300.0)).length() < 1.0);
        assert_eq!(dragged, None);
        let begun = event(
            &mut tool,
            doc,
            ToolEvent::Begin(pen(Phase::Down, 420.0, 340.0)),
        );
        assert!(
            matches!(begun, ToolOutput::Begin(Op::Transform(_))),
            "{begun:?}"
        );
        let revised = event(
            &mut tool,
            doc,
            ToolEvent::Move(pen(Phase::Move, 470.0, 340.0)),
        );
        let ToolOutput::Revise(Op::Transform(input)) = revised else {
            panic!("expected a revised transform, got {revised:?}");
        };
        assert!(
            input.matrix[12] > 0.0 && input.matrix[13].abs() < 1e-9,
            "moves right"
        );
        let ended = event(&mut tool, doc, ToolEvent::End(pen(Phase::Up, 520.0, 340.0)));
        let ToolOutput::FinishWith(Op::Transform(last)) = ended else {
            panic!("expected the committed transform, got {ended:?}");
        };
        assert!(last.matrix[12] > input.matrix[12]);
    }

    #[test]
    fn two_fingers_on_the_selected_model_turn_and_pinch_it_and_elsewhere_are_not_taken() {
        let editor = shape();
        let doc = editor.document();
        let mut tool = ArrangeTool::default();
        let v = view();
        let hands = |tool: &mut ArrangeTool, h: Hands| tool.on_hands(&h, &v, doc);
        let (a, b) = (egui::pos2(360.0, 340.0), egui::pos2(440.0, 340.0));
        assert_eq!(
            hands(&mut tool, Hands::Down([a, b])),
            ToolOutput::None,
            "nothing selected"
        );
        tap(&mut tool, doc, 400.0, 340.0);
        let far = [egui::pos2(20.0, 60.0), egui::pos2(90.0, 60.0)];
        assert_eq!(
            hands(&mut tool, Hands::Down(far)),
            ToolOutput::None,
            "beside the model"
        );
        let begun = hands(&mut tool, Hands::Down([a, b]));
        assert!(
            matches!(begun, ToolOutput::Begin(Op::Transform(_))),
            "{begun:?}"
        );
        // A quarter turn, the fingers spread to 1.5 times as far apart.
        let turned = [egui::pos2(400.0, 280.0), egui::pos2(400.0, 400.0)];
        let revised = hands(&mut tool, Hands::Move(turned));
        let ToolOutput::Revise(Op::Transform(input)) = revised else {
            panic!("expected a revised transform, got {revised:?}");
        };
        let m = glam::DMat4::from_cols_array(&input.matrix);
        assert!((m.transform_vector3(glam::DVec3::X).length() - 1.5).abs() < 1e-9);
        let x = m.transform_vector3(glam::DVec3::X);
        assert!(
            x.x.abs() < 1e-9 && x.y < 0.0,
            "x turns to screen down (world -y): {x}"
        );
        let ended = hands(&mut tool, Hands::Up);
        assert!(
            matches!(ended, ToolOutput::FinishWith(Op::Transform(_))),
            "{ended:?}"
        );
        // Two fingers that come down and lift without moving change nothing.
        hands(&mut tool, Hands::Down([a, b]));
        assert_eq!(hands(&mut tool, Hands::Up), ToolOutput::Cancel);
    }

    #[test]
    fn a_tap_on_empty_canvas_deselects_and_delete_needs_a_selection() {
        let editor = shape();
        let doc = editor.document();
        let mut tool = ArrangeTool::default();
        assert_eq!(tool.delete(doc), ToolOutput::None);
        tap(&mut tool, doc, 400.0, 340.0);
        tap(&mut tool, doc, 760.0, 80.0);
        assert!(
            tool.gizmo(doc, &Camera::default(), DVec2::new(800.0, 600.0))
                .is_none()
        );
        // Without a selection a drag on the model is no edit: it may be a tap.
        let pressed = event(
            &mut tool,
            doc,
            ToolEvent::Begin(pen(Phase::Down, 400.0, 340.0)),
        );
        assert_eq!(pressed, ToolOutput::None);
        event(&mut tool, doc, ToolEvent::End(pen(Phase::Up, 400.0, 340.0)));
        let deleted = tool.delete(doc);
        assert!(matches!(
            deleted,
            ToolOutput::Commit(Op::Delete(ModelInput { model: 0 }))
        ));
    }

    #[test]
    fn a_tap_on_the_selected_model_moves_nothing() {
        let editor = shape();
        let doc = editor.document();
        let mut tool = ArrangeTool::default();
        tap(&mut tool, doc, 400.0, 340.0);
        assert!(matches!(
            tap(&mut tool, doc, 400.0, 340.0),
            ToolOutput::Cancel
        ));
    }
}

//! The pose tool (Zhou et al. 2005, §4): bend a model by a control curve, keeping its
//! volume, and key its poses into an animation.
//!
//! A closed loop drawn first (off the curve) holds still what it surrounds. A stroke along
//! a model picks the control curve (the edge path under it) and the view turns to face the
//! curve's editing plane, side on to the surface; the next stroke is the curve's new shape:
//! it begins a `curve_deform` edit as a gesture at pointer-down, each sample extends it (the
//! core back-substitutes, so the model follows the pen), and release commits it. The panel
//! keys the pose at a time, deletes a key, puts the models in their pose at a time (**Pose
//! at**: to edit a pose between keys, or to start each frame of a retargeted motion from the
//! rest pose), and plays the animation.

mod icon;

use crate::ui_size::target_size;
use glam::DVec3;
use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::bspline::{uniform_knots, with_widest_span_split};
use sketchmesh_core::curve::{StrokePoint, is_closed_loop};
use sketchmesh_core::document::{
    CLOSE_TOLERANCE_PX, CoarseInput, CurveDeformInput, Document, KeyframeInput, Op, StrokeInput,
    model_under,
};
use sketchmesh_core::feature::Sketch;
use sketchmesh_core::mesh::VertexId;
use sketchmesh_core::volumetric::{
    COARSE_CONTROLS, CoarsePlaneCurve, Falloff, Plane, editing_plane, pick_curve,
};

use crate::input::router::ToolEvent;
use crate::overlay::outline_ui;
use crate::tools::context::{ToolOutput, ViewCtx};
use crate::tools::draw::{DrawTool, is_tap, point};
use crate::tools::hint::{Device, Hint};
use crate::tools::tool::{Gestures, Group, Mark, Scene, Tool, ToolInfo};

/// The pose tool's name, icon, key and description.
static INFO: ToolInfo = ToolInfo {
    label: "Pose",
    icon: icon::draw,
    key: egui::Key::Q,
    group: Group::Animate,
    about: "Draw a curve along a model, then its new shape: it bends keeping its volume; key poses, play",
    gestures: Gestures {
        pen: "Draw along a limb, then draw its new shape",
        finger: "Draw along a limb, then draw its new shape",
        mouse: "Left-drag along a limb, then its new shape",
    },
    when: Some("To bend a limb keeping its volume, and to key poses for an animation"),
};

/// Seconds the time moves on after a key, so the next pose goes after it.
const KEY_STEP_S: f64 = 1.0;

/// A picked control curve: its vertices on its model (a deformation keeps them, so the curve
/// can be redrawn again and again) and its editing plane.
#[derive(Clone, Debug)]
struct PoseCurve {
    model: usize,
    path: Vec<u32>,
    /// The editing plane: chosen for the curve when picked, or turned by the user.
    plane: Plane,
    /// The interior knots of its coarse spline.
    knots: Vec<f64>,
}

impl PoseCurve {
    /// Whether the curve still lies on its model: the model is there and the curve's
    /// vertices are still joined by edges (an undo past its model or a remesh breaks that).
    fn fits(&self, doc: &Document) -> bool {
        let Some(model) = doc.models.get(self.model) else {
            return false;
        };
        let mesh = &model.mesh;
        let n = mesh.n_vertices() as u32;
        self.path.iter().all(|&v| v < n)
            && (self.path.windows(2))
                .all(|w| mesh.find_edge(VertexId(w[0]), VertexId(w[1])).is_some())
    }

    /// The curve's vertices' positions in `doc`, or where its model is drawn when it is
    /// among the `moved` (by an edit in progress, or posed by the animation playing).
    fn points(&self, doc: &Document, moved: Moved) -> Vec<DVec3> {
        match moved.iter().find(|(model, _)| *model == self.model) {
            Some((_, positions)) => self.path.iter().map(|&v| positions[v as usize]).collect(),
            None => {
                let mesh = &doc.models[self.model].mesh;
                self.path
                    .iter()
                    .map(|&v| mesh.position(VertexId(v)))
                    .collect()
            }
        }
    }

    /// Its coarse spline's control points where the curve is (fitted to it, as the op
    /// fits it: on the plane through the curve's centroid); none if the fit fails.
    fn controls(&self, doc: &Document, moved: Moved) -> Vec<DVec3> {
        let points = self.points(doc, moved);
        let origin = points.iter().sum::<DVec3>() / points.len().max(1) as f64;
        let plane = Plane {
            origin,
            ..self.plane
        };
        CoarsePlaneCurve::new(&points, &plane, &self.knots)
            .map(|coarse| coarse.controls())
            .unwrap_or_default()
    }
}

/// How near (CSS px) a pointer must come down to a control point to drag it: a fingertip.
const GRAB_PX: f64 = 28.0;

/// The models drawn elsewhere than the document has them (see
/// [`crate::tools::Scene::moved_models`]), and where their vertices are shown.
pub type Moved<'a> = &'a [(usize, &'a [DVec3])];

/// How far **Turn plane** turns the editing plane about the curve's chord.
const PLANE_TURN_DEG: f64 = 45.0;

/// The pose tool's state.
#[derive(Debug, Default)]
pub struct PoseTool {
    draw: DrawTool,
    /// The loop around what holds still, as drawn.
    fixed: Option<StrokeInput>,
    /// The picked curves: the active one is redrawn, the others on its model hold.
    curves: Vec<PoseCurve>,
    active: Option<usize>,
    /// Whether the next stroke along a model picks another curve.
    adding: bool,
    /// Whether the curve's new shape is being drawn (a gesture).
    reshaping: bool,
    /// Whether the curve is reshaped by its spline's control points, not by a sketch.
    spline: bool,
    falloff: Falloff,
    /// The time the next key goes at (s).
    time: f64,
    /// Whether the animation plays: the panel's Play is then Stop.
    is_playing: bool,
}

impl PoseTool {
    /// Feeds one event: strokes make the loop, the curves and their new shapes.
    pub fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        self.forget_stale(doc);
        if self.active.is_some() && !self.adding {
            return self.reshape(event, view, doc);
        }
        let Some(input) = self.draw.capture(event, view) else {
            return ToolOutput::None;
        };
        if is_tap(&input) {
            return ToolOutput::None;
        }
        if model_under(doc, &input).is_none() {
            if is_closed_loop(&input.points(), CLOSE_TOLERANCE_PX) {
                self.fixed = Some(input);
                return ToolOutput::None;
            }
            return ToolOutput::Refused(String::from(
                "Draw the control curve along a model, from one end to the other.",
            ));
        }
        self.pick(doc, input)
    }

    /// Drops the curves that no longer lie on their models.
    fn forget_stale(&mut self, doc: &Document) {
        let active = self.active.map(|k| self.curves[k].clone());
        self.curves.retain(|c| c.fits(doc));
        self.active = active.and_then(|a| {
            (self.curves.iter()).position(|c| c.model == a.model && c.path == a.path)
        });
    }

    /// Picks the curve under `input`, makes it the active one and turns the view to its
    /// editing plane.
    fn pick(&mut self, doc: &Document, input: StrokeInput) -> ToolOutput {
        let Some(model) = model_under(doc, &input) else {
            return ToolOutput::None;
        };
        let mesh = &doc.models[model].mesh;
        let sketch = Sketch {
            camera: input.camera,
            viewport: input.viewport_size(),
            points: input.points().iter().map(|p| p.pos).collect(),
            region: None,
        };
        match pick_curve(mesh, &sketch) {
            Ok(path) => {
                let plane = editing_plane(mesh, &path);
                self.curves.push(PoseCurve {
                    model,
                    path: path.iter().map(|v| v.0).collect(),
                    plane,
                    knots: uniform_knots(COARSE_CONTROLS),
                });
                self.select(self.curves.len() - 1)
            }
            Err(err) => ToolOutput::Refused(err.to_string()),
        }
    }

    /// Makes curve `k` the one redrawn and turns the view to its plane.
    fn select(&mut self, k: usize) -> ToolOutput {
        self.active = Some(k);
        self.adding = false;
        let plane = self.curves[k].plane;
        ToolOutput::Face {
            point: plane.origin,
            normal: plane.normal,
        }
    }

    /// The new shape's stroke, or a control point's drag: a gesture whose samples the edit
    /// follows.
    fn reshape(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        let sample = |s| {
            let p = point(s, view);
            [p.pos.x, p.pos.y, p.pressure]
        };
        match event {
            ToolEvent::Begin(s) => {
                let first = sample(s);
                let coarse = if self.spline {
                    let Some(control) = self.grabbed(doc, view, first) else {
                        return ToolOutput::Refused(String::from(
                            "Drag one of the curve's round control points (+ Knot adds one), or turn Spline off to redraw the curve.",
                        ));
                    };
                    Some(control)
                } else {
                    None
                };
                match self.deform(view, first, coarse) {
                    Some(op) => {
                        self.reshaping = true;
                        ToolOutput::Begin(op)
                    }
                    None => ToolOutput::None,
                }
            }
            ToolEvent::Move(s) if self.reshaping => ToolOutput::Extend(sample(s)),
            ToolEvent::End(s) if self.reshaping => {
                self.reshaping = false;
                ToolOutput::End(sample(s))
            }
            ToolEvent::Cancel if self.reshaping => {
                self.reshaping = false;
                ToolOutput::Cancel
            }
            _ => ToolOutput::None,
        }
    }

    /// The active curve's control point nearest the screen point `at`, when it is within
    /// [`GRAB_PX`].
    fn grabbed(&self, doc: &Document, view: &ViewCtx, at: [f64; 3]) -> Option<usize> {
        let curve = &self.curves[self.active?];
        let size = view.viewport.size();
        let size = glam::DVec2::new(size.x.into(), size.y.into());
        let at = glam::DVec2::new(at[0], at[1]);
        (curve.controls(doc, &[]).iter().enumerate())
            .filter_map(|(k, &c)| {
                let s = view.camera.screen_from_world(c, size)?.truncate();
                Some((k, s.distance(at)))
            })
            .filter(|&(_, d)| d <= GRAB_PX)
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(k, _)| k)
    }

    /// The op that gives the active curve the shape of a stroke drawn in `view`, begun with
    /// `first` (with `coarse`, the drag of that control point of its spline); the other
    /// curves on its model hold, and so does what the loop surrounds.
    fn deform(&self, view: &ViewCtx, first: [f64; 3], coarse: Option<usize>) -> Option<Op> {
        let active = self.active?;
        let curve = &self.curves[active];
        let held = (self.curves.iter().enumerate())
            .filter(|&(k, c)| k != active && c.model == curve.model)
            .map(|(_, c)| c.path.clone())
            .collect();
        let size = view.viewport.size();
        let here = [f64::from(size.x), f64::from(size.y)];
        let fixed = self.fixed.as_ref().filter(|f| f.viewport == here);
        let camera = fixed.map_or(view.camera, |f| f.camera);
        Some(Op::CurveDeform(CurveDeformInput {
            model: curve.model,
            viewport: here,
            camera,
            curve: Vec::new(),
            path: Some(curve.path.clone()),
            held,
            stroke: vec![first],
            stroke_camera: (view.camera != camera).then_some(view.camera),
            plane: Some(curve.plane.normal.to_array()),
            fixed: fixed.map(|f| f.stroke.clone()),
            falloff: self.falloff,
            coarse: coarse.map(|control| CoarseInput {
                knots: curve.knots.clone(),
                control,
            }),
        }))
    }

    /// Turns the active curve's editing plane by [`PLANE_TURN_DEG`] about the curve's chord
    /// (its ends' join), and the view to face it.
    fn turn_plane(&mut self, doc: &Document) -> ToolOutput {
        let Some(curve) = self.active.map(|k| &mut self.curves[k]) else {
            return ToolOutput::None;
        };
        let points = curve.points(doc, &[]);
        let (first, last) = (points[0], points[points.len() - 1]);
        let Some(axis) = (last - first).try_normalize() else {
            return ToolOutput::None;
        };
        let turn = glam::DQuat::from_axis_angle(axis, PLANE_TURN_DEG.to_radians());
        curve.plane.normal = (turn * curve.plane.normal).normalize();
        ToolOutput::Face {
            point: curve.plane.origin,
            normal: curve.plane.normal,
        }
    }

    /// Forgets the loop, the curves and the stroke.
    pub fn cancel(&mut self) {
        *self = PoseTool {
            falloff: self.falloff,
            time: self.time,
            ..PoseTool::default()
        };
    }

    /// The stroke being drawn, for live display.
    pub fn preview(&self) -> Option<&[StrokePoint]> {
        self.draw.preview()
    }

    /// The picked curves' points in `doc`, or on the model an edit in progress `moves`, to
    /// draw over the models, each with whether it is the one redrawn.
    pub fn curves(&self, doc: &Document, moved: Moved) -> Vec<(Vec<DVec3>, bool)> {
        (self.curves.iter().enumerate())
            .filter(|(_, c)| c.fits(doc))
            .map(|(k, c)| (c.points(doc, moved), self.active == Some(k)))
            .collect()
    }

    /// The active curve's spline control points in `doc` (or as an edit in progress `moves`
    /// them), to draw, while the curve is reshaped by them.
    pub fn controls(&self, doc: &Document, moved: Moved) -> Vec<DVec3> {
        match self.active.map(|k| &self.curves[k]) {
            Some(curve) if self.spline && curve.fits(doc) => curve.controls(doc, moved),
            _ => Vec::new(),
        }
    }

    /// The loop around what holds still, while the view is the one it was drawn in.
    pub fn marks(&self, camera: &Camera) -> Vec<Mark> {
        (self.fixed.iter())
            .filter(|f| f.camera == *camera)
            .map(|f| Mark {
                points: f.points(),
                radius: None,
                features: false,
            })
            .collect()
    }

    /// What the tool asks the user to do next.
    pub fn hint(&self) -> &'static str {
        match (self.active, self.adding, &self.fixed) {
            (None, _, None) if self.curves.is_empty() => {
                "Draw a control curve {with} along a model (a closed loop off it first holds a part still)"
            }
            (Some(_), false, _) if self.spline => {
                "Drag the curve's control points; the model bends and keeps its volume"
            }
            (Some(_), false, _) => {
                "Draw the curve's new shape; the model bends and keeps its volume (+ Curve picks another)"
            }
            (_, true, _) => {
                "Draw another control curve along the model; the others hold their place"
            }
            _ => "Now draw the control curve along the model",
        }
    }

    /// The picked curves' buttons (which one is redrawn), **+ Curve**, **Clear**, **Spline**,
    /// **+ Knot**, and the **⋯** menu (turn the plane, the backdrop).
    fn curves_ui(&mut self, ui: &mut egui::Ui, doc: &Document) -> ToolOutput {
        let button_size = wide_target(ui);
        let mut output = ToolOutput::None;
        for k in 0..self.curves.len() {
            let chosen = self.active == Some(k) && !self.adding;
            let button =
                egui::Button::selectable(chosen, format!("Curve {}", k + 1)).min_size(button_size);
            if ui
                .add(button)
                .on_hover_text("Redraw this curve; the others hold their place")
                .clicked()
            {
                output = self.select(k);
            }
        }
        let add = ui.add_enabled(
            !self.curves.is_empty(),
            egui::Button::selectable(self.adding, "+ Curve").min_size(button_size),
        );
        if add
            .on_hover_text("Draw another control curve; the picked ones hold their place")
            .clicked()
        {
            self.adding = !self.adding;
        }
        let clear = ui.add_enabled(
            !self.curves.is_empty() || self.fixed.is_some(),
            egui::Button::new("Clear"),
        );
        if clear
            .on_hover_text("Forget the picked curves and the held part")
            .clicked()
        {
            self.cancel();
        }
        let spline = egui::Button::selectable(self.spline, "Spline").min_size(button_size);
        if ui
            .add(spline)
            .on_hover_text(
                "Drag the control points of the curve's coarse shape, its detail kept (off: draw the whole new shape)",
            )
            .clicked()
        {
            self.spline = !self.spline;
        }
        let knot = ui.add_enabled(
            self.spline && self.active.is_some(),
            egui::Button::new("+ Knot").min_size(button_size),
        );
        if knot
            .on_hover_text("One more control point, in the widest span")
            .clicked()
            && let Some(curve) = self.active.map(|k| &mut self.curves[k])
        {
            curve.knots = with_widest_span_split(&curve.knots);
        }
        // The menu's own ui has the context's style, not the toolbar's: take the size here.
        let height = target_size(ui).y;
        let more = egui::Button::new("⋯").min_size(target_size(ui));
        egui::containers::menu::MenuButton::from_button(more)
            .ui(ui, |ui| {
                let item = |label| egui::Button::new(label).min_size(egui::vec2(140.0, height));
                let turn = ui.add_enabled(self.active.is_some(), item("Turn plane"));
                if turn
                    .on_hover_text("Turn the editing plane about the curve by 45°")
                    .clicked()
                {
                    output = self.turn_plane(doc);
                }
                let hint = "Show an image over the view, to trace a motion's frames";
                if ui.add(item("Backdrop…")).on_hover_text(hint).clicked() {
                    output = ToolOutput::Backdrop(true);
                }
                if ui.add(item("No backdrop")).clicked() {
                    output = ToolOutput::Backdrop(false);
                }
            })
            .0
            .on_hover_text("Turn the plane; a backdrop image to trace");
        output
    }

    /// The panel: the fall-off, the curves, and the timeline's key, delete and play.
    pub fn settings_ui(&mut self, ui: &mut egui::Ui, doc: &Document) -> ToolOutput {
        let button_size = wide_target(ui);
        let falloffs = [
            (
                Falloff::Linear,
                "Linear",
                "The bend spreads evenly toward what holds still",
            ),
            (
                Falloff::Gaussian,
                "Smooth",
                "The bend gathers near the curve",
            ),
            (
                Falloff::Constant,
                "Rigid",
                "Everything the curve reaches turns with it",
            ),
        ];
        let chosen = falloffs.iter().find(|f| f.0 == self.falloff);
        egui::ComboBox::from_id_salt("pose falloff")
            .selected_text(chosen.map_or("", |f| f.1))
            .height(200.0)
            .show_ui(ui, |ui| {
                for (falloff, label, hint) in falloffs {
                    ui.selectable_value(&mut self.falloff, falloff, label)
                        .on_hover_text(hint);
                }
            })
            .response
            .on_hover_text("How the bend fades toward what holds still")
            .widget_info(|| egui::WidgetInfo::labeled(egui::Role::ComboBox, true, "pose fall-off"));
        ui.separator();
        let mut output = ToolOutput::None;
        ui.add(
            egui::DragValue::new(&mut self.time)
                .range(0.0..=600.0)
                .speed(0.1)
                .suffix(" s"),
        )
        .on_hover_text("The time of the next key");
        let has_models = !doc.models.is_empty();
        let key = ui.add_enabled(has_models, egui::Button::new("Key").min_size(button_size));
        if key
            .on_hover_text("Keep every model's pose at this time")
            .clicked()
        {
            output = ToolOutput::Commit(Op::Keyframe(KeyframeInput { time: self.time }));
            self.time += KEY_STEP_S;
        }
        let animated = doc.models.iter().any(|m| m.keyframes().next().is_some());
        let go = ui.add_enabled(animated, egui::Button::new("Pose at"));
        let hint = "Put the models in their pose at this time, to edit it (or to start each \
                    frame of a retargeted motion from the rest pose)";
        if go.on_hover_text(hint).clicked() {
            output = ToolOutput::Commit(Op::PoseAt(KeyframeInput { time: self.time }));
        }
        let keyed = doc
            .models
            .iter()
            .any(|m| m.keyframes.iter().any(|k| k.time == self.time));
        let delete = ui.add_enabled(keyed, egui::Button::new("Delete key"));
        if delete
            .on_hover_text("Remove the keys at this time")
            .clicked()
        {
            output = ToolOutput::Commit(Op::DeleteKeyframe(KeyframeInput { time: self.time }));
        }
        if self.is_playing {
            let stop = ui.add(egui::Button::new("Stop").min_size(button_size));
            if stop.on_hover_text("Stop playing (Esc)").clicked() {
                output = ToolOutput::Play(false);
            }
        } else {
            let playable = doc.models.iter().any(|m| m.keyframes().count() >= 2);
            let play = ui.add_enabled(playable, egui::Button::new("▶ Play").min_size(button_size));
            if play
                .on_hover_text("Play the key-framed animation")
                .clicked()
            {
                output = ToolOutput::Play(true);
            }
        }
        ui.separator();
        let curves = self.curves_ui(ui, doc);
        if curves != ToolOutput::None {
            output = curves;
        }
        output
    }
}

/// The toolbar's target, at least 44 points wide: the panel's short labels ("Key", "Spline")
/// read as buttons at that width.
fn wide_target(ui: &egui::Ui) -> egui::Vec2 {
    target_size(ui).max(egui::vec2(44.0, 0.0))
}

impl Tool for PoseTool {
    fn info(&self) -> &'static ToolInfo {
        &INFO
    }

    fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        PoseTool::on_event(self, event, view, doc)
    }

    fn cancel(&mut self) -> ToolOutput {
        PoseTool::cancel(self);
        ToolOutput::None
    }

    fn panel(&mut self, ui: &mut egui::Ui, doc: &Document) -> Option<ToolOutput> {
        Some(self.settings_ui(ui, doc))
    }

    /// The picked control curves (as the edit in progress moves them), the one redrawn
    /// marked, and the spline's control points while it reshapes by them.
    fn overlay(&self, ui: &egui::Ui, scene: &Scene<'_>) {
        let (camera, size) = (scene.camera, scene.size());
        let moved = scene.moved_models();
        for (curve, active) in self.curves(scene.shown, &moved) {
            let on_screen: Vec<glam::DVec2> = curve
                .iter()
                .filter_map(|&p| camera.screen_from_world(p, size).map(|s| s.truncate()))
                .collect();
            outline_ui(ui, scene.viewport, &on_screen, active, active);
        }
        let controls: Vec<egui::Pos2> = (self.controls(scene.shown, &moved).iter())
            .filter_map(|&p| camera.screen_from_world(p, size))
            .map(|s| scene.at(s.truncate()))
            .collect();
        let colour = egui::Color32::from_rgb(250, 210, 80);
        ui.painter().add(egui::Shape::line(
            controls.clone(),
            egui::Stroke::new(1.5, colour.gamma_multiply(0.7)),
        ));
        for c in controls {
            ui.painter()
                .circle(c, 9.0, colour, egui::Stroke::new(2.0, egui::Color32::BLACK));
        }
    }

    fn hint(&self, _doc: &Document, device: Device) -> Hint {
        device.say(PoseTool::hint(self))
    }

    fn playing(&mut self, is_playing: bool) {
        self.is_playing = is_playing;
    }

    fn preview(&self) -> Option<&[StrokePoint]> {
        PoseTool::preview(self)
    }

    fn marks(&self, camera: &Camera) -> Vec<Mark> {
        PoseTool::marks(self, camera)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::Phase;
    use crate::tools::test_support::{pen, shape, view};
    use sketchmesh_core::geometry::enclosed_volume;

    /// Feeds a stroke through `points` (screen points) and returns the tool's last output.
    fn stroke(
        tool: &mut PoseTool,
        view: &ViewCtx,
        doc: &Document,
        points: &[(f32, f32)],
    ) -> ToolOutput {
        let last = points.len() - 1;
        let mut output = ToolOutput::None;
        for (k, &(x, y)) in points.iter().enumerate() {
            let event = match k {
                0 => ToolEvent::Begin(pen(Phase::Down, x, y)),
                k if k == last => ToolEvent::End(pen(Phase::Up, x, y)),
                _ => ToolEvent::Move(pen(Phase::Move, x, y)),
            };
            output = tool.on_event(&event, view, doc);
        }
        output
    }

    #[test]
    fn a_curve_then_its_new_shape_bend_the_model_keeping_its_volume() {
        let mut editor = shape();
        let mut tool = PoseTool::default();
        let front = view();
        // Across the shape's middle, from left to right (the shape spans 250..550 x 190..490).
        let across: Vec<(f32, f32)> = (0..=40).map(|k| (300.0 + 5.0 * k as f32, 340.0)).collect();
        let output = stroke(&mut tool, &front, editor.document(), &across);
        let ToolOutput::Face { normal, .. } = output else {
            panic!("no plane to face: {output:?}");
        };
        let rest = tool.curves(editor.document(), &[])[0].0.clone();
        assert!(rest.len() > 5);
        // Drawn on a model posed elsewhere (the animation playing), the curve follows it.
        let lifted: Vec<DVec3> = (editor.document().models[0].mesh.positions().iter())
            .map(|&p| p + DVec3::Y)
            .collect();
        let posed = tool.curves(editor.document(), &[(0, lifted.as_slice())])[0]
            .0
            .clone();
        assert!(
            rest.iter()
                .zip(&posed)
                .all(|(a, b)| (*b - *a - DVec3::Y).length() < 1e-12)
        );
        // Turning the plane round: the op names the normal the view faces.
        let turned = tool.turn_plane(editor.document());
        let ToolOutput::Face { normal: once, .. } = turned else {
            panic!("no turn: {turned:?}");
        };
        assert!((once.angle_between(normal).to_degrees() - PLANE_TURN_DEG).abs() < 1e-6);
        for _ in 0..7 {
            tool.turn_plane(editor.document());
        }
        let Some(plane) = tool.active.map(|k| tool.curves[k].plane) else {
            panic!("the curve was dropped");
        };
        let (point, normal) = (plane.origin, plane.normal);
        // The app turns the view to face the plane; the new shape is drawn there.
        let mut camera = crate::camera::OrbitCamera::default();
        camera.face(point, normal);
        let side = ViewCtx {
            camera: camera.camera(),
            ..front
        };
        let eye_to_target = (side.camera.target - side.camera.eye).normalize();
        assert!(eye_to_target.dot(normal).abs() > 0.99, "not face on");
        // The curve as seen there, its right half swung up by up to 40 px: a bend.
        let size = glam::DVec2::new(800.0, 600.0);
        let seen: Vec<glam::DVec2> = tool.curves(editor.document(), &[])[0]
            .0
            .iter()
            .filter_map(|&p| side.camera.screen_from_world(p, size).map(|s| s.truncate()))
            .collect();
        let n = seen.len() as f32;
        let bent: Vec<(f32, f32)> = seen
            .iter()
            .enumerate()
            .map(|(k, s)| {
                let lift = (k as f32 / n - 0.5).max(0.0) * 80.0;
                (s.x as f32, s.y as f32 + 40.0 - lift)
            })
            .collect();
        // The new shape is a gesture: begun at pointer-down, extended by every sample.
        let mut op = None;
        for (k, &(x, y)) in bent.iter().enumerate() {
            let event = match k {
                0 => ToolEvent::Begin(pen(Phase::Down, x, y)),
                k if k + 1 == bent.len() => ToolEvent::End(pen(Phase::Up, x, y)),
                _ => ToolEvent::Move(pen(Phase::Move, x, y)),
            };
            match tool.on_event(&event, &side, editor.document()) {
                ToolOutput::Begin(begun) => op = Some(begun),
                ToolOutput::Extend(sample) | ToolOutput::End(sample) => {
                    if let Some(stroke) = op.as_mut().and_then(Op::stroke_mut) {
                        stroke.push(sample);
                    }
                }
                output => panic!("unexpected {output:?}"),
            }
        }
        let Some(op @ Op::CurveDeform(_)) = op else {
            panic!("no curve deform");
        };
        let before = enclosed_volume(&editor.document().models[0].mesh);
        let rest = tool.curves(editor.document(), &[])[0].0.clone();
        editor.apply(op).unwrap();
        let after = enclosed_volume(&editor.document().models[0].mesh);
        assert!(
            (after / before - 1.0).abs() < 0.05,
            "volume {before} -> {after}"
        );
        // The curve stays picked, where the bend took it, to be redrawn again.
        let curves = tool.curves(editor.document(), &[]);
        assert!(curves.len() == 1 && curves[0].1, "{curves:?}");
        assert!(curves[0].0 != rest, "the curve did not follow the model");
        // **+ Curve**, then a stroke along the model's lower part picks a second curve; its
        // new shape's op holds the first.
        tool.adding = true;
        let lower: Vec<(f32, f32)> = (0..=30).map(|k| (320.0 + 5.0 * k as f32, 420.0)).collect();
        let picked = stroke(&mut tool, &front, editor.document(), &lower);
        assert!(matches!(picked, ToolOutput::Face { .. }), "{picked:?}");
        let down = ToolEvent::Begin(pen(Phase::Down, 400.0, 300.0));
        let ToolOutput::Begin(Op::CurveDeform(second)) =
            tool.on_event(&down, &front, editor.document())
        else {
            panic!("no second curve's edit");
        };
        assert_eq!(tool.active, Some(1));
        assert_eq!(second.held, vec![tool.curves[0].path.clone()]);
        assert_eq!(second.path.as_ref(), Some(&tool.curves[1].path));
    }

    #[test]
    fn in_spline_mode_a_press_on_a_control_point_drags_it_and_elsewhere_is_refused() {
        let mut editor = shape();
        let mut tool = PoseTool::default();
        let front = view();
        let across: Vec<(f32, f32)> = (0..=40).map(|k| (300.0 + 5.0 * k as f32, 340.0)).collect();
        let ToolOutput::Face { point, normal } =
            stroke(&mut tool, &front, editor.document(), &across)
        else {
            panic!("no plane to face");
        };
        let mut camera = crate::camera::OrbitCamera::default();
        camera.face(point, normal);
        let side = ViewCtx {
            camera: camera.camera(),
            ..front
        };
        tool.spline = true;
        let controls = tool.controls(editor.document(), &[]);
        assert_eq!(controls.len(), COARSE_CONTROLS);
        let size = glam::DVec2::new(800.0, 600.0);
        let Some(last) = side
            .camera
            .screen_from_world(controls[COARSE_CONTROLS - 1], size)
        else {
            panic!("the last control point is off screen");
        };
        // The viewport starts 40 px down the screen.
        let (x, y) = (last.x as f32 + 5.0, last.y as f32 + 40.0);
        let near = ToolEvent::Begin(pen(Phase::Down, x, y));
        let ToolOutput::Begin(Op::CurveDeform(drag)) =
            tool.on_event(&near, &side, editor.document())
        else {
            panic!("no drag");
        };
        let coarse = drag.coarse.as_ref().map(|c| c.control);
        assert_eq!(coarse, Some(COARSE_CONTROLS - 1));
        // Released 60 px up: the op bends the shape.
        let up = ToolEvent::End(pen(Phase::Up, x, y - 60.0));
        let ToolOutput::End(sample) = tool.on_event(&up, &side, editor.document()) else {
            panic!("no end");
        };
        let mut drag = drag;
        drag.stroke.push(sample);
        let before = editor.document().models[0].mesh.positions().to_vec();
        editor.apply(Op::CurveDeform(drag)).unwrap();
        assert!(editor.document().models[0].mesh.positions() != before.as_slice());
        // Far from every control point: refused with a sentence; + Knot gives one more.
        let far = ToolEvent::Begin(pen(Phase::Down, 20.0, 20.0));
        let refused = tool.on_event(&far, &side, editor.document());
        assert!(matches!(refused, ToolOutput::Refused(_)), "{refused:?}");
        let curve = &mut tool.curves[0];
        curve.knots = with_widest_span_split(&curve.knots);
        assert_eq!(
            tool.controls(editor.document(), &[]).len(),
            COARSE_CONTROLS + 1
        );
    }
}

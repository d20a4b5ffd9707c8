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

use glam::DVec3;
use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::{StrokePoint, is_closed_loop};
use sketchmesh_core::document::{
    CLOSE_TOLERANCE_PX, CurveDeformInput, Document, KeyframeInput, Op, StrokeInput, model_under,
};
use sketchmesh_core::feature::Sketch;
use sketchmesh_core::volumetric::{Falloff, Plane, editing_plane, pick_curve};

use super::context::{ToolOutput, ViewCtx};
use super::draw::{DrawTool, is_tap, point};
use super::optimize::Mark;
use crate::input::router::ToolEvent;

/// Seconds the time moves on after a key, so the next pose goes after it.
const KEY_STEP_S: f64 = 1.0;

/// A picked control curve, waiting for its new shape.
#[derive(Clone, Debug)]
struct Picked {
    model: usize,
    /// The stroke along the surface, in the view it was drawn in.
    input: StrokeInput,
    /// The curve's vertices' positions, to draw.
    points: Vec<DVec3>,
    /// The editing plane: chosen for the curve, or turned by the user.
    plane: Plane,
    /// Whether the user turned it (the op then names its normal).
    turned: bool,
}

/// How far **Turn plane** turns the editing plane about the curve's chord.
const PLANE_TURN_DEG: f64 = 45.0;

/// The pose tool's state.
#[derive(Debug, Default)]
pub struct PoseTool {
    draw: DrawTool,
    /// The loop around what holds still, in the view it was drawn in.
    fixed: Option<(Camera, Vec<StrokePoint>)>,
    picked: Option<Picked>,
    /// Whether the curve's new shape is being drawn (a gesture).
    reshaping: bool,
    falloff: Falloff,
    /// The time the next key goes at (s).
    time: f64,
}

impl PoseTool {
    /// Feeds one event: strokes make the loop, the curve and its new shape.
    pub fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        if self.picked.is_some() {
            return self.reshape(event, view);
        }
        let Some(input) = self.draw.capture(event, view) else {
            return ToolOutput::None;
        };
        if is_tap(&input) {
            return ToolOutput::None;
        }
        let points = input.points();
        if model_under(doc, &input).is_none() {
            if is_closed_loop(&points, CLOSE_TOLERANCE_PX) {
                self.fixed = Some((input.camera, points));
                return ToolOutput::None;
            }
            return ToolOutput::Refused(String::from(
                "Draw the control curve along a model, from one end to the other.",
            ));
        }
        self.pick(doc, input)
    }

    /// Picks the curve under `input` and turns the view to its editing plane.
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
                self.picked = Some(Picked {
                    model,
                    points: path.iter().map(|&v| mesh.position(v)).collect(),
                    input,
                    plane,
                    turned: false,
                });
                ToolOutput::Face {
                    point: plane.origin,
                    normal: plane.normal,
                }
            }
            Err(err) => ToolOutput::Refused(err.to_string()),
        }
    }

    /// The new shape's stroke: a gesture whose samples the edit follows.
    fn reshape(&mut self, event: &ToolEvent, view: &ViewCtx) -> ToolOutput {
        let sample = |s| {
            let p = point(s, view);
            [p.pos.x, p.pos.y, p.pressure]
        };
        match event {
            ToolEvent::Begin(s) => {
                let Some(picked) = &self.picked else {
                    return ToolOutput::None;
                };
                self.reshaping = true;
                ToolOutput::Begin(self.deform(picked, view.camera, sample(s)))
            }
            ToolEvent::Move(s) if self.reshaping => ToolOutput::Extend(sample(s)),
            ToolEvent::End(s) if self.reshaping => {
                self.cancel();
                ToolOutput::End(sample(s))
            }
            ToolEvent::Cancel if self.reshaping => {
                self.reshaping = false;
                ToolOutput::Cancel
            }
            _ => ToolOutput::None,
        }
    }

    /// The op that gives the picked curve the shape of a stroke drawn with `camera`, begun
    /// with `first`.
    fn deform(&self, picked: &Picked, camera: Camera, first: [f64; 3]) -> Op {
        let fixed = (self.fixed.as_ref())
            .filter(|(camera, _)| *camera == picked.input.camera)
            .map(|(_, points)| {
                points
                    .iter()
                    .map(|p| [p.pos.x, p.pos.y, p.pressure])
                    .collect()
            });
        Op::CurveDeform(CurveDeformInput {
            model: picked.model,
            viewport: picked.input.viewport,
            camera: picked.input.camera,
            curve: picked.input.stroke.clone(),
            stroke: vec![first],
            stroke_camera: (camera != picked.input.camera).then_some(camera),
            plane: picked.turned.then_some(picked.plane.normal.to_array()),
            fixed,
            falloff: self.falloff,
        })
    }

    /// Turns the picked curve's editing plane by [`PLANE_TURN_DEG`] about the curve's chord
    /// (its ends' join), and the view to face it.
    fn turn_plane(&mut self) -> ToolOutput {
        let Some(picked) = &mut self.picked else {
            return ToolOutput::None;
        };
        let (first, last) = (picked.points[0], picked.points[picked.points.len() - 1]);
        let Some(axis) = (last - first).try_normalize() else {
            return ToolOutput::None;
        };
        let turn = glam::DQuat::from_axis_angle(axis, PLANE_TURN_DEG.to_radians());
        picked.plane.normal = (turn * picked.plane.normal).normalize();
        picked.turned = true;
        ToolOutput::Face {
            point: picked.plane.origin,
            normal: picked.plane.normal,
        }
    }

    /// Forgets the loop, the curve and the stroke.
    pub fn cancel(&mut self) {
        self.draw = DrawTool::Idle;
        self.fixed = None;
        self.picked = None;
        self.reshaping = false;
    }

    /// The stroke being drawn, for live display.
    pub fn preview(&self) -> Option<&[StrokePoint]> {
        self.draw.preview()
    }

    /// The picked curve's points, to draw over the model.
    pub fn curve(&self) -> Option<&[DVec3]> {
        self.picked.as_ref().map(|p| p.points.as_slice())
    }

    /// The loop around what holds still, while the view is the one it was drawn in.
    pub fn marks(&self, camera: &Camera) -> Vec<Mark> {
        (self.fixed.iter())
            .filter(|(c, _)| c == camera)
            .map(|(_, points)| Mark {
                points: points.clone(),
                radius: None,
                features: false,
            })
            .collect()
    }

    /// What the tool asks the user to do next.
    pub fn hint(&self) -> Option<&'static str> {
        Some(match (&self.picked, &self.fixed) {
            (None, None) => {
                "Draw a control curve along a model (a closed loop off it first holds a part still)"
            }
            (None, Some(_)) => "Now draw the control curve along the model",
            (Some(_), _) => "Draw the curve's new shape; the model bends and keeps its volume",
        })
    }

    /// The panel: the fall-off, and the timeline's key, delete and play.
    pub fn settings_ui(&mut self, ui: &mut egui::Ui, doc: &Document) -> ToolOutput {
        let mut output = ToolOutput::None;
        for (falloff, label, hint) in [
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
        ] {
            let button = egui::Button::selectable(self.falloff == falloff, label)
                .min_size(egui::vec2(36.0, 36.0));
            if ui.add(button).on_hover_text(hint).clicked() {
                self.falloff = falloff;
            }
        }
        ui.separator();
        ui.add(
            egui::DragValue::new(&mut self.time)
                .range(0.0..=600.0)
                .speed(0.1)
                .suffix(" s"),
        )
        .on_hover_text("The time of the next key");
        let has_models = !doc.models.is_empty();
        let key = ui.add_enabled(
            has_models,
            egui::Button::new("Key").min_size(egui::vec2(44.0, 36.0)),
        );
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
        let turn = ui.add_enabled(self.picked.is_some(), egui::Button::new("Turn plane"));
        if turn
            .on_hover_text("Turn the editing plane about the curve by 45°")
            .clicked()
        {
            output = self.turn_plane();
        }
        let playable = doc.models.iter().any(|m| m.keyframes().count() >= 2);
        let play = ui.add_enabled(
            playable,
            egui::Button::new("▶ Play").min_size(egui::vec2(44.0, 36.0)),
        );
        if play
            .on_hover_text("Play the key-framed animation")
            .clicked()
        {
            output = ToolOutput::Play;
        }
        output
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
        assert!(tool.curve().is_some_and(|c| c.len() > 5));
        // Turning the plane twice and back: the op names the normal the view faces.
        let turned = tool.turn_plane();
        let ToolOutput::Face { normal: once, .. } = turned else {
            panic!("no turn: {turned:?}");
        };
        assert!((once.angle_between(normal).to_degrees() - PLANE_TURN_DEG).abs() < 1e-6);
        for _ in 0..7 {
            tool.turn_plane();
        }
        let (point, normal) = match tool.picked.as_ref() {
            Some(p) => (p.plane.origin, p.plane.normal),
            None => panic!("the curve was dropped"),
        };
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
        let seen: Vec<glam::DVec2> = tool
            .curve()
            .unwrap_or_default()
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
        editor.apply(op).unwrap();
        let after = enclosed_volume(&editor.document().models[0].mesh);
        assert!(
            (after / before - 1.0).abs() < 0.05,
            "volume {before} -> {after}"
        );
        assert!(tool.curve().is_none(), "the curve was used");
    }
}

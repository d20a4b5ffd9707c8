//! The over-sketch tool: redraw part of an outline and the model follows (SilSketch, SEED).
//!
//! It captures a stroke exactly as the draw tool does (it wraps one, for the live stroke)
//! and begins an `oversketch` edit as a gesture, fed every sample: while the stroke is drawn
//! the edit shows which silhouette piece it would replace ([`Edit::outline`]), which the app
//! highlights green when the match is confident, orange when core would refuse it; release
//! commits the op.
//!
//! [`Edit::outline`]: sketchmesh_core::document::Edit::outline
//!
//! In manual mode (the toolbar's "Pick handle") the first stroke picks the handle instead
//! ([`pick_handle`]): along an outline, that outline's piece; over the model elsewhere, a
//! curve on the surface. A stroke from an end of a picked piece along the outline moves that
//! end (a crop); any other stroke is the handle's new shape. The crop is decided when the
//! stroke ends, since a new shape also starts at an end but leaves the outline. Orbiting or zooming drops the pick, since it is kept in screen points.

mod icon;
mod settings;

use glam::DVec2;
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{Document, Op, OversketchInput, StrokeInput};
use sketchmesh_core::oversketch::{
    ManualHandle, OversketchRoi, manual_handle_preview, pick_handle,
};

use crate::input::router::ToolEvent;
use crate::overlay::outline_ui;
use crate::tools::context::{ToolOutput, ViewCtx};
use crate::tools::draw::{DrawTool, point};
use crate::tools::hint::{Device, Hint};
use crate::tools::tool::{Gestures, Group, Scene, Tool, ToolInfo};

use settings::OversketchSettings;

/// The over-sketch tool's name, icon, key and description.
static INFO: ToolInfo = ToolInfo {
    label: "Over-sketch",
    icon: icon::draw,
    key: egui::Key::O,
    group: Group::Reshape,
    about: "Draw near an outline where you want it to be",
    gestures: Gestures {
        pen: "Draw the outline where it should be",
        finger: "Draw the outline where it should be",
        mouse: "Left-drag the outline where it should be",
    },
    when: Some("To change a silhouette: redraw the outline you see, on any model"),
};

/// A stroke starting this close (points) to an end of a picked outline piece and running
/// along the outline moves that end (a crop).
const END_GRAB_PX: f64 = 16.0;

/// A picked handle as it resolves on the model, in viewport-relative points.
#[derive(Clone, Debug, PartialEq)]
pub struct HandlePreview {
    /// The piece, in order.
    pub points: Vec<DVec2>,
    /// Whether the match is confident enough to be applied.
    pub confident: bool,
    /// Whether the ends can be dragged to crop it (a picked outline piece).
    pub croppable: bool,
}

/// A handle picked in manual mode, with the view it was picked in.
#[derive(Clone, Debug, PartialEq)]
struct Picked {
    handle: ManualHandle,
    camera: Camera,
    viewport: DVec2,
}

/// The over-sketch tool's state: the stroke being drawn, the pick in manual mode, and the
/// user's settings.
#[derive(Clone, Debug, Default)]
pub struct OversketchTool {
    stroke: DrawTool,
    /// The picked handle as shown.
    handle: Option<HandlePreview>,
    settings: OversketchSettings,
    picked: Option<Picked>,
}

impl OversketchTool {
    /// Feeds one event: a stroke is an `oversketch` gesture (in manual mode, the pick, a
    /// crop, or an op committed at its end).
    pub fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        if self.settings.manual {
            return self.on_manual_event(event, view, doc);
        }
        self.picked = None;
        self.handle = None;
        let was_drawing = self.stroke.preview().is_some();
        let finished = self.stroke.capture(event, view);
        let is_drawing = self.stroke.preview().is_some();
        let sample = |s| {
            let p = point(s, view);
            [p.pos.x, p.pos.y, p.pressure]
        };
        match event {
            ToolEvent::Begin(s) if is_drawing && !was_drawing => {
                let size = view.viewport.size();
                let input = StrokeInput {
                    viewport: [size.x.into(), size.y.into()],
                    camera: view.camera,
                    stroke: vec![sample(s)],
                };
                ToolOutput::Begin(self.op(input, None))
            }
            ToolEvent::Move(s) if is_drawing => ToolOutput::Extend(sample(s)),
            ToolEvent::End(s) if finished.is_some() => ToolOutput::End(sample(s)),
            ToolEvent::Cancel if was_drawing => ToolOutput::Cancel,
            _ => ToolOutput::None,
        }
    }

    /// Manual mode: pick, crop by dragging an end, then the new shape.
    fn on_manual_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        let size = view.viewport.size();
        let viewport = DVec2::new(size.x.into(), size.y.into());
        if self
            .picked
            .as_ref()
            .is_some_and(|p| p.camera != view.camera || p.viewport != viewport)
        {
            self.picked = None;
            self.handle = None;
        }
        let Some(input) = self.stroke.capture(event, view) else {
            return ToolOutput::None;
        };
        let stroke: Vec<DVec2> = input
            .stroke
            .iter()
            .map(|p| DVec2::new(p[0], p[1]))
            .collect();
        if let Some(picked) = self.picked.take() {
            if let Some(cropped) = self.cropped(&picked, &stroke, doc) {
                self.picked = Some(cropped);
                self.handle = self.picked_preview(doc);
                return ToolOutput::None;
            }
            self.handle = None;
            return ToolOutput::Commit(self.op(input, Some(picked.handle)));
        }
        let picked = doc.models.iter().find_map(|model| {
            pick_handle(
                &model.mesh,
                &input.camera,
                viewport,
                &stroke,
                self.settings.outline,
            )
        });
        let Some(handle) = picked else {
            return ToolOutput::Refused(String::from(
                "Draw along an outline, or across the model, to pick what moves.",
            ));
        };
        self.picked = Some(Picked {
            handle,
            camera: input.camera,
            viewport,
        });
        self.handle = self.picked_preview(doc);
        ToolOutput::None
    }

    /// The pick with one end moved, when `stroke` starts at an end of a picked outline piece
    /// and runs along the outline (a crop); `None` when it is the piece's new shape.
    fn cropped(&self, picked: &Picked, stroke: &[DVec2], doc: &Document) -> Option<Picked> {
        let ManualHandle::Silhouette {
            from,
            via,
            to,
            outline,
        } = picked.handle
        else {
            return None;
        };
        let shown = &self.handle.as_ref()?.points;
        let (&first, &last) = shown.first().zip(shown.last())?;
        let (&start, &end) = stroke.first().zip(stroke.last())?;
        let (to_first, to_last) = (start.distance(first), start.distance(last));
        if to_first.min(to_last) > END_GRAB_PX {
            return None;
        }
        let is_along = doc.models.iter().any(|model| {
            matches!(
                pick_handle(
                    &model.mesh,
                    &picked.camera,
                    picked.viewport,
                    stroke,
                    outline
                ),
                Some(ManualHandle::Silhouette { .. })
            )
        });
        let handle = if to_last < to_first {
            ManualHandle::Silhouette {
                from,
                via,
                to: end,
                outline,
            }
        } else {
            ManualHandle::Silhouette {
                from: end,
                via,
                to,
                outline,
            }
        };
        is_along.then(|| Picked {
            handle,
            ..picked.clone()
        })
    }

    /// The `oversketch` op of a stroke, with the user's settings.
    fn op(&self, input: StrokeInput, handle: Option<ManualHandle>) -> Op {
        Op::Oversketch(OversketchInput {
            viewport: input.viewport,
            camera: input.camera,
            stroke: input.stroke,
            fit: self.settings.fit,
            roi: self.settings.roi,
            handle,
        })
    }

    /// Drops the stroke in progress and the pick; the settings stay.
    pub fn cancel(&mut self) {
        *self = Self {
            settings: self.settings,
            ..Self::default()
        };
    }

    /// The stroke in progress, as the draw tool shows it.
    pub fn preview(&self) -> Option<&[sketchmesh_core::curve::StrokePoint]> {
        self.stroke.preview()
    }

    /// The picked handle (manual mode).
    pub fn handle(&self) -> Option<&HandlePreview> {
        let is_stale_pick = self.picked.is_some() && !self.settings.manual;
        self.handle.as_ref().filter(|_| !is_stale_pick)
    }

    /// What to do next: in manual mode, pick then redraw; else redraw the outline.
    pub fn hint(&self) -> &'static str {
        if !self.settings.manual {
            return match self.preview() {
                None => {
                    "Draw {with} where a model's outline should be, along it: the outline moves \
                     to your stroke (green: it is sure which part; orange: draw nearer the outline)"
                }
                Some(_) => "Let go to move the outline to your stroke",
            };
        }
        match (&self.picked, &self.handle) {
            (None, _) => "Draw along an outline, or across the model, to pick what moves",
            (Some(_), Some(h)) if h.croppable => {
                "Draw along the outline from a dot to crop it, or draw its new shape"
            }
            (Some(_), _) => "Now draw its new position",
        }
    }

    /// The picked handle as it resolves on the first model it finds.
    fn picked_preview(&self, doc: &Document) -> Option<HandlePreview> {
        let picked = self.picked.as_ref()?;
        let croppable = matches!(picked.handle, ManualHandle::Silhouette { .. });
        doc.models.iter().find_map(|model| {
            manual_handle_preview(&model.mesh, &picked.camera, picked.viewport, &picked.handle).map(
                |points| HandlePreview {
                    points,
                    confident: true,
                    croppable,
                },
            )
        })
    }
}

impl Tool for OversketchTool {
    fn info(&self) -> &'static ToolInfo {
        &INFO
    }

    fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        OversketchTool::on_event(self, event, view, doc)
    }

    fn cancel(&mut self) -> ToolOutput {
        OversketchTool::cancel(self);
        ToolOutput::None
    }

    fn panel(&mut self, ui: &mut egui::Ui, _doc: &Document) -> Option<ToolOutput> {
        settings::options_ui(ui, &mut self.settings);
        Some(ToolOutput::None)
    }

    /// The picked handle, its ends marked when they can be dragged.
    fn overlay(&self, ui: &egui::Ui, scene: &Scene<'_>) {
        if let Some(h) = self.handle() {
            outline_ui(ui, scene.viewport, &h.points, h.confident, h.croppable);
        }
    }

    fn hint(&self, _doc: &Document, device: Device) -> Hint {
        device.say(OversketchTool::hint(self))
    }

    fn preview(&self) -> Option<&[sketchmesh_core::curve::StrokePoint]> {
        OversketchTool::preview(self)
    }

    /// K: manual handle picking on or off; A: the whole part or the surface near the
    /// outline.
    fn keys_anywhere(&self) -> &'static [egui::Key] {
        &[egui::Key::K, egui::Key::A]
    }

    fn on_key(&mut self, key: egui::Key, _doc: &Document) -> ToolOutput {
        match key {
            egui::Key::K => self.settings.manual = !self.settings.manual,
            egui::Key::A => {
                self.settings.roi = match self.settings.roi {
                    OversketchRoi::NearHandle => OversketchRoi::Part,
                    OversketchRoi::Part => OversketchRoi::NearHandle,
                }
            }
            _ => {}
        }
        ToolOutput::None
    }
}

#[cfg(test)]
mod tests {
    use egui::{Rect, pos2};
    use sketchmesh_core::camera::Camera;
    use sketchmesh_core::document::OversketchFit;

    use super::*;
    use crate::input::{Phase, PointerKind, PointerSample};

    fn pen(phase: Phase, x: f32) -> PointerSample {
        PointerSample {
            id: 1,
            phase,
            pos_in_screen: pos2(x, 100.0),
            pressure: 0.5,
            kind: PointerKind::Pen,
            buttons: 1,
            contact: 0.0,
            time: 0.0,
        }
    }

    /// What the app commits for a tool's outputs: a gesture's op as a core edit builds it
    /// from the samples, or the last output that is not part of a gesture.
    fn committed(doc: &Document, outputs: Vec<ToolOutput>) -> ToolOutput {
        let mut editor = sketchmesh_core::document::Editor::new();
        if !doc.models.is_empty() {
            let input = sketchmesh_core::document::ImportInput {
                files: vec![sketchmesh_core::document::FileInput {
                    name: String::from("doc.glb"),
                    data: Some(std::sync::Arc::new(sketchmesh_core::io::write_glb(doc))),
                }],
                beside: false,
            };
            editor.apply(Op::Import(input)).unwrap();
        }
        let mut edit = None;
        let mut last = ToolOutput::None;
        for output in outputs {
            match output {
                ToolOutput::Begin(op) => edit = Some(editor.begin_gesture(op).unwrap()),
                ToolOutput::Extend(sample) => edit.as_mut().unwrap().extend(sample),
                ToolOutput::End(sample) => {
                    let edit = edit.as_mut().unwrap();
                    edit.extend(sample);
                    edit.end_gesture();
                    last = ToolOutput::Commit(edit.op().clone());
                }
                ToolOutput::None => {}
                other => last = other,
            }
        }
        last
    }

    /// Draws a short stroke and returns what the app commits for it.
    fn draw(tool: &mut OversketchTool) -> ToolOutput {
        let view = ViewCtx {
            camera: Camera::default(),
            viewport: Rect::from_min_max(pos2(0.0, 40.0), pos2(800.0, 640.0)),
        };
        let doc = Document::default();
        let outputs = vec![
            tool.on_event(&ToolEvent::Begin(pen(Phase::Down, 10.0)), &view, &doc),
            tool.on_event(&ToolEvent::Move(pen(Phase::Move, 60.0)), &view, &doc),
            tool.on_event(&ToolEvent::End(pen(Phase::Up, 110.0)), &view, &doc),
        ];
        committed(&doc, outputs)
    }

    #[test]
    fn the_fit_setting_goes_into_the_op_and_outlives_a_cancel() {
        let mut tool = OversketchTool::default();
        let ToolOutput::Commit(Op::Oversketch(exact)) = draw(&mut tool) else {
            panic!("no oversketch op");
        };
        assert_eq!(exact.fit, OversketchFit::Exact);
        assert_eq!(exact.stroke.len(), 3);
        tool.settings.fit = OversketchFit::Soft;
        tool.cancel();
        let ToolOutput::Commit(Op::Oversketch(soft)) = draw(&mut tool) else {
            panic!("no oversketch op");
        };
        assert_eq!(soft.fit, OversketchFit::Soft);
        assert_eq!(soft.stroke, exact.stroke);
    }

    /// A unit sphere seen by the default camera in a 1000 × 1000 viewport: its outline is
    /// the circle of radius 1 / (√24 · tan 22.5°) · 500 px about the centre.
    fn sphere_view() -> (ViewCtx, Document, f64) {
        let view = ViewCtx {
            camera: Camera::default(),
            viewport: Rect::from_min_max(pos2(0.0, 0.0), pos2(1000.0, 1000.0)),
        };
        let model = sketchmesh_core::document::Model {
            mesh: sketchmesh_core::mesh::primitives::icosphere(1.0, 4),
            ..Default::default()
        };
        let doc = Document {
            models: vec![std::sync::Arc::new(model)],
            ..Document::default()
        };
        let radius = 500.0 / (24f64.sqrt() * 22.5f64.to_radians().tan());
        (view, doc, radius)
    }

    fn at(phase: Phase, p: DVec2) -> PointerSample {
        PointerSample {
            pos_in_screen: pos2(p.x as f32, p.y as f32),
            ..pen(phase, 0.0)
        }
    }

    /// Feeds a stroke through `points`; what the app commits for it (or the tool's
    /// refusal).
    fn stroke_through(
        tool: &mut OversketchTool,
        view: &ViewCtx,
        doc: &Document,
        points: &[DVec2],
    ) -> ToolOutput {
        let (first, rest) = points.split_first().unwrap();
        let (last, middle) = rest.split_last().unwrap();
        let mut outputs =
            vec![tool.on_event(&ToolEvent::Begin(at(Phase::Down, *first)), view, doc)];
        for p in middle {
            outputs.push(tool.on_event(&ToolEvent::Move(at(Phase::Move, *p)), view, doc));
        }
        outputs.push(tool.on_event(&ToolEvent::End(at(Phase::Up, *last)), view, doc));
        committed(doc, outputs)
    }

    /// Points on the circle of `radius` about the viewport centre, from `a` to `b` degrees.
    fn arc(radius: f64, a: f64, b: f64) -> Vec<DVec2> {
        (0..=40)
            .map(|k| {
                let angle = (a + (b - a) * k as f64 / 40.0).to_radians();
                DVec2::splat(500.0) + radius * DVec2::from_angle(angle)
            })
            .collect()
    }

    #[test]
    fn manual_mode_picks_a_surface_curve_then_commits_its_new_position() {
        let (view, doc, _) = sphere_view();
        let mut tool = OversketchTool::default();
        tool.settings.manual = true;
        assert!(tool.hint().contains("pick"));
        let across: Vec<DVec2> = (0..=20)
            .map(|k| DVec2::new(400.0 + 10.0 * k as f64, 500.0))
            .collect();
        assert_eq!(
            stroke_through(&mut tool, &view, &doc, &across),
            ToolOutput::None
        );
        let picked = tool.handle().unwrap();
        assert!(picked.confident && !picked.croppable && picked.points.len() > 10);
        assert_eq!(tool.hint(), "Now draw its new position");
        let higher: Vec<DVec2> = across.iter().map(|p| *p - DVec2::new(0.0, 30.0)).collect();
        let ToolOutput::Commit(Op::Oversketch(input)) =
            stroke_through(&mut tool, &view, &doc, &higher)
        else {
            panic!("the second stroke should commit");
        };
        assert!(matches!(input.handle, Some(ManualHandle::Surface { .. })));
        assert!(tool.handle().is_none());
        // Off the model entirely: refused with a sentence, nothing picked.
        let off: Vec<DVec2> = (0..=20)
            .map(|k| DVec2::new(10.0 + k as f64, 20.0))
            .collect();
        let ToolOutput::Refused(message) = stroke_through(&mut tool, &view, &doc, &off) else {
            panic!("a stroke off the model should be refused");
        };
        assert!(message.ends_with('.'));
    }

    #[test]
    fn the_ops_carry_the_region_setting() {
        let (view, doc, radius) = sphere_view();
        let mut tool = OversketchTool::default();
        for roi in [OversketchRoi::Part, OversketchRoi::NearHandle] {
            tool.settings.roi = roi;
            let beyond = arc(radius + 15.0, -30.0, 30.0);
            let ToolOutput::Commit(Op::Oversketch(input)) =
                stroke_through(&mut tool, &view, &doc, &beyond)
            else {
                panic!("a stroke beside the outline should commit");
            };
            assert_eq!(input.roi, roi);
        }
    }

    #[test]
    fn a_picked_outline_piece_is_cropped_from_its_end_and_dropped_by_orbiting() {
        let (view, doc, radius) = sphere_view();
        let mut tool = OversketchTool::default();
        tool.settings.manual = true;
        let along = arc(radius, -30.0, 30.0);
        assert_eq!(
            stroke_through(&mut tool, &view, &doc, &along),
            ToolOutput::None
        );
        let picked = tool.handle().unwrap().clone();
        assert!(picked.croppable);
        // Silhouette points are the outline's edge crossings, about 8 px apart here.
        assert!(picked.points.last().unwrap().distance(along[40]) < 10.0);
        // From the end at +30° back along the outline to +10°: a crop, no op.
        let crop = arc(radius, 30.0, 10.0);
        assert_eq!(
            stroke_through(&mut tool, &view, &doc, &crop),
            ToolOutput::None
        );
        let cropped = tool.handle().unwrap().clone();
        assert!(cropped.points.len() < picked.points.len() * 3 / 4);
        assert!(cropped.points.last().unwrap().distance(crop[40]) < 10.0);
        // The new shape commits the cropped handle.
        let out = arc(radius + 20.0, -30.0, 10.0);
        let ToolOutput::Commit(Op::Oversketch(input)) =
            stroke_through(&mut tool, &view, &doc, &out)
        else {
            panic!("the new shape should commit");
        };
        let Some(ManualHandle::Silhouette { to, .. }) = input.handle else {
            panic!("an outline handle, got {:?}", input.handle);
        };
        assert!(to.distance(crop[40]) < 1e-3, "{to} vs {}", crop[40]);
        // Pick again, then orbit: the pick is gone and the next stroke picks anew.
        stroke_through(&mut tool, &view, &doc, &along);
        assert!(tool.handle().is_some());
        let orbited = ViewCtx {
            camera: Camera {
                eye: glam::DVec3::new(1.0, 0.0, 5.0),
                ..Camera::default()
            },
            ..view
        };
        assert_eq!(
            stroke_through(&mut tool, &orbited, &doc, &along),
            ToolOutput::None
        );
        assert_eq!(
            tool.picked.as_ref().map(|p| p.camera),
            Some(orbited.camera),
            "the stroke after orbiting picked again"
        );
    }
}

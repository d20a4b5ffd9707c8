//! The sketch tool (FiberMesh §3.2.1): what a stroke means is read from the stroke in core
//! ([`op_for_stroke`]); a closed curve on a shape and a cross-section wait for a confirming
//! tap, as in the thesis. A closed curve followed by a stroke from near it out beside the
//! shape and back to near it grows a limb with that silhouette; followed by a second
//! closed loop on a shape (drawn after orbiting to the far side) it drills a tunnel between
//! them; followed by anything else it stays ink. A cross-section is a cut unless the tap comes within [`CUT_WAIT_SECONDS`]
//! (the thesis' "a cutting stroke followed by a click" adds the curve).

mod icon;

use sketchmesh_core::curve::StrokePoint;
use sketchmesh_core::document::{
    Document, Op, cut_instead, extrude_from, ink_instead, is_cross_section, needs_tap,
    op_for_stroke, tunnel_from,
};

use crate::input::router::ToolEvent;
use crate::overlay::stroke_ui;
use crate::tools::context::{ToolOutput, ViewCtx};
use crate::tools::draw::{DrawTool, is_tap};
use crate::tools::hint::{Device, Hint};
use crate::tools::tool::{Gestures, Group, Scene, Tool, ToolInfo};
use crate::ui_size::target_size;

/// The sketch tool's name, icon, key and description.
static INFO: ToolInfo = ToolInfo {
    label: "Sketch",
    icon: icon::draw,
    key: egui::Key::S,
    group: Group::Make,
    about: "Closed outline on empty canvas: a shape. On a shape: a curve (closed ones and strokes across a shape: tap to confirm).",
    gestures: Gestures {
        pen: "Draw a closed outline on empty canvas for a shape; draw on a shape for a curve",
        finger: "One finger draws as a pen does; tap to keep a closed curve",
        mouse: "Left-drag to draw; click to keep a closed curve",
    },
    when: None,
};

/// How finely a new shape is meshed: about how many vertices it gets. Coarse shapes edit
/// fastest; fine ones hold small detail (and a fine creation is computed off the frame,
/// with a progress line).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Detail {
    /// The default, 2,500 vertices: created and edited live on any device.
    #[default]
    Standard,
    /// 10,000 vertices.
    Fine,
    /// 40,000 vertices.
    Finest,
}

impl Detail {
    /// Every choice, with its label and what it means.
    const ALL: [(Detail, &'static str, &'static str); 3] = [
        (
            Detail::Standard,
            "2.5k",
            "New shapes get about 2,500 vertices: fastest to edit",
        ),
        (Detail::Fine, "10k", "New shapes get about 10,000 vertices"),
        (
            Detail::Finest,
            "40k",
            "New shapes get about 40,000 vertices: fine detail, slower edits",
        ),
    ];

    /// The `create` op's `vertices`: none for the default, so sessions stay as they were.
    fn vertices(self) -> Option<usize> {
        match self {
            Detail::Standard => None,
            Detail::Fine => Some(10_000),
            Detail::Finest => Some(40_000),
        }
    }
}

/// How long a stroke across a shape waits for the tap that makes it a cross-section curve
/// before it cuts: a little longer than a double tap's gap, so a deliberate tap makes it.
pub const CUT_WAIT_SECONDS: f64 = 0.6;

/// A stroke that waits for its confirming tap.
#[derive(Clone, Debug)]
struct Waiting {
    op: Op,
    points: Vec<StrokePoint>,
    /// When a cross-section becomes a cut, once the first frame after it has seen the clock.
    deadline: Option<f64>,
}

impl Waiting {
    /// What the stroke becomes when its tap does not come.
    fn without_tap(self) -> Op {
        if is_cross_section(&self.op) {
            cut_instead(self.op)
        } else {
            ink_instead(self.op)
        }
    }
}

/// The sketch tool's state.
#[derive(Clone, Debug, Default)]
pub struct SketchTool {
    draw: DrawTool,
    waiting: Option<Waiting>,
    detail: Detail,
}

impl SketchTool {
    /// Feeds one event; see the module docs for what a finished stroke commits.
    pub fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        let Some(input) = self.draw.capture(event, view) else {
            return ToolOutput::None;
        };
        let held = self.waiting.take();
        if is_tap(&input) {
            return held.map_or(ToolOutput::None, |w| ToolOutput::Commit(w.op));
        }
        if let Some(extrusion) = held.as_ref().and_then(|w| extrude_from(doc, &w.op, &input)) {
            return ToolOutput::Commit(extrusion);
        }
        let mut op = op_for_stroke(doc, input);
        if let Op::Create(create) = &mut op {
            create.vertices = self.detail.vertices();
        }
        if let Some(tunnel) = held.as_ref().and_then(|w| tunnel_from(&w.op, &op)) {
            return ToolOutput::Commit(tunnel);
        }
        let mut ops: Vec<Op> = held.map(Waiting::without_tap).into_iter().collect();
        if needs_tap(&op) {
            self.waiting = Some(Waiting {
                points: op.stroke_points(),
                op,
                deadline: None,
            });
        } else {
            ops.push(op);
        }
        match ops.len() {
            0 => ToolOutput::None,
            1 => ToolOutput::Commit(ops.remove(0)),
            _ => ToolOutput::CommitAll(ops),
        }
    }

    /// The tool's options in the toolbar: the detail of new shapes.
    pub fn settings_ui(&mut self, ui: &mut egui::Ui) {
        ui.label("Detail");
        for (detail, label, hint) in Detail::ALL {
            let button =
                egui::Button::selectable(self.detail == detail, label).min_size(target_size(ui));
            if ui.add(button).on_hover_text(hint).clicked() {
                self.detail = detail;
            }
        }
    }

    /// Called every frame with the frame's clock (s): a cross-section whose tap did not come
    /// in time becomes a cut. Returns how long until it does, for the next frame, if one
    /// waits.
    pub fn poll(&mut self, now: f64) -> (ToolOutput, Option<f64>) {
        let drawing = self.draw.preview().is_some();
        let Some(waiting) = self.waiting.as_mut().filter(|w| is_cross_section(&w.op)) else {
            return (ToolOutput::None, None);
        };
        let deadline = *waiting.deadline.get_or_insert(now + CUT_WAIT_SECONDS);
        if drawing {
            // The next stroke may be the tap: its end decides.
            return (ToolOutput::None, None);
        }
        if now < deadline {
            return (ToolOutput::None, Some(deadline - now));
        }
        let cut = self.waiting.take().map(Waiting::without_tap);
        (cut.map_or(ToolOutput::None, ToolOutput::Commit), None)
    }

    /// Drops a stroke in progress; a stroke waiting for a tap becomes ink.
    pub fn cancel(&mut self) -> ToolOutput {
        self.draw = DrawTool::Idle;
        self.waiting
            .take()
            .map_or(ToolOutput::None, |w| ToolOutput::Commit(ink_instead(w.op)))
    }

    /// The stroke being drawn.
    pub fn preview(&self) -> Option<&[StrokePoint]> {
        self.draw.preview()
    }

    /// The stroke waiting for a tap, and what the tap will do.
    pub fn waiting(&self) -> Option<(&[StrokePoint], &'static str)> {
        let waiting = self.waiting.as_ref()?;
        let what = match is_cross_section(&waiting.op) {
            true => "Cutting… {tap} now to add a cross-section curve instead",
            // What the next stroke may do, with the conditions `extrude_from` and
            // `tunnel_from` check, said before they refuse.
            false => {
                "{Tap} to keep this closed curve. For a limb, draw from the loop out past the \
                 outline and back to it (the loop must lie near the outline); for a tunnel, \
                 {orbit} half round and draw a loop on the far side"
            }
        };
        Some((&waiting.points, what))
    }

    /// What to do next: the waiting stroke's choices, else what a stroke makes here.
    pub fn hint(&self, doc: &Document, device: Device) -> Hint {
        if let Some((_, what)) = self.waiting() {
            return device.say(what);
        }
        if self.draw.preview().is_some() {
            return device.say("Lift to finish; end an outline where it began to close it");
        }
        match doc.models.is_empty() {
            true => device.say("Draw a closed outline {with} to make a shape; {orbit}"),
            false => device.say(
                "Draw {with}: an outline off the shapes makes another, a line on a shape adds a \
                 curve, a line across one cuts it; {orbit}",
            ),
        }
    }
}

impl Tool for SketchTool {
    fn info(&self) -> &'static ToolInfo {
        &INFO
    }

    fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        SketchTool::on_event(self, event, view, doc)
    }

    fn cancel(&mut self) -> ToolOutput {
        SketchTool::cancel(self)
    }

    fn panel(&mut self, ui: &mut egui::Ui, _doc: &Document) -> Option<ToolOutput> {
        self.settings_ui(ui);
        Some(ToolOutput::None)
    }

    /// A stroke waiting for its confirming tap: shown dimmer (the hint says what a tap does).
    fn overlay(&self, ui: &egui::Ui, scene: &Scene<'_>) {
        if let Some((points, _)) = self.waiting() {
            stroke_ui(
                ui,
                scene.viewport,
                points,
                egui::Color32::from_rgb(120, 200, 255),
            );
        }
    }

    /// The outline of a fine shape the worker computes stays, dimmer, until the shape lands.
    fn edit_overlay(&self, ui: &egui::Ui, scene: &Scene<'_>) {
        let computed =
            (scene.edit).filter(|edit| scene.computing && matches!(edit.op(), Op::Create(_)));
        if let Some(edit) = computed {
            let points = edit.op().stroke_points();
            stroke_ui(
                ui,
                scene.viewport,
                &points,
                egui::Color32::from_rgb(200, 170, 90),
            );
        }
    }

    fn preview(&self) -> Option<&[StrokePoint]> {
        SketchTool::preview(self)
    }

    fn hint(&self, doc: &Document, device: Device) -> Hint {
        SketchTool::hint(self, doc, device)
    }

    /// A closed outline on empty canvas makes a shape.
    fn makes_shapes(&self) -> bool {
        true
    }

    fn poll(&mut self, now: f64) -> (ToolOutput, Option<f64>) {
        SketchTool::poll(self, now)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::Phase;
    use crate::tools::test_support::{pen, shape, view};

    /// Draws a straight stroke in `steps` moves (a single point is a tap).
    fn draw(tool: &mut SketchTool, doc: &Document, from: (f32, f32), to: (f32, f32)) -> ToolOutput {
        let v = view();
        tool.on_event(&ToolEvent::Begin(pen(Phase::Down, from.0, from.1)), &v, doc);
        let steps = 30;
        for k in 1..steps {
            let t = k as f32 / steps as f32;
            let (x, y) = (from.0 + t * (to.0 - from.0), from.1 + t * (to.1 - from.1));
            tool.on_event(&ToolEvent::Move(pen(Phase::Move, x, y)), &v, doc);
        }
        tool.on_event(&ToolEvent::End(pen(Phase::Up, to.0, to.1)), &v, doc)
    }

    #[test]
    fn a_stroke_across_a_shape_cuts_when_no_tap_comes_in_time() {
        let editor = shape();
        let doc = editor.document();
        let mut tool = SketchTool::default();
        let across = draw(&mut tool, doc, (100.0, 340.0), (700.0, 340.0));
        assert_eq!(across, ToolOutput::None);
        assert!(
            tool.waiting()
                .is_some_and(|(_, what)| what.contains("cross-section"))
        );
        let (output, left) = tool.poll(10.0);
        assert_eq!(output, ToolOutput::None);
        assert!((left.unwrap() - CUT_WAIT_SECONDS).abs() < 1e-9);
        let (output, left) = tool.poll(10.3);
        assert_eq!(output, ToolOutput::None);
        assert!((left.unwrap() - 0.3).abs() < 1e-9);
        let (output, left) = tool.poll(10.0 + CUT_WAIT_SECONDS);
        assert!(
            matches!(output, ToolOutput::Commit(Op::Cut(_))),
            "{output:?}"
        );
        assert_eq!(left, None);
        assert!(tool.waiting().is_none());
    }

    #[test]
    fn a_tap_in_time_makes_the_stroke_a_cross_section_curve() {
        let editor = shape();
        let doc = editor.document();
        let mut tool = SketchTool::default();
        draw(&mut tool, doc, (100.0, 340.0), (700.0, 340.0));
        tool.poll(10.0);
        let v = view();
        tool.on_event(&ToolEvent::Begin(pen(Phase::Down, 400.0, 500.0)), &v, doc);
        // The deadline passes while the finger is down: its end decides.
        assert_eq!(tool.poll(11.0), (ToolOutput::None, None));
        let tap = tool.on_event(&ToolEvent::End(pen(Phase::Up, 400.0, 500.0)), &v, doc);
        assert!(
            matches!(&tap, ToolOutput::Commit(Op::AddCurve(input)) if input.cross_section),
            "{tap:?}"
        );
    }

    /// Draws a closed loop of `radius` around `(cx, 340)` in 40 moves.
    fn draw_loop(tool: &mut SketchTool, doc: &Document, cx: f32, radius: f32) -> ToolOutput {
        let points: Vec<(f32, f32)> = (0..=40)
            .map(|i| {
                let a = std::f32::consts::TAU * i as f32 / 40.0;
                (cx + radius * a.cos(), 340.0 + radius * a.sin())
            })
            .collect();
        draw_path(tool, doc, &points)
    }

    /// Draws a stroke through `points`.
    fn draw_path(tool: &mut SketchTool, doc: &Document, points: &[(f32, f32)]) -> ToolOutput {
        let v = view();
        let (first, last) = (points[0], points[points.len() - 1]);
        tool.on_event(
            &ToolEvent::Begin(pen(Phase::Down, first.0, first.1)),
            &v,
            doc,
        );
        for &(x, y) in &points[1..] {
            tool.on_event(&ToolEvent::Move(pen(Phase::Move, x, y)), &v, doc);
        }
        tool.on_event(&ToolEvent::End(pen(Phase::Up, last.0, last.1)), &v, doc)
    }

    #[test]
    fn a_stroke_from_the_loop_out_and_back_instead_of_the_tap_extrudes() {
        let editor = shape();
        let doc = editor.document();
        let mut tool = SketchTool::default();
        assert_eq!(draw_loop(&mut tool, doc, 470.0, 25.0), ToolOutput::None);
        // From the loop's top out past the shape's side and back to its bottom: the ends are
        // as close as a closed loop's, but the stroke leaves the shape.
        let silhouette: Vec<(f32, f32)> = (0..=40)
            .map(|i| {
                let a = std::f32::consts::PI * (i as f32 / 40.0 - 0.5);
                (470.0 + 250.0 * a.cos(), 340.0 + 25.0 * a.sin())
            })
            .collect();
        let out = draw_path(&mut tool, doc, &silhouette);
        assert!(matches!(out, ToolOutput::Commit(Op::Extrude(_))), "{out:?}");
        assert!(tool.waiting().is_none());
    }

    #[test]
    fn a_closed_outline_creates_at_the_chosen_detail() {
        let doc = Document::default();
        let v = view();
        let outline = |tool: &mut SketchTool| {
            let at = |k: usize| {
                let a = std::f32::consts::TAU * k as f32 / 40.0;
                (400.0 + 120.0 * a.cos(), 340.0 + 90.0 * a.sin())
            };
            tool.on_event(
                &ToolEvent::Begin(pen(Phase::Down, at(0).0, at(0).1)),
                &v,
                &doc,
            );
            for k in 1..40 {
                tool.on_event(
                    &ToolEvent::Move(pen(Phase::Move, at(k).0, at(k).1)),
                    &v,
                    &doc,
                );
            }
            match tool.on_event(
                &ToolEvent::End(pen(Phase::Up, at(40).0, at(40).1)),
                &v,
                &doc,
            ) {
                ToolOutput::Commit(Op::Create(input)) => input.vertices,
                other => panic!("not a creation: {other:?}"),
            }
        };
        let mut tool = SketchTool::default();
        assert_eq!(
            outline(&mut tool),
            None,
            "the default leaves sessions as they were"
        );
        tool.detail = Detail::Finest;
        assert_eq!(outline(&mut tool), Some(40_000));
    }

    #[test]
    fn a_closed_curve_without_its_tap_stays_ink_and_never_cuts() {
        let editor = shape();
        let doc = editor.document();
        let mut tool = SketchTool::default();
        draw_loop(&mut tool, doc, 400.0, 50.0);
        assert!(tool.waiting().is_some());
        assert_eq!(tool.poll(10.0), (ToolOutput::None, None));
        assert_eq!(tool.poll(20.0), (ToolOutput::None, None));
        assert!(matches!(tool.cancel(), ToolOutput::Commit(Op::Stroke(_))));
    }

    #[test]
    fn a_second_loop_instead_of_the_tap_drills_a_tunnel() {
        let editor = shape();
        let doc = editor.document();
        let mut tool = SketchTool::default();
        assert_eq!(draw_loop(&mut tool, doc, 360.0, 30.0), ToolOutput::None);
        let second = draw_loop(&mut tool, doc, 440.0, 30.0);
        assert!(
            matches!(second, ToolOutput::Commit(Op::Tunnel(_))),
            "{second:?}"
        );
        assert!(tool.waiting().is_none());
    }
}

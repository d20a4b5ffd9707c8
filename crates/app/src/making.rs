//! Playing how a document was made: the ops of a session (an example's) applied one at a
//! time, each one's strokes first drawn over the view as they were drawn, seen through the
//! camera they were drawn with, then the op run by the edit runner exactly as a tool's op
//! (so the document at the end is the one `sketchmesh replay` makes of the session), then a
//! short hold on the result. A caption names the tool and what the step does; Pause, Skip
//! and Skip to end are touch-sized.
//!
//! A session keeps each stroke's samples in order but not their times; pointer events come
//! at a steady rate, so a stroke is drawn sample by sample at a steady pace, its length in
//! time following its number of samples, sped up or slowed to between
//! [`STROKE_MIN_MS`] and [`STROKE_MAX_MS`] so that a person can follow it.

use std::cell::RefCell;

use glam::DVec2;
use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::StrokePoint;
use sketchmesh_core::document::{Op, Session, StrokeInput};

use crate::camera::OrbitCamera;
use crate::clock;
use crate::edit_runner::{Cx, EditRunner};
use crate::overlay;
use crate::shared::Shared;

/// A drawn sample's share of the time a stroke is drawn in (ms).
const MS_PER_SAMPLE: f64 = 20.0;
/// The shortest time a stroke is drawn in (ms).
pub const STROKE_MIN_MS: f64 = 900.0;
/// The longest time a stroke is drawn in (ms).
pub const STROKE_MAX_MS: f64 = 2200.0;
/// How long the result of a step stays with its caption before the next one (ms).
const HOLD_MS: f64 = 1000.0;
/// The most playing time one frame advances (ms): a slow frame slows the playing down
/// rather than skip a stroke.
const MAX_FRAME_MS: f64 = 100.0;
/// Touch-sized buttons.
const BUTTON: egui::Vec2 = egui::vec2(96.0, 44.0);
/// The colour of a replayed stroke: the ink's.
const INK: egui::Color32 = egui::Color32::from_rgb(242, 199, 82);

/// What a step of the making is doing.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Stage {
    /// Drawing the op's strokes, since this playing time (ms).
    Drawing { since: f64 },
    /// The op is with the edit runner; `ops_before` is how many ops the document had.
    Applying { ops_before: Option<usize> },
    /// Showing the result, since this playing time (ms).
    Holding { since: f64 },
}

/// A button of the making's panel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Control {
    /// Pause, or resume when paused.
    Pause,
    /// The next step at once: the strokes drawn so far are cut short and the op applied.
    Skip,
    /// Every step left applied without drawing or holding.
    ToEnd,
}

/// How the playing of a making stands, for the page API (`examplePlayback`).
#[derive(Clone, Debug, Default, serde::Serialize)]
pub struct Standing {
    /// Whether it is still playing (paused counts).
    pub playing: bool,
    /// Whether it is paused.
    pub paused: bool,
    /// The step shown, from 1.
    pub op: usize,
    /// How many steps.
    pub of: usize,
    /// The step's caption.
    pub caption: String,
    /// `"drawing"`, `"applying"`, `"holding"` or `"done"`.
    pub stage: &'static str,
    /// How much of the step's strokes is drawn, 0 to 1.
    pub drawn: f64,
    /// The sentence that stopped it, if an op was refused.
    pub failed: Option<String>,
    /// The buttons' rectangles in CSS px, `[x, y, width, height]`: pause, skip, end.
    pub buttons: Option<[[f32; 4]; 3]>,
}

/// A making being played.
#[derive(Debug)]
pub struct Making {
    ops: Vec<Op>,
    captions: Vec<String>,
    /// The step shown.
    current: usize,
    stage: Stage,
    /// Playing time (ms), which stands still while paused.
    clock_ms: f64,
    /// The frame clock at the last frame (ms).
    last_ms: Option<f64>,
    paused: bool,
    to_end: bool,
    /// No hold after the op in progress lands (Skip was pressed while it ran).
    skip_hold: bool,
    /// The step and stroke whose camera the view took last.
    looked: Option<(usize, usize)>,
    /// The buttons as drawn last.
    buttons: Option<[egui::Rect; 3]>,
}

/// What the app does for the making this frame.
#[derive(Debug, PartialEq)]
pub enum Step {
    /// Look through this camera (a stroke's, drawn in a viewport of this size).
    Look(Camera, [f64; 2]),
    /// Hand this op to the edit runner (boxed: an op is several times a camera's size).
    Begin(Box<Op>),
    /// It is over: every op landed, or the sentence of the one refused.
    Over(Result<(), String>),
}

impl Making {
    /// The making of `session` (its JSON), a caption per op (missing ones name the op).
    pub fn new(session: &str, captions: Vec<String>) -> Result<Making, String> {
        let session = Session::from_json(session).map_err(|e| e.to_string())?;
        if session.ops.is_empty() {
            return Err(String::from("That session has no steps to play."));
        }
        Ok(Making {
            ops: session.ops,
            captions,
            current: 0,
            stage: Stage::Drawing { since: 0.0 },
            clock_ms: 0.0,
            last_ms: None,
            paused: false,
            to_end: false,
            skip_hold: false,
            looked: None,
            buttons: None,
        })
    }

    /// The caption of the step shown.
    fn caption(&self) -> String {
        match self.captions.get(self.current) {
            Some(caption) => caption.clone(),
            None => (self.ops.get(self.current)).map_or_else(String::new, |op| {
                let title = op.title();
                let mut letters = title.chars();
                letters.next().map_or_else(String::new, |first| {
                    first.to_uppercase().chain(letters).collect::<String>()
                })
            }),
        }
    }

    /// The strokes of the step shown.
    fn strokes(&self) -> Vec<StrokeInput> {
        self.ops
            .get(self.current)
            .map(Op::drawn_strokes)
            .unwrap_or_default()
    }

    /// Carries out a button's press.
    pub fn control(&mut self, control: Control) {
        match control {
            Control::Pause => self.paused ^= true,
            Control::Skip => match self.stage {
                Stage::Drawing { .. } => self.stage = Stage::Applying { ops_before: None },
                Stage::Applying { .. } => self.skip_hold = true,
                Stage::Holding { .. } => self.next_step(),
            },
            Control::ToEnd => {
                self.to_end = true;
                self.paused = false;
                self.control(Control::Skip);
            }
        }
    }

    fn next_step(&mut self) {
        self.current += 1;
        self.skip_hold = false;
        self.stage = Stage::Drawing {
            since: self.clock_ms,
        };
    }

    /// Advances the playing to the frame clock `now_ms`, given how many ops the document
    /// has and whether the edit runner is idle (no edit, nothing computing or waiting);
    /// what the app is to do, in order.
    pub fn advance(&mut self, now_ms: f64, ops: usize, idle: bool) -> Vec<Step> {
        let elapsed = self.last_ms.map_or(0.0, |last| now_ms - last);
        self.last_ms = Some(now_ms);
        if !self.paused {
            self.clock_ms += elapsed.clamp(0.0, MAX_FRAME_MS);
        }
        let mut steps = Vec::new();
        // Ops without strokes, and a hold skipped, move on within the frame.
        for _ in 0..4 {
            let before = (self.current, self.stage);
            self.advance_stage(ops, idle, &mut steps);
            if matches!(steps.last(), Some(Step::Over(_) | Step::Begin(_)))
                || before == (self.current, self.stage)
            {
                break;
            }
        }
        steps
    }

    fn advance_stage(&mut self, ops: usize, idle: bool, steps: &mut Vec<Step>) {
        match self.stage {
            Stage::Drawing { since } => {
                let strokes = self.strokes();
                let (index, _) = drawn_so_far(&strokes, self.clock_ms - since);
                let done = self.to_end || index >= strokes.len();
                if let Some(stroke) = strokes.get(index)
                    && self.looked != Some((self.current, index))
                    && !self.to_end
                {
                    self.looked = Some((self.current, index));
                    steps.push(Step::Look(stroke.camera, stroke.viewport));
                }
                if done {
                    self.stage = Stage::Applying { ops_before: None };
                }
            }
            Stage::Applying { ops_before: None } => {
                if !idle {
                    return;
                }
                let Some(op) = self.ops.get(self.current) else {
                    return steps.push(Step::Over(Ok(())));
                };
                steps.push(Step::Begin(Box::new(op.clone())));
                self.stage = Stage::Applying {
                    ops_before: Some(ops),
                };
            }
            Stage::Applying {
                ops_before: Some(before),
            } => {
                if ops > before {
                    if self.current + 1 == self.ops.len() {
                        self.current += 1;
                        return steps.push(Step::Over(Ok(())));
                    }
                    match self.to_end || self.skip_hold {
                        true => self.next_step(),
                        false => {
                            self.stage = Stage::Holding {
                                since: self.clock_ms,
                            }
                        }
                    }
                } else if idle {
                    let step = self.current + 1;
                    steps.push(Step::Over(Err(format!(
                        "Step {step} of the example was refused; the document shows the steps \
                         before it."
                    ))));
                }
            }
            Stage::Holding { since } => {
                if self.to_end || self.clock_ms - since >= HOLD_MS {
                    self.next_step();
                }
            }
        }
    }

    /// How it stands, for the page API.
    pub fn standing(&self) -> Standing {
        let (stage, drawn) = match self.stage {
            Stage::Drawing { since } => {
                let strokes = self.strokes();
                let total: f64 = strokes.iter().map(stroke_ms).sum();
                let fraction = match total > 0.0 {
                    true => ((self.clock_ms - since) / total).clamp(0.0, 1.0),
                    false => 1.0,
                };
                ("drawing", fraction)
            }
            Stage::Applying { .. } => ("applying", 1.0),
            Stage::Holding { .. } => ("holding", 1.0),
        };
        let rect = |r: &egui::Rect| [r.min.x, r.min.y, r.width(), r.height()];
        Standing {
            playing: true,
            paused: self.paused,
            op: (self.current + 1).min(self.ops.len()),
            of: self.ops.len(),
            caption: self.caption(),
            stage,
            drawn,
            failed: None,
            buttons: self
                .buttons
                .as_ref()
                .map(|b| [rect(&b[0]), rect(&b[1]), rect(&b[2])]),
        }
    }

    /// How it stands once over: every step done, or stopped by `failed`.
    pub fn ended(&self, failed: Option<String>) -> Standing {
        Standing {
            playing: false,
            op: self.current.min(self.ops.len()),
            stage: "done",
            drawn: 1.0,
            failed,
            buttons: None,
            ..self.standing()
        }
    }

    /// Draws the step's strokes so far over `viewport` (seen through `camera`) and the
    /// panel with the caption and the buttons, and carries out a button pressed.
    pub fn ui(&mut self, ui: &egui::Ui, viewport: egui::Rect, camera: &Camera) {
        let strokes = self.strokes();
        // The strokes stay while the op computes and over its result, until the next step.
        let shown_ms = match self.stage {
            Stage::Drawing { since } => self.clock_ms - since,
            Stage::Applying { .. } | Stage::Holding { .. } => f64::INFINITY,
        };
        let (index, part) = drawn_so_far(&strokes, shown_ms);
        for (k, stroke) in strokes.iter().enumerate().take(index + 1) {
            let samples = match k == index {
                true => (part * stroke.stroke.len() as f64).ceil() as usize,
                false => stroke.stroke.len(),
            };
            let points = on_screen(stroke, samples, camera, viewport);
            overlay::stroke_ui(ui, viewport, &points, INK);
        }
        self.panel_ui(ui.ctx(), viewport);
    }

    fn panel_ui(&mut self, ctx: &egui::Context, viewport: egui::Rect) {
        let mut pressed = None;
        let width = (viewport.width() - 24.0).clamp(BUTTON.x * 3.0 + 40.0, 560.0);
        let caption = self.caption();
        let counter = format!("Step {} of {}", self.current + 1, self.ops.len());
        let mut rects = [egui::Rect::NOTHING; 3];
        crate::overlay::bottom_card(ctx, "making", viewport, width, |ui| {
            ui.vertical_centered(|ui| {
                ui.label(egui::RichText::new(counter).weak());
                ui.add(egui::Label::new(egui::RichText::new(caption).size(16.0)).wrap());
                ui.horizontal(|ui| {
                    let row = 3.0 * BUTTON.x + 2.0 * ui.spacing().item_spacing.x;
                    ui.add_space(((ui.available_width() - row) / 2.0).max(0.0));
                    let pause = match self.paused {
                        true => "Resume",
                        false => "Pause",
                    };
                    for (k, (label, control)) in [
                        (pause, Control::Pause),
                        ("Skip step", Control::Skip),
                        ("Skip to end", Control::ToEnd),
                    ]
                    .into_iter()
                    .enumerate()
                    {
                        let response = ui.add(egui::Button::new(label).min_size(BUTTON));
                        rects[k] = response.rect;
                        if response.clicked() {
                            pressed = Some(control);
                        }
                    }
                });
            });
        });
        self.buttons = Some(rects);
        if let Some(control) = pressed {
            self.control(control);
        }
    }
}

/// How long a stroke is drawn in (ms).
fn stroke_ms(stroke: &StrokeInput) -> f64 {
    (stroke.stroke.len() as f64 * MS_PER_SAMPLE).clamp(STROKE_MIN_MS, STROKE_MAX_MS)
}

/// Which of `strokes` is being drawn `ms` after the first began, and how much of it (0 to
/// 1); the index is `strokes.len()` once all are drawn.
fn drawn_so_far(strokes: &[StrokeInput], mut ms: f64) -> (usize, f64) {
    for (index, stroke) in strokes.iter().enumerate() {
        let length = stroke_ms(stroke);
        if ms < length {
            return (index, (ms / length).clamp(0.0, 1.0));
        }
        ms -= length;
    }
    (strokes.len(), 1.0)
}

/// The first `samples` samples of `stroke` where they show in `viewport` through `camera`:
/// each on the plane it was drawn on (through its camera's target, facing it), seen anew.
fn on_screen(
    stroke: &StrokeInput,
    samples: usize,
    camera: &Camera,
    viewport: egui::Rect,
) -> Vec<StrokePoint> {
    let drawn_in = DVec2::from(stroke.viewport);
    let size = DVec2::new(viewport.width().into(), viewport.height().into());
    (stroke.stroke.iter().take(samples))
        .filter_map(|&[x, y, pressure]| {
            let world = stroke
                .camera
                .point_on_target_plane(DVec2::new(x, y), drawn_in)?;
            let seen = camera.screen_from_world(world, size)?;
            Some(StrokePoint {
                pos: DVec2::new(seen.x, seen.y),
                pressure: pressure.clamp(0.0, 1.0),
            })
        })
        .collect()
}

/// The view's camera for a stroke drawn through `camera` in a viewport of `drawn_in`, shown
/// in one of `size`: the same camera, moved back when the view is narrower than the one
/// drawn in, so that what was seen across it is seen again (a phone shows a desktop's
/// strokes whole).
pub fn looking_as(camera: &Camera, drawn_in: [f64; 2], size: egui::Vec2) -> OrbitCamera {
    let mut orbit = OrbitCamera::looking_as(camera);
    let aspect_drawn = drawn_in[0] / drawn_in[1].max(1.0);
    let aspect = f64::from(size.x / size.y.max(1.0));
    if aspect < aspect_drawn {
        orbit.distance *= aspect_drawn / aspect;
    }
    orbit
}

/// The making the app plays, begun when the page asks for one
/// (`window.sketchmesh.playMaking`); how it stands is in [`Shared::making`] for the page.
#[derive(Debug, Default)]
pub struct Player(Option<Making>);

impl Player {
    /// Whether a making plays (paused counts): the user's strokes and undo wait.
    pub fn is_playing(&self) -> bool {
        self.0.is_some()
    }

    /// Drops the making without a word: another document was opened.
    pub fn drop_for_another(&mut self, shared: &RefCell<Shared>) {
        if self.0.take().is_some() {
            shared.borrow_mut().making = None;
        }
    }

    /// This frame's part: begins the making the page asked for (the document shown is the
    /// new, empty one the page opened for it), then plays; the sentence to say once over.
    pub fn run(
        &mut self,
        ctx: &egui::Context,
        runner: &mut EditRunner,
        cx: &mut Cx<'_>,
        viewport: egui::Rect,
    ) -> Option<String> {
        let asked = cx.shared.borrow_mut().making_asked.take();
        if let Some((session, captions, reply)) = asked {
            let begun = Making::new(&session, captions);
            reply.send(begun.as_ref().map(|_| ()).map_err(Clone::clone));
            self.0 = begun.ok();
        }
        let making = self.0.as_mut()?;
        ctx.request_repaint();
        let over = run(making, runner, cx, viewport, clock::now_ms())?;
        self.end(over.err(), cx.shared)
    }

    /// Ends the making, all played or stopped with `why`; the sentence to say (none when
    /// nothing played).
    pub fn end(&mut self, why: Option<String>, shared: &RefCell<Shared>) -> Option<String> {
        let ended = self.0.take()?;
        shared.borrow_mut().making = serde_json::to_value(ended.ended(why.clone())).ok();
        Some(why.unwrap_or_else(|| {
            String::from("That is how it was made. It is yours now: change it as you like.")
        }))
    }

    /// Draws the making over the view, if one plays (see [`Making::ui`]); whether it did.
    pub fn ui(&mut self, ui: &egui::Ui, viewport: egui::Rect, shared: &RefCell<Shared>) -> bool {
        let Some(making) = &mut self.0 else {
            return false;
        };
        let camera = shared.borrow().camera.camera();
        making.ui(ui, viewport, &camera);
        shared.borrow_mut().making = serde_json::to_value(making.standing()).ok();
        true
    }
}

/// Runs this frame's part of `making` with the edit runner: the view turned to a stroke's
/// camera, an op begun; what it ended with, once over.
fn run(
    making: &mut Making,
    runner: &mut EditRunner,
    cx: &mut Cx<'_>,
    viewport: egui::Rect,
    now_ms: f64,
) -> Option<Result<(), String>> {
    let idle =
        runner.edit().is_none() && !runner.is_computing() && runner.waiting().next().is_none();
    let ops = cx.shared.borrow().editor.ops().len();
    for step in making.advance(now_ms, ops, idle) {
        match step {
            Step::Look(camera, drawn_in) => {
                cx.shared.borrow_mut().camera = looking_as(&camera, drawn_in, viewport.size());
            }
            Step::Begin(op) => runner.begin(*op, false, cx),
            Step::Over(result) => return Some(result),
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn making() -> Making {
        let session = r#"{"format":"sketchmesh-session","version":1,"ops":[
{"op":"stroke","viewport":[800,600],"camera":{"eye":[0,0,5],"target":[0,0,0],"up":[0,1,0],"fov_y_deg":45},"stroke":[[100,100,0.5],[200,120,0.5],[300,160,0.5]]},
{"op":"keyframe","time":0}]}"#;
        Making::new(session, vec![String::from("Sketch: ink")]).expect("a session")
    }

    #[test]
    fn a_step_draws_its_stroke_then_begins_its_op_then_holds() {
        let mut m = making();
        let steps = m.advance(0.0, 0, true);
        assert!(
            matches!(steps[0], Step::Look(_, [800.0, 600.0])),
            "{steps:?}"
        );
        assert_eq!(m.standing().stage, "drawing");
        // Half way through the stroke's 900 ms.
        for t in (50..=450).step_by(50) {
            assert!(m.advance(f64::from(t), 0, true).is_empty());
        }
        assert!((m.standing().drawn - 0.5).abs() < 1e-9);
        let steps = (500..=900)
            .step_by(50)
            .flat_map(|t| m.advance(f64::from(t), 0, true));
        let begun: Vec<Step> = steps.collect();
        assert!(
            matches!(begun.as_slice(), [Step::Begin(op)] if matches!(**op, Op::Stroke(_))),
            "{begun:?}"
        );
        assert_eq!(m.standing().stage, "applying");
        assert!(m.advance(950.0, 0, false).is_empty(), "it waits for the op");
        assert!(m.advance(1000.0, 1, true).is_empty());
        assert_eq!(m.standing().stage, "holding");
        assert_eq!(m.standing().caption, "Sketch: ink");
    }

    #[test]
    fn pause_holds_skip_moves_on_and_the_last_op_ends_it() {
        let mut m = making();
        m.advance(0.0, 0, true);
        m.control(Control::Pause);
        for t in (100..=3000).step_by(100) {
            assert!(m.advance(f64::from(t), 0, true).is_empty());
        }
        assert_eq!((m.standing().stage, m.standing().drawn), ("drawing", 0.0));
        m.control(Control::Pause);
        m.control(Control::Skip);
        assert!(matches!(m.advance(3100.0, 0, true)[..], [Step::Begin(_)]));
        m.control(Control::Skip);
        // Landed: no hold, the next op has no stroke and begins at once.
        let steps = m.advance(3200.0, 1, true);
        assert!(
            matches!(&steps[..], [Step::Begin(op)] if matches!(**op, Op::Keyframe(_))),
            "{steps:?}"
        );
        assert_eq!(m.standing().caption, "Keyframe");
        assert_eq!(m.advance(3300.0, 2, true), vec![Step::Over(Ok(()))]);
        assert_eq!((m.ended(None).op, m.ended(None).of), (2, 2));
    }

    #[test]
    fn a_refused_op_ends_it_with_a_sentence() {
        let mut m = making();
        m.control(Control::ToEnd);
        assert!(matches!(m.advance(0.0, 0, true)[..], [Step::Begin(_)]));
        let steps = m.advance(20.0, 0, true);
        assert!(matches!(&steps[..], [Step::Over(Err(why))] if why.contains("Step 1")));
    }

    #[test]
    fn a_stroke_shows_where_it_was_drawn_and_a_narrow_view_sees_all_of_it() {
        let m = making();
        let stroke = &m.strokes()[0];
        let wide = egui::Rect::from_min_size(egui::pos2(0.0, 40.0), egui::vec2(800.0, 600.0));
        let points = on_screen(stroke, 3, &stroke.camera, wide);
        assert!((points[2].pos - DVec2::new(300.0, 160.0)).length() < 1e-9);
        let narrow = egui::vec2(300.0, 600.0);
        let camera = looking_as(&stroke.camera, stroke.viewport, narrow).camera();
        let rect = egui::Rect::from_min_size(egui::Pos2::ZERO, narrow);
        for p in on_screen(stroke, 3, &camera, rect) {
            assert!(p.pos.x > 0.0 && p.pos.x < 300.0, "{p:?}");
        }
    }
}

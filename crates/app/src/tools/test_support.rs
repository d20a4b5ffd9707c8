//! What the tools' tests share: a pen sample, the view they act in, a document with a shape,
//! a pen stroke fed to a tool.

use egui::{Rect, pos2};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{Document, Editor, Op, StrokeInput};

use super::{Tool, ToolEvent, ToolOutput, ViewCtx};
use crate::input::{Phase, PointerKind, PointerSample};

/// A pen sample at `(x, y)` screen points, half pressure.
pub fn pen(phase: Phase, x: f32, y: f32) -> PointerSample {
    PointerSample {
        id: 1,
        phase,
        pos_in_screen: pos2(x, y),
        pressure: 0.5,
        kind: PointerKind::Pen,
        buttons: 1,
        contact: 0.0,
        time: 0.0,
    }
}

/// An 800×600 view 40 points below the top of the screen, default camera.
pub fn view() -> ViewCtx {
    ViewCtx {
        camera: Camera::default(),
        viewport: Rect::from_min_max(pos2(0.0, 40.0), pos2(800.0, 640.0)),
    }
}

/// A document with a shape created from a circle of 150 px around the view's centre
/// (screen `(400, 340)`).
pub fn shape() -> Editor {
    let circle = (0..=80)
        .map(|i| {
            let a = std::f64::consts::TAU * f64::from(i) / 80.0;
            [400.0 + 150.0 * a.cos(), 300.0 + 150.0 * a.sin(), 0.5]
        })
        .collect();
    let mut editor = Editor::new();
    let input = StrokeInput {
        viewport: [800.0, 600.0],
        camera: Camera::default(),
        stroke: circle,
    };
    editor.apply(Op::Create(input.into())).unwrap();
    editor
}

/// Feeds `tool` a pen stroke through `points` (screen points; one point is a tap) in
/// [`view`]: what it answered to the pointer going down, to each move, and to the release.
pub fn stroke(tool: &mut dyn Tool, doc: &Document, points: &[(f32, f32)]) -> Vec<ToolOutput> {
    let v = view();
    (stroke_events(points).iter())
        .map(|event| tool.on_event(event, &v, doc))
        .collect()
}

/// The events of a pen stroke through `points` (see [`stroke`]).
pub fn stroke_events(points: &[(f32, f32)]) -> Vec<ToolEvent> {
    let last = points.len() - 1;
    let mut events: Vec<ToolEvent> = (points.iter().enumerate())
        .map(|(k, &(x, y))| match k {
            0 => ToolEvent::Begin(pen(Phase::Down, x, y)),
            k if k == last => ToolEvent::End(pen(Phase::Up, x, y)),
            _ => ToolEvent::Move(pen(Phase::Move, x, y)),
        })
        .collect();
    if last == 0 {
        let (x, y) = points[0];
        events.push(ToolEvent::End(pen(Phase::Up, x, y)));
    }
    events
}

/// `n + 1` points from `from` to `to`, evenly spaced.
pub fn line(from: (f32, f32), to: (f32, f32), n: usize) -> Vec<(f32, f32)> {
    (0..=n)
        .map(|k| {
            let t = k as f32 / n as f32;
            (from.0 + t * (to.0 - from.0), from.1 + t * (to.1 - from.1))
        })
        .collect()
}

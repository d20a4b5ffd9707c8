//! What the tools' tests share: a pen sample, the view they act in, a document with a shape.

use egui::{Rect, pos2};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{Editor, Op, StrokeInput};

use super::ViewCtx;
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

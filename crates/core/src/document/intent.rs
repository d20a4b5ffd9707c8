//! What a finished stroke means: a new shape, or ink.
//!
//! FiberMesh's sketch tool reads intent from the stroke itself: a closed stroke drawn on
//! empty canvas creates a shape; a stroke that starts on a model is not a creation (later
//! issues make it a curve on that model); anything else stays as ink on the drawing plane.

use glam::DVec2;

use super::{Document, Op, StrokeInput};
use crate::curve::is_closed_loop;
use crate::geometry::raycast;

/// How far apart, in CSS px, a stroke's ends may be for it to read as closed.
pub const CLOSE_TOLERANCE_PX: f64 = 40.0;

/// The op a finished sketch stroke stands for in `doc`.
pub fn op_for_stroke(doc: &Document, input: StrokeInput) -> Op {
    let points = input.points();
    let closed = is_closed_loop(&points, CLOSE_TOLERANCE_PX);
    if closed && !starts_on_model(doc, &input) {
        Op::Create(input)
    } else {
        Op::Stroke(input)
    }
}

/// Whether the stroke's first point lies over a model in the stroke's view.
pub fn starts_on_model(doc: &Document, input: &StrokeInput) -> bool {
    let Some(&[x, y, _]) = input.stroke.first() else {
        return false;
    };
    let (origin, dir) = input
        .camera
        .ray_in_world(DVec2::new(x, y), input.viewport_size());
    doc.models
        .iter()
        .any(|m| raycast(&m.mesh, origin, dir).is_some())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::Camera;

    fn circle(center: DVec2, radius: f64, turns: f64) -> StrokeInput {
        let n = 80;
        StrokeInput {
            viewport: [800.0, 600.0],
            camera: Camera::default(),
            stroke: (0..=n)
                .map(|i| {
                    let a = turns * std::f64::consts::TAU * i as f64 / n as f64;
                    [
                        center.x + radius * a.cos(),
                        center.y + radius * a.sin(),
                        0.5,
                    ]
                })
                .collect(),
        }
    }

    #[test]
    fn closed_stroke_on_empty_canvas_creates_and_open_stroke_inks() {
        let doc = Document::default();
        assert!(matches!(
            op_for_stroke(&doc, circle(DVec2::new(400.0, 300.0), 120.0, 1.0)),
            Op::Create(_)
        ));
        assert!(matches!(
            op_for_stroke(&doc, circle(DVec2::new(400.0, 300.0), 120.0, 0.5)),
            Op::Stroke(_)
        ));
    }

    #[test]
    fn closed_stroke_starting_on_a_model_is_not_a_creation() {
        let mut editor = crate::document::Editor::new();
        editor
            .apply(Op::Create(circle(DVec2::new(400.0, 300.0), 150.0, 1.0)))
            .expect("creation");
        let doc = editor.document();
        // Starts at (470, 300): on the model. Beside it, at (700, 300): empty canvas.
        assert!(matches!(
            op_for_stroke(doc, circle(DVec2::new(400.0, 300.0), 70.0, 1.0)),
            Op::Stroke(_)
        ));
        assert!(matches!(
            op_for_stroke(doc, circle(DVec2::new(690.0, 300.0), 60.0, 1.0)),
            Op::Create(_)
        ));
    }
}

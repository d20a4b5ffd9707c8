//! What a finished stroke means: a new shape, a curve on a shape, or ink.
//!
//! FiberMesh's sketch tool reads intent from the stroke itself (thesis §3.2.1, Fig. 3.4): a
//! closed stroke drawn on empty canvas creates a shape; a stroke that starts on a shape with
//! control curves adds a curve to it (a closed one after a confirming tap, without which it
//! stays ink, so nothing the user drew is lost; a second closed loop instead of the tap
//! drills a tunnel between the two, and a stroke from near the loop out and back to near
//! it grows a limb there, whose silhouette it is); a stroke from beside a shape across it cuts
//! the shape, unless a tap follows at once, which makes it a cross-section loop instead (the
//! gesture the thesis uses to get a handle for fatness). Anything else is ink on the drawing
//! plane.

use glam::{DVec2, DVec3};

use super::{AddCurveInput, Document, Model, Op, StrokeInput, StrokePairInput};
use crate::curve::polyline::centroid;
use crate::curve::polyline::distance_to_polyline;
use crate::curve::{StrokePoint, is_closed_loop};
use crate::fibermesh::extrude::NEAR_BASE_PX;
use crate::geometry::raycast;

/// How far apart, in CSS px, a stroke's ends may be for it to read as closed.
pub const CLOSE_TOLERANCE_PX: f64 = 40.0;

/// The op a finished sketch stroke stands for in `doc`. An op for which [`needs_tap`] holds
/// is to be applied only if a tap follows; otherwise the stroke is ink.
pub fn op_for_stroke(doc: &Document, input: StrokeInput) -> Op {
    let points = input.points();
    let closed = is_closed_loop(&points, CLOSE_TOLERANCE_PX);
    let on_curved = |sample: Option<&[f64; 3]>| {
        sample.is_some_and(|&[x, y, _]| hits_model(doc, &input, DVec2::new(x, y), has_curves))
    };
    let starts_on_curved = on_curved(input.stroke.first());
    let ends_on_curved = on_curved(input.stroke.last());
    let crosses_curved = || {
        input.stroke[1..input.stroke.len().saturating_sub(1)]
            .iter()
            .any(|s| on_curved(Some(s)))
    };
    if starts_on_curved {
        Op::AddCurve(curve_input(input, closed, false))
    } else if closed && !starts_on_model(doc, &input) {
        Op::Create(input.into())
    } else if !closed && !ends_on_curved && input.stroke.len() > 2 && crosses_curved() {
        Op::AddCurve(curve_input(input, false, true))
    } else {
        Op::Stroke(input)
    }
}

/// Whether `op` (from [`op_for_stroke`]) waits for a confirming tap: a closed curve or a
/// cross-section.
pub fn needs_tap(op: &Op) -> bool {
    matches!(op, Op::AddCurve(input) if input.closed || input.cross_section)
}

/// Whether `op` is a cross-section, which becomes a cut when no tap comes ([`cut_instead`]).
pub fn is_cross_section(op: &Op) -> bool {
    matches!(op, Op::AddCurve(input) if input.cross_section)
}

/// The tunnel two closed loops on shapes make, drawn one after the other without the tap
/// that would make the first a curve: `None` unless both are such loops.
pub fn tunnel_from(first: &Op, second: &Op) -> Option<Op> {
    let is_loop =
        |op: &Op| matches!(op, Op::AddCurve(input) if input.closed && !input.cross_section);
    match (first, second) {
        (Op::AddCurve(a), Op::AddCurve(b)) if is_loop(first) && is_loop(second) => {
            Some(Op::Tunnel(StrokePairInput {
                strokes: [StrokeInput::of_add_curve(a), StrokeInput::of_add_curve(b)],
            }))
        }
        _ => None,
    }
}

/// The extrusion a closed loop on a shape and a following stroke make when the stroke starts
/// and ends within [`NEAR_BASE_PX`] of the loop and leaves the shapes on the way, both drawn
/// in one view: the stroke is the new limb's silhouette. `None` otherwise. (Its ends may be
/// as close as a closed loop's: what tells it from a tunnel's second loop is that it leaves
/// the surface.)
pub fn extrude_from(doc: &Document, first: &Op, second: &StrokeInput) -> Option<Op> {
    let Op::AddCurve(base) = first else {
        return None;
    };
    if !base.closed || base.cross_section || base.camera != second.camera {
        return None;
    }
    let outline: Vec<DVec2> = (base.stroke.iter())
        .chain(base.stroke.first())
        .map(|&[x, y, _]| DVec2::new(x, y))
        .collect();
    let points = second.points();
    let near = |p: Option<&StrokePoint>| {
        p.is_some_and(|p| distance_to_polyline(p.pos, &outline) <= NEAR_BASE_PX)
    };
    let leaves = || (points.iter()).any(|p| !hits_model(doc, second, p.pos, |_| true));
    (near(points.first()) && near(points.last()) && leaves()).then(|| {
        Op::Extrude(StrokePairInput {
            strokes: [StrokeInput::of_add_curve(base), second.clone()],
        })
    })
}

/// The cut for a cross-section stroke whose tap did not come; other ops stay as they are.
pub fn cut_instead(op: Op) -> Op {
    match op {
        Op::AddCurve(input) if input.cross_section => Op::Cut(StrokeInput::of_add_curve(&input)),
        other => other,
    }
}

/// The ink op for a stroke whose confirming tap did not come.
pub fn ink_instead(op: Op) -> Op {
    match op {
        Op::AddCurve(input) => Op::Stroke(StrokeInput::of_add_curve(&input)),
        other => other,
    }
}

/// Whether the stroke's first point lies over a model in the stroke's view.
pub fn starts_on_model(doc: &Document, input: &StrokeInput) -> bool {
    model_under(doc, input).is_some()
}

/// The index of the model nearest the eye under the stroke's first point (a tap), if any.
pub fn model_under(doc: &Document, input: &StrokeInput) -> Option<usize> {
    let &[x, y, _] = input.stroke.first()?;
    model_at(doc, input, DVec2::new(x, y))
}

/// The index of the model a closed stroke (a lasso) is drawn around: the one under its
/// centroid, else under the first of its samples that lies over a model.
pub fn model_in_lasso(doc: &Document, lasso: &StrokeInput) -> Option<usize> {
    let points: Vec<DVec2> = lasso.points().iter().map(|p| p.pos).collect();
    std::iter::once(centroid(&points))
        .chain(points)
        .find_map(|screen| model_at(doc, lasso, screen))
}

/// The index of the model nearest the eye under `screen`, seen in the stroke's view.
fn model_at(doc: &Document, input: &StrokeInput, screen: DVec2) -> Option<usize> {
    surface_at(doc, input, screen).map(|(index, _)| index)
}

/// The model nearest the eye under `screen`, seen in the stroke's view, and the point of
/// its surface there.
pub fn surface_at(doc: &Document, input: &StrokeInput, screen: DVec2) -> Option<(usize, DVec3)> {
    let (origin, dir) = input.camera.ray_in_world(screen, input.viewport_size());
    let hits =
        doc.models.iter().enumerate().filter_map(|(i, model)| {
            raycast(&model.mesh, origin, dir).map(|hit| (hit.distance, i))
        });
    hits.min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(distance, i)| (i, origin + dir * distance))
}

/// Whether the view ray through `screen` hits a model for which `accept` holds.
fn hits_model(
    doc: &Document,
    input: &StrokeInput,
    screen: DVec2,
    accept: impl Fn(&Model) -> bool,
) -> bool {
    let (origin, dir) = input.camera.ray_in_world(screen, input.viewport_size());
    doc.models
        .iter()
        .any(|m| accept(m) && raycast(&m.mesh, origin, dir).is_some())
}

/// Whether a model's shape is held by control curves (made here, or imported with them).
fn has_curves(model: &Model) -> bool {
    !model.curves.is_empty()
}

fn curve_input(input: StrokeInput, closed: bool, cross_section: bool) -> AddCurveInput {
    AddCurveInput {
        viewport: input.viewport,
        camera: input.camera,
        stroke: input.stroke,
        closed,
        cross_section,
    }
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
    fn a_lasso_finds_the_model_it_is_drawn_around_even_off_its_centre() {
        let sphere = Model {
            mesh: crate::mesh::primitives::icosphere(0.5, 2),
            ..Model::default()
        };
        let mut doc = Document::default();
        doc.models.push(std::sync::Arc::new(sphere));
        let centre = Camera::default()
            .screen_from_world(glam::DVec3::ZERO, DVec2::new(800.0, 600.0))
            .unwrap()
            .truncate();
        // Around the sphere; then a crescent whose centroid misses it but whose samples cross
        // it; then a loop in empty space.
        assert_eq!(model_in_lasso(&doc, &circle(centre, 200.0, 1.0)), Some(0));
        let crescent = circle(centre + DVec2::new(400.0, 0.0), 400.0, 0.6);
        assert_eq!(model_in_lasso(&doc, &crescent), Some(0));
        assert_eq!(
            model_in_lasso(&doc, &circle(DVec2::new(60.0, 60.0), 30.0, 1.0)),
            None
        );
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
    fn strokes_on_a_shape_add_curves() {
        let mut editor = crate::document::Editor::new();
        editor
            .apply(Op::Create(
                circle(DVec2::new(400.0, 300.0), 150.0, 1.0).into(),
            ))
            .expect("creation");
        let doc = editor.document();
        // Open, starting on the model: an open curve, applied at once.
        let open = op_for_stroke(doc, circle(DVec2::new(400.0, 300.0), 70.0, 0.5));
        assert!(matches!(&open, Op::AddCurve(c) if !c.closed && !c.cross_section));
        assert!(!needs_tap(&open));
        // From beside the model across it: a cross-section, waiting for a tap.
        let across = StrokeInput {
            stroke: (0..=40)
                .map(|i| [200.0 + 10.0 * f64::from(i), 300.0, 0.5])
                .collect(),
            ..circle(DVec2::ZERO, 1.0, 1.0)
        };
        let cross = op_for_stroke(doc, across.clone());
        assert!(matches!(&cross, Op::AddCurve(c) if c.cross_section));
        assert!(needs_tap(&cross));
        assert_eq!(ink_instead(cross), Op::Stroke(across));
    }

    #[test]
    fn closed_stroke_starting_on_a_model_is_not_a_creation() {
        let mut editor = crate::document::Editor::new();
        editor
            .apply(Op::Create(
                circle(DVec2::new(400.0, 300.0), 150.0, 1.0).into(),
            ))
            .expect("creation");
        let doc = editor.document();
        // Starts at (470, 300): on the model, so a closed curve after a tap. Beside it, at
        // (700, 300): empty canvas.
        let on_model = op_for_stroke(doc, circle(DVec2::new(400.0, 300.0), 70.0, 1.0));
        assert!(matches!(&on_model, Op::AddCurve(c) if c.closed));
        assert!(needs_tap(&on_model));
        assert!(matches!(
            op_for_stroke(doc, circle(DVec2::new(690.0, 300.0), 60.0, 1.0)),
            Op::Create(_)
        ));
    }
}

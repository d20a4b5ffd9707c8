//! What the curve ops share: reading the stroke, picking the model and the curve vertex
//! under it, and putting the changed model together.

use glam::DVec2;

use crate::document::{CommandError, Document, StrokeInput};
use crate::fibermesh::ViewedStroke;
use crate::fibermesh::curve_tools::VisibleCurves;
use crate::geometry::Bvh;
use crate::mesh::{Mesh, VertexId};
use crate::model::ControlCurve;
use crate::model::Model;

/// How close (CSS px) a stroke must pass to a curve to act on it.
pub const CURVE_PICK_RADIUS_PX: f64 = 16.0;

/// The stroke's points in screen space, after checking the view and the numbers.
///
/// Errors: [`CommandError::BadView`], [`CommandError::StrokeNotFinite`],
/// [`CommandError::StrokeTooShort`] (fewer than `min_points` samples).
pub(crate) fn screen_stroke(
    input: &StrokeInput,
    min_points: usize,
) -> Result<Vec<DVec2>, CommandError> {
    input.checked_viewport()?;
    if input.stroke.iter().flatten().any(|x| !x.is_finite()) {
        return Err(CommandError::StrokeNotFinite);
    }
    if input.stroke.len() < min_points {
        return Err(CommandError::StrokeTooShort);
    }
    Ok(input.points().iter().map(|p| p.pos).collect())
}

/// A stroke with its view, as the topology ops take it.
pub(super) fn viewed<'a>(input: &'a StrokeInput, stroke: &'a [DVec2]) -> ViewedStroke<'a> {
    ViewedStroke {
        camera: &input.camera,
        viewport: input.viewport_size(),
        stroke,
    }
}

/// Whether the curve ops may act on `model`: whether its shape is defined by curves.
pub(super) fn has_curves(model: &Model) -> bool {
    !model.curves.is_empty()
}

/// A curve vertex a pointer is over, found in screen space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct CurvePick {
    /// Index of the model in the document.
    pub(super) model: usize,
    /// The curve vertex.
    pub(super) vertex: VertexId,
}

/// The visible curve vertex nearest to `screen` within [`CURVE_PICK_RADIUS_PX`], over all
/// models with curves.
pub(super) fn pick_curve_vertex(
    doc: &Document,
    input: &StrokeInput,
    screen: DVec2,
) -> Result<CurvePick, CommandError> {
    let viewport = input.viewport_size();
    let mut best: Option<(f64, CurvePick)> = None;
    for (index, model) in doc.models.iter().enumerate() {
        if !has_curves(model) {
            continue;
        }
        let vertices = || model.curves.iter().flat_map(|c| &c.vertices);
        let visible = VisibleCurves::new(&model.mesh, vertices(), &input.camera, viewport);
        for &v in vertices() {
            let Some(distance) = visible.screen(v).map(|s| s.distance(screen)) else {
                continue;
            };
            if distance <= CURVE_PICK_RADIUS_PX && best.is_none_or(|(d, _)| distance < d) {
                let pick = CurvePick {
                    model: index,
                    vertex: v,
                };
                best = Some((distance, pick));
            }
        }
    }
    best.map(|(_, pick)| pick).ok_or(CommandError::NoCurveHere)
}

/// The length of a mesh's bounding-box diagonal.
pub(super) fn bounding_diagonal(mesh: &Mesh) -> f64 {
    mesh.bounding_box().map_or(1.0, |(lo, hi)| lo.distance(hi))
}

/// `model` with a new mesh and curves, keeping its name, appearance and input (which apply
/// while the new mesh keeps the triangles).
pub(super) fn replaced(model: &Model, mesh: Mesh, curves: Vec<ControlCurve>) -> Model {
    Model {
        curves,
        mesh,
        ..model.clone()
    }
}

/// Inserts `new` between consecutive vertices `a` and `b` of `curve` (either order,
/// including the closing edge), where an embedding split that curve edge.
fn insert_on_edge(curve: &mut ControlCurve, a: VertexId, b: VertexId, new: VertexId) {
    let n = curve.vertices.len();
    let n_edges = if curve.is_closed {
        n
    } else {
        n.saturating_sub(1)
    };
    let is_edge = |k: usize| {
        let (p, q) = (curve.vertices[k], curve.vertices[(k + 1) % n]);
        (p, q) == (a, b) || (p, q) == (b, a)
    };
    if let Some(k) = (0..n_edges).find(|&k| is_edge(k)) {
        curve.vertices.insert(k + 1, new);
    }
}

/// The model for which `accept` holds that most stroke samples hit, if any sample hits one.
pub(super) fn model_crossed(
    doc: &Document,
    input: &StrokeInput,
    stroke: &[DVec2],
    accept: impl Fn(&Model) -> bool,
) -> Option<usize> {
    let viewport = input.viewport_size();
    let rays: Vec<_> = stroke
        .iter()
        .map(|&s| input.camera.ray_in_world(s, viewport))
        .collect();
    doc.models
        .iter()
        .enumerate()
        .filter(|(_, model)| accept(model))
        .map(|(index, model)| {
            let bvh = Bvh::new(&model.mesh);
            let hits = rays
                .iter()
                .filter(|&&(origin, dir)| bvh.raycast(&model.mesh, origin, dir).is_some())
                .count();
            (hits, index)
        })
        .filter(|&(hits, _)| hits > 0)
        .max()
        .map(|(_, index)| index)
}

/// `curves` with the vertices that split their edges (`split_edges`, as an embedding logs
/// them) inserted.
pub(in crate::document) fn with_splits(
    curves: &[ControlCurve],
    split_edges: &[(VertexId, VertexId, VertexId)],
) -> Vec<ControlCurve> {
    let mut curves = curves.to_vec();
    for &(a, b, new) in split_edges {
        for curve in &mut curves {
            insert_on_edge(curve, a, b, new);
        }
    }
    curves
}

/// `curves` after an op that split edges (`split_edges`, as an embedding logs them), removed
/// vertices and renumbered the rest (`remap`) into `mesh`: each curve gets the split
/// vertices on its edges, then keeps its runs that survive.
pub(super) fn carried_over(
    curves: &[ControlCurve],
    split_edges: &[(VertexId, VertexId, VertexId)],
    remap: &[Option<VertexId>],
    mesh: &Mesh,
) -> Vec<ControlCurve> {
    with_splits(curves, split_edges)
        .iter()
        .flat_map(|curve| kept_pieces(curve, remap, mesh))
        .collect()
}

/// The runs of `curve` that an op kept, in its new mesh's numbering: a closed curve cut
/// open becomes open runs, each of at least two vertices joined by mesh edges.
fn kept_pieces(curve: &ControlCurve, remap: &[Option<VertexId>], mesh: &Mesh) -> Vec<ControlCurve> {
    let mapped: Vec<Option<VertexId>> = curve.vertices.iter().map(|v| remap[v.index()]).collect();
    let n = mapped.len();
    let joined = |k: usize| match (mapped[k], mapped[(k + 1) % n]) {
        (Some(a), Some(b)) => mesh.find_edge(a, b).is_some(),
        _ => false,
    };
    let n_links = if curve.is_closed {
        n
    } else {
        n.saturating_sub(1)
    };
    if n > 0 && (0..n_links).all(joined) {
        let vertices = mapped.into_iter().flatten().collect();
        return vec![ControlCurve {
            vertices,
            ..curve.clone()
        }];
    }
    // Start after a break, so that a closed curve's run across its first vertex stays whole.
    let start = if curve.is_closed {
        (0..n).find(|&k| !joined(k)).map_or(0, |k| k + 1)
    } else {
        0
    };
    let mut pieces = Vec::new();
    let mut run: Vec<VertexId> = Vec::new();
    for step in 0..n {
        let k = (start + step) % n;
        if let Some(v) = mapped[k] {
            run.push(v);
        }
        let last = step + 1 == n;
        if last || !joined(k) {
            if run.len() >= 2 {
                pieces.push(ControlCurve {
                    vertices: std::mem::take(&mut run),
                    is_closed: false,
                    kind: curve.kind,
                });
            }
            run.clear();
        }
    }
    pieces
}

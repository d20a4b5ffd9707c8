//! Over-sketching where a control curve draws the outline (Nealen's thesis §3.2.2 with
//! SilSketch's matching, ch. 5): the curve piece the stroke redraws moves onto it, and the
//! fair surface settles through the curves as after a pull, so the curve stays the outline.
//!
//! Bending the mesh instead (the over-sketch of any mesh, [`crate::oversketch`]) left the
//! curve 2–2.6 px off the new outline at the stroke's ends, with a sliver of surface showing
//! beyond it: the curve followed its vertices, but the fair surface was not asked again.

use glam::{DVec2, DVec3};

use super::pull::region_radius;
use super::settle::{Change, remesh_and_settle, settle};
use super::shared::replaced;
use crate::camera::Camera;
use crate::curve::polyline::distance_to_polyline;
use crate::document::CommandError;
use crate::fibermesh::curve_tools::VisibleCurves;
use crate::geometry::Bvh;
use crate::mesh::VertexId;
use crate::model::Model;
use crate::oversketch::{
    MatchParams, handle_points, match_stroke, outline_targets, simplify_stroke,
};
use crate::silhouette::silhouettes;

/// A curve point is on the outline when it is drawn within this many px of a silhouette.
const ON_OUTLINE_PX: f64 = 3.0;

/// The fewest curve vertices a redrawn piece has.
const MIN_PIECE: usize = 3;

/// Over-sketches `model` along one of its control curves: the new model and the match
/// score, or `None` when no visible piece of a curve on the outline matches `stroke`
/// confidently (the caller then bends the mesh).
///
/// Errors: failures of the surface solve or the remesher.
pub(in crate::document) fn oversketch_curve(
    model: &Model,
    camera: &Camera,
    viewport: DVec2,
    stroke: &[DVec2],
) -> Option<Result<(Model, f64), CommandError>> {
    let stroke = simplify_stroke(stroke);
    let (piece, score) = matched_piece(model, camera, viewport, &stroke)?;
    let worlds: Vec<DVec3> = piece.iter().map(|&(v, _)| model.mesh.position(v)).collect();
    let screen: Vec<DVec2> = piece.iter().map(|&(_, s)| s).collect();
    let targets = outline_targets(camera, viewport, &worlds, &screen, &stroke);
    let vertices: Vec<VertexId> = piece.iter().map(|&(v, _)| v).collect();
    Some(moved(model, &vertices, &targets).map(|model| (model, score)))
}

/// The curve vertices (with where they are drawn) of the piece `stroke` redraws, in the
/// stroke's direction, and the match score: only visible vertices on the outline.
fn matched_piece(
    model: &Model,
    camera: &Camera,
    viewport: DVec2,
    stroke: &[DVec2],
) -> Option<(Vec<(VertexId, DVec2)>, f64)> {
    let all = model.curves.iter().flat_map(|c| &c.vertices);
    let visible = VisibleCurves::new(&model.mesh, all, camera, viewport);
    let polylines: Vec<Vec<DVec2>> = model
        .curves
        .iter()
        .map(|curve| {
            let mut points: Vec<DVec2> = curve
                .vertices
                .iter()
                .map(|&v| {
                    let world = model.mesh.position(v);
                    camera
                        .screen_from_world(world, viewport)
                        .map_or(DVec2::ZERO, |p| p.truncate())
                })
                .collect();
            if curve.is_closed {
                points.push(points[0]);
            }
            points
        })
        .collect();
    let slices: Vec<&[DVec2]> = polylines.iter().map(Vec::as_slice).collect();
    let found = match_stroke(stroke, &slices, &MatchParams::default())?;
    let curve = &model.curves[found.silhouette];
    let n = curve.vertices.len();
    let mut piece: Vec<(VertexId, DVec2)> = Vec::new();
    for (index, _) in handle_points(&polylines[found.silhouette], found.start, found.end) {
        let v = curve.vertices[(index.round() as usize) % n];
        if piece.last().is_none_or(|&(last, _)| last != v) {
            piece.push((v, visible.screen(v)?));
        }
    }
    let outline = outline_polylines(model, camera, viewport);
    let on_outline = piece.iter().all(|&(_, p)| {
        outline
            .iter()
            .any(|o| distance_to_polyline(p, o) <= ON_OUTLINE_PX)
    });
    (found.confident && on_outline && piece.len() >= MIN_PIECE).then_some((piece, found.score))
}

/// The screen polylines of `model`'s visible silhouettes.
fn outline_polylines(model: &Model, camera: &Camera, viewport: DVec2) -> Vec<Vec<DVec2>> {
    silhouettes(&model.mesh, &Bvh::new(&model.mesh), camera, viewport)
        .iter()
        .map(|s| s.points.iter().map(|p| p.screen).collect())
        .collect()
}

/// `model` with the curve `vertices` at `targets` and the surface settled and remeshed
/// around them.
fn moved(model: &Model, vertices: &[VertexId], targets: &[DVec3]) -> Result<Model, CommandError> {
    let mut mesh = model.mesh.clone();
    let mut farthest: f64 = 0.0;
    for (&v, &target) in vertices.iter().zip(targets) {
        farthest = farthest.max(target.distance(mesh.position(v)));
        mesh.positions_mut()[v.index()] = target;
    }
    let change = Change {
        around: vertices,
        radius: region_radius(&model.mesh, farthest),
    };
    settle(
        &mut mesh,
        &model.curves,
        model.mesh.positions(),
        change,
        false,
    )?;
    let (mesh, curves) = remesh_and_settle(&mesh, &model.curves, change)?;
    Ok(replaced(model, mesh, curves))
}

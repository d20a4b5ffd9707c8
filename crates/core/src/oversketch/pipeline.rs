//! The whole over-sketch of one mesh: silhouettes, handle, targets, ROI and the Laplacian
//! edit (SilSketch, Nealen's dissertation §5.4; SEED §4).
//!
//! 1. Silhouettes of the mesh as seen ([`crate::silhouette::silhouettes`]), as screen
//!    polylines (a closed one repeats its first point at the end).
//! 2. The stroke simplified ([`simplify_stroke`]) and matched ([`match_stroke`]); no match
//!    or a guess is refused rather than applied.
//! 3. The handle: the silhouette points of the matched piece, each a point inside its mesh
//!    edge. The fractional ends of the match are rounded to the nearest silhouette point.
//! 4. The bend ([`super::bend`]): targets on the stroke by relative arclength, blended
//!    at the ends and unprojected at each point's depth; the ROI; the band of vertices around
//!    the handle as constraints; a detail-preserving edit with rotations.

use glam::{DVec2, DVec3};

use super::bend::{BendOptions, HandleCurve, bend};
use super::error::OversketchError;
use super::{MatchParams, handle_points, match_stroke, simplify_stroke};
use crate::camera::Camera;
use crate::geometry::Bvh;
use crate::mesh::{Mesh, VertexId};
use crate::silhouette::{Silhouette, SilhouettePoint, silhouettes};

/// The result of an over-sketch.
#[derive(Clone, Debug, PartialEq)]
pub struct Oversketched {
    /// New vertex positions, one per vertex of the input mesh (same topology).
    pub positions: Vec<DVec3>,
    /// The matched silhouette piece on screen (CSS px), in the stroke's direction.
    pub handle: Vec<DVec2>,
    /// Number of vertices in the region that was allowed to move.
    pub roi_size: usize,
    /// The match score in `(0, 1]` (see [`super::Match::score`]); higher is better.
    pub score: f64,
}

/// A matched handle: silhouette points in stroke order, and the simplified stroke.
struct Found {
    points: Vec<SilhouettePoint>,
    stroke: Vec<DVec2>,
    score: f64,
    is_confident: bool,
}

/// The handle weight of a soft over-sketch ([`HandleFit::Soft`](crate::deform::HandleFit::Soft)): each handle point's row
/// weighs as much as the detail of one vertex, so a handle point meets its target only as
/// far as the surface around it agrees.
pub const SOFT_FIT_WEIGHT: f64 = 1.0;

/// Over-sketches `mesh` seen by `camera` in a `viewport` (CSS px) with `stroke` (screen
/// points in drawing order): the silhouette piece the stroke redraws moves onto it, the
/// surface around it follows with its details, and everything else stays bit for bit.
///
/// Errors: [`OversketchError::NoMatch`], [`OversketchError::LowConfidence`], and
/// [`OversketchError::Deform`] when the handle cannot drive an exact edit.
pub fn oversketch(
    mesh: &Mesh,
    camera: &Camera,
    viewport: DVec2,
    stroke: &[DVec2],
) -> Result<Oversketched, OversketchError> {
    oversketch_with(mesh, camera, viewport, stroke, BendOptions::EXACT)
}

/// [`oversketch`] with the handles fitted as `options.fit` says: [`HandleFit::Exact`](crate::deform::HandleFit::Exact) puts
/// the outline on the stroke, [`HandleFit::Soft`](crate::deform::HandleFit::Soft) draws it towards the stroke as far as the
/// surface details allow (detail-preserving editing's approximate fit, Nealen §4.2); and
/// the region `options.roi`.
///
/// Errors: those of [`oversketch`], and [`OversketchError::NoPart`] for a part ROI that
/// does not stand out.
pub fn oversketch_with(
    mesh: &Mesh,
    camera: &Camera,
    viewport: DVec2,
    stroke: &[DVec2],
    options: BendOptions,
) -> Result<Oversketched, OversketchError> {
    let found = Outlines::new(mesh, camera, viewport)
        .find(stroke)
        .ok_or(OversketchError::NoMatch)?;
    if !found.is_confident {
        return Err(OversketchError::LowConfidence);
    }
    let handle = HandleCurve::of_silhouette(&found.points);
    let (positions, roi) = bend(mesh, camera, viewport, &handle, &found.stroke, options)?;
    Ok(Oversketched {
        positions,
        handle: handle.screen,
        roi_size: roi.iter().filter(|&&r| r).count(),
        score: found.score,
    })
}

/// The silhouette piece that [`oversketch`] would move for `stroke`, on screen (CSS px), and
/// whether the match is confident (an over-sketch is refused otherwise). `None` when nothing
/// matches. For highlighting while the stroke is drawn: silhouettes and matching only
/// ([`Outlines`] keeps the silhouettes for the next samples).
pub fn preview_handle(
    mesh: &Mesh,
    camera: &Camera,
    viewport: DVec2,
    stroke: &[DVec2],
) -> Option<(Vec<DVec2>, bool)> {
    Outlines::new(mesh, camera, viewport).preview(stroke)
}

/// The visible silhouettes of a mesh from one view, found once and matched against a stroke
/// as it grows: the camera stays put while a stroke is drawn.
#[derive(Clone, Debug)]
pub struct Outlines {
    curves: Vec<Silhouette>,
    polylines: Vec<Vec<DVec2>>,
}

impl Outlines {
    /// The silhouettes of `mesh` seen by `camera` in a `viewport` (CSS px).
    pub fn new(mesh: &Mesh, camera: &Camera, viewport: DVec2) -> Self {
        let (curves, polylines) = seen_silhouettes(mesh, camera, viewport);
        Outlines { curves, polylines }
    }

    /// [`preview_handle`] for `stroke` on these silhouettes.
    pub fn preview(&self, stroke: &[DVec2]) -> Option<(Vec<DVec2>, bool)> {
        let found = self.find(stroke)?;
        let screen = found.points.iter().map(|p| p.screen).collect();
        Some((screen, found.is_confident))
    }

    /// Matching: the handle's silhouette points in stroke order, each edge once. `None` when
    /// the stroke is degenerate or nothing matches.
    fn find(&self, stroke: &[DVec2]) -> Option<Found> {
        if !stroke.iter().all(|p| p.is_finite()) {
            return None;
        }
        let stroke = simplify_stroke(stroke);
        if stroke.len() < 2 {
            return None;
        }
        let slices: Vec<&[DVec2]> = self.polylines.iter().map(Vec::as_slice).collect();
        let found = match_stroke(&stroke, &slices, &MatchParams::default())?;
        let polyline = &self.polylines[found.silhouette];
        let indices: Vec<f64> = handle_points(polyline, found.start, found.end)
            .into_iter()
            .map(|(index, _)| index)
            .collect();
        let points = piece_points(&self.curves[found.silhouette], polyline.len(), &indices);
        (points.len() >= 2).then_some(Found {
            points,
            stroke,
            score: found.score,
            is_confident: found.confident,
        })
    }
}

/// The visible silhouettes and their screen polylines ([`screen_polyline`]).
pub(super) fn seen_silhouettes(
    mesh: &Mesh,
    camera: &Camera,
    viewport: DVec2,
) -> (Vec<Silhouette>, Vec<Vec<DVec2>>) {
    let bvh = Bvh::new(mesh);
    let curves = silhouettes(mesh, &bvh, camera, viewport);
    let polylines = curves.iter().map(screen_polyline).collect();
    (curves, polylines)
}

/// The silhouette points at fractional `indices` of `curve`'s polyline (`polyline_len`
/// points), each rounded to the nearest point and each edge kept once.
pub(super) fn piece_points(
    curve: &Silhouette,
    polyline_len: usize,
    indices: &[f64],
) -> Vec<SilhouettePoint> {
    let n = curve.points.len();
    let mut points: Vec<SilhouettePoint> = Vec::new();
    for &index in indices {
        // The repeated closing point of a closed curve is point 0.
        let k = (index.round() as usize).min(polyline_len - 1) % n;
        let point = curve.points[k];
        if !points.iter().any(|p| same_edge(p.edge, point.edge)) {
            points.push(point);
        }
    }
    points
}

/// The screen points of a silhouette; a closed one repeats its first point at the end, as
/// matching expects.
fn screen_polyline(curve: &Silhouette) -> Vec<DVec2> {
    let mut points: Vec<DVec2> = curve.points.iter().map(|p| p.screen).collect();
    if curve.closed
        && let Some(&first) = points.first()
        && points.last().is_some_and(|&last| last != first)
    {
        points.push(first);
    }
    points
}

fn same_edge(a: [VertexId; 2], b: [VertexId; 2]) -> bool {
    a == b || a == [b[1], b[0]]
}

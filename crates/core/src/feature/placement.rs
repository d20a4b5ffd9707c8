//! Where a sketch lands: the vertices that may move and the edge path under the sketch
//! (§4.2, §4.4.1 steps 1–2).

use std::cell::Cell;
use std::collections::VecDeque;

use glam::{DVec2, DVec3};

use super::{FeatureError, Sketch};
use crate::camera::Camera;
use crate::curve::polyline::{contains, distance_to_polyline, resample, self_crossings};
use crate::geometry::Bvh;
use crate::mesh::{Mesh, VertexId};

/// Half the width (CSS px) of the region around a sketch drawn without a lasso; see the
/// module docs of `feature` for why.
pub const BAND_PX: f64 = 40.0;

/// Spacing (px) of the sketch's samples once resampled: finer than any triangle on screen
/// that the path could follow.
const SPACING_PX: f64 = 3.0;

/// Spacing (px) at which a sketch is checked for turning back: coarse enough that a pen's
/// jitter is not a turn.
const FOLD_SPACING_PX: f64 = 10.0;

/// A sketch turns back where two successive coarse segments make an angle wider than this
/// (cosine of 150°).
const FOLD_COS: f64 = -0.866;

/// An edge's cost per px of its length on screen, beside its ends' distances to the sketch:
/// among paths equally close to the sketch, the shorter.
const LENGTH_COST: f64 = 0.1;

/// A sketch placed on a mesh.
#[derive(Clone, Debug)]
pub(crate) struct Placed {
    /// The sketch resampled evenly, in screen px.
    pub points: Vec<DVec2>,
    /// One entry per vertex: whether it may move.
    pub region: Vec<bool>,
    /// The edge path under the sketch, from its first point to its last.
    pub path: Vec<VertexId>,
}

/// Places `sketch` on `mesh`: checks it, finds the region and the path under it.
///
/// Errors: [`FeatureError::TooShort`], [`FeatureError::FoldsBack`],
/// [`FeatureError::RegionCrosses`], [`FeatureError::RegionMissesSketch`],
/// [`FeatureError::MissesMesh`], [`FeatureError::LeavesMesh`], [`FeatureError::NoPath`].
pub(crate) fn place(
    mesh: &Mesh,
    bvh: &Bvh,
    normals: &[DVec3],
    sketch: &Sketch,
) -> Result<Placed, FeatureError> {
    let points = resample(&sketch.points, SPACING_PX);
    if points.len() < 2 {
        return Err(FeatureError::TooShort);
    }
    check_turns(&sketch.points)?;
    if let Some(lasso) = &sketch.region {
        // A lasso whose last point repeats its first is as good as one that does not.
        let lasso = match lasso.split_last() {
            Some((last, rest)) if rest.first() == Some(last) => rest,
            _ => lasso,
        };
        if lasso.len() < 3 || !self_crossings(lasso, true).is_empty() {
            return Err(FeatureError::RegionCrosses);
        }
        if !points.iter().all(|&p| contains(lasso, p)) {
            return Err(FeatureError::RegionMissesSketch);
        }
    }
    let hits = hit_vertices(mesh, bvh, sketch, &points)?;
    let screen = |v: VertexId| {
        (sketch.camera)
            .screen_from_world(mesh.position(v), sketch.viewport)
            .map(|s| s.truncate())
    };
    let nearest = |candidates: &[VertexId; 3], to: DVec2| {
        *candidates
            .iter()
            .min_by(|a, b| {
                let d = |v: VertexId| screen(v).map_or(f64::INFINITY, |s| s.distance(to));
                d(**a).total_cmp(&d(**b))
            })
            .expect("a face has three vertices")
    };
    let (first, last) = (hits[0], hits[hits.len() - 1]);
    let start = nearest(&first, points[0]);
    let end = nearest(&last, points[points.len() - 1]);
    if start == end {
        return Err(FeatureError::TooShort);
    }
    let distance = SketchDistance::new(mesh.n_vertices(), &points, &screen);
    let region = grow_region(mesh, normals, sketch, &hits, &screen, &distance);
    if region.iter().filter(|&&r| r).count() < 3 {
        return Err(FeatureError::RegionMissesSketch);
    }
    let cost = |a: VertexId, b: VertexId| {
        let length = match (screen(a), screen(b)) {
            (Some(sa), Some(sb)) => sa.distance(sb),
            _ => f64::INFINITY,
        };
        distance.of(a) + distance.of(b) + LENGTH_COST * length
    };
    let path = mesh
        .shortest_path(start, end, |v| region[v.index()], cost)
        .ok_or(FeatureError::NoPath)?;
    Ok(Placed {
        points,
        region,
        path,
    })
}

/// Refuses a sketch that crosses itself or turns back on itself.
fn check_turns(points: &[DVec2]) -> Result<(), FeatureError> {
    let coarse = resample(points, FOLD_SPACING_PX);
    let turns_back = coarse.windows(3).any(|w| {
        let (u, v) = (w[1] - w[0], w[2] - w[1]);
        u.normalize_or_zero().dot(v.normalize_or_zero()) < FOLD_COS
    });
    if turns_back || !self_crossings(points, false).is_empty() {
        return Err(FeatureError::FoldsBack);
    }
    Ok(())
}

/// How far (px) a ray that slips between two triangles (a sketch along an edge of a flat
/// grid) is nudged to try again.
const NUDGE_PX: f64 = 1e-3;

/// The vertices of the face under each of `points`.
fn hit_vertices(
    mesh: &Mesh,
    bvh: &Bvh,
    sketch: &Sketch,
    points: &[DVec2],
) -> Result<Vec<[VertexId; 3]>, FeatureError> {
    points
        .iter()
        .enumerate()
        .map(|(i, &p)| {
            let nudges = [DVec2::ZERO, DVec2::X, DVec2::Y, -DVec2::X, -DVec2::Y];
            let hit = nudges.iter().find_map(|&nudge| {
                let at = p + NUDGE_PX * nudge;
                let (origin, dir) = sketch.camera.ray_in_world(at, sketch.viewport);
                bvh.raycast(mesh, origin, dir)
            });
            match hit {
                Some(hit) => Ok(mesh.face_vertices(hit.face)),
                None if i == 0 => Err(FeatureError::MissesMesh),
                None => Err(FeatureError::LeavesMesh),
            }
        })
        .collect()
}

/// The region that may move, grown over the mesh's edges from the faces under the sketch
/// through the vertices that face the camera and lie inside the lasso (or within
/// [`BAND_PX`] of the sketch). Growing over edges, not testing every vertex, keeps a part
/// behind the sketch (the far side of a thin ear) out, and costs what the region holds.
fn grow_region(
    mesh: &Mesh,
    normals: &[DVec3],
    sketch: &Sketch,
    hits: &[[VertexId; 3]],
    screen: &impl Fn(VertexId) -> Option<DVec2>,
    distance: &SketchDistance<'_>,
) -> Vec<bool> {
    let mut region = vec![false; mesh.n_vertices()];
    let mut queue: VecDeque<VertexId> = VecDeque::new();
    let mut visited = vec![false; mesh.n_vertices()];
    let admits = |v: VertexId, s: DVec2| {
        let p = mesh.position(v);
        let faces_the_eye = normals[v.index()].dot(toward_eye(&sketch.camera, p)) > 0.0;
        faces_the_eye
            && match &sketch.region {
                Some(lasso) => contains(lasso, s),
                None => distance.of(v) <= BAND_PX,
            }
    };
    // The vertices under the sketch are in, whatever their normals say.
    for &v in hits.iter().flatten() {
        if !std::mem::replace(&mut visited[v.index()], true) {
            region[v.index()] = true;
            queue.push_back(v);
        }
    }
    while let Some(v) = queue.pop_front() {
        for w in mesh.vertex_neighbors(v) {
            if std::mem::replace(&mut visited[w.index()], true) {
                continue;
            }
            if screen(w).is_some_and(|s| admits(w, s)) {
                region[w.index()] = true;
                queue.push_back(w);
            }
        }
    }
    region
}

/// Each vertex's distance (px) on screen to the sketch, computed when first asked for: the
/// band needs it for the vertices it tries, the path for those its search reaches, and a
/// lasso's region for none.
struct SketchDistance<'a> {
    known: Vec<Cell<f64>>,
    points: &'a [DVec2],
    screen: &'a dyn Fn(VertexId) -> Option<DVec2>,
}

impl<'a> SketchDistance<'a> {
    fn new(n: usize, points: &'a [DVec2], screen: &'a dyn Fn(VertexId) -> Option<DVec2>) -> Self {
        SketchDistance {
            known: vec![Cell::new(f64::NAN); n],
            points,
            screen,
        }
    }

    /// The distance of `v` (infinite behind the eye).
    fn of(&self, v: VertexId) -> f64 {
        let slot = &self.known[v.index()];
        if slot.get().is_nan() {
            let d =
                (self.screen)(v).map_or(f64::INFINITY, |s| distance_to_polyline(s, self.points));
            slot.set(d);
        }
        slot.get()
    }
}

/// The direction from `p` toward the viewer: to the eye, or against the view direction of
/// an orthographic camera.
pub(super) fn toward_eye(camera: &Camera, p: DVec3) -> DVec3 {
    match camera.ortho_height {
        Some(_) => -camera.forward(),
        None => camera.eye - p,
    }
}

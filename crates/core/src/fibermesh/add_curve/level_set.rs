//! Cross sections: the closed curve where the surface swept by the view rays through the
//! stroke cuts the shape, front and back.
//!
//! A walk cannot follow the back of the shape, which no ray reaches, so the curve is the
//! zero set of a scalar instead: each vertex's signed screen distance to the stroke, its
//! ends extended straight. Every edge whose ends have opposite signs is split at the
//! linear zero; the faces then fall into a negative and a positive region, and the curve
//! is the boundary between them, traced into loops.

use glam::{DVec2, DVec3};

use super::embedding::Embedding;
use crate::camera::Camera;
use crate::mesh::{HalfedgeId, Mesh, VertexId};

/// Zero crossings this close to an edge's end (fraction of the edge) put the curve through
/// that vertex instead, which avoids slivers.
const SNAP_CROSSING: f64 = 0.05;

/// The signed screen distance (px) of every vertex to the stroke polyline (at least two
/// points), its first and last segments extended to lines. Vertices behind the eye count
/// as far on the positive side.
pub(crate) fn screen_distances(
    positions: &[DVec3],
    camera: &Camera,
    viewport: DVec2,
    polyline: &[DVec2],
) -> Vec<f64> {
    positions
        .iter()
        .map(|&p| match camera.screen_from_world(p, viewport) {
            Some(s) => signed_distance(polyline, s.truncate()),
            None => f64::MAX,
        })
        .collect()
}

/// Signed distance to the extended polyline. At a corner both segments are equally near;
/// the one whose line lies farther decides the side (the 2D pseudo-normal rule).
fn signed_distance(polyline: &[DVec2], p: DVec2) -> f64 {
    let last = polyline.len().saturating_sub(2);
    let mut best = (f64::INFINITY, 0.0f64);
    for (i, w) in polyline.windows(2).enumerate() {
        let (a, ab) = (w[0], w[1] - w[0]);
        let length_squared = ab.length_squared();
        if length_squared == 0.0 {
            continue;
        }
        let lo = if i == 0 { f64::NEG_INFINITY } else { 0.0 };
        let hi = if i == last { f64::INFINITY } else { 1.0 };
        let t = ((p - a).dot(ab) / length_squared).clamp(lo, hi);
        let distance = p.distance(a + ab * t);
        let off_line = ab.perp_dot(p - a) / length_squared.sqrt();
        let tie = 1e-9 * (1.0 + distance);
        if distance < best.0 - tie || (distance <= best.0 + tie && off_line.abs() > best.1.abs()) {
            best = (distance, off_line);
        }
    }
    best.0.copysign(best.1)
}

/// A mesh split along the zero set of a per-vertex value.
pub(crate) struct ZeroSet {
    /// Whether each face (of the split mesh) lies on the positive side.
    pub is_positive: Vec<bool>,
    /// The closed loops of the zero set, as vertex cycles with a positive face on the left of
    /// each edge `loop[k] → loop[k + 1]`.
    pub loops: Vec<Vec<VertexId>>,
}

/// Embeds the zero set of the per-vertex `distances` into the mesh: every edge whose ends
/// have opposite signs is split at its linear zero (or the zero snaps onto a near end).
/// `None` when a split fails.
pub(crate) fn split_zero_set(embedding: &mut Embedding, distances: &[f64]) -> Option<ZeroSet> {
    let mut value = distances.to_vec();
    snap_near_zero(&embedding.mesh, &mut value);
    for (a, b) in undirected_edges(&embedding.mesh) {
        let (fa, fb) = (value[a.index()], value[b.index()]);
        if fa * fb < 0.0 {
            embedding.split_edge(a, b, fa / (fa - fb))?;
            value.push(0.0);
        }
    }
    let mesh = &embedding.mesh;
    let is_positive: Vec<bool> = mesh
        .triangles()
        .iter()
        .map(|t| is_positive_face(t, &value, distances))
        .collect();
    let loops = mesh.face_set_loops(&is_positive);
    Some(ZeroSet { is_positive, loops })
}

/// Embeds the zero set of the per-vertex `distances` and returns its loop nearest to any
/// of the points `near` (the stroke's hits on the visible surface), or `None` if the zero
/// set holds no closed loop.
pub(super) fn cross_section(
    embedding: &mut Embedding,
    distances: &[f64],
    near: &[DVec3],
) -> Option<Vec<VertexId>> {
    let zero_set = split_zero_set(embedding, distances)?;
    let mesh = &embedding.mesh;
    let gap = |curve: &Vec<VertexId>| {
        let mut gap = f64::INFINITY;
        for &v in curve {
            for &p in near {
                gap = gap.min(mesh.position(v).distance_squared(p));
            }
        }
        gap
    };
    zero_set
        .loops
        .into_iter()
        .map(|curve| (gap(&curve), curve))
        .min_by(|x, y| x.0.total_cmp(&y.0))
        .map(|(_, curve)| curve)
}

/// Each edge once, as `(a, b)` with `a < b` or as a boundary edge, in face order.
fn undirected_edges(mesh: &Mesh) -> Vec<(VertexId, VertexId)> {
    (0..mesh.n_halfedges() as u32)
        .map(HalfedgeId)
        .map(|h| (h, mesh.tail(h), mesh.head(h)))
        .filter(|&(h, a, b)| a < b || mesh.twin(h).is_none())
        .map(|(_, a, b)| (a, b))
        .collect()
}

/// Puts the curve through a vertex (value 0) where a zero crossing lies within
/// [`SNAP_CROSSING`] of it.
fn snap_near_zero(mesh: &Mesh, value: &mut [f64]) {
    let mut on_curve = Vec::new();
    for (a, b) in undirected_edges(mesh) {
        let (fa, fb) = (value[a.index()], value[b.index()]);
        if fa * fb < 0.0 {
            let t = fa / (fa - fb);
            if t < SNAP_CROSSING {
                on_curve.push(a);
            } else if t > 1.0 - SNAP_CROSSING {
                on_curve.push(b);
            }
        }
    }
    for v in on_curve {
        value[v.index()] = 0.0;
    }
}

/// The side of a face after the splits, when no face has corners of both signs: that of
/// its nonzero corners; a face with all corners on the curve goes by the unsnapped values.
fn is_positive_face(t: &[u32; 3], value: &[f64], unsnapped: &[f64]) -> bool {
    let sum = |values: &[f64]| -> f64 {
        t.iter()
            .map(|&v| values.get(v as usize).copied().unwrap_or(0.0))
            .sum()
    };
    let snapped = sum(value);
    if snapped != 0.0 {
        snapped > 0.0
    } else {
        sum(unsnapped) > 0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn signed_distance_to_a_bent_polyline() {
        let polyline = [
            DVec2::new(0.0, 0.0),
            DVec2::new(10.0, 0.0),
            DVec2::new(10.0, 10.0),
        ];
        // Beside the first segment, beyond its extended start, and around the corner.
        assert!((signed_distance(&polyline, DVec2::new(5.0, 3.0)) - 3.0).abs() < 1e-12);
        assert!((signed_distance(&polyline, DVec2::new(-50.0, -2.0)) + 2.0).abs() < 1e-12);
        let outside = signed_distance(&polyline, DVec2::new(13.0, -4.0));
        assert!((outside + 5.0).abs() < 1e-12, "{outside}");
        let inside = signed_distance(&polyline, DVec2::new(8.0, 1.0));
        assert!((inside - 1.0).abs() < 1e-12, "{inside}");
    }
}

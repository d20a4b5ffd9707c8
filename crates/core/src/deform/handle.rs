//! Handle points: a vertex, or a point inside an edge or a face as a barycentric combination.
//!
//! Over-sketching drags silhouette points, which mostly lie inside edges. Nealen's Eq. 4.2
//! constrains such a point as the combination `(1 - λ) v_i + λ v_j = v̂_ij` of its edge's
//! vertices; a point inside a triangle uses its two free barycentric coordinates. A
//! [`HandlePoint`] stores up to three vertices with weights that sum to one.
//!
//! An edit sorts its handles by how they enter the system: soft rows, fixed vertices (exact
//! handles at a vertex) or hard constraints (exact handles inside an edge or face).

use glam::DVec3;

use super::DeformError;
use super::exact_handles::ConstraintRow;
use super::params::HandleFit;
use super::region::Region;
use crate::mesh::{FaceId, Mesh, VertexId};

/// A point on the mesh that a deformation moves to a target: `Σ weights[k] · x[vertices[k]]`.
///
/// Build it with [`HandlePoint::vertex`], [`HandlePoint::on_edge`] or
/// [`HandlePoint::in_face`]. Unused slots have weight zero.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HandlePoint {
    vertices: [VertexId; 3],
    weights: [f64; 3],
}

impl HandlePoint {
    /// The vertex `v` itself.
    pub fn vertex(v: VertexId) -> HandlePoint {
        HandlePoint {
            vertices: [v; 3],
            weights: [1.0, 0.0, 0.0],
        }
    }

    /// The point `(1 - t) a + t b` on edge `ab` (Eq. 4.2 with `λ = t`).
    pub fn on_edge(a: VertexId, b: VertexId, t: f64) -> HandlePoint {
        HandlePoint {
            vertices: [a, b, b],
            weights: [1.0 - t, t, 0.0],
        }
    }

    /// The point of face `f` with barycentric coordinates `barycentric` (x, y, z for the face's
    /// three vertices in order; they should sum to one).
    pub fn in_face(mesh: &Mesh, f: FaceId, barycentric: DVec3) -> HandlePoint {
        HandlePoint {
            vertices: mesh.face_vertices(f),
            weights: barycentric.to_array(),
        }
    }

    /// The vertices of the combination (repeated or with zero weight where unused).
    pub fn vertices(&self) -> [VertexId; 3] {
        self.vertices
    }

    /// The weights of the combination.
    pub fn weights(&self) -> [f64; 3] {
        self.weights
    }

    /// The point for vertex positions `positions`.
    pub fn position(&self, positions: &[DVec3]) -> DVec3 {
        self.vertices
            .iter()
            .zip(self.weights)
            .filter(|(_, w)| *w != 0.0)
            .map(|(v, w)| w * positions[v.index()])
            .sum()
    }

    /// Distinct vertices with their summed weights, zero weights dropped: `(vertex, weight)`.
    pub(crate) fn terms(&self) -> impl Iterator<Item = (VertexId, f64)> + '_ {
        (0..3).filter_map(|k| {
            let v = self.vertices[k];
            // Only the first slot of each vertex reports, with the sum over its slots.
            if self.vertices[..k].contains(&v) {
                return None;
            }
            let w: f64 = (k..3)
                .filter(|&j| self.vertices[j] == v)
                .map(|j| self.weights[j])
                .sum();
            (w != 0.0).then_some((v, w))
        })
    }

    /// The one vertex carrying all the weight, when the point is a vertex.
    pub(crate) fn as_vertex(&self) -> Option<VertexId> {
        let mut terms = self.terms();
        match (terms.next(), terms.next()) {
            (Some((v, 1.0)), None) => Some(v),
            _ => None,
        }
    }

    /// Whether the weights are finite and sum to one (to 1e-9).
    pub(crate) fn is_affine(&self) -> bool {
        self.weights.iter().all(|w| w.is_finite())
            && (self.weights.iter().sum::<f64>() - 1.0).abs() <= 1e-9
    }
}

/// The handle sets of one edit, by how they enter the system.
#[derive(Default)]
pub(crate) struct HandleSplit {
    /// Soft rows: handle index, rest value, local terms.
    pub(crate) soft: Vec<(usize, DVec3, ConstraintRow)>,
    /// Exact vertex handles: local index, handle index.
    pub(crate) fixed: Vec<(usize, usize)>,
    /// Exact rows: handle index, rest value, local terms.
    pub(crate) exact: Vec<(usize, DVec3, ConstraintRow)>,
}

/// Sorts handles into soft rows, fixed vertices and exact rows, checking each.
pub(crate) fn split_handles(
    mesh: &Mesh,
    region: &Region,
    handles: &[HandlePoint],
    fit: HandleFit,
) -> Result<HandleSplit, DeformError> {
    let mut split = HandleSplit::default();
    let mut is_fixed_by_handle = vec![false; region.n_roi()];
    for (index, handle) in handles.iter().enumerate() {
        let is_valid = handle.is_affine()
            && handle
                .vertices()
                .iter()
                .all(|v| v.index() < mesh.n_vertices());
        if !is_valid {
            return Err(DeformError::InvalidHandle { index });
        }
        let outside = DeformError::HandleOutsideRoi { index };
        let mut terms = ConstraintRow::new();
        for (v, w) in handle.terms() {
            terms.push((region.local(v).ok_or(outside.clone())?, w));
        }
        if terms.iter().all(|&(j, _)| j >= region.n_roi()) {
            return Err(outside);
        }
        let rest = handle.position(mesh.positions());
        match (fit, handle.as_vertex()) {
            (HandleFit::Soft { .. }, _) => split.soft.push((index, rest, terms)),
            (HandleFit::Exact, Some(_)) => {
                let local = terms[0].0;
                if std::mem::replace(&mut is_fixed_by_handle[local], true) {
                    return Err(DeformError::ConflictingHandles { index });
                }
                split.fixed.push((local, index));
            }
            (HandleFit::Exact, None) => split.exact.push((index, rest, terms)),
        }
    }
    Ok(split)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;

    #[test]
    fn points_interpolate_their_vertices() {
        let mesh = primitives::grid(2, 2, 2.0);
        let p = mesh.positions();
        let edge = HandlePoint::on_edge(VertexId(0), VertexId(1), 0.25);
        assert_eq!(edge.position(p), 0.75 * p[0] + 0.25 * p[1]);
        assert!(edge.is_affine() && edge.as_vertex().is_none());
        let face = HandlePoint::in_face(&mesh, FaceId(0), DVec3::new(0.2, 0.3, 0.5));
        let [a, b, c] = mesh.face_positions(FaceId(0));
        assert!((face.position(p) - (0.2 * a + 0.3 * b + 0.5 * c)).length() < 1e-15);
        assert_eq!(
            HandlePoint::vertex(VertexId(4)).as_vertex(),
            Some(VertexId(4))
        );
        // An edge point at an end is that vertex.
        let end = HandlePoint::on_edge(VertexId(3), VertexId(4), 1.0);
        assert_eq!(end.as_vertex(), Some(VertexId(4)));
        assert_eq!(end.terms().count(), 1);
        assert!(!HandlePoint::on_edge(VertexId(0), VertexId(1), f64::NAN).is_affine());
        assert!(!HandlePoint::in_face(&mesh, FaceId(0), DVec3::ONE).is_affine());
    }
}

//! A region found once for a pair of curves, moved by any transform in one pass.

use glam::{DMat4, DVec3, DVec4};

use super::falloff::closeness;
use super::{Levels, RegionError, RegionSketch};
use crate::feature::{Sketch, place};
use crate::geometry::{Bvh, Fractions, vertex_normals};
use crate::mesh::{Mesh, VertexId};

/// A region of one mesh with its fall-off: see the [module docs](super).
#[derive(Clone, Debug)]
pub struct RegionEdit {
    /// The vertices that may move, in increasing order.
    vertices: Vec<VertexId>,
    /// Each one's closeness to the reference curve, in [0, 1].
    closeness: Vec<f64>,
    /// Each one's weight: its closeness read through the levels.
    weights: Vec<f64>,
    /// The edge path under the reference curve.
    reference: Vec<VertexId>,
}

impl RegionEdit {
    /// Places `sketch`'s curves on `mesh` and weighs the region with `levels`.
    ///
    /// Errors: the curves' refusals (see [`RegionError`]).
    pub fn new(mesh: &Mesh, sketch: &RegionSketch, levels: &Levels) -> Result<Self, RegionError> {
        let boundary = match sketch.boundary.split_last() {
            Some((last, rest)) if rest.first() == Some(last) => rest.to_vec(),
            _ => sketch.boundary.clone(),
        };
        if boundary.iter().any(|p| !p.is_finite()) {
            return Err(RegionError::BoundaryCrosses);
        }
        let placed = place(
            mesh,
            &Bvh::new(mesh),
            &vertex_normals(mesh),
            &Sketch {
                camera: sketch.camera,
                viewport: sketch.viewport,
                points: sketch.reference.clone(),
                region: Some(boundary),
            },
        )?;
        let vertices: Vec<VertexId> = mesh
            .vertices()
            .filter(|v| placed.region[v.index()])
            .collect();
        let closeness = closeness(mesh, &placed.region, &vertices, &placed.path);
        let weights = closeness.iter().map(|&s| levels.weight(s)).collect();
        Ok(RegionEdit {
            vertices,
            closeness,
            weights,
            reference: placed.path,
        })
    }

    /// The vertices that may move, in increasing order.
    pub fn vertices(&self) -> &[VertexId] {
        &self.vertices
    }

    /// Each region vertex's weight, in the order of [`RegionEdit::vertices`]: 1 moves fully,
    /// 0 stays.
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The edge path under the reference curve.
    pub fn reference(&self) -> &[VertexId] {
        &self.reference
    }

    /// Every vertex's weight, 0 outside the region: what the fall-off overlay shows.
    pub fn weight_per_vertex(&self, n_vertices: usize) -> Vec<f64> {
        let mut all = vec![0.0; n_vertices];
        for (v, &w) in self.vertices.iter().zip(&self.weights) {
            all[v.index()] = w;
        }
        all
    }

    /// Weighs the region again with other levels (a level handle dragged): the region and
    /// the closeness stay.
    pub fn set_levels(&mut self, levels: &Levels) {
        for (w, &s) in self.weights.iter_mut().zip(&self.closeness) {
            *w = levels.weight(s);
        }
    }

    /// Moves each region vertex of `base` to `(w ⊙ T) p` in `out` (the same length; the
    /// vertices outside the region are not written). Allocates nothing: a drag frame.
    pub fn apply_into(&self, transform: &Fractions, base: &[DVec3], out: &mut [DVec3]) {
        for (v, &w) in self.vertices.iter().zip(&self.weights) {
            out[v.index()] = transform.apply(w, base[v.index()]);
        }
    }

    /// Every vertex of `mesh` with the region moved by `transform`.
    pub fn applied(&self, mesh: &Mesh, transform: &Fractions) -> Vec<DVec3> {
        let mut out = mesh.positions().to_vec();
        self.apply_into(transform, mesh.positions(), &mut out);
        out
    }
}

/// The fractions of a transform given column by column, as an op holds it.
///
/// Errors: a transform that is not finite, not affine, mirrors or flattens, or turns by half
/// a turn (no fraction of it is defined).
pub fn checked_transform(columns: &[f64; 16]) -> Result<Fractions, RegionError> {
    if columns.iter().any(|x| !x.is_finite()) {
        return Err(RegionError::TransformNotFinite);
    }
    let matrix = DMat4::from_cols_array(columns);
    if matrix.row(3) != DVec4::W {
        return Err(RegionError::TransformNotAffine);
    }
    if matrix.determinant() <= 0.0 {
        return Err(RegionError::TransformMirrors);
    }
    Fractions::new(matrix).ok_or(RegionError::TransformTurnsHalfWay)
}

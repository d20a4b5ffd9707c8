//! How far each vertex of a region moves: its closeness to the reference curve, read
//! through the user's levels (the thesis' gray-scale fall-off, §5.2).

use super::RegionError;
use crate::mesh::{Mesh, VertexId, distances_within, shortest_paths};

/// The fall-off's levels: weights at evenly spaced closeness from the boundary (the first)
/// to the reference curve (the last), linear in between.
#[derive(Clone, Debug, PartialEq)]
pub struct Levels(Vec<f64>);

impl Levels {
    /// Levels from their weights, at least two, each in [0, 1].
    ///
    /// Errors: [`RegionError::BadLevels`].
    pub fn new(weights: Vec<f64>) -> Result<Self, RegionError> {
        let in_range = weights.iter().all(|w| (0.0..=1.0).contains(w));
        if weights.len() < 2 || !in_range {
            return Err(RegionError::BadLevels);
        }
        Ok(Levels(weights))
    }

    /// The weights, from the boundary to the reference curve.
    pub fn weights(&self) -> &[f64] {
        &self.0
    }

    /// The weight at closeness `s` in [0, 1] (0 at the boundary, 1 on the reference curve).
    pub fn weight(&self, s: f64) -> f64 {
        let last = self.0.len() - 1;
        let at = s.clamp(0.0, 1.0) * last as f64;
        let below = (at.floor() as usize).min(last - 1);
        let t = at - below as f64;
        self.0[below] * (1.0 - t) + self.0[below + 1] * t
    }
}

impl Default for Levels {
    /// Five levels, the thesis' default, evenly from 0 to 1: the weight is the closeness.
    fn default() -> Self {
        Levels(vec![0.0, 0.25, 0.5, 0.75, 1.0])
    }
}

/// How each region vertex lies to the reference curve, in the order of the region's
/// vertices.
pub(super) struct Closeness {
    /// `d_b / (d_r + d_b)` (see the module docs of `region_edit`), in [0, 1].
    pub closeness: Vec<f64>,
    /// The index in the reference path of the path vertex nearest along edges (0 for a
    /// vertex the curve does not reach, whose closeness is 0).
    pub nearest: Vec<u32>,
}

/// How each vertex of `vertices` lies to the `reference` path; `region` has one entry per
/// vertex of `mesh`.
pub(super) fn closeness(
    mesh: &Mesh,
    region: &[bool],
    vertices: &[VertexId],
    reference: &[VertexId],
) -> Closeness {
    let inside = |v: VertexId| region[v.index()];
    let outside_neighbours: Vec<u32> = {
        let mut seen = vec![false; mesh.n_vertices()];
        vertices
            .iter()
            .flat_map(|&v| mesh.vertex_neighbors(v))
            .filter(|&w| !inside(w) && !std::mem::replace(&mut seen[w.index()], true))
            .map(|w| w.0)
            .collect()
    };
    let reference: Vec<u32> = reference.iter().map(|v| v.0).collect();
    // Walks only into the region: from the reference curve or the vertices just outside.
    let edges = |v: u32| {
        let p = mesh.position(VertexId(v));
        mesh.vertex_neighbors(VertexId(v))
            .filter(move |&w| inside(w))
            .map(move |w| (w.0, p.distance(mesh.position(w))))
    };
    let to_reference = shortest_paths(
        mesh.n_vertices(),
        &reference,
        f64::INFINITY,
        edges,
        |_, _| false,
    );
    let to_boundary =
        distances_within(mesh.n_vertices(), &outside_neighbours, f64::INFINITY, edges);
    let closeness = vertices
        .iter()
        .map(|v| {
            let (r, b) = (to_reference.distance[v.index()], to_boundary[v.index()]);
            match (r.is_finite(), b.is_finite()) {
                // A region that is a whole part of the model: everything moves fully.
                (true, false) => 1.0,
                (false, _) => 0.0,
                (true, true) if r + b == 0.0 => 1.0,
                (true, true) => b / (r + b),
            }
        })
        .collect();
    let nearest = vertices
        .iter()
        .map(|v| match to_reference.seed[v.index()] {
            u32::MAX => 0,
            k => k,
        })
        .collect();
    Closeness { closeness, nearest }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn levels_interpolate_between_evenly_spaced_weights() {
        let linear = Levels::default();
        for s in [0.0, 0.1, 0.5, 0.93, 1.0] {
            assert!((linear.weight(s) - s).abs() < 1e-15);
        }
        let steep = Levels::new(vec![0.0, 1.0, 1.0]).unwrap();
        assert_eq!(steep.weight(0.25), 0.5);
        assert_eq!(steep.weight(0.75), 1.0);
        assert_eq!(steep.weight(-1.0), 0.0);
        assert!(Levels::new(vec![0.5]).is_err());
        assert!(Levels::new(vec![0.0, 1.5]).is_err());
        assert!(Levels::new(vec![0.0, f64::NAN]).is_err());
    }
}

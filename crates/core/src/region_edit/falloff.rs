//! How far each vertex of a region moves: its closeness to the reference curve, read
//! through the user's levels (the thesis' gray-scale fall-off, §5.2).

use glam::DVec2;

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

impl Levels {
    /// The levels after level `level` is dragged to weight `to`, with the levels `pinned`
    /// anchored (Bujans §5.3: a handle anchors its level; with one handle every level
    /// changes, with several only those between the dragged one and its pinned neighbours).
    /// The levels between a neighbour (a pinned level, or the boundary's 0 and the curve's 1
    /// beyond the last pin) and the dragged one keep their places between the two, as a
    /// monotone remapping: pulled together, a level can vanish into its neighbour and come
    /// back, but none is made. `to` is held between the neighbours' weights.
    pub fn dragged(&self, level: usize, to: f64, pinned: &[bool]) -> Levels {
        let n = self.0.len();
        let Some(&from) = self.0.get(level) else {
            return self.clone();
        };
        let is_pinned = |i: usize| i != level && pinned.get(i).copied().unwrap_or(false);
        let below = (0..level).rev().find(|&i| is_pinned(i));
        let above = (level + 1..n).find(|&i| is_pinned(i));
        let low = below.map_or(0.0, |i| self.0[i]);
        let high = above.map_or(1.0, |i| self.0[i]);
        let to = to.clamp(low.min(high), high.max(low));
        let remap = |w: f64, (a, b): (f64, f64), (c, d): (f64, f64)| {
            if (b - a).abs() < 1e-12 {
                d
            } else {
                c + (w - a) / (b - a) * (d - c)
            }
        };
        let under = |i: usize| i < level && below.is_none_or(|k| i > k);
        let over = |i: usize| i > level && above.is_none_or(|k| i < k);
        let mut weights = self.0.clone();
        for (i, w) in weights.iter_mut().enumerate() {
            if i == level {
                *w = to;
            } else if under(i) {
                *w = remap(*w, (low, from), (low, to)).clamp(0.0, 1.0);
            } else if over(i) {
                *w = remap(*w, (from, high), (to, high)).clamp(0.0, 1.0);
            }
        }
        Levels(weights)
    }
}

/// A part of the region whose fall-off has levels of its own (Bujans §5.4: "edits can apply
/// only inside an area picked with a lasso"): the region vertices seen inside the lasso (in
/// the view the curves were drawn in; even-odd, so a lasso may cross itself) take `levels`.
#[derive(Clone, Debug, PartialEq)]
pub struct Area {
    /// The lasso, closed, in screen CSS px of the curves' view.
    pub lasso: Vec<DVec2>,
    /// The levels inside it.
    pub levels: Levels,
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
    fn a_dragged_level_moves_the_levels_up_to_its_pinned_neighbours() {
        let linear = Levels::default();
        // No pin: every level follows, keeping its place between the ends and the handle.
        let all = linear.dragged(2, 0.8, &[false; 5]);
        assert_eq!(all.weights()[2], 0.8);
        assert!((all.weights()[1] - 0.4).abs() < 1e-12 && (all.weights()[3] - 0.9).abs() < 1e-12);
        assert_eq!((all.weights()[0], all.weights()[4]), (0.0, 1.0));
        // Pins at levels 1 and 4: level 3, dragged, moves; 0, 1 and 4 do not; 2 follows.
        let pinned = [false, true, false, false, true];
        let some = linear.dragged(3, 0.5, &pinned);
        assert_eq!(some.weights()[..2], linear.weights()[..2]);
        assert_eq!(some.weights()[4], 1.0);
        assert!(
            (some.weights()[2] - (0.25 + 0.5 * 0.25)).abs() < 1e-12,
            "{:?}",
            some.weights()
        );
        // Dragged past a pinned neighbour, it stops there: the level between vanishes.
        let squeezed = linear.dragged(3, 0.0, &pinned);
        assert_eq!(squeezed.weights()[3], 0.25);
        assert_eq!(squeezed.weights()[2], 0.25);
        assert!(squeezed.weights().windows(2).all(|w| w[0] <= w[1]));
    }

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

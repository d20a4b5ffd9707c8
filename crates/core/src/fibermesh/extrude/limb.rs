//! The extrusion's limb: rings swept from the base loop along the silhouette's two sides to
//! the tip, each a copy of the loop moved, turned and scaled so that the loop's two
//! vertices under the silhouette's ends land on the sides.

use glam::{DMat3, DVec3};

use crate::fibermesh::rings::{closed_cumulative, fractions, point_at, zip_chains};

/// A limb to attach to a rim.
#[derive(Clone, Debug)]
pub(super) struct Limb {
    /// The new vertices: the rings in order, then the tip.
    pub(super) positions: Vec<DVec3>,
    /// The triangles; corners below the rim's length index the rim, the rest `positions`
    /// after it.
    pub(super) triangles: Vec<[u32; 3]>,
    /// The silhouette as corners: from the rim's first end along the left side to the tip
    /// and back along the right side to the rim's second end.
    pub(super) silhouette: Vec<u32>,
}

/// A ring as corners with positions, starting at its vertex on the left side, and where
/// its vertex on the right side is.
struct SweptRing {
    vertices: Vec<(u32, DVec3)>,
    right: usize,
}

impl SweptRing {
    /// The arc from the left side to the right one, and the arc from the right side back to
    /// the left one (both ends included).
    fn arcs(&self) -> [Vec<(u32, DVec3)>; 2] {
        let first = self.vertices[..=self.right].to_vec();
        let mut second = self.vertices[self.right..].to_vec();
        second.push(self.vertices[0]);
        [first, second]
    }
}

/// Sweeps the limb from `rim` (a closed polyline, running as its kept faces hold its edges
/// `k → k + 1`) whose vertices `ends` lie under the silhouette's start and end. `sides`
/// holds the silhouette's (left, right) pairs from the rim's ends (first) to the tip (last,
/// both sides meeting); rings get vertices about `spacing` apart.
pub(super) fn limb(
    rim: &[DVec3],
    ends: [usize; 2],
    sides: &[(DVec3, DVec3)],
    spacing: f64,
) -> Limb {
    let n_rim = rim.len();
    let cumulative = closed_cumulative(rim);
    let params = fractions(&cumulative);
    let (u_left, u_right) = (params[ends[0]], params[ends[1]]);
    let arc = (u_right - u_left).rem_euclid(1.0);
    let middle = |k: usize| 0.5 * (sides[k].0 + sides[k].1);
    let along = |k: usize| middle((k + 1).min(sides.len() - 1)) - middle(k.saturating_sub(1));
    let width = |k: usize| sides[k].1 - sides[k].0;
    let base_frame = frame(width(0), along(0));
    let base_width = width(0).length();
    let mut rings = vec![SweptRing {
        vertices: (0..n_rim)
            .map(|j| {
                let k = (ends[0] + j) % n_rim;
                (k as u32, rim[k])
            })
            .collect(),
        right: (ends[1] + n_rim - ends[0]) % n_rim,
    }];
    let mut positions = Vec::new();
    for k in 1..sides.len() - 1 {
        let turn = frame(width(k), along(k)) * base_frame.transpose();
        let scale = width(k).length() / base_width;
        let n = ((scale * cumulative[n_rim] / spacing).round() as usize).max(4);
        let n_left = ((n as f64 * arc).round() as usize).clamp(1, n - 1);
        let ring_params = (0..n_left)
            .map(|j| u_left + arc * j as f64 / n_left as f64)
            .chain((0..n - n_left).map(|j| u_right + (1.0 - arc) * j as f64 / (n - n_left) as f64));
        let first = (n_rim + positions.len()) as u32;
        let vertices: Vec<(u32, DVec3)> = ring_params
            .enumerate()
            .map(|(j, u)| {
                let p = point_at(rim, &cumulative, u) - middle(0);
                (first + j as u32, middle(k) + scale * (turn * p))
            })
            .collect();
        positions.extend(vertices.iter().map(|&(_, p)| p));
        rings.push(SweptRing {
            vertices,
            right: n_left,
        });
    }
    let tip = (n_rim + positions.len()) as u32;
    positions.push(middle(sides.len() - 1));
    let mut triangles = Vec::new();
    for pair in rings.windows(2) {
        for (a, b) in pair[0].arcs().iter().zip(&pair[1].arcs()) {
            zip_chains(a, b, &mut triangles);
        }
    }
    let last = &rings[rings.len() - 1].vertices;
    for j in 0..last.len() {
        triangles.push([last[(j + 1) % last.len()].0, last[j].0, tip]);
    }
    let silhouette = rings
        .iter()
        .map(|r| r.vertices[0].0)
        .chain(std::iter::once(tip))
        .chain(rings.iter().rev().map(|r| r.vertices[r.right].0))
        .collect();
    Limb {
        positions,
        triangles,
        silhouette,
    }
}

/// A right-handed orthonormal frame: the first axis along `width`, the second along the
/// part of `along` square to it.
fn frame(width: DVec3, along: DVec3) -> DMat3 {
    let e1 = width.normalize_or_zero();
    let e2 = (along - along.dot(e1) * e1)
        .try_normalize()
        .unwrap_or_else(|| e1.any_orthonormal_vector());
    DMat3::from_cols(e1, e2, e1.cross(e2))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_limb_on_a_circle_uses_every_inner_edge_both_ways_and_ends_at_the_tip() {
        let n = 16;
        let rim: Vec<DVec3> = (0..n)
            .map(|k| {
                let a = std::f64::consts::TAU * k as f64 / n as f64;
                DVec3::new(a.cos(), 0.0, a.sin())
            })
            .collect();
        // Straight up from the rim's vertices 0 (x = 1) and 8 (x = -1), narrowing to a tip.
        let sides: Vec<(DVec3, DVec3)> = (0..=6)
            .map(|k| {
                let t = k as f64 / 6.0;
                let half = 1.0 - t;
                (
                    DVec3::new(half, 2.0 * t, 0.0),
                    DVec3::new(-half, 2.0 * t, 0.0),
                )
            })
            .collect();
        let limb = limb(&rim, [0, 8], &sides, 0.4);
        let mut directed = std::collections::HashSet::new();
        for t in &limb.triangles {
            for k in 0..3 {
                assert!(
                    directed.insert((t[k], t[(k + 1) % 3])),
                    "an edge used twice one way"
                );
            }
        }
        let one_way: Vec<_> = directed
            .iter()
            .filter(|(a, b)| !directed.contains(&(*b, *a)))
            .collect();
        // Only the rim's edges are used one way, backwards (the kept faces hold them forwards).
        assert_eq!(one_way.len(), n);
        assert!(one_way.iter().all(|&&(a, b)| (b + 1) % n as u32 == a));
        // The silhouette is an edge chain through the tip, in the plane z = 0 of the sides.
        let s = &limb.silhouette;
        assert_eq!((s[0], s[s.len() - 1]), (0, 8));
        for w in s.windows(2) {
            assert!(directed.contains(&(w[0], w[1])) || directed.contains(&(w[1], w[0])));
        }
        let at = |c: u32| {
            if (c as usize) < n {
                rim[c as usize]
            } else {
                limb.positions[c as usize - n]
            }
        };
        assert!(s.iter().all(|&c| at(c).z.abs() < 1e-9));
        assert!((at(s[s.len() / 2]) - DVec3::new(0.0, 2.0, 0.0)).length() < 1e-9);
    }
}

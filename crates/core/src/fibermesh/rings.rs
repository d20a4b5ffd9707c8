//! Rings of vertices and the strips of triangles between them: what the tunnel's tube, the
//! extrusion's limb and the merge's seam are built of. A ring is a closed polyline; each
//! vertex carries a parameter (its arclength fraction in some reference ring), and
//! consecutive rings are zipped by those parameters along the shorter diagonals.

use glam::DVec3;

/// A ring: its vertices' parameters in `[0, 1)` and their positions.
pub(super) type Ring = (Vec<f64>, Vec<DVec3>);

/// A closed polyline's point at arclength fraction `u` (any real; it wraps).
pub(super) fn point_at(ring: &[DVec3], cumulative: &[f64], u: f64) -> DVec3 {
    let total = cumulative[ring.len()];
    let s = u.rem_euclid(1.0) * total;
    let k = cumulative
        .partition_point(|&c| c <= s)
        .saturating_sub(1)
        .min(ring.len() - 1);
    let span = cumulative[k + 1] - cumulative[k];
    let t = if span > 0.0 {
        (s - cumulative[k]) / span
    } else {
        0.0
    };
    ring[k].lerp(ring[(k + 1) % ring.len()], t)
}

/// Arclength at each vertex of a closed polyline, with the total last.
pub(super) fn closed_cumulative(ring: &[DVec3]) -> Vec<f64> {
    let mut cumulative = vec![0.0];
    for k in 0..ring.len() {
        let step = ring[k].distance(ring[(k + 1) % ring.len()]);
        cumulative.push(cumulative[k] + step);
    }
    cumulative
}

/// The arclength fraction of each vertex.
pub(super) fn fractions(cumulative: &[f64]) -> Vec<f64> {
    let total = cumulative[cumulative.len() - 1].max(f64::MIN_POSITIVE);
    cumulative[..cumulative.len() - 1]
        .iter()
        .map(|c| c / total)
        .collect()
}

/// The shift of `second`'s parametrization that brings it closest to `first`'s (sum of
/// squared distances at `samples` points).
fn best_shift(first: &[DVec3], second: &[DVec3], samples: usize) -> f64 {
    let (cf, cs) = (closed_cumulative(first), closed_cumulative(second));
    let cost = |shift: f64| {
        (0..samples)
            .map(|i| {
                let u = i as f64 / samples as f64;
                point_at(first, &cf, u).distance_squared(point_at(second, &cs, u + shift))
            })
            .sum::<f64>()
    };
    (0..samples)
        .map(|i| i as f64 / samples as f64)
        .min_by(|&a, &b| cost(a).total_cmp(&cost(b)))
        .unwrap_or(0.0)
}

/// A tube from ring `first` to ring `second` (closed polylines running the same way round
/// the tube), with `inner` rings between them whose vertex counts go from the first's to the
/// second's. Returns the inner rings' positions and the triangles, whose corners index the
/// first ring (`0..n_first`), then the inner rings in order, then the second ring. Each
/// triangle holds one ring's edge `k + 1 → k` on the first ring's side of the strip and
/// `k → k + 1` on the other.
pub(super) fn tube(first: &[DVec3], second: &[DVec3], inner: usize) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let shift = best_shift(first, second, 64);
    let (cf, cs) = (closed_cumulative(first), closed_cumulative(second));
    let (uf, us) = (fractions(&cf), fractions(&cs));
    // Each ring: its vertices' parameters (in the first ring's parametrization) and positions.
    let mut rings: Vec<Ring> = vec![(uf.clone(), first.to_vec())];
    let mut positions = Vec::new();
    for i in 1..=inner {
        let t = i as f64 / (inner + 1) as f64;
        let n = ((1.0 - t) * first.len() as f64 + t * second.len() as f64)
            .round()
            .max(3.0) as usize;
        let params: Vec<f64> = (0..n).map(|k| k as f64 / n as f64).collect();
        let ring: Vec<DVec3> = params
            .iter()
            .map(|&u| point_at(first, &cf, u).lerp(point_at(second, &cs, u + shift), t))
            .collect();
        positions.extend_from_slice(&ring);
        rings.push((params, ring));
    }
    rings.push((
        us.iter().map(|u| (u - shift).rem_euclid(1.0)).collect(),
        second.to_vec(),
    ));
    let mut triangles = Vec::new();
    let mut base = 0u32;
    for pair in rings.windows(2) {
        let next_base = base + pair[0].1.len() as u32;
        zip(&pair[0], &pair[1], base, next_base, &mut triangles);
        base = next_base;
    }
    (positions, triangles)
}

/// Triangles between two rings (parameters and positions), their vertices numbered from
/// `a_base` and `b_base`: [`zip_chains`] once round, starting from the vertices with the
/// smallest parameters.
pub(super) fn zip(
    (a_params, a): &Ring,
    (b_params, b): &Ring,
    a_base: u32,
    b_base: u32,
    triangles: &mut Vec<[u32; 3]>,
) {
    let round = |params: &[f64], ring: &[DVec3], base: u32| {
        let start = (0..params.len())
            .min_by(|&i, &j| params[i].total_cmp(&params[j]))
            .unwrap_or(0);
        (0..=ring.len())
            .map(|i| {
                let k = (start + i) % ring.len();
                (base + k as u32, ring[k])
            })
            .collect::<Vec<_>>()
    };
    zip_chains(
        &round(a_params, a, a_base),
        &round(b_params, b, b_base),
        triangles,
    );
}

/// Triangles between two chains of (vertex, position) whose first vertices are to be joined
/// by an edge, and their last ones too: each step advances along the chain whose next
/// vertex makes the shorter diagonal. Each triangle holds `a`'s edge `i + 1 → i` or `b`'s
/// `j → j + 1`.
pub(super) fn zip_chains(a: &[(u32, DVec3)], b: &[(u32, DVec3)], triangles: &mut Vec<[u32; 3]>) {
    let (na, nb) = (a.len() - 1, b.len() - 1);
    let (mut i, mut j) = (0, 0);
    while i < na || j < nb {
        let advance_a = if i == na {
            false
        } else if j == nb {
            true
        } else {
            a[i + 1].1.distance_squared(b[j].1) <= a[i].1.distance_squared(b[j + 1].1)
        };
        if advance_a {
            triangles.push([a[i + 1].0, a[i].0, b[j].0]);
            i += 1;
        } else {
            triangles.push([a[i].0, b[j].0, b[j + 1].0]);
            j += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn circle(n: usize, z: f64, phase: f64) -> Vec<DVec3> {
        (0..n)
            .map(|k| {
                let a = std::f64::consts::TAU * k as f64 / n as f64 + phase;
                DVec3::new(a.cos(), a.sin(), z)
            })
            .collect()
    }

    #[test]
    fn a_tube_between_unequal_circles_uses_every_edge_once_each_way() {
        let (first, second) = (circle(12, 0.0, 0.0), circle(17, 2.0, 0.4));
        let (inner, triangles) = tube(&first, &second, 3);
        let n = first.len() + inner.len() + second.len();
        // 12 + 17 triangles per ring step: each strip has as many as its two rings' vertices.
        let rings: Vec<usize> = std::iter::once(12)
            .chain((1..=3).map(|i| (12.0 + (17.0 - 12.0) * i as f64 / 4.0).round() as usize))
            .chain(std::iter::once(17))
            .collect();
        let expected: usize = rings.windows(2).map(|w| w[0] + w[1]).sum();
        assert_eq!(triangles.len(), expected);
        let mut directed = std::collections::HashSet::new();
        for t in &triangles {
            assert!(t.iter().all(|&v| (v as usize) < n));
            for k in 0..3 {
                assert!(
                    directed.insert((t[k], t[(k + 1) % 3])),
                    "an edge used twice one way"
                );
            }
        }
        // Inner edges have both directions; the rims only one.
        let one_way = directed
            .iter()
            .filter(|(a, b)| !directed.contains(&(*b, *a)))
            .count();
        assert_eq!(one_way, 12 + 17);
    }
}

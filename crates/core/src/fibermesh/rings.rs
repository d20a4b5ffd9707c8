//! Rings of vertices and the strips of triangles between them: what the tunnel's tube and
//! the extrusion's limb are built of. A ring is a closed polyline; each vertex carries a
//! parameter (its arclength fraction in some reference ring), and consecutive rings are
//! zipped by those parameters.

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
    zip_chains(&round(a_params, a, a_base), &round(b_params, b, b_base), triangles);
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

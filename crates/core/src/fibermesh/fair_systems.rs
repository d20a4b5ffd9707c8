//! The two constant least-squares systems of the fair-surface optimization, assembled and
//! factored once per topology and curve set (see [`super::fair_surface`]).

use super::measure::Rings;
use crate::solve::{Prefactored, SolveError, Triplets};

/// Weight of the rows `c_i = c'_i` against the smoothing rows `L_d c = 0` (thesis: 1).
pub(crate) const DIFFUSION_WEIGHT: f64 = 1.0;
/// Weight of the edge-vector rows against the Laplacian rows (thesis: 1).
pub(crate) const EDGE_WEIGHT: f64 = 1.0;
/// Weight of the Laplacian rows of smooth curve vertices. These few rows decide whether the
/// surface is smooth across the curve, against many interior rows: with weight 1 the arm
/// tips of a seven-armed star (outline radius about one spacing) met front to back at 96°,
/// with 2 at 75° (thinner arms still reach about 95°); with 10 the interior folds.
pub(crate) const SMOOTH_CURVE_WEIGHT: f64 = 2.0;

/// `[L_d; w_d I]`: a smoothing row for each non-sharp vertex with `has_rows` over its
/// non-sharp neighbours (so nothing diffuses across a sharp curve), then identity rows.
/// Unknowns with `fixed` hold given values (the frame of a regional solve). Returns the
/// factored system and the number of smoothing rows.
///
/// Errors: those of [`Prefactored::new`] (none for a valid mesh: the identity rows make
/// the system positive definite).
pub(crate) fn factor_diffusion(
    rings: &Rings,
    is_sharp: &[bool],
    has_rows: &[bool],
    fixed: &[bool],
) -> Result<(Prefactored, usize), SolveError> {
    let n = rings.len();
    let is_smooth = |j: &&u32| !is_sharp[**j as usize];
    let smoothing: Vec<usize> = (0..n)
        .filter(|&i| has_rows[i] && !is_sharp[i] && rings.ring(i).iter().any(|j| is_smooth(&j)))
        .collect();
    let n_rows = smoothing.len();
    let mut triplets = Triplets::with_capacity(n_rows + n, n, 8 * n);
    for (row, &i) in smoothing.iter().enumerate() {
        let count = rings.ring(i).iter().filter(is_smooth).count() as f64;
        triplets.push(row, i, 1.0);
        for &j in rings.ring(i).iter().filter(is_smooth) {
            triplets.push(row, j as usize, -1.0 / count);
        }
    }
    for i in 0..n {
        triplets.push(n_rows + i, i, DIFFUSION_WEIGHT);
    }
    Ok((Prefactored::new(&triplets.build(), fixed)?, n_rows))
}

/// The weight of vertex `i`'s Laplacian row in the position system.
pub(crate) fn laplacian_weight(is_curve: bool) -> f64 {
    if is_curve { SMOOTH_CURVE_WEIGHT } else { 1.0 }
}

/// `[w_i L rows of laplacian_rows; w_e (v_i - v_j) for B]` with the `fixed` vertices (the
/// curves, and the frame of a regional solve) given.
///
/// Errors: those of [`Prefactored::new`], for example when a connected part has no curve
/// vertex.
pub(crate) fn factor_placement(
    rings: &Rings,
    laplacian_rows: &[u32],
    edge_rows: &[[u32; 2]],
    is_curve: &[bool],
    fixed: &[bool],
) -> Result<Prefactored, SolveError> {
    let n = rings.len();
    let n_rows = laplacian_rows.len() + edge_rows.len();
    let mut triplets = Triplets::with_capacity(n_rows, n, 8 * n + 2 * edge_rows.len());
    for (row, &i) in laplacian_rows.iter().enumerate() {
        let ring = rings.ring(i as usize);
        let w = laplacian_weight(is_curve[i as usize]);
        triplets.push(row, i as usize, w);
        for &j in ring {
            triplets.push(row, j as usize, -w / ring.len() as f64);
        }
    }
    let offset = laplacian_rows.len();
    for (k, &[i, j]) in edge_rows.iter().enumerate() {
        triplets.push(offset + k, i as usize, EDGE_WEIGHT);
        triplets.push(offset + k, j as usize, -EDGE_WEIGHT);
    }
    Prefactored::new(&triplets.build(), fixed)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;
    use glam::DVec3;

    #[test]
    fn diffusion_keeps_constants_and_does_not_cross_sharp_vertices() {
        let mesh = primitives::icosphere(1.0, 2);
        let rings = Rings::of_mesh(&mesh);
        let n = mesh.n_vertices();
        // No sharp vertices: a constant is its own smoothing.
        let all = vec![true; n];
        let none = vec![false; n];
        let (mut solver, n_rows) = factor_diffusion(&rings, &none, &all, &none).unwrap();
        assert_eq!(n_rows, n);
        let mut rhs = vec![DVec3::ZERO; 2 * n];
        rhs[n..].fill(DVec3::new(2.0, 3.0, 0.0));
        let mut out = vec![DVec3::ZERO; n];
        solver.solve(&rhs, &vec![DVec3::ZERO; n], &mut out).unwrap();
        assert!(
            out.iter()
                .all(|v| (*v - DVec3::new(2.0, 3.0, 0.0)).length() < 1e-10)
        );
        // A sharp vertex keeps exactly its own value: it has only its identity row.
        let mut is_sharp = vec![false; n];
        is_sharp[0] = true;
        let (mut solver, n_rows) = factor_diffusion(&rings, &is_sharp, &all, &none).unwrap();
        assert_eq!(n_rows, n - 1);
        let mut rhs = vec![DVec3::ZERO; n_rows + n];
        rhs[n_rows] = DVec3::X * 5.0;
        solver.solve(&rhs, &vec![DVec3::ZERO; n], &mut out).unwrap();
        assert!((out[0].x - 5.0).abs() < 1e-12);
        assert!(
            out[1..].iter().all(|v| v.x.abs() < 1e-12),
            "the sharp value leaked"
        );
    }
}

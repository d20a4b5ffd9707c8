//! The volumetric graph Laplacian's weights (Zhou et al. 2005, §3.3 "Weighting Scheme"):
//! at each graph point `i` with neighbours `j`, the weights solve the small QP
//!
//! `min ‖p_i − Σ w_j p_j‖² + λ (Σ w_j ‖p_i − p_j‖)²  s.t.  Σ w_j = 1, w_j ≥ ξ`,
//!
//! small Laplacian coordinates (the first term) balanced by the scale-dependent umbrella
//! operator (the second, which prefers weights inversely proportional to edge length), with
//! λ = ξ = 0.01 as the paper sets them. Written with the edges `e_j = p_j − p_i` (the
//! weights sum to one) the objective is `wᵀ H w` with `H = EᵀE + λ d dᵀ`, `d_j = ‖e_j‖`.
//!
//! `H` has rank at most four, so with more than four neighbours the minimiser is not
//! unique; a ridge of `1e-9 tr H / k` picks the one of least norm among the near-optimal
//! (the paper does not say). Solved by a primal active-set method (Nocedal & Wright,
//! Alg. 16.3) from the uniform weights, which are feasible: each step solves the equality
//! problem on the free weights with faer's dense LU, stops at the first bound it would
//! cross, and frees the bound weight with the most negative multiplier once none would.
//! A point has about 8 to 20 neighbours, so each QP is a few 20 × 20 solves.

use faer::Mat;
use faer::linalg::solvers::Solve;
use glam::DVec3;

/// The paper's λ: the weight of the umbrella term.
pub const LAMBDA: f64 = 0.01;
/// The paper's ξ: the least weight of a neighbour.
pub const XI: f64 = 0.01;
/// Relative size of the ridge that makes `H` definite.
const RIDGE: f64 = 1e-9;
/// A multiplier or step this far below zero counts as negative.
const TOLERANCE: f64 = 1e-12;

/// The weights of `p`'s `neighbours` (in their order), positive and summing to one. With so
/// many neighbours that `k ξ > 1/2`, the bound is lowered to `1 / (2k)`, so the uniform
/// weights stay strictly feasible.
pub(super) fn graph_weights(p: DVec3, neighbours: &[DVec3]) -> Vec<f64> {
    let k = neighbours.len();
    if k <= 1 {
        return vec![1.0; k];
    }
    let lower = XI.min(0.5 / k as f64);
    let edges: Vec<DVec3> = neighbours.iter().map(|&q| q - p).collect();
    let lengths: Vec<f64> = edges.iter().map(|e| e.length()).collect();
    let mut h = Mat::from_fn(k, k, |a, b| {
        edges[a].dot(edges[b]) + LAMBDA * lengths[a] * lengths[b]
    });
    let trace: f64 = (0..k).map(|a| h[(a, a)]).sum();
    let ridge = RIDGE * trace.max(f64::MIN_POSITIVE) / k as f64;
    for a in 0..k {
        h[(a, a)] += ridge;
    }
    active_set(&h, lower)
}

/// Minimises `wᵀ H w` over `Σ w = 1, w ≥ lower` from the uniform weights.
fn active_set(h: &Mat<f64>, lower: f64) -> Vec<f64> {
    let k = h.nrows();
    let mut w = vec![1.0 / k as f64; k];
    let mut bound = vec![false; k];
    for _ in 0..4 * k {
        let target = equality_minimiser(h, &w, &bound, lower);
        // The largest step toward the target that keeps every weight at or above the bound.
        let mut step = 1.0;
        let mut blocking = None;
        for j in (0..k).filter(|&j| !bound[j]) {
            if target[j] < lower && w[j] > target[j] {
                let reach = (w[j] - lower) / (w[j] - target[j]);
                if reach < step {
                    step = reach;
                    blocking = Some(j);
                }
            }
        }
        for j in 0..k {
            w[j] += step * (target[j] - w[j]);
        }
        if let Some(j) = blocking {
            bound[j] = true;
            w[j] = lower;
            continue;
        }
        // At the equality minimiser: free the bound weight whose multiplier is most negative.
        let gradient: Vec<f64> = (0..k)
            .map(|a| 2.0 * (0..k).map(|b| h[(a, b)] * w[b]).sum::<f64>())
            .collect();
        let free: Vec<usize> = (0..k).filter(|&j| !bound[j]).collect();
        let nu = -free.iter().map(|&j| gradient[j]).sum::<f64>() / free.len() as f64;
        let release = (0..k)
            .filter(|&j| bound[j])
            .map(|j| (j, gradient[j] + nu))
            .filter(|&(_, multiplier)| multiplier < -TOLERANCE)
            .min_by(|a, b| a.1.total_cmp(&b.1));
        match release {
            Some((j, _)) => bound[j] = false,
            None => break,
        }
    }
    w
}

/// The minimiser of `wᵀ H w` with the bound weights at `lower` and the free ones summing to
/// the rest of one: the KKT system `[2 H_ff 1; 1ᵀ 0] [w_f; ν] = [−2 H_fb w_b; 1 − Σ w_b]`.
fn equality_minimiser(h: &Mat<f64>, w: &[f64], bound: &[bool], lower: f64) -> Vec<f64> {
    let free: Vec<usize> = (0..w.len()).filter(|&j| !bound[j]).collect();
    let m = free.len();
    let n_bound = (w.len() - m) as f64;
    let kkt = Mat::from_fn(m + 1, m + 1, |a, b| match (a < m, b < m) {
        (true, true) => 2.0 * h[(free[a], free[b])],
        (true, false) | (false, true) => 1.0,
        (false, false) => 0.0,
    });
    let rhs = Mat::from_fn(m + 1, 1, |a, _| {
        if a < m {
            let row = free[a];
            -2.0 * (0..w.len())
                .filter(|&j| bound[j])
                .map(|j| h[(row, j)] * lower)
                .sum::<f64>()
        } else {
            1.0 - n_bound * lower
        }
    });
    let solution = kkt.partial_piv_lu().solve(&rhs);
    let mut target = vec![lower; w.len()];
    for (a, &j) in free.iter().enumerate() {
        target[j] = solution[(a, 0)];
    }
    target
}

#[cfg(test)]
mod tests {
    use super::*;

    fn objective(p: DVec3, neighbours: &[DVec3], w: &[f64]) -> f64 {
        let combination: DVec3 = neighbours.iter().zip(w).map(|(&q, &w)| q * w).sum();
        let umbrella: f64 = neighbours
            .iter()
            .zip(w)
            .map(|(&q, &w)| w * p.distance(q))
            .sum();
        (p - combination).length_squared() + LAMBDA * umbrella * umbrella
    }

    #[test]
    fn symmetric_neighbours_get_equal_weights() {
        let neighbours: Vec<DVec3> = [
            DVec3::X,
            -DVec3::X,
            DVec3::Y,
            -DVec3::Y,
            DVec3::Z,
            -DVec3::Z,
        ]
        .to_vec();
        let w = graph_weights(DVec3::ZERO, &neighbours);
        for x in &w {
            assert!((x - 1.0 / 6.0).abs() < 1e-6, "{w:?}");
        }
    }

    #[test]
    fn weights_are_feasible_and_beat_random_feasible_weights() {
        let p = DVec3::new(0.1, -0.2, 0.05);
        let neighbours: Vec<DVec3> = (0..11)
            .map(|i| {
                let a = i as f64 * 2.39996;
                let r = 0.5 + 0.4 * (i as f64 * 1.3).sin().abs();
                DVec3::new(r * a.cos(), r * a.sin(), 0.6 * (a * 0.7).sin())
            })
            .collect();
        let w = graph_weights(p, &neighbours);
        assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-12);
        assert!(w.iter().all(|&x| x >= XI - 1e-12), "{w:?}");
        let best = objective(p, &neighbours, &w);
        // Any feasible perturbation is no better.
        for seed in 0..200u32 {
            let mut v: Vec<f64> = (0..11)
                .map(|j| XI + ((seed * 31 + j * 17) % 97) as f64 / 97.0)
                .collect();
            let excess = v.iter().sum::<f64>() - 11.0 * XI;
            for x in &mut v {
                *x = XI + (*x - XI) / excess * (1.0 - 11.0 * XI);
            }
            assert!(objective(p, &neighbours, &v) >= best - 1e-9);
        }
        // Farther neighbours weigh less, all else equal: the umbrella term at work.
        let line = [DVec3::X, -2.0 * DVec3::X];
        let w = graph_weights(DVec3::ZERO, &line);
        assert!((w[0] - 2.0 / 3.0).abs() < 5e-3 && w[0] > w[1], "{w:?}");
    }
}

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

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::cholesky::llt::factor::{
    LltRegularization, cholesky_in_place, cholesky_in_place_scratch,
};
use faer::linalg::cholesky::llt::solve::solve_in_place;
use faer::{Mat, Par};
use glam::DVec3;

/// The paper's λ: the weight of the umbrella term.
const LAMBDA: f64 = 0.01;
/// The paper's ξ: the least weight of a neighbour.
const XI: f64 = 0.01;
/// Relative size of the ridge that makes `H` definite.
const RIDGE: f64 = 1e-9;
/// A multiplier this far below zero counts as negative.
const TOLERANCE: f64 = 1e-12;

/// Buffers for the QPs of one graph, sized for its largest neighbourhood.
pub(super) struct WeightSolver {
    h: Mat<f64>,
    factor: Mat<f64>,
    columns: Mat<f64>,
    memory: MemBuffer,
    edges: Vec<DVec3>,
    lengths: Vec<f64>,
    w: Vec<f64>,
    target: Vec<f64>,
    bound: Vec<bool>,
    free: Vec<usize>,
}

impl WeightSolver {
    /// Buffers for neighbourhoods of up to `max_k` points.
    pub(super) fn new(max_k: usize) -> WeightSolver {
        let scratch = cholesky_in_place_scratch::<f64>(max_k, Par::Seq, Default::default());
        WeightSolver {
            h: Mat::zeros(max_k, max_k),
            factor: Mat::zeros(max_k, max_k),
            columns: Mat::zeros(max_k, 2),
            memory: MemBuffer::new(scratch),
            edges: Vec::with_capacity(max_k),
            lengths: Vec::with_capacity(max_k),
            w: Vec::with_capacity(max_k),
            target: Vec::with_capacity(max_k),
            bound: Vec::with_capacity(max_k),
            free: Vec::with_capacity(max_k),
        }
    }

    /// Appends the weights of `p`'s `neighbours` (in their order) to `out`: positive and
    /// summing to one. With so many neighbours that `k ξ > 1/2`, the bound is lowered to
    /// `1 / (2k)`, so the uniform weights stay strictly feasible.
    pub(super) fn weights(&mut self, p: DVec3, neighbours: &[DVec3], out: &mut Vec<f64>) {
        let k = neighbours.len();
        if k <= 1 {
            out.extend(std::iter::repeat_n(1.0, k));
            return;
        }
        let lower = XI.min(0.5 / k as f64);
        self.edges.clear();
        self.edges.extend(neighbours.iter().map(|&q| q - p));
        self.lengths.clear();
        self.lengths.extend(self.edges.iter().map(|e| e.length()));
        let mut trace = 0.0;
        for a in 0..k {
            for b in 0..k {
                let value =
                    self.edges[a].dot(self.edges[b]) + LAMBDA * self.lengths[a] * self.lengths[b];
                self.h[(a, b)] = value;
            }
            trace += self.h[(a, a)];
        }
        let ridge = RIDGE * trace.max(f64::MIN_POSITIVE) / k as f64;
        for a in 0..k {
            self.h[(a, a)] += ridge;
        }
        self.active_set(k, lower);
        out.extend_from_slice(&self.w);
    }

    /// Minimises `wᵀ H w` over `Σ w = 1, w ≥ lower` from the uniform weights, into `self.w`.
    fn active_set(&mut self, k: usize, lower: f64) {
        self.w.clear();
        self.w.resize(k, 1.0 / k as f64);
        self.bound.clear();
        self.bound.resize(k, false);
        for _ in 0..4 * k {
            let Some(nu) = self.equality_minimiser(k, lower) else {
                return;
            };
            // The largest step toward the target that keeps every weight at or above the bound.
            let mut step = 1.0;
            let mut blocking = None;
            for j in (0..k).filter(|&j| !self.bound[j]) {
                let (w, t) = (self.w[j], self.target[j]);
                if t < lower && w > t {
                    let reach = (w - lower) / (w - t);
                    if reach < step {
                        step = reach;
                        blocking = Some(j);
                    }
                }
            }
            for j in 0..k {
                self.w[j] += step * (self.target[j] - self.w[j]);
            }
            if let Some(j) = blocking {
                self.bound[j] = true;
                self.w[j] = lower;
                continue;
            }
            // At the equality minimiser: free the bound weight whose multiplier
            // `2 (H w)_j + ν` is most negative.
            let release = (0..k)
                .filter(|&j| self.bound[j])
                .map(|j| {
                    let gradient: f64 = (0..k).map(|b| 2.0 * self.h[(j, b)] * self.w[b]).sum();
                    (j, gradient + nu)
                })
                .filter(|&(_, multiplier)| multiplier < -TOLERANCE)
                .min_by(|a, b| a.1.total_cmp(&b.1));
            match release {
                Some((j, _)) => self.bound[j] = false,
                None => return,
            }
        }
    }

    /// The minimiser of `wᵀ H w` with the bound weights at `lower` and the free ones summing
    /// to the rest of one, into `self.target`; returns the sum's multiplier `ν`, or `None`
    /// when `H_ff` cannot be factored (not finite).
    fn equality_minimiser(&mut self, k: usize, lower: f64) -> Option<f64> {
        self.free.clear();
        self.free.extend((0..k).filter(|&j| !self.bound[j]));
        let m = self.free.len();
        let rest = 1.0 - (k - m) as f64 * lower;
        for (a, &i) in self.free.iter().enumerate() {
            for (b, &j) in self.free.iter().enumerate() {
                self.factor[(a, b)] = self.h[(i, j)];
            }
            let coupling: f64 = (0..k)
                .filter(|&j| self.bound[j])
                .map(|j| self.h[(i, j)] * lower)
                .sum();
            self.columns[(a, 0)] = -coupling;
            self.columns[(a, 1)] = 1.0;
        }
        let mut factor = self.factor.as_mut().submatrix_mut(0, 0, m, m);
        let stack = MemStack::new(&mut self.memory);
        cholesky_in_place(
            factor.as_mut(),
            LltRegularization::default(),
            Par::Seq,
            stack,
            Default::default(),
        )
        .ok()?;
        solve_in_place(
            factor.as_ref(),
            self.columns.as_mut().submatrix_mut(0, 0, m, 2),
            Par::Seq,
            MemStack::new(&mut []),
        );
        let sum_a: f64 = (0..m).map(|a| self.columns[(a, 0)]).sum();
        let sum_b: f64 = (0..m).map(|a| self.columns[(a, 1)]).sum();
        let half_nu = (sum_a - rest) / sum_b;
        self.target.clear();
        self.target.resize(k, lower);
        for (a, &j) in self.free.iter().enumerate() {
            self.target[j] = self.columns[(a, 0)] - half_nu * self.columns[(a, 1)];
        }
        Some(2.0 * half_nu)
    }
}

/// The weights of one point, with buffers of its own (tests and one-off use).
#[cfg(test)]
fn graph_weights(p: DVec3, neighbours: &[DVec3]) -> Vec<f64> {
    let mut out = Vec::new();
    WeightSolver::new(neighbours.len()).weights(p, neighbours, &mut out);
    out
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

//! One-dimensional Gaussian mixtures fitted by expectation-maximisation, for SEED's part ROI
//! (Bao & Howard §4.2: one mixture of the whole model's SDF values, one of the seeds').
//!
//! SEED uses greedy EM (Vlassis & Likas) with 4 components; we start plain EM from
//! components at evenly spaced quantiles, which on one dimension finds the same modes
//! without the greedy insertion search. A variance floor keeps a component from collapsing
//! onto repeated values (a sphere's SDF is nearly constant).

/// EM iterations; one-dimensional mixtures of a few components settle well before this.
const ITERATIONS: usize = 60;

/// A component's standard deviation is at least this fraction of the samples' median.
const MIN_RELATIVE_SIGMA: f64 = 0.02;

/// A mixture of one-dimensional Gaussians.
#[derive(Clone, Debug, PartialEq)]
pub struct Mixture {
    /// `(weight, mean, standard deviation)` per component; weights sum to 1.
    pub components: Vec<(f64, f64, f64)>,
}

impl Mixture {
    /// Fits up to `n_components` Gaussians to `samples` (finite values); `None` when there
    /// are no samples.
    pub fn fit(samples: &[f64], n_components: usize) -> Option<Mixture> {
        if samples.is_empty() {
            return None;
        }
        let mut sorted = samples.to_vec();
        sorted.sort_by(f64::total_cmp);
        let median = sorted[sorted.len() / 2].abs();
        let floor = (MIN_RELATIVE_SIGMA * median).max(1e-12);
        let k = n_components.clamp(1, samples.len());
        let spread = (sorted[sorted.len() - 1] - sorted[0]) / k as f64;
        let mut components: Vec<(f64, f64, f64)> = (0..k)
            .map(|c| {
                let quantile = sorted[((2 * c + 1) * sorted.len()) / (2 * k)];
                (1.0 / k as f64, quantile, spread.max(floor))
            })
            .collect();
        let mut responsibility = vec![0.0; k];
        for _ in 0..ITERATIONS {
            let mut sums = vec![(0.0, 0.0, 0.0); k];
            for &x in samples {
                let total = weighted_densities(&components, x, &mut responsibility);
                if total <= 0.0 {
                    continue;
                }
                for (sum, r) in sums.iter_mut().zip(&responsibility) {
                    let r = r / total;
                    *sum = (sum.0 + r, sum.1 + r * x, sum.2 + r * x * x);
                }
            }
            let n = samples.len() as f64;
            components = sums
                .into_iter()
                .filter(|&(r, _, _)| r > 1e-9 * n)
                .map(|(r, rx, rxx)| {
                    let mean = rx / r;
                    let variance = (rxx / r - mean * mean).max(0.0);
                    (r / n, mean, variance.sqrt().max(floor))
                })
                .collect();
            responsibility.truncate(components.len());
        }
        let total: f64 = components.iter().map(|c| c.0).sum();
        for c in &mut components {
            c.0 /= total;
        }
        Some(Mixture { components })
    }

    /// The mixture's density at `x`.
    pub fn density(&self, x: f64) -> f64 {
        self.components
            .iter()
            .map(|&(w, mean, sigma)| w * gaussian(x, mean, sigma))
            .sum()
    }

    /// `-ln density(x)`, bounded so that a value far from every component costs a lot
    /// but not infinity.
    pub fn cost(&self, x: f64) -> f64 {
        -self.density(x).max(1e-300).ln()
    }
}

/// Writes each component's weighted density at `x` and returns their sum.
fn weighted_densities(components: &[(f64, f64, f64)], x: f64, out: &mut [f64]) -> f64 {
    let mut total = 0.0;
    for (o, &(w, mean, sigma)) in out.iter_mut().zip(components) {
        *o = w * gaussian(x, mean, sigma);
        total += *o;
    }
    total
}

fn gaussian(x: f64, mean: f64, sigma: f64) -> f64 {
    let z = (x - mean) / sigma;
    (-0.5 * z * z).exp() / (sigma * (std::f64::consts::TAU).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Deterministic normal samples (Box–Muller over a fixed low-discrepancy sequence).
    fn normal_samples(mean: f64, sigma: f64, n: usize) -> Vec<f64> {
        (0..n)
            .map(|i| {
                let u = (i as f64 + 0.5) / n as f64;
                let v = ((i as f64) * 0.618_033_988_75).fract().max(1e-9);
                mean + sigma * (-2.0 * v.ln()).sqrt() * (std::f64::consts::TAU * u).cos()
            })
            .collect()
    }

    #[test]
    fn two_separated_modes_are_found() {
        let mut samples = normal_samples(0.3, 0.03, 600);
        samples.extend(normal_samples(2.0, 0.1, 1400));
        let mixture = Mixture::fit(&samples, 4).unwrap();
        let total: f64 = mixture.components.iter().map(|c| c.0).sum();
        assert!((total - 1.0).abs() < 1e-12);
        // The mass near each mode matches the samples'.
        let mass_near = |centre: f64| -> f64 {
            mixture
                .components
                .iter()
                .filter(|c| (c.1 - centre).abs() < 0.3)
                .map(|c| c.0)
                .sum()
        };
        assert!((mass_near(0.3) - 0.3).abs() < 0.02, "{mixture:?}");
        assert!((mass_near(2.0) - 0.7).abs() < 0.02, "{mixture:?}");
        assert!(mixture.cost(0.3) < mixture.cost(1.1));
        assert!(mixture.cost(2.0) < mixture.cost(1.1));
    }

    #[test]
    fn constant_samples_keep_a_floor_on_sigma() {
        let mixture = Mixture::fit(&[1.5; 50], 4).unwrap();
        assert!(mixture.components.iter().all(|c| c.2 >= 0.02 * 1.5));
        assert!(mixture.density(1.5).is_finite());
        assert_eq!(Mixture::fit(&[], 4), None);
    }
}

//! Per-vertex weights of the optimization: positional weights from the mean curvature
//! (§6.5), the feature-preserving Laplacian weights (§6.5.3) and the quality modulation
//! (§6.5.2).

use super::WeightScheme;
use super::quality::radius_ratio;
use crate::geometry::mean_curvature_normals;
use crate::mesh::Mesh;

/// The mean curvature magnitude `κ̄` of every vertex (Eq. 6.7, mixed Voronoi areas).
pub fn curvature_magnitudes(mesh: &Mesh) -> Vec<f64> {
    mean_curvature_normals(mesh)
        .iter()
        .map(|hn| hn.length())
        .collect()
}

/// Positional weights in `[0, scale]` from the curvatures `kappa` by `scheme`.
pub fn positional_weights(kappa: &[f64], scheme: WeightScheme, scale: f64) -> Vec<f64> {
    match scheme {
        WeightScheme::Const => vec![scale; kappa.len()],
        WeightScheme::Linear => linear_weights(kappa, scale),
        WeightScheme::Cdf => cdf_weights(kappa, scale),
    }
}

/// `κ̄` mapped linearly from its minimum to the box-plot fence `Q3 + 1.5 IQR` (Tukey) onto
/// `[0, scale]`; curvatures above the fence, the outliers, get `scale`. With no spread
/// (a flat or uniformly curved mesh) every weight is `scale`.
pub fn linear_weights(kappa: &[f64], scale: f64) -> Vec<f64> {
    let lo = kappa.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = box_plot_fence(kappa);
    // No spread (or no values): `hi <= lo`, or an infinite `lo`.
    if hi.partial_cmp(&lo) != Some(std::cmp::Ordering::Greater) {
        return vec![scale; kappa.len()];
    }
    kappa
        .iter()
        .map(|&k| scale * ((k - lo) / (hi - lo)).clamp(0.0, 1.0))
        .collect()
}

/// `scale` times the empirical cumulative distribution of `κ̄` (Eq. 6.13): the share of
/// vertices at most as curved. It spreads the weights evenly whatever the outliers.
pub fn cdf_weights(kappa: &[f64], scale: f64) -> Vec<f64> {
    let mut sorted = kappa.to_vec();
    sorted.sort_by(f64::total_cmp);
    let n = sorted.len() as f64;
    kappa
        .iter()
        .map(|&k| scale * sorted.partition_point(|&s| s <= k) as f64 / n)
        .collect()
}

/// Laplacian row weights that keep features (§6.5.3): `(scale − w) / scale` from positional
/// weights `weights` in `[0, scale]` ([`linear_weights`] or [`cdf_weights`]), so the most
/// curved vertices (weight `scale`) get no Laplacian row and stay where they are.
pub fn feature_laplacian_weights(weights: &[f64], scale: f64) -> Vec<f64> {
    weights
        .iter()
        .map(|&w| ((scale - w) / scale).clamp(0.0, 1.0))
        .collect()
}

/// Laplacian row weights with a Gaussian fall-off in the curvature, `exp(−(κ̄ / σ)²)`, with
/// `σ` the box-plot fence `Q3 + 1.5 IQR` of `kappa` (1 everywhere when it is zero: nothing
/// stands out as a feature).
pub fn gaussian_laplacian_weights(kappa: &[f64]) -> Vec<f64> {
    let sigma = box_plot_fence(kappa);
    if sigma <= 0.0 {
        return vec![1.0; kappa.len()];
    }
    kappa
        .iter()
        .map(|&k| (-(k / sigma).powi(2)).exp())
        .collect()
}

/// Tukey's upper fence `Q3 + 1.5 IQR` (nearest-rank quartiles), at most the largest value.
fn box_plot_fence(values: &[f64]) -> f64 {
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    let Some(&largest) = sorted.last() else {
        return 0.0;
    };
    let quartile = |q: f64| sorted[((sorted.len() - 1) as f64 * q).round() as usize];
    let (q1, q3) = (quartile(0.25), quartile(0.75));
    (q3 + 1.5 * (q3 - q1)).min(largest)
}

/// The worst radius ratio among each vertex's triangles (§6.5.2): multiplied into the
/// positional weights, it frees the vertices of poor triangles to move.
pub fn worst_radius_ratios(mesh: &Mesh) -> Vec<f64> {
    let mut worst = vec![1.0f64; mesh.n_vertices()];
    for f in mesh.faces() {
        let t = radius_ratio(mesh.face_positions(f));
        for v in mesh.face_vertices(f) {
            worst[v.index()] = worst[v.index()].min(t);
        }
    }
    worst
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gaussian_weights_fall_to_one_over_e_at_the_fence() {
        let mut kappa: Vec<f64> = (0..=20).map(f64::from).collect();
        kappa.push(1000.0);
        let w = gaussian_laplacian_weights(&kappa);
        // The fence is 32.5 (see the linear test): 0 keeps its row, 20 keeps exp(−(20/32.5)²).
        assert_eq!(w[0], 1.0);
        assert!((w[20] - (-(20.0f64 / 32.5).powi(2)).exp()).abs() < 1e-12);
        assert!(w[21] < 1e-300, "the outlier loses its row");
        assert_eq!(gaussian_laplacian_weights(&[0.0; 3]), vec![1.0; 3]);
    }

    #[test]
    fn linear_weights_truncate_outliers_at_the_fence() {
        let mut kappa: Vec<f64> = (0..=20).map(f64::from).collect();
        kappa.push(1000.0);
        let w = linear_weights(&kappa, 2.0);
        // Q1 = 5, Q3 = 16 (nearest rank), fence 32.5 above every inlier: inliers spread
        // over [0, 2 · 20 / 32.5], the outlier gets the full scale.
        assert_eq!(w[0], 0.0);
        assert!((w[20] - 2.0 * 20.0 / 32.5).abs() < 1e-12);
        assert_eq!(w[21], 2.0);
        assert_eq!(linear_weights(&[3.0; 4], 0.5), vec![0.5; 4]);
    }

    #[test]
    fn cdf_weights_are_ranks() {
        let w = cdf_weights(&[4.0, 1.0, 3.0, 2.0], 1.0);
        assert_eq!(w, vec![1.0, 0.25, 0.75, 0.5]);
        assert_eq!(cdf_weights(&[0.0, 0.0], 2.0), vec![2.0, 2.0]);
    }
}

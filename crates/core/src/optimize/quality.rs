//! How good a result is: the radius ratio of its triangles (Eq. 6.12) and its distance to
//! the input surface (the thesis's Hausdorff distance, measured with Metro).

use glam::DVec3;
use serde::Serialize;

use crate::geometry::Bvh;
use crate::mesh::Mesh;

/// The radius ratio `2 r / R` of a triangle (inradius over half the circumradius): 1 for an
/// equilateral triangle, 0 for a degenerate one.
pub fn radius_ratio([a, b, c]: [DVec3; 3]) -> f64 {
    let (la, lb, lc) = (b.distance(c), c.distance(a), a.distance(b));
    let area_sq = (b - a).cross(c - a).length_squared() / 4.0;
    let denominator = la * lb * lc * (la + lb + lc);
    // 2r/R = 2 (2A / perimeter) / (abc / 4A) = 16 A² / (abc · perimeter).
    if denominator > 0.0 {
        (16.0 * area_sq / denominator).min(1.0)
    } else {
        0.0
    }
}

/// Triangle quality and geometric error of an optimization's result.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct QualityReport {
    /// The worst radius ratio of the result.
    pub min_radius_ratio: f64,
    /// The mean radius ratio of the result.
    pub mean_radius_ratio: f64,
    /// The worst radius ratio before the optimization.
    pub input_min_radius_ratio: f64,
    /// The mean radius ratio before the optimization.
    pub input_mean_radius_ratio: f64,
    /// One-sided Hausdorff distance from the result to the input surface, sampled at the
    /// result's vertices and face centroids, over the input's bounding-box diagonal.
    pub hausdorff_relative: f64,
}

impl QualityReport {
    /// One sentence for the user, in plain words: how even the triangles are before and
    /// after (the radius ratio as a percentage of an equilateral triangle's), and how far the
    /// surface moved.
    pub fn summary(&self) -> String {
        format!(
            "The most uneven triangle went from {:.0}% to {:.0}% even, the average from {:.0}% \
             to {:.0}%; the surface moved at most {:.2}% of the model's size.",
            100.0 * self.input_min_radius_ratio,
            100.0 * self.min_radius_ratio,
            100.0 * self.input_mean_radius_ratio,
            100.0 * self.mean_radius_ratio,
            100.0 * self.hausdorff_relative
        )
    }
}

/// Radius ratios (worst, mean) of `mesh`'s triangles with the given positions.
fn radius_ratios(mesh: &Mesh, positions: &[DVec3]) -> (f64, f64) {
    let (mut worst, mut sum) = (1.0f64, 0.0);
    for f in mesh.faces() {
        let t = radius_ratio(mesh.face_vertices(f).map(|v| positions[v.index()]));
        worst = worst.min(t);
        sum += t;
    }
    (worst, sum / mesh.n_faces().max(1) as f64)
}

/// The report for `input` optimized to `result` (one position per vertex of `input`).
pub fn quality_report(input: &Mesh, result: &[DVec3]) -> QualityReport {
    let (min_before, mean_before) = radius_ratios(input, input.positions());
    let (min_after, mean_after) = radius_ratios(input, result);
    let bvh = Bvh::new(input);
    let centroids = input.faces().map(|f| {
        input
            .face_vertices(f)
            .map(|v| result[v.index()])
            .iter()
            .sum::<DVec3>()
            / 3.0
    });
    let distance = result
        .iter()
        .copied()
        .chain(centroids)
        .filter_map(|p| bvh.nearest(input, p).map(|(q, _)| q.distance(p)))
        .fold(0.0, f64::max);
    let diagonal = input.bounding_box().map_or(1.0, |(lo, hi)| lo.distance(hi));
    QualityReport {
        min_radius_ratio: min_after,
        mean_radius_ratio: mean_after,
        input_min_radius_ratio: min_before,
        input_mean_radius_ratio: mean_before,
        hausdorff_relative: if diagonal > 0.0 {
            distance / diagonal
        } else {
            0.0
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn radius_ratio_of_known_triangles() {
        let equilateral = [
            DVec3::ZERO,
            DVec3::X,
            DVec3::new(0.5, 3f64.sqrt() / 2.0, 0.0),
        ];
        assert!((radius_ratio(equilateral) - 1.0).abs() < 1e-12);
        // Right isosceles: r = (2 − √2)/2, R = √2/2, so 2r/R = 2(√2 − 1).
        let right = [DVec3::ZERO, DVec3::X, DVec3::Y];
        assert!((radius_ratio(right) - 2.0 * (2f64.sqrt() - 1.0)).abs() < 1e-12);
        assert_eq!(radius_ratio([DVec3::ZERO, DVec3::X, DVec3::X * 2.0]), 0.0);
    }
}

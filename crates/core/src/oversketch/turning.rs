//! Turning-angle summaries and their misfit, after Cohen and Guibas's polyline shape
//! search as SilSketch uses it (Nealen's dissertation §5.4.2, Eqs. 5.3–5.6).
//!
//! A summary is the piecewise-constant function "direction of the edge at arclength `s`",
//! unwrapped so it is continuous across ±π: `t_0 = ∠(e_0, x)` and
//! `t_i = t_{i−1} + ∠(e_{i−1}, e_i)` (Eq. 5.3). Rotating a polyline shifts it up or down;
//! scaling stretches it along `s`.
//!
//! The misfit of a pattern `Ψ` (the stroke, on `u ∈ [0, 1]`) against the silhouette summary
//! `Θ` on `[lo, hi]` is the variance of `Θ(lo + u (hi − lo)) − Ψ(u)` over `u`: the mean
//! difference is the optimal rotation `γ = I₁ / α` (Eq. 5.5) and the variance is
//! `I₂ / α − γ²`, in rad². Eq. 5.6 divides this once more by `α l`; we leave that factor
//! out so the misfit does not depend on the stroke's size in pixels and the weights stay
//! unitless.

use glam::DVec2;

/// Edges shorter than this (px) carry no direction and are skipped.
const MIN_EDGE: f64 = 1e-9;

/// A turning-angle summary: edge `i` spans `breaks[i]..breaks[i + 1]` with direction
/// `angles[i]`.
#[derive(Clone, Debug, Default)]
pub(crate) struct TurningSummary {
    breaks: Vec<f64>,
    angles: Vec<f64>,
}

impl TurningSummary {
    /// The summary of `points`, with point `i` placed at position `positions[i]` (its own
    /// arclength, or any other increasing parameter). Zero-length edges are skipped.
    pub(crate) fn new(points: &[DVec2], positions: &[f64]) -> Self {
        debug_assert_eq!(points.len(), positions.len());
        let mut summary = TurningSummary::default();
        let mut previous: Option<DVec2> = None;
        for i in 1..points.len().min(positions.len()) {
            let edge = points[i] - points[i - 1];
            if edge.length() < MIN_EDGE {
                continue;
            }
            let angle = match (previous, summary.angles.last()) {
                (Some(before), Some(&t)) => t + before.perp_dot(edge).atan2(before.dot(edge)),
                _ => edge.y.atan2(edge.x),
            };
            if summary.breaks.is_empty() {
                summary.breaks.push(positions[i - 1]);
            } else if let Some(last) = summary.breaks.last_mut() {
                // A skipped edge before this one: start this edge where the last one ended.
                *last = positions[i - 1];
            }
            summary.breaks.push(positions[i]);
            summary.angles.push(angle);
            previous = Some(edge);
        }
        summary
    }

    /// The same summary with positions mapped affinely so that they span `[0, 1]`.
    pub(crate) fn normalized(mut self) -> Self {
        if let (Some(&first), Some(&last)) = (self.breaks.first(), self.breaks.last()) {
            let span = last - first;
            if span > 0.0 {
                self.breaks
                    .iter_mut()
                    .for_each(|b| *b = (*b - first) / span);
            }
        }
        self
    }

    /// True when no edge had a direction.
    pub(crate) fn is_empty(&self) -> bool {
        self.angles.is_empty()
    }

    /// The variance of `self(lo + u (hi − lo)) − pattern(u)` over `u ∈ [0, 1]`, where
    /// `pattern` is [`normalized`](Self::normalized). Beyond its ends `self` is extended by
    /// its first and last directions. Runs in time linear in the edges involved.
    pub(crate) fn misfit(&self, lo: f64, hi: f64, pattern: &TurningSummary) -> f64 {
        let span = hi - lo;
        if self.is_empty() || pattern.is_empty() || span <= 0.0 {
            return 0.0;
        }
        let (n_self, n_pattern) = (self.angles.len(), pattern.angles.len());
        let mut i = self
            .breaks
            .partition_point(|&b| b <= lo)
            .saturating_sub(1)
            .min(n_self - 1);
        let mut j = 0;
        let (mut u, mut sum, mut sum_sq) = (0.0, 0.0, 0.0);
        while u < 1.0 {
            let self_end = if i + 1 < n_self {
                (self.breaks[i + 1] - lo) / span
            } else {
                1.0
            };
            let pattern_end = if j + 1 < n_pattern {
                pattern.breaks[j + 1]
            } else {
                1.0
            };
            let next = self_end.min(pattern_end).clamp(u, 1.0);
            let difference = self.angles[i] - pattern.angles[j];
            sum += difference * (next - u);
            sum_sq += difference * difference * (next - u);
            if self_end <= next && i + 1 < n_self {
                i += 1;
            }
            if pattern_end <= next && j + 1 < n_pattern {
                j += 1;
            }
            u = next;
        }
        (sum_sq - sum * sum).max(0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::polyline::cumulative_lengths;
    use std::f64::consts::PI;

    fn summary(points: &[DVec2]) -> TurningSummary {
        TurningSummary::new(points, &cumulative_lengths(points))
    }

    fn arc(center: DVec2, radius: f64, from: f64, to: f64, n: usize) -> Vec<DVec2> {
        (0..=n)
            .map(|k| {
                let t = from + (to - from) * k as f64 / n as f64;
                center + radius * DVec2::from_angle(t)
            })
            .collect()
    }

    #[test]
    fn angles_unwrap_across_pi() {
        // A full circle turns by 2π; the summary keeps climbing instead of wrapping.
        let circle = arc(DVec2::ZERO, 1.0, 0.0, 2.0 * PI, 64);
        let s = summary(&circle);
        let turn = s.angles[s.angles.len() - 1] - s.angles[0];
        assert!((turn - 2.0 * PI * 63.0 / 64.0).abs() < 1e-9, "{turn}");
    }

    #[test]
    fn misfit_ignores_rotation_translation_and_scale() {
        let shape = arc(DVec2::ZERO, 50.0, 0.0, 2.0, 40);
        let moved: Vec<DVec2> = shape
            .iter()
            .map(|&p| DVec2::new(300.0, -20.0) + 3.0 * DVec2::from_angle(1.1).rotate(p))
            .collect();
        let pattern = summary(&moved).normalized();
        let cumulative = cumulative_lengths(&shape);
        let length = cumulative[cumulative.len() - 1];
        assert!(summary(&shape).misfit(0.0, length, &pattern) < 1e-20);
    }

    #[test]
    fn straight_against_half_circle_has_the_uniform_variance() {
        // Θ constant, Ψ linear over an angle range of π: variance π²/12 in the limit.
        let line = [DVec2::ZERO, DVec2::new(100.0, 0.0)];
        let half = arc(DVec2::ZERO, 10.0, 0.0, PI, 2000);
        let misfit = summary(&line).misfit(0.0, 100.0, &summary(&half).normalized());
        assert!((misfit - PI * PI / 12.0).abs() < 1e-5, "{misfit}");
    }

    #[test]
    fn misfit_looks_only_inside_the_window() {
        // A straight run, then a right angle: a straight pattern fits the run exactly and
        // fits a window straddling the corner by the variance of a two-valued step.
        let polyline = [
            DVec2::ZERO,
            DVec2::new(100.0, 0.0),
            DVec2::new(100.0, 100.0),
        ];
        let theta = summary(&polyline);
        let straight = summary(&[DVec2::ZERO, DVec2::X]).normalized();
        assert!(theta.misfit(10.0, 90.0, &straight) < 1e-20);
        // Half the window at 0, half at π/2: variance (π/4)².
        let misfit = theta.misfit(50.0, 150.0, &straight);
        assert!((misfit - (PI / 4.0).powi(2)).abs() < 1e-12, "{misfit}");
    }

    #[test]
    fn zero_length_edges_are_skipped() {
        let points = [DVec2::ZERO, DVec2::X, DVec2::X, DVec2::new(1.0, 1.0)];
        let s = summary(&points);
        assert_eq!(s.angles.len(), 2);
        assert_eq!(s.breaks, vec![0.0, 1.0, 2.0]);
        assert!((s.angles[1] - PI / 2.0).abs() < 1e-12);
    }
}

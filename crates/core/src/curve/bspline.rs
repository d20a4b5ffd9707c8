//! Clamped cubic B-splines in the plane: the coarse shape of a curve that the user edits by
//! a few control points (Zhou et al. 2005, §4.1; the volumetric technique fits them by least
//! squares), with knots the user can add (Boehm's insertion keeps the shape exactly, so
//! adding a knot never moves the curve, it only gives another control point).

use glam::DVec2;

/// The fewest control points a cubic needs.
pub const MIN_CONTROLS: usize = 4;

/// A clamped cubic B-spline over `[0, 1]`: it starts at its first control point and ends at
/// its last.
#[derive(Clone, Debug, PartialEq)]
pub struct BSpline {
    /// The interior knots, increasing, strictly inside `(0, 1)`; the end knots (0 and 1,
    /// four times each) are implied.
    pub knots: Vec<f64>,
    /// `knots.len() + 4` control points.
    pub controls: Vec<DVec2>,
}

/// The uniform interior knots of a spline with `controls` control points.
pub fn uniform_knots(controls: usize) -> Vec<f64> {
    let spans = controls.max(MIN_CONTROLS) - 3;
    (1..spans).map(|k| k as f64 / spans as f64).collect()
}

/// The whole knot vector of a clamped cubic with these interior knots.
fn full_knots(interior: &[f64]) -> Vec<f64> {
    let mut knots = vec![0.0; 4];
    knots.extend_from_slice(interior);
    knots.extend([1.0; 4]);
    knots
}

/// The four control points a spline with these interior knots takes its point at `t` from,
/// by the index of the first, and their weights: what a fit of the control points solves
/// for.
pub fn weights_at(knots: &[f64], t: f64) -> (usize, [f64; 4]) {
    let (span, weights) = basis(&full_knots(knots), t);
    (span - 3, weights)
}

/// The index `k` of the knot span `[u_k, u_{k+1})` holding `t` (the last span holds 1), and
/// the four basis functions that do not vanish there, for control points `k − 3..=k`
/// (Cox–de Boor, as The NURBS Book's A2.2).
fn basis(knots: &[f64], t: f64) -> (usize, [f64; 4]) {
    let last = knots.len() - 5;
    let t = t.clamp(0.0, 1.0);
    let span = (3..=last)
        .rev()
        .find(|&k| knots[k] <= t)
        .unwrap_or(3)
        .min(last);
    let mut n = [1.0, 0.0, 0.0, 0.0];
    let mut left = [0.0; 4];
    let mut right = [0.0; 4];
    for j in 1..=3 {
        left[j] = t - knots[span + 1 - j];
        right[j] = knots[span + j] - t;
        let mut saved = 0.0;
        for r in 0..j {
            let denominator = right[r + 1] + left[j - r];
            let term = if denominator > 0.0 {
                n[r] / denominator
            } else {
                0.0
            };
            n[r] = saved + right[r + 1] * term;
            saved = left[j - r] * term;
        }
        n[j] = saved;
    }
    (span, n)
}

impl BSpline {
    /// The point at parameter `t` in `[0, 1]`.
    pub fn at(&self, t: f64) -> DVec2 {
        let (span, weights) = basis(&full_knots(&self.knots), t);
        (weights.iter().enumerate()).fold(DVec2::ZERO, |sum, (r, &w)| {
            sum + self.controls[span - 3 + r] * w
        })
    }

    /// The direction of travel at `t` (a central difference; the spline is C² between
    /// distinct knots).
    pub fn direction(&self, t: f64) -> DVec2 {
        const H: f64 = 1e-4;
        let (a, b) = ((t - H).max(0.0), (t + H).min(1.0));
        self.at(b) - self.at(a)
    }

    /// The same curve with one more knot at `t` (Boehm's insertion): one more control
    /// point, the shape unchanged. A `t` outside `(0, 1)` or on a knot already there adds
    /// nothing.
    pub fn with_knot(&self, t: f64) -> BSpline {
        let exists = self.knots.iter().any(|&u| (u - t).abs() < 1e-9);
        if !(t > 0.0 && t < 1.0) || exists {
            return self.clone();
        }
        let full = full_knots(&self.knots);
        let (span, _) = basis(&full, t);
        let p = &self.controls;
        let mut controls = Vec::with_capacity(p.len() + 1);
        controls.extend_from_slice(&p[..=span - 3]);
        for i in span - 2..=span {
            let a = (t - full[i]) / (full[i + 3] - full[i]);
            controls.push(p[i - 1] * (1.0 - a) + p[i] * a);
        }
        controls.extend_from_slice(&p[span..]);
        let mut knots = self.knots.clone();
        knots.insert(span - 3, t);
        BSpline { knots, controls }
    }
}

/// Whether `knots` can be a spline's interior knots: increasing, strictly inside `(0, 1)`.
pub fn valid_knots(knots: &[f64]) -> bool {
    knots.iter().all(|&u| u > 0.0 && u < 1.0) && knots.windows(2).all(|w| w[0] < w[1])
}

/// `knots` with one more at the midpoint of the longest knot span: where a knot adds the
/// most freedom.
pub fn with_widest_span_split(knots: &[f64]) -> Vec<f64> {
    let full = full_knots(knots);
    let (mut widest, mut middle) = (0.0, 0.5);
    for w in full.windows(2) {
        if w[1] - w[0] > widest {
            (widest, middle) = (w[1] - w[0], 0.5 * (w[0] + w[1]));
        }
    }
    let mut more = knots.to_vec();
    more.push(middle);
    more.sort_by(f64::total_cmp);
    more
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_weights_are_a_partition_of_unity_over_four_control_points() {
        let knots = [0.2, 0.5, 0.55, 0.9];
        assert_eq!(weights_at(&knots, 0.0).0, 0);
        assert_eq!(weights_at(&knots, 1.0).0, knots.len());
        assert_eq!(weights_at(&knots, 0.52).0, 2);
    }

    #[test]
    fn the_basis_is_a_partition_of_unity() {
        let knots = full_knots(&[0.2, 0.5, 0.55, 0.9]);
        for k in 0..=100 {
            let (_, n) = basis(&knots, k as f64 / 100.0);
            assert!((n.iter().sum::<f64>() - 1.0).abs() < 1e-12, "at {k}");
            assert!(n.iter().all(|&w| w >= -1e-15));
        }
    }

    #[test]
    fn a_knot_inserted_keeps_the_shape_and_adds_a_control_point() {
        let controls = [(0.0, 0.0), (1.0, 2.0), (2.0, -1.0), (3.0, 0.5), (4.0, 0.0)];
        let spline = BSpline {
            knots: uniform_knots(5),
            controls: controls.iter().map(|&(x, y)| DVec2::new(x, y)).collect(),
        };
        let split = with_widest_span_split(&spline.knots);
        assert!(valid_knots(&split) && split.len() == spline.knots.len() + 1);
        let middle = split.iter().find(|u| !spline.knots.contains(u)).copied();
        assert_eq!(middle, Some(0.25), "the first of the widest spans, halved");
        let finer = spline.with_knot(0.25).with_knot(0.1);
        assert_eq!(finer.controls.len(), 7);
        assert_eq!(finer.knots.len(), 3);
        for k in 0..=200 {
            let t = k as f64 / 200.0;
            assert!(finer.at(t).distance(spline.at(t)) < 1e-12, "at {t}");
        }
        assert_eq!(finer.with_knot(0.1), finer, "a knot already there");
        assert_eq!(finer.with_knot(1.0), finer, "an end");
    }
}

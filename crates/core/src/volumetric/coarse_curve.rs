//! Editing a planar curve by its coarse shape while keeping its detail (Zhou et al. 2005,
//! §4.1): the curve is fitted by a least-squares [`BSpline`] ([`fit_spline`]); the user moves
//! its control points; the detail comes back through the curve's Laplacian coordinates.
//!
//! Each point keeps its offset from the spline and its Laplacian coordinate (its offset from
//! its neighbours' mean), both turned by the turn of the spline's direction where it sits.
//! The new curve is the least-squares compromise between the two (ends on the spline's
//! ends): an unmoved spline gives the curve back exactly, and a moved one carries the
//! wiggles along rather than flattening them or dragging them straight.

use glam::{DVec2, DVec3};

use crate::curve::bspline::{BSpline, weights_at};
use crate::curve::polyline::cumulative_lengths;
use crate::solve::{SolveError, Triplets, solve_least_squares};

/// How strongly the fit keeps each control point near the mean of its neighbours, next to
/// the data: enough that a knot span no sample falls in still has a defined control point,
/// too little to bend the fit.
const REGULARIZATION: f64 = 1e-3;

/// A curve and its coarse spline.
#[derive(Clone, Debug)]
pub struct CoarseCurve {
    points: Vec<DVec2>,
    /// Each point's parameter on the spline: its share of the curve's length.
    params: Vec<f64>,
    spline: BSpline,
}

/// The least-squares spline through `points` at parameters `params` (increasing, from 0 to
/// 1) with these interior knots: its ends are the first and last points.
///
/// Errors: [`SolveError`] when the fit cannot be solved (non-finite points).
pub fn fit_spline(points: &[DVec2], params: &[f64], knots: &[f64]) -> Result<BSpline, SolveError> {
    let n = knots.len() + 4;
    let rows = points.len() + n - 2;
    let mut a = Triplets::with_capacity(rows, n, 4 * points.len() + 3 * n);
    let mut b = Vec::with_capacity(rows);
    for (i, (&p, &t)) in points.iter().zip(params).enumerate() {
        let (first, weights) = weights_at(knots, t);
        for (r, &w) in weights.iter().enumerate() {
            a.push(i, first + r, w);
        }
        b.push(p.extend(0.0));
    }
    for j in 1..n - 1 {
        let row = points.len() + j - 1;
        a.push(row, j - 1, -0.5 * REGULARIZATION);
        a.push(row, j, REGULARIZATION);
        a.push(row, j + 1, -0.5 * REGULARIZATION);
        b.push(DVec3::ZERO);
    }
    let mut fixed = vec![false; n];
    let mut ends = vec![DVec3::ZERO; n];
    (fixed[0], fixed[n - 1]) = (true, true);
    ends[0] = points[0].extend(0.0);
    ends[n - 1] = points[points.len() - 1].extend(0.0);
    let solved = solve_least_squares(&a.build(), &b, &fixed, &ends)?;
    Ok(BSpline {
        knots: knots.to_vec(),
        controls: solved.iter().map(|c| c.truncate()).collect(),
    })
}

/// The turn, as a unit complex number, from direction `from` to `to`.
fn turn(from: DVec2, to: DVec2) -> DVec2 {
    match (from.try_normalize(), to.try_normalize()) {
        (Some(a), Some(b)) => DVec2::new(a.dot(b), a.perp_dot(b)),
        _ => DVec2::X,
    }
}

impl CoarseCurve {
    /// `points` (at least two) fitted with these interior knots.
    ///
    /// Errors: the fit's.
    pub fn fit(points: &[DVec2], knots: &[f64]) -> Result<CoarseCurve, SolveError> {
        let along = cumulative_lengths(points);
        let total = along[along.len() - 1].max(f64::MIN_POSITIVE);
        let params: Vec<f64> = along.iter().map(|s| s / total).collect();
        let spline = fit_spline(points, &params, knots)?;
        Ok(CoarseCurve {
            points: points.to_vec(),
            params,
            spline,
        })
    }

    /// The fitted spline.
    pub fn spline(&self) -> &BSpline {
        &self.spline
    }

    /// The curve with the spline's control points moved to `controls` (as many as the
    /// spline has), its detail kept; see the module docs.
    ///
    /// Errors: the solve's, and a wrong number of control points.
    pub fn reshape(&self, controls: &[DVec2]) -> Result<Vec<DVec2>, SolveError> {
        crate::solve::check_len("control points", self.spline.controls.len(), controls.len())?;
        let moved = BSpline {
            knots: self.spline.knots.clone(),
            controls: controls.to_vec(),
        };
        let n = self.points.len();
        let turns: Vec<DVec2> = (self.params.iter())
            .map(|&t| turn(self.spline.direction(t), moved.direction(t)))
            .collect();
        let rotate = |z: DVec2, v: DVec2| z.rotate(v);
        let mut a = Triplets::with_capacity(n + n.saturating_sub(2), n, 4 * n);
        let mut b = Vec::with_capacity(2 * n);
        for (i, ((&p, &t), &z)) in self.points.iter().zip(&self.params).zip(&turns).enumerate() {
            a.push(i, i, 1.0);
            b.push((moved.at(t) + rotate(z, p - self.spline.at(t))).extend(0.0));
        }
        for (i, (w, &z)) in self.points.windows(3).zip(&turns[1..]).enumerate() {
            let row = n + i;
            a.push(row, i, -0.5);
            a.push(row, i + 1, 1.0);
            a.push(row, i + 2, -0.5);
            b.push(rotate(z, w[1] - 0.5 * (w[0] + w[2])).extend(0.0));
        }
        let mut fixed = vec![false; n];
        let mut ends = vec![DVec3::ZERO; n];
        (fixed[0], fixed[n - 1]) = (true, true);
        ends[0] = moved.at(0.0).extend(0.0);
        ends[n - 1] = moved.at(1.0).extend(0.0);
        let solved = solve_least_squares(&a.build(), &b, &fixed, &ends)?;
        Ok(solved.iter().map(|p| p.truncate()).collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::bspline::uniform_knots;

    #[test]
    fn a_cubic_is_fitted_exactly_and_its_ends_interpolated() {
        // A cubic polynomial curve lies in the spline space whatever the knots.
        let cubic = |t: f64| DVec2::new(t, 2.0 * t * t * t - t * t + 0.5 * t);
        let params: Vec<f64> = (0..50).map(|i| i as f64 / 49.0).collect();
        let points: Vec<DVec2> = params.iter().map(|&t| cubic(t)).collect();
        let spline = fit_spline(&points, &params, &uniform_knots(6)).unwrap();
        assert_eq!(spline.controls.len(), 6);
        assert_eq!(spline.controls[0], points[0]);
        assert_eq!(spline.controls[5], points[49]);
        for &t in &[0.0, 0.13, 0.5, 0.77, 1.0] {
            assert!(spline.at(t).distance(cubic(t)) < 1e-3, "at {t}");
        }
    }

    #[test]
    fn a_fit_is_close_to_the_arc_it_approximates() {
        let params: Vec<f64> = (0..80).map(|i| i as f64 / 79.0).collect();
        let arc: Vec<DVec2> = (params.iter())
            .map(|&t| DVec2::new((2.0 * t).cos(), (2.0 * t).sin()))
            .collect();
        let spline = fit_spline(&arc, &params, &uniform_knots(5)).unwrap();
        for (&p, &t) in arc.iter().zip(&params) {
            assert!(spline.at(t).distance(p) < 5e-3);
        }
    }

    /// A straight line with a fine zig-zag on it.
    fn wiggly() -> Vec<DVec2> {
        (0..=100)
            .map(|i| {
                let x = i as f64 / 100.0 * 4.0;
                DVec2::new(x, 0.05 * (i as f64 * 0.9).sin())
            })
            .collect()
    }

    #[test]
    fn unmoved_controls_give_the_curve_back() {
        let points = wiggly();
        let curve = CoarseCurve::fit(&points, &uniform_knots(6)).unwrap();
        let same = curve.reshape(&curve.spline().controls).unwrap();
        for (p, q) in points.iter().zip(&same) {
            assert!(p.distance(*q) < 1e-9, "{p} -> {q}");
        }
    }

    #[test]
    fn a_turned_spline_turns_the_curve_with_its_wiggles() {
        let points = wiggly();
        let curve = CoarseCurve::fit(&points, &uniform_knots(5)).unwrap();
        // Every control point turned by 90° about the first end: the whole curve turns.
        let start = points[0];
        let turned: Vec<DVec2> = (curve.spline().controls.iter())
            .map(|&c| start + (c - start).perp())
            .collect();
        let moved = curve.reshape(&turned).unwrap();
        for (p, q) in points.iter().zip(&moved) {
            let expected = start + (*p - start).perp();
            assert!(q.distance(expected) < 1e-6, "{q} against {expected}");
        }
        // The last control point lifted: the end rises, the wiggle's amplitude stays.
        let mut lifted = curve.spline().controls.clone();
        let last = lifted.len() - 1;
        lifted[last].y += 1.0;
        let bent = curve.reshape(&lifted).unwrap();
        assert!(bent[100].distance(points[100] + DVec2::Y) < 1e-9 && bent[0] == points[0]);
        let wiggle = |c: &[DVec2], i: usize| (c[i] - 0.5 * (c[i - 1] + c[i + 1])).length();
        for i in [20, 50, 80] {
            let (before, after) = (wiggle(&points, i), wiggle(&bent, i));
            assert!(
                (after / before - 1.0).abs() < 0.15,
                "at {i}: {before} -> {after}"
            );
        }
    }
}

//! Editing a planar curve by its coarse shape while keeping its detail (Zhou et al. 2005,
//! §4.1): the curve is fitted by a least-squares [`BSpline`]; the user moves its control
//! points; the detail comes back through the curve's Laplacian coordinates.
//!
//! Each point keeps its offset from the spline and its Laplacian coordinate (its offset from
//! its neighbours' mean), both turned by the turn of the spline's direction where it sits.
//! The new curve is the least-squares compromise between the two (ends on the spline's
//! ends): an unmoved spline gives the curve back exactly, and a moved one carries the
//! wiggles along rather than flattening them or dragging them straight.

use glam::{DVec2, DVec3};

use super::bspline::BSpline;
use super::polyline::cumulative_lengths;
use crate::solve::{SolveError, Triplets, solve_least_squares};

/// A curve and its coarse spline.
#[derive(Clone, Debug)]
pub struct CoarseCurve {
    points: Vec<DVec2>,
    /// Each point's parameter on the spline: its share of the curve's length.
    params: Vec<f64>,
    spline: BSpline,
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
        let spline = BSpline::fit(points, &params, knots)?;
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

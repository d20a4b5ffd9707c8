//! A curve handle as a document keeps it: its control points, and the twist and scale set
//! at each (Blanco §4, §5.3).

use glam::DVec3;

use super::curve::Spline;
use super::error::SkeletonError;
use super::frames::Shaping;
use crate::model::HandleCurve;

/// A change to one control point: a move, a twist, a scale, each spread over `spread`
/// control points on each side, fading linearly.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PointEdit {
    /// The control point.
    pub point: usize,
    /// Moves it (and only it).
    pub translate: Option<DVec3>,
    /// Adds this twist, in radians.
    pub twist: Option<f64>,
    /// Multiplies its scales by these.
    pub scale: Option<[f64; 2]>,
    /// How many neighbours on each side a twist or scale reaches.
    pub spread: usize,
}

/// A handle's geometry: its spline, its frames' shaping, its edits. The curve itself is plain
/// data of the document ([`crate::model`]).
impl HandleCurve {
    /// A curve through `points`, untwisted and unscaled.
    pub fn new(points: Vec<DVec3>, is_rigid: bool) -> Self {
        let n = points.len();
        HandleCurve {
            points,
            twist: vec![0.0; n],
            scale: vec![[1.0, 1.0]; n],
            is_rigid,
        }
    }

    /// The spline through the control points.
    pub fn spline(&self) -> Spline<'_> {
        Spline::new(&self.points, self.is_rigid)
    }

    /// Its twist and scales.
    pub fn shaping(&self) -> Shaping<'_> {
        Shaping {
            twist: &self.twist,
            scale: &self.scale,
        }
    }

    /// The curve after `edit`.
    ///
    /// Errors: a point that does not exist; an amount that is not finite, a scale ≤ 0.
    pub fn edited(&self, edit: &PointEdit) -> Result<HandleCurve, SkeletonError> {
        let n = self.points.len();
        if edit.point >= n {
            return Err(SkeletonError::NoSuchPoint(edit.point));
        }
        let finite = edit.translate.is_none_or(|t| t.is_finite())
            && edit.twist.is_none_or(f64::is_finite)
            && edit
                .scale
                .is_none_or(|s| s.iter().all(|&s| s.is_finite() && s > 0.0));
        if !finite {
            return Err(SkeletonError::BadAmount);
        }
        let mut next = self.clone();
        if let Some(t) = edit.translate {
            next.points[edit.point] += t;
        }
        for (k, fade) in spread(edit.point, edit.spread, n) {
            if let Some(angle) = edit.twist {
                next.twist[k] += fade * angle;
            }
            if let Some([sv, sw]) = edit.scale {
                let [a, b] = &mut next.scale[k];
                *a *= sv.powf(fade);
                *b *= sw.powf(fade);
            }
        }
        Ok(next)
    }
}

/// The control points a twist or scale at `point` reaches and their share: 1 at the point,
/// falling linearly to 0 one step past `spread` neighbours.
fn spread(point: usize, spread: usize, n: usize) -> impl Iterator<Item = (usize, f64)> {
    let from = point.saturating_sub(spread);
    let to = (point + spread).min(n - 1);
    (from..=to).map(move |k| (k, 1.0 - k.abs_diff(point) as f64 / (spread + 1) as f64))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_twist_fades_over_its_spread_and_bad_amounts_are_refused() {
        let curve = HandleCurve::new(
            vec![DVec3::ZERO, DVec3::X, DVec3::X * 2.0, DVec3::X * 3.0],
            false,
        );
        let edit = PointEdit {
            point: 1,
            twist: Some(1.0),
            spread: 1,
            ..PointEdit::default()
        };
        let twisted = curve.edited(&edit).unwrap();
        assert_eq!(twisted.twist, vec![0.5, 1.0, 0.5, 0.0]);
        let bad = PointEdit {
            point: 0,
            scale: Some([0.0, 1.0]),
            ..PointEdit::default()
        };
        assert_eq!(curve.edited(&bad), Err(SkeletonError::BadAmount));
        let missing = PointEdit {
            point: 9,
            ..PointEdit::default()
        };
        assert_eq!(curve.edited(&missing), Err(SkeletonError::NoSuchPoint(9)));
    }
}

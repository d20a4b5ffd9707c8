//! A silhouette polyline prepared for matching: arclength, closure, positions and
//! fractional indices by arclength, and its turning-angle summary.
//!
//! A closed silhouette (last point equal to the first) is unrolled to twice its length, so
//! a handle may cross the seam: arclength `s` and `s + L` are the same place, and index
//! `i + (n − 1)` is point `i`.

use glam::DVec2;

use super::turning::TurningSummary;
use crate::curve::polyline::{
    cumulative_lengths, douglas_peucker, index_at, point_at, point_at_index,
};

/// A silhouette whose last point lies this close to its first (px) is closed.
pub const CLOSED_TOLERANCE_PX: f64 = 1e-6;

/// One silhouette, read-only, with its arclength table.
pub(crate) struct Track<'a> {
    points: &'a [DVec2],
    cumulative: Vec<f64>,
    length: f64,
    is_closed: bool,
}

impl<'a> Track<'a> {
    /// `None` for fewer than two points or zero length.
    pub(crate) fn new(points: &'a [DVec2]) -> Option<Self> {
        let (first, last) = (*points.first()?, *points.last()?);
        let cumulative = cumulative_lengths(points);
        let length = *cumulative.last()?;
        if points.len() < 2 || length <= 0.0 {
            return None;
        }
        Some(Track {
            points,
            cumulative,
            length,
            is_closed: points.len() >= 4 && first.distance(last) <= CLOSED_TOLERANCE_PX,
        })
    }

    pub(crate) fn length(&self) -> f64 {
        self.length
    }

    pub(crate) fn is_closed(&self) -> bool {
        self.is_closed
    }

    /// Arclength `s` brought into `[0, L)` on a closed track; clamped on an open one.
    fn wrap(&self, s: f64) -> f64 {
        if self.is_closed {
            s.rem_euclid(self.length)
        } else {
            s.clamp(0.0, self.length)
        }
    }

    /// The point at arclength `s`.
    pub(crate) fn position(&self, s: f64) -> DVec2 {
        point_at(self.points, &self.cumulative, self.wrap(s))
    }

    /// The fractional point index at arclength `s`; on a closed track, `s` in `[L, 2L)`
    /// gives indices past `n − 1`.
    pub(crate) fn index(&self, s: f64) -> f64 {
        if !self.is_closed {
            return index_at(&self.cumulative, self.wrap(s));
        }
        let laps = (s / self.length).floor();
        let loop_points = (self.points.len() - 1) as f64;
        laps * loop_points + index_at(&self.cumulative, self.wrap(s))
    }

    /// Arclength positions every `spacing` px (the whole loop once when closed; both ends
    /// when open) with their points.
    pub(crate) fn samples(&self, spacing: f64) -> Vec<(f64, DVec2)> {
        let steps = ((self.length / spacing).ceil() as usize).max(1);
        let step = self.length / steps as f64;
        let count = if self.is_closed { steps } else { steps + 1 };
        (0..count)
            .map(|k| {
                let s = k as f64 * step;
                (s, self.position(s))
            })
            .collect()
    }

    /// The turning-angle summary of the Douglas–Peucker delegate at `tolerance` px, over
    /// this track's full-resolution arclength (twice round when closed).
    pub(crate) fn turning_summary(&self, tolerance: f64) -> TurningSummary {
        if !self.is_closed {
            let kept = douglas_peucker(self.points, tolerance);
            let points: Vec<DVec2> = kept.iter().map(|&i| self.points[i]).collect();
            let positions: Vec<f64> = kept.iter().map(|&i| self.cumulative[i]).collect();
            return TurningSummary::new(&points, &positions);
        }
        let unrolled: Vec<DVec2> = self
            .points
            .iter()
            .chain(&self.points[1..])
            .copied()
            .collect();
        let positions: Vec<f64> = self
            .cumulative
            .iter()
            .copied()
            .chain(self.cumulative[1..].iter().map(|s| s + self.length))
            .collect();
        let kept = douglas_peucker(&unrolled, tolerance);
        let points: Vec<DVec2> = kept.iter().map(|&i| unrolled[i]).collect();
        let positions: Vec<f64> = kept.iter().map(|&i| positions[i]).collect();
        TurningSummary::new(&points, &positions)
    }
}

/// The handle between fractional indices `start` and `end` of `silhouette`, in that order
/// (decreasing indices when `start > end`), as `(index, point)` pairs: the two ends and
/// every silhouette point strictly between them.
///
/// On a closed silhouette (last point equal to the first) indices past `n − 1` wrap, and
/// each returned index is brought back into `[0, n − 1]`, ready for interpolating per-point
/// data such as depth.
pub fn handle_points(silhouette: &[DVec2], start: f64, end: f64) -> Vec<(f64, DVec2)> {
    let n = silhouette.len();
    if n < 2 {
        return silhouette.iter().map(|&p| (0.0, p)).collect();
    }
    let is_closed = n >= 4 && silhouette[0].distance(silhouette[n - 1]) <= CLOSED_TOLERANCE_PX;
    let loop_points = (n - 1) as f64;
    let wrap = |t: f64| {
        if is_closed {
            t.rem_euclid(loop_points)
        } else {
            t.clamp(0.0, loop_points)
        }
    };
    let at = |t: f64| {
        let t = wrap(t);
        (t, point_at_index(silhouette, t))
    };
    let mut out = vec![at(start)];
    if start <= end {
        let mut k = start.floor() + 1.0;
        while k < end {
            out.push(at(k));
            k += 1.0;
        }
    } else {
        let mut k = end.floor() + 1.0;
        let mut between = Vec::new();
        while k < start {
            between.push(at(k));
            k += 1.0;
        }
        out.extend(between.into_iter().rev());
    }
    out.push(at(end));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> Vec<DVec2> {
        // A closed 10 px square: 4 sides, 5 points.
        vec![
            DVec2::ZERO,
            DVec2::new(10.0, 0.0),
            DVec2::new(10.0, 10.0),
            DVec2::new(0.0, 10.0),
            DVec2::ZERO,
        ]
    }

    #[test]
    fn closed_tracks_unroll() {
        let points = square();
        let track = Track::new(&points).expect("square");
        assert!(track.is_closed() && track.length() == 40.0);
        assert_eq!(track.position(45.0), DVec2::new(5.0, 0.0));
        assert_eq!(track.position(-5.0), DVec2::new(0.0, 5.0));
        assert_eq!(track.index(35.0), 3.5);
        assert_eq!(track.index(45.0), 4.5);
        assert_eq!(track.samples(10.0).len(), 4);
        let open = Track::new(&points[..4]).expect("open");
        assert!(!open.is_closed());
        assert_eq!(open.samples(10.0).len(), 4);
        assert_eq!(open.index(45.0), 3.0);
    }

    #[test]
    fn handle_points_follow_the_index_order_and_wrap() {
        let points = square();
        let forward = handle_points(&points, 3.5, 4.5);
        let indices: Vec<f64> = forward.iter().map(|h| h.0).collect();
        assert_eq!(indices, vec![3.5, 0.0, 0.5]);
        assert_eq!(forward[2].1, DVec2::new(5.0, 0.0));
        let backward = handle_points(&points, 2.5, 0.5);
        let indices: Vec<f64> = backward.iter().map(|h| h.0).collect();
        assert_eq!(indices, vec![2.5, 2.0, 1.0, 0.5]);
    }
}

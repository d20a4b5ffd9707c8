//! Even arclength resampling of a polyline or polygon.

use glam::DVec2;

/// A point of a polyline that [`resample`] can place between two others: a bare position,
/// or a position with data that varies along the line (a stroke's pressure).
pub trait PolylinePoint: Copy {
    /// Where the point lies.
    fn position(&self) -> DVec2;
    /// The point a fraction `t` (in `[0, 1]`) of the way from `self` to `other`.
    fn interpolate(self, other: Self, t: f64) -> Self;
}

impl PolylinePoint for DVec2 {
    fn position(&self) -> DVec2 {
        *self
    }

    fn interpolate(self, other: Self, t: f64) -> Self {
        self.lerp(other, t)
    }
}

/// Resamples a polyline at an even arc-length step close to `spacing`, interpolating what
/// the points carry with [`PolylinePoint::interpolate`].
///
/// The step is `L / n` with `n = max(1, round(L / spacing))` for arc length `L`, so the
/// first and last points are kept exactly and every step is equal. Coincident input points
/// are harmless. A polyline of zero length becomes its first point; a non-positive or
/// non-finite `spacing` returns the input unchanged. One pass over the input, so it can
/// run on a live stroke every frame.
pub fn resample<P: PolylinePoint>(points: &[P], spacing: f64) -> Vec<P> {
    let (Some(&first), Some(&last)) = (points.first(), points.last()) else {
        return Vec::new();
    };
    if !(spacing.is_finite() && spacing > 0.0) {
        return points.to_vec();
    }
    let length = super::length(points.iter().map(P::position));
    if length <= 0.0 {
        return vec![first];
    }
    let segments = ((length / spacing).round() as usize).max(1);
    let step = length / segments as f64;

    let mut out = Vec::with_capacity(segments + 1);
    out.push(first);
    // Walk the input once; `start` is the arc length at the start of segment `i`.
    let mut i = 0;
    let mut start = 0.0;
    for k in 1..segments {
        let wanted = k as f64 * step;
        loop {
            let (a, b) = (points[i], points[i + 1]);
            let segment_length = a.position().distance(b.position());
            if start + segment_length >= wanted || i + 2 == points.len() {
                let t = if segment_length > 0.0 {
                    ((wanted - start) / segment_length).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                out.push(a.interpolate(b, t));
                break;
            }
            start += segment_length;
            i += 1;
        }
    }
    out.push(last);
    out
}

/// Resamples a closed polygon (the first point not repeated at the end) at an even step
/// close to `spacing`, closing edge included; the first point is kept.
pub fn resample_closed<P: PolylinePoint>(points: &[P], spacing: f64) -> Vec<P> {
    let mut open = points.to_vec();
    if let Some(&first) = open.first() {
        open.push(first);
    }
    let mut even = resample(&open, spacing);
    even.pop();
    even
}

#[cfg(test)]
mod tests {
    use super::*;

    fn assert_points(got: &[DVec2], expected: &[(f64, f64)]) {
        assert_eq!(got.len(), expected.len(), "{got:?}");
        for (p, &(x, y)) in got.iter().zip(expected) {
            assert!(p.distance(DVec2::new(x, y)) < 1e-12, "{p} vs ({x}, {y})");
        }
    }

    #[test]
    fn even_steps_around_a_corner() {
        // An L of length 10 + 10, resampled at 5: the corner is a sample.
        let input = [DVec2::ZERO, DVec2::new(10.0, 0.0), DVec2::new(10.0, 10.0)];
        let out = resample(&input, 5.0);
        let corner = [
            (0.0, 0.0),
            (5.0, 0.0),
            (10.0, 0.0),
            (10.0, 5.0),
            (10.0, 10.0),
        ];
        assert_points(&out, &corner);
    }

    #[test]
    fn uneven_input_comes_out_even() {
        // Steps of 0.5 and 9.5 along x, resampled at 2: 10 / round(5) = 2 exactly.
        let points = [DVec2::ZERO, DVec2::new(0.5, 0.0), DVec2::new(10.0, 0.0)];
        let even = resample(&points, 2.0);
        assert_eq!(even.len(), 6);
        for (k, p) in even.iter().enumerate() {
            assert!((p.x - 2.0 * k as f64).abs() < 1e-12 && p.y == 0.0);
        }
    }

    #[test]
    fn spacing_is_even_and_ends_are_kept() {
        let input: Vec<DVec2> = (0..50)
            .map(|k| {
                let t = k as f64 * 0.1;
                DVec2::new(30.0 * t.cos(), 20.0 * t.sin() + t * t)
            })
            .collect();
        let out = resample(&input, 3.0);
        assert_eq!(out.first(), input.first());
        assert_eq!(out.last(), input.last());
        let length = super::super::length(&input);
        let n = (length / 3.0).round();
        assert_eq!(out.len() as f64, n + 1.0);
        // Chords are at most the arc step, and close to it on this gentle curve.
        for pair in out.windows(2) {
            let chord = pair[0].distance(pair[1]);
            assert!(
                chord <= length / n + 1e-9 && chord > 0.95 * length / n,
                "{chord}"
            );
        }
    }

    #[test]
    fn degenerate_inputs() {
        assert!(resample::<DVec2>(&[], 4.0).is_empty());
        let single = [DVec2::new(1.0, 2.0)];
        assert_eq!(resample(&single, 4.0), single.to_vec());
        assert_eq!(resample(&[single[0]; 2], 4.0), single.to_vec());
        let duplicates = [DVec2::ZERO, DVec2::ZERO, DVec2::new(8.0, 0.0)];
        let out = resample(&duplicates, 4.0);
        assert_eq!(out.len(), 3);
        assert!((out[1] - DVec2::new(4.0, 0.0)).length() < 1e-12);
        assert_eq!(resample(&duplicates, 0.0), duplicates.to_vec());
        assert_eq!(resample(&duplicates, f64::NAN), duplicates.to_vec());
        // Shorter than the spacing: just the ends.
        let short = [DVec2::ZERO, DVec2::X];
        assert_eq!(resample(&short, 4.0), short.to_vec());
    }

    #[test]
    fn a_closed_square_keeps_its_corners() {
        // Perimeter 8 at spacing 1: every corner and every side's midpoint.
        let square = [
            DVec2::ZERO,
            DVec2::new(2.0, 0.0),
            DVec2::new(2.0, 2.0),
            DVec2::new(0.0, 2.0),
        ];
        let even = resample_closed(&square, 1.0);
        let corners_and_midpoints = [
            (0.0, 0.0),
            (1.0, 0.0),
            (2.0, 0.0),
            (2.0, 1.0),
            (2.0, 2.0),
            (1.0, 2.0),
            (0.0, 2.0),
            (0.0, 1.0),
        ];
        assert_points(&even, &corners_and_midpoints);
        assert!(resample_closed::<DVec2>(&[], 1.0).is_empty());
    }
}

//! Even arc-length resampling of a polyline.

use super::point::{StrokePoint, arc_length};

/// Resamples a polyline at an even arc-length step close to `spacing`, interpolating
/// pressure linearly.
///
/// The step is `L / n` with `n = max(1, round(L / spacing))` for arc length `L`, so the
/// first and last points are kept exactly and every step is equal. Coincident input points
/// are harmless. A polyline of zero length becomes its first point; a non-positive or
/// non-finite `spacing` returns the input unchanged.
pub fn resample(points: &[StrokePoint], spacing: f64) -> Vec<StrokePoint> {
    let (Some(&first), Some(&last)) = (points.first(), points.last()) else {
        return Vec::new();
    };
    if !(spacing.is_finite() && spacing > 0.0) {
        return points.to_vec();
    }
    let length = arc_length(points);
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
            let segment_length = points[i].pos.distance(points[i + 1].pos);
            if start + segment_length >= wanted || i + 2 == points.len() {
                let t = if segment_length > 0.0 {
                    ((wanted - start) / segment_length).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                let (a, b) = (points[i], points[i + 1]);
                out.push(StrokePoint {
                    pos: a.pos.lerp(b.pos, t),
                    pressure: a.pressure + (b.pressure - a.pressure) * t,
                });
                break;
            }
            start += segment_length;
            i += 1;
        }
    }
    out.push(last);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    fn point(x: f64, y: f64, pressure: f64) -> StrokePoint {
        StrokePoint::new(DVec2::new(x, y), pressure)
    }

    #[test]
    fn even_steps_around_a_corner() {
        // An L of length 10 + 10, resampled at 5: the corner is a sample.
        let input = [
            point(0.0, 0.0, 0.0),
            point(10.0, 0.0, 0.5),
            point(10.0, 10.0, 1.0),
        ];
        let out = resample(&input, 5.0);
        let expected = [
            point(0.0, 0.0, 0.0),
            point(5.0, 0.0, 0.25),
            point(10.0, 0.0, 0.5),
            point(10.0, 5.0, 0.75),
            point(10.0, 10.0, 1.0),
        ];
        assert_eq!(out.len(), expected.len());
        for (got, want) in out.iter().zip(&expected) {
            assert!((got.pos - want.pos).length() < 1e-12, "{got:?} {want:?}");
            assert!((got.pressure - want.pressure).abs() < 1e-12);
        }
    }

    #[test]
    fn spacing_is_even_and_ends_are_kept() {
        let input: Vec<StrokePoint> = (0..50)
            .map(|k| {
                let t = k as f64 * 0.1;
                point(30.0 * t.cos(), 20.0 * t.sin() + t * t, 0.5)
            })
            .collect();
        let out = resample(&input, 3.0);
        assert_eq!(out.first(), input.first());
        assert_eq!(out.last(), input.last());
        let length = arc_length(&input);
        let n = (length / 3.0).round();
        assert_eq!(out.len() as f64, n + 1.0);
        // Chords are at most the arc step, and close to it on this gentle curve.
        for pair in out.windows(2) {
            let chord = pair[0].pos.distance(pair[1].pos);
            assert!(
                chord <= length / n + 1e-9 && chord > 0.95 * length / n,
                "{chord}"
            );
        }
    }

    #[test]
    fn degenerate_inputs() {
        assert!(resample(&[], 4.0).is_empty());
        let single = [point(1.0, 2.0, 0.5)];
        assert_eq!(resample(&single, 4.0), single.to_vec());
        let same = [point(1.0, 2.0, 0.5), point(1.0, 2.0, 0.7)];
        assert_eq!(resample(&same, 4.0), vec![same[0]]);
        let duplicates = [
            point(0.0, 0.0, 0.5),
            point(0.0, 0.0, 0.5),
            point(8.0, 0.0, 0.5),
        ];
        let out = resample(&duplicates, 4.0);
        assert_eq!(out.len(), 3);
        assert!((out[1].pos - DVec2::new(4.0, 0.0)).length() < 1e-12);
        assert_eq!(resample(&duplicates, 0.0), duplicates.to_vec());
        // Shorter than the spacing: just the ends.
        let short = [point(0.0, 0.0, 0.5), point(1.0, 0.0, 0.5)];
        assert_eq!(resample(&short, 4.0), short.to_vec());
    }
}

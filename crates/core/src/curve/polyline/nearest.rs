//! Nearest points and distances: to a segment, to a polyline, and the closest point of a
//! polyline with its arclength.

use glam::DVec2;

/// The parameter in `[0, 1]` of the point of segment `a b` nearest `p` (0 when the segment
/// is a point).
fn parameter_on_segment(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let length_squared = ab.length_squared();
    if length_squared > 0.0 {
        ((p - a).dot(ab) / length_squared).clamp(0.0, 1.0)
    } else {
        0.0
    }
}

/// Distance from `p` to the segment `a b`.
pub fn distance_to_segment(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let t = parameter_on_segment(p, a, b);
    p.distance(a + t * (b - a))
}

/// Distance from `p` to the polyline: to its nearest segment, to its point when it has just
/// one, infinite when it has none. For a closed polygon, repeat the first point at the end.
pub fn distance_to_polyline(p: DVec2, points: &[DVec2]) -> f64 {
    match points {
        [] => f64::INFINITY,
        [only] => p.distance(*only),
        _ => points
            .windows(2)
            .map(|w| distance_to_segment(p, w[0], w[1]))
            .fold(f64::INFINITY, f64::min),
    }
}

/// The point of a polyline nearest a query point ([`closest_point`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Closest {
    /// Its arclength along the polyline.
    pub arclength: f64,
    /// The point.
    pub point: DVec2,
    /// Its distance from the query point.
    pub distance: f64,
    /// The unit direction of the segment it lies on; when that segment has zero length, the
    /// direction of an earlier segment that was nearest so far, or `+x`.
    pub direction: DVec2,
}

/// The point of the polyline `points` (at least two) nearest `p`, with `cumulative` the
/// polyline's [`super::cumulative_lengths`]. Of equally near segments, the first wins.
/// With fewer than two points: arclength 0, direction `+x`, infinitely far.
pub fn closest_point(points: &[DVec2], cumulative: &[f64], p: DVec2) -> Closest {
    let mut best = Closest {
        arclength: 0.0,
        point: points.first().copied().unwrap_or(p),
        distance: f64::INFINITY,
        direction: DVec2::X,
    };
    let mut best_distance_squared = f64::INFINITY;
    for i in 0..points.len().saturating_sub(1) {
        let (a, b) = (points[i], points[i + 1]);
        let edge = b - a;
        let t = parameter_on_segment(p, a, b);
        let point = a + t * edge;
        let distance_squared = p.distance_squared(point);
        if distance_squared < best_distance_squared {
            best_distance_squared = distance_squared;
            best = Closest {
                arclength: cumulative[i] + t * (cumulative[i + 1] - cumulative[i]),
                point,
                distance: distance_squared.sqrt(),
                direction: edge.try_normalize().unwrap_or(best.direction),
            };
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::super::cumulative_lengths;
    use super::*;

    #[test]
    fn segment_distances() {
        let (a, b) = (DVec2::ZERO, DVec2::new(4.0, 0.0));
        // Above the middle, beyond either end, and on the segment.
        assert_eq!(distance_to_segment(DVec2::new(1.0, 3.0), a, b), 3.0);
        assert_eq!(distance_to_segment(DVec2::new(7.0, 4.0), a, b), 5.0);
        assert_eq!(distance_to_segment(DVec2::new(-3.0, -4.0), a, b), 5.0);
        assert_eq!(distance_to_segment(DVec2::new(2.0, 0.0), a, b), 0.0);
        // A segment that is a point.
        assert_eq!(distance_to_segment(DVec2::new(3.0, 4.0), a, a), 5.0);
    }

    #[test]
    fn polyline_distances() {
        let line = [DVec2::ZERO, DVec2::new(10.0, 0.0), DVec2::new(10.0, 10.0)];
        assert_eq!(distance_to_polyline(DVec2::new(5.0, 3.0), &line), 3.0);
        assert_eq!(distance_to_polyline(DVec2::new(13.0, 6.0), &line), 3.0);
        assert_eq!(distance_to_polyline(DVec2::new(0.0, 4.0), &line[..1]), 4.0);
        assert_eq!(distance_to_polyline(DVec2::ZERO, &[]), f64::INFINITY);
    }

    #[test]
    fn closest_point_on_an_l_shape() {
        let points = [DVec2::ZERO, DVec2::new(3.0, 0.0), DVec2::new(3.0, 1.0)];
        let cumulative = cumulative_lengths(&points);
        let closest = closest_point(&points, &cumulative, DVec2::new(5.0, 0.5));
        assert!((closest.arclength - 3.5).abs() < 1e-12);
        assert_eq!(closest.point, DVec2::new(3.0, 0.5));
        assert_eq!(closest.distance, 2.0);
        assert_eq!(closest.direction, DVec2::Y);
        let before = closest_point(&points, &cumulative, DVec2::new(-1.0, -1.0));
        assert_eq!((before.arclength, before.point), (0.0, DVec2::ZERO));
        assert_eq!(before.direction, DVec2::X);
        // A zero-length segment has no direction of its own.
        let stutter = [DVec2::ZERO, DVec2::ZERO, DVec2::new(0.0, 2.0)];
        let cumulative = cumulative_lengths(&stutter);
        let closest = closest_point(&stutter, &cumulative, DVec2::new(-3.0, -4.0));
        assert_eq!((closest.direction, closest.distance), (DVec2::X, 5.0));
        // Fewer than two points.
        let none = closest_point(&stutter[..1], &cumulative[..1], DVec2::ONE);
        assert_eq!(none.distance, f64::INFINITY);
    }
}

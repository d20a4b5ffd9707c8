//! Planar polygon helpers for outlines: area, centroid, point-in-polygon, segment crossings
//! and distances.

use glam::DVec2;

/// Signed area of a closed polygon (counter-clockwise positive).
pub(crate) fn signed_area(points: &[DVec2]) -> f64 {
    let n = points.len();
    0.5 * (0..n)
        .map(|i| points[i].perp_dot(points[(i + 1) % n]))
        .sum::<f64>()
}

/// Length of a closed polygon, closing edge included.
pub(crate) fn perimeter(points: &[DVec2]) -> f64 {
    let n = points.len();
    (0..n)
        .map(|i| points[i].distance(points[(i + 1) % n]))
        .sum()
}

/// Area centroid of a closed polygon; the vertex mean when the area vanishes.
pub(crate) fn centroid(points: &[DVec2]) -> DVec2 {
    let n = points.len();
    let area = signed_area(points);
    if area.abs() < 1e-300 {
        return points.iter().copied().sum::<DVec2>() / n.max(1) as f64;
    }
    let sum: DVec2 = (0..n)
        .map(|i| {
            let (a, b) = (points[i], points[(i + 1) % n]);
            (a + b) * a.perp_dot(b)
        })
        .sum();
    sum / (6.0 * area)
}

/// Whether `p` lies inside the closed polygon (even-odd rule).
pub(crate) fn contains(points: &[DVec2], p: DVec2) -> bool {
    let n = points.len();
    let mut inside = false;
    for i in 0..n {
        let (a, b) = (points[i], points[(i + 1) % n]);
        if (a.y > p.y) != (b.y > p.y) {
            let x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
            if p.x < x {
                inside = !inside;
            }
        }
    }
    inside
}

/// Where segments `a0 a1` and `b0 b1` meet, as the parameter along `a0 a1`: a proper
/// crossing, or one segment touching the other (an end on the other segment, or collinear
/// overlap). Segments of a chain that share an end point touch, so callers skip neighbours.
pub(crate) fn crossing(a0: DVec2, a1: DVec2, b0: DVec2, b1: DVec2) -> Option<f64> {
    let (da, db) = (a1 - a0, b1 - b0);
    let o1 = da.perp_dot(b0 - a0);
    let o2 = da.perp_dot(b1 - a0);
    let o3 = db.perp_dot(a0 - b0);
    let o4 = db.perp_dot(a1 - b0);
    if o1 * o2 < 0.0 && o3 * o4 < 0.0 {
        return Some((b0 - a0).perp_dot(db) / da.perp_dot(db));
    }
    let along_a = |p: DVec2| (p - a0).dot(da) / da.length_squared().max(f64::MIN_POSITIVE);
    let is_on = |o: f64, p: DVec2, q0: DVec2, q1: DVec2| {
        o == 0.0 && p.cmpge(q0.min(q1)).all() && p.cmple(q0.max(q1)).all()
    };
    // An end of one segment on the other; `along_a` of an end of `a` is 0 or 1.
    [
        (o1, b0, a0, a1),
        (o2, b1, a0, a1),
        (o3, a0, b0, b1),
        (o4, a1, b0, b1),
    ]
    .into_iter()
    .find(|&(o, p, q0, q1)| is_on(o, p, q0, q1))
    .map(|(_, p, _, _)| along_a(p))
}

/// Distance from `p` to the segment `a b`.
pub(crate) fn distance_to_segment(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let length_squared = ab.length_squared();
    let t = if length_squared > 0.0 {
        ((p - a).dot(ab) / length_squared).clamp(0.0, 1.0)
    } else {
        0.0
    };
    p.distance(a + t * ab)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> Vec<DVec2> {
        vec![
            DVec2::new(0.0, 0.0),
            DVec2::new(2.0, 0.0),
            DVec2::new(2.0, 2.0),
            DVec2::new(0.0, 2.0),
        ]
    }

    #[test]
    fn area_centroid_and_containment_of_a_square() {
        let s = square();
        assert_eq!(signed_area(&s), 4.0);
        assert_eq!(perimeter(&s), 8.0);
        assert!((centroid(&s) - DVec2::ONE).length() < 1e-15);
        assert!(contains(&s, DVec2::new(0.5, 1.5)));
        assert!(!contains(&s, DVec2::new(2.5, 1.0)));
        let reversed: Vec<DVec2> = s.iter().rev().copied().collect();
        assert_eq!(signed_area(&reversed), -4.0);
    }

    #[test]
    fn crossings_and_touches() {
        let t = crossing(
            DVec2::ZERO,
            DVec2::new(2.0, 0.0),
            DVec2::new(0.5, -1.0),
            DVec2::new(0.5, 1.0),
        );
        assert_eq!(t, Some(0.25));
        // Touching counts: an end on the other segment, or a shared end.
        let t = crossing(
            DVec2::ZERO,
            DVec2::new(2.0, 0.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(1.0, 1.0),
        );
        assert_eq!(t, Some(0.5));
        assert_eq!(
            crossing(DVec2::ZERO, DVec2::X, DVec2::X, DVec2::new(1.0, 1.0)),
            Some(1.0)
        );
        // Apart, or on one line without overlapping.
        assert_eq!(
            crossing(DVec2::ZERO, DVec2::X, DVec2::Y, DVec2::new(1.0, 1.0)),
            None
        );
        assert_eq!(
            crossing(
                DVec2::ZERO,
                DVec2::X,
                DVec2::new(2.0, 0.0),
                DVec2::new(3.0, 0.0)
            ),
            None
        );
    }
}

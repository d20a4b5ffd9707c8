//! Where two segments meet: the one test that the crossings of a polyline and the grid that
//! buckets its segments both use.

use glam::DVec2;

/// Where segments `a0 a1` and `b0 b1` meet, as the parameter along `a0 a1`: a proper
/// crossing, or one segment touching the other (an end on the other segment, or collinear
/// overlap). Segments of a chain that share an end point touch, so callers skip neighbours.
pub fn segment_crossing(a0: DVec2, a1: DVec2, b0: DVec2, b1: DVec2) -> Option<f64> {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crossings_and_touches() {
        let t = segment_crossing(
            DVec2::ZERO,
            DVec2::new(2.0, 0.0),
            DVec2::new(0.5, -1.0),
            DVec2::new(0.5, 1.0),
        );
        assert_eq!(t, Some(0.25));
        // Touching counts: an end on the other segment, or a shared end.
        let t = segment_crossing(
            DVec2::ZERO,
            DVec2::new(2.0, 0.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(1.0, 1.0),
        );
        assert_eq!(t, Some(0.5));
        assert_eq!(
            segment_crossing(DVec2::ZERO, DVec2::X, DVec2::X, DVec2::new(1.0, 1.0)),
            Some(1.0)
        );
        // Apart, or on one line without overlapping.
        assert_eq!(
            segment_crossing(DVec2::ZERO, DVec2::X, DVec2::Y, DVec2::new(1.0, 1.0)),
            None
        );
        assert_eq!(
            segment_crossing(
                DVec2::ZERO,
                DVec2::X,
                DVec2::new(2.0, 0.0),
                DVec2::new(3.0, 0.0)
            ),
            None
        );
    }
}

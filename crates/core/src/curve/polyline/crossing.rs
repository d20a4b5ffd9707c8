//! Where segments cross, and whether a polyline or polygon crosses itself.

use glam::DVec2;

use super::SegmentGrid;

/// The pairs of segments of a polyline that cross or touch ([`super::segment_crossing`]) and are
/// not neighbours, as sorted, unique pairs `(i, j)` with `i + 1 < j`, segment `i` running
/// from point `i` to point `i + 1`. `is_closed` adds the closing segment (index `n − 1`,
/// from the last point back to the first), a neighbour of the first. Empty for a simple
/// polyline.
///
/// The segments are bucketed in a grid of cells about twice the mean segment length, so a
/// polyline of `m` evenly spaced segments costs about `O(m)`, not `O(m²)`.
pub fn self_crossings(points: &[DVec2], is_closed: bool) -> Vec<(usize, usize)> {
    let n = points.len();
    let (segments, length) = if is_closed {
        (n, super::perimeter(points))
    } else {
        (n.saturating_sub(1), super::length(points))
    };
    if segments < 3 {
        return Vec::new();
    }
    let cell = 2.0 * length / segments as f64;
    let grid = if is_closed {
        SegmentGrid::closed(points, cell)
    } else {
        SegmentGrid::new(points.windows(2).map(|w| [w[0], w[1]]).collect(), cell)
    };
    grid.chain_crossings(is_closed)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::TAU;

    #[test]
    fn a_figure_eight_crosses_itself_once_and_an_ellipse_does_not() {
        let n = 200;
        let eight: Vec<DVec2> = (0..n)
            .map(|k| {
                let t = TAU * k as f64 / n as f64;
                DVec2::new(100.0 * t.sin(), 50.0 * (2.0 * t).sin())
            })
            .collect();
        // The lobes meet at the origin, passed at k = 0 and k = 100: segments 99 and 100
        // touch there, and so do the closing segment 199 and segment 0, which are
        // neighbours but also touch 99 and 100.
        let crossings = self_crossings(&eight, true);
        assert!(!crossings.is_empty());
        assert!(
            crossings
                .iter()
                .all(|&(i, j)| [0, 99, 100, 199].contains(&i) && [99, 100, 199].contains(&j)),
            "{crossings:?}"
        );
        let ellipse: Vec<DVec2> = (0..n)
            .map(|k| DVec2::from_angle(TAU * k as f64 / n as f64) * DVec2::new(100.0, 50.0))
            .collect();
        assert!(self_crossings(&ellipse, true).is_empty());
        // Open, the ellipse's ends are not joined, so nothing touches either.
        assert!(self_crossings(&ellipse, false).is_empty());
    }

    #[test]
    fn a_bow_tie_and_a_square() {
        // A bow tie: the edges 0 -> 1 and 2 -> 3 cross at (1, 1).
        let bow = [(0.0, 0.0), (2.0, 2.0), (2.0, 0.0), (0.0, 2.0)].map(|(x, y)| DVec2::new(x, y));
        assert_eq!(self_crossings(&bow, true), vec![(0, 2)]);
        // Open, the crossing segments are still there.
        assert_eq!(self_crossings(&bow, false), vec![(0, 2)]);
        let square =
            [(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)].map(|(x, y)| DVec2::new(x, y));
        assert!(self_crossings(&square, true).is_empty());
        // A spiral's closing edge cuts its inner turn.
        let spiral: Vec<DVec2> = (0..=80)
            .map(|k| {
                let turns = 2.0 * k as f64 / 80.0;
                (100.0 - 10.0 * turns) * DVec2::from_angle(TAU * turns + 0.3)
            })
            .collect();
        assert!(self_crossings(&spiral, false).is_empty());
        assert!(!self_crossings(&spiral, true).is_empty());
        assert!(self_crossings(&bow[..3], true).is_empty());
    }
}

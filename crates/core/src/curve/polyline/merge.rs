//! Over-sketching a polyline: Baudel's merge ("A mark-based interaction paradigm for
//! free-hand drawing", UIST 1994) as Bujans redraws her curves (§4.2, with `k = 6`), with the
//! digest's fixes: the blend is a scalar ramp (a smoothstep), the end transition mirrors the
//! start, a stroke drawn against the curve's direction is reversed first, and distances along
//! the curve are arclengths, so `k` times the gap at a stroke end is a length.
//!
//! The stroke replaces the stretch of the curve between the points nearest its ends; on
//! either side, over `k` times the gap between the stroke's end and the curve, the curve
//! blends into a Hermite arc from itself to the stroke's end, so the result has no kink. A
//! stroke that runs past an end of the curve replaces that end.

use glam::DVec2;

use super::{closest_point, cumulative_lengths, point_at};

/// Bujans' smoothing coefficient (Baudel recommends 3): the transitions are six times as long
/// as the gap they close.
pub const BAUDEL_K: f64 = 6.0;

/// Spacing (in the curves' units) of the points of a transition.
const TRANSITION_SPACING: f64 = 2.0;

/// `original` with `stroke` drawn over part of it (both at least two points; otherwise the
/// one that has them is returned), smoothed over `k` times each end's gap.
pub fn oversketch_merge(original: &[DVec2], stroke: &[DVec2], k: f64) -> Vec<DVec2> {
    if stroke.len() < 2 {
        return original.to_vec();
    }
    if original.len() < 2 {
        return stroke.to_vec();
    }
    let cumulative = cumulative_lengths(original);
    let total = cumulative[cumulative.len() - 1];
    let nearest = |p: DVec2| closest_point(original, &cumulative, p);
    let mut stroke = stroke.to_vec();
    if nearest(stroke[0]).arclength > nearest(stroke[stroke.len() - 1]).arclength {
        stroke.reverse();
    }
    let (first, last) = (stroke[0], stroke[stroke.len() - 1]);
    let (start, end) = (nearest(first), nearest(last));
    let before = start.arclength - k * start.distance;
    let after = end.arclength + k * end.distance;
    let on_original = |s: f64| point_at(original, &cumulative, s);
    let mut merged = Vec::with_capacity(original.len() + stroke.len());
    if before > 0.0 {
        merged.extend(
            original
                .iter()
                .zip(&cumulative)
                .take_while(|(_, s)| **s < before)
                .map(|(p, _)| *p),
        );
        let from_tangent = (on_original(before + 1e-6) - on_original(before)).normalize_or_zero();
        let to_tangent = (stroke[1] - first).normalize_or_zero();
        let arc = Hermite::new(on_original(before), from_tangent, first, to_tangent);
        merged.push(on_original(before));
        merged.extend(transition(
            arc,
            |u| on_original(before + u * (start.arclength - before)),
            false,
        ));
    }
    merged.extend(&stroke);
    if after < total {
        let from_tangent = (last - stroke[stroke.len() - 2]).normalize_or_zero();
        let to_tangent = (on_original(after) - on_original(after - 1e-6)).normalize_or_zero();
        let arc = Hermite::new(last, from_tangent, on_original(after), to_tangent);
        merged.extend(transition(
            arc,
            |u| on_original(end.arclength + u * (after - end.arclength)),
            true,
        ));
        merged.push(on_original(after));
        merged.extend(
            original
                .iter()
                .zip(&cumulative)
                .skip_while(|(_, s)| **s <= after)
                .map(|(p, _)| *p),
        );
    }
    merged
}

/// The inner points of a transition: along `arc`, blended with the curve (`along(u)` for
/// `u` in [0, 1]) by a ramp that gives the arc full weight at the stroke's end (the arc's
/// end, or its start when `from_stroke`).
/// [`oversketch_merge`] for a closed loop (first point not repeated): the loop is opened
/// half way round from where the stroke lies, so the stroke and its transitions fall inside
/// the open polyline, merged, and closed again. A stroke that covers more than about half
/// the loop is beyond what one opening serves.
pub fn oversketch_merge_closed(loop_: &[DVec2], stroke: &[DVec2], k: f64) -> Vec<DVec2> {
    let n = loop_.len();
    if n < 3 || stroke.len() < 2 {
        return oversketch_merge(loop_, stroke, k);
    }
    let middle = stroke[stroke.len() / 2];
    let nearest = (0..n)
        .min_by(|&a, &b| {
            loop_[a]
                .distance(middle)
                .total_cmp(&loop_[b].distance(middle))
        })
        .unwrap_or(0);
    let seam = (nearest + n / 2) % n;
    let opened: Vec<DVec2> = (0..=n).map(|i| loop_[(seam + i) % n]).collect();
    let mut merged = oversketch_merge(&opened, stroke, k);
    if merged.len() > 1 && merged[0].distance(merged[merged.len() - 1]) < 1e-9 {
        merged.pop();
    }
    merged
}

fn transition(arc: Hermite, along: impl Fn(f64) -> DVec2, from_stroke: bool) -> Vec<DVec2> {
    let n = (arc.chord() / TRANSITION_SPACING).ceil().max(2.0) as usize;
    (1..n)
        .map(|i| {
            let u = i as f64 / n as f64;
            let ramp = u * u * (3.0 - 2.0 * u);
            let c = if from_stroke { 1.0 - ramp } else { ramp };
            (1.0 - c) * along(u) + c * arc.at(u)
        })
        .collect()
}

/// A cubic Hermite arc between two points with unit tangents, scaled by the chord.
#[derive(Clone, Copy, Debug)]
struct Hermite {
    from: DVec2,
    from_tangent: DVec2,
    to: DVec2,
    to_tangent: DVec2,
}

impl Hermite {
    fn new(from: DVec2, from_tangent: DVec2, to: DVec2, to_tangent: DVec2) -> Self {
        let chord = from.distance(to);
        Hermite {
            from,
            from_tangent: from_tangent * chord,
            to,
            to_tangent: to_tangent * chord,
        }
    }

    fn chord(&self) -> f64 {
        self.from.distance(self.to)
    }

    fn at(&self, u: f64) -> DVec2 {
        let (u2, u3) = (u * u, u * u * u);
        (2.0 * u3 - 3.0 * u2 + 1.0) * self.from
            + (u3 - 2.0 * u2 + u) * self.from_tangent
            + (-2.0 * u3 + 3.0 * u2) * self.to
            + (u3 - u2) * self.to_tangent
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::polyline::distance_to_polyline;

    fn line(a: DVec2, b: DVec2, n: usize) -> Vec<DVec2> {
        (0..=n).map(|i| a.lerp(b, i as f64 / n as f64)).collect()
    }

    #[test]
    fn a_stroke_over_the_middle_replaces_it_and_blends_in() {
        let original = line(DVec2::ZERO, DVec2::new(300.0, 0.0), 150);
        let stroke = line(DVec2::new(100.0, 10.0), DVec2::new(200.0, 10.0), 50);
        let merged = oversketch_merge(&original, &stroke, BAUDEL_K);
        // The ends stay; the middle is the stroke; nothing jumps.
        assert_eq!(merged[0], original[0]);
        assert_eq!(merged[merged.len() - 1], original[original.len() - 1]);
        for p in &stroke {
            assert!(merged.contains(p));
        }
        assert!(merged.windows(2).all(|w| w[0].distance(w[1]) < 3.0));
        // The transitions reach 6 gaps (60) back along the curve, and stay between the two.
        for p in &merged {
            assert!((-1e-9..=10.0 + 1e-9).contains(&p.y), "{p}");
            if p.x < 40.0 - 1e-9 || p.x > 260.0 + 1e-9 {
                assert_eq!(p.y, 0.0, "untouched beyond the transitions: {p}");
            }
        }
        assert!(
            merged
                .iter()
                .any(|p| p.x > 45.0 && p.x < 95.0 && p.y > 0.5 && p.y < 9.5)
        );
        // Drawn the other way, the same curve.
        let mut reversed = stroke.clone();
        reversed.reverse();
        assert_eq!(oversketch_merge(&original, &reversed, BAUDEL_K), merged);
    }

    #[test]
    fn a_loop_redrawn_in_part_stays_closed_and_takes_the_stroke() {
        let ring: Vec<DVec2> = (0..90)
            .map(|i| 100.0 * DVec2::from_angle(std::f64::consts::TAU * f64::from(i) / 90.0))
            .collect();
        // A bulge over the ring's right side, drawn downward (against the ring's turn).
        let stroke: Vec<DVec2> = (0..=30)
            .map(|i| {
                let a = 0.6 - 1.2 * f64::from(i) / 30.0;
                (100.0 + 20.0 * (std::f64::consts::PI * f64::from(i) / 30.0).sin())
                    * DVec2::from_angle(a)
            })
            .collect();
        let merged = oversketch_merge_closed(&ring, &stroke, BAUDEL_K);
        // Closed: its last point is next to its first, as the ring's are.
        let gap = merged[0].distance(merged[merged.len() - 1]);
        assert!(gap < 10.0, "{gap}");
        // The stroke's tip is in it; the left side is untouched.
        let tip = stroke[15];
        assert!(merged.iter().any(|p| p.distance(tip) < 1e-9));
        for p in ring.iter().filter(|p| p.x < -50.0) {
            assert!(merged.iter().any(|q| q.distance(*p) < 1e-9), "{p}");
        }
        assert!(
            merged
                .iter()
                .all(|p| p.length() < 121.0 && p.length() > 99.0)
        );
    }

    #[test]
    fn a_stroke_along_the_curve_leaves_it_and_one_past_an_end_replaces_it() {
        let original = line(DVec2::ZERO, DVec2::new(300.0, 0.0), 150);
        let same = line(DVec2::new(100.0, 0.0), DVec2::new(200.0, 0.0), 50);
        let merged = oversketch_merge(&original, &same, BAUDEL_K);
        assert!(
            merged
                .iter()
                .all(|&p| distance_to_polyline(p, &original) < 1e-9)
        );
        let past = line(DVec2::new(250.0, 0.0), DVec2::new(350.0, 40.0), 50);
        let extended = oversketch_merge(&original, &past, BAUDEL_K);
        assert_eq!(
            extended[extended.len() - 1],
            DVec2::new(350.0, 40.0),
            "ends where the stroke does"
        );
        assert_eq!(extended[0], original[0]);
        assert_eq!(oversketch_merge(&original, &past[..1], BAUDEL_K), original);
    }
}

//! Screen polylines: arclength, lookup by arclength, closest points, even resampling and
//! Douglas–Peucker simplification (D. Douglas and T. Peucker, The Canadian Cartographer
//! 10(2), 1973), as SilSketch applies to the user's stroke and to the silhouettes
//! (Nealen's dissertation §5.4, §5.4.2).

use glam::DVec2;

/// Spacing of the even resampling in [`simplify_stroke`], in px.
pub const STROKE_SPACING_PX: f64 = 2.0;
/// Douglas–Peucker tolerance of [`simplify_stroke`], in px.
pub const STROKE_TOLERANCE_PX: f64 = 1.0;

/// Simplifies a drawn stroke as SilSketch does before matching: even resampling at
/// [`STROKE_SPACING_PX`] (so bursts and gaps of pointer events weigh alike), then
/// Douglas–Peucker at [`STROKE_TOLERANCE_PX`].
///
/// The first and last points are kept exactly. Fewer than two points, or a stroke of zero
/// length, come back as at most one point.
pub fn simplify_stroke(points: &[DVec2]) -> Vec<DVec2> {
    let even = resample(points, STROKE_SPACING_PX);
    douglas_peucker(&even, STROKE_TOLERANCE_PX)
        .into_iter()
        .map(|i| even[i])
        .collect()
}

/// Arclength at each point, starting at 0.
pub(crate) fn cumulative_lengths(points: &[DVec2]) -> Vec<f64> {
    let mut out = Vec::with_capacity(points.len());
    let mut total = 0.0;
    for (i, p) in points.iter().enumerate() {
        if i > 0 {
            total += p.distance(points[i - 1]);
        }
        out.push(total);
    }
    out
}

/// The segment `i` (from point `i` to `i + 1`) that contains arclength `s`, clamped to
/// the polyline. Needs at least two points.
pub(crate) fn segment_at(cumulative: &[f64], s: f64) -> usize {
    let after = cumulative.partition_point(|&c| c <= s);
    after
        .saturating_sub(1)
        .min(cumulative.len().saturating_sub(2))
}

/// Fractional point index at arclength `s` (clamped): `i + t` on segment `i`.
pub(crate) fn index_at(cumulative: &[f64], s: f64) -> f64 {
    if cumulative.len() < 2 {
        return 0.0;
    }
    let i = segment_at(cumulative, s);
    let length = cumulative[i + 1] - cumulative[i];
    let t = if length > 0.0 {
        ((s - cumulative[i]) / length).clamp(0.0, 1.0)
    } else {
        0.0
    };
    i as f64 + t
}

/// The point at arclength `s` (clamped to the polyline). Needs at least one point.
pub(crate) fn point_at(points: &[DVec2], cumulative: &[f64], s: f64) -> DVec2 {
    if points.len() < 2 {
        return points.first().copied().unwrap_or(DVec2::ZERO);
    }
    let t = index_at(cumulative, s);
    let i = (t.floor() as usize).min(points.len() - 2);
    points[i].lerp(points[i + 1], t - i as f64)
}

/// The point at fractional index `t` (clamped). Needs at least one point.
pub(crate) fn point_at_index(points: &[DVec2], t: f64) -> DVec2 {
    if points.len() < 2 {
        return points.first().copied().unwrap_or(DVec2::ZERO);
    }
    let t = t.clamp(0.0, (points.len() - 1) as f64);
    let i = (t.floor() as usize).min(points.len() - 2);
    points[i].lerp(points[i + 1], t - i as f64)
}

/// Closest point of the polyline to `p`: its arclength and the segment's unit direction.
/// Needs at least two points.
pub(crate) fn closest_point(points: &[DVec2], cumulative: &[f64], p: DVec2) -> (f64, DVec2) {
    let mut best = (f64::INFINITY, 0.0, DVec2::X);
    for i in 0..points.len().saturating_sub(1) {
        let (a, b) = (points[i], points[i + 1]);
        let edge = b - a;
        let length_sq = edge.length_squared();
        let t = if length_sq > 0.0 {
            ((p - a).dot(edge) / length_sq).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let distance_sq = p.distance_squared(a + t * edge);
        if distance_sq < best.0 {
            let s = cumulative[i] + t * (cumulative[i + 1] - cumulative[i]);
            best = (distance_sq, s, edge.try_normalize().unwrap_or(best.2));
        }
    }
    (best.1, best.2)
}

/// Even arclength resampling: steps of `L / round(L / spacing)`, first and last points kept.
pub(crate) fn resample(points: &[DVec2], spacing: f64) -> Vec<DVec2> {
    let cumulative = cumulative_lengths(points);
    let Some(&length) = cumulative.last() else {
        return Vec::new();
    };
    if length <= 0.0 || !(spacing.is_finite() && spacing > 0.0) {
        return points[..1].to_vec();
    }
    let steps = ((length / spacing).round() as usize).max(1);
    (0..=steps)
        .map(|k| point_at(points, &cumulative, length * k as f64 / steps as f64))
        .collect()
}

/// Indices of the points Douglas–Peucker keeps at `tolerance` px, in order; the first and
/// last are always kept. Iterative, so long silhouettes cannot overflow the stack.
pub(crate) fn douglas_peucker(points: &[DVec2], tolerance: f64) -> Vec<usize> {
    let n = points.len();
    if n <= 2 {
        return (0..n).collect();
    }
    let mut keep = vec![false; n];
    keep[0] = true;
    keep[n - 1] = true;
    let mut stack = vec![(0, n - 1)];
    while let Some((first, last)) = stack.pop() {
        let (a, b) = (points[first], points[last]);
        let mut farthest = (0.0, first);
        for (i, &p) in points.iter().enumerate().take(last).skip(first + 1) {
            let distance = distance_to_segment(p, a, b);
            if distance > farthest.0 {
                farthest = (distance, i);
            }
        }
        if farthest.0 > tolerance {
            keep[farthest.1] = true;
            stack.push((first, farthest.1));
            stack.push((farthest.1, last));
        }
    }
    (0..n).filter(|&i| keep[i]).collect()
}

fn distance_to_segment(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let edge = b - a;
    let length_sq = edge.length_squared();
    let t = if length_sq > 0.0 {
        ((p - a).dot(edge) / length_sq).clamp(0.0, 1.0)
    } else {
        0.0
    };
    p.distance(a + t * edge)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lookups_on_an_uneven_l_shape() {
        let points = [DVec2::ZERO, DVec2::new(3.0, 0.0), DVec2::new(3.0, 1.0)];
        let cumulative = cumulative_lengths(&points);
        assert_eq!(cumulative, vec![0.0, 3.0, 4.0]);
        assert_eq!(index_at(&cumulative, 1.5), 0.5);
        assert_eq!(index_at(&cumulative, 3.5), 1.5);
        assert_eq!(index_at(&cumulative, 9.0), 2.0);
        assert_eq!(point_at(&points, &cumulative, 3.25), DVec2::new(3.0, 0.25));
        assert_eq!(point_at_index(&points, 1.25), DVec2::new(3.0, 0.25));
        let (s, direction) = closest_point(&points, &cumulative, DVec2::new(5.0, 0.5));
        assert!((s - 3.5).abs() < 1e-12 && direction == DVec2::Y);
    }

    #[test]
    fn resampling_keeps_ends_and_spaces_evenly() {
        let points = [DVec2::ZERO, DVec2::new(0.5, 0.0), DVec2::new(10.0, 0.0)];
        let even = resample(&points, 2.0);
        assert_eq!(even.len(), 6);
        for (k, p) in even.iter().enumerate() {
            assert!((p.x - 2.0 * k as f64).abs() < 1e-12 && p.y == 0.0);
        }
    }

    #[test]
    fn douglas_peucker_keeps_only_corners_of_a_noisy_polyline() {
        // An L with sub-tolerance wiggles along both legs.
        let mut points: Vec<DVec2> = (0..=20)
            .map(|i| DVec2::new(i as f64, 0.2 * (i as f64).sin()))
            .collect();
        points.extend((1..=20).map(|i| DVec2::new(20.0 + 0.2 * (i as f64).cos(), i as f64)));
        let kept = douglas_peucker(&points, 0.6);
        assert_eq!(kept, vec![0, 20, 40]);
        // A tolerance below the wiggle keeps more.
        assert!(douglas_peucker(&points, 0.05).len() > 3);
    }

    #[test]
    fn simplified_stroke_keeps_ends_and_shape() {
        // A dense, jittery half circle of radius 100 px.
        let raw: Vec<DVec2> = (0..=500)
            .map(|k| {
                let t = std::f64::consts::PI * k as f64 / 500.0;
                (100.0 + 0.2 * (37.0 * t).sin()) * DVec2::new(t.cos(), t.sin())
            })
            .collect();
        let simple = simplify_stroke(&raw);
        assert_eq!(simple.first(), raw.first());
        assert_eq!(simple.last(), raw.last());
        assert!(simple.len() < 40, "{} points", simple.len());
        for p in &simple {
            assert!((p.length() - 100.0).abs() < 1.5);
        }
    }
}

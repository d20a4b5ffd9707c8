//! Polyline simplification: Douglas–Peucker (D. Douglas and T. Peucker, The Canadian
//! Cartographer 10(2), 1973), after an even resampling when the input's spacing is uneven.

use glam::DVec2;

use super::{PolylinePoint, distance_to_segment, resample};

/// The points no nearer than `spacing` to the last point kept, the first always kept:
/// Bujans' filter of a pen's input before a smooth fit (10 px), so that a hand lingering in
/// one place leaves no knot.
pub fn thin<P: PolylinePoint>(points: &[P], spacing: f64) -> Vec<P> {
    let mut kept: Vec<P> = Vec::with_capacity(points.len());
    for &p in points {
        match kept.last() {
            Some(last) if last.position().distance(p.position()) < spacing => {}
            _ => kept.push(p),
        }
    }
    kept
}

/// Even resampling at `spacing` (so bursts and gaps of pointer events weigh alike), then
/// [`douglas_peucker`] at `tolerance`: the points kept. The first and last points are kept
/// exactly; a polyline of zero length comes back as its first point, an empty one empty.
pub fn simplify(points: &[DVec2], spacing: f64, tolerance: f64) -> Vec<DVec2> {
    let even = resample(points, spacing);
    douglas_peucker(&even, tolerance)
        .into_iter()
        .map(|i| even[i])
        .collect()
}

/// Indices of the points Douglas–Peucker keeps at `tolerance`, in order; the first and
/// last are always kept. Iterative, so long silhouettes cannot overflow the stack.
pub fn douglas_peucker(points: &[DVec2], tolerance: f64) -> Vec<usize> {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thinning_keeps_points_a_spacing_apart() {
        let points: Vec<DVec2> = (0..=40).map(|i| DVec2::new(f64::from(i), 0.0)).collect();
        let kept = thin(&points, 10.0);
        assert_eq!(
            kept,
            [0.0, 10.0, 20.0, 30.0, 40.0].map(|x| DVec2::new(x, 0.0))
        );
        assert!(thin::<DVec2>(&[], 10.0).is_empty());
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
        assert_eq!(douglas_peucker(&points[..2], 0.6), vec![0, 1]);
    }

    #[test]
    fn simplifying_a_dense_square_wave_keeps_its_corners() {
        // Two teeth of height 5, sampled every 0.25 along each side.
        let corners = [(0, 0), (5, 0), (5, 5), (10, 5), (10, 0), (15, 0)];
        let mut dense = vec![DVec2::ZERO];
        for pair in corners.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            let (a, b) = (
                DVec2::new(a.0 as f64, a.1 as f64),
                DVec2::new(b.0 as f64, b.1 as f64),
            );
            dense.extend((1..=20).map(|k| a.lerp(b, k as f64 / 20.0)));
        }
        // Length 25 at spacing 1: every corner is a sample, the sides are straight.
        let simple = simplify(&dense, 1.0, 0.1);
        let expected: Vec<DVec2> = corners
            .iter()
            .map(|&(x, y)| DVec2::new(x as f64, y as f64))
            .collect();
        assert_eq!(simple.len(), expected.len(), "{simple:?}");
        for (p, q) in simple.iter().zip(&expected) {
            assert!(p.distance(*q) < 1e-9, "{p} vs {q}");
        }
        assert!(simplify(&[], 1.0, 0.1).is_empty());
    }
}

//! Stroke jitter filtering (Blanco §3.1.1, Alg. 1, after Kho and Garland 2005).

use glam::DVec2;

/// The smallest movement that counts, in CSS px (the thesis leaves δ open; 4 px removes a
/// hand's tremor and a finger's wobble and keeps the turns a handle needs).
pub const JITTER_PX: f64 = 4.0;

/// Alg. 1: each output point is the running mean of the raw points after the previous
/// output, emitted once it is at least `delta` from it.
pub fn filter_jitter(points: &[DVec2], delta: f64) -> Vec<DVec2> {
    let Some(&first) = points.first() else {
        return Vec::new();
    };
    let mut filtered = vec![first];
    let mut from = first;
    let mut rest = points[1..].iter();
    while let Some(&p) = rest.next() {
        let (mut sum, mut added, mut mean) = (p, 1.0, p);
        while from.distance(mean) < delta {
            let Some(&q) = rest.next() else { break };
            sum += q;
            added += 1.0;
            mean = sum / added;
        }
        filtered.push(mean);
        from = mean;
    }
    filtered
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_segment_but_the_last_is_at_least_delta_and_jitter_is_calmer() {
        let raw: Vec<DVec2> = (0..400)
            .map(|i| {
                let x = f64::from(i) * 0.5;
                DVec2::new(x, 2.0 * ((f64::from(i) * 2.3).sin()))
            })
            .collect();
        let filtered = filter_jitter(&raw, JITTER_PX);
        for pair in filtered.windows(2).take(filtered.len().saturating_sub(2)) {
            assert!(pair[0].distance(pair[1]) >= JITTER_PX - 1e-9);
        }
        let turning = |p: &[DVec2]| -> f64 {
            p.windows(3)
                .map(|w| (w[1] - w[0]).angle_to(w[2] - w[1]).abs())
                .sum()
        };
        assert!(turning(&filtered) < 0.5 * turning(&raw));
    }
}

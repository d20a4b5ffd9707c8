//! Taubin smoothing of polylines (λ|μ low-pass filter).
//!
//! G. Taubin, "A signal processing approach to fair surface design", SIGGRAPH 1995: a step
//! `p ← p + λ Δp` followed by `p ← p + μ Δp` with `μ < −λ < 0` damps high frequencies while
//! leaving low ones almost untouched, so a curve does not shrink the way plain Laplacian
//! smoothing makes it. `Δp_i = (p_{i−1} + p_{i+1}) / 2 − p_i` is the umbrella operator.
//! Pressure is smoothed along with position.

use super::point::StrokePoint;

/// Taubin's shrinking step.
const LAMBDA: f64 = 0.5;
/// Taubin's inflating step (`μ < −λ`, pass-band frequency `1/λ + 1/μ ≈ 0.11`).
const MU: f64 = -0.53;

/// Smooths an open polyline with `iterations` Taubin λ|μ passes; the end points stay fixed.
pub fn smooth(points: &[StrokePoint], iterations: usize) -> Vec<StrokePoint> {
    let mut current = points.to_vec();
    if points.len() < 3 {
        return current;
    }
    let mut scratch = current.clone();
    for _ in 0..iterations {
        for factor in [LAMBDA, MU] {
            for i in 1..current.len() - 1 {
                scratch[i] = umbrella_step(current[i - 1], current[i], current[i + 1], factor);
            }
            std::mem::swap(&mut current, &mut scratch);
            // Keep the fixed ends in both buffers.
            scratch[0] = current[0];
            let last = current.len() - 1;
            scratch[last] = current[last];
        }
    }
    current
}

/// Smooths a closed polyline (the last point connects back to the first; do not repeat the
/// first point at the end) with `iterations` Taubin λ|μ passes.
pub fn smooth_closed(points: &[StrokePoint], iterations: usize) -> Vec<StrokePoint> {
    let mut current = points.to_vec();
    let n = points.len();
    if n < 3 {
        return current;
    }
    let mut scratch = current.clone();
    for _ in 0..iterations {
        for factor in [LAMBDA, MU] {
            for i in 0..n {
                let previous = current[(i + n - 1) % n];
                let next = current[(i + 1) % n];
                scratch[i] = umbrella_step(previous, current[i], next, factor);
            }
            std::mem::swap(&mut current, &mut scratch);
        }
    }
    current
}

fn umbrella_step(
    previous: StrokePoint,
    point: StrokePoint,
    next: StrokePoint,
    factor: f64,
) -> StrokePoint {
    let laplacian_pos = 0.5 * (previous.pos + next.pos) - point.pos;
    let laplacian_pressure = 0.5 * (previous.pressure + next.pressure) - point.pressure;
    StrokePoint {
        pos: point.pos + factor * laplacian_pos,
        pressure: point.pressure + factor * laplacian_pressure,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;
    use std::f64::consts::TAU;

    fn polygon(n: usize, radius: f64) -> Vec<StrokePoint> {
        (0..n)
            .map(|k| {
                let angle = k as f64 / n as f64 * TAU;
                StrokePoint::new(radius * DVec2::new(angle.cos(), angle.sin()), 0.5)
            })
            .collect()
    }

    #[test]
    fn regular_polygon_scales_by_the_transfer_function() {
        // A regular n-gon is an eigenvector of the umbrella operator with eigenvalue
        // −k, k = 1 − cos(2π/n); one λ|μ pass scales it by (1 − λk)(1 − μk).
        let n = 24;
        let iterations = 3;
        let out = smooth_closed(&polygon(n, 10.0), iterations);
        let k = 1.0 - (TAU / n as f64).cos();
        let expected = 10.0 * ((1.0 - LAMBDA * k) * (1.0 - MU * k)).powi(iterations as i32);
        for point in &out {
            assert!((point.pos.length() - expected).abs() < 1e-12);
        }
        // Taubin barely shrinks it (plain Laplacian would give 10·(1 − k/2)^6 ≈ 9.69).
        assert!(expected > 9.99);
    }

    #[test]
    fn high_frequency_is_damped() {
        // The alternating zigzag has k = 2: each pass multiplies it by (1 − 2λ)(1 − 2μ) = 0.
        let zigzag: Vec<StrokePoint> = (0..12)
            .map(|k| {
                StrokePoint::new(
                    DVec2::new(k as f64, if k % 2 == 0 { 1.0 } else { -1.0 }),
                    0.5,
                )
            })
            .collect();
        let out = smooth_closed(&zigzag, 1);
        for point in &out {
            assert!(point.pos.y.abs() < 1e-12);
        }
    }

    #[test]
    fn open_smoothing_keeps_ends_and_lines() {
        let line: Vec<StrokePoint> = (0..10)
            .map(|k| StrokePoint::new(DVec2::new(3.0 * k as f64, 1.0), k as f64 / 8.0))
            .collect();
        assert_eq!(smooth(&line, 5), line);
        let mut bumped = line.clone();
        bumped[5].pos.y = 3.0;
        let out = smooth(&bumped, 2);
        assert_eq!(out[0], bumped[0]);
        assert_eq!(out[9], bumped[9]);
        assert!(out[5].pos.y > 1.0 && out[5].pos.y < 2.5, "{}", out[5].pos.y);
        assert_eq!(smooth(&bumped[..2], 3), bumped[..2].to_vec());
    }
}

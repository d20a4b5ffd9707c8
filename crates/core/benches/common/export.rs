//! Writing problems for the libigl comparisons (`examples/*_export.rs`) and timing them.

use std::fmt::Write as _;

use glam::DVec3;

/// Runs per timing; the median is printed.
pub const RUNS: usize = 15;

/// One `x y z` line per vector, in Rust's shortest round-trip form (both sides read the same
/// numbers).
pub fn vectors(points: &[DVec3]) -> String {
    points.iter().fold(String::new(), |mut s, p| {
        let _ = writeln!(s, "{} {} {}", p.x, p.y, p.z);
        s
    })
}

/// The median of `samples` (seconds), in ms.
pub fn median_ms(mut samples: Vec<f64>) -> f64 {
    samples.sort_by(f64::total_cmp);
    samples[samples.len() / 2] * 1e3
}

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

/// Writes `mesh.off` and `roi.txt` (0 or 1 per vertex) to `dir`.
pub fn write_mesh_and_roi(
    dir: &std::path::Path,
    mesh: &sketchmesh_core::mesh::Mesh,
    roi: &[bool],
) -> std::io::Result<()> {
    let mut off = format!("OFF\n{} {} 0\n", mesh.n_vertices(), mesh.n_faces());
    off += &vectors(mesh.positions());
    for [a, b, c] in mesh.triangles() {
        let _ = writeln!(off, "3 {a} {b} {c}");
    }
    std::fs::write(dir.join("mesh.off"), off)?;
    let flags: String = roi.iter().map(|&r| if r { "1\n" } else { "0\n" }).collect();
    std::fs::write(dir.join("roi.txt"), flags)
}

/// The median of `samples` (seconds), in ms.
pub fn median_ms(mut samples: Vec<f64>) -> f64 {
    samples.sort_by(f64::total_cmp);
    samples[samples.len() / 2] * 1e3
}

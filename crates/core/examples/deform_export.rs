//! Writes the over-sketch edit of `benches/deform.rs` and our linear, exact-handle solution to
//! a directory, for `benches/libigl_compare.py` to solve again with libigl and compare, and
//! prints our own factor and solve times on the same problem.
//!
//! Run: `cargo run --release -p sketchmesh-core --example deform_export -- /tmp/deform_compare`
//! Files: `mesh.off`, `roi.txt` (0 or 1 per vertex), `handles.txt` (`v0 v1 v2 w0 w1 w2` per
//! handle), `targets.txt` and `ours_linear.txt` (`x y z` per line). Floats are written in
//! Rust's shortest round-trip form, so both sides read the same numbers.

use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use glam::DVec3;
use sketchmesh_core::deform::{EditParams, HandleFit, LaplacianEdit, Rotations};

#[path = "../benches/common/export.rs"]
mod export;
#[path = "../benches/common/off.rs"]
mod off;
#[path = "../benches/common/oversketch.rs"]
mod oversketch;
use export::{RUNS, median_ms, vectors};
use off::write_mesh_and_roi;
use oversketch::{oversketch_edit, sphere, targets};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = PathBuf::from(
        std::env::args()
            .nth(1)
            .unwrap_or_else(|| "/tmp/deform_compare".to_owned()),
    );
    std::fs::create_dir_all(&dir)?;
    let mesh = sphere();
    let (roi, handles) = oversketch_edit(&mesh);
    let targets = targets(&mesh, &handles);
    let params = EditParams {
        fit: HandleFit::Exact,
        rotations: Rotations::None,
    };

    let mut factor_times = Vec::new();
    let mut edit = LaplacianEdit::new(&mesh, &roi, &handles, params)?;
    for _ in 0..RUNS {
        let start = Instant::now();
        edit = LaplacianEdit::new(&mesh, &roi, &handles, params)?;
        factor_times.push(start.elapsed().as_secs_f64());
    }
    let mut out = vec![DVec3::ZERO; mesh.n_vertices()];
    let mut solve_times = Vec::new();
    for _ in 0..RUNS {
        let start = Instant::now();
        edit.deform(&targets, &mut out)?;
        solve_times.push(start.elapsed().as_secs_f64());
    }
    println!(
        "ours: {} vertices, ROI {}, {} handles; new {:.2} ms, deform {:.3} ms (median of {RUNS})",
        mesh.n_vertices(),
        edit.n_roi(),
        handles.len(),
        median_ms(factor_times),
        median_ms(solve_times)
    );

    write_mesh_and_roi(&dir, &mesh, &roi)?;
    let handle_lines = handles.iter().fold(String::new(), |mut s, h| {
        let [v0, v1, v2] = h.vertices().map(|v| v.0);
        let [w0, w1, w2] = h.weights();
        let _ = writeln!(s, "{v0} {v1} {v2} {w0} {w1} {w2}");
        s
    });
    std::fs::write(dir.join("handles.txt"), handle_lines)?;
    std::fs::write(dir.join("targets.txt"), vectors(&targets))?;
    std::fs::write(dir.join("ours_linear.txt"), vectors(&out))?;
    println!("wrote {}", dir.display());
    Ok(())
}

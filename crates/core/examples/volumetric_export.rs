//! Writes one frame of the volumetric graph Laplacian's system (the bench capsule, 28.6k
//! graph points: its left end held, its right end turned by 60°, the turn spread linearly)
//! and our solution to a directory, for `benches/libigl_volumetric.py` to solve the same
//! least squares with libigl and compare, and prints our own factor and solve times.
//!
//! Run: `cargo run --release -p sketchmesh-core --example volumetric_export -- /tmp/volumetric_compare`
//! Files: `a.txt` (`row col value` per entry, first line `rows cols`), `b.txt`, `known.txt`
//! (the fixed unknowns' indices), `known_values.txt` and `ours.txt` (the displacements,
//! `x y z` per line). Floats are written in Rust's shortest round-trip form.

use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use glam::DVec3;
use sketchmesh_core::volumetric::{Similarity, VolumetricEdit};

#[path = "../benches/common/export.rs"]
mod export;
#[path = "../benches/common/volumetric_capsule.rs"]
mod volumetric_capsule;
use export::{RUNS, median_ms, vectors};
use volumetric_capsule::Capsule;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = PathBuf::from(
        std::env::args()
            .nth(1)
            .unwrap_or_else(|| "/tmp/volumetric_compare".to_owned()),
    );
    std::fs::create_dir_all(&dir)?;
    let capsule = Capsule::new();
    let (mesh, graph) = (&capsule.mesh, &capsule.graph);
    let points = graph.points();
    let new_edit = || VolumetricEdit::new(mesh, graph, &capsule.constraints, capsule.params);
    let mut factor_times = Vec::new();
    let mut edit = new_edit()?;
    for _ in 0..RUNS {
        let start = Instant::now();
        edit = new_edit()?;
        factor_times.push(start.elapsed().as_secs_f64());
    }
    let mut transforms = vec![Similarity::IDENTITY; points.len()];
    let place = capsule.turn(60f64.to_radians(), &mut transforms);
    let mut out = vec![DVec3::ZERO; points.len()];
    let mut solve_times = Vec::new();
    for _ in 0..RUNS {
        let start = Instant::now();
        edit.deform(&transforms, &place, &[], &mut out)?;
        solve_times.push(start.elapsed().as_secs_f64());
    }
    println!(
        "volumetric, ours: capsule {} vertices, {} graph points; assemble and factor {:.1} ms, one frame's solve {:.2} ms (median of {RUNS})",
        mesh.n_vertices(),
        points.len(),
        median_ms(factor_times),
        median_ms(solve_times)
    );
    let (a, b, known, known_values) = edit.last_system();
    let mut entries = format!("{} {}\n", a.nrows(), a.ncols());
    for col in 0..a.ncols() {
        for (row, value) in a.column(col) {
            writeln!(entries, "{row} {col} {value}")?;
        }
    }
    std::fs::write(dir.join("a.txt"), entries)?;
    std::fs::write(dir.join("b.txt"), vectors(b))?;
    let known_indices: Vec<usize> = (0..known.len()).filter(|&j| known[j]).collect();
    let indices = known_indices.iter().fold(String::new(), |mut s, j| {
        let _ = writeln!(s, "{j}");
        s
    });
    std::fs::write(dir.join("known.txt"), indices)?;
    let values: Vec<DVec3> = known_indices.iter().map(|&j| known_values[j]).collect();
    std::fs::write(dir.join("known_values.txt"), vectors(&values))?;
    let displacements: Vec<DVec3> = out.iter().zip(points).map(|(o, p)| *o - *p).collect();
    std::fs::write(dir.join("ours.txt"), vectors(&displacements))?;
    Ok(())
}

//! Writes the least-squares system of a Laplacian mesh optimization of the Stanford bunny
//! (shape mode, W_cdf, s = 1: the defaults) and our solution to a directory, for
//! `benches/libigl_optimize.py` to solve the same normal equations with libigl and compare,
//! and prints our own factor and solve times.
//!
//! Run: `cargo run --release -p sketchmesh-core --example optimize_export -- /tmp/optimize_compare`
//! Files: `a.txt` (`row col value` per entry of the `2n × n` matrix, first line `rows cols`),
//! `b.txt` and `ours.txt` (`x y z` per line). Floats are written in Rust's shortest
//! round-trip form, so both sides read the same numbers. Needs `../shared/testdata`.

use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use sketchmesh_core::optimize::{OptimizeParams, Optimizer, Selection};

#[path = "../benches/common/export.rs"]
mod export;
#[path = "../benches/common/scan.rs"]
mod scan;
use export::{RUNS, median_ms, vectors};
use scan::scan;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = PathBuf::from(
        std::env::args()
            .nth(1)
            .unwrap_or_else(|| "/tmp/optimize_compare".to_owned()),
    );
    std::fs::create_dir_all(&dir)?;
    let mesh = scan("stanford_bunny.glb").ok_or("the shared test data is missing")?;
    let params = OptimizeParams::default();
    let mut factor_times = Vec::new();
    let mut optimizer = Optimizer::new(&mesh, &params, &Selection::default())?;
    for _ in 0..RUNS {
        let start = Instant::now();
        optimizer = Optimizer::new(&mesh, &params, &Selection::default())?;
        factor_times.push(start.elapsed().as_secs_f64());
    }
    let mut solve_times = Vec::new();
    let mut ours = optimizer.solve(params.scale)?;
    for _ in 0..RUNS {
        let start = Instant::now();
        ours = optimizer.solve(params.scale)?;
        solve_times.push(start.elapsed().as_secs_f64());
    }
    println!(
        "optimize, ours: bunny {} vertices, shape W_cdf s = 1; weights, system and factor {:.1} ms, solve {:.1} ms (median of {RUNS})",
        mesh.n_vertices(),
        median_ms(factor_times),
        median_ms(solve_times)
    );
    let (a, b) = optimizer
        .least_squares_system()
        .ok_or("the system is coupled")?;
    let mut entries = format!("{} {}\n", a.nrows(), a.ncols());
    for col in 0..a.ncols() {
        for (row, value) in a.column(col) {
            writeln!(entries, "{row} {col} {value}")?;
        }
    }
    std::fs::write(dir.join("a.txt"), entries)?;
    std::fs::write(dir.join("b.txt"), vectors(&b))?;
    std::fs::write(dir.join("ours.txt"), vectors(&ours))?;
    println!("wrote {}", dir.display());
    Ok(())
}

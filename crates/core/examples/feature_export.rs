//! Writes the region system of a feature sketch (`benches/feature.rs`'s bump over a lasso of
//! about 20k vertices) and our solution to a directory, for `benches/libigl_feature.py` to
//! solve again with libigl's `min_quad_with_fixed` and compare, and prints our own times.
//!
//! The system is the one `FeatureEdit` factors: on the mesh with the sketch embedded, the
//! normalised cotangent Laplacian rows of the region and its first anchor ring, unknowns the
//! region's displacements, anchors fixed, right-hand side the change of the Laplacian
//! coordinates (here a bump's, `(a − 1) δ` on the region). We time building and factoring it
//! (`FeatureEdit::region_system`, a `LaplacianEdit`) and one solve (`prescribed_displacement`); `FeatureEdit::new`, which
//! also places and embeds the sketch, is timed by the criterion bench.
//!
//! Run: `cargo run --release -p sketchmesh-core --example feature_export -- /tmp/feature_compare`
//! Files: `mesh.off`, `roi.txt`, `amount.txt` and `ours.txt` (`x y z` per vertex).

use std::path::PathBuf;
use std::time::Instant;

use glam::DVec3;
use sketchmesh_core::feature::{FeatureEdit, FeatureKind};

#[path = "../benches/common/export.rs"]
mod export;
#[path = "../benches/common/feature.rs"]
mod feature;
#[path = "../benches/common/off.rs"]
mod off;
use export::{RUNS, median_ms, vectors};
use off::write_mesh_and_roi;

/// The bump's factor.
const AMOUNT: f64 = 3.0;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = PathBuf::from(
        std::env::args()
            .nth(1)
            .unwrap_or_else(|| "/tmp/feature_compare".to_owned()),
    );
    std::fs::create_dir_all(&dir)?;
    let sphere = feature::sphere();
    let placed = FeatureEdit::new(&sphere, &feature::sketch(true), FeatureKind::Bump)?;
    let mut mesh = sphere.clone();
    mesh.positions_mut().copy_from_slice(placed.embedded());
    let mut roi = vec![false; mesh.n_vertices()];
    placed.roi().iter().for_each(|v| roi[v.index()] = true);
    let mut factor_times = Vec::new();
    let mut system = placed.region_system(&sphere)?;
    for _ in 0..RUNS {
        let start = Instant::now();
        system = placed.region_system(&sphere)?;
        factor_times.push(start.elapsed().as_secs_f64());
    }
    let change: Vec<DVec3> = system
        .laplacian_rows()
        .map(|(v, delta)| {
            if roi[v.index()] {
                (AMOUNT - 1.0) * delta
            } else {
                DVec3::ZERO
            }
        })
        .collect();
    let mut displacement = Vec::new();
    let mut solve_times = Vec::new();
    for _ in 0..RUNS {
        let start = Instant::now();
        displacement = system.prescribed_displacement(&change)?;
        solve_times.push(start.elapsed().as_secs_f64());
    }
    println!(
        "ours: {} vertices, region {}; build and factor {:.2} ms, solve {:.3} ms (median of {RUNS})",
        mesh.n_vertices(),
        system.n_roi(),
        median_ms(factor_times),
        median_ms(solve_times)
    );
    let mut ours = mesh.positions().to_vec();
    for (v, d) in system.roi_vertices().iter().zip(&displacement) {
        ours[v.index()] += *d;
    }
    write_mesh_and_roi(&dir, &mesh, &roi)?;
    std::fs::write(dir.join("amount.txt"), format!("{AMOUNT}\n"))?;
    std::fs::write(dir.join("ours.txt"), vectors(&ours))?;
    println!("wrote {}", dir.display());
    Ok(())
}

//! Laplacian mesh optimization on real scans and models (`../shared/testdata`): shape
//! optimization with the cumulative-distribution weights evens out their triangles within
//! half a percent of their size, and tangent-plane rows bring the result closer still.
//!
//! Where it cannot: Suzanne is a 500-vertex low-poly model, not a scan. Its one-rings are
//! far from flat, so moving a vertex toward its uniform centroid leaves the surface by
//! 3.5% of the diagonal (1% even with constant weights); tangent-plane rows bring that to
//! 1.3%. The worst radius ratio also falls on Spot (0.25 to 0.17): the scheme evens the
//! mean, not the worst triangle; `--quality` is the option for that. Igea (270k vertices)
//! is left to the benchmark, to keep the suite fast, and so is the
//! tangent-plane system above 10k vertices.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use crate::common::testdata_meshes as meshes;
use sketchmesh_core::mesh::Mesh;
use sketchmesh_core::optimize::{OptimizeParams, QualityReport, optimize, quality_report};

fn run(mesh: &Mesh, params: &OptimizeParams) -> QualityReport {
    let result = optimize(mesh, params).unwrap();
    quality_report(mesh, &result)
}

#[test]
fn shape_optimization_improves_every_scan_and_stays_on_it() {
    let cases = [
        ("spot.glb", 0.005),
        ("stanford_bunny.glb", 0.005),
        ("nefertiti.glb", 0.005),
        ("suzanne.glb", 0.05),
    ];
    for (name, limit) in cases {
        let Some(meshes) = meshes(name) else { return };
        for mesh in &meshes {
            let plain = run(mesh, &OptimizeParams::default());
            eprintln!("{name} ({} vertices), W_cdf: {plain:?}", mesh.n_vertices());
            assert!(
                plain.mean_radius_ratio > plain.input_mean_radius_ratio,
                "{name}: {plain:?}"
            );
            assert!(plain.hausdorff_relative < limit, "{name}: {plain:?}");
            if mesh.n_vertices() > 10_000 {
                // The coupled 3n system costs seconds at this size: left to the benchmark.
                continue;
            }
            let tangent = run(
                mesh,
                &OptimizeParams {
                    tangent_plane: true,
                    ..OptimizeParams::default()
                },
            );
            eprintln!("{name}, W_cdf + tangent plane: {tangent:?}");
            assert!(
                tangent.hausdorff_relative < plain.hausdorff_relative,
                "{name}: {tangent:?} vs {plain:?}"
            );
            assert!(tangent.mean_radius_ratio > tangent.input_mean_radius_ratio);
        }
    }
}

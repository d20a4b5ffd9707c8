//! Laplacian mesh optimization (`core::optimize`): the whole call (curvatures, weights, the
//! system, one sparse factorization, the solves) on scans of the shared test data and on a
//! subdivided sphere of 164k vertices, near the thesis's 17k and 173k (Fig. 6.5, §6.7).
//!
//! `optimize_rescale` is the exact result at a new scale on a kept [`Optimizer`] (what Apply
//! costs after the slider moved); `optimize_preview_step` is one step of the slider's preview.
//!
//! `cargo bench -p sketchmesh-core --bench core -- '^optimize_'`. The scans come from
//! `../shared/testdata`; without it the bench says so and runs the generated mesh only.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group};
use sketchmesh_core::mesh::{Mesh, primitives};
use sketchmesh_core::optimize::{OptimizeParams, Optimizer, Selection, optimize};

use crate::common::scan;
use scan::scan;

fn bench_optimize(c: &mut Criterion) {
    let mut group = c.benchmark_group("optimize_shape_cdf");
    group.sample_size(10);
    let mut cases: Vec<(String, Mesh)> = ["stanford_bunny.glb", "nefertiti.glb", "igea.glb"]
        .iter()
        .filter_map(|name| scan(name).map(|mesh| (name.trim_end_matches(".glb").to_owned(), mesh)))
        .collect();
    cases.push((String::from("sphere"), primitives::icosphere(1.0, 7)));
    for (name, mesh) in &cases {
        let id = BenchmarkId::from_parameter(format!("{name}_{}", mesh.n_vertices()));
        group.bench_function(id, |b| {
            b.iter(|| optimize(black_box(mesh), &OptimizeParams::default()).expect("solves"));
        });
    }
    group.finish();
    // The slider: a kept optimizer solving at a new scale (numeric refactorization on the
    // kept analysis, then a back-substitution), alternating so that every call refactors.
    let mut group = c.benchmark_group("optimize_rescale");
    group.sample_size(10);
    for (name, mesh) in &cases {
        let id = BenchmarkId::from_parameter(format!("{name}_{}", mesh.n_vertices()));
        let mut optimizer = Optimizer::new(mesh, &OptimizeParams::default(), &Selection::default())
            .expect("factors");
        let mut scale = 1.0;
        group.bench_function(id, |b| {
            b.iter(|| {
                scale = if scale == 1.0 { 0.5 } else { 1.0 };
                optimizer.solve(black_box(scale)).expect("solves")
            });
        });
    }
    group.finish();
    // A preview step of the slider: a conjugate-gradient iteration toward a new scale,
    // preconditioned by the kept factorization (each call starts toward another scale, so it
    // also sets the iteration up: the most a step costs).
    let mut group = c.benchmark_group("optimize_preview_step");
    group.sample_size(20);
    for (name, mesh) in &cases {
        let id = BenchmarkId::from_parameter(format!("{name}_{}", mesh.n_vertices()));
        let mut optimizer = Optimizer::new(mesh, &OptimizeParams::default(), &Selection::default())
            .expect("factors");
        let mut shown = optimizer.solve(1.0).expect("solves");
        let mut scale = 0.5;
        group.bench_function(id, |b| {
            b.iter(|| {
                scale = if scale == 0.5 { 0.6 } else { 0.5 };
                optimizer
                    .refine(black_box(scale), &mut shown)
                    .expect("solves")
            });
        });
    }
    group.finish();
}

criterion_group!(benches, bench_optimize);

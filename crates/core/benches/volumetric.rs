//! The volumetric graph Laplacian (`core::volumetric`, Zhou et al. 2005) on a capsule whose
//! graph has about 29k points: *graph* builds it (shells, lattice, collapse, smoothing, QP
//! weights), *factor* assembles and factors the energy for one handle set (a fixed end and
//! a handle end), *frame* is one drag frame (the handle's turn spread to every point, the
//! right-hand side, one back-substitution), *spread* and *solve* its two parts. Targets
//! (issue 20): graph under 300 ms, factor under 200 ms, a frame under 16 ms in the page.
//! Results go in BENCHMARKS.md. Run with
//! `cargo bench -p sketchmesh-core --bench core -- '^volumetric/' --warm-up-time 1 --measurement-time 3`.

use std::f64::consts::PI;
use std::hint::black_box;

use criterion::{Criterion, criterion_group};
use glam::DVec3;
use sketchmesh_core::volumetric::{Similarity, VolumetricEdit, VolumetricGraph};

use crate::common::volumetric_capsule;
use volumetric_capsule::Capsule;

fn bench_volumetric(c: &mut Criterion) {
    let capsule = Capsule::new();
    let (mesh, graph) = (&capsule.mesh, &capsule.graph);
    println!(
        "volumetric bench: {} vertices, {} graph points",
        mesh.n_vertices(),
        graph.n_points()
    );
    let new_edit =
        || VolumetricEdit::new(mesh, graph, &capsule.constraints, capsule.params).expect("factors");
    let mut edit = new_edit();
    let mut transforms = vec![Similarity::IDENTITY; graph.n_points()];
    let mut out = vec![DVec3::ZERO; graph.n_points()];
    let mut group = c.benchmark_group("volumetric");
    group.sample_size(10);
    group.bench_function("graph", |b| {
        b.iter(|| VolumetricGraph::build(black_box(mesh)).expect("builds"))
    });
    group.bench_function("factor", |b| b.iter(new_edit));
    let mut angle = 0.0;
    group.bench_function("frame", |b| {
        b.iter(|| {
            angle = (angle + 0.01) % PI;
            let place = capsule.turn(angle, &mut transforms);
            edit.deform(&transforms, place, &[], &mut out)
                .expect("solves");
            black_box(&out);
        })
    });
    // The frame's parts: the turn spread to every point, and the solve alone.
    group.bench_function("spread", |b| b.iter(|| capsule.turn(1.0, &mut transforms)));
    let place = capsule.turn(1.0, &mut transforms);
    group.bench_function("solve", |b| {
        b.iter(|| {
            edit.deform(&transforms, &place, &[], &mut out)
                .expect("solves")
        })
    });
    group.finish();
}

criterion_group!(benches, bench_volumetric);

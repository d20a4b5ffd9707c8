//! The volumetric graph Laplacian (`core::volumetric`, Zhou et al. 2005) on a capsule whose
//! graph has about 29k points: *graph* builds it (shells, lattice, collapse, smoothing, QP
//! weights), *factor* assembles and factors the energy for one handle set (a fixed end and
//! a handle end), *frame* is one drag frame (the handle's turn spread to every point, the
//! right-hand side, one back-substitution). Targets (issue 20): graph under 300 ms, factor
//! under 200 ms, a frame under 16 ms in the page. Results go in BENCHMARKS.md. Run with
//! `cargo bench -p sketchmesh-core --bench volumetric -- --warm-up-time 1 --measurement-time 3`.

use std::f64::consts::PI;
use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use glam::{DMat3, DVec3};
use sketchmesh_core::mesh::primitives;
use sketchmesh_core::volumetric::{
    Constraints, Falloff, Similarity, VolumetricEdit, VolumetricGraph, VolumetricParams, spread,
};

fn bench_volumetric(c: &mut Criterion) {
    let mesh = primitives::capsule(0.5, 3.0, 42, 126);
    let graph = VolumetricGraph::build(&mesh).expect("a closed capsule");
    println!(
        "volumetric bench: {} vertices, {} graph points",
        mesh.n_vertices(),
        graph.n_points()
    );
    let points = graph.points();
    let fixed: Vec<u32> = (0..points.len() as u32)
        .filter(|&i| points[i as usize].x < -2.0)
        .collect();
    let handle: Vec<u32> = (0..points.len() as u32)
        .filter(|&i| points[i as usize].x > 2.0)
        .collect();
    let mut hard = vec![false; points.len()];
    for &i in fixed.iter().chain(&handle) {
        hard[i as usize] = true;
    }
    let constraints = Constraints {
        hard,
        soft: Vec::new(),
    };
    let params = VolumetricParams::default();
    let handle_distances = vec![graph.distances(&mesh, &handle)];
    let fixed_distances = graph.distances(&mesh, &fixed);
    let mut edit = VolumetricEdit::new(&mesh, &graph, &constraints, params).expect("factors");
    let mut transforms = vec![Similarity::IDENTITY; points.len()];
    let mut out = vec![DVec3::ZERO; points.len()];
    let mut group = c.benchmark_group("volumetric");
    group.sample_size(10);
    group.bench_function("graph", |b| {
        b.iter(|| VolumetricGraph::build(black_box(&mesh)).expect("builds"))
    });
    group.bench_function("factor", |b| {
        b.iter(|| VolumetricEdit::new(&mesh, &graph, &constraints, params).expect("factors"))
    });
    let mut angle = 0.0;
    group.bench_function("frame", |b| {
        b.iter(|| {
            angle += 0.01;
            let turn = Similarity::nearest(DMat3::from_rotation_z(angle % PI)).expect("a turn");
            spread(
                &[turn],
                &handle_distances,
                &fixed_distances,
                Falloff::Linear,
                &mut transforms,
            );
            let rotate = glam::DMat4::from_rotation_z(angle % PI);
            edit.deform(
                &transforms,
                |_, p| {
                    if p.x > 2.0 {
                        rotate.transform_point3(p)
                    } else {
                        p
                    }
                },
                &[],
                &mut out,
            )
            .expect("solves");
            black_box(&out);
        })
    });
    // The frame's parts: the turn spread to every point, and the solve alone.
    let turn = Similarity::nearest(DMat3::from_rotation_z(1.0)).expect("a turn");
    group.bench_function("spread", |b| {
        b.iter(|| {
            spread(
                &[turn],
                &handle_distances,
                &fixed_distances,
                Falloff::Linear,
                &mut transforms,
            )
        })
    });
    let rotate = glam::DMat4::from_rotation_z(1.0);
    group.bench_function("solve", |b| {
        b.iter(|| {
            edit.deform(
                &transforms,
                |_, p| rotate.transform_point3(p),
                &[],
                &mut out,
            )
            .expect("solves")
        })
    });
    group.finish();
}

criterion_group!(benches, bench_volumetric);
criterion_main!(benches);

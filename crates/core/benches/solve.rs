//! Sparse least-squares solves at 1k, 10k and 100k unknowns: factor, refactor and solve apart.
//!
//! The system is shaped like FiberMesh's (Nealen et al. 2007): the uniform Laplacian of a
//! closed torus mesh stacked on soft positional rows `w x_i = w p_i` for every tenth vertex,
//! with nothing fixed, solved for x, y and z together. Results go in BENCHMARKS.md. Run with
//! `cargo bench -p sketchmesh-core --bench core -- '^(factor|refactor_values|solve)/' --warm-up-time 1 --measurement-time 3`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group};
use glam::DVec3;
use sketchmesh_core::geometry::uniform_laplacian;
use sketchmesh_core::mesh::{Mesh, primitives};
use sketchmesh_core::solve::{Prefactored, SparseMatrix, Triplets};

/// Weight of the soft positional rows relative to the Laplacian rows.
const ANCHOR_WEIGHT: f64 = 1.0;

/// A closed torus with about `n` vertices: `4 m` segments around the axis, `m` around the tube.
fn torus_with_about(n: usize) -> Mesh {
    let m = ((n as f64 / 4.0).sqrt().round() as usize).max(3);
    primitives::torus(2.0, 0.5, 4 * m, m)
}

/// `[L; w I_anchors]` and its right-hand side `[0; w p_anchors]`.
fn fibermesh_system(mesh: &Mesh) -> (SparseMatrix, Vec<DVec3>) {
    let n = mesh.n_vertices();
    let anchors: Vec<usize> = (0..n).step_by(10).collect();
    let mut triplets = Triplets::new(n + anchors.len(), n);
    triplets.push_matrix(&uniform_laplacian(mesh), 0, 0, 1.0);
    let mut rhs = vec![DVec3::ZERO; n];
    for (k, &v) in anchors.iter().enumerate() {
        triplets.push(n + k, v, ANCHOR_WEIGHT);
        rhs.push(ANCHOR_WEIGHT * mesh.positions()[v] * 1.1);
    }
    (triplets.build(), rhs)
}

fn bench_solve(c: &mut Criterion) {
    let sizes = [1_000, 10_000, 100_000];
    let systems: Vec<(usize, SparseMatrix, Vec<DVec3>)> = sizes
        .iter()
        .map(|&n| {
            let mesh = torus_with_about(n);
            let (a, rhs) = fibermesh_system(&mesh);
            (mesh.n_vertices(), a, rhs)
        })
        .collect();

    let mut group = c.benchmark_group("factor");
    group.sample_size(10);
    for (n, a, _) in &systems {
        let fixed = vec![false; *n];
        group.bench_with_input(BenchmarkId::from_parameter(n), a, |b, a| {
            b.iter(|| Prefactored::new(black_box(a), &fixed).expect("system is well posed"));
        });
    }
    group.finish();

    let mut group = c.benchmark_group("refactor_values");
    group.sample_size(10);
    for (n, a, _) in &systems {
        let mut solver = Prefactored::new(a, &vec![false; *n]).expect("system is well posed");
        let mut stiffer = a.clone();
        stiffer.values_mut().iter_mut().for_each(|v| *v *= 1.5);
        group.bench_with_input(BenchmarkId::from_parameter(n), &stiffer, |b, stiffer| {
            b.iter(|| {
                solver
                    .refactor_values(black_box(stiffer))
                    .expect("same pattern")
            });
        });
    }
    group.finish();

    let mut group = c.benchmark_group("solve");
    for (n, a, rhs) in &systems {
        let mut solver = Prefactored::new(a, &vec![false; *n]).expect("system is well posed");
        let fixed_values = vec![DVec3::ZERO; *n];
        let mut out = vec![DVec3::ZERO; *n];
        group.bench_with_input(BenchmarkId::from_parameter(n), rhs, |b, rhs| {
            b.iter(|| {
                solver
                    .solve(black_box(rhs), &fixed_values, &mut out)
                    .expect("lengths match")
            });
        });
    }
    group.finish();
}

criterion_group!(benches, bench_solve);

//! Silhouette extraction for over-sketching on a sphere with 40,962 vertices (icosphere,
//! 6 subdivisions) and a bumpy torus with 34,960: BVH build and refit, and
//! [`silhouettes`] (normals, contour chaining, one occlusion ray per point, thinning,
//! smoothing). The whole over-sketch (silhouettes, matching, deformation) should take under
//! 40 ms natively, so silhouettes under 10 ms. Results go in BENCHMARKS.md. Run with
//! `cargo bench -p sketchmesh-core --bench core -- '^(bvh_build|bvh_refit|silhouettes)/' --warm-up-time 1 --measurement-time 3`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group};
use glam::{DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::geometry::{Bvh, vertex_normals};
use sketchmesh_core::mesh::{Mesh, primitives};
use sketchmesh_core::silhouette::silhouettes;

const VIEWPORT: DVec2 = DVec2::new(1280.0, 720.0);

/// A torus with bumps along its normals: many small silhouette loops and self-occlusion.
fn bumpy_torus() -> Mesh {
    let (n_major, n_minor) = (380, 92);
    let mut mesh = primitives::torus(1.0, 0.35, n_major, n_minor);
    let normals = vertex_normals(&mesh);
    for (k, p) in mesh.positions_mut().iter_mut().enumerate() {
        let (i, j) = (k / n_minor, k % n_minor);
        let u = std::f64::consts::TAU * i as f64 / n_major as f64;
        let v = std::f64::consts::TAU * j as f64 / n_minor as f64;
        *p += normals[k] * 0.02 * (12.0 * u).sin() * (6.0 * v).sin();
    }
    mesh
}

fn cases() -> Vec<(&'static str, Mesh, Camera)> {
    let three_quarter = Camera {
        eye: DVec3::new(2.0, -3.0, 2.0),
        ..Camera::default()
    };
    vec![
        (
            "sphere_40962",
            primitives::icosphere(1.0, 6),
            Camera::default(),
        ),
        ("bumpy_torus_34960", bumpy_torus(), three_quarter),
    ]
}

fn bench_silhouettes(c: &mut Criterion) {
    let cases = cases();
    let mut group = c.benchmark_group("bvh_build");
    for (name, mesh, _) in &cases {
        group.bench_with_input(BenchmarkId::from_parameter(name), mesh, |b, mesh| {
            b.iter(|| Bvh::new(black_box(mesh)));
        });
    }
    group.finish();

    let mut group = c.benchmark_group("bvh_refit");
    for (name, mesh, _) in &cases {
        let mut bvh = Bvh::new(mesh);
        group.bench_function(BenchmarkId::from_parameter(name), |b| {
            b.iter(|| bvh.refit(black_box(mesh)));
        });
    }
    group.finish();

    let mut group = c.benchmark_group("silhouettes");
    for (name, mesh, camera) in &cases {
        let bvh = Bvh::new(mesh);
        group.bench_function(BenchmarkId::from_parameter(name), |b| {
            b.iter(|| silhouettes(black_box(mesh), &bvh, camera, VIEWPORT));
        });
    }
    group.finish();
}

criterion_group!(benches, bench_silhouettes);

//! Adding a control curve ([`add_curve`]) on icospheres of 2,562, 10,242 and 40,962
//! vertices under the default camera in an 800×600 viewport: an open wavy stroke across
//! the front, a closed loop on the front and a cross section through the whole sphere. The
//! target is well under 20 ms at 10k vertices natively. Results go in BENCHMARKS.md.
//! Run with `cargo bench -p sketchmesh-core --bench core -- '^add_curve_' --warm-up-time 1 --measurement-time 3`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group};
use glam::{DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::fibermesh::add_curve::{CurveShape, add_curve};
use sketchmesh_core::mesh::primitives;

const VIEWPORT: DVec2 = DVec2::new(800.0, 600.0);

/// The screen point over the unit sphere's front at `(x, y)`.
fn over_front(x: f64, y: f64) -> DVec2 {
    let p = DVec3::new(x, y, (1.0 - x * x - y * y).sqrt());
    Camera::default()
        .screen_from_world(p, VIEWPORT)
        .map_or(DVec2::ZERO, |s| s.truncate())
}

fn strokes() -> Vec<(&'static str, Vec<DVec2>, CurveShape)> {
    let wavy = (0..=60)
        .map(|i| {
            let x = -0.8 + 1.6 * i as f64 / 60.0;
            over_front(x, 0.15 + 0.2 * (4.0 * x).sin())
        })
        .collect();
    let closed = (0..60)
        .map(|i| {
            let angle = std::f64::consts::TAU * i as f64 / 60.0;
            over_front(0.5 * angle.cos(), 0.5 * angle.sin())
        })
        .collect();
    let across = vec![DVec2::new(100.0, 310.0), DVec2::new(700.0, 290.0)];
    vec![
        ("open", wavy, CurveShape::Open),
        ("closed", closed, CurveShape::Closed),
        ("cross_section", across, CurveShape::CrossSection),
    ]
}

fn bench_add_curve(c: &mut Criterion) {
    let camera = Camera::default();
    for (name, stroke, shape) in strokes() {
        let mut group = c.benchmark_group(format!("add_curve_{name}"));
        for subdivisions in [4, 5, 6] {
            let mesh = primitives::icosphere(1.0, subdivisions);
            group.bench_with_input(
                BenchmarkId::from_parameter(mesh.n_vertices()),
                &mesh,
                |b, mesh| {
                    b.iter(|| add_curve(black_box(mesh), &camera, VIEWPORT, &stroke, shape));
                },
            );
        }
        group.finish();
    }
}

criterion_group!(benches, bench_add_curve);

//! FiberMesh creation from a circle-like stroke at 2k, 10k and 40k vertices: time to the
//! first display ([`seed_from_stroke`]: outline, triangulation, seed), to the first
//! optimized mesh ([`create_from_stroke`]: the seed plus both factorizations and one
//! iteration), to convergence, and one iteration (targets: under 50 ms to first display and
//! under 300 ms to convergence at 10k in the browser, which runs about 2-3x slower than
//! native; one iteration at 10k under 8 ms natively). Results go in BENCHMARKS.md. Run with
//! `cargo bench -p sketchmesh-core --bench core -- '^fibermesh_' --warm-up-time 1 --measurement-time 3`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group};
use glam::DVec2;
use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::StrokePoint;
use sketchmesh_core::fibermesh::{
    CreateError, CreateParams, create_converged_from_stroke, create_from_stroke, seed_from_stroke,
};

const VIEWPORT: DVec2 = DVec2::new(1280.0, 720.0);

/// A hand-drawn-like circle of radius 250 px: slightly wobbly, with a small gap.
fn circle_like_stroke() -> Vec<StrokePoint> {
    let n = 400;
    (0..n)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / n as f64 * 0.98;
            let r = 250.0 * (1.0 + 0.03 * (3.0 * t).sin() + 0.02 * (5.0 * t + 1.0).cos());
            StrokePoint::new(DVec2::new(640.0, 360.0) + r * DVec2::from_angle(t), 0.5)
        })
        .collect()
}

/// One group timing `create` at each target vertex count.
fn bench_sizes(
    c: &mut Criterion,
    name: &str,
    sizes: &[usize],
    create: impl Fn(&CreateParams) -> Result<(), CreateError>,
) {
    let mut group = c.benchmark_group(name);
    group.sample_size(10);
    for &n in sizes {
        let params = CreateParams {
            target_vertices: n,
            ..CreateParams::default()
        };
        group.bench_with_input(BenchmarkId::from_parameter(n), &params, |b, params| {
            b.iter(|| create(params).expect("stroke is fine"));
        });
    }
    group.finish();
}

fn bench_creation(c: &mut Criterion) {
    let stroke = circle_like_stroke();
    let camera = Camera::default();
    let sizes = [2_000, 10_000, 40_000];

    bench_sizes(c, "fibermesh_first_display", &sizes, |params| {
        seed_from_stroke(black_box(&stroke), &camera, VIEWPORT, params).map(drop)
    });
    bench_sizes(c, "fibermesh_first_iteration", &sizes, |params| {
        create_from_stroke(black_box(&stroke), &camera, VIEWPORT, params).map(drop)
    });
    bench_sizes(c, "fibermesh_converged", &sizes, |params| {
        create_converged_from_stroke(black_box(&stroke), &camera, VIEWPORT, params).map(drop)
    });

    let mut group = c.benchmark_group("fibermesh_iteration");
    for &n in &sizes {
        let params = CreateParams {
            target_vertices: n,
            ..CreateParams::default()
        };
        let mut creation =
            create_from_stroke(&stroke, &camera, VIEWPORT, &params).expect("stroke is fine");
        let n_vertices = creation.mesh.n_vertices();
        group.bench_function(BenchmarkId::from_parameter(n_vertices), |b| {
            b.iter(|| {
                creation
                    .surface
                    .iterate(creation.mesh.positions_mut())
                    .expect("lengths match")
            });
        });
    }
    group.finish();
}

criterion_group!(benches, bench_creation);

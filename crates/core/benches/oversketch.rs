//! Over-sketch handle matching: [`match_stroke`] of a 200-point stroke against 10
//! silhouettes of 500 points each, once with every silhouette within reach of the stroke's
//! ends (the worst case: nested wavy loops) and once with the silhouettes spread over the
//! screen so that only one is near (the usual case). The whole over-sketch must stay under
//! 40 ms natively, so matching should take a few ms at most. Results go in BENCHMARKS.md.
//!
//! `oversketch_whole` times the whole [`oversketch`] call (BVH, silhouettes, matching,
//! ROI, factorization and the ARAP edit) on a 40,962-vertex icosphere, with a stroke
//! pushing a sixth of the outline out by up to 40 px; `oversketch_part` the same on a
//! 40,962-vertex horned sphere with SEED's part ROI (SDF, mixtures, region growing) against
//! the default ROI.
//! Run with `cargo bench -p sketchmesh-core --bench core -- '^oversketch_' --warm-up-time 1 --measurement-time 3`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group};
use glam::DVec2;
use sketchmesh_core::camera::Camera;
use sketchmesh_core::deform::HandleFit;
use sketchmesh_core::geometry::Bvh;
use sketchmesh_core::mesh::primitives;
use sketchmesh_core::oversketch::{
    BendOptions, MatchParams, OversketchRoi, match_stroke, oversketch, oversketch_with,
};
use sketchmesh_core::silhouette::silhouettes;

const SILHOUETTE_POINTS: usize = 500;

/// A closed wavy loop of `SILHOUETTE_POINTS` points (first point repeated at the end).
fn wavy_loop(center: DVec2, radius: f64, phase: f64) -> Vec<DVec2> {
    (0..=SILHOUETTE_POINTS)
        .map(|k| {
            let t =
                std::f64::consts::TAU * (k % SILHOUETTE_POINTS) as f64 / SILHOUETTE_POINTS as f64;
            let r = radius * (1.0 + 0.05 * (5.0 * t + phase).sin());
            center + r * DVec2::from_angle(t)
        })
        .collect()
}

/// A 200-point, slightly wobbly stroke over the right side of a loop about `center`.
fn stroke(center: DVec2) -> Vec<DVec2> {
    (0..200)
        .map(|k| {
            let t = (-35.0 + 70.0 * k as f64 / 199.0).to_radians();
            let wobble = 0.5 * (0.9 * k as f64).sin();
            center + (190.0 + wobble) * DVec2::from_angle(t)
        })
        .collect()
}

fn bench_match(c: &mut Criterion) {
    let center = DVec2::new(640.0, 360.0);
    let nested: Vec<Vec<DVec2>> = (0..10)
        .map(|k| wavy_loop(center, 140.0 + 8.0 * k as f64, 0.3 * k as f64))
        .collect();
    let spread: Vec<Vec<DVec2>> = (0..10)
        .map(|k| {
            let cell = DVec2::new((k % 5) as f64 * 500.0, (k / 5) as f64 * 500.0);
            wavy_loop(center + cell, 170.0, 0.3 * k as f64)
        })
        .collect();
    let stroke = stroke(center);
    let params = MatchParams::default();

    let mut group = c.benchmark_group("oversketch_match");
    for (name, silhouettes) in [("nested", &nested), ("spread", &spread)] {
        let slices: Vec<&[DVec2]> = silhouettes.iter().map(Vec::as_slice).collect();
        group.bench_with_input(BenchmarkId::from_parameter(name), &slices, |b, slices| {
            b.iter(|| match_stroke(black_box(&stroke), black_box(slices), &params));
        });
    }
    group.finish();
}

/// The part of the longest silhouette within 60 degrees of the rightmost point, pushed
/// outward by up to `push` px (`push · sin(π u)`, so it starts and ends on the outline).
fn pushed_outline_stroke(
    mesh: &sketchmesh_core::mesh::Mesh,
    viewport: DVec2,
    push: f64,
) -> Vec<DVec2> {
    let camera = Camera::default();
    let bvh = Bvh::new(mesh);
    let curves = silhouettes(mesh, &bvh, &camera, viewport);
    let Some(outline) = curves
        .iter()
        .max_by(|a, b| a.screen_length().total_cmp(&b.screen_length()))
    else {
        return Vec::new();
    };
    let centre = 0.5 * viewport;
    let piece: Vec<DVec2> = outline
        .points
        .iter()
        .map(|p| p.screen)
        .filter(|p| (*p - centre).x > 0.5 * (*p - centre).length())
        .collect();
    let mut piece = piece;
    piece.sort_by(|a, b| a.y.total_cmp(&b.y));
    let last = (piece.len().max(2) - 1) as f64;
    piece
        .iter()
        .enumerate()
        .map(|(k, &p)| {
            let u = k as f64 / last;
            p + (p - centre).normalize() * push * (std::f64::consts::PI * u).sin()
        })
        .collect()
}

fn bench_whole(c: &mut Criterion) {
    let viewport = DVec2::new(1000.0, 1000.0);
    let camera = Camera::default();
    let mut group = c.benchmark_group("oversketch_whole");
    group.sample_size(20);
    for (name, mesh) in [
        ("icosphere_40962", primitives::icosphere(1.0, 6)),
        ("bumpy_torus_36864", primitives::bumpy_torus(0.03, 384, 96)),
    ] {
        let stroke = pushed_outline_stroke(&mesh, viewport, 40.0);
        group.bench_function(name, |b| {
            b.iter(|| {
                let result = oversketch(black_box(&mesh), &camera, viewport, black_box(&stroke));
                assert!(result.is_ok(), "{result:?}");
                result
            });
        });
    }
    group.finish();
}

fn bench_part(c: &mut Criterion) {
    let viewport = DVec2::new(1000.0, 1000.0);
    let camera = Camera::default();
    let mesh = primitives::horned_sphere(6, 1.2, 0.22);
    let stroke = pushed_outline_stroke(&mesh, viewport, 40.0);
    let mut group = c.benchmark_group("oversketch_part");
    group.sample_size(10);
    for (name, roi) in [
        ("near_handle", OversketchRoi::NearHandle),
        ("part", OversketchRoi::Part),
    ] {
        let options = BendOptions {
            fit: HandleFit::Exact,
            roi,
        };
        group.bench_function(name, |b| {
            b.iter(|| {
                let result = oversketch_with(&mesh, &camera, viewport, black_box(&stroke), options);
                assert!(result.is_ok(), "{result:?}");
                result
            });
        });
    }
    group.finish();
}

criterion_group!(benches, bench_match, bench_whole, bench_part);

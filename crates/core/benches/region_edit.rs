//! Region editing (`core::region_edit`) on a 163,842-vertex icosphere seen from the front
//! (orthographic): `RegionEdit::new` for a reference curve across the front and a boundary
//! around about 50k vertices (the curves placed, the region grown, two Dijkstra passes, the
//! weights), one drag frame (the transform's fractions, then every region vertex moved by
//! `w ⊙ T`), a handles frame, the region laid flat in the disc (whole and in its three
//! steps), and a re-sketched profile
//! swept along the curve. Targets (issue 22): setup under 100 ms natively at 50k; a frame well under
//! 16 ms. Results go in BENCHMARKS.md. Run with
//! `cargo bench -p sketchmesh-core --bench core -- '^region_edit/' --warm-up-time 1 --measurement-time 3`.

use std::hint::black_box;

use criterion::{Criterion, criterion_group};
use glam::{DMat4, DQuat, DVec2, DVec3};
use sketchmesh_core::mesh::primitives;
use sketchmesh_core::region_edit::{Handle, Levels, RegionEdit, RegionSketch, checked_transform};

use crate::common::feature;

/// The boundary's radius as a fraction of the sphere's on screen: the front-facing cap
/// inside it holds 30% of the sphere, about 50k vertices.
const BOUNDARY: f64 = 0.92;

fn sketch() -> RegionSketch {
    let along = feature::sketch(false);
    let centre = (along.camera)
        .screen_from_world(DVec3::Z, along.viewport)
        .expect("in front")
        .truncate();
    let rim = (along.camera)
        .screen_from_world(DVec3::X, along.viewport)
        .expect("in front")
        .x
        - centre.x;
    RegionSketch {
        camera: along.camera,
        viewport: along.viewport,
        boundary: (0..128)
            .map(|i| {
                let turn = std::f64::consts::TAU * f64::from(i) / 128.0;
                centre + BOUNDARY * rim * DVec2::from_angle(turn)
            })
            .collect(),
        reference: along.points,
    }
}

fn bench_region_edit(c: &mut Criterion) {
    let mesh = primitives::icosphere(1.0, 7);
    let sketch = sketch();
    let levels = Levels::default();
    let edit = RegionEdit::new(&mesh, &sketch, &levels).expect("the curves are on the sphere");
    println!(
        "region bench: {} vertices, region {}, reference {}",
        mesh.n_vertices(),
        edit.vertices().len(),
        edit.reference().len()
    );
    let mut group = c.benchmark_group("region_edit");
    group.sample_size(10);
    group.bench_function("new_50k", |b| {
        b.iter(|| RegionEdit::new(black_box(&mesh), &sketch, &levels).expect("placed"));
    });
    // A bump across the cross-section at the curve's middle, swept along the curve: a
    // re-sketched profile, paid once per stroke.
    let profile = edit.profile(0.5).expect("a cross-section");
    let (lo, hi) = (
        profile.points[0].x,
        profile.points[profile.points.len() - 1].x,
    );
    let stroke: Vec<DVec2> = (0..=40)
        .map(|i| {
            let t = f64::from(i) / 40.0;
            let u = lo + (hi - lo) * (0.3 + 0.4 * t);
            DVec2::new(u, 0.1 * (hi - lo) * (std::f64::consts::PI * t).sin())
        })
        .collect();
    group.bench_function("profile_50k", |b| {
        b.iter(|| {
            edit.profile_applied(black_box(0.5), &stroke)
                .expect("applied")
        });
    });
    group.bench_function("disc_50k", |b| {
        b.iter(|| black_box(&edit).disc().expect("a disc"));
    });
    // The disc's three steps, a frame each in the page: the system analysed, factored,
    // then solved.
    group.bench_function("disc_analysed_50k", |b| {
        b.iter(|| black_box(&edit).flattening().expect("a disc"));
    });
    group.bench_function("disc_factored_50k", |b| {
        b.iter_batched(
            || edit.flattening().expect("a disc"),
            |mut flattening| {
                flattening.factor().expect("factored");
                flattening
            },
            criterion::BatchSize::LargeInput,
        );
    });
    group.bench_function("disc_solved_50k", |b| {
        b.iter_batched(
            || {
                let mut flattening = edit.flattening().expect("a disc");
                flattening.factor().expect("factored");
                flattening
            },
            |flattening| flattening.finish().expect("solved"),
            criterion::BatchSize::LargeInput,
        );
    });
    let base = edit.mesh().positions();
    let mut out = base.to_vec();
    let mut frame = 0.0;
    group.bench_function("frame_50k", |b| {
        b.iter(|| {
            // A new transform each frame, as a drag makes: a lift with a little turn.
            frame += 1e-3;
            let turn = DMat4::from_quat(DQuat::from_rotation_x(0.3 + frame));
            let t = DMat4::from_translation(DVec3::new(0.0, 0.2 + frame, 0.1)) * turn;
            let fractions = checked_transform(&t.to_cols_array()).expect("a real logarithm");
            edit.apply_into(&fractions.into(), base, &mut out);
        });
    });
    group.bench_function("handles_frame_50k", |b| {
        b.iter(|| {
            // Three handles, the middle one dragged: every path vertex between the pins
            // blends its own transform.
            frame += 1e-3;
            let pin = |at: f64| Handle {
                at,
                transform: DMat4::IDENTITY,
            };
            let turn = DMat4::from_quat(DQuat::from_rotation_x(0.3 + frame));
            let middle = Handle {
                at: 0.5,
                transform: DMat4::from_translation(DVec3::new(0.0, 0.2 + frame, 0.1)) * turn,
            };
            let motion = edit
                .motion(&[pin(0.0), middle, pin(1.0)])
                .expect("real logarithms");
            edit.apply_into(&motion, base, &mut out);
        });
    });
    group.finish();
}

criterion_group!(benches, bench_region_edit);

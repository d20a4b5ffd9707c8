//! Curve handles (`core::skeleton`, Blanco) on a 500k-vertex bar (a capsule along x, 1,000
//! rings of 500), seen from the front: a stroke along its whole length, so every vertex is
//! deformed. *place* is a `curve_handle` op's work (the stroke filtered, four samples cast
//! onto the triangles), *bind* a drag's first step (the region grown, every vertex bound to
//! its slab), *frame* one drag frame (200 new frames, then every vertex rebuilt), *skeleton*
//! placing a skeleton handle (the centroids of the region's slices too). Targets (issue 21):
//! a frame under 16 ms at 500k (60 fps, the page), setup per stroke under 100 ms. Results go
//! in BENCHMARKS.md. Run with
//! `cargo bench -p sketchmesh-core --bench core -- '^skeleton 500k/' --warm-up-time 1 --measurement-time 3`.

use std::hint::black_box;

use criterion::{Criterion, criterion_group};
use glam::{DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::mesh::primitives;
use sketchmesh_core::skeleton::{
    Deformation, HandleKind, HandleStroke, Mover, PointEdit, Shape, place_handle,
};

const VIEWPORT: DVec2 = DVec2::new(1000.0, 800.0);

fn bench_skeleton(c: &mut Criterion) {
    let mesh = primitives::capsule(0.2, 1.0, 500, 1001);
    let shape = Shape {
        positions: mesh.positions(),
        triangles: mesh.triangles(),
    };
    let camera = Camera {
        eye: DVec3::new(0.0, 0.0, 3.5),
        ..Camera::default()
    };
    let (from, to) = (
        camera
            .screen_from_world(DVec3::new(-1.0, 0.0, 0.2), VIEWPORT)
            .expect("in view"),
        camera
            .screen_from_world(DVec3::new(1.0, 0.0, 0.2), VIEWPORT)
            .expect("in view"),
    );
    let points: Vec<DVec2> = (0..=100)
        .map(|i| from.truncate().lerp(to.truncate(), f64::from(i) / 100.0))
        .collect();
    let stroke = HandleStroke {
        points: &points,
        camera: &camera,
        viewport: VIEWPORT,
    };
    let handle = place_handle(&shape, &stroke, HandleKind::Surface, 4, false).expect("on the bar");
    let movers = [Mover {
        rest: &handle,
        links: &[],
    }];
    let deformation = Deformation::new(&shape, &movers).expect("a region");
    println!(
        "skeleton bench: {} vertices, {:?} region/rigid/blended",
        mesh.n_vertices(),
        deformation.counts()
    );
    let pose = handle
        .edited(&PointEdit {
            point: 2,
            translate: Some(DVec3::new(0.0, 0.3, 0.0)),
            twist: Some(0.5),
            ..PointEdit::default()
        })
        .expect("a valid edit");
    let mut out = vec![DVec3::ZERO; mesh.n_vertices()];
    let mut group = c.benchmark_group("skeleton 500k");
    group.sample_size(10);
    group.bench_function("place", |b| {
        b.iter(|| place_handle(&shape, black_box(&stroke), HandleKind::Surface, 4, false))
    });
    group.bench_function("bind", |b| {
        b.iter(|| Deformation::new(&shape, black_box(&movers)))
    });
    group.bench_function("frame", |b| {
        b.iter(|| {
            deformation.apply_into(
                mesh.positions(),
                std::slice::from_ref(black_box(&pose)),
                &mut out,
            )
        })
    });
    group.bench_function("skeleton", |b| {
        b.iter(|| place_handle(&shape, black_box(&stroke), HandleKind::Skeleton, 4, false))
    });
    group.finish();
}

criterion_group!(benches, bench_skeleton);

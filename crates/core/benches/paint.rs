//! One sample of a paint stroke on a 655,362-vertex sphere (a large scan's size), with a
//! brush whose ball covers about 5,000 vertices: the view ray, the dab's faces from the
//! hierarchy and their vertices' strengths. Target (issue 51): at most 4 ms natively. The
//! hierarchy is built once per stroke, timed apart. Results go in BENCHMARKS.md.
//! Run with `cargo bench -p sketchmesh-core --bench core -- '^paint/'`.

use std::hint::black_box;

use criterion::{Criterion, criterion_group};
use glam::DVec2;
use sketchmesh_core::camera::Camera;
use sketchmesh_core::geometry::Bvh;
use sketchmesh_core::mesh::primitives;
use sketchmesh_core::paint::{Brush, PaintStroke, dabs_between};

const VIEWPORT: DVec2 = DVec2::new(800.0, 600.0);

fn bench_paint(c: &mut Criterion) {
    let mesh = primitives::icosphere(1.0, 8);
    let camera = Camera::default();
    let brush = Brush {
        color: [0.8, 0.1, 0.1],
        radius: 32.0,
        hardness: 0.5,
        opacity: 1.0,
    };
    let mut group = c.benchmark_group("paint");
    group.sample_size(10);
    group.bench_function("hierarchy_655k", |b| b.iter(|| black_box(Bvh::new(&mesh))));
    let bvh = Bvh::new(&mesh);
    let mut stroke = PaintStroke::new(mesh.n_vertices());
    let reach = dabs_between(
        &camera,
        VIEWPORT,
        None,
        [400.0, 300.0, 0.5],
        &brush,
        &mesh,
        &bvh,
    );
    stroke.dab(&mesh, &bvh, &reach[0], &brush);
    eprintln!("paint: one dab reaches {} vertices", stroke.touched().len());
    group.sample_size(50);
    let mut k = 0usize;
    group.bench_function("sample_655k_5k_vertices", |b| {
        b.iter(|| {
            // Along a line across the front, 8 px a sample.
            let x = 300.0 + 8.0 * (k % 25) as f64;
            k += 1;
            let from = Some([x - 8.0, 300.0, 0.5]);
            for dab in dabs_between(
                &camera,
                VIEWPORT,
                from,
                [x, 300.0, 0.5],
                &brush,
                &mesh,
                &bvh,
            ) {
                stroke.dab(&mesh, &bvh, &dab, &brush);
            }
        });
    });
    group.finish();
}

criterion_group!(benches, bench_paint);

//! glTF import and export of a 1 M-triangle model (issue target: import < 400 ms, export
//! < 300 ms natively). The model is a 708 × 708 grid with a wave, written by Sketchmesh's own
//! exporter, so the import measures the parse, accessor reads, weld and manifold check of a
//! clean file. Run with `cargo bench -p sketchmesh-core --bench gltf`.

use std::hint::black_box;
use std::sync::Arc;

use criterion::{Criterion, criterion_group, criterion_main};
use sketchmesh_core::document::{Document, Model};
use sketchmesh_core::io::{ImportFile, ImportLimits, import_gltf, write_glb};
use sketchmesh_core::mesh::primitives;

fn million_triangle_document() -> Document {
    let mut mesh = primitives::grid(708, 708, 10.0);
    for p in mesh.positions_mut() {
        p.z = 0.3 * (p.x * 2.0).sin() * (p.y * 3.0).cos();
    }
    Document {
        models: vec![Arc::new(Model {
            mesh,
            ..Model::default()
        })],
        ..Document::default()
    }
}

fn bench_gltf(c: &mut Criterion) {
    let document = million_triangle_document();
    let triangles = document.stats().triangles;
    let glb = write_glb(&document);
    let mut group = c.benchmark_group(format!("gltf {triangles} triangles"));
    group.sample_size(10);
    group.bench_function("export", |b| b.iter(|| write_glb(black_box(&document))));
    group.bench_function("import", |b| {
        b.iter(|| {
            let file = ImportFile {
                name: "grid.glb",
                bytes: black_box(&glb),
            };
            import_gltf(&file, &[], &ImportLimits::default())
        })
    });
    group.finish();
}

criterion_group!(benches, bench_gltf);
criterion_main!(benches);

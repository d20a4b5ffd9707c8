//! glTF import and export of a 1 M-triangle model (issue target: import < 400 ms, export
//! < 300 ms natively). The model is a 708 × 708 grid with a wave, written by Sketchmesh's own
//! exporter, so the import measures the parse, accessor reads, weld and manifold check of a
//! clean file. Run with `cargo bench -p sketchmesh-core --bench core -- '^gltf '`.

use std::alloc::System;
use std::hint::black_box;
use std::sync::Arc;

use criterion::{Criterion, criterion_group};
use peakmem_alloc::{INSTRUMENTED_SYSTEM, PeakMemAlloc, PeakMemAllocTrait as _};
use sketchmesh_core::document::{Document, Model};
use sketchmesh_core::io::{ImportFile, ImportLimits, import_gltf, write_glb};
use sketchmesh_core::mesh::primitives;

/// The system allocator, instrumented to measure the peak memory of one import.
#[global_allocator]
static ALLOCATOR: &PeakMemAlloc<System> = &INSTRUMENTED_SYSTEM;

/// Peak extra memory of one import, against the budget: 3 × the file plus the mesh.
fn report_import_memory(glb: &[u8]) {
    let file = ImportFile {
        name: "grid.glb",
        bytes: glb,
    };
    ALLOCATOR.reset_peak_memory();
    let imported = import_gltf(&file, &[], &ImportLimits::default());
    let peak = ALLOCATOR.get_peak_memory();
    // What the imported mesh keeps: positions (24 B) and a half-edge per vertex (4 B), three
    // corners (12 B) and three twins (12 B) per triangle.
    let mesh_bytes: usize = imported
        .iter()
        .flat_map(|i| &i.models)
        .map(|m| 28 * m.mesh.n_vertices() + 24 * m.mesh.n_faces())
        .sum();
    let mb = |bytes: usize| bytes as f64 / 1e6;
    eprintln!(
        "import memory: file {:.1} MB, mesh {:.1} MB, peak {:.1} MB = mesh + {:.2} x file (budget: mesh + 3 x file)",
        mb(glb.len()),
        mb(mesh_bytes),
        mb(peak),
        peak.saturating_sub(mesh_bytes) as f64 / glb.len() as f64
    );
}

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
    report_import_memory(&glb);
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

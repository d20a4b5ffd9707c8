//! Laplacian editing (`core::deform`) on an over-sketch-sized edit: a 40,962-vertex icosphere
//! (6 subdivisions) with a cap ROI of about 5k vertices and about 100 exact handles at the
//! points where edges cross a curve through the cap, as silhouette points do. Times `new`
//! (region, weights, factorization, exact-handle Green's functions) and one `deform` (one
//! drag frame), linear and with rotations, with exact handles and with soft ones (weight
//! 100). Target (issue 6): a whole over-sketch under 40 ms
//! natively, so `new` plus one `deform` well under 30 ms. Results go in BENCHMARKS.md. Run
//! with `cargo bench -p sketchmesh-core --bench core -- '^deform_' --warm-up-time 1 --measurement-time 3`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group};
use glam::DVec3;
use sketchmesh_core::deform::{EditParams, HandleFit, LaplacianEdit, Rotations};

use crate::common::oversketch;
use oversketch::{oversketch_edit, sphere, targets};

fn bench_deform(c: &mut Criterion) {
    let mesh = sphere();
    let (roi, handles) = oversketch_edit(&mesh);
    let targets = targets(&mesh, &handles);
    let n_roi = roi.iter().filter(|&&r| r).count();
    println!(
        "deform bench: {} vertices, ROI {n_roi}, {} handles",
        mesh.n_vertices(),
        handles.len()
    );
    let rotations = Rotations::Arap {
        iterations: EditParams::DEFAULT_ARAP_ITERATIONS,
    };
    let soft = HandleFit::Soft { weight: 100.0 };
    let variants = [
        ("exact_linear", HandleFit::Exact, Rotations::None),
        ("exact_rotations", HandleFit::Exact, rotations),
        ("soft_linear", soft, Rotations::None),
        ("soft_rotations", soft, rotations),
    ];

    let mut group = c.benchmark_group("deform_new");
    group.sample_size(10);
    for (name, fit, rotations) in variants {
        let params = EditParams { fit, rotations };
        group.bench_with_input(BenchmarkId::from_parameter(name), &params, |b, &params| {
            b.iter(|| {
                LaplacianEdit::new(black_box(&mesh), &roi, &handles, params)
                    .expect("edit is well posed")
            });
        });
    }
    group.finish();

    let mut group = c.benchmark_group("deform_frame");
    for (name, fit, rotations) in variants {
        let params = EditParams { fit, rotations };
        let mut edit =
            LaplacianEdit::new(&mesh, &roi, &handles, params).expect("edit is well posed");
        let mut out = vec![DVec3::ZERO; mesh.n_vertices()];
        group.bench_with_input(BenchmarkId::from_parameter(name), &targets, |b, targets| {
            b.iter(|| {
                edit.deform(black_box(targets), &mut out)
                    .expect("lengths match")
            });
        });
    }
    group.finish();
}

criterion_group!(benches, bench_deform);

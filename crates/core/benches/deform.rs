//! Laplacian editing (`core::deform`) on an over-sketch-sized edit: a 40,962-vertex icosphere
//! (6 subdivisions) with a cap ROI of about 5k vertices and about 100 exact handles at the
//! points where edges cross a curve through the cap, as silhouette points do. Times `new`
//! (region, weights, factorization, exact-handle Green's functions) and one `deform` (one
//! drag frame), linear and with rotations, with exact handles and with soft ones (weight
//! 100). Target (issue 6): a whole over-sketch under 40 ms
//! natively, so `new` plus one `deform` well under 30 ms. Results go in BENCHMARKS.md. Run
//! with `cargo bench -p sketchmesh-core --bench deform -- --warm-up-time 1 --measurement-time 3`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use glam::{DMat3, DVec3};
use sketchmesh_core::deform::{EditParams, HandleFit, HandlePoint, LaplacianEdit, Rotations};
use sketchmesh_core::mesh::{HalfedgeId, Mesh, primitives};

/// The pole of the cap.
const POLE: DVec3 = DVec3::Z;
/// Chord radius of the cap ROI: `(1 - cos θ) / 2` of the sphere, about 12% or 5k vertices.
const ROI_RADIUS: f64 = 0.7;
/// Chord radius of the handle curve's extent around the pole.
const HANDLE_RADIUS: f64 = 0.45;
/// The handle curve lies in the plane `y = PLANE_Y`, off the icosphere's symmetry planes so
/// that no vertex lies on it.
const PLANE_Y: f64 = 0.0123;

/// The cap ROI and handles at the edge crossings of the plane `y = PLANE_Y` near the pole.
fn oversketch_edit(mesh: &Mesh) -> (Vec<bool>, Vec<HandlePoint>) {
    let p = mesh.positions();
    let roi = p
        .iter()
        .map(|&q| (q - POLE).length() < ROI_RADIUS)
        .collect();
    let handles = (0..mesh.n_halfedges() as u32)
        .map(HalfedgeId)
        .filter_map(|h| {
            let (a, b) = (mesh.tail(h), mesh.head(h));
            let (pa, pb) = (p[a.index()], p[b.index()]);
            // Each edge once: from its lower end to its upper end.
            let crosses = pa.y < PLANE_Y && pb.y > PLANE_Y;
            let is_near = (0.5 * (pa + pb) - POLE).length() < HANDLE_RADIUS;
            (crosses && is_near)
                .then(|| HandlePoint::on_edge(a, b, (PLANE_Y - pa.y) / (pb.y - pa.y)))
        })
        .collect();
    (roi, handles)
}

/// Targets: the handle curve pushed outward and turned a little, like a redrawn silhouette.
fn targets(mesh: &Mesh, handles: &[HandlePoint]) -> Vec<DVec3> {
    let turn = DMat3::from_rotation_y(0.2);
    handles
        .iter()
        .map(|h| {
            let q = h.position(mesh.positions());
            let bulge = 0.15 * (1.0 - ((q - POLE).length() / HANDLE_RADIUS).powi(2));
            turn * q + q.normalize() * bulge
        })
        .collect()
}

fn bench_deform(c: &mut Criterion) {
    let mesh = primitives::icosphere(1.0, 6);
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
criterion_main!(benches);

//! Symmetric modelling (issue 50): a pull's drag frame on a symmetric shape of about 10k
//! vertices, made with symmetry off and on. With symmetry on, the frame also does what the
//! app does to show both sides: the side that moved (`moved_side`) and the other side made
//! its mirror image through the pairing found once per drag (`mirror_positions`). Target:
//! the mirrored frame at most 1.3× the plain one. Also `symmetrize` on the 10k shape and on
//! the bunny (35k vertices), about a plane off its centre.
//! Run with `cargo bench -p sketchmesh-core --bench core -- '^symmetry/'`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group};
use glam::{DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{Edit, Editor, Op, StrokeInput, SymmetrizeInput};
use sketchmesh_core::model::{MirrorPlane, Model, Side};
use sketchmesh_core::symmetry::{mirror_positions, moved_side, partners, symmetrized};

use crate::common::fibermesh_shape::{HALF_AXES, VIEWPORT, ellipse_editor};
use crate::common::scan::scan;

/// The 10k ellipse made symmetric about x = 0.
fn symmetric_ellipse() -> Editor {
    let mut editor = ellipse_editor(10_000).expect("the ellipse inflates and imports");
    let symmetrize = SymmetrizeInput {
        model: 0,
        plane: MirrorPlane::default(),
        keep: Side::Positive,
    };
    editor
        .apply(Op::Symmetrize(symmetrize))
        .expect("symmetrize");
    editor
}

/// Samples of a drag from the outline's rightmost point, 50 px right.
fn drag() -> Vec<[f64; 3]> {
    let start = VIEWPORT / 2.0 + DVec2::new(HALF_AXES.x, 0.0);
    (0..=40)
        .map(|i| {
            let p = start + DVec2::X * 50.0 * f64::from(i) / 40.0;
            [p.x, p.y, 0.5]
        })
        .collect()
}

/// The pull begun (with symmetry on or off), factored and dragged most of the way.
fn dragging(editor: &Editor, mirrored: bool) -> Edit {
    let samples = drag();
    let grab = Op::Pull(StrokeInput {
        viewport: VIEWPORT.to_array(),
        camera: Camera::default(),
        stroke: samples[..1].to_vec(),
    });
    let op = match mirrored {
        true => grab.mirrored(MirrorPlane::default()),
        false => grab,
    };
    let mut edit = editor.begin_gesture(op).expect("grab");
    for &sample in &samples[1..30] {
        edit.extend(sample);
        edit.step().expect("drag");
    }
    edit
}

fn bench_symmetry(c: &mut Criterion) {
    let mut group = c.benchmark_group("symmetry");
    group.sample_size(10);
    let editor = symmetric_ellipse();
    let model = editor.document().models[0].clone();
    let vertices = model.mesh.n_vertices();
    let plane = MirrorPlane::default();
    let samples = drag();
    for mirrored in [false, true] {
        let name = if mirrored {
            "drag_frame_mirrored"
        } else {
            "drag_frame"
        };
        group.bench_with_input(BenchmarkId::new(name, vertices), &editor, |b, editor| {
            let mut edit = dragging(editor, mirrored);
            let pairs = partners(&model.mesh, &plane).expect("symmetric");
            let base = model.mesh.positions();
            let mut shown = Vec::with_capacity(base.len());
            let mut k = 30;
            b.iter(|| {
                edit.extend(samples[k]);
                edit.step().expect("drag");
                if mirrored && let Some((_, moved)) = edit.moved_model() {
                    shown.clear();
                    shown.extend_from_slice(moved);
                    let keep = moved_side(base, moved, &plane);
                    mirror_positions(base, &mut shown, &pairs, &plane, keep);
                }
                k = if k + 1 < samples.len() { k + 1 } else { 30 };
                black_box(&shown);
            });
        });
    }
    let off_centre = |model: &Model| {
        let (lo, hi) = model.mesh.bounding_box().expect("a mesh");
        let through = 0.5 * (lo + hi) + DVec3::X * 0.2 * (hi.x - lo.x);
        MirrorPlane::through(through, DVec3::new(1.0, 0.18, 0.0)).expect("a plane")
    };
    let mut shapes = vec![("ellipse", Model::clone(&model))];
    if let Some(mesh) = scan("stanford_bunny.glb") {
        shapes.push((
            "bunny",
            Model {
                mesh,
                ..Model::default()
            },
        ));
    }
    for (name, shape) in shapes {
        let plane = off_centre(&shape);
        let id = BenchmarkId::new(format!("symmetrize_{name}"), shape.mesh.n_vertices());
        group.bench_with_input(id, &shape, |b, shape| {
            b.iter(|| symmetrized(black_box(shape), &plane, Side::Negative).expect("symmetrize"));
        });
    }
    group.finish();
}

criterion_group!(benches, bench_symmetry);

//! FiberMesh curve editing (issue 4) on created shapes of about 10k and 40k vertices: a pull
//! of the outline's rightmost point by 50 px, a tenth of the shape's width. Times the grab
//! (`Editor::begin_gesture` of the `pull` op and its first step: curve network, regional
//! factorization), one drag frame (`Edit::extend` and a step: curve deformation and one
//! back-substitution of the region), and the committed `pull` op at release (deformation,
//! regional settle, remesh, settle).
//! Targets: a drag frame under 16 ms at 10k and under 33 ms at 40k in the browser; release
//! under 250 ms at 10k.
//!
//! Also the `cut` op (issue 16) on the same shapes: a vertical stroke across the ellipse a
//! fifth of its half-width from its right end, from above it to below it; the whole op
//! (level set, caps, remesh and settle of the band). And the `tunnel` op: loops of 50 px
//! around the middle seen from the front and from behind (embedding both, the tube, its
//! fairing, the remesh and settle of the band). The `extrude` op: a loop of a fifth of the
//! ellipse's half-height at three fifths of its half-width right of the middle, and a
//! silhouette from its top out to 1.6 half-widths and back to its bottom (embedding, the
//! limb, the remesh and re-optimization of the limb and a band). The `merge` op: the ellipse
//! and a copy moved to overlap it by half its width (signed distances, splits, seam, the
//! remesh and re-optimization of the band), each part of the given size. Target for each:
//! under 100 ms at 10k natively.
//! Run with
//! `cargo bench -p sketchmesh-core --bench core -- '^(pull|cut|tunnel|extrude|merge)/' --warm-up-time 1 --measurement-time 3`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group};
use glam::DVec2;
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{
    DuplicateInput, Edit, Editor, MergeInput, Op, StrokeInput, StrokePairInput, TransformInput,
};

use crate::common::fibermesh_shape;
use fibermesh_shape::{HALF_AXES, VIEWPORT, ellipse_editor};

/// The drag from the outline's rightmost point, `steps` samples, 50 px right in all.
fn drag(steps: usize) -> StrokeInput {
    let start = VIEWPORT / 2.0 + DVec2::new(HALF_AXES.x, 0.0);
    StrokeInput {
        viewport: VIEWPORT.to_array(),
        camera: Camera::default(),
        stroke: (0..=steps)
            .map(|i| {
                let p = start + DVec2::X * 50.0 * i as f64 / steps as f64;
                [p.x, p.y, 0.5]
            })
            .collect(),
    }
}

/// Pointer-down: the pull begun as a gesture, and its first step (the region's factorization).
fn grab_at(editor: &Editor, grab: &StrokeInput) -> Edit {
    let mut edit = editor.begin_gesture(Op::Pull(grab.clone())).expect("grab");
    edit.step().expect("factor");
    edit
}

/// One drag frame: the pointer's latest sample, followed by one step.
fn drag_frame(edit: &mut Edit, sample: [f64; 3]) {
    edit.extend(sample);
    edit.step().expect("drag");
}

fn bench_curve_edit(c: &mut Criterion) {
    let mut group = c.benchmark_group("pull");
    group.sample_size(10);
    for n in [10_000, 40_000] {
        let editor = ellipse_editor(n).expect("the ellipse inflates and imports");
        let vertices = editor.document().stats().vertices;
        let grab = StrokeInput {
            stroke: drag(1).stroke[..1].to_vec(),
            ..drag(1)
        };
        group.bench_with_input(BenchmarkId::new("grab", vertices), &editor, |b, editor| {
            b.iter(|| grab_at(editor, black_box(&grab)));
        });
        let samples = drag(40).stroke;
        group.bench_with_input(
            BenchmarkId::new("drag_frame", vertices),
            &editor,
            |b, editor| {
                let mut edit = grab_at(editor, &grab);
                // Pull most of the way first, so that frames measure a grown peel and region.
                for &sample in &samples[1..30] {
                    drag_frame(&mut edit, sample);
                }
                let mut k = 30;
                b.iter(|| {
                    drag_frame(&mut edit, samples[k]);
                    k = if k + 1 < samples.len() { k + 1 } else { 30 };
                });
            },
        );
        group.bench_with_input(
            BenchmarkId::new("release", vertices),
            &editor,
            |b, editor| {
                b.iter(|| editor.clone().apply(Op::Pull(drag(40))).expect("pull"));
            },
        );
    }
    group.finish();
}

/// A vertical stroke across the ellipse at a fifth of its half-width from its right end.
fn cut_stroke() -> StrokeInput {
    let x = VIEWPORT.x / 2.0 + 0.8 * HALF_AXES.x;
    let (top, bottom) = (
        VIEWPORT.y / 2.0 - 1.5 * HALF_AXES.y,
        VIEWPORT.y / 2.0 + 1.5 * HALF_AXES.y,
    );
    StrokeInput {
        viewport: VIEWPORT.to_array(),
        camera: Camera::default(),
        stroke: (0..=60)
            .map(|i| [x, top + (bottom - top) * f64::from(i) / 60.0, 0.5])
            .collect(),
    }
}

fn bench_cut(c: &mut Criterion) {
    let mut group = c.benchmark_group("cut");
    group.sample_size(10);
    for n in [10_000, 40_000] {
        let editor = ellipse_editor(n).expect("the ellipse inflates and imports");
        let vertices = editor.document().stats().vertices;
        let cut = Op::Cut(cut_stroke());
        group.bench_with_input(BenchmarkId::new("op", vertices), &editor, |b, editor| {
            b.iter(|| editor.clone().apply(black_box(cut.clone())).expect("cut"));
        });
    }
    group.finish();
}

/// A loop of 50 px around the view's middle, seen through `camera`.
fn middle_loop(camera: Camera) -> StrokeInput {
    let centre = VIEWPORT / 2.0;
    StrokeInput {
        viewport: VIEWPORT.to_array(),
        camera,
        stroke: (0..=48)
            .map(|i| {
                let p =
                    centre + 50.0 * DVec2::from_angle(std::f64::consts::TAU * f64::from(i) / 48.0);
                [p.x, p.y, 0.5]
            })
            .collect(),
    }
}

fn bench_tunnel(c: &mut Criterion) {
    let mut group = c.benchmark_group("tunnel");
    group.sample_size(10);
    let behind = Camera {
        eye: glam::DVec3::new(0.0, 0.0, -5.0),
        ..Camera::default()
    };
    for n in [10_000, 40_000] {
        let editor = ellipse_editor(n).expect("the ellipse inflates and imports");
        let vertices = editor.document().stats().vertices;
        let tunnel = Op::Tunnel(StrokePairInput {
            strokes: [middle_loop(Camera::default()), middle_loop(behind)],
        });
        group.bench_with_input(BenchmarkId::new("op", vertices), &editor, |b, editor| {
            b.iter(|| {
                editor
                    .clone()
                    .apply(black_box(tunnel.clone()))
                    .expect("tunnel")
            });
        });
    }
    group.finish();
}

fn bench_extrude(c: &mut Criterion) {
    let mut group = c.benchmark_group("extrude");
    group.sample_size(10);
    let base = VIEWPORT / 2.0 + DVec2::new(0.6 * HALF_AXES.x, 0.0);
    let radius = 0.2 * HALF_AXES.y;
    let reach = HALF_AXES.x;
    let stroke = |points: Vec<DVec2>| StrokeInput {
        viewport: VIEWPORT.to_array(),
        camera: Camera::default(),
        stroke: points.iter().map(|p| [p.x, p.y, 0.5]).collect(),
    };
    let base_loop: Vec<DVec2> = (0..=48)
        .map(|i| base + radius * DVec2::from_angle(std::f64::consts::TAU * f64::from(i) / 48.0))
        .collect();
    let silhouette: Vec<DVec2> = (0..=60)
        .map(|i| {
            let a = std::f64::consts::PI * (f64::from(i) / 60.0 - 0.5);
            base + DVec2::new(reach * a.cos(), radius * a.sin())
        })
        .collect();
    let extrude = Op::Extrude(StrokePairInput {
        strokes: [stroke(base_loop), stroke(silhouette)],
    });
    for n in [10_000, 40_000] {
        let editor = ellipse_editor(n).expect("the ellipse inflates and imports");
        let vertices = editor.document().stats().vertices;
        group.bench_with_input(BenchmarkId::new("op", vertices), &editor, |b, editor| {
            b.iter(|| {
                editor
                    .clone()
                    .apply(black_box(extrude.clone()))
                    .expect("extrude")
            });
        });
    }
    group.finish();
}

fn bench_merge(c: &mut Criterion) {
    let mut group = c.benchmark_group("merge");
    group.sample_size(10);
    for n in [10_000, 40_000] {
        let mut editor = ellipse_editor(n).expect("the ellipse inflates and imports");
        let vertices = editor.document().stats().vertices;
        let (lo, hi) = editor.document().models[0]
            .mesh
            .bounding_box()
            .expect("a mesh");
        let width = hi.x - lo.x;
        // A duplicate lands 1.2 widths to the right; bring it back to overlap by half a width.
        editor
            .apply(Op::Duplicate(DuplicateInput {
                model: 0,
                beside: None,
            }))
            .expect("duplicate");
        let back = glam::DMat4::from_translation(glam::DVec3::new(-0.7 * width, 0.0, 0.0));
        editor
            .apply(Op::Transform(TransformInput {
                model: 1,
                matrix: back.to_cols_array(),
            }))
            .expect("move");
        let merge = Op::Merge(MergeInput { models: [0, 1] });
        group.bench_with_input(BenchmarkId::new("op", vertices), &editor, |b, editor| {
            b.iter(|| {
                editor
                    .clone()
                    .apply(black_box(merge.clone()))
                    .expect("merge")
            });
        });
    }
    group.finish();
}

criterion_group!(
    benches,
    bench_curve_edit,
    bench_cut,
    bench_tunnel,
    bench_extrude,
    bench_merge
);

//! Bujans' region editor: a reference curve and a boundary around it move a region by a
//! transform with a fall-off, on a generated sphere and on scans.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use glam::{DMat4, DQuat, DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::polyline::contains;
use sketchmesh_core::document::{
    CommandError, Editor, Op, RegionDrag, RegionEditInput, dragged_region,
};
use sketchmesh_core::geometry::Fractions;
use sketchmesh_core::mesh::{Mesh, primitives};
use sketchmesh_core::region_edit::{Levels, RegionEdit, RegionError, RegionSketch};

use crate::common::{circle, diagonal, digest, import_mesh, samples, screen, testdata_meshes};

const VIEWPORT: DVec2 = DVec2::new(800.0, 800.0);

/// A camera looking at `mesh`'s bounding box from +z, the box filling about half the view.
fn camera_on(mesh: &Mesh) -> Camera {
    let (lo, hi) = mesh.bounding_box().unwrap();
    let centre = 0.5 * (lo + hi);
    Camera {
        eye: centre + DVec3::new(0.0, 0.0, 1.5 * (hi - lo).length()),
        target: centre,
        ..Camera::default()
    }
}

/// A straight reference curve of `half` px either side of the middle of `mesh` on screen,
/// and a circular boundary of `radius` px around it.
fn curves(mesh: &Mesh, half: f64, radius: f64) -> RegionSketch {
    let camera = camera_on(mesh);
    let (lo, hi) = mesh.bounding_box().unwrap();
    let middle = screen(&camera, VIEWPORT, 0.5 * (lo + hi)).unwrap();
    let n = (2.0 * half / 3.0).ceil() as usize;
    let (a, b) = (
        middle - DVec2::new(half, 0.0),
        middle + DVec2::new(half, 0.0),
    );
    let mut boundary = circle(middle, radius);
    boundary.pop();
    RegionSketch {
        camera,
        viewport: VIEWPORT,
        reference: (0..=n).map(|i| a.lerp(b, i as f64 / n as f64)).collect(),
        boundary,
    }
}

/// A turn of `degrees` about an oblique axis through `centre`, a scale and a move.
fn transform(centre: DVec3, degrees: f64, scale: f64, shift: DVec3) -> DMat4 {
    DMat4::from_translation(centre + shift)
        * DMat4::from_quat(DQuat::from_axis_angle(
            DVec3::new(0.3, 1.0, 0.2).normalize(),
            degrees.to_radians(),
        ))
        * DMat4::from_scale(DVec3::splat(scale))
        * DMat4::from_translation(-centre)
}

#[test]
fn weights_fall_from_the_reference_curve_to_the_boundary() {
    let mesh = primitives::icosphere(1.0, 4);
    let sketch = curves(&mesh, 60.0, 140.0);
    let edit = RegionEdit::new(&mesh, &sketch, &Levels::default()).unwrap();
    assert!(edit.vertices().len() > 100, "{}", edit.vertices().len());
    let on_screen = |v| screen(&sketch.camera, VIEWPORT, mesh.position(v)).unwrap();
    let all = edit.weight_per_vertex(mesh.n_vertices());
    for &v in edit.reference() {
        assert_eq!(all[v.index()], 1.0, "the reference curve moves fully");
    }
    let middle = sketch.reference[sketch.reference.len() / 2];
    for (&v, &w) in edit.vertices().iter().zip(edit.weights()) {
        assert!((0.0..=1.0).contains(&w));
        let s = on_screen(v);
        assert!(
            contains(&sketch.boundary, s),
            "region vertices lie inside the boundary"
        );
        // Near the boundary the weight is small; near the curve's middle it is large.
        let to_rim = 140.0 - s.distance(middle);
        if to_rim < 8.0 {
            assert!(w < 0.25, "{w} at {to_rim} px from the boundary");
        }
        if s.distance(middle) < 8.0 {
            assert!(w > 0.8, "{w} next to the curve");
        }
    }
    let outside: Vec<_> = mesh
        .vertices()
        .filter(|v| !edit.vertices().contains(v))
        .collect();
    assert!(outside.len() > 1000);
    assert!(outside.iter().all(|v| all[v.index()] == 0.0));
    // New levels weigh the same region again.
    let mut steep = edit.clone();
    steep.set_levels(&Levels::new(vec![0.0, 1.0]).unwrap());
    steep.set_levels(&Levels::new(vec![1.0, 1.0]).unwrap());
    assert!(steep.weights().iter().all(|&w| w == 1.0));
    assert_eq!(steep.vertices(), edit.vertices());
}

#[test]
fn outside_stays_bit_for_bit_and_the_curve_moves_exactly_by_the_transform() {
    let mesh = primitives::icosphere(1.0, 4);
    let edit = RegionEdit::new(&mesh, &curves(&mesh, 60.0, 140.0), &Levels::default()).unwrap();
    let t = transform(
        DVec3::new(0.0, 0.0, 1.0),
        70.0,
        1.3,
        DVec3::new(0.1, 0.4, 0.2),
    );
    let moved = edit.applied(&mesh, &Fractions::new(t).unwrap());
    for v in mesh.vertices() {
        let (before, after) = (mesh.position(v), moved[v.index()]);
        if !edit.vertices().contains(&v) {
            assert_eq!(after, before, "outside the boundary nothing moves");
        }
    }
    for &v in edit.reference() {
        assert_eq!(moved[v.index()], t.transform_point3(mesh.position(v)));
    }
    // Every vertex moved by its own fraction of the transform.
    let log = sketchmesh_core::geometry::log_affine(t).unwrap();
    for (&v, &w) in edit.vertices().iter().zip(edit.weights()) {
        let exact =
            sketchmesh_core::geometry::exp_affine(log * w).transform_point3(mesh.position(v));
        assert!(moved[v.index()].distance(exact) < 1e-12);
    }
}

#[test]
fn half_the_transform_twice_is_the_whole() {
    let mesh = primitives::icosphere(1.0, 4);
    let sketch = curves(&mesh, 60.0, 140.0);
    let half = RegionEdit::new(&mesh, &sketch, &Levels::new(vec![0.5, 0.5]).unwrap()).unwrap();
    let whole = RegionEdit::new(&mesh, &sketch, &Levels::new(vec![1.0, 1.0]).unwrap()).unwrap();
    let t = Fractions::new(transform(DVec3::Z, 150.0, 0.8, DVec3::new(0.0, 0.3, 0.0))).unwrap();
    let once = half.applied(&mesh, &t);
    let mut twice = once.clone();
    half.apply_into(&t, &once, &mut twice);
    let full = whole.applied(&mesh, &t);
    let worst = twice
        .iter()
        .zip(&full)
        .map(|(a, b)| a.distance(*b))
        .fold(0.0, f64::max);
    assert!(worst < 1e-9 * diagonal(mesh.positions()), "{worst}");
}

fn op(sketch: &RegionSketch, transform: DMat4, levels: Option<Vec<f64>>) -> Op {
    Op::RegionEdit(RegionEditInput {
        viewport: sketch.viewport.to_array(),
        camera: sketch.camera,
        reference: samples(sketch.reference.iter().copied()),
        boundary: samples(sketch.boundary.iter().copied()),
        levels,
        transform: transform.to_cols_array(),
    })
}

#[test]
fn the_op_replays_and_its_drag_commits_what_replay_gives() {
    let mesh = primitives::icosphere(1.0, 4);
    let sketch = curves(&mesh, 60.0, 140.0);
    let mut editor = Editor::new();
    editor.apply(import_mesh("sphere.glb", &mesh)).unwrap();
    let imported = editor.document().models[0].mesh.clone();
    let lift = |y: f64| DMat4::from_translation(DVec3::new(0.0, y, 0.1));
    // A drag: the transform revised frame by frame, then released.
    let mut edit = editor.begin_gesture(op(&sketch, lift(0.0), None)).unwrap();
    for y in [0.05, 0.1, 0.2, 0.3] {
        edit.revise(op(&sketch, lift(y), None));
        edit.step().unwrap();
        let (model, shown) = edit.moved_model().unwrap();
        assert_eq!(model, 0);
        assert!(shown.iter().zip(imported.positions()).any(|(a, b)| a != b));
    }
    let (model, vertices, weights) = edit.region_falloff().unwrap();
    assert_eq!((model, vertices.len()), (0, weights.len()));
    assert!(weights.contains(&1.0) && weights.iter().all(|&w| w >= 0.0));
    edit.finish(&mut editor).unwrap();
    let mut applied = Editor::new();
    applied.apply(import_mesh("sphere.glb", &mesh)).unwrap();
    applied.apply(op(&sketch, lift(0.3), None)).unwrap();
    assert_eq!(digest(editor.document()), digest(applied.document()));
    let replayed = Editor::replay_json(&editor.session_json()).unwrap();
    assert_eq!(digest(replayed.document()), digest(editor.document()));
    // A second edit with steeper levels, then undo and redo.
    editor
        .apply(op(&sketch, lift(-0.2), Some(vec![0.0, 1.0, 1.0])))
        .unwrap();
    let after = digest(editor.document());
    editor.undo().unwrap();
    assert_eq!(digest(editor.document()), digest(applied.document()));
    editor.redo().unwrap();
    assert_eq!(digest(editor.document()), after);
}

#[test]
fn bad_curves_levels_and_transforms_are_refused_and_change_nothing() {
    let mesh = primitives::icosphere(1.0, 4);
    let sketch = curves(&mesh, 60.0, 140.0);
    let mut editor = Editor::new();
    editor.apply(import_mesh("sphere.glb", &mesh)).unwrap();
    let before = digest(editor.document());
    let session = editor.session_json();
    let refused = |editor: &mut Editor, op: Op| match editor.apply(op) {
        Err(CommandError::Region(error)) => error,
        other => panic!("{other:?}"),
    };
    let shift = DMat4::from_translation(DVec3::Y * 0.1);
    let small = RegionSketch {
        boundary: {
            let mut ring = circle(sketch.reference[0], 20.0);
            ring.pop();
            ring
        },
        ..sketch.clone()
    };
    let off = RegionSketch {
        reference: sketch
            .reference
            .iter()
            .map(|p| *p + DVec2::new(500.0, 0.0))
            .collect(),
        ..sketch.clone()
    };
    let mut nan = shift;
    nan.w_axis.x = f64::NAN;
    let mut projective = shift;
    projective.x_axis.w = 0.1;
    for (op, expected) in [
        (
            op(&small, shift, None),
            RegionError::BoundaryMissesReference,
        ),
        (op(&off, shift, None), RegionError::ReferenceMissesModel),
        (
            op(&sketch, shift, Some(vec![0.0, 1.5])),
            RegionError::BadLevels,
        ),
        (op(&sketch, nan, None), RegionError::TransformNotFinite),
        (
            op(&sketch, projective, None),
            RegionError::TransformNotAffine,
        ),
        (
            op(&sketch, DMat4::from_scale(DVec3::new(-1.0, 1.0, 1.0)), None),
            RegionError::TransformMirrors,
        ),
        (
            op(&sketch, DMat4::from_rotation_y(std::f64::consts::PI), None),
            RegionError::TransformTurnsHalfWay,
        ),
    ] {
        let error = refused(&mut editor, op);
        assert_eq!(error, expected);
        assert_eq!(digest(editor.document()), before, "{error}");
        assert_eq!(editor.session_json(), session);
    }
}

#[test]
fn a_region_on_scans_moves_inside_its_boundary_only() {
    for name in [
        "spot.glb",
        "stanford_bunny.glb",
        "nefertiti.glb",
        "igea.glb",
    ] {
        let Some(meshes) = testdata_meshes(name) else {
            return;
        };
        let mesh = &meshes[0];
        let sketch = curves(mesh, 50.0, 120.0);
        let edit = RegionEdit::new(mesh, &sketch, &Levels::default())
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let (lo, hi) = mesh.bounding_box().unwrap();
        let up = 0.1 * (hi - lo).length();
        let t = transform(0.5 * (lo + hi), 20.0, 1.1, DVec3::new(0.0, up, 0.3 * up));
        let moved = edit.applied(mesh, &Fractions::new(t).unwrap());
        let region: std::collections::HashSet<_> = edit.vertices().iter().copied().collect();
        for v in mesh.vertices() {
            let p = moved[v.index()];
            assert!(p.is_finite(), "{name}");
            if !region.contains(&v) {
                assert_eq!(p, mesh.position(v), "{name}: outside the boundary");
            }
        }
        for &v in edit.reference() {
            assert_eq!(
                moved[v.index()],
                t.transform_point3(mesh.position(v)),
                "{name}"
            );
        }
        eprintln!(
            "{name}: {} region vertices of {}, reference {} vertices",
            edit.vertices().len(),
            mesh.n_vertices(),
            edit.reference().len()
        );
        assert!(edit.vertices().len() > 50, "{name}");
    }
}

/// A sphere imported into an editor, the curves on it, and their op that moves nothing.
fn sphere_in_editor() -> (Mesh, RegionSketch, Editor, RegionEditInput) {
    let mesh = primitives::icosphere(1.0, 4);
    let sketch = curves(&mesh, 60.0, 140.0);
    let mut editor = Editor::new();
    editor.apply(import_mesh("sphere.glb", &mesh)).unwrap();
    let Op::RegionEdit(still) = op(&sketch, DMat4::IDENTITY, None) else {
        unreachable!()
    };
    (mesh, sketch, editor, still)
}

#[test]
fn a_drag_carries_the_reference_curve_with_the_pointer() {
    let (mesh, sketch, mut editor, still) = sphere_in_editor();
    let offset = DVec2::new(30.0, -50.0);
    let dragged = dragged_region(editor.document(), &still, RegionDrag::Move, offset);
    editor.apply(Op::RegionEdit(dragged)).unwrap();
    let edit = RegionEdit::new(&mesh, &sketch, &Levels::default()).unwrap();
    let moved = &editor.document().models[0].mesh;
    let middle = edit.reference()[edit.reference().len() / 2];
    let px = |m: &Mesh| screen(&sketch.camera, VIEWPORT, m.position(middle)).unwrap();
    let shift = px(moved) - px(&mesh);
    assert!(
        shift.distance(offset) < 2.0,
        "moved {shift} on screen for {offset}"
    );
}

#[test]
fn a_turning_drag_twists_the_region_about_the_curve_s_middle() {
    let (mesh, sketch, mut editor, still) = sphere_in_editor();
    let doc = editor.document();
    // 60 px to the right: 30° clockwise as seen, about the view axis.
    let turned = dragged_region(doc, &still, RegionDrag::Turn, DVec2::new(60.0, 0.0));
    let t = DMat4::from_cols_array(&turned.transform);
    let edit = RegionEdit::new(&mesh, &sketch, &Levels::default()).unwrap();
    let ends = [edit.reference()[0], *edit.reference().last().unwrap()];
    let [a, b] = ends.map(|v| screen(&sketch.camera, VIEWPORT, mesh.position(v)).unwrap());
    let [a2, b2] = ends.map(|v| {
        screen(
            &sketch.camera,
            VIEWPORT,
            t.transform_point3(mesh.position(v)),
        )
        .unwrap()
    });
    // On screen, y down, a positive angle turns clockwise.
    let angle = (b - a).angle_to(b2 - a2).to_degrees();
    assert!((angle - 30.0).abs() < 2.0, "turned {angle}° on screen");
    // Up 150 px doubles; turns stop short of half a turn.
    let grown = dragged_region(doc, &still, RegionDrag::Scale, DVec2::new(0.0, -150.0));
    let m = DMat4::from_cols_array(&grown.transform);
    assert!((m.x_axis.x - 2.0).abs() < 1e-12 && (m.determinant() - 8.0).abs() < 1e-9);
    let far = dragged_region(doc, &still, RegionDrag::Turn, DVec2::new(2000.0, 0.0));
    editor.apply(Op::RegionEdit(far)).unwrap();
    editor.apply(Op::RegionEdit(grown)).unwrap();
}

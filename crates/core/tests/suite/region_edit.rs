//! Bujans' region editor: a reference curve and a boundary around it move a region by a
//! transform with a fall-off, on a generated sphere and on scans.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use glam::{DMat4, DQuat, DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::polyline::contains;
use sketchmesh_core::document::{
    CommandError, Editor, Op, Progress, RegionDrag, RegionEditInput, dragged_region,
};
use sketchmesh_core::geometry::Fractions;
use sketchmesh_core::mesh::{Mesh, primitives};
use sketchmesh_core::region_edit::{
    Handle, Levels, Motion, ProfileChange, RegionEdit, RegionError, RegionSketch, blend_at,
};

use crate::common::{
    circle, diagonal, digest, import_mesh, samples, screen, supply_elsewhere, testdata_meshes,
};

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

/// One transform for the whole region.
fn whole(t: DMat4) -> Motion {
    Fractions::new(t).unwrap().into()
}

#[test]
fn weights_fall_from_the_reference_curve_to_the_boundary() {
    let input = primitives::icosphere(1.0, 4);
    let sketch = curves(&input, 60.0, 140.0);
    let edit = RegionEdit::new(&input, &sketch, &Levels::default()).unwrap();
    let mesh = edit.mesh();
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
    let input = primitives::icosphere(1.0, 4);
    let edit = RegionEdit::new(&input, &curves(&input, 60.0, 140.0), &Levels::default()).unwrap();
    let mesh = edit.mesh();
    let t = transform(
        DVec3::new(0.0, 0.0, 1.0),
        70.0,
        1.3,
        DVec3::new(0.1, 0.4, 0.2),
    );
    let moved = edit.applied(&whole(t));
    // The embedding only added vertices: the input's are where they were.
    assert_eq!(&mesh.positions()[..input.n_vertices()], input.positions());
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

/// How far (CSS px, as seen) from the drawn boundary lie the vertices that hold the region
/// in (outside it, next to one inside), farthest first.
fn rim_off_boundary(mesh: &Mesh, edit: &RegionEdit, sketch: &RegionSketch) -> Vec<f64> {
    let region: std::collections::HashSet<_> = edit.vertices().iter().copied().collect();
    let mut looped = sketch.boundary.clone();
    looped.push(looped[0]);
    let mut off: Vec<f64> = mesh
        .vertices()
        .filter(|v| !region.contains(v) && mesh.vertex_neighbors(*v).any(|w| region.contains(&w)))
        .map(|v| {
            let at = screen(&sketch.camera, VIEWPORT, mesh.position(v)).unwrap();
            sketchmesh_core::curve::polyline::distance_to_polyline(at, &looped)
        })
        .collect();
    off.sort_by(|a, b| b.total_cmp(a));
    off
}

#[test]
fn the_curves_are_embedded_as_mesh_vertices_and_the_edit_ends_on_the_drawn_boundary() {
    let mut cases = vec![("sphere".to_string(), primitives::icosphere(1.0, 4))];
    for name in ["spot.glb", "stanford_bunny.glb", "igea.glb"] {
        if let Some(mut meshes) = testdata_meshes(name) {
            cases.push((name.to_string(), meshes.swap_remove(0)));
        }
    }
    for (name, input) in &cases {
        // On the scans, a loop that stays on one sheet of the front (a wider one crosses
        // spot's and the bunny's silhouettes and is traced over edges instead).
        let sketch = match name.as_str() {
            "sphere" => curves(input, 60.0, 140.0),
            "igea.glb" => curves(input, 25.0, 60.0),
            _ => curves(input, 12.0, 30.0),
        };
        let edit = RegionEdit::new(input, &sketch, &Levels::default()).unwrap();
        let mesh = edit.mesh();
        mesh.validate().unwrap();
        // New vertices only, appended: the input's keep their ids and places.
        assert!(mesh.n_vertices() > input.n_vertices(), "{name}");
        assert_eq!(&mesh.positions()[..input.n_vertices()], input.positions());
        assert!(!edit.splits().is_empty(), "{name}");
        // The reference curve is an edge chain lying on the sketch as seen.
        let reference = edit.reference();
        assert!(
            reference
                .windows(2)
                .all(|w| mesh.find_edge(w[0], w[1]).is_some())
        );
        let off_sketch = reference[1..reference.len() - 1]
            .iter()
            .map(|&v| {
                let at = screen(&sketch.camera, VIEWPORT, mesh.position(v)).unwrap();
                sketchmesh_core::curve::polyline::distance_to_polyline(at, &sketch.reference)
            })
            .fold(0.0, f64::max);
        // The boundary is a loop of vertices that stay, on the loop drawn: the rim of what
        // stays lies on it, where the curves traced over edges leave it up to an edge away.
        let on_loop =
            |off: &[f64]| off.iter().filter(|&&d| d < 0.5).count() as f64 / off.len() as f64;
        let embedded = rim_off_boundary(mesh, &edit, &sketch);
        let traced = RegionEdit::on_edges(input, &sketch, &Levels::default()).unwrap();
        let on_edges = rim_off_boundary(input, &traced, &sketch);
        eprintln!(
            "{name}: {} new vertices, reference {} vertices at most {off_sketch:.3} px off \
             the sketch; rim of {} vertices, {:.1}% on the loop drawn, the farthest {:.2} px \
             off (traced over edges: {:.1}%, {:.2} px)",
            mesh.n_vertices() - input.n_vertices(),
            reference.len(),
            embedded.len(),
            100.0 * on_loop(&embedded),
            embedded[0],
            100.0 * on_loop(&on_edges),
            on_edges[0],
        );
        assert!(off_sketch < 0.5, "{name}: {off_sketch} px");
        assert!(embedded[0] < 0.5, "{name}: {} px", embedded[0]);
        assert!(on_loop(&on_edges) < 0.5, "{name}");
    }
}

#[test]
fn a_boundary_past_the_outline_is_embedded_where_it_runs_over_the_model() {
    for name in ["spot.glb", "stanford_bunny.glb"] {
        let Some(mut meshes) = testdata_meshes(name) else {
            return;
        };
        let input = meshes.swap_remove(0);
        // A loop wider than the model's front: it runs off past the outline.
        let sketch = curves(&input, 50.0, 120.0);
        let edit = RegionEdit::new(&input, &sketch, &Levels::default()).unwrap();
        let traced = RegionEdit::on_edges(&input, &sketch, &Levels::default()).unwrap();
        edit.mesh().validate().unwrap();
        let on_loop = |off: &[f64]| off.iter().filter(|&&d| d < 0.5).count();
        let (embedded, on_edges) = (
            rim_off_boundary(edit.mesh(), &edit, &sketch),
            rim_off_boundary(&input, &traced, &sketch),
        );
        eprintln!(
            "{name}: rim of {} vertices, {} on the loop drawn (traced over edges: {} of {})",
            embedded.len(),
            on_loop(&embedded),
            on_loop(&on_edges),
            on_edges.len()
        );
        // Where the loop lies over the model, what stays is held by vertices on it.
        assert!(
            on_loop(&embedded) > 3 * on_loop(&on_edges).max(10),
            "{name}"
        );
    }
}

#[test]
fn half_the_transform_twice_is_the_whole() {
    let mesh = primitives::icosphere(1.0, 4);
    let sketch = curves(&mesh, 60.0, 140.0);
    let half = RegionEdit::new(&mesh, &sketch, &Levels::new(vec![0.5, 0.5]).unwrap()).unwrap();
    let full_weight =
        RegionEdit::new(&mesh, &sketch, &Levels::new(vec![1.0, 1.0]).unwrap()).unwrap();
    let t = whole(transform(DVec3::Z, 150.0, 0.8, DVec3::new(0.0, 0.3, 0.0)));
    let once = half.applied(&t);
    let mut twice = once.clone();
    half.apply_into(&t, &once, &mut twice);
    let full = full_weight.applied(&t);
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
        areas: Vec::new(),
        transform: Some(transform.to_cols_array()),
        handles: None,
        profile: None,
        remesh: false,
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
    // A drag: the transform revised frame by frame, then released. The region is found in
    // steps (placed, embedded, weighed), each a frame of its own in the page: until then the
    // model is shown as it is.
    let mut edit = editor.begin_gesture(op(&sketch, lift(0.0), None)).unwrap();
    for _ in 0..2 {
        assert_eq!(edit.step().unwrap(), Progress::Working);
        assert!(edit.moved_model().is_none() && edit.region_falloff().is_none());
        assert_eq!(
            edit.document().models[0].mesh.positions(),
            imported.positions()
        );
    }
    // Then weighed and shown; the fall-off panel's disc follows in three steps of its own
    // (its system analysed, factored, then solved), none more than 40 of the 80 ms it takes
    // at once on a 50k-vertex region.
    while edit.moved_model().is_none() {
        assert_eq!(edit.step().unwrap(), Progress::Working);
    }
    for _ in 0..2 {
        assert!(edit.region_disc().is_none());
        assert_eq!(edit.step().unwrap(), Progress::Working);
    }
    assert!(edit.region_disc().is_none());
    assert_ne!(edit.step().unwrap(), Progress::Working);
    assert!(edit.region_disc().unwrap().is_ok());
    for y in [0.05, 0.1, 0.2, 0.3] {
        edit.revise(op(&sketch, lift(y), None));
        while edit.step().unwrap() == Progress::Working {}
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

/// The page computes a region drag's commit (its remesh, 0.1 s on the bunny) in its worker:
/// the preview stays shown until the result lands, and the result is the one the kept region
/// gives here.
#[test]
fn a_region_drag_s_commit_computed_elsewhere_is_the_one_made_here() {
    let (mesh, _, mut editor, still) = sphere_in_editor();
    let remeshed = |y: f64| {
        Op::RegionEdit(RegionEditInput {
            transform: Some(DMat4::from_translation(DVec3::Y * y).to_cols_array()),
            remesh: true,
            ..still.clone()
        })
    };
    let dragged = |editor: &Editor| {
        let mut edit = editor.begin_gesture(remeshed(0.0)).unwrap();
        for y in [0.2, 0.5] {
            edit.revise(remeshed(y));
            while edit.step().unwrap() == Progress::Working {}
        }
        edit.end_gesture();
        edit
    };
    let mut here = editor.clone();
    let edit = dragged(&here);
    assert!(edit.model_op_to_run().is_some(), "offered to the worker");
    edit.finish(&mut here).unwrap();

    let mut edit = dragged(&editor);
    let shown = edit.moved_model().map(|(index, p)| (index, p.to_vec()));
    let embedded = edit.document().models[0].mesh.n_vertices();
    assert!(
        shown.is_some() && embedded > mesh.n_vertices(),
        "the preview"
    );
    supply_elsewhere(&mut edit);
    edit.finish(&mut editor).unwrap();
    assert_eq!(digest(editor.document()), digest(here.document()));
    assert_eq!(editor.session_json(), here.session_json());
    let remeshed_model = &editor.document().models[0].mesh;
    assert_ne!(
        remeshed_model.n_vertices(),
        embedded,
        "the region was remeshed"
    );
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
        let sketch = curves(&meshes[0], 50.0, 120.0);
        let edit = RegionEdit::new(&meshes[0], &sketch, &Levels::default())
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let mesh = edit.mesh();
        let (lo, hi) = mesh.bounding_box().unwrap();
        let up = 0.1 * (hi - lo).length();
        let t = transform(0.5 * (lo + hi), 20.0, 1.1, DVec3::new(0.0, up, 0.3 * up));
        let moved = edit.applied(&whole(t));
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
    let (_, sketch, mut editor, still) = sphere_in_editor();
    let imported = editor.document().models[0].mesh.clone();
    let offset = DVec2::new(30.0, -50.0);
    let dragged = dragged_region(editor.document(), &still, RegionDrag::Move, offset);
    editor.apply(Op::RegionEdit(dragged)).unwrap();
    let edit = RegionEdit::new(&imported, &sketch, &Levels::default()).unwrap();
    let moved = &editor.document().models[0].mesh;
    let middle = edit.reference()[edit.reference().len() / 2];
    let px = |m: &Mesh| screen(&sketch.camera, VIEWPORT, m.position(middle)).unwrap();
    let shift = px(moved) - px(edit.mesh());
    assert!(
        shift.distance(offset) < 2.0,
        "moved {shift} on screen for {offset}"
    );
}

#[test]
fn a_turning_drag_twists_the_region_about_the_curve_s_middle() {
    let (input, sketch, mut editor, still) = sphere_in_editor();
    let doc = editor.document();
    // 60 px to the right: 30° clockwise as seen, about the view axis.
    let turned = dragged_region(doc, &still, RegionDrag::Turn, DVec2::new(60.0, 0.0));
    let t = DMat4::from_cols_array(&turned.transform.unwrap());
    let edit = RegionEdit::new(&input, &sketch, &Levels::default()).unwrap();
    let mesh = edit.mesh();
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
    let m = DMat4::from_cols_array(&grown.transform.unwrap());
    assert!((m.x_axis.x - 2.0).abs() < 1e-12 && (m.determinant() - 8.0).abs() < 1e-9);
    let far = dragged_region(doc, &still, RegionDrag::Turn, DVec2::new(2000.0, 0.0));
    editor.apply(Op::RegionEdit(far)).unwrap();
    editor.apply(Op::RegionEdit(grown)).unwrap();
}

#[test]
fn one_handle_is_one_transform_and_handles_blend_between_neighbours() {
    let input = primitives::icosphere(1.0, 4);
    let edit = RegionEdit::new(&input, &curves(&input, 80.0, 160.0), &Levels::default()).unwrap();
    let mesh = edit.mesh();
    let t = transform(DVec3::Z, 60.0, 1.2, DVec3::new(0.0, 0.3, 0.0));
    let one = edit
        .motion(&[Handle {
            at: 0.3,
            transform: t,
        }])
        .unwrap();
    assert_eq!(edit.applied(&one), edit.applied(&whole(t)));

    // Pinned at both ends and turned in the middle: each path vertex takes Alexa's blend of
    // its two neighbouring handles, `(1 − u) ⊙ A ⊕ u ⊙ B`, and the ends stay.
    let pin = |at: f64| Handle {
        at,
        transform: DMat4::IDENTITY,
    };
    let middle = Handle {
        at: 0.5,
        transform: t,
    };
    let handles = [pin(0.0), middle, pin(1.0)];
    let moved = edit.applied(&edit.motion(&handles).unwrap());
    let log = sketchmesh_core::geometry::log_affine(t).unwrap();
    let reference = edit.reference();
    for (&v, &at) in reference.iter().zip(edit.reference_params()) {
        let u = 1.0 - (at - 0.5).abs() / 0.5;
        let exact =
            sketchmesh_core::geometry::exp_affine(log * u).transform_point3(mesh.position(v));
        assert!(moved[v.index()].distance(exact) < 1e-12, "at {at}");
    }
    // Path vertices at or beyond the curve's ends (where the pins are) stay.
    for (&v, &at) in reference.iter().zip(edit.reference_params()) {
        if at == 0.0 || at == 1.0 {
            assert_eq!(moved[v.index()], mesh.position(v));
        }
    }
    let last = *reference.last().unwrap();
    // Nothing outside the boundary moves; inside, each vertex takes its weight of the
    // transform at its nearest point of the curve, so nothing moves more than at the curve.
    let region: std::collections::HashSet<_> = edit.vertices().iter().copied().collect();
    for v in mesh.vertices().filter(|v| !region.contains(v)) {
        assert_eq!(moved[v.index()], mesh.position(v));
    }
    let most = |m: &[DVec3], vs: &mut dyn Iterator<Item = sketchmesh_core::mesh::VertexId>| {
        vs.map(|v| m[v.index()].distance(mesh.position(v)))
            .fold(0.0, f64::max)
    };
    let whole_moved = edit.applied(&whole(t));
    assert!(
        most(&moved, &mut edit.vertices().iter().copied())
            < most(&whole_moved, &mut edit.vertices().iter().copied())
    );

    // What the curve takes between handles is what a new handle there would keep.
    let quarter = blend_at(&handles, 0.25).unwrap();
    let half = sketchmesh_core::geometry::exp_affine(log * 0.5);
    assert!(
        (quarter - half)
            .to_cols_array()
            .iter()
            .all(|x| x.abs() < 1e-12)
    );
    assert_eq!(blend_at(&handles, 0.5).unwrap(), t);
    // The rail: frames on the curve, orthonormal and right-handed.
    let rail = edit.rail();
    // The rail is the sketch cast onto the surface; the edge path zig-zags about it.
    let edge = mesh.mean_edge_length();
    assert!(
        rail.frame_at(0.0)
            .origin
            .distance(mesh.position(reference[0]))
            < edge
    );
    assert!(rail.frame_at(1.0).origin.distance(mesh.position(last)) < edge);
    assert!(
        rail.points()
            .iter()
            .all(|p| (p.length() - 1.0).abs() < 0.01)
    );
    for at in [0.0, 0.3, 0.5, 0.77, 1.0] {
        let [a, b, c] = rail.frame_at(at).axes;
        assert!((a.cross(b) - c).length() < 1e-12 && (a.length() - 1.0).abs() < 1e-12);
        assert!(a.dot(b).abs() < 1e-12);
        // On the front of the sphere seen from +z, the surface normal points at the viewer.
        assert!(b.z > 0.5, "{b} at {at}");
    }

    // A handle reaches only its neighbours: with pins at 0.25 and 0.75, the curve beyond
    // them does not move.
    let handles = [pin(0.25), middle, pin(0.75)];
    let moved = edit.applied(&edit.motion(&handles).unwrap());
    for (&v, &at) in reference.iter().zip(edit.reference_params()) {
        let p = mesh.position(v);
        if !(0.25..=0.75).contains(&at) {
            assert_eq!(moved[v.index()], p, "at {at}");
        } else if (at - 0.5).abs() < 0.2 {
            assert_ne!(moved[v.index()], p, "at {at}");
        }
    }
    // Refused: no handle, a handle off the curve, two at one place, a mirror.
    let mirror = DMat4::from_scale(DVec3::new(-1.0, 1.0, 1.0));
    for (handles, expected) in [
        (vec![], RegionError::BadHandles),
        (vec![pin(1.5)], RegionError::BadHandles),
        (vec![pin(0.5), middle], RegionError::BadHandles),
        (vec![pin(f64::NAN)], RegionError::BadHandles),
        (
            vec![Handle {
                at: 0.2,
                transform: mirror,
            }],
            RegionError::TransformMirrors,
        ),
    ] {
        assert_eq!(edit.motion(&handles).unwrap_err(), expected);
    }
}

#[test]
fn a_handles_op_replays_and_one_motion_is_required() {
    let (_, _, mut editor, still) = sphere_in_editor();
    let before = digest(editor.document());
    let turn = transform(DVec3::Z, 40.0, 1.0, DVec3::new(0.0, 0.2, 0.0));
    let handle = |at: f64, t: DMat4| sketchmesh_core::document::HandleInput {
        at,
        transform: t.to_cols_array(),
    };
    let handles = RegionEditInput {
        transform: None,
        handles: Some(vec![handle(0.0, DMat4::IDENTITY), handle(1.0, turn)]),
        profile: None,
        ..still.clone()
    };
    for unclear in [
        RegionEditInput {
            transform: None,
            ..still.clone()
        },
        RegionEditInput {
            handles: handles.handles.clone(),
            ..still.clone()
        },
    ] {
        match editor.apply(Op::RegionEdit(unclear)) {
            Err(CommandError::Region(RegionError::MotionUnclear)) => {}
            other => panic!("{other:?}"),
        }
        assert_eq!(digest(editor.document()), before);
    }
    // A drag of the handles: the preview commits what replay gives.
    let mut edit = editor.begin_gesture(Op::RegionEdit(still.clone())).unwrap();
    edit.revise(Op::RegionEdit(handles.clone()));
    edit.step().unwrap();
    edit.finish(&mut editor).unwrap();
    assert_ne!(digest(editor.document()), before);
    let replayed = Editor::replay_json(&editor.session_json()).unwrap();
    assert_eq!(digest(replayed.document()), digest(editor.document()));
    assert!(editor.session_json().contains("\"handles\""));
}

#[test]
fn the_region_lies_flat_in_the_unit_disc_without_a_flipped_triangle() {
    let sphere = primitives::icosphere(1.0, 4);
    let mut cases = vec![("sphere".to_string(), sphere)];
    for name in ["stanford_bunny.glb", "nefertiti.glb"] {
        if let Some(mut meshes) = testdata_meshes(name) {
            cases.push((name.to_string(), meshes.swap_remove(0)));
        }
    }
    for (name, mesh) in &cases {
        let edit = RegionEdit::new(mesh, &curves(mesh, 50.0, 120.0), &Levels::default()).unwrap();
        let disc = edit.disc().unwrap_or_else(|e| panic!("{name}: {e}"));
        let mesh = edit.mesh();
        assert_eq!(disc.len(), edit.vertices().len());
        assert!(
            disc.iter()
                .all(|p| p.is_finite() && p.length() <= 1.0 + 1e-9),
            "{name}"
        );
        let on_circle = disc
            .iter()
            .filter(|p| (p.length() - 1.0).abs() < 1e-12)
            .count();
        assert!(on_circle > 10, "{name}: {on_circle} on the rim");
        // Every triangle inside the region turns the same way in the disc (Tutte's
        // embedding of a disc); where the region pinches to a vertex on its rim (on
        // Nefertiti, 5 such vertices) it is no disc, and a few triangles there may fold.
        let at: std::collections::HashMap<_, _> = edit
            .vertices()
            .iter()
            .copied()
            .zip(disc.iter().copied())
            .collect();
        let (mut positive, mut negative) = (0, 0);
        for f in mesh.faces() {
            let Some([a, b, c]) = mesh
                .face_vertices(f)
                .map(|v| at.get(&v).copied())
                .into_iter()
                .collect::<Option<Vec<_>>>()
                .map(|v| [v[0], v[1], v[2]])
            else {
                continue;
            };
            let area = (b - a).perp_dot(c - a);
            if area > 0.0 {
                positive += 1;
            } else {
                negative += 1;
            }
        }
        eprintln!(
            "{name}: {} region vertices flat, {positive} / {negative} triangles",
            disc.len()
        );
        let (folded, kept) = (positive.min(negative), positive.max(negative));
        assert!(kept > 100, "{name}: {kept} triangles");
        if name == "sphere" || name == "stanford_bunny.glb" {
            assert_eq!(folded, 0, "{name}");
        }
        assert!(folded * 500 < kept, "{name}: {folded} of {kept} folded");
    }
}

#[test]
fn a_stretched_region_is_remeshed_and_the_rest_stays() {
    let (mesh, _, mut editor, still) = sphere_in_editor();
    // Stretched to three times its size along the view: long, thin triangles.
    let (lo, hi) = mesh.bounding_box().unwrap();
    let centre = 0.5 * (lo + hi);
    let stretch = DMat4::from_translation(centre)
        * DMat4::from_scale(DVec3::new(1.0, 1.0, 3.0))
        * DMat4::from_translation(-centre);
    let op = |remesh| {
        Op::RegionEdit(RegionEditInput {
            transform: Some(stretch.to_cols_array()),
            levels: Some(vec![0.0, 1.0, 1.0]),
            areas: Vec::new(),
            remesh,
            ..still.clone()
        })
    };
    let mut plain = Editor::new();
    plain.apply(import_mesh("sphere.glb", &mesh)).unwrap();
    plain.apply(op(false)).unwrap();
    editor.apply(op(true)).unwrap();
    let (stretched, remeshed) = (
        &plain.document().models[0].mesh,
        &editor.document().models[0].mesh,
    );
    let longest = |m: &Mesh| {
        m.faces()
            .flat_map(|f| {
                let [a, b, c] = m.face_positions(f);
                [a.distance(b), b.distance(c), c.distance(a)]
            })
            .fold(0.0, f64::max)
    };
    let target = mesh.mean_edge_length();
    eprintln!(
        "longest edge: stretched {:.4}, remeshed {:.4} (target {target:.4}); {} → {} vertices",
        longest(stretched),
        longest(remeshed),
        stretched.n_vertices(),
        remeshed.n_vertices()
    );
    assert!(
        remeshed.n_vertices() > stretched.n_vertices(),
        "the stretch got new vertices"
    );
    assert!(longest(remeshed) < 0.8 * longest(stretched));
    remeshed.validate().unwrap();
    // Outside the region every vertex is where it was, bit for bit (the positions as
    // imported, which a glTF file holds in single precision).
    let mut imported = Editor::new();
    imported.apply(import_mesh("sphere.glb", &mesh)).unwrap();
    let before = &imported.document().models[0].mesh;
    // The region as the input's vertices (the op's curves, smoothed, are embedded at other
    // places than the raw ones here; the input's vertices are the same).
    let edit = RegionEdit::new(before, &curves(&mesh, 60.0, 140.0), &Levels::default()).unwrap();
    let region: std::collections::HashSet<_> = edit.vertices().iter().copied().collect();
    let kept: std::collections::HashSet<[u64; 3]> = remeshed
        .positions()
        .iter()
        .map(|p| p.to_array().map(f64::to_bits))
        .collect();
    let bits = |v: sketchmesh_core::mesh::VertexId| before.position(v).to_array().map(f64::to_bits);
    let moved = before
        .vertices()
        .filter(|v| !region.contains(v) && !kept.contains(&bits(*v)))
        .count();
    assert_eq!(moved, 0, "outside vertices moved");
    // The session replays it.
    let replayed = Editor::replay_json(&editor.session_json()).unwrap();
    assert_eq!(digest(replayed.document()), digest(editor.document()));
    assert!(editor.session_json().contains("\"remesh\":true"));
}

#[test]
fn a_resketched_profile_is_the_new_cross_section() {
    let mut cases = vec![("sphere".to_string(), primitives::icosphere(1.0, 5))];
    if let Some(mut meshes) = testdata_meshes("spot.glb") {
        cases.push(("spot.glb".to_string(), meshes.swap_remove(0)));
    }
    for (name, mesh) in &cases {
        let edit = RegionEdit::new(mesh, &curves(mesh, 70.0, 150.0), &Levels::default()).unwrap();
        let mesh = edit.mesh();
        let profile = edit.profile(0.5).unwrap();
        let (lo, hi) = (
            profile.points[0].x,
            profile.points[profile.points.len() - 1].x,
        );
        assert!(
            lo < 0.0 && hi > 0.0,
            "{name}: across the curve from {lo} to {hi}"
        );
        assert!(profile.points.windows(2).all(|w| w[0].distance(w[1]) > 0.0));
        // On the plane through the curve's middle, across it.
        for &p in &profile.points {
            let d = (profile.to_world(p) - profile.frame.origin).dot(profile.frame.axes[0]);
            assert!(d.abs() < 1e-12, "{name}");
        }
        // A bump across the middle, from the cross-section back to it, a tenth of the
        // width high.
        let width = hi - lo;
        let raise = 0.1 * width;
        let stroke: Vec<DVec2> = (0..=40)
            .map(|i| {
                let u = lo + width * (0.3 + 0.4 * f64::from(i) / 40.0);
                let base = profile
                    .points
                    .iter()
                    .min_by(|a, b| (a.x - u).abs().total_cmp(&(b.x - u).abs()))
                    .unwrap()
                    .y;
                let t = f64::from(i) / 40.0;
                DVec2::new(u, base + raise * (std::f64::consts::PI * t).sin())
            })
            .collect();
        let change = ProfileChange::new(&profile, &stroke).unwrap();
        let moved = edit.profile_applied(0.5, &stroke).unwrap();
        let moved_mesh = {
            let mut m = mesh.clone();
            m.positions_mut().copy_from_slice(&moved);
            m
        };
        let after = edit.cross_section_in(&moved_mesh, profile.frame).unwrap();
        // Within 2 px of the merged stroke in a 200 px panel across the cross-section.
        let px = 200.0 / width;
        let merged = &change.merged;
        let worst = after
            .points
            .iter()
            .filter(|p| p.x > lo + 0.05 * width && p.x < hi - 0.05 * width)
            .map(|p| sketchmesh_core::curve::polyline::distance_to_polyline(*p, merged) * px)
            .fold(0.0, f64::max);
        eprintln!(
            "{name}: {} profile points, worst {worst:.2} px",
            after.points.len()
        );
        assert!(worst < 2.0, "{name}: {worst} px off the stroke");
        // The middle rose by the raise; outside the region nothing moved.
        let middle = after
            .points
            .iter()
            .min_by(|a, b| a.x.abs().total_cmp(&b.x.abs()))
            .unwrap();
        let old_middle = profile
            .points
            .iter()
            .min_by(|a, b| a.x.abs().total_cmp(&b.x.abs()))
            .unwrap();
        assert!(
            (middle.y - old_middle.y - raise).abs() < 0.02 * width,
            "{name}"
        );
        let region: std::collections::HashSet<_> = edit.vertices().iter().copied().collect();
        for v in mesh.vertices().filter(|v| !region.contains(v)) {
            assert_eq!(moved[v.index()], mesh.position(v));
        }
    }
}

#[test]
fn a_profile_op_replays_and_a_bad_stroke_is_refused() {
    let (_, _, mut editor, still) = sphere_in_editor();
    let before = digest(editor.document());
    let profile = |stroke: Vec<[f64; 2]>| RegionEditInput {
        transform: None,
        profile: Some(sketchmesh_core::document::ProfileInput { at: 0.5, stroke }),
        ..still.clone()
    };
    match editor.apply(Op::RegionEdit(profile(vec![[0.0, 0.1]]))) {
        Err(CommandError::Region(RegionError::BadProfileStroke)) => {}
        other => panic!("{other:?}"),
    }
    assert_eq!(digest(editor.document()), before);
    let bump = vec![
        [-0.1, 0.0],
        [-0.05, 0.08],
        [0.0, 0.1],
        [0.05, 0.08],
        [0.1, 0.0],
    ];
    editor.apply(Op::RegionEdit(profile(bump))).unwrap();
    assert_ne!(digest(editor.document()), before);
    let replayed = Editor::replay_json(&editor.session_json()).unwrap();
    assert_eq!(digest(replayed.document()), digest(editor.document()));
}

#[test]
fn an_area_of_the_falloff_has_its_own_levels() {
    let (mesh, sketch, mut editor, still) = sphere_in_editor();
    let middle = sketch.reference[sketch.reference.len() / 2];
    // A lasso over the right half of the region, where nothing is to move.
    let lasso: Vec<[f64; 3]> = [(0.0, -200.0), (300.0, -200.0), (300.0, 200.0), (0.0, 200.0)]
        .iter()
        .map(|&(x, y)| [middle.x + x, middle.y + y, 0.5])
        .collect();
    let lift = DMat4::from_translation(DVec3::new(0.0, 0.2, 0.0));
    let input = RegionEditInput {
        transform: Some(lift.to_cols_array()),
        areas: vec![sketchmesh_core::document::AreaInput {
            lasso: lasso.clone(),
            levels: vec![0.0, 0.0],
        }],
        ..still.clone()
    };
    editor.apply(Op::RegionEdit(input)).unwrap();
    let moved = &editor.document().models[0].mesh;
    let mut imported = Editor::new();
    imported.apply(import_mesh("sphere.glb", &mesh)).unwrap();
    let before = &imported.document().models[0].mesh;
    let (mut right_moved, mut left_moved) = (0, 0);
    for v in before.vertices() {
        let p = before.position(v);
        let Some(at) = screen(&sketch.camera, VIEWPORT, p) else {
            continue;
        };
        let changed = moved.position(v) != p;
        if at.x > middle.x + 2.0 && changed {
            right_moved += 1;
        }
        if at.x < middle.x - 2.0 && changed {
            left_moved += 1;
        }
    }
    assert_eq!(right_moved, 0, "inside the area nothing moves");
    assert!(left_moved > 50, "outside it the region moves: {left_moved}");
    let replayed = Editor::replay_json(&editor.session_json()).unwrap();
    assert_eq!(digest(replayed.document()), digest(editor.document()));
    // A lasso of two points is refused.
    let bad = RegionEditInput {
        areas: vec![sketchmesh_core::document::AreaInput {
            lasso: lasso[..2].to_vec(),
            levels: vec![0.0, 0.0],
        }],
        ..still
    };
    match editor.apply(Op::RegionEdit(bad)) {
        Err(CommandError::Region(RegionError::BadArea)) => {}
        other => panic!("{other:?}"),
    }
}

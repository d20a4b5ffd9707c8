//! FiberMesh's topology operations and moving models through the document (issue 16): a cut
//! of a created shape and of a real scan leaves a closed manifold with a flat cap whose rim
//! is a sharp curve, nothing beyond the cut, every curve an edge chain; it undoes and replays
//! exactly, and a stroke that does not cross is refused with the document untouched. Models
//! are moved, mirrored, duplicated and deleted exactly, and an import lands beside them.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::f64::consts::TAU;

use glam::{DMat4, DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{
    CommandError, DuplicateInput, Editor, MergeInput, Model, ModelInput, Op, StrokeInput,
    StrokePairInput, TransformInput,
};
use sketchmesh_core::fibermesh::cut::CutError;
use sketchmesh_core::geometry::{Bvh, enclosed_volume};

use crate::common::{import_mesh, samples, segment, supply_elsewhere, testdata_meshes};

const VIEWPORT: DVec2 = DVec2::new(800.0, 600.0);
const CENTRE: DVec2 = DVec2::new(400.0, 300.0);

fn input(camera: Camera, points: &[DVec2]) -> StrokeInput {
    StrokeInput {
        viewport: VIEWPORT.to_array(),
        camera,
        stroke: samples(points.iter().copied()),
    }
}

fn created_circle() -> Editor {
    let circle: Vec<DVec2> = (0..=80)
        .map(|i| CENTRE + 150.0 * DVec2::from_angle(TAU * f64::from(i) / 80.0))
        .collect();
    let mut editor = Editor::new();
    editor
        .apply(Op::Create(input(Camera::default(), &circle).into()))
        .unwrap();
    editor
}

/// A vertical cut at screen x = `x`, from above the view's middle to below it.
fn vertical_cut(camera: Camera, x: f64) -> Op {
    let stroke = segment(DVec2::new(x, 20.0), DVec2::new(x, 580.0));
    Op::Cut(input(camera, &stroke))
}

/// How far past screen x = `x` (px) the farthest vertex of the model lies.
fn past(model: &Model, camera: &Camera, x: f64) -> f64 {
    model
        .mesh
        .positions()
        .iter()
        .map(|&p| camera.screen_from_world(p, VIEWPORT).unwrap().x - x)
        .fold(f64::MIN, f64::max)
}

/// Closed, manifold, genus 0, no triangle through another, every curve a chain of mesh
/// edges.
fn assert_closed_and_embedded(model: &Model) {
    assert_closed_of_genus(model, 0);
}

/// Closed, manifold, of genus `genus`, no triangle through another, every curve a chain of
/// mesh edges.
fn assert_closed_of_genus(model: &Model, genus: u32) {
    let mesh = &model.mesh;
    mesh.validate().unwrap();
    assert!(mesh.is_closed());
    assert_eq!(mesh.genus(), Some(genus));
    let crossing = Bvh::new(mesh).crossing_faces(mesh, |_| true);
    assert!(crossing.is_empty(), "triangles cross: {crossing:?}");
    for curve in &model.curves {
        let n = curve.vertices.len();
        let links = if curve.is_closed { n } else { n - 1 };
        for k in 0..links {
            let (a, b) = (curve.vertices[k], curve.vertices[(k + 1) % n]);
            assert!(mesh.find_edge(a, b).is_some(), "{a:?}–{b:?} is no edge");
        }
    }
}

#[test]
fn a_cut_across_a_created_shape_leaves_a_flat_cap_with_a_sharp_rim() {
    let mut editor = created_circle();
    let before = editor.document().clone();
    let volume_before = enclosed_volume(&before.models[0].mesh);
    let camera = Camera::default();
    let x = CENTRE.x + 60.0;
    editor.apply(vertical_cut(camera, x)).unwrap();
    let model = &editor.document().models[0];
    assert_closed_and_embedded(model);
    let rim = model.curves.last().unwrap();
    assert!(rim.is_closed && rim.is_sharp());
    // The outline curve lost its part past the cut: one open smooth piece is left.
    let smooth: Vec<_> = model.curves.iter().filter(|c| !c.is_sharp()).collect();
    assert_eq!(smooth.len(), 1);
    assert!(!smooth[0].is_closed);
    // The rim lies on the cutting surface, and the surface settled behind it.
    for p in rim.points(&model.mesh) {
        let s = camera.screen_from_world(p, VIEWPORT).unwrap();
        assert!((s.x - x).abs() < 1e-6, "rim point at x = {}", s.x);
    }
    let past = past(model, &camera, x);
    assert!(past < 0.05, "a vertex lies {past} px past the cut");
    let volume = enclosed_volume(&model.mesh);
    assert!(volume < 0.95 * volume_before && volume > 0.5 * volume_before);
    // Undo gives the shape back bit for bit; replay gives the cut bit for bit.
    let cut = editor.document().clone();
    editor.apply(Op::Undo).unwrap();
    assert_eq!(editor.document(), &before);
    editor.apply(Op::Redo).unwrap();
    assert_eq!(editor.document(), &cut);
    let replayed = Editor::replay_json(&editor.session_json()).unwrap();
    assert_eq!(replayed.document(), &cut);
}

#[test]
fn a_cut_shape_stays_editable_with_curves_and_a_second_cut() {
    let mut editor = created_circle();
    let camera = Camera::default();
    editor.apply(vertical_cut(camera, CENTRE.x + 60.0)).unwrap();
    let across = segment(
        CENTRE - DVec2::new(250.0, 40.0),
        CENTRE + DVec2::new(250.0, -40.0),
    );
    editor.apply(Op::Cut(input(camera, &across))).unwrap();
    let model = &editor.document().models[0];
    assert_closed_and_embedded(model);
    assert_eq!(model.curves.iter().filter(|c| c.is_sharp()).count(), 2);
    // The first rim lost its part past the second cut: it is open now, the second closed.
    let rims: Vec<_> = model.curves.iter().filter(|c| c.is_sharp()).collect();
    assert!(!rims[0].is_closed && rims[1].is_closed);
    let json = editor.session_json();
    assert!(json.contains(r#""op":"cut""#));
    let replayed = Editor::replay_json(&json).unwrap();
    assert_eq!(replayed.document(), editor.document());
}

#[test]
fn strokes_that_do_not_cut_are_refused_and_change_nothing() {
    let mut editor = created_circle();
    let before = editor.document().clone();
    let json = editor.session_json();
    let camera = Camera::default();
    let from_inside = segment(CENTRE, CENTRE + DVec2::new(0.0, 280.0));
    let beside = segment(DVec2::new(700.0, 20.0), DVec2::new(700.0, 580.0));
    let refusals = [
        (from_inside, CommandError::Cut(CutError::DoesNotCross)),
        (beside, CommandError::Cut(CutError::DoesNotCross)),
    ];
    for (stroke, expected) in refusals {
        let error = editor.apply(Op::Cut(input(camera, &stroke))).unwrap_err();
        assert_eq!(error, expected);
        assert!(!error.to_string().is_empty());
        assert_eq!(editor.document(), &before);
        assert_eq!(editor.session_json(), json);
    }
}

#[test]
fn a_cut_through_a_real_scan_closes_it_with_a_flat_cap() {
    let Some(meshes) = testdata_meshes("spot.glb") else {
        return;
    };
    let spot = &meshes[0];
    let (lo, hi) = spot.bounding_box().unwrap();
    let centre = 0.5 * (lo + hi);
    let camera = Camera {
        eye: centre + DVec3::Z * 2.5 * lo.distance(hi),
        target: centre,
        ..Camera::default()
    };
    let mut editor = Editor::new();
    editor.apply(import_mesh("spot.glb", spot)).unwrap();
    // Through the head: spot faces +x, so the smaller part past the line is the head.
    let head = camera
        .screen_from_world(
            DVec3::new(hi.x - 0.25 * (hi.x - lo.x), centre.y, centre.z),
            VIEWPORT,
        )
        .unwrap();
    editor.apply(vertical_cut(camera, head.x)).unwrap();
    let model = &editor.document().models[0];
    assert!(model.curves.is_empty(), "an imported model gets no curves");
    assert_closed_and_embedded(model);
    let past = past(model, &camera, head.x);
    assert!(past < 0.05, "a vertex lies {past} px past the cut");
    let volume = enclosed_volume(&model.mesh);
    let whole = enclosed_volume(spot);
    assert!(
        volume < 0.97 * whole && volume > 0.6 * whole,
        "{volume} of {whole}"
    );
}

// ---------------------------------------------------------------------------------------
// Moving, deleting and duplicating models
// ---------------------------------------------------------------------------------------

fn bounds(model: &Model) -> (DVec3, DVec3) {
    model.mesh.bounding_box().unwrap()
}

#[test]
fn a_transform_moves_rotates_and_scales_a_model_with_its_curves() {
    let mut editor = created_circle();
    let before = editor.document().models[0].clone();
    let volume = enclosed_volume(&before.mesh);
    let matrix = DMat4::from_scale_rotation_translation(
        DVec3::splat(1.5),
        glam::DQuat::from_rotation_y(0.7),
        DVec3::new(2.0, -1.0, 0.5),
    );
    editor
        .apply(Op::Transform(TransformInput {
            model: 0,
            matrix: matrix.to_cols_array(),
        }))
        .unwrap();
    let after = &editor.document().models[0];
    for (p, q) in before.mesh.positions().iter().zip(after.mesh.positions()) {
        assert!(matrix.transform_point3(*p).distance(*q) < 1e-12);
    }
    assert_eq!(
        after.curves, before.curves,
        "curves are vertex chains and follow"
    );
    assert_eq!(after.mesh.triangles(), before.mesh.triangles());
    let scaled = enclosed_volume(&after.mesh);
    assert!((scaled / (1.5f64.powi(3) * volume) - 1.0).abs() < 1e-9);
    let replayed = Editor::replay_json(&editor.session_json()).unwrap();
    assert_eq!(replayed.document(), editor.document());
}

#[test]
fn a_mirror_keeps_the_surface_facing_out() {
    let mut editor = created_circle();
    let volume = enclosed_volume(&editor.document().models[0].mesh);
    let mirror = DMat4::from_scale(DVec3::new(-1.0, 1.0, 1.0));
    editor
        .apply(Op::Transform(TransformInput {
            model: 0,
            matrix: mirror.to_cols_array(),
        }))
        .unwrap();
    let mesh = &editor.document().models[0].mesh;
    mesh.validate().unwrap();
    assert!(
        (enclosed_volume(mesh) / volume - 1.0).abs() < 1e-9,
        "still outward"
    );
}

#[test]
fn bad_transforms_are_refused_and_change_nothing() {
    let mut editor = created_circle();
    let before = editor.document().clone();
    let mut not_finite = DMat4::IDENTITY.to_cols_array();
    not_finite[12] = f64::NAN;
    let flat = DMat4::from_scale(DVec3::new(1.0, 0.0, 1.0)).to_cols_array();
    let mut projective = DMat4::IDENTITY.to_cols_array();
    projective[3] = 0.5;
    for matrix in [not_finite, flat, projective] {
        let error = editor
            .apply(Op::Transform(TransformInput { model: 0, matrix }))
            .unwrap_err();
        assert_eq!(error, CommandError::BadTransform);
        assert_eq!(editor.document(), &before);
    }
    let missing = Op::Transform(TransformInput {
        model: 3,
        matrix: DMat4::IDENTITY.to_cols_array(),
    });
    assert_eq!(
        editor.apply(missing).unwrap_err(),
        CommandError::NoSuchModel(3)
    );
    let error = editor
        .apply(Op::Delete(ModelInput { model: 1 }))
        .unwrap_err();
    assert_eq!(error, CommandError::NoSuchModel(1));
}

#[test]
fn duplicate_puts_a_copy_beside_and_delete_removes_one_undoably() {
    let mut editor = created_circle();
    editor
        .apply(Op::Duplicate(DuplicateInput {
            model: 0,
            beside: None,
        }))
        .unwrap();
    let models = &editor.document().models;
    assert_eq!(models.len(), 2);
    let ((lo, hi), (copy_lo, _)) = (bounds(&models[0]), bounds(&models[1]));
    assert!(copy_lo.x > hi.x, "the copy lies beside the original");
    assert!((copy_lo.x - lo.x - 1.2 * (hi.x - lo.x)).abs() < 1e-9);
    assert_eq!(models[1].curves, models[0].curves);
    let both = editor.document().clone();
    editor.apply(Op::Delete(ModelInput { model: 0 })).unwrap();
    assert_eq!(editor.document().models.len(), 1);
    assert_eq!(editor.document().models[0], both.models[1]);
    editor.apply(Op::Undo).unwrap();
    assert_eq!(editor.document(), &both);
    let replayed = Editor::replay_json(&editor.session_json()).unwrap();
    assert_eq!(replayed.document(), editor.document());
}

#[test]
fn duplicates_along_a_direction_land_beside_overlapping_no_model_and_replay_exactly() {
    let mut editor = created_circle();
    // A second model just right of the first: the nearest free spot is past it.
    let (lo, hi) = bounds(&editor.document().models[0]);
    editor
        .apply(Op::Duplicate(DuplicateInput {
            model: 0,
            beside: None,
        }))
        .unwrap();
    let overlap =
        |a: (DVec3, DVec3), b: (DVec3, DVec3)| (a.1.min(b.1) - a.0.max(b.0)).min_element();
    let right = DVec3::new(0.8, 0.0, -0.6);
    for _ in 0..4 {
        editor
            .apply(Op::Duplicate(DuplicateInput {
                model: 0,
                beside: Some(right.to_array()),
            }))
            .unwrap();
    }
    let boxes: Vec<_> = editor.document().models.iter().map(|m| bounds(m)).collect();
    assert_eq!(boxes.len(), 6);
    for (i, &a) in boxes.iter().enumerate() {
        for &b in &boxes[i + 1..] {
            assert!(overlap(a, b) < 0.0, "{a:?} overlaps {b:?}");
        }
    }
    // Each copy lies along the direction from the original, the first nearest.
    let along = |k: usize| (boxes[k].0 - lo).dot(right);
    let offsets: Vec<f64> = (2..6).map(along).collect();
    assert!(offsets.windows(2).all(|w| w[0] < w[1]), "{offsets:?}");
    for copy in &boxes[2..6] {
        let moved = copy.0 - lo;
        assert!(
            moved.cross(right).length() < 1e-9 * (1.0 + moved.length()),
            "{moved:?}"
        );
    }
    // The first copy is as near as the gap allows: a model-sized step, not more.
    let size = (hi - lo).max_element();
    assert!(
        offsets[0] < 2.5 * size,
        "{offsets:?} for a model {size} wide"
    );
    let replayed = Editor::replay_json(&editor.session_json()).unwrap();
    assert_eq!(
        replayed.document(),
        editor.document(),
        "it replays bit for bit"
    );
}

#[test]
fn an_import_beside_lands_next_to_the_models_and_into_an_empty_document_stays() {
    let sphere = sketchmesh_core::mesh::primitives::icosphere(1.0, 2);
    let beside = |op: Op| match op {
        Op::Import(mut input) => {
            input.beside = true;
            Op::Import(input)
        }
        other => other,
    };
    // Sessions from before the field import where the file says (the .glb holds f32).
    let mut old = Editor::new();
    old.apply(import_mesh("a.glb", &sphere)).unwrap();
    old.apply(import_mesh("b.glb", &sphere)).unwrap();
    let as_read = old.document().models[0].mesh.positions().to_vec();
    assert_eq!(old.document().models[1].mesh.positions(), as_read);
    let mut editor = Editor::new();
    editor.apply(beside(import_mesh("a.glb", &sphere))).unwrap();
    let first = editor.document().models[0].mesh.positions();
    assert_eq!(
        first, as_read,
        "into an empty document the file's coordinates stay"
    );
    editor.apply(beside(import_mesh("b.glb", &sphere))).unwrap();
    let models = &editor.document().models;
    let ((lo, hi), (new_lo, new_hi)) = (bounds(&models[0]), bounds(&models[1]));
    let gap = new_lo.x - hi.x;
    assert!(
        (gap - 0.1 * (hi.x - lo.x)).abs() < 1e-12,
        "beside, a tenth of their size apart ({gap})"
    );
    assert!((new_lo.y - lo.y).abs() < 1e-12, "on the same floor");
    assert!(
        (new_hi.z + new_lo.z - hi.z - lo.z).abs() < 1e-12,
        "centred in depth"
    );
    let json = editor.session_json();
    assert!(json.contains(r#""beside":true"#));
    let replayed = Editor::replay_json(&json).unwrap();
    assert_eq!(replayed.document(), editor.document());
}

// ---------------------------------------------------------------------------------------
// Tunnels
// ---------------------------------------------------------------------------------------

/// A closed loop of `radius` px around the view's centre.
fn loop_around_centre(camera: Camera, radius: f64) -> StrokeInput {
    let points: Vec<DVec2> = (0..=48)
        .map(|i| CENTRE + radius * DVec2::from_angle(TAU * f64::from(i) / 48.0))
        .collect();
    input(camera, &points)
}

fn behind() -> Camera {
    Camera {
        eye: DVec3::new(0.0, 0.0, -5.0),
        ..Camera::default()
    }
}

#[test]
fn loops_on_the_front_and_the_back_of_a_shape_drill_a_smooth_tunnel() {
    let mut editor = created_circle();
    let before = editor.document().clone();
    let volume_before = enclosed_volume(&before.models[0].mesh);
    let strokes = [
        loop_around_centre(Camera::default(), 40.0),
        loop_around_centre(behind(), 40.0),
    ];
    editor
        .apply(Op::Tunnel(StrokePairInput { strokes }))
        .unwrap();
    let model = &editor.document().models[0];
    assert_closed_of_genus(model, 1);
    let loops: Vec<_> = model.curves.iter().skip(1).collect();
    assert_eq!(loops.len(), 2);
    assert!(loops.iter().all(|c| c.is_closed && !c.is_sharp()));
    let volume = enclosed_volume(&model.mesh);
    assert!(
        volume < 0.98 * volume_before && volume > 0.5 * volume_before,
        "{volume} of {volume_before}"
    );
    // The view straight through the hole: the ray down the axis meets nothing.
    let hit = sketchmesh_core::geometry::raycast(&model.mesh, DVec3::new(0.0, 0.0, 5.0), -DVec3::Z);
    assert!(hit.is_none(), "the tunnel is open: {hit:?}");
    let tunnelled = editor.document().clone();
    editor.apply(Op::Undo).unwrap();
    assert_eq!(editor.document(), &before);
    editor.apply(Op::Redo).unwrap();
    let replayed = Editor::replay_json(&editor.session_json()).unwrap();
    assert_eq!(replayed.document(), &tunnelled);
}

#[test]
fn a_second_loop_beside_the_first_on_the_same_side_is_refused_or_drills_inside() {
    let mut editor = created_circle();
    let before = editor.document().clone();
    let far = Op::Tunnel(StrokePairInput {
        strokes: [
            loop_around_centre(Camera::default(), 40.0),
            input(
                Camera::default(),
                &segment(DVec2::new(700.0, 50.0), DVec2::new(760.0, 80.0)),
            ),
        ],
    });
    assert!(editor.apply(far).is_err());
    assert_eq!(editor.document(), &before);
}

// ---------------------------------------------------------------------------------------
// Extrusions
// ---------------------------------------------------------------------------------------

/// [`extrusion_points`]'s base loop as a stroke in `camera`'s view, and its silhouette.
fn extrusion(camera: Camera, centre: DVec2, radius: f64, reach: f64) -> (StrokeInput, Vec<DVec2>) {
    let (base, silhouette) = crate::common::extrusion_points(centre, radius, reach);
    (input(camera, &base), silhouette)
}

/// The distance (px) from `p` to the nearest point of the visible outlines of `model`.
fn to_outline(model: &Model, camera: &Camera, p: DVec2) -> f64 {
    crate::common::outlines(&model.mesh, camera, VIEWPORT)
        .iter()
        .flat_map(|line| line.windows(2).map(|w| (w[0], w[1])))
        .map(|(a, b)| {
            let t = ((p - a).dot(b - a) / (b - a).length_squared().max(1e-12)).clamp(0.0, 1.0);
            p.distance(a + t * (b - a))
        })
        .fold(f64::INFINITY, f64::min)
}

/// The size of a model on screen: its projected bounding box's diagonal.
fn screen_size(model: &Model, camera: &Camera) -> f64 {
    let points: Vec<DVec2> = (model.mesh.positions().iter())
        .map(|&p| camera.screen_from_world(p, VIEWPORT).unwrap().truncate())
        .collect();
    let lo = points.iter().fold(DVec2::MAX, |a, &b| a.min(b));
    let hi = points.iter().fold(DVec2::MIN, |a, &b| a.max(b));
    lo.distance(hi)
}

#[test]
fn a_loop_and_a_silhouette_grow_a_limb_whose_outline_follows_the_stroke() {
    let mut editor = created_circle();
    let before = editor.document().clone();
    let camera = Camera::default();
    let (base, silhouette) = extrusion(camera, CENTRE + DVec2::new(90.0, 0.0), 30.0, 160.0);
    let strokes = [base, input(camera, &silhouette)];
    editor
        .apply(Op::Extrude(StrokePairInput { strokes }))
        .unwrap();
    let model = &editor.document().models[0];
    assert_closed_of_genus(model, 0);
    let new: Vec<_> = model.curves.iter().skip(1).collect();
    assert_eq!(new.len(), 2);
    assert!(
        new[0].is_closed && new[0].is_sharp(),
        "the base loop is sharp"
    );
    assert!(
        !new[1].is_closed && !new[1].is_sharp(),
        "the silhouette is smooth"
    );
    // Beyond the body, the limb's outline follows the stroke within 3% of the model's size.
    let tolerance = 0.03 * screen_size(model, &camera);
    let beyond = silhouette.iter().filter(|p| p.x > CENTRE.x + 150.0);
    let worst = beyond
        .map(|&p| to_outline(model, &camera, p))
        .fold(0.0, f64::max);
    assert!(
        worst < tolerance,
        "the outline is {worst} px off the stroke (allowed {tolerance})"
    );
    let grown = editor.document().clone();
    editor.apply(Op::Undo).unwrap();
    assert_eq!(editor.document(), &before);
    editor.apply(Op::Redo).unwrap();
    let replayed = Editor::replay_json(&editor.session_json()).unwrap();
    assert_eq!(replayed.document(), &grown);
}

#[test]
fn a_silhouette_that_does_not_start_and_end_near_the_loop_is_refused() {
    let mut editor = created_circle();
    let before = editor.document().clone();
    let camera = Camera::default();
    let (base, _) = extrusion(camera, CENTRE + DVec2::new(90.0, 0.0), 30.0, 160.0);
    let (_, elsewhere) = extrusion(camera, CENTRE + DVec2::new(-90.0, 0.0), 30.0, 160.0);
    let strokes = [base, input(camera, &elsewhere)];
    let error = editor
        .apply(Op::Extrude(StrokePairInput { strokes }))
        .unwrap_err();
    assert!(
        error.to_string().contains("near one side of the loop"),
        "{error}"
    );
    assert_eq!(editor.document(), &before);
}

// ---------------------------------------------------------------------------------------
// Merging
// ---------------------------------------------------------------------------------------

/// A document with the created circle and a smaller one created beside it, then moved
/// `overlap` px (at the target plane) into it.
fn two_shapes_overlapping(overlap: f64) -> Editor {
    let mut editor = created_circle();
    let beside: Vec<DVec2> = (0..=80)
        .map(|i| {
            CENTRE + DVec2::new(300.0, 0.0) + 100.0 * DVec2::from_angle(TAU * f64::from(i) / 80.0)
        })
        .collect();
    editor
        .apply(Op::Create(input(Camera::default(), &beside).into()))
        .unwrap();
    let camera = Camera::default();
    let at = |x: f64| {
        camera
            .point_on_target_plane(CENTRE + DVec2::new(x, 0.0), VIEWPORT)
            .unwrap()
    };
    let shift = at(150.0 + 100.0 - overlap) - at(300.0);
    editor
        .apply(Op::Transform(TransformInput {
            model: 1,
            matrix: DMat4::from_translation(shift).to_cols_array(),
        }))
        .unwrap();
    editor
}

/// The volume of the union of `meshes`: the cells of an `n³` grid over their bounding box
/// whose centres lie inside any of them.
fn union_volume(meshes: &[&sketchmesh_core::mesh::Mesh], n: usize) -> f64 {
    let boxes: Vec<(DVec3, DVec3)> = meshes.iter().map(|m| m.bounding_box().unwrap()).collect();
    let lo = boxes.iter().fold(DVec3::MAX, |a, b| a.min(b.0));
    let hi = boxes.iter().fold(DVec3::MIN, |a, b| a.max(b.1));
    let cell = (hi - lo) / n as f64;
    let bvhs: Vec<Bvh> = meshes.iter().map(|m| Bvh::new(m)).collect();
    let mut inside = 0usize;
    for i in 0..n {
        for j in 0..n {
            for k in 0..n {
                let p = lo + cell * (DVec3::new(i as f64, j as f64, k as f64) + 0.5);
                inside += usize::from(meshes.iter().zip(&bvhs).any(|(m, b)| b.contains(m, p)));
            }
        }
    }
    inside as f64 * cell.x * cell.y * cell.z
}

#[test]
fn two_overlapping_shapes_merge_into_one_that_keeps_the_union_s_volume() {
    let mut editor = two_shapes_overlapping(60.0);
    let before = editor.document().clone();
    let (a, b) = (&before.models[0], &before.models[1]);
    let union = union_volume(&[&a.mesh, &b.mesh], 64);
    // Before the optimization: the parts joined as they are.
    let raw = sketchmesh_core::fibermesh::merge::merge(&a.mesh, &b.mesh).unwrap();
    let raw_volume = enclosed_volume(&raw.mesh);
    assert!(
        (raw_volume / union - 1.0).abs() < 0.02,
        "{raw_volume} against {union}"
    );
    editor
        .apply(Op::Merge(MergeInput { models: [1, 0] }))
        .unwrap();
    let doc = editor.document();
    assert_eq!(doc.models.len(), 1);
    let model = &doc.models[0];
    assert_closed_of_genus(model, 0);
    // Both outlines (each cut open where the other part was) and the seam.
    let seam = model.curves.last().unwrap();
    assert!(seam.is_closed && !seam.is_sharp());
    assert!(model.curves.len() >= 3);
    let volume = enclosed_volume(&model.mesh);
    assert!(
        (volume / union - 1.0).abs() < 0.05,
        "{volume} against {union}"
    );
    let merged = doc.clone();
    // As the page computes it: in its worker, the second model going when it lands.
    let mut elsewhere = two_shapes_overlapping(60.0);
    let mut edit = elsewhere
        .begin(Op::Merge(MergeInput { models: [1, 0] }))
        .unwrap();
    supply_elsewhere(&mut edit);
    edit.finish(&mut elsewhere).unwrap();
    assert_eq!(elsewhere.document(), &merged);
    assert_eq!(elsewhere.session_json(), editor.session_json());
    editor.apply(Op::Undo).unwrap();
    assert_eq!(editor.document(), &before);
    editor.apply(Op::Redo).unwrap();
    let replayed = Editor::replay_json(&editor.session_json()).unwrap();
    assert_eq!(replayed.document(), &merged);
}

#[test]
fn models_that_do_not_touch_are_not_merged() {
    let mut editor = two_shapes_overlapping(-40.0);
    let before = editor.document().clone();
    let error = editor
        .apply(Op::Merge(MergeInput { models: [0, 1] }))
        .unwrap_err();
    assert!(error.to_string().contains("do not touch"), "{error}");
    let same = editor
        .apply(Op::Merge(MergeInput { models: [1, 1] }))
        .unwrap_err();
    assert!(same.to_string().contains("two different"), "{same}");
    assert!(matches!(
        editor.apply(Op::Merge(MergeInput { models: [0, 7] })),
        Err(CommandError::NoSuchModel(7))
    ));
    assert_eq!(editor.document(), &before);
}

// ---------------------------------------------------------------------------------------
// A whole session
// ---------------------------------------------------------------------------------------

/// `tests/fixtures/topology-session.json`: the session of
/// [`a_session_of_every_topology_op_replays_to_the_same_mesh`], which the CLI's and the
/// page's tests replay.
fn topology_session_fixture() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../tests/fixtures/topology-session.json")
}

/// Creates a shape, extrudes it twice, drills a tunnel through it, cuts a limb's tip off,
/// creates a second shape, moves it into the first and merges them; after every op the model
/// is closed, manifold, of its genus, without crossing triangles, its curves edge chains.
/// The session replays to the same document, and is the fixture the CLI and the page replay;
/// `topology-session.expected.json` beside it holds the mesh's counts, which all three check
/// (`UPDATE_FIXTURE=1` writes both again).
#[test]
fn a_session_of_every_topology_op_replays_to_the_same_mesh() {
    let camera = Camera::default();
    let mut editor = created_circle();
    let step = |editor: &mut Editor, op: Op, genus: u32| {
        let name = op.name();
        editor.apply(op).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_closed_of_genus(&editor.document().models[0], genus);
    };
    for (side, reach) in [(90.0, 160.0), (-90.0, -160.0)] {
        let (base, silhouette) = extrusion(camera, CENTRE + DVec2::new(side, 0.0), 30.0, reach);
        let strokes = [base, input(camera, &silhouette)];
        step(&mut editor, Op::Extrude(StrokePairInput { strokes }), 0);
    }
    let loops = [
        loop_around_centre(camera, 40.0),
        loop_around_centre(behind(), 40.0),
    ];
    step(
        &mut editor,
        Op::Tunnel(StrokePairInput { strokes: loops }),
        1,
    );
    step(&mut editor, vertical_cut(camera, CENTRE.x + 200.0), 1);
    let ball: Vec<DVec2> = (0..=64)
        .map(|i| DVec2::new(700.0, 500.0) + 60.0 * DVec2::from_angle(TAU * f64::from(i) / 64.0))
        .collect();
    editor
        .apply(Op::Create(input(camera, &ball).into()))
        .unwrap();
    assert_eq!(editor.document().models.len(), 2);
    let at = |s: DVec2| camera.point_on_target_plane(s, VIEWPORT).unwrap();
    let shift = at(CENTRE + DVec2::new(0.0, 140.0)) - at(DVec2::new(700.0, 500.0));
    let matrix = DMat4::from_translation(shift).to_cols_array();
    editor
        .apply(Op::Transform(TransformInput { model: 1, matrix }))
        .unwrap();
    step(&mut editor, Op::Merge(MergeInput { models: [0, 1] }), 1);
    assert_eq!(editor.document().models.len(), 1);
    let json = editor.session_json();
    let replayed = Editor::replay_json(&json).unwrap();
    assert_eq!(replayed.document(), editor.document());
    let fixture = topology_session_fixture();
    let stats = editor.document().stats();
    let expected = serde_json::json!({
        "vertices": stats.vertices,
        "triangles": stats.triangles,
        "curves": editor.document().models[0].curves.len(),
    });
    let expected_path = fixture.with_extension("expected.json");
    if std::env::var_os("UPDATE_FIXTURE").is_some() {
        std::fs::write(&fixture, &json).unwrap();
        std::fs::write(&expected_path, format!("{expected:#}\n")).unwrap();
    }
    let recorded_expected: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&expected_path).unwrap()).unwrap();
    assert_eq!(
        recorded_expected, expected,
        "the replayed mesh is the one the CLI and the page expect"
    );
    let recorded = std::fs::read_to_string(&fixture).expect("the fixture exists");
    let ops = |text: &str| serde_json::from_str::<serde_json::Value>(text).unwrap()["ops"].clone();
    assert_eq!(
        ops(&recorded),
        ops(&json),
        "tests/fixtures/topology-session.json is out of date: UPDATE_FIXTURE=1 writes it again"
    );
}

/// Spot, and where a turned copy of it is placed: its middle moved by a fraction of Spot's
/// size along each axis, turned about y and then x (radians). The first is the copy beside
/// it, half a width along x: the two meet in three loops, and where each pokes out of the
/// other by less than the seam gap, a rim loses its partner and a nub is cut off on its own.
const SPOT_PLACEMENTS: [([f64; 3], [f64; 2]); 8] = [
    ([0.5, 0.0, 0.0], [0.0, 0.0]),
    ([-0.37, -0.21, 0.35], [0.4, 2.6]),
    ([0.06, 0.27, -0.1], [3.3, 1.2]),
    ([-0.45, -0.37, -0.25], [5.0, 0.8]),
    ([0.42, -0.41, -0.41], [1.9, 4.4]),
    ([-0.2, -0.01, -0.26], [2.2, 5.7]),
    ([-0.46, -0.02, -0.26], [0.9, 3.1]),
    ([0.3, 0.3, 0.3], [1.0, 1.0]),
];

#[test]
fn a_scan_merges_with_turned_copies_of_itself_keeping_the_union_s_volume() {
    let Some(meshes) = testdata_meshes("spot.glb") else {
        return;
    };
    let spot = &meshes[0];
    let (lo, hi) = spot.bounding_box().unwrap();
    let centre = 0.5 * (lo + hi);
    for (by, [about_y, about_x]) in SPOT_PLACEMENTS {
        let matrix = DMat4::from_translation(centre + DVec3::from(by) * (hi - lo))
            * DMat4::from_rotation_y(about_y)
            * DMat4::from_rotation_x(about_x)
            * DMat4::from_translation(-centre);
        let mut editor = Editor::new();
        editor.apply(import_mesh("spot.glb", spot)).unwrap();
        editor.apply(import_mesh("spot.glb", spot)).unwrap();
        let transform = TransformInput {
            model: 1,
            matrix: matrix.to_cols_array(),
        };
        editor.apply(Op::Transform(transform)).unwrap();
        let models = &editor.document().models;
        let union = union_volume(&[&models[0].mesh, &models[1].mesh], 64);
        editor
            .apply(Op::Merge(MergeInput { models: [0, 1] }))
            .unwrap_or_else(|e| panic!("placed at {by:?} turned {about_y}, {about_x}: {e}"));
        let model = &editor.document().models[0];
        // Legs and ears that pass through the other body make handles.
        assert_closed_of_genus(model, model.mesh.genus().unwrap());
        assert_eq!(model.mesh.n_components(), 1);
        let volume = enclosed_volume(&model.mesh);
        assert!(
            (volume / union - 1.0).abs() < 0.02,
            "placed at {by:?}: {volume} against {union}"
        );
    }
}

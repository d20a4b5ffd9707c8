//! Blanco's curve handles and skeletons: a stroke becomes a handle, and moving, twisting or
//! scaling it deforms the object as it is, on a generated bar, a Möbius strip, a soup with
//! fins and duplicate faces, a point cloud and the scans.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::sync::Arc;

use glam::{DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{
    AsImported, CommandError, CurveHandleInput, DeleteHandleInput, Document, Editor,
    HandleEditInput, HandleTarget, LinkHandlesInput, Model, Op, PointCloud, Progress,
};
use sketchmesh_core::geometry::Bvh;
use sketchmesh_core::io::{ImportFile, Info, import_gltf, inspect_gltf, write_glb};
use sketchmesh_core::mesh::{Mesh, TriSoup, make_manifold, primitives};
use sketchmesh_core::skeleton::{
    Deformation, HandleCurve, HandleKind, HandleStroke, Link, Mover, PointEdit, Shape,
    SkeletonError, place_handle,
};

use crate::common::{
    diagonal, digest, import_document, import_mesh, samples, screen, testdata_meshes,
};

const VIEWPORT: DVec2 = DVec2::new(800.0, 800.0);

/// A camera looking at the bounding box of `positions` from +z.
fn camera_on(positions: &[DVec3]) -> Camera {
    let (lo, hi) = bounds(positions);
    let centre = 0.5 * (lo + hi);
    Camera {
        eye: centre + DVec3::new(0.0, 0.0, 1.5 * (hi - lo).length()),
        target: centre,
        ..Camera::default()
    }
}

fn bounds(positions: &[DVec3]) -> (DVec3, DVec3) {
    positions
        .iter()
        .fold((DVec3::MAX, DVec3::MIN), |(lo, hi), &p| {
            (lo.min(p), hi.max(p))
        })
}

/// A horizontal stroke `half` px to each side of the middle of the view, `dy` px below it.
fn across_the_middle(positions: &[DVec3], camera: &Camera, half: f64, dy: f64) -> Vec<DVec2> {
    let (lo, hi) = bounds(positions);
    let middle = screen(camera, VIEWPORT, 0.5 * (lo + hi)).unwrap() + DVec2::new(0.0, dy);
    (0..=60)
        .map(|i| middle + DVec2::new(-half + 2.0 * half * f64::from(i) / 60.0, 0.0))
        .collect()
}

/// A handle under a horizontal stroke across the middle, or the first row below or above
/// it where the stroke lies over the object (a Möbius strip is a hole in the middle).
fn handle_on(shape: &Shape, half: f64, kind: HandleKind, n: usize) -> HandleCurve {
    let camera = camera_on(shape.positions);
    [0.0, 40.0, -40.0, 80.0, -80.0, 120.0, -120.0, 200.0, -200.0]
        .into_iter()
        .find_map(|dy| {
            let points = across_the_middle(shape.positions, &camera, half, dy);
            let stroke = HandleStroke {
                points: &points,
                camera: &camera,
                viewport: VIEWPORT,
            };
            place_handle(shape, &stroke, kind, n, false).ok()
        })
        .expect("no stroke across the middle lies over the object")
}

/// The binding of `shape` to one handle with no links.
fn alone(shape: &Shape, rest: &HandleCurve) -> Deformation {
    Deformation::new(shape, &[Mover { rest, links: &[] }]).unwrap()
}

fn deformed(shape: &Shape, rest: &HandleCurve, pose: &HandleCurve) -> Vec<DVec3> {
    let deformation = alone(shape, rest);
    let mut out = vec![DVec3::ZERO; shape.positions.len()];
    deformation.apply_into(shape.positions, std::slice::from_ref(pose), &mut out);
    out
}

fn soup_of(mesh: &Mesh) -> TriSoup {
    TriSoup {
        positions: mesh.positions().to_vec(),
        triangles: mesh.triangles().to_vec(),
    }
}

/// A bar along x: 2.4 long, 0.4 thick.
fn bar() -> TriSoup {
    soup_of(&primitives::capsule(0.2, 1.0, 24, 120))
}

/// A Möbius strip: non-orientable, one boundary.
fn moebius(n: usize) -> TriSoup {
    let mut positions = Vec::new();
    for i in 0..n {
        let a = std::f64::consts::TAU * i as f64 / n as f64;
        for s in [-0.3, 0.0, 0.3] {
            let r = 1.0 + s * (a / 2.0).cos();
            positions.push(DVec3::new(r * a.cos(), r * a.sin(), s * (a / 2.0).sin()));
        }
    }
    let mut triangles = Vec::new();
    for i in 0..n {
        let next = (i + 1) % n;
        for k in 0..2u32 {
            // The last ring joins the first one turned over.
            let (a, b) = (3 * i as u32 + k, 3 * i as u32 + k + 1);
            let (c, d) = if next == 0 {
                (2 - k, 1 - k)
            } else {
                (3 * next as u32 + k, 3 * next as u32 + k + 1)
            };
            triangles.push([a, c, b]);
            triangles.push([b, c, d]);
        }
    }
    TriSoup {
        positions,
        triangles,
    }
}

/// The bar with a fin (three triangles on one edge) and every tenth triangle twice.
fn soup_with_fins() -> TriSoup {
    let mut soup = bar();
    let t = soup.triangles[500];
    let apex = soup.positions[t[0] as usize] + DVec3::new(0.0, 0.0, 0.3);
    soup.positions.push(apex);
    let apex = soup.positions.len() as u32 - 1;
    soup.triangles.push([t[0], t[1], apex]);
    let copies: Vec<[u32; 3]> = soup.triangles.iter().step_by(10).copied().collect();
    soup.triangles.extend(copies);
    soup
}

fn shape(soup: &TriSoup) -> Shape<'_> {
    Shape {
        positions: &soup.positions,
        triangles: &soup.triangles,
    }
}

/// Every test shape: generated ones and the scans (loudly absent without the test data).
fn all_soups() -> Vec<(String, TriSoup)> {
    let mut soups = vec![
        (String::from("bar"), bar()),
        (String::from("Möbius strip"), moebius(120)),
        (String::from("soup with fins"), soup_with_fins()),
    ];
    for name in [
        "stanford_bunny.glb",
        "suzanne.glb",
        "nefertiti.glb",
        "igea.glb",
    ] {
        let meshes = testdata_meshes(name).expect("the shared test data is missing");
        let mut soup = TriSoup::default();
        for mesh in &meshes {
            soup.append(&soup_of(mesh));
        }
        soups.push((name.to_owned(), soup));
    }
    soups
}

/// A handle of `n` control points along the x axis from `from`, `step` apart.
fn along_x(n: u32, from: f64, step: f64) -> HandleCurve {
    HandleCurve::new(
        (0..n)
            .map(|k| DVec3::new(from + step * f64::from(k), 0.0, 0.0))
            .collect(),
        false,
    )
}

fn moved_by(curve: &HandleCurve, t: DVec3) -> HandleCurve {
    let mut moved = curve.clone();
    for p in &mut moved.points {
        *p += t;
    }
    moved
}

#[test]
fn an_unmoved_handle_leaves_every_point_bit_for_bit() {
    for (name, soup) in all_soups() {
        let shape = shape(&soup);
        let handle = handle_on(&shape, 80.0, HandleKind::Surface, 4);
        let out = deformed(&shape, &handle, &handle);
        assert!(out == soup.positions, "{name}: a point moved");
    }
}

#[test]
fn moving_every_control_point_by_t_moves_everything_by_t() {
    for (name, soup) in all_soups() {
        let shape = shape(&soup);
        let handle = handle_on(&shape, 80.0, HandleKind::Surface, 4);
        let t = 0.05 * diagonal(&soup.positions) * DVec3::new(0.3, 1.0, -0.5).normalize();
        let out = deformed(&shape, &handle, &moved_by(&handle, t));
        let worst = out
            .iter()
            .zip(&soup.positions)
            .map(|(a, b)| (*a - *b - t).length())
            .fold(0.0, f64::max);
        assert!(
            worst < 1e-9 * diagonal(&soup.positions),
            "{name}: off by {worst}"
        );
    }
}

#[test]
fn moving_one_end_bends_the_region_and_carries_the_end_rigidly() {
    for (name, soup) in all_soups() {
        let shape = shape(&soup);
        let handle = handle_on(&shape, 80.0, HandleKind::Surface, 4);
        let lift = 0.1 * diagonal(&soup.positions);
        let pose = handle
            .edited(&PointEdit {
                point: 3,
                translate: Some(DVec3::new(0.0, lift, 0.0)),
                ..PointEdit::default()
            })
            .unwrap();
        let deformation = alone(&shape, &handle);
        let mut out = vec![DVec3::ZERO; soup.positions.len()];
        deformation.apply_into(&soup.positions, std::slice::from_ref(&pose), &mut out);
        assert!(out.iter().all(|p| p.is_finite()), "{name}: not a number");
        let [region, rigid, _] = deformation.counts();
        assert!(
            region > 10 && rigid > 10,
            "{name}: {region} region, {rigid} rigid"
        );
        // Vertices past the end move as one body: distances among them are kept.
        let end: Vec<usize> = (0..soup.positions.len())
            .filter(|&v| (out[v] - soup.positions[v]).length() > 0.0)
            .filter(|&v| !deformation.region_of(0).any(|r| r == v))
            .take(200)
            .collect();
        for pair in end.windows(2) {
            let before = soup.positions[pair[0]].distance(soup.positions[pair[1]]);
            let after = out[pair[0]].distance(out[pair[1]]);
            assert!(
                (before - after).abs() < 1e-9 * diagonal(&soup.positions),
                "{name}"
            );
        }
        // The end point itself moved by about the lift.
        let tip_moved = out
            .iter()
            .zip(&soup.positions)
            .map(|(a, b)| (*a - *b).y)
            .fold(0.0, f64::max);
        assert!(
            tip_moved > 0.5 * lift,
            "{name}: the end rose {tip_moved} of {lift}"
        );
    }
}

#[test]
fn a_twist_turns_the_slab_at_its_control_point_by_its_angle() {
    let soup = bar();
    let shape = shape(&soup);
    let handle = along_x(5, -0.8, 0.4);
    let angle = 70f64.to_radians();
    let pose = handle
        .edited(&PointEdit {
            point: 2,
            twist: Some(angle),
            spread: 1,
            ..PointEdit::default()
        })
        .unwrap();
    let out = deformed(&shape, &handle, &pose);
    let mut checked = 0;
    for (before, after) in soup.positions.iter().zip(&out) {
        if before.x.abs() < 0.01 && before.truncate().y.hypot(before.z) > 0.1 {
            let (a, b) = (DVec2::new(before.y, before.z), DVec2::new(after.y, after.z));
            let turned = a.angle_to(b);
            assert!(
                (turned - angle).abs() < 1f64.to_radians(),
                "turned {}°",
                turned.to_degrees()
            );
            assert!((after.x - before.x).abs() < 1e-3);
            checked += 1;
        }
    }
    assert!(checked >= 24, "{checked}");
}

#[test]
fn stretching_the_curve_stretches_the_region_and_keeps_its_sections() {
    let soup = bar();
    let shape = shape(&soup);
    let handle = along_x(2, -0.8, 1.6);
    let mut pose = handle.clone();
    pose.points[1].x = 1.6; // 1.6 long becomes 2.4: × 1.5
    let out = deformed(&shape, &handle, &pose);
    for (before, after) in soup.positions.iter().zip(&out) {
        if before.x.abs() < 0.79 {
            let expected = -0.8 + 1.5 * (before.x + 0.8);
            assert!(
                (after.x - expected).abs() < 0.02 * 2.4,
                "{} → {}",
                before.x,
                after.x
            );
            assert!((after.y - before.y).abs() < 1e-9 && (after.z - before.z).abs() < 1e-9);
        }
    }
}

#[test]
fn a_scale_widens_the_sections_near_its_control_point() {
    let soup = bar();
    let shape = shape(&soup);
    let handle = along_x(3, -0.8, 0.8);
    let pose = handle
        .edited(&PointEdit {
            point: 1,
            scale: Some([1.5, 1.5]),
            spread: 0,
            ..PointEdit::default()
        })
        .unwrap();
    let out = deformed(&shape, &handle, &pose);
    for (before, after) in soup.positions.iter().zip(&out) {
        if before.x.abs() < 0.005 {
            let ratio = after.y.hypot(after.z) / before.y.hypot(before.z);
            assert!((ratio - 1.5).abs() < 0.02, "{ratio}");
        }
    }
}

/// The largest factor by which an edge of `soup` grew in `out`.
fn worst_stretch(soup: &TriSoup, out: &[DVec3]) -> f64 {
    soup.triangles
        .iter()
        .flat_map(|t| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])])
        .map(|(i, j)| {
            let before = soup.positions[i as usize].distance(soup.positions[j as usize]);
            out[i as usize].distance(out[j as usize]) / before
        })
        .fold(0.0, f64::max)
}

#[test]
fn linked_curves_deform_continuously_across_their_joint() {
    let soup = bar();
    let shape = shape(&soup);
    let (first, second) = (along_x(3, -0.9, 0.45), along_x(3, 0.0, 0.45));
    let lift = DVec3::new(0.0, 0.3, 0.0);
    let (mut a, mut b) = (first.clone(), second.clone());
    a.points[2] += lift;
    b.points[0] += lift;
    let deform = |links: [&[Link]; 2]| {
        let movers = [
            Mover {
                rest: &first,
                links: links[0],
            },
            Mover {
                rest: &second,
                links: links[1],
            },
        ];
        let deformation = Deformation::new(&shape, &movers).unwrap();
        let mut out = vec![DVec3::ZERO; soup.positions.len()];
        deformation.apply_into(&soup.positions, &[a.clone(), b.clone()], &mut out);
        out
    };
    let linked = deform([
        &[Link {
            point: 2,
            partner: Some((1, 0)),
        }],
        &[Link {
            point: 0,
            partner: Some((0, 2)),
        }],
    ]);
    let apart = deform([&[], &[]]);
    // Bent at the joint, the outside of the bend stretches; apart, the two regions tear.
    let (joined, torn) = (worst_stretch(&soup, &linked), worst_stretch(&soup, &apart));
    assert!(
        joined < 2.0,
        "an edge stretched × {joined}: a crack at the joint"
    );
    assert!(torn > 5.0, "unlinked, the joint should tear (× {torn})");
    let joint = linked
        .iter()
        .zip(&soup.positions)
        .filter(|(_, p)| p.x.abs() < 0.01)
        .map(|(a, b)| (*a - *b).y)
        .fold(f64::INFINITY, f64::min);
    assert!(joint > 0.25, "the joint rose {joint}");
}

#[test]
fn a_skeleton_handle_runs_along_the_middle_of_a_bar() {
    let soup = bar();
    let shape = shape(&soup);
    let handle = handle_on(&shape, 80.0, HandleKind::Skeleton, 5);
    for p in &handle.points {
        assert!(
            p.y.hypot(p.z) < 0.02,
            "{p} is off the axis of a bar of radius 0.2"
        );
    }
}

#[test]
fn a_bend_tighter_than_the_part_is_held_before_it_folds_through_itself() {
    let soup = bar();
    let mesh = Mesh::from_soup(&soup).unwrap();
    let shape = shape(&soup);
    let handle = along_x(5, -0.8, 0.4);
    // A right angle turned within 0.1 on a bar of radius 0.2.
    let pose = |f: f64| {
        let mut pose = handle.clone();
        pose.points[3] = handle.points[3].lerp(DVec3::new(0.1, 0.1, 0.0), f);
        pose.points[4] = handle.points[4].lerp(DVec3::new(0.1, 0.5, 0.0), f);
        vec![pose]
    };
    let deformation = alone(&shape, &handle);
    let crossings = |positions: &[DVec3]| {
        let mut bent = mesh.clone();
        bent.positions_mut().copy_from_slice(positions);
        Bvh::new(&bent).crossing_faces(&bent, |_| true).len()
    };
    let mut out = vec![DVec3::ZERO; soup.positions.len()];
    let folded = deformation.apply_into(&soup.positions, &pose(1.0), &mut out);
    assert!(
        folded > 0 && crossings(&out) > 0,
        "the whole bend should fold ({folded})"
    );
    let kept = deformation.unfolded(&soup.positions, pose, &mut out);
    assert!(kept > 0.3 && kept < 1.0, "{kept} of the bend kept");
    assert_eq!(
        crossings(&out),
        0,
        "held at {kept}, the bar still crosses itself"
    );
}

#[test]
fn a_point_cloud_is_hit_on_its_splats_and_deforms() {
    let sphere = primitives::icosphere(1.0, 4);
    let cloud = TriSoup {
        positions: sphere.positions().to_vec(),
        triangles: Vec::new(),
    };
    let shape = shape(&cloud);
    let handle = handle_on(&shape, 100.0, HandleKind::Surface, 4);
    for p in &handle.points {
        assert!((p.length() - 1.0).abs() < 0.1, "{p} is off the cloud");
        assert!(p.z > 0.0, "{p} is on the far side");
    }
    assert_eq!(deformed(&shape, &handle, &handle), cloud.positions);
    let t = DVec3::new(0.0, 0.2, 0.0);
    let out = deformed(&shape, &handle, &moved_by(&handle, t));
    assert!(
        out.iter()
            .zip(&cloud.positions)
            .all(|(a, b)| (*a - *b - t).length() < 1e-9)
    );
}

#[test]
fn bad_strokes_and_amounts_are_refused_with_a_sentence() {
    let soup = bar();
    let shape = shape(&soup);
    let camera = camera_on(&soup.positions);
    let beside: Vec<DVec2> = (0..40)
        .map(|i| DVec2::new(20.0 + 4.0 * f64::from(i), 20.0))
        .collect();
    let stroke = HandleStroke {
        points: &beside,
        camera: &camera,
        viewport: VIEWPORT,
    };
    let refused = place_handle(&shape, &stroke, HandleKind::Surface, 4, false);
    assert_eq!(refused, Err(SkeletonError::StrokeMisses));
    let over = across_the_middle(&soup.positions, &camera, 80.0, 0.0);
    let stroke = HandleStroke {
        points: &over,
        camera: &camera,
        viewport: VIEWPORT,
    };
    assert_eq!(
        place_handle(&shape, &stroke, HandleKind::Surface, 1, false),
        Err(SkeletonError::TooFewPoints)
    );
    let dot = [over[0]; 5];
    let stroke = HandleStroke {
        points: &dot,
        camera: &camera,
        viewport: VIEWPORT,
    };
    assert_eq!(
        place_handle(&shape, &stroke, HandleKind::Surface, 4, false),
        Err(SkeletonError::StrokeTooShort)
    );
    for message in [SkeletonError::StrokeMisses, SkeletonError::BadAmount] {
        assert!(message.to_string().ends_with('.'));
    }
}

/// A model as a file with `soup`'s triangles would import: repaired, the soup kept.
fn soup_model(soup: &TriSoup) -> Model {
    let repaired = make_manifold(soup).unwrap();
    Model {
        as_imported: Some(Arc::new(AsImported {
            soup: soup.clone(),
            vertex_source: repaired.vertex_source.iter().map(|v| v.0).collect(),
            mesh_triangles: repaired.mesh.triangles().to_vec(),
            appearance: None,
        })),
        mesh: repaired.mesh,
        ..Model::default()
    }
}

fn info_of(glb: &[u8]) -> Info {
    inspect_gltf(
        &ImportFile {
            name: "out.glb",
            bytes: glb,
        },
        &[],
    )
    .unwrap()
}

/// A `curve_handle` op across the middle of `positions` seen from +z.
fn handle_op(positions: &[DVec3], kind: HandleKind) -> Op {
    let camera = camera_on(positions);
    let points = across_the_middle(positions, &camera, 80.0, 0.0);
    Op::CurveHandle(CurveHandleInput {
        viewport: VIEWPORT.to_array(),
        camera,
        stroke: samples(points),
        kind,
        control_points: 4,
        rigid: false,
    })
}

fn lift(handle: u32, point: usize, y: f64) -> Op {
    Op::HandleEdit(HandleEditInput {
        handle,
        point,
        translate: Some([0.0, y, 0.0]),
        twist_deg: None,
        scale: None,
        spread: 1,
    })
}

#[test]
fn a_soup_keeps_its_structure_through_import_deformation_and_export() {
    let soup = soup_with_fins();
    let document = Document {
        models: vec![Arc::new(soup_model(&soup))],
        ..Document::default()
    };
    let input = info_of(&write_glb(&document));
    assert_eq!(input.triangles, soup.triangles.len());
    assert!(!input.manifold);
    let mut editor = Editor::new();
    editor
        .apply(import_document("soup.glb", &document))
        .unwrap();
    let imported = editor.document().models[0]
        .as_imported()
        .expect("the soup is kept")
        .clone();
    assert_eq!(imported.soup.triangles.len(), soup.triangles.len());
    editor
        .apply(handle_op(&imported.soup.positions, HandleKind::Surface))
        .unwrap();
    editor.apply(lift(0, 3, 0.3)).unwrap();
    let moved = &editor.document().models[0];
    let kept = moved.as_imported().expect("still as imported");
    assert_ne!(kept.soup.positions, imported.soup.positions);
    assert_eq!(
        moved.mesh.positions(),
        kept.mesh_positions(&kept.soup.positions)
    );
    let output = info_of(&write_glb(editor.document()));
    assert_eq!(
        (
            output.triangles,
            output.components,
            output.vertices,
            output.manifold
        ),
        (
            input.triangles,
            input.components,
            input.vertices,
            input.manifold
        )
    );
    // The handle's own control point moved with the edit.
    let handle = &editor.document().handles[0];
    assert!(
        (handle.curve.points[3].y
            - imported
                .soup
                .positions
                .iter()
                .map(|p| p.y)
                .fold(f64::MIN, f64::max))
        .abs()
            < 1.0
    );
}

#[test]
fn a_point_cloud_from_a_gltf_points_primitive_deforms_and_keeps_its_points() {
    let sphere = primitives::icosphere(1.0, 4);
    let cloud = PointCloud {
        positions: sphere.positions().to_vec(),
        colors: None,
    };
    let document = Document {
        point_clouds: vec![Arc::new(cloud.clone())],
        ..Document::default()
    };
    let mut editor = Editor::new();
    editor
        .apply(import_document("cloud.glb", &document))
        .unwrap();
    let positions = editor.document().point_clouds[0].positions.clone();
    editor
        .apply(handle_op(&positions, HandleKind::Skeleton))
        .unwrap();
    assert_eq!(editor.document().handles[0].target, HandleTarget::Cloud(0));
    editor.apply(lift(0, 3, 0.4)).unwrap();
    let moved = &editor.document().point_clouds[0].positions;
    assert_eq!(moved.len(), positions.len());
    assert!(
        moved
            .iter()
            .zip(&positions)
            .any(|(a, b)| a.distance(*b) > 0.1)
    );
    let exported = import_gltf(
        &ImportFile {
            name: "out.glb",
            bytes: &write_glb(editor.document()),
        },
        &[],
        &Default::default(),
    )
    .unwrap();
    assert_eq!(exported.point_clouds[0].positions.len(), positions.len());
}

#[test]
fn handle_ops_replay_undo_and_drag_exactly() {
    let mesh = primitives::capsule(0.2, 1.0, 24, 120);
    let mut editor = Editor::new();
    editor.apply(import_mesh("bar.glb", &mesh)).unwrap();
    let positions = editor.document().models[0].mesh.positions().to_vec();
    editor
        .apply(handle_op(&positions, HandleKind::Surface))
        .unwrap();
    editor
        .apply(handle_op(&positions, HandleKind::Skeleton))
        .unwrap();
    editor
        .apply(Op::LinkHandles(LinkHandlesInput {
            a: (0, 0),
            b: (1, 0),
        }))
        .unwrap();
    let before = digest(editor.document());
    // A drag: the preview follows each pose; the commit equals the op applied at once.
    let mut drag = editor.begin_gesture(lift(0, 3, 0.05)).unwrap();
    // The first pose takes five steps, a frame each in the page: who is next to whom, the
    // handles' parts, their points bound to slabs, the rest of the binding, then the pose.
    for _ in 0..4 {
        assert_eq!(drag.step().unwrap(), Progress::Working);
        assert!(drag.moved_model().is_none());
    }
    for y in [0.1, 0.2, 0.3] {
        drag.revise(lift(0, 3, y));
        while drag.step().unwrap() == Progress::Working {}
        assert!(drag.moved_model().is_some());
    }
    drag.finish(&mut editor).unwrap();
    let applied = Editor::replay(&editor.session()).unwrap();
    assert_eq!(digest(applied.document()), digest(editor.document()));
    let twist = Op::HandleEdit(HandleEditInput {
        handle: 1,
        point: 2,
        translate: None,
        twist_deg: Some(45.0),
        scale: Some([1.2, 0.8]),
        spread: 2,
    });
    editor.apply(twist).unwrap();
    editor.apply(Op::Undo).unwrap();
    editor.apply(Op::Undo).unwrap();
    assert_eq!(digest(editor.document()), before);
    editor
        .apply(Op::DeleteHandle(DeleteHandleInput { handle: 0 }))
        .unwrap();
    assert!(editor.document().handles[0].links.is_empty());
}

#[test]
fn bad_handle_ops_are_refused_and_change_nothing() {
    let mesh = primitives::capsule(0.2, 1.0, 24, 120);
    let mut editor = Editor::new();
    editor.apply(import_mesh("bar.glb", &mesh)).unwrap();
    let positions = mesh.positions().to_vec();
    editor
        .apply(handle_op(&positions, HandleKind::Surface))
        .unwrap();
    let before = digest(editor.document());
    let log = editor.session().ops.len();
    let edit = |twist: f64, scale: [f64; 2]| {
        Op::HandleEdit(HandleEditInput {
            handle: 0,
            point: 1,
            translate: None,
            twist_deg: Some(twist),
            scale: Some(scale),
            spread: 1,
        })
    };
    let refusals = [
        edit(f64::NAN, [1.0, 1.0]),
        edit(10.0, [0.0, 1.0]),
        edit(10.0, [-1.0, 1.0]),
        lift(7, 0, 0.1),
        lift(0, 9, 0.1),
        Op::DeleteHandle(DeleteHandleInput { handle: 3 }),
        Op::LinkHandles(LinkHandlesInput {
            a: (0, 0),
            b: (0, 2),
        }),
        Op::HandleEdit(HandleEditInput {
            handle: 0,
            point: 0,
            translate: None,
            twist_deg: None,
            scale: None,
            spread: 1,
        }),
    ];
    for op in refusals {
        let error = editor.apply(op.clone()).unwrap_err();
        assert!(error.to_string().ends_with('.'), "{op:?}: {error}");
        assert_eq!(
            digest(editor.document()),
            before,
            "{op:?} changed the document"
        );
    }
    let mut beside = handle_op(&positions, HandleKind::Surface);
    if let Op::CurveHandle(input) = &mut beside {
        for sample in &mut input.stroke {
            sample[1] = 10.0;
        }
    }
    assert!(matches!(
        editor.apply(beside),
        Err(CommandError::Skeleton(SkeletonError::StrokeMisses))
    ));
    assert_eq!(editor.session().ops.len(), log);
}

//! Previews that look like the result (issue 49): a region drag's preview is the surface its
//! release commits, as smooth, and a pull's preview folds no triangle over.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use glam::{DMat4, DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{
    CreateInput, Editor, Op, Progress, RegionDrag, RegionEditInput, dragged_region,
};
use sketchmesh_core::geometry::{Bvh, face_normals, flipped_faces};
use sketchmesh_core::mesh::{HalfedgeId, Mesh};

use crate::common::{circle, import_mesh, samples, screen, stroke_input, testdata_meshes};

const VIEWPORT: DVec2 = DVec2::new(800.0, 800.0);

/// The largest distance from a vertex of `a` to the surface `b`, and from `b`'s to `a`.
fn deviation(a: &Mesh, b: &Mesh) -> f64 {
    let one_way = |from: &Mesh, to: &Mesh| {
        let bvh = Bvh::new(to);
        (from.positions().iter())
            .map(|&p| {
                bvh.nearest(to, p)
                    .map_or(f64::INFINITY, |(q, _)| p.distance(q))
            })
            .fold(0.0, f64::max)
    };
    one_way(a, b).max(one_way(b, a))
}

/// The largest angle (degrees) between the normals of two triangles sharing an edge: a
/// stair-step shows as a crease sharper than the surface's own.
fn sharpest_crease(mesh: &Mesh) -> f64 {
    let normals = face_normals(mesh);
    (0..mesh.n_halfedges() as u32)
        .map(HalfedgeId)
        .filter_map(|h| Some((mesh.face(h), mesh.face(mesh.twin(h)?))))
        .map(|(f, g)| {
            let cos = normals[f.index()].dot(normals[g.index()]).clamp(-1.0, 1.0);
            cos.acos().to_degrees()
        })
        .fold(0.0, f64::max)
}

fn diagonal(mesh: &Mesh) -> f64 {
    let (lo, hi) = mesh.bounding_box().unwrap();
    (hi - lo).length()
}

/// A region drag on `editor`'s model as the Region tool makes it (the curves, then a move
/// by `offset` px, released): the preview shown at the end of the drag, as a mesh, and the
/// committed mesh. The gray levels are shown before the drag only.
fn region_drag(editor: &Editor, curves: &RegionEditInput, offset: DVec2) -> (Mesh, Mesh) {
    let mut editor = editor.clone();
    let mut edit = editor
        .begin_gesture(Op::RegionEdit(curves.clone()))
        .unwrap();
    while edit.step().unwrap() == Progress::Working {}
    // The fall-off is shaded in gray levels until the region moves, then the surface is
    // drawn lit, as the release commits it.
    assert_eq!(edit.region_shade_levels(), Some(5));
    let op = dragged_region(editor.document(), curves, RegionDrag::Move, offset);
    edit.revise(Op::RegionEdit(op));
    while edit.step().unwrap() == Progress::Working {}
    assert_eq!(edit.region_shade_levels(), None);
    let (model, shown) = edit.moved_model().unwrap();
    let mut preview = edit.document().models[model].mesh.clone();
    preview.positions_mut().copy_from_slice(shown);
    edit.finish(&mut editor).unwrap();
    (preview, editor.document().models[model].mesh.clone())
}

/// A straight reference curve `half` px either side of `middle` and a circular boundary of
/// `radius` px around it, with the Region tool's settings (linear levels, remeshed).
fn region_curves(camera: Camera, middle: DVec2, half: f64, radius: f64) -> RegionEditInput {
    let n = (2.0 * half / 3.0).ceil() as usize;
    let (a, b) = (middle - DVec2::X * half, middle + DVec2::X * half);
    let mut boundary = circle(middle, radius);
    boundary.pop();
    RegionEditInput {
        viewport: VIEWPORT.to_array(),
        camera,
        reference: samples((0..=n).map(|i| a.lerp(b, i as f64 / n as f64))),
        boundary: samples(boundary),
        levels: Some(vec![0.0, 0.25, 0.5, 0.75, 1.0]),
        areas: Vec::new(),
        transform: Some(DMat4::IDENTITY.to_cols_array()),
        handles: None,
        profile: None,
        remesh: true,
    }
}

/// Drags of `offsets` px up: the preview within 0.5% of the model's size of the committed
/// surface, and no crease in it more than 5° sharper than the commit's sharpest.
fn check_region_drags(name: &str, editor: &Editor, curves: &RegionEditInput, offsets: &[f64]) {
    for &up in offsets {
        let (preview, commit) = region_drag(editor, curves, DVec2::new(0.0, -up));
        let off = deviation(&preview, &commit) / diagonal(&commit);
        let (shown, committed) = (sharpest_crease(&preview), sharpest_crease(&commit));
        eprintln!(
            "{name}, dragged {up} px: the preview is {:.3}% of the size off the commit; sharpest crease {shown:.1}° (commit {committed:.1}°)",
            100.0 * off
        );
        assert!(off < 0.005, "{name}: the preview is {off} of the size off");
        assert!(shown < committed + 5.0, "{name}: a crease of {shown}°");
    }
}

#[test]
fn a_region_drag_s_preview_is_the_surface_its_release_commits() {
    let mut editor = Editor::new();
    let camera = Camera::default();
    let centre = VIEWPORT / 2.0;
    let outline = circle(centre, 200.0);
    (editor.apply(Op::Create(stroke_input(VIEWPORT, camera, &outline).into()))).unwrap();
    let curves = region_curves(camera, centre, 60.0, 150.0);
    check_region_drags("a created dome", &editor, &curves, &[20.0, 60.0]);
    // Bunny: seen from +z, the curves over the middle of its bounding box.
    let meshes = testdata_meshes("stanford_bunny.glb").expect("the bunny scan");
    let mut scanned = Editor::new();
    scanned.apply(import_mesh("bunny.glb", &meshes[0])).unwrap();
    let mesh = &scanned.document().models[0].mesh;
    let (lo, hi) = mesh.bounding_box().unwrap();
    let camera = Camera {
        eye: 0.5 * (lo + hi) + DVec3::new(0.0, 0.0, 1.5 * (hi - lo).length()),
        target: 0.5 * (lo + hi),
        ..Camera::default()
    };
    let middle = screen(&camera, VIEWPORT, 0.5 * (lo + hi)).unwrap();
    let curves = region_curves(camera, middle, 40.0, 100.0);
    check_region_drags("the bunny", &scanned, &curves, &[10.0, 30.0]);
}

/// The Pull tool's drag of a 40k-vertex shape's outline (the page's case: its right end
/// 90 px right and 30 up in 60 samples, and faster ones), the preview followed every 5
/// samples as the page's worker does: no preview, nor the one held after the release until
/// the result lands, folds a triangle over, and the preview moves.
#[test]
fn a_pull_preview_of_a_40k_shape_folds_no_triangle_over() {
    let viewport = DVec2::new(1280.0, 800.0);
    let camera = Camera::default();
    let c = DVec2::new(640.0, 400.0);
    let outline: Vec<DVec2> = (0..=60)
        .map(|i| {
            c + DVec2::new(170.0, 120.0)
                * DVec2::from_angle(std::f64::consts::TAU * i as f64 / 60.0)
        })
        .collect();
    let mut editor = Editor::new();
    let mut create: CreateInput = stroke_input(viewport, camera, &outline).into();
    create.vertices = Some(40_000);
    editor.apply(Op::Create(create)).unwrap();
    let mesh = editor.document().models[0].mesh.clone();
    for (step, gentle) in [
        (DVec2::new(1.5, -0.5), true),
        (DVec2::new(3.0, -1.0), false),
        (DVec2::new(0.0, -2.0), false),
    ] {
        let grab = c + DVec2::new(170.0, 0.0);
        let mut edit = editor
            .begin_gesture(Op::Pull(stroke_input(viewport, camera, &[grab])))
            .unwrap();
        let mut worst = 0;
        for i in 1..=60 {
            let p = grab + step * i as f64;
            edit.extend([p.x, p.y, 0.5]);
            if i % 5 == 0 {
                while edit.step().unwrap() == Progress::Working {}
                let (_, shown) = edit.moved_model().unwrap();
                worst = worst.max(flipped_faces(mesh.triangles(), mesh.positions(), shown));
            }
        }
        let (_, shown) = edit.moved_model().unwrap();
        let moved = (shown.iter().zip(mesh.positions()))
            .map(|(a, b)| a.distance(*b))
            .fold(0.0, f64::max);
        eprintln!(
            "a pull by {step} px a sample: {worst} triangles folded at worst; the preview moved {:.3} of the size",
            moved / diagonal(&mesh)
        );
        assert_eq!(worst, 0, "triangles folded over in a pull's preview");
        if gentle {
            assert!(
                moved > 0.01 * diagonal(&mesh),
                "the preview follows the drag"
            );
        }
    }
}

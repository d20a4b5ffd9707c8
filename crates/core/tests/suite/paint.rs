//! Colour (issue 51): the brush paints what lies under the pen and nothing behind it, colours
//! follow the ops that remake a model's triangles, symmetry paints the mirror image, and glTF
//! carries paint and material out and back.

#![allow(clippy::unwrap_used)] // A panic is a test failure with a location.

use glam::{DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{
    CommandError, Editor, FillInput, MaterialInput, MergeInput, Model, Op, PaintInput, StrokeInput,
    TransformInput,
};
use sketchmesh_core::io::{ImportFile, ImportLimits, import_gltf, write_glb};
use sketchmesh_core::model::{Finish, MirrorPlane};

use crate::common::{circle, samples, segment};

const VIEWPORT: DVec2 = DVec2::new(800.0, 600.0);
const CENTRE: DVec2 = DVec2::new(400.0, 300.0);
const RED: [f64; 3] = [1.0, 0.0, 0.0];

fn create(centre: DVec2, radius: f64) -> Op {
    Op::Create(
        StrokeInput {
            viewport: VIEWPORT.to_array(),
            camera: Camera::default(),
            stroke: samples(circle(centre, radius)),
        }
        .into(),
    )
}

fn paint(points: &[DVec2], radius: f64) -> PaintInput {
    PaintInput {
        viewport: VIEWPORT.to_array(),
        camera: Camera::default(),
        stroke: samples(points.iter().copied()),
        color: RED,
        radius,
        hardness: 1.0,
        opacity: 1.0,
    }
}

fn screen(p: DVec3) -> DVec2 {
    Camera::default()
        .screen_from_world(p, VIEWPORT)
        .unwrap()
        .truncate()
}

fn is_red(c: [f32; 3]) -> bool {
    c == [1.0, 0.0, 0.0]
}

/// The shown colour of each vertex (`paint × base colour`), as the view draws it.
fn shown(model: &Model) -> Vec<[f32; 3]> {
    sketchmesh_core::paint::shown_colors(model)
}

fn ball() -> Editor {
    let mut editor = Editor::new();
    editor.apply(create(CENTRE, 120.0)).unwrap();
    editor
}

#[test]
fn a_stroke_paints_under_the_pen_only_and_undo_takes_it_back() {
    let mut editor = ball();
    let stroke = segment(
        CENTRE - DVec2::new(60.0, 0.0),
        CENTRE + DVec2::new(60.0, 0.0),
    );
    editor.apply(Op::Paint(paint(&stroke, 16.0))).unwrap();
    let model = &editor.document().models[0];
    let colors = shown(model);
    let (mut painted, mut clay) = (0, 0);
    for (v, &p) in model.mesh.positions().iter().enumerate() {
        let s = screen(p);
        let off_line = (s.y - CENTRE.y).abs().max((s.x - CENTRE.x).abs() - 60.0);
        let is_front = p.z > 0.0;
        if is_front && off_line < 10.0 {
            assert!(
                is_red(colors[v]),
                "vertex {v} under the pen is {:?}",
                colors[v]
            );
            painted += 1;
        } else if !is_front || off_line > 22.0 {
            assert_eq!(
                colors[v],
                Finish::CLAY.rgb(),
                "vertex {v} away from the pen"
            );
            clay += 1;
        }
    }
    assert!(painted > 10 && clay > 100, "{painted} painted, {clay} clay");
    editor.undo().unwrap();
    assert!(editor.document().models[0].vertex_colors().is_none());
}

#[test]
fn a_brush_over_empty_canvas_paints_nothing_and_changes_nothing() {
    let mut editor = ball();
    let before = editor.document().clone();
    let corner = segment(DVec2::new(20.0, 20.0), DVec2::new(80.0, 20.0));
    let error = editor.apply(Op::Paint(paint(&corner, 16.0))).unwrap_err();
    assert_eq!(error, CommandError::NothingPainted);
    assert_eq!(editor.document(), &before);
    assert_eq!(editor.ops().len(), 1);
}

#[test]
fn fill_clamps_its_colour_and_material_its_numbers() {
    let mut editor = ball();
    let fill = FillInput {
        model: 0,
        color: [2.0, -1.0, 0.5],
    };
    editor.apply(Op::Fill(fill)).unwrap();
    let model = &editor.document().models[0];
    assert!(shown(model).iter().all(|&c| c == [1.0, 0.0, 0.5]));
    let material = MaterialInput {
        model: 0,
        base_color: [0.5, 0.5, 0.5, 3.0],
        roughness: -2.0,
        metalness: f64::NAN,
    };
    editor.apply(Op::Material(material)).unwrap();
    let finish = editor.document().models[0].finish();
    assert_eq!(finish.base_color, [0.5, 0.5, 0.5, 1.0]);
    assert_eq!((finish.roughness, finish.metalness), (0.0, 0.0));
    // The base colour multiplies the paint, as glTF's COLOR_0 multiplies the factor.
    assert!(
        shown(&editor.document().models[0])
            .iter()
            .all(|&c| c == [0.5, 0.0, 0.25])
    );
}

#[test]
fn colours_follow_a_cut_and_each_side_keeps_its_own_through_a_merge() {
    let mut editor = ball();
    editor
        .apply(Op::Fill(FillInput {
            model: 0,
            color: [0.0, 0.0, 1.0],
        }))
        .unwrap();
    // A red band across the top, then the right third cut off.
    let band = segment(
        CENTRE + DVec2::new(-100.0, -60.0),
        CENTRE + DVec2::new(100.0, -60.0),
    );
    editor.apply(Op::Paint(paint(&band, 18.0))).unwrap();
    let before = editor.document().models[0].clone();
    let cut = segment(DVec2::new(470.0, 100.0), DVec2::new(470.0, 500.0));
    editor
        .apply(Op::Cut(StrokeInput {
            viewport: VIEWPORT.to_array(),
            camera: Camera::default(),
            stroke: samples(cut),
        }))
        .unwrap();
    let model = &editor.document().models[0];
    assert_ne!(model.mesh.triangles(), before.mesh.triangles());
    let colors = model
        .vertex_colors()
        .expect("the cut model keeps its paint");
    let old = shown(&before);
    let old_nearest = |p: DVec3| {
        let v = (0..before.mesh.n_vertices())
            .min_by(|&a, &b| {
                let d = |v: usize| before.mesh.positions()[v].distance_squared(p);
                d(a).total_cmp(&d(b))
            })
            .unwrap();
        (before.mesh.positions()[v].distance(p), old[v])
    };
    let mut kept = 0;
    for (v, &p) in model.mesh.positions().iter().enumerate() {
        let (distance, colour) = old_nearest(p);
        if distance < 1e-9 {
            assert_eq!(
                colors[v], colour,
                "vertex {v} kept its place and its colour"
            );
            kept += 1;
        }
    }
    assert!(kept > 100, "{kept} kept");
    // What moved stays red only near the band.
    for (v, &p) in model.mesh.positions().iter().enumerate() {
        if is_red(colors[v]) && p.z > 0.0 {
            let y = screen(p).y - CENTRE.y;
            assert!(
                (y + 60.0).abs() < 30.0,
                "a red vertex {y} px below the centre"
            );
        }
    }
    assert!(colors.iter().any(|&c| is_red(c)) && colors.contains(&[0.0, 0.0, 1.0]));
    // A red ball merged into the blue one: each keeps its colour away from the seam.
    editor
        .apply(create(CENTRE + DVec2::new(-150.0, 0.0), 80.0))
        .unwrap();
    editor
        .apply(Op::Fill(FillInput {
            model: 1,
            color: RED,
        }))
        .unwrap();
    let (blue_part, red_part) = (
        editor.document().models[0].clone(),
        editor.document().models[1].clone(),
    );
    editor
        .apply(Op::Merge(MergeInput { models: [0, 1] }))
        .unwrap();
    let merged = &editor.document().models[0];
    let colors = merged.vertex_colors().unwrap();
    let bvh = |m: &Model| sketchmesh_core::geometry::Bvh::new(&m.mesh);
    let (blue_bvh, red_bvh) = (bvh(&blue_part), bvh(&red_part));
    let (mut reds, mut blues) = (0, 0);
    for (v, &p) in merged.mesh.positions().iter().enumerate() {
        let d = |m: &Model, b: &sketchmesh_core::geometry::Bvh| {
            b.nearest(&m.mesh, p).unwrap().0.distance(p)
        };
        let (to_blue, to_red) = (d(&blue_part, &blue_bvh), d(&red_part, &red_bvh));
        if to_red < 1e-9 && to_blue > 0.05 {
            assert!(is_red(colors[v]));
            reds += 1;
        } else if to_blue < 1e-9 && to_red > 0.05 && screen(p).y > CENTRE.y {
            assert_eq!(colors[v], [0.0, 0.0, 1.0]);
            blues += 1;
        }
    }
    assert!(reds > 50 && blues > 50, "{reds} red, {blues} blue");
}

#[test]
fn symmetry_paints_the_other_side_and_the_twin() {
    let plane = MirrorPlane::default();
    let mut editor = Editor::new();
    editor.apply(create(CENTRE, 120.0).mirrored(plane)).unwrap();
    editor
        .apply(create(CENTRE + DVec2::new(250.0, -150.0), 50.0).mirrored(plane))
        .unwrap();
    assert_eq!(editor.document().models.len(), 3);
    // On the body's right side, and over the small ball on the right.
    let right = segment(
        CENTRE + DVec2::new(40.0, -40.0),
        CENTRE + DVec2::new(70.0, 40.0),
    );
    editor
        .apply(Op::Paint(paint(&right, 14.0)).mirrored(plane))
        .unwrap();
    let ball = CENTRE + DVec2::new(250.0, -150.0);
    editor
        .apply(Op::Paint(paint(&segment(ball, ball + DVec2::new(10.0, 0.0)), 14.0)).mirrored(plane))
        .unwrap();
    let doc = editor.document();
    let body = &doc.models[0];
    let partner = sketchmesh_core::symmetry::partners(&body.mesh, &plane).unwrap();
    let colors = shown(body);
    let painted = (0..colors.len()).filter(|&v| is_red(colors[v])).count();
    assert!(painted > 10);
    for v in 0..colors.len() {
        assert_eq!(
            colors[v],
            colors[partner[v].index()],
            "vertex {v} and its partner"
        );
    }
    let (small, twin) = (shown(&doc.models[1]), shown(&doc.models[2]));
    assert!(small.iter().any(|&c| is_red(c)));
    assert_eq!(small, twin, "the twin is painted vertex for vertex");
}

#[test]
fn paint_and_material_go_out_to_gltf_and_come_back() {
    let mut editor = ball();
    let stroke = segment(
        CENTRE - DVec2::new(40.0, 0.0),
        CENTRE + DVec2::new(40.0, 0.0),
    );
    let mut soft = paint(&stroke, 30.0);
    (soft.hardness, soft.opacity, soft.color) = (0.2, 0.7, [0.1, 0.6, 0.3]);
    editor.apply(Op::Paint(soft)).unwrap();
    let material = MaterialInput {
        model: 0,
        base_color: [0.9, 0.8, 0.7, 1.0],
        roughness: 0.25,
        metalness: 0.5,
    };
    editor.apply(Op::Material(material)).unwrap();
    // Moved, so the file holds more than the create's own numbers.
    let mut matrix = glam::DMat4::from_translation(DVec3::new(0.5, 0.0, 0.0)).to_cols_array();
    matrix[0] = 1.0;
    editor
        .apply(Op::Transform(TransformInput { model: 0, matrix }))
        .unwrap();
    let model = &editor.document().models[0];
    let glb = write_glb(editor.document());
    let file = ImportFile {
        name: "painted.glb",
        bytes: &glb,
    };
    let back = import_gltf(&file, &[], &ImportLimits::default()).unwrap();
    let again = &back.models[0];
    assert_eq!(again.finish, model.finish);
    assert!(again.appearance.is_none());
    let (ours, theirs) = (
        model.vertex_colors().unwrap(),
        again.vertex_colors().unwrap(),
    );
    assert_eq!(ours.len(), theirs.len());
    // The import welds the file's vertices in its own order: compare by position.
    for (v, &p) in again.mesh.positions().iter().enumerate() {
        let w = (0..model.mesh.n_vertices())
            .min_by(|&a, &b| {
                let d = |u: usize| model.mesh.positions()[u].distance_squared(p);
                d(a).total_cmp(&d(b))
            })
            .unwrap();
        assert_eq!(theirs[v], ours[w]);
    }
}

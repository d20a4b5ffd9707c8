//! Symmetric modelling (issue 50): ops made with symmetry on keep every model symmetric about
//! the plane, or mirror twins, to 1e-9 of the bounding-box diagonal.

#![allow(clippy::unwrap_used)] // A panic is a test failure with a location.

use glam::{DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{
    CommandError, Document, Editor, Model, Op, StrokeInput, SymmetrizeInput,
};
use sketchmesh_core::mesh::VertexId;
use sketchmesh_core::model::{MirrorPlane, Side};
use sketchmesh_core::symmetry::{EXACT, are_twins, diagonal, partners};

use crate::common::{
    add_curve, circle, longest_outline, outline, oversketch, pushed_stroke, samples, segment,
    set_type,
};
use sketchmesh_core::document::{
    CurveHandleInput, DuplicateInput, HandleEditInput, KeyframeInput, MergeInput, ModelInput,
    OptimizeInput, OversketchFit, RegionEditInput, SketchFeatureInput, StrokePairInput,
    TransformInput,
};
use sketchmesh_core::feature::FeatureKind;
use sketchmesh_core::oversketch::OversketchRoi;
use sketchmesh_core::skeleton::HandleKind;

const VIEWPORT: DVec2 = DVec2::new(800.0, 600.0);
const CENTRE: DVec2 = DVec2::new(400.0, 300.0);

fn plane() -> MirrorPlane {
    MirrorPlane::default()
}

fn input(points: &[DVec2]) -> StrokeInput {
    StrokeInput {
        viewport: VIEWPORT.to_array(),
        camera: Camera::default(),
        stroke: samples(points.iter().copied()),
    }
}

fn screen(p: DVec3) -> DVec2 {
    Camera::default()
        .screen_from_world(p, VIEWPORT)
        .unwrap()
        .truncate()
}

fn mirrored(op: Op) -> Op {
    op.mirrored(plane())
}

/// A lumpy body drawn across the plane (not symmetric as drawn) and a small blob on the right,
/// both made with symmetry on: the body symmetric, the blob with a twin on the left.
fn body_and_limbs() -> Editor {
    let mut editor = Editor::new();
    let body = outline(
        CENTRE,
        150.0,
        &[(2, 0.12, 0.4), (3, 0.06, 1.1)],
        0.8,
        0.0,
        90,
    );
    editor
        .apply(mirrored(Op::Create(input(&body).into())))
        .unwrap();
    let blob = circle(CENTRE + DVec2::new(290.0, -170.0), 60.0);
    editor
        .apply(mirrored(Op::Create(input(&blob).into())))
        .unwrap();
    editor
}

/// The largest distance between a vertex's mirror image and its partner, over the models
/// of `doc`, relative to each model's diagonal; panics naming a model with no partner or twin.
fn asymmetry(doc: &Document) -> f64 {
    let mut worst = 0.0f64;
    for (i, model) in doc.models.iter().enumerate() {
        let scale = diagonal(&model.mesh);
        let twin = (doc.models.iter().enumerate())
            .find(|&(j, other)| j != i && are_twins(&model.mesh, &other.mesh, &plane()));
        let pairs = match twin {
            Some((_, other)) => {
                let p = model.mesh.positions().iter().zip(other.mesh.positions());
                p.map(|(&a, &b)| plane().reflect(a).distance(b))
                    .fold(0.0, f64::max)
            }
            None => {
                let partner = partners(&model.mesh, &plane())
                    .unwrap_or_else(|| panic!("model {i} is neither symmetric nor a twin"));
                assert_symmetric_connectivity(model, &partner);
                let p = model.mesh.positions();
                (0..p.len())
                    .map(|v| plane().reflect(p[v]).distance(p[partner[v].index()]))
                    .fold(0.0, f64::max)
            }
        };
        worst = worst.max(pairs / scale);
    }
    worst
}

/// Every triangle's mirror image (its corners' partners, turned over) is a triangle too.
fn assert_symmetric_connectivity(model: &Model, partner: &[VertexId]) {
    let triangles: std::collections::HashSet<[u32; 3]> = (model.mesh.triangles().iter())
        .map(|&t| canonical(t))
        .collect();
    for &[a, b, c] in model.mesh.triangles() {
        let image = [a, c, b].map(|v| partner[v as usize].0);
        assert!(
            triangles.contains(&canonical(image)),
            "triangle {a} {b} {c} has no mirror image"
        );
    }
}

fn canonical(t: [u32; 3]) -> [u32; 3] {
    let first = (0..3).min_by_key(|&k| t[k]).unwrap();
    [t[first], t[(first + 1) % 3], t[(first + 2) % 3]]
}

#[test]
fn a_body_across_the_plane_is_symmetric_and_a_limb_beside_it_gets_a_twin() {
    let editor = body_and_limbs();
    let doc = editor.document();
    assert_eq!(doc.models.len(), 3);
    assert!(asymmetry(doc) <= EXACT, "{}", asymmetry(doc));
    assert_eq!(doc.symmetry, Some(plane()));
    for model in &doc.models {
        model.mesh.validate().unwrap();
        assert!(model.mesh.is_closed());
        assert!(!model.curves.is_empty());
    }
    // The session says so, and replays bit for bit.
    let json = editor.session_json();
    assert!(json.contains(r#""mirror":[1.0,0.0,0.0,0.0]"#), "{json}");
    let replayed = Editor::replay_json(&json).unwrap();
    assert_eq!(replayed.document(), doc);
}

#[test]
fn a_pull_on_one_side_moves_both() {
    let mut editor = body_and_limbs();
    let before = editor.document().models[0].clone();
    let outline = before.curves[0].points(&before.mesh);
    let grab = *outline.iter().max_by(|a, b| a.x.total_cmp(&b.x)).unwrap();
    let from = screen(grab);
    let pull = Op::Pull(input(&segment(from, from + DVec2::new(60.0, -20.0))));
    editor.apply(mirrored(pull)).unwrap();
    let doc = editor.document();
    assert!(asymmetry(doc) <= EXACT, "{}", asymmetry(doc));
    let after = &doc.models[0];
    let (lo, hi) = after.mesh.bounding_box().unwrap();
    let (lo0, hi0) = before.mesh.bounding_box().unwrap();
    assert!(
        hi.x > hi0.x + 0.1 && lo.x < lo0.x - 0.1,
        "both sides moved out: {lo0} {hi0} → {lo} {hi}"
    );
}

#[test]
fn symmetrize_keeps_the_side_asked_for_and_refuses_a_plane_that_misses() {
    let mut editor = Editor::new();
    let body = outline(
        CENTRE + DVec2::new(60.0, 0.0),
        150.0,
        &[(2, 0.12, 0.4)],
        0.8,
        0.3,
        90,
    );
    editor.apply(Op::Create(input(&body).into())).unwrap();
    let off_centre = MirrorPlane::new(DVec3::new(1.0, 0.2, 0.0), 0.15).unwrap();
    let op = Op::Symmetrize(SymmetrizeInput {
        model: 0,
        plane: off_centre,
        keep: Side::Negative,
    });
    editor.apply(op).unwrap();
    let model = &editor.document().models[0];
    let partner = partners(&model.mesh, &off_centre).unwrap();
    assert_symmetric_connectivity(model, &partner);
    let far = MirrorPlane::new(DVec3::X, 100.0).unwrap();
    let refused = editor.apply(Op::Symmetrize(SymmetrizeInput {
        model: 0,
        plane: far,
        keep: Side::Positive,
    }));
    assert!(
        matches!(refused, Err(CommandError::Symmetry(_))),
        "{refused:?}"
    );
}

/// Points of a model's curve `k` on the right of the plane, on screen.
fn right_part(model: &Model, k: usize) -> Vec<DVec2> {
    let points = model.curves[k].points(&model.mesh);
    points
        .iter()
        .filter(|p| p.x > 0.15)
        .map(|&p| screen(p))
        .collect()
}

/// A limb's loop and silhouette ([`crate::common::extrusion_points`]) as strokes.
fn extrusion(centre: DVec2, radius: f64, reach: f64) -> [StrokeInput; 2] {
    let (base, silhouette) = crate::common::extrusion_points(centre, radius, reach);
    [input(&base), input(&silhouette)]
}

/// Applies `op` with symmetry on to a copy of `editor`; it must be accepted and leave every
/// model symmetric or a twin, to 1e-9 of its diagonal.
fn mirrored_ok(editor: &Editor, op: Op, what: &str) -> Editor {
    let mut editor = editor.clone();
    editor
        .apply(mirrored(op))
        .unwrap_or_else(|e| panic!("{what}: refused: {e}"));
    let worst = asymmetry(editor.document());
    assert!(worst <= EXACT, "{what}: asymmetry {worst}");
    editor
}

#[test]
fn every_kind_of_edit_made_with_symmetry_on_keeps_the_pairing() {
    let base = body_and_limbs();
    let body = base.document().models[0].clone();
    let centre = |model: usize| {
        let (lo, hi) = base.document().models[model].mesh.bounding_box().unwrap();
        screen(0.5 * (lo + hi))
    };
    let (right_blob, body_right) = (centre(1), CENTRE + DVec2::new(80.0, 0.0));

    // Curves: an open one across the body's right half and one on the twin blob; a closed one.
    let open = segment(
        body_right - DVec2::new(40.0, 50.0),
        body_right + DVec2::new(40.0, 50.0),
    );
    let with_curve = mirrored_ok(
        &base,
        add_curve(VIEWPORT, Camera::default(), &open, false, false),
        "add_curve",
    );
    let on_blob = segment(
        right_blob - DVec2::new(30.0, 0.0),
        right_blob + DVec2::new(30.0, 0.0),
    );
    mirrored_ok(
        &base,
        add_curve(VIEWPORT, Camera::default(), &on_blob, false, false),
        "add_curve on a twin",
    );
    mirrored_ok(
        &base,
        add_curve(
            VIEWPORT,
            Camera::default(),
            &circle(body_right, 30.0),
            true,
            false,
        ),
        "closed add_curve",
    );
    let curved = &with_curve.document().models[0];
    assert_eq!(
        curved.curves.len(),
        body.curves.len() + 2,
        "the curve and its image"
    );
    let mean_x = |k: usize| {
        let points = curved.curves[k].points(&curved.mesh);
        points.iter().map(|p| p.x).sum::<f64>() / points.len() as f64
    };
    let added = (0..curved.curves.len())
        .max_by(|&a, &b| mean_x(a).total_cmp(&mean_x(b)))
        .unwrap();
    let on_curve = right_part(curved, added);
    mirrored_ok(&with_curve, Op::Erase(input(&on_curve)), "erase");
    let outline_right = right_part(&body, 0);
    mirrored_ok(
        &base,
        set_type(VIEWPORT, Camera::default(), &outline_right, true),
        "set_curve_type",
    );
    mirrored_ok(&base, Op::Rub(input(&outline_right)), "rub");
    // Pulling the twin blob's outline moves its twin.
    let blob = &base.document().models[1];
    let grab = screen(blob.curves[0].points(&blob.mesh)[0]);
    mirrored_ok(
        &base,
        Op::Pull(input(&segment(grab, grab + DVec2::new(30.0, 10.0)))),
        "pull on a twin",
    );

    // Topology: cuts of the twin and of the body's right side, a limb out of the body.
    let down = |x: f64| Op::Cut(input(&segment(DVec2::new(x, 20.0), DVec2::new(x, 580.0))));
    let cut = mirrored_ok(&base, down(right_blob.x + 25.0), "cut a twin");
    assert_eq!(cut.document().models.len(), 3);
    let cut_body = mirrored_ok(&base, down(CENTRE.x + 110.0), "cut the body");
    let (lo, hi) = cut_body.document().models[0].mesh.bounding_box().unwrap();
    assert!(hi.x < body.mesh.bounding_box().unwrap().1.x - 0.2 && (lo.x + hi.x).abs() < 1e-9);
    let limb = mirrored_ok(
        &base,
        Op::Extrude(StrokePairInput {
            strokes: extrusion(body_right + DVec2::new(40.0, 0.0), 25.0, 150.0),
        }),
        "extrude",
    );
    let (lo, hi) = limb.document().models[0].mesh.bounding_box().unwrap();
    assert!(
        hi.x > body.mesh.bounding_box().unwrap().1.x + 0.3
            && lo.x < body.mesh.bounding_box().unwrap().0.x - 0.3,
        "two limbs"
    );

    // Over-sketch, feature and optimization on the body's right side.
    let silhouette = longest_outline(&body.mesh, &Camera::default(), VIEWPORT).unwrap();
    let pushed = pushed_stroke(&silhouette, DVec2::X, 12, 25.0);
    mirrored_ok(
        &base,
        oversketch(
            VIEWPORT,
            Camera::default(),
            &pushed,
            OversketchFit::Exact,
            OversketchRoi::NearHandle,
            None,
        ),
        "oversketch",
    );
    let ridge = SketchFeatureInput {
        viewport: VIEWPORT.to_array(),
        camera: Camera::default(),
        stroke: samples(segment(
            body_right - DVec2::new(0.0, 50.0),
            body_right + DVec2::new(0.0, 50.0),
        )),
        kind: FeatureKind::Ridge,
        amount: Some(2.0),
        region: None,
    };
    mirrored_ok(&base, Op::SketchFeature(ridge), "sketch_feature");
    mirrored_ok(
        &base,
        Op::Optimize(OptimizeInput {
            model: 0,
            ..OptimizeInput::default()
        }),
        "optimize",
    );

    // Arranging: a twin moves with its pair, goes with it, and a mirrored duplicate is a twin.
    let shift = glam::DMat4::from_translation(DVec3::new(0.3, 0.2, 0.0)).to_cols_array();
    let moved = mirrored_ok(
        &base,
        Op::Transform(TransformInput {
            model: 1,
            matrix: shift,
        }),
        "transform",
    );
    let (lo, hi) = moved.document().models[2].mesh.bounding_box().unwrap();
    let (lo1, hi1) = base.document().models[2].mesh.bounding_box().unwrap();
    assert!((lo.x - (lo1.x - 0.3)).abs() < 1e-9 && (hi.y - (hi1.y + 0.2)).abs() < 1e-9);
    let deleted = mirrored_ok(&base, Op::Delete(ModelInput { model: 2 }), "delete");
    assert_eq!(deleted.document().models.len(), 1);
    let copied = mirrored_ok(
        &deleted,
        Op::Duplicate(DuplicateInput {
            model: 0,
            beside: None,
        }),
        "duplicate",
    );
    assert_eq!(copied.document().models.len(), 2);
    // A blob moved into the body merges into both sides.
    let (blob_lo, blob_hi) = base.document().models[1].mesh.bounding_box().unwrap();
    let (_, body_hi) = body.mesh.bounding_box().unwrap();
    let target = DVec3::new(body_hi.x - 0.1, 0.0, 0.0);
    let into = glam::DMat4::from_translation(target - 0.5 * (blob_lo + blob_hi)).to_cols_array();
    let inside = mirrored_ok(
        &base,
        Op::Transform(TransformInput {
            model: 1,
            matrix: into,
        }),
        "move into the body",
    );
    let merged = mirrored_ok(&inside, Op::Merge(MergeInput { models: [0, 1] }), "merge");
    assert_eq!(merged.document().models.len(), 1);

    // A tunnel through the body's right side, drilled from the front and the back.
    let behind = Camera {
        eye: DVec3::new(0.0, 0.0, -5.0),
        ..Camera::default()
    };
    let back = DVec2::new(VIEWPORT.x - body_right.x, body_right.y);
    let loops = [
        input(&circle(body_right, 28.0)),
        StrokeInput {
            camera: behind,
            ..input(&circle(back, 28.0))
        },
    ];
    let drilled = mirrored_ok(
        &base,
        Op::Tunnel(StrokePairInput { strokes: loops }),
        "tunnel",
    );
    assert_eq!(
        drilled.document().models[0].mesh.genus(),
        Some(2),
        "a tunnel each side"
    );

    // A region of the body's right side moved (Bujans), and a curve handle bent (Blanco).
    let region = RegionEditInput {
        viewport: VIEWPORT.to_array(),
        camera: Camera::default(),
        reference: samples(segment(
            body_right - DVec2::new(0.0, 25.0),
            body_right + DVec2::new(0.0, 25.0),
        )),
        boundary: samples(circle(body_right, 60.0).into_iter().skip(1)),
        levels: None,
        areas: Vec::new(),
        transform: Some(glam::DMat4::from_translation(DVec3::new(0.1, 0.0, 0.2)).to_cols_array()),
        handles: None,
        profile: None,
        remesh: false,
    };
    mirrored_ok(&base, Op::RegionEdit(region), "region_edit");
    let handle = CurveHandleInput {
        viewport: VIEWPORT.to_array(),
        camera: Camera::default(),
        stroke: samples(segment(
            CENTRE + DVec2::new(20.0, 0.0),
            CENTRE + DVec2::new(140.0, 0.0),
        )),
        kind: HandleKind::Surface,
        control_points: 4,
        rigid: false,
    };
    let handled = mirrored_ok(&base, Op::CurveHandle(handle), "curve_handle");
    let number = handled.document().handles[0].id;
    let bend = HandleEditInput {
        handle: number,
        point: 3,
        translate: Some([0.0, 0.3, 0.0]),
        twist_deg: None,
        scale: None,
        spread: 1,
    };
    let bent = mirrored_ok(&handled, Op::HandleEdit(bend), "handle_edit");
    let (lo, hi) = bent.document().models[0].mesh.bounding_box().unwrap();
    assert!((lo.x + hi.x).abs() < 1e-9, "bent on both sides");

    // Animation: a key of the symmetric pose.
    mirrored_ok(&base, Op::Keyframe(KeyframeInput { time: 1.0 }), "keyframe");
}

/// The smallest corner angle (degrees) of the triangles with a corner within `band` of the
/// plane (relative to the diagonal), and of all triangles.
fn smallest_angles(model: &Model, plane: &MirrorPlane, band: f64) -> (f64, f64) {
    let tolerance = band * diagonal(&model.mesh);
    let (mut at_join, mut anywhere) = (180.0f64, 180.0f64);
    for f in model.mesh.faces() {
        let p = model.mesh.face_positions(f);
        let angle = (0..3)
            .map(|k| {
                let (a, b) = (p[(k + 1) % 3] - p[k], p[(k + 2) % 3] - p[k]);
                a.angle_between(b).to_degrees()
            })
            .fold(180.0, f64::min);
        anywhere = anywhere.min(angle);
        if p.iter()
            .any(|&q| plane.signed_distance(q).abs() <= tolerance)
        {
            at_join = at_join.min(angle);
        }
    }
    (at_join, anywhere)
}

#[test]
fn scans_are_symmetrized_about_an_off_centre_plane_with_no_new_sliver() {
    let Some(bunny) = crate::common::testdata_meshes("stanford_bunny.glb") else {
        return;
    };
    let Some(nefertiti) = crate::common::testdata_meshes("nefertiti.glb") else {
        return;
    };
    for (name, mesh) in [("bunny", &bunny[0]), ("Nefertiti", &nefertiti[0])] {
        let (lo, hi) = mesh.bounding_box().unwrap();
        // Off centre and tilted: a fifth of the width right of the middle, turned 10°.
        let through = 0.5 * (lo + hi) + DVec3::X * 0.2 * (hi.x - lo.x);
        let plane = MirrorPlane::through(through, DVec3::new(1.0, 0.18, 0.0)).unwrap();
        let mut editor = Editor::new();
        editor
            .apply(crate::common::import_mesh(name, mesh))
            .unwrap();
        let before = editor.document().models[0].clone();
        editor
            .apply(Op::Symmetrize(SymmetrizeInput {
                model: 0,
                plane,
                keep: Side::Negative,
            }))
            .unwrap();
        let model = &editor.document().models[0];
        model.mesh.validate().unwrap();
        let partner = partners(&model.mesh, &plane).expect("every vertex has a partner");
        assert_symmetric_connectivity(model, &partner);
        let (at_join, anywhere) = smallest_angles(model, &plane, 1e-9);
        let (input_near, input_anywhere) = smallest_angles(&before, &plane, 0.01);
        eprintln!(
            "{name}: {} → {} vertices; smallest angle at the join {at_join:.1}°, anywhere {anywhere:.2}° (input: {input_near:.2}° near the plane, {input_anywhere:.2}° anywhere)",
            before.mesh.n_vertices(),
            model.mesh.n_vertices()
        );
        // The join makes no triangle thinner than 5°, or than the input had near the plane.
        let floor = 5f64.min(0.9 * input_near);
        assert!(
            at_join >= floor,
            "{name}: a sliver at the join ({at_join:.2}°)"
        );
        // The kept side did not move: its vertices are the input's.
        let kept = (before.mesh.positions().iter())
            .filter(|&&p| plane.signed_distance(p) < -0.01 * diagonal(&before.mesh))
            .count();
        let found = (model.mesh.positions().iter())
            .filter(|&&p| plane.signed_distance(p) < -0.01 * diagonal(&before.mesh))
            .count();
        assert_eq!(kept, found, "{name}: the kept side's vertices stay");
    }
}

#[test]
fn symmetry_survives_a_glb_round_trip() {
    let made = body_and_limbs();
    let op = crate::common::import_document("symmetric.glb", made.document());
    let mut editor = Editor::new();
    editor.apply(op).unwrap();
    let doc = editor.document();
    assert_eq!(doc.symmetry, Some(plane()));
    assert_eq!(doc.models.len(), 3);
    // 32-bit positions in the file, exact pairs again once imported.
    let worst = asymmetry(doc);
    assert!(worst <= EXACT, "asymmetry after import {worst}");
    // And it keeps: a pull made with symmetry on acts on both sides.
    let model = &doc.models[0];
    let outline = model.curves[0].points(&model.mesh);
    let grab = *outline.iter().max_by(|a, b| a.x.total_cmp(&b.x)).unwrap();
    let from = screen(grab);
    let pull = Op::Pull(input(&segment(from, from + DVec2::new(40.0, 0.0))));
    let pulled = mirrored_ok(&editor, pull, "pull after import");
    assert!(asymmetry(pulled.document()) <= EXACT);
}

#[test]
fn a_mirrored_pull_previews_while_dragged_and_commits_symmetric() {
    let mut editor = body_and_limbs();
    let model = editor.document().models[0].clone();
    let outline = model.curves[0].points(&model.mesh);
    let grab = *outline.iter().max_by(|a, b| a.x.total_cmp(&b.x)).unwrap();
    let from = screen(grab);
    let mut edit = editor
        .begin_gesture(mirrored(Op::Pull(input(&[from]))))
        .unwrap();
    for k in 1..=15 {
        let p = from + DVec2::new(4.0 * f64::from(k), 0.0);
        edit.extend([p.x, p.y, 0.5]);
        while edit.step().unwrap() == sketchmesh_core::document::Progress::Working {}
    }
    let (index, moved) = edit.moved_model().expect("a preview while dragging");
    assert_eq!(index, 0);
    let farthest = moved.iter().map(|p| p.x).fold(f64::MIN, f64::max);
    assert!(
        farthest > grab.x + 0.2,
        "the preview follows the drag: {farthest}"
    );
    edit.finish(&mut editor).unwrap();
    assert!(asymmetry(editor.document()) <= EXACT);
    assert!(matches!(editor.ops().last(), Some(Op::Mirrored(_))));
}

#[test]
fn an_outline_drawn_off_centre_across_the_plane_comes_out_even_without_a_notch() {
    let mut editor = Editor::new();
    // An egg drawn 40 px right of the plane: kept as drawn, one half would meet its image at
    // an angle, a notch at the top and the bottom.
    let drawn = outline(
        CENTRE + DVec2::new(40.0, 0.0),
        140.0,
        &[(1, 0.12, 0.0)],
        1.2,
        0.3,
        90,
    );
    editor
        .apply(mirrored(Op::Create(input(&drawn).into())))
        .unwrap();
    let model = &editor.document().models[0];
    assert!(asymmetry(editor.document()) <= EXACT);
    let points = model.curves[0].points(&model.mesh);
    let n = points.len();
    let mut crossings = 0;
    for i in 0..n {
        let (before, at, after) = (points[(i + n - 1) % n], points[i], points[(i + 1) % n]);
        if at.x.abs() > 1e-9 * diagonal(&model.mesh) {
            continue;
        }
        crossings += 1;
        let kink = (at - before).angle_between(after - at).to_degrees();
        assert!(
            kink < 15.0,
            "the outline turns {kink:.1}° where it crosses the plane"
        );
    }
    assert_eq!(
        crossings, 2,
        "the outline crosses the plane at its top and bottom"
    );
    // The session keeps the stroke as drawn, and replays to the same shape.
    assert_eq!(editor.ops()[0].stroke().unwrap().len(), drawn.len());
    let replayed = Editor::replay_json(&editor.session_json()).unwrap();
    assert_eq!(replayed.document(), editor.document());
}

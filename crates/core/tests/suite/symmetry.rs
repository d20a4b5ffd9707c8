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

use crate::common::{circle, outline, samples, segment};

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

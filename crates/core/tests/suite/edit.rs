//! One protocol for every op: an edit begun, stepped and finished by hand (gestures extended
//! sample by sample, as the app does) gives the very document `apply` gives; a cancelled or
//! refused edit changes nothing.

#![allow(clippy::unwrap_used)] // A panic is a test failure with a location.

use std::f64::consts::TAU;

use crate::common::{commit_elsewhere, preview_elsewhere};
use glam::{DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{
    AddCurveInput, BrushInput, CommandError, Editor, Op, OptimizeInput, OversketchFit,
    OversketchInput, Progress, SketchFeatureInput, StrokeInput,
};
use sketchmesh_core::feature::{FeatureError, FeatureKind};
use sketchmesh_core::io::Previewed;
use sketchmesh_core::optimize::region::brushed_vertices;
use sketchmesh_core::optimize::{Mode, OptimizeParams, Optimizer, Selection};
use sketchmesh_core::oversketch::OversketchRoi;

const VIEWPORT: [f64; 2] = [800.0, 600.0];
const CENTRE: DVec2 = DVec2::new(400.0, 300.0);

fn input(points: impl IntoIterator<Item = DVec2>) -> StrokeInput {
    StrokeInput {
        viewport: VIEWPORT,
        camera: Camera::default(),
        stroke: points.into_iter().map(|p| [p.x, p.y, 0.5]).collect(),
    }
}

fn circle(centre: DVec2, radius: f64) -> StrokeInput {
    input((0..=80).map(|i| centre + radius * DVec2::from_angle(TAU * f64::from(i) / 80.0)))
}

/// Samples along the segment from `a` to `b`, about every 4 px.
fn segment(a: DVec2, b: DVec2) -> Vec<DVec2> {
    let n = (a.distance(b) / 4.0).ceil().max(1.0) as usize;
    (0..=n).map(|i| a.lerp(b, i as f64 / n as f64)).collect()
}

fn screen(p: DVec3) -> DVec2 {
    Camera::default()
        .screen_from_world(p, DVec2::from(VIEWPORT))
        .unwrap()
        .truncate()
}

/// The arc of radius `radius` about the centre from `a` to `b` degrees.
fn arc(radius: f64, a: f64, b: f64) -> Vec<DVec2> {
    (0..=60)
        .map(|k| {
            CENTRE + radius * DVec2::from_angle((a + (b - a) * f64::from(k) / 60.0).to_radians())
        })
        .collect()
}

fn oversketch(points: &[DVec2]) -> Op {
    let stroke = input(points.iter().copied());
    Op::Oversketch(OversketchInput {
        viewport: stroke.viewport,
        camera: stroke.camera,
        stroke: stroke.stroke,
        fit: OversketchFit::Exact,
        roi: OversketchRoi::NearHandle,
        handle: None,
    })
}

/// An op made from the document it applies to.
type MakeOp = Box<dyn Fn(&Editor) -> Op>;

/// The ops of a short session: ink, a shape, a curve across it, a pull of that curve, an
/// over-sketch of the outline, an erase of the pulled curve, undo and redo.
fn session() -> Vec<MakeOp> {
    vec![
        Box::new(|_| {
            Op::Stroke(input(segment(
                DVec2::new(40.0, 40.0),
                DVec2::new(200.0, 60.0),
            )))
        }),
        Box::new(|_| Op::Create(circle(CENTRE, 150.0).into())),
        Box::new(|_| {
            let stroke = input(segment(CENTRE - DVec2::X * 90.0, CENTRE + DVec2::X * 90.0));
            Op::AddCurve(AddCurveInput {
                viewport: stroke.viewport,
                camera: stroke.camera,
                stroke: stroke.stroke,
                closed: false,
                cross_section: false,
            })
        }),
        Box::new(|editor| {
            let model = &editor.document().models[0];
            let points = model.curves[1].points(&model.mesh);
            let start = screen(points[points.len() / 2]);
            Op::Pull(input(segment(start, start + DVec2::new(0.0, -60.0))))
        }),
        Box::new(|_| oversketch(&arc(165.0, -30.0, 30.0))),
        Box::new(|editor| {
            let model = &editor.document().models[0];
            let points = model.curves[1].points(&model.mesh);
            Op::Erase(input(points.iter().map(|&p| screen(p))))
        }),
        Box::new(|_| Op::Undo),
        Box::new(|_| Op::Redo),
    ]
}

/// Whether the app draws `op` as a gesture: begun at pointer-down, extended on moves.
fn is_gesture(op: &Op) -> bool {
    matches!(op, Op::Pull(_) | Op::Oversketch(_))
}

/// Applies `op` through the protocol by hand, one step at a time; a gesture is begun with
/// its first sample and extended by the others, stepping in between as frames would.
/// Returns how many steps it took.
fn by_hand(editor: &mut Editor, op: Op) -> Result<usize, CommandError> {
    let mut steps = 0;
    let mut edit = if is_gesture(&op) {
        let samples = op.stroke().unwrap().to_vec();
        let mut first = op;
        first.stroke_mut().unwrap().truncate(1);
        let mut edit = editor.begin_gesture(first)?;
        for &sample in &samples[1..] {
            edit.extend(sample);
            loop {
                steps += 1;
                if edit.step()? == Progress::Waiting {
                    break;
                }
            }
        }
        assert_eq!(edit.op().stroke().unwrap(), &samples[..]);
        edit.end_gesture();
        edit
    } else {
        editor.begin(op)?
    };
    loop {
        steps += 1;
        if edit.step()? == Progress::Done {
            break;
        }
    }
    edit.finish(editor)?;
    Ok(steps)
}

#[test]
fn applying_equals_beginning_stepping_and_finishing_by_hand() {
    let (mut direct, mut hand) = (Editor::new(), Editor::new());
    for (k, make) in session().iter().enumerate() {
        let op = make(&direct);
        let name = op.name();
        direct
            .apply(op.clone())
            .unwrap_or_else(|e| panic!("op {k} ({name}): {e}"));
        let steps = by_hand(&mut hand, op).unwrap();
        assert_eq!(hand.document(), direct.document(), "op {k} ({name})");
        assert_eq!(
            hand.session_json(),
            direct.session_json(),
            "op {k} ({name})"
        );
        if name == "create" {
            assert!(
                steps > 3,
                "a creation refines over several steps, not {steps}"
            );
        }
    }
    assert_eq!(hand.ops().len(), 8);
    let replayed = Editor::replay_json(&hand.session_json()).unwrap();
    assert_eq!(replayed.document(), hand.document());
}

#[test]
fn gestures_preview_without_changing_the_document() {
    let mut editor = Editor::new();
    for make in &session()[1..3] {
        editor.apply(make(&editor)).unwrap();
    }
    let before = editor.document().clone();
    // A pull: the first step factors the region, each followed sample moves its vertices.
    let Op::Pull(drag) = session()[3](&editor) else {
        unreachable!("the fourth op is a pull")
    };
    let mut edit = editor
        .begin_gesture(Op::Pull(StrokeInput {
            stroke: drag.stroke[..1].to_vec(),
            ..drag.clone()
        }))
        .unwrap();
    assert_eq!(edit.step().unwrap(), Progress::Waiting);
    let rest = before.models[0].mesh.positions();
    assert_eq!(edit.moved_model(), Some((0, rest)));
    let generation = edit.generation();
    // Five samples arrive between two frames (the page's worker's pace): one step follows
    // the latest, and a step with nothing new changes nothing.
    let (first, rest_of_drag) = drag.stroke[1..].split_at(5);
    for &sample in first {
        edit.extend(sample);
    }
    assert_eq!(edit.step().unwrap(), Progress::Waiting);
    assert_eq!(edit.generation(), generation + 1);
    assert_eq!(edit.step().unwrap(), Progress::Waiting);
    assert_eq!(edit.generation(), generation + 1, "nothing new to follow");
    for samples in rest_of_drag.chunks(5) {
        for &sample in samples {
            edit.extend(sample);
        }
        assert_eq!(edit.step().unwrap(), Progress::Waiting);
    }
    let (index, moved) = edit.moved_model().unwrap();
    assert_eq!(index, 0);
    assert_ne!(moved, rest);
    assert_eq!((edit.document(), edit.revision()), (&before, 0));
    edit.cancel();
    // An over-sketch: each model's silhouettes once, then the stroke so far is matched.
    let Op::Oversketch(stroke) = session()[4](&editor) else {
        unreachable!("the fifth op is an over-sketch")
    };
    let mut edit = editor
        .begin_gesture(Op::Oversketch(OversketchInput {
            stroke: stroke.stroke[..1].to_vec(),
            ..stroke.clone()
        }))
        .unwrap();
    assert_eq!(edit.step().unwrap(), Progress::Waiting);
    assert!(edit.outline().is_none());
    for &sample in &stroke.stroke[1..] {
        edit.extend(sample);
        while edit.step().unwrap() == Progress::Working {}
    }
    let piece = edit.outline().expect("the stroke matches the outline");
    assert!(piece.is_confident && piece.points.len() > 5);
    assert_eq!(edit.document(), &before);
    edit.cancel();
    assert_eq!(editor.document(), &before);
}

/// An optimization of the first model at `scale` in `mode`, other settings as default.
fn optimize(scale: f64, mode: Mode) -> Op {
    Op::Optimize(OptimizeInput {
        model: 0,
        settings: OptimizeParams {
            mode,
            scale,
            ..OptimizeParams::default()
        },
        ..OptimizeInput::default()
    })
}

#[test]
fn an_optimization_previews_each_setting_and_commits_the_last_without_solving_again() {
    let mut editor = Editor::new();
    editor.apply(session()[1](&editor)).unwrap();
    let before = editor.document().clone();
    let mut edit = editor.begin_gesture(optimize(1.0, Mode::Smooth)).unwrap();
    let rest = before.models[0].mesh.positions();
    assert_eq!(edit.moved_model(), Some((0, rest)), "the model as it is");
    assert_eq!(edit.step().unwrap(), Progress::Waiting);
    let at_one = edit.moved_model().unwrap().1.to_vec();
    assert_ne!(at_one, rest);
    let generation = edit.generation();
    assert_eq!(edit.step().unwrap(), Progress::Waiting);
    assert_eq!(edit.generation(), generation, "nothing new to solve");
    // The slider: conjugate-gradient steps toward the new scale, close to the exact result.
    edit.revise(optimize(0.2, Mode::Smooth));
    let mut iterations = 0;
    while edit.step().unwrap() == Progress::Working {
        iterations += 1;
    }
    assert!((1..40).contains(&iterations), "{iterations} iterations");
    let mut exact = editor.clone();
    exact.apply(optimize(0.2, Mode::Smooth)).unwrap();
    let (_, approached) = edit.moved_model().unwrap();
    let error = approached
        .iter()
        .zip(exact.document().models[0].mesh.positions())
        .map(|(a, b)| a.distance(*b))
        .fold(0.0, f64::max);
    assert!(error < 1e-4, "the preview is {error} from the exact result");
    // The mode: a new system, solved in one step.
    edit.revise(optimize(0.5, Mode::Shape));
    assert_eq!(edit.step().unwrap(), Progress::Waiting);
    edit.revise(Op::Undo);
    assert_eq!(
        edit.op(),
        &optimize(0.5, Mode::Shape),
        "another kind of op is ignored"
    );
    let previewed = edit.moved_model().unwrap().1.to_vec();
    assert_eq!((edit.document(), edit.revision()), (&before, 0));
    edit.end_gesture();
    assert_eq!(
        edit.step().unwrap(),
        Progress::Done,
        "the preview is the result"
    );
    edit.finish(&mut editor).unwrap();
    assert_eq!(editor.document().models[0].mesh.positions(), previewed);
    let mut applied = Editor::new();
    applied.apply(session()[1](&applied)).unwrap();
    applied.apply(optimize(0.5, Mode::Shape)).unwrap();
    assert_eq!(applied.document(), editor.document());
    assert_eq!(applied.session_json(), editor.session_json());
}

#[test]
fn an_optimization_in_a_lasso_moves_only_what_the_lasso_holds() {
    let mut editor = Editor::new();
    editor.apply(session()[1](&editor)).unwrap();
    let before = editor.document().clone();
    let lasso = |half: f64| {
        let corner = |x: f64, y: f64| CENTRE + DVec2::new(60.0 + x * half, y * half);
        let square = [
            corner(-1.0, -1.0),
            corner(1.0, -1.0),
            corner(1.0, 1.0),
            corner(-1.0, 1.0),
        ];
        Op::Optimize(OptimizeInput {
            model: 0,
            settings: OptimizeParams {
                mode: Mode::Smooth,
                scale: 0.3,
                ..OptimizeParams::default()
            },
            region: Some(input(square)),
            ..OptimizeInput::default()
        })
    };
    editor.apply(lasso(50.0)).unwrap();
    let mesh = &before.models[0].mesh;
    let after = editor.document().models[0].mesh.positions();
    let camera = Camera::default();
    let mut moved = 0;
    for (p, q) in mesh.positions().iter().zip(after) {
        if p != q {
            moved += 1;
            let s = camera.screen_from_world(*p, DVec2::from(VIEWPORT)).unwrap();
            let offset = s.truncate() - CENTRE - DVec2::new(60.0, 0.0);
            assert!(
                offset.abs().max_element() <= 50.0,
                "a vertex outside the lasso moved"
            );
        }
    }
    assert!(moved > 10, "{moved} vertices moved");
    // A lasso around nothing of the model is refused and changes nothing.
    let far = Op::Optimize(OptimizeInput {
        region: Some(input([
            DVec2::new(5.0, 5.0),
            DVec2::new(30.0, 5.0),
            DVec2::new(5.0, 30.0),
        ])),
        ..match lasso(1.0) {
            Op::Optimize(op) => op,
            _ => unreachable!("an optimize op"),
        }
    });
    let kept = editor.document().clone();
    let refused = editor.apply(far).unwrap_err();
    assert!(refused.to_string().contains("lasso"), "{refused}");
    assert_eq!(editor.document(), &kept);
    let replayed = Editor::replay_json(&editor.session_json()).unwrap();
    assert_eq!(replayed.document(), editor.document());
}

/// A brush stroke painted across the shape bounds what smoothing moves to the band under it;
/// a second stroke painted over part of that band tags features: the op gives what the
/// optimizer gives with the vertices each brush covers (the features' effect is measured on
/// a cube's edges in `core::optimize`); the session replays both.
#[test]
fn a_painted_area_bounds_the_optimization_and_painted_features_are_tagged() {
    let mut editor = Editor::new();
    editor.apply(session()[1](&editor)).unwrap();
    let before = editor.document().clone();
    let mesh = &before.models[0].mesh;
    let brush = |a: DVec2, b: DVec2| BrushInput {
        stroke: input(segment(a, b)),
        radius: 20.0,
    };
    let band = brush(CENTRE - DVec2::X * 100.0, CENTRE + DVec2::X * 100.0);
    let keep = brush(CENTRE - DVec2::X * 30.0, CENTRE + DVec2::X * 30.0);
    let settings = OptimizeParams {
        mode: Mode::Smooth,
        scale: 0.1,
        ..OptimizeParams::default()
    };
    let op = |painted_features: Vec<BrushInput>| {
        Op::Optimize(OptimizeInput {
            model: 0,
            settings,
            painted: vec![band.clone()],
            painted_features,
            ..OptimizeInput::default()
        })
    };
    editor.apply(op(Vec::new())).unwrap();
    let mut moved = 0;
    let after = editor.document().models[0].mesh.positions().to_vec();
    for (p, q) in mesh.positions().iter().zip(&after) {
        if p != q {
            moved += 1;
            let offset = (screen(*p) - CENTRE).abs();
            assert!(offset.x <= 120.0 && offset.y <= 30.0, "moved at {offset}");
        }
    }
    assert!(moved > 10, "{moved} vertices moved");
    editor.undo().unwrap();
    editor.apply(op(vec![keep.clone()])).unwrap();
    let covered = |b: &BrushInput| {
        let viewport = DVec2::from(VIEWPORT);
        brushed_vertices(
            mesh,
            &b.stroke.camera,
            viewport,
            &b.stroke.points(),
            b.radius,
        )
    };
    let selection = Selection {
        movable: Some(covered(&band)),
        features: Some(covered(&keep)),
        sliding: None,
    };
    let expected = Optimizer::new(mesh, &settings, &selection)
        .unwrap()
        .solve(settings.scale)
        .unwrap();
    assert_eq!(editor.document().models[0].mesh.positions(), expected);
    assert_ne!(editor.document().models[0].mesh.positions(), after);
    let replayed = Editor::replay_json(&editor.session_json()).unwrap();
    assert_eq!(replayed.document(), editor.document());
}

#[test]
fn a_cancelled_edit_leaves_the_document_and_history_untouched() {
    let mut editor = Editor::new();
    for make in &session()[..3] {
        editor.apply(make(&editor)).unwrap();
    }
    editor.undo().unwrap();
    let state = |e: &Editor| {
        (
            e.document().clone(),
            e.session_json(),
            e.revision(),
            e.can_undo(),
            e.can_redo(),
        )
    };
    let before = state(&editor);
    let mut creation = editor
        .begin(Op::Create(circle(CENTRE + DVec2::X * 200.0, 60.0).into()))
        .unwrap();
    for _ in 0..3 {
        creation.step().unwrap();
    }
    assert_eq!(creation.document().models.len(), 2);
    creation.cancel();
    let mut pull = editor
        .begin_gesture(Op::Pull(input([CENTRE + DVec2::X * 150.0])))
        .unwrap();
    pull.step().unwrap();
    pull.extend([CENTRE.x + 190.0, CENTRE.y, 0.5]);
    pull.step().unwrap();
    pull.cancel();
    assert!(state(&editor) == before, "a cancel changed the editor");
    // Redo still finds what the undo took.
    editor.redo().unwrap();
    assert_eq!(editor.document().models[0].curves.len(), 2);
}

#[test]
fn a_refused_op_changes_nothing_whether_at_begin_a_step_or_finish() {
    let mut editor = Editor::new();
    assert_eq!(
        editor.begin(Op::Undo).err(),
        Some(CommandError::NothingToUndo)
    );
    editor.apply(session()[1](&editor)).unwrap();
    let (document, ops) = (editor.document().clone(), editor.ops().len());
    let unchanged = |e: &Editor| e.document() == &document && e.ops().len() == ops;
    // At begin: a drag that grabs no curve.
    let nowhere = Op::Pull(input([DVec2::new(20.0, 20.0)]));
    let refusal = editor.begin_gesture(nowhere.clone()).err();
    assert_eq!(refusal, Some(CommandError::NoCurveHere));
    // At a step: the same op begun whole refuses when computed, and then keeps refusing.
    let mut edit = editor.begin(nowhere).unwrap();
    assert_eq!(edit.step(), Err(CommandError::NoCurveHere));
    assert_eq!(edit.step(), Err(CommandError::NoCurveHere));
    assert_eq!(edit.finish(&mut editor), Err(CommandError::NoCurveHere));
    assert!(unchanged(&editor));
    // At finish: an undo begun while there was something to undo, finished after another
    // undo took it. The document changed, so the op is computed again, and refused.
    let undo = editor.begin(Op::Undo).unwrap();
    editor.undo().unwrap();
    let (document, ops) = (editor.document().clone(), editor.ops().len());
    assert_eq!(undo.finish(&mut editor), Err(CommandError::NothingToUndo));
    assert_eq!((editor.document(), editor.ops().len()), (&document, ops));
}

#[test]
fn an_edit_finished_after_the_document_changed_is_computed_again() {
    let first = Op::Stroke(input(segment(
        DVec2::new(40.0, 40.0),
        DVec2::new(200.0, 60.0),
    )));
    let second = Op::Create(circle(CENTRE, 120.0).into());
    let mut editor = Editor::new();
    let late = editor.begin(first.clone()).unwrap();
    editor.apply(second.clone()).unwrap();
    late.finish(&mut editor).unwrap();
    let mut in_order = Editor::new();
    in_order.apply(second).unwrap();
    in_order.apply(first).unwrap();
    assert_eq!(editor.document(), in_order.document());
    assert_eq!(editor.session_json(), in_order.session_json());
}

/// A ridge dragged up and down by hand (the app's live preview: the op revised with each
/// amount, one step each) commits the very mesh `apply` makes of the final op; the session
/// replays it; an amount that is not a number is refused and changes nothing; undo restores.
#[test]
fn a_dragged_feature_commits_what_apply_makes() {
    let mut editor = Editor::new();
    editor.apply(session()[1](&editor)).unwrap();
    let before = editor.document().clone();
    let op = feature_across_the_middle;
    for (kind, amounts) in [
        (FeatureKind::Ridge, [1.0, 3.0, 8.0, -2.0, 5.0]),
        (FeatureKind::Suggestive, [0.0, 30.0, 90.0, -45.0, 60.0]),
    ] {
        let mut edit = editor.begin_gesture(op(kind, amounts[0])).unwrap();
        let mut previews = Vec::new();
        for &amount in &amounts {
            edit.revise(op(kind, amount));
            assert_eq!(edit.step().unwrap(), Progress::Waiting);
            let (model, shown) = edit.moved_model().expect("a preview");
            assert_eq!(model, 0);
            previews.push(shown.to_vec());
        }
        assert_ne!(previews[1], previews[2], "the preview follows the amount");
        edit.finish(&mut editor).unwrap();
        let committed = editor.document().models[0].mesh.positions().to_vec();
        assert_eq!(&committed, previews.last().unwrap());
        let mut applied = Editor::new();
        applied.apply(session()[1](&applied)).unwrap();
        applied.apply(op(kind, *amounts.last().unwrap())).unwrap();
        assert_eq!(applied.document(), editor.document());
        let replayed = Editor::replay_json(&editor.session_json()).unwrap();
        assert_eq!(replayed.document(), editor.document());
        editor.undo().unwrap();
        assert_eq!(editor.document(), &before);
    }
    let n_ops = editor.ops().len();
    let refused = editor.apply(op(FeatureKind::Ridge, f64::NAN)).unwrap_err();
    assert_eq!(
        refused,
        CommandError::Feature(FeatureError::AmountNotFinite)
    );
    assert_eq!((editor.document(), editor.ops().len()), (&before, n_ops));
}

/// Brings a gesture stepped here and the same gesture previewed elsewhere (`worker` holds the
/// worker's kept edit) to `op`, their `k`-th revision (none for the first): the one here
/// steps, the one there gets the worker's preview of version `k + 1` and has nothing left
/// to step here.
fn revise_here_and_there(
    k: usize,
    op: Op,
    [here, there]: [&mut sketchmesh_core::document::Edit; 2],
    worker: &mut Option<sketchmesh_core::document::Edit>,
) {
    if k > 0 {
        here.revise(op.clone());
        there.revise(op);
    }
    while here.step().unwrap() == Progress::Working {}
    let version = preview_elsewhere(there, worker);
    assert_eq!(version, k + 1, "begun, then one version per revision");
    assert_eq!(
        there.step().unwrap(),
        Progress::Waiting,
        "nothing to step here"
    );
}

/// A `sketch_feature` op along a segment across the middle of the view.
fn feature_across_the_middle(kind: FeatureKind, amount: f64) -> Op {
    let sketch = input(segment(CENTRE - DVec2::X * 80.0, CENTRE + DVec2::X * 80.0));
    Op::SketchFeature(SketchFeatureInput {
        viewport: sketch.viewport,
        camera: sketch.camera,
        stroke: sketch.stroke,
        kind,
        amount: Some(amount),
        region: None,
    })
}

/// The page computes a feature's preview in its worker as its amount is dragged: each
/// preview the worker's edit computes (its feature edit built once, kept while the sketch
/// stays) is the one stepping here shows, cut back where stepping here cuts it back, and
/// the commit, from the worker's kept edit, is the op applied.
#[test]
fn a_feature_previewed_elsewhere_commits_what_apply_makes() {
    use sketchmesh_core::document::Edit;
    let mut editor = Editor::new();
    editor.apply(session()[1](&editor)).unwrap();
    let amounts = [1.0, 3.0, 1.0e4, -2.0, 5.0];
    let op = |amount| feature_across_the_middle(FeatureKind::Ridge, amount);
    let mut here = editor.begin_gesture(op(amounts[0])).unwrap();
    let mut there = editor.begin_gesture(op(amounts[0])).unwrap();
    let mut worker: Option<Edit> = None;
    let mut limited = 0;
    for (k, &amount) in amounts.iter().enumerate() {
        revise_here_and_there(k, op(amount), [&mut here, &mut there], &mut worker);
        assert_eq!(there.moved_model(), here.moved_model(), "amount {amount}");
        assert_eq!(
            there.limited_amount(),
            here.limited_amount(),
            "amount {amount}"
        );
        limited += usize::from(here.limited_amount().is_some());
    }
    assert!(
        limited > 0,
        "an amount of 10000 would fold the surface: it is cut back"
    );
    commit_elsewhere(there, worker, &mut editor);
    let mut applied = Editor::new();
    applied.apply(session()[1](&applied)).unwrap();
    applied.apply(op(5.0)).unwrap();
    assert_eq!(applied.document(), editor.document());
}

/// The page reads an import's files in its worker and hands the result, through the transfer
/// buffer, to the edit: the document and the session are those `apply` gives, placed beside
/// what the document holds. A refusal handed over changes nothing; so does a cancel.
#[test]
fn an_import_read_elsewhere_lands_as_the_applied_import() {
    use sketchmesh_core::document::{FileInput, ImportInput, import_files};
    use sketchmesh_core::io::{decode_imported, encode_imported};
    use std::sync::Arc;
    let Some(root) = crate::common::testdata() else {
        return;
    };
    let bytes = std::fs::read(root.join("meshes/spot.glb")).unwrap();
    let import = Op::Import(ImportInput {
        files: vec![FileInput {
            name: String::from("spot.glb"),
            data: Some(Arc::new(bytes)),
        }],
        beside: true,
    });
    let mut applied = Editor::new();
    applied
        .apply(Op::Create(circle(CENTRE, 120.0).into()))
        .unwrap();
    let mut by_worker = applied.clone();
    applied.apply(import.clone()).unwrap();

    let mut edit = by_worker.begin(import.clone()).unwrap();
    let input = edit.import_to_read().unwrap().clone();
    // What the worker does: read, encode; what the page does: decode, hand over.
    let buffer = encode_imported(&import_files(&input).unwrap());
    edit.supply_import(Ok(decode_imported(&buffer).unwrap()));
    assert!(edit.import_to_read().is_none(), "read once");
    assert_eq!(edit.step().unwrap(), Progress::Done);
    edit.finish(&mut by_worker).unwrap();
    assert_eq!(by_worker.document(), applied.document());
    assert_eq!(by_worker.session_json(), applied.session_json());
    assert_eq!(
        by_worker.document().models.len(),
        2,
        "spot beside the shape"
    );

    let before = by_worker.clone();
    let mut refused = by_worker.begin(import.clone()).unwrap();
    refused.supply_import(Err(CommandError::Elsewhere(String::from("Not today."))));
    assert_eq!(refused.step().unwrap_err().to_string(), "Not today.");
    assert_eq!(by_worker.document(), before.document());
    by_worker.begin(import).unwrap().cancel();
    assert_eq!(by_worker.document(), before.document());
    assert_eq!(by_worker.session_json(), before.session_json());
}

/// The page computes a curve op or an over-sketch in its worker from a copy of the models
/// (through the transfer buffer) and hands the changed model to the edit: every recorded
/// session, its curve ops and over-sketches landed that way, is the session replayed, bit
/// for bit, and the looks of an imported model stay shared with the model before. A refusal
/// handed over changes nothing.
#[test]
fn curve_ops_computed_elsewhere_land_as_the_applied_ones() {
    use sketchmesh_core::document::{Document, Session, model_op};
    use sketchmesh_core::io::{decode_changed, decode_models, encode_changed, encode_models};
    use std::sync::Arc;
    // What the worker does: decode the models, compute, encode the one changed; what the
    // page does: decode it, hand it over.
    let elsewhere = |models: &[Arc<sketchmesh_core::document::Model>], op: &Op| {
        let sent = encode_models(&models.iter().map(|m| &**m).collect::<Vec<_>>());
        let doc = Document {
            models: decode_models(&sent)
                .unwrap()
                .into_iter()
                .map(Arc::new)
                .collect(),
            ..Document::default()
        };
        model_op(&doc, op)
            .map(|(index, model)| decode_changed(&encode_changed(index, &model)).unwrap())
    };
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/sessions");
    let mut offloaded = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if !path.to_string_lossy().ends_with(".json") || path.ends_with("golden.json") {
            continue;
        }
        let json = std::fs::read_to_string(&path).unwrap();
        let mut editor = Editor::new();
        for op in Session::from_json(&json).unwrap().ops {
            let mut edit = editor.begin(op).unwrap();
            if let Some((models, op)) = edit.model_op_to_run() {
                let changed = elsewhere(models, op);
                let looks = changed
                    .as_ref()
                    .ok()
                    .map(|&(i, _)| (i, models[i].appearance.clone()));
                edit.supply_model(changed);
                assert!(edit.model_op_to_run().is_none(), "computed once");
                assert_eq!(edit.step().unwrap(), Progress::Done);
                if let Some((index, Some(looks))) = looks {
                    let after = edit.document().models[index].appearance.as_ref().unwrap();
                    assert!(
                        **after != *looks || Arc::ptr_eq(after, &looks),
                        "model {index}'s unchanged looks are shared again"
                    );
                }
                offloaded += 1;
            }
            edit.finish(&mut editor).unwrap();
        }
        let replayed = Editor::replay_json(&json).unwrap();
        assert_eq!(editor.document(), replayed.document(), "{}", path.display());
        assert_eq!(editor.session_json(), replayed.session_json());
    }
    assert!(offloaded >= 10, "only {offloaded} ops went elsewhere");

    let mut editor = Editor::new();
    editor
        .apply(Op::Create(circle(CENTRE, 120.0).into()))
        .unwrap();
    let before = editor.clone();
    let far = StrokeInput {
        stroke: vec![[20.0, 20.0, 0.5], [40.0, 30.0, 0.5]],
        ..circle(CENTRE, 120.0)
    };
    let mut refused = editor.begin(Op::Pull(far)).unwrap();
    let (models, op) = refused.model_op_to_run().unwrap();
    let answer = elsewhere(models, op);
    assert_eq!(answer.as_ref().unwrap_err(), &CommandError::NoCurveHere);
    refused.supply_model(answer);
    assert_eq!(refused.step().unwrap_err(), CommandError::NoCurveHere);
    assert_eq!(editor.document(), before.document());
    assert_eq!(editor.session_json(), before.session_json());
}

/// The page computes a pull's preview in its worker while the pointer moves: the worker's
/// edit follows the samples the page sends (one factorization for the whole drag), every
/// preview it hands back through the transfer buffer is the one a step here shows for the
/// same samples, bit for bit, a late one for fewer samples is ignored, and the drag commits
/// what `apply` makes.
#[test]
fn a_pull_previewed_elsewhere_shows_what_stepping_here_shows() {
    use sketchmesh_core::document::Edit;
    let mut editor = Editor::new();
    for make in &session()[1..3] {
        editor.apply(make(&editor)).unwrap();
    }
    let Op::Pull(drag) = session()[3](&editor) else {
        unreachable!("the fourth op is a pull")
    };
    let grab = Op::Pull(StrokeInput {
        stroke: drag.stroke[..1].to_vec(),
        ..drag.clone()
    });
    let mut here = editor.begin_gesture(grab.clone()).unwrap();
    let mut there = editor.begin_gesture(grab).unwrap();
    let mut worker: Option<Edit> = None;
    let mut followed = 1;
    for samples in [1, 4, 9, drag.stroke.len()] {
        for &sample in &drag.stroke[followed..samples] {
            here.extend(sample);
            there.extend(sample);
        }
        followed = samples;
        while here.step().unwrap() == Progress::Working {}
        preview_elsewhere(&mut there, &mut worker);
        assert!(there.preview_to_run().is_none(), "up to date");
        let generation = there.generation();
        assert_eq!(there.step().unwrap(), Progress::Waiting);
        assert_eq!(
            there.generation(),
            generation,
            "no step here once previewed there"
        );
        assert_eq!(there.moved_model(), here.moved_model(), "{samples} samples");
    }
    // Should the worker fail now, the frames take the preview back: the same as stepping here.
    let mut taken_back = editor.begin_gesture(Op::Pull(drag.clone())).unwrap();
    let mut gone: Option<Edit> = None;
    preview_elsewhere(&mut taken_back, &mut gone);
    taken_back.preview_here();
    assert!(
        taken_back.preview_to_run().is_some(),
        "asked again of a new worker"
    );
    let mut stepped = editor.begin_gesture(Op::Pull(drag.clone())).unwrap();
    for edit in [&mut taken_back, &mut stepped] {
        while edit.step().unwrap() == Progress::Working {}
    }
    assert!(taken_back.moved_model().is_some());
    assert_eq!(
        taken_back.moved_model(),
        stepped.moved_model(),
        "previewed here again"
    );
    let rest = editor.document().models[0].mesh.positions().to_vec();
    there.supply_preview(Ok(Previewed {
        version: 2,
        moved: Some((0, rest)),
        limited: None,
    }));
    assert_eq!(there.moved_model(), here.moved_model(), "an older preview");
    for edit in [&mut here, &mut there] {
        edit.end_gesture();
    }
    let mut applied = editor.clone();
    applied.apply(Op::Pull(drag)).unwrap();
    here.finish(&mut editor.clone()).unwrap();
    there.finish(&mut editor).unwrap();
    assert_eq!(editor.document(), applied.document());
}

/// The page computes an optimization's preview in its worker as its settings change: each
/// preview the worker's edit computes (its optimizer kept while it serves) is the one
/// stepping here shows, the commit comes from the worker's kept optimizer, and the document
/// is the op applied.
#[test]
fn an_optimization_previewed_elsewhere_commits_what_apply_makes() {
    use sketchmesh_core::document::Edit;
    let mut editor = Editor::new();
    editor.apply(session()[1](&editor)).unwrap();
    let settings = [(1.0, Mode::Smooth), (0.2, Mode::Smooth), (0.5, Mode::Shape)];
    let mut here = editor.begin_gesture(optimize(1.0, Mode::Smooth)).unwrap();
    let mut there = editor.begin_gesture(optimize(1.0, Mode::Smooth)).unwrap();
    let mut worker: Option<Edit> = None;
    for (k, &(scale, mode)) in settings.iter().enumerate() {
        let op = optimize(scale, mode);
        revise_here_and_there(k, op, [&mut here, &mut there], &mut worker);
        assert_eq!(there.moved_model(), here.moved_model(), "scale {scale}");
    }
    commit_elsewhere(there, worker, &mut editor);
    let mut applied = Editor::new();
    applied.apply(session()[1](&applied)).unwrap();
    applied.apply(optimize(0.5, Mode::Shape)).unwrap();
    assert_eq!(applied.document(), editor.document());
}

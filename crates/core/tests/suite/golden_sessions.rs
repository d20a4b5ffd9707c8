//! Recorded sessions replay to the very same documents: the guard for "what must not
//! change" while the core is refactored.
//!
//! `tests/fixtures/sessions/*.json` are sessions recorded with the editor (one file per
//! theme, together covering every kind of op in [`Op::NAMES`], which
//! [`every_op_kind_has_a_golden_session`] checks: create, ink stroke, pull, add_curve open,
//! closed and cross-section, erase, set_curve_type sharp and smooth, rub, over-sketch
//! automatic, manual with a picked silhouette or surface curve, soft fit and part ROI,
//! import of a .glb carried in the session, cut, tunnel, extrude, merge, transform,
//! duplicate, delete, optimize, sketch_feature, region_edit, the four handle ops, deform,
//! curve_deform, the three key frame ops, undo and redo). Each generator below checks that
//! its ops do what they should, and the replay checks that no op leaves the document as it
//! was. `golden.json` holds, per session, the
//! digest of the replayed document after every op ([`crate::common::digest`]: every position as
//! f64 bits, triangles, control curves, sketches), the digest of its integer structure, and
//! summary numbers per model; `<session>.positions.bin` holds the final positions (for
//! the deviation printed on a mismatch, and for the allowance below).
//!
//! A replay must match bit for bit. The only exception is [`ALLOWANCES`]: a session listed
//! there with the reason may differ by at most [`ALLOWED_DEVIATION`] of the bounding-box
//! diagonal in vertex positions (an order of floating-point operations that had to change),
//! with the same structure. The list is empty: nothing may move yet.
//!
//! The fixtures are frozen inputs. To record them again with the editor of the day (only
//! when the behaviour is meant to change, and saying so in the commit):
//!
//! - `UPDATE_GOLDEN=digests cargo test -p sketchmesh-core --test suite golden_sessions -- --ignored`
//!   rewrites `golden.json` and the positions from the existing session files
//!   (`GOLDEN_ONLY=name,name` limits that to the sessions named);
//! - `UPDATE_GOLDEN=sessions ...` also regenerates the session files with the generators
//!   below (their strokes are computed from the shapes of the day, so they may differ;
//!   `GOLDEN_ONLY` limits this too, as when a new session is added).

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a test failure.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::common::{
    Digest, ModelSummary, add_curve, circle, digest, import_document, import_mesh, longest_outline,
    outline, oversketch, pushed_stroke, quarter_bend, screen, segment, set_type, stroke_input,
    summary,
};
use glam::{DMat4, DVec2, DVec3};
use serde_json::{Value, json};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{
    CurveHandleInput, CurveKind, DeformHandleInput, DeformInput, DeformMethod, DeleteHandleInput,
    Document, DuplicateInput, Editor, FillInput, HandleEditInput, KeyframeInput, LinkHandlesInput,
    MaterialInput, MergeInput, ModelInput, Op, OptimizeInput, OversketchFit, PaintInput,
    PlaneInput, RegionEditInput, Session, SketchFeatureInput, StrokePairInput, SymmetrizeInput,
    TransformInput,
};
use sketchmesh_core::feature::FeatureKind;
use sketchmesh_core::mesh::{Mesh, VertexId, primitives};
use sketchmesh_core::model::{MirrorPlane, Side};
use sketchmesh_core::optimize::{OptimizeParams, quality_report};
use sketchmesh_core::oversketch::{ManualHandle, OutlineKind, OversketchRoi, pick_handle};
use sketchmesh_core::skeleton::HandleKind;
use sketchmesh_core::symmetry::{are_twins, partners};

/// Re-recorded on purpose: `import_created`'s golden, when control curves became chains of
/// vertices (issue 15). The import now turns the file's curve points into a vertex chain and
/// gives each vertex the file's f64 curve point (its buffer holds only f32), so that export,
/// import and export again give the same bytes; before, the imported curve kept the points
/// beside the f32 vertices, and later ops started from those.
///
/// Re-recorded on purpose: `closed_curve_and_rub`, `curve_tools` and `import_created`, when
/// curve embedding moved onto the one mutable mesh (issue 15, point 1). The curve is the same
/// (the same crossings, vertices and positions), but the old private triangle list kept the
/// other half of a split edge's second triangle in place and rotated the split triangles'
/// corners, so the faces come out in another order; the remesh that follows every add-curve
/// visits edges in face order, so its splits, collapses and flips, and the vertex count,
/// differ from then on (by under 0.5% of the vertices). Sessions without an added curve replay
/// bit for bit through the ported remesher. Every other golden is the one recorded with the
/// code before the refactor.
///
/// Re-recorded on purpose: `oversketch_created`, `oversketch_imported` and
/// `oversketch_part_roi`, when over-sketching was made to land the rendered outline on the
/// stroke without seams (issue 19): the outline's vertices are snapped onto the stroke after
/// the bend, the ends blend with a smoothstep over at least 20 px, the near-handle region
/// reaches at least three edges and never 150 px past the stroke, a created model's
/// control curve is moved and the surface settled instead of the mesh bent, and a manual
/// handle drawn on the surface is embedded in the mesh as a feature sketch is.
///
/// Re-recorded on purpose: `closed_curve_and_rub`, `curve_tools` and `import_created`, when
/// a curve op's remesh and settle came to be followed by a tidy-up of poor triangles
/// (issue 23: Laplacian mesh optimization after sketch operations, with curve vertices
/// sliding along their curves). The worst radius ratio after their add-curve ops rose from
/// 0.249, 0.034, 0.213 and 0.062 to 0.345, 0.345, 0.354 and 0.525; sessions without a poor
/// triangle after a curve op replay as before.
///
/// Re-recorded on purpose: the same three, when the tidy-up came to move only the vertices
/// within eight rings of the poor triangles instead of the whole remeshed region (it took
/// 0.65 s of a 0.9 s pull at 40k vertices). The worst radius ratios after the add-curve ops
/// stayed 0.338 and 0.344 (to the fifth digit).
/// Sessions allowed to differ slightly from their golden, each with the reason: an entry
/// needs a refactor that had to reorder floating-point operations, named here.
const ALLOWANCES: &[(&str, &str)] = &[];

/// The largest vertex deviation an allowance accepts, relative to the model's bounding-box
/// diagonal.
const ALLOWED_DEVIATION: f64 = 1e-12;

fn fixture_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/sessions")
}

fn hex(value: u64) -> String {
    format!("{value:016x}")
}

/// Replays a session op by op, with the digest after each op.
fn replay(json: &str) -> (Editor, Vec<Digest>) {
    let session = Session::from_json(json).unwrap();
    let mut editor = Editor::new();
    let mut digests = Vec::with_capacity(session.ops.len());
    for (index, op) in session.ops.into_iter().enumerate() {
        let name = op.name();
        editor
            .apply(op)
            .unwrap_or_else(|error| panic!("op {index} ({name}) refused: {error}"));
        digests.push(digest(editor.document()));
    }
    // The one-call replay is the same thing.
    let whole = Editor::replay_json(json).unwrap();
    assert_eq!(digest(whole.document()), digest(editor.document()));
    (editor, digests)
}

fn summary_json(summary: &ModelSummary) -> Value {
    json!({
        "vertices": summary.vertices,
        "faces": summary.faces,
        "curves": summary.curves,
        "diagonal": summary.diagonal,
        "centroid": summary.centroid.to_array(),
    })
}

fn golden_entry(document: &Document, digests: &[Digest]) -> Value {
    let last = digests.last().copied().unwrap_or(digest(document));
    json!({
        "ops": digests.len(),
        "digest": hex(last.full),
        "topology": hex(last.topology),
        "op_digests": digests.iter().map(|d| hex(d.full)).collect::<Vec<_>>(),
        "models": document.models.iter().map(|m| summary_json(&summary(m))).collect::<Vec<_>>(),
        "sketches": document.sketches.len(),
        "point_clouds": document.point_clouds.len(),
    })
}

/// Final positions: per model its vertex count (u64) and its coordinates (f64), little
/// endian.
fn positions_bytes(document: &Document) -> Vec<u8> {
    let mut out = Vec::new();
    out.extend((document.models.len() as u64).to_le_bytes());
    for model in &document.models {
        let positions = model.mesh.positions();
        out.extend((positions.len() as u64).to_le_bytes());
        for p in positions {
            for c in p.to_array() {
                out.extend(c.to_le_bytes());
            }
        }
    }
    out
}

fn positions_from_bytes(bytes: &[u8]) -> Vec<Vec<DVec3>> {
    let mut words = bytes
        .chunks_exact(8)
        .map(|c| <[u8; 8]>::try_from(c).unwrap());
    let mut next = || words.next().expect("positions file too short");
    let n_models = u64::from_le_bytes(next());
    (0..n_models)
        .map(|_| {
            let n = u64::from_le_bytes(next());
            (0..n)
                .map(|_| {
                    let mut c = [0.0; 3];
                    for x in &mut c {
                        *x = f64::from_le_bytes(next());
                    }
                    DVec3::from_array(c)
                })
                .collect()
        })
        .collect()
}

fn session_names() -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(fixture_dir())
        .unwrap()
        .map(|entry| entry.unwrap().path())
        .filter(|path| path.extension().is_some_and(|e| e == "json"))
        .filter_map(|path| path.file_stem().map(|s| s.to_string_lossy().into_owned()))
        .filter(|name| name != "golden")
        .collect();
    names.sort();
    names
}

fn read_golden() -> BTreeMap<String, Value> {
    let text = std::fs::read_to_string(fixture_dir().join("golden.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

/// Compares one replayed session with its golden; `Err` describes the difference.
fn check(
    name: &str,
    golden: &Value,
    document: &Document,
    digests: &[Digest],
) -> Result<(), String> {
    let expected_ops: Vec<&str> = golden["op_digests"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| d.as_str().unwrap())
        .collect();
    let actual_ops: Vec<String> = digests.iter().map(|d| hex(d.full)).collect();
    let last = digests.last().copied().unwrap_or(digest(document));
    if hex(last.full) == golden["digest"] && actual_ops == expected_ops {
        return Ok(());
    }
    let mut report = format!("session {name}: the replayed document differs from its golden\n");
    if let Some(k) =
        (0..expected_ops.len().min(actual_ops.len())).find(|&k| expected_ops[k] != actual_ops[k])
    {
        report += &format!("  first differing document: after op {k}\n");
    }
    if expected_ops.len() != actual_ops.len() {
        report += &format!(
            "  ops: golden {}, replayed {}\n",
            expected_ops.len(),
            actual_ops.len()
        );
    }
    let topology_same = hex(last.topology) == golden["topology"];
    report += &format!("  structure (counts, triangles, curve chains) same: {topology_same}\n");
    let expected_models = golden["models"].as_array().unwrap();
    report += &format!(
        "  models: golden {}, replayed {}; sketches golden {}, replayed {}\n",
        expected_models.len(),
        document.models.len(),
        golden["sketches"],
        document.sketches.len()
    );
    let reference = std::fs::read(fixture_dir().join(format!("{name}.positions.bin")))
        .ok()
        .map(|bytes| positions_from_bytes(&bytes));
    let mut worst_relative: f64 = 0.0;
    let mut comparable = topology_same && expected_models.len() == document.models.len();
    for (k, model) in document.models.iter().enumerate() {
        let actual = summary(model);
        report += &format!("  model {k}: replayed {}\n", summary_json(&actual));
        if let Some(expected) = expected_models.get(k) {
            report += &format!("  model {k}: golden   {expected}\n");
        }
        let reference = reference.as_ref().and_then(|r| r.get(k));
        match reference {
            Some(reference) if reference.len() == actual.vertices => {
                let deviation = reference
                    .iter()
                    .zip(model.mesh.positions())
                    .map(|(a, b)| a.distance(*b))
                    .fold(0.0, f64::max);
                let relative = deviation / diagonal_or_one(reference);
                worst_relative = worst_relative.max(relative);
                report += &format!(
                    "  model {k}: max vertex deviation {deviation:.3e} = {relative:.3e} of the diagonal\n"
                );
            }
            _ => comparable = false,
        }
    }
    if let Some((_, why)) = ALLOWANCES.iter().find(|(session, _)| *session == name) {
        if comparable && worst_relative <= ALLOWED_DEVIATION {
            eprintln!("{report}  accepted by its allowance ({why})");
            return Ok(());
        }
        report += &format!(
            "  its allowance ({why}) covers deviations up to {ALLOWED_DEVIATION:e} of the diagonal with the same structure only\n"
        );
    }
    Err(report)
}

fn diagonal_or_one(positions: &[DVec3]) -> f64 {
    let d = crate::common::diagonal(positions);
    if d > 0.0 { d } else { 1.0 }
}

#[test]
fn recorded_sessions_replay_bit_for_bit() {
    let golden = read_golden();
    let names = session_names();
    assert!(names.len() >= 6, "fixtures missing: {names:?}");
    for (session, why) in ALLOWANCES {
        assert!(
            names.iter().any(|n| n == session) && !why.trim().is_empty(),
            "allowance for {session} must name a session and say why"
        );
    }
    let mut failures = Vec::new();
    for name in &names {
        let start = Instant::now();
        let json = std::fs::read_to_string(fixture_dir().join(format!("{name}.json"))).unwrap();
        let (editor, digests) = replay(&json);
        // Read and written again, the session is the same text.
        assert_eq!(Session::from_json(&json).unwrap().to_json(), json, "{name}");
        assert_eq!(editor.session_json(), json, "{name}");
        let golden = golden
            .get(name)
            .unwrap_or_else(|| panic!("{name} has no golden entry"));
        eprintln!(
            "{name}: {} ops replayed in {:.0} ms",
            digests.len(),
            start.elapsed().as_secs_f64() * 1e3
        );
        if let Err(report) = check(name, golden, editor.document(), &digests) {
            failures.push(report);
        }
        // A golden shows what its ops do: none of them leaves the document as it was.
        let mut before = digest(&Document::default());
        for (k, after) in digests.iter().enumerate() {
            if after.full == before.full {
                failures.push(format!("session {name}: op {k} changes nothing"));
            }
            before = *after;
        }
    }
    assert!(
        golden.keys().all(|k| names.contains(k)),
        "golden.json has entries without a session file"
    );
    assert!(failures.is_empty(), "\n{}", failures.join("\n"));
}

/// The sample sessions beside the browser suite (`tests/fixtures`, the ones the CLI and the
/// page replay; written by hand, so `0` where the app writes `0.0`) are read back from what
/// they write as the same ops, and that text writes itself again.
#[test]
fn the_sample_sessions_round_trip() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/fixtures");
    let mut checked = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        let text = std::fs::read_to_string(&path).unwrap();
        if !text.starts_with(r#"{"format":"sketchmesh-session""#) {
            continue;
        }
        let session = Session::from_json(&text).unwrap();
        let written = session.to_json();
        let again = Session::from_json(&written).unwrap();
        assert_eq!(again, session, "{}", path.display());
        assert_eq!(again.to_json(), written, "{}", path.display());
        checked += 1;
    }
    assert!(checked >= 3, "only {checked} sample sessions");
}

/// Every kind of op in [`Op::NAMES`] is replayed by some golden session, and each op of a
/// session is written with its name as its `"op"` tag.
#[test]
fn every_op_kind_has_a_golden_session() {
    let mut covered: BTreeMap<&str, Vec<String>> = BTreeMap::new();
    for name in session_names() {
        let json = std::fs::read_to_string(fixture_dir().join(format!("{name}.json"))).unwrap();
        let written: Value = serde_json::from_str(&json).unwrap();
        let session = Session::from_json(&json).unwrap();
        for (op, written) in session.ops.iter().zip(written["ops"].as_array().unwrap()) {
            assert_eq!(written["op"], op.name(), "{name}: an op tagged otherwise");
            covered.entry(op.name()).or_default().push(name.clone());
        }
    }
    for (op, sessions) in &mut covered {
        sessions.dedup();
        eprintln!("{op:>16}: {}", sessions.join(", "));
    }
    let missing: Vec<&str> = (Op::NAMES.iter().copied())
        .filter(|op| !covered.contains_key(op))
        .collect();
    assert!(
        missing.is_empty(),
        "ops without a golden session: {missing:?}"
    );
}

/// The digest sees what it must: a one-ulp move of one coordinate, a flipped curve kind.
#[test]
fn the_digest_notices_one_ulp() {
    let json = std::fs::read_to_string(fixture_dir().join("curve_tools.json")).unwrap();
    let editor = Editor::replay_json(&json).unwrap();
    let document = editor.document().clone();
    let base = digest(&document);
    let mut moved = document.clone();
    let mut model = (*moved.models[0]).clone();
    let p = &mut model.mesh.positions_mut()[7];
    p.y = f64::from_bits(p.y.to_bits() + 1);
    moved.models[0] = std::sync::Arc::new(model);
    let d = digest(&moved);
    assert_ne!(d.full, base.full);
    assert_eq!(d.topology, base.topology);
    let mut flipped = document.clone();
    let mut model = (*flipped.models[0]).clone();
    model.curves[0].kind = match model.curves[0].kind {
        CurveKind::Smooth => CurveKind::Sharp,
        CurveKind::Sharp => CurveKind::Smooth,
    };
    flipped.models[0] = std::sync::Arc::new(model);
    assert_ne!(digest(&flipped).topology, base.topology);
}

// ---------------------------------------------------------------------------------------
// Recording
// ---------------------------------------------------------------------------------------

#[test]
#[ignore = "records the fixtures; run with UPDATE_GOLDEN=digests or UPDATE_GOLDEN=sessions"]
fn write_golden() {
    let mode = std::env::var("UPDATE_GOLDEN").unwrap_or_default();
    assert!(
        mode == "digests" || mode == "sessions",
        "set UPDATE_GOLDEN=digests (golden from the session files) or UPDATE_GOLDEN=sessions \
         (regenerate the session files too)"
    );
    let dir = fixture_dir();
    std::fs::create_dir_all(&dir).unwrap();
    // `GOLDEN_ONLY=a,b` re-records only those sessions and keeps the others' goldens.
    let only = std::env::var("GOLDEN_ONLY").ok();
    let is_chosen = |name: &str| {
        only.as_ref()
            .is_none_or(|o| o.split(',').any(|n| n == name))
    };
    if mode == "sessions" {
        for (name, generate) in generators().into_iter().filter(|(n, _)| is_chosen(n)) {
            let editor = generate();
            std::fs::write(dir.join(format!("{name}.json")), editor.session_json()).unwrap();
            eprintln!("wrote {name}.json ({} ops)", editor.ops().len());
        }
    }
    let mut golden: BTreeMap<String, Value> = match std::fs::read_to_string(dir.join("golden.json"))
    {
        Ok(text) if only.is_some() => serde_json::from_str(&text).unwrap(),
        _ => BTreeMap::new(),
    };
    for name in session_names().into_iter().filter(|n| is_chosen(n)) {
        let json = std::fs::read_to_string(dir.join(format!("{name}.json"))).unwrap();
        let (editor, digests) = replay(&json);
        // A replay of the replay gives the same file: the session is stable.
        assert_eq!(editor.session_json(), json, "{name} does not print back");
        golden.insert(name.clone(), golden_entry(editor.document(), &digests));
        std::fs::write(
            dir.join(format!("{name}.positions.bin")),
            positions_bytes(editor.document()),
        )
        .unwrap();
    }
    let mut text = serde_json::to_string_pretty(&golden).unwrap();
    text.push('\n');
    std::fs::write(dir.join("golden.json"), text).unwrap();
}

/// The points of the first model's curve `index`.
fn curve_points(editor: &Editor, index: usize) -> Vec<DVec3> {
    let model = &editor.document().models[0];
    model.curves[index].points(&model.mesh)
}

type Generator = fn() -> Editor;

fn generators() -> Vec<(&'static str, Generator)> {
    vec![
        ("create_and_ink", create_and_ink),
        ("curve_tools", curve_tools),
        ("closed_curve_and_rub", closed_curve_and_rub),
        ("oversketch_created", oversketch_created),
        ("oversketch_imported", oversketch_imported),
        ("oversketch_part_roi", oversketch_part_roi),
        ("import_created", import_created),
        ("cut_tunnel_extrude", cut_tunnel_extrude),
        ("arrange_and_merge", arrange_and_merge),
        ("optimize_feature_region", optimize_feature_region),
        ("curve_handles", curve_handles),
        ("deform_and_keyframes", deform_and_keyframes),
        ("symmetric_modelling", symmetric_modelling),
        ("painted", painted),
    ]
}

const VIEWPORT: DVec2 = DVec2::new(800.0, 600.0);
const CENTRE: DVec2 = DVec2::new(400.0, 300.0);
/// The over-sketch tests' square view.
const SQUARE: DVec2 = DVec2::new(1000.0, 1000.0);

fn apply(editor: &mut Editor, op: Op) {
    let name = op.name();
    editor
        .apply(op)
        .unwrap_or_else(|error| panic!("recording a {name} op: {error}"));
}

fn create(points: &[DVec2], camera: Camera) -> Op {
    Op::Create(stroke_input(VIEWPORT, camera, points).into())
}

/// Deterministic wobble, as a hand adds to a stroke.
fn wobbly(points: &[DVec2], amplitude: f64) -> Vec<DVec2> {
    points
        .iter()
        .enumerate()
        .map(|(i, &p)| {
            let i = i as f64;
            p + amplitude * DVec2::new((0.7 * i).sin(), (1.3 * i).cos())
        })
        .collect()
}

fn tilted() -> Camera {
    Camera {
        eye: DVec3::new(3.0, 1.5, 3.8),
        ..Camera::default()
    }
}

/// A stroke along a curve's screen projection.
fn along(points: &[DVec3], camera: &Camera, viewport: DVec2) -> Vec<DVec2> {
    points
        .iter()
        .filter_map(|&p| screen(camera, viewport, p))
        .collect()
}

/// Ink strokes and three creations (a circle, a tilted ellipse seen from an oblique camera,
/// a wavy blob drawn by hand), undone and redone, a new stroke dropping the redo.
fn create_and_ink() -> Editor {
    let mut editor = Editor::new();
    let camera = Camera::default();
    apply(
        &mut editor,
        Op::Stroke(stroke_input(
            VIEWPORT,
            camera,
            &wobbly(
                &segment(DVec2::new(60.0, 80.0), DVec2::new(300.0, 120.0)),
                1.5,
            ),
        )),
    );
    apply(
        &mut editor,
        create(&circle(DVec2::new(250.0, 300.0), 110.0), camera),
    );
    apply(
        &mut editor,
        create(
            &outline(DVec2::new(560.0, 260.0), 120.0, &[], 0.55, 0.4, 120),
            tilted(),
        ),
    );
    apply(
        &mut editor,
        create(
            &wobbly(
                &outline(
                    DVec2::new(420.0, 430.0),
                    90.0,
                    &[(3, 0.08, 0.5), (5, 0.05, 1.0)],
                    0.8,
                    0.3,
                    160,
                ),
                0.6,
            ),
            camera,
        ),
    );
    apply(&mut editor, Op::Undo);
    apply(&mut editor, Op::Undo);
    apply(&mut editor, Op::Redo);
    apply(
        &mut editor,
        Op::Stroke(stroke_input(
            VIEWPORT,
            tilted(),
            &segment(DVec2::new(100.0, 500.0), DVec2::new(700.0, 540.0)),
        )),
    );
    assert!(!editor.can_redo());
    apply(&mut editor, Op::Undo);
    apply(&mut editor, Op::Redo);
    editor
}

/// The curve tools on one shape: an open curve added, pulled, a cross-section loop, the
/// outline made sharp then smooth again, the added curve erased; undo, redo.
fn curve_tools() -> Editor {
    let camera = Camera::default();
    let mut editor = Editor::new();
    apply(&mut editor, create(&circle(CENTRE, 150.0), camera));
    let across = segment(CENTRE - DVec2::X * 90.0, CENTRE + DVec2::X * 90.0);
    apply(
        &mut editor,
        add_curve(VIEWPORT, camera, &across, false, false),
    );
    let points = curve_points(&editor, 1);
    let middle = screen(&camera, VIEWPORT, points[points.len() / 2]).unwrap();
    apply(
        &mut editor,
        Op::Pull(stroke_input(
            VIEWPORT,
            camera,
            &segment(middle, middle + DVec2::new(0.0, -40.0)),
        )),
    );
    let cross = segment(
        CENTRE + DVec2::new(-40.0, -200.0),
        CENTRE + DVec2::new(-40.0, 200.0),
    );
    apply(
        &mut editor,
        add_curve(VIEWPORT, camera, &cross, false, true),
    );
    let outline_points = curve_points(&editor, 0);
    let outline_stroke = along(&outline_points, &camera, VIEWPORT);
    apply(
        &mut editor,
        set_type(VIEWPORT, camera, &outline_stroke, true),
    );
    let outline_points = curve_points(&editor, 0);
    apply(
        &mut editor,
        set_type(
            VIEWPORT,
            camera,
            &along(&outline_points, &camera, VIEWPORT),
            false,
        ),
    );
    let added = curve_points(&editor, 1);
    apply(
        &mut editor,
        Op::Erase(stroke_input(
            VIEWPORT,
            camera,
            &along(&added, &camera, VIEWPORT),
        )),
    );
    apply(&mut editor, Op::Undo);
    apply(&mut editor, Op::Redo);
    editor
}

/// A closed curve on a shape, a wobbly open one rubbed with one and three passes, the
/// outline pulled out sideways from an oblique view.
fn closed_curve_and_rub() -> Editor {
    let camera = Camera::default();
    let mut editor = Editor::new();
    apply(&mut editor, create(&circle(CENTRE, 150.0), camera));
    apply(
        &mut editor,
        add_curve(
            VIEWPORT,
            camera,
            &circle(CENTRE + DVec2::new(20.0, 30.0), 50.0),
            true,
            false,
        ),
    );
    let wavy: Vec<DVec2> = (0..=60)
        .map(|i| {
            let x = -90.0 + 3.0 * f64::from(i);
            CENTRE + DVec2::new(x, -70.0 + 6.0 * (f64::from(i) * 1.3).sin())
        })
        .collect();
    apply(
        &mut editor,
        add_curve(VIEWPORT, camera, &wavy, false, false),
    );
    let (a, b) = (
        CENTRE + DVec2::new(-60.0, -70.0),
        CENTRE + DVec2::new(60.0, -70.0),
    );
    apply(
        &mut editor,
        Op::Rub(stroke_input(VIEWPORT, camera, &segment(a, b))),
    );
    let mut passes = segment(a, b);
    passes.extend(segment(b, a));
    passes.extend(segment(a, b));
    apply(
        &mut editor,
        Op::Rub(stroke_input(VIEWPORT, camera, &passes)),
    );
    let outline_points = curve_points(&editor, 0);
    let right = outline_points
        .iter()
        .copied()
        .max_by(|p, q| p.x.total_cmp(&q.x))
        .unwrap();
    let oblique = Camera {
        eye: DVec3::new(1.5, 1.0, 4.6),
        ..Camera::default()
    };
    let start = screen(&oblique, VIEWPORT, right).unwrap();
    apply(
        &mut editor,
        Op::Pull(stroke_input(
            VIEWPORT,
            oblique,
            &segment(start, start + DVec2::new(60.0, -15.0)),
        )),
    );
    apply(&mut editor, Op::Undo);
    editor
}

/// A created shape over-sketched automatically (exact, then soft on the other side), undo
/// and redo.
fn oversketch_created() -> Editor {
    let camera = Camera::default();
    let mut editor = Editor::new();
    let circle_points: Vec<DVec2> = circle(SQUARE / 2.0, 180.0);
    apply(
        &mut editor,
        Op::Create(stroke_input(SQUARE, camera, &circle_points).into()),
    );
    let mesh = editor.document().models[0].mesh.clone();
    let outline = longest_outline(&mesh, &camera, SQUARE).unwrap();
    let stroke = pushed_stroke(&outline, DVec2::X, 25, 30.0);
    let exact = OversketchFit::Exact;
    let near = OversketchRoi::NearHandle;
    apply(
        &mut editor,
        oversketch(SQUARE, camera, &stroke, exact, near, None),
    );
    let mesh = editor.document().models[0].mesh.clone();
    let outline = longest_outline(&mesh, &camera, SQUARE).unwrap();
    let stroke = pushed_stroke(&outline, DVec2::new(-0.6, -0.8), 25, 25.0);
    apply(
        &mut editor,
        oversketch(SQUARE, camera, &stroke, OversketchFit::Soft, near, None),
    );
    apply(&mut editor, Op::Undo);
    apply(&mut editor, Op::Redo);
    editor
}

/// An imported sphere over-sketched automatically, then with a picked silhouette piece,
/// then with a picked surface curve; undo and redo.
fn oversketch_imported() -> Editor {
    let camera = Camera::default();
    let mut editor = Editor::new();
    apply(
        &mut editor,
        import_mesh("sphere.glb", &primitives::icosphere(1.0, 3)),
    );
    let mesh = editor.document().models[0].mesh.clone();
    let outline = longest_outline(&mesh, &camera, SQUARE).unwrap();
    let stroke = pushed_stroke(&outline, DVec2::new(0.6, -0.8), 30, 40.0);
    let (exact, near) = (OversketchFit::Exact, OversketchRoi::NearHandle);
    apply(
        &mut editor,
        oversketch(SQUARE, camera, &stroke, exact, near, None),
    );

    let mesh = editor.document().models[0].mesh.clone();
    let outline = longest_outline(&mesh, &camera, SQUARE).unwrap();
    let on_outline = pushed_stroke(&outline, DVec2::NEG_X, 20, 0.0);
    let handle = pick_handle(&mesh, &camera, SQUARE, &on_outline, OutlineKind::Smooth).unwrap();
    assert!(
        matches!(handle, ManualHandle::Silhouette { .. }),
        "{handle:?}"
    );
    let stroke = pushed_stroke(&outline, DVec2::NEG_X, 20, 30.0);
    apply(
        &mut editor,
        oversketch(SQUARE, camera, &stroke, exact, near, Some(handle)),
    );

    let centre = SQUARE / 2.0;
    let line = |dy: f64| -> Vec<DVec2> {
        (0..=50)
            .map(|k| centre + DVec2::new(-100.0 + 4.0 * f64::from(k), dy))
            .collect()
    };
    let mesh = editor.document().models[0].mesh.clone();
    let handle = pick_handle(&mesh, &camera, SQUARE, &line(40.0), OutlineKind::Smooth).unwrap();
    assert!(matches!(handle, ManualHandle::Surface { .. }), "{handle:?}");
    apply(
        &mut editor,
        oversketch(
            SQUARE,
            camera,
            &line(15.0),
            OversketchFit::Soft,
            near,
            Some(handle),
        ),
    );
    apply(&mut editor, Op::Undo);
    apply(&mut editor, Op::Undo);
    apply(&mut editor, Op::Redo);
    editor
}

/// A horned sphere (a horn a little wider than `oversketch_pipeline.rs`'s, since at
/// subdivision 4, which keeps the file small, the thinner one does not stand out) imported
/// and its horn bent by an over-sketch with the part ROI.
fn oversketch_part_roi() -> Editor {
    let camera = Camera::default();
    let mut editor = Editor::new();
    apply(
        &mut editor,
        import_mesh("horned.glb", &primitives::horned_sphere(4, 1.2, 0.3)),
    );
    let mesh = editor.document().models[0].mesh.clone();
    let outline = longest_outline(&mesh, &camera, SQUARE).unwrap();
    let stroke = pushed_stroke(&outline, DVec2::X, 20, 60.0);
    apply(
        &mut editor,
        oversketch(
            SQUARE,
            camera,
            &stroke,
            OversketchFit::Exact,
            OversketchRoi::Part,
            None,
        ),
    );
    editor
}

/// A created shape with a sketch, exported and imported into a new document (curves and
/// sketch come back), its imported outline pulled and a curve added on it.
fn import_created() -> Editor {
    let camera = Camera::default();
    let mut source = Editor::new();
    apply(
        &mut source,
        Op::Stroke(stroke_input(
            VIEWPORT,
            camera,
            &segment(DVec2::new(100.0, 100.0), DVec2::new(300.0, 140.0)),
        )),
    );
    apply(
        &mut source,
        create(&outline(CENTRE, 140.0, &[], 0.7, 0.2, 100), camera),
    );
    let mut editor = Editor::new();
    apply(&mut editor, import_document("shape.glb", source.document()));
    let model = editor.document().models[0].clone();
    assert!(!model.curves.is_empty() && !model.curves[0].vertices.is_empty());
    let top = model.curves[0]
        .points(&model.mesh)
        .into_iter()
        .max_by(|p, q| p.y.total_cmp(&q.y))
        .unwrap();
    let start = screen(&camera, VIEWPORT, top).unwrap();
    apply(
        &mut editor,
        Op::Pull(stroke_input(
            VIEWPORT,
            camera,
            &segment(start, start + DVec2::new(10.0, -45.0)),
        )),
    );
    let across = segment(
        CENTRE + DVec2::new(-80.0, 20.0),
        CENTRE + DVec2::new(80.0, 10.0),
    );
    apply(
        &mut editor,
        add_curve(VIEWPORT, camera, &across, false, false),
    );
    editor
}

/// How far a mesh reaches on screen in `direction`: the largest `direction · pixel`.
fn screen_extent(mesh: &Mesh, camera: &Camera, direction: DVec2) -> f64 {
    (mesh.positions().iter())
        .filter_map(|&p| screen(camera, VIEWPORT, p))
        .map(|pixel| pixel.dot(direction))
        .fold(f64::MIN, f64::max)
}

/// A created shape drilled through by a tunnel (loops drawn front and back), grown a limb by
/// an extrusion on its right, and cut on its left; undo and redo.
fn cut_tunnel_extrude() -> Editor {
    let camera = Camera::default();
    let behind = Camera {
        eye: DVec3::new(0.0, 0.0, -5.0),
        ..Camera::default()
    };
    let mut editor = Editor::new();
    apply(&mut editor, create(&circle(CENTRE, 150.0), camera));
    let ring = |camera: Camera| stroke_input(VIEWPORT, camera, &circle(CENTRE, 40.0));
    apply(
        &mut editor,
        Op::Tunnel(StrokePairInput {
            strokes: [ring(camera), ring(behind)],
        }),
    );
    assert_eq!(editor.document().models[0].mesh.genus(), Some(1));

    let base_centre = CENTRE + DVec2::new(95.0, 0.0);
    let silhouette: Vec<DVec2> = (0..=60)
        .map(|i| {
            let a = std::f64::consts::PI * (f64::from(i) / 60.0 - 0.5);
            base_centre + DVec2::new(150.0 * a.cos(), 25.0 * a.sin())
        })
        .collect();
    let curves = editor.document().models[0].curves.len();
    apply(
        &mut editor,
        Op::Extrude(StrokePairInput {
            strokes: [
                stroke_input(VIEWPORT, camera, &circle(base_centre, 25.0)),
                stroke_input(VIEWPORT, camera, &silhouette),
            ],
        }),
    );
    let model = &editor.document().models[0];
    assert_eq!(
        model.curves.len(),
        curves + 2,
        "a base loop and a limb outline"
    );
    let reach = screen_extent(&model.mesh, &camera, DVec2::X) - base_centre.x;
    assert!(reach > 120.0, "the limb reaches {reach} px out of its base");

    let x = CENTRE.x - 90.0;
    apply(
        &mut editor,
        Op::Cut(stroke_input(
            VIEWPORT,
            camera,
            &segment(DVec2::new(x, 40.0), DVec2::new(x, 560.0)),
        )),
    );
    let model = &editor.document().models[0];
    let rim = model.curves.last().unwrap();
    assert!(
        rim.is_closed && rim.is_sharp(),
        "the cut's cap has a sharp rim"
    );
    let past = screen_extent(&model.mesh, &camera, DVec2::NEG_X) + x;
    assert!(past < 0.05, "a vertex lies {past} px past the cut");
    apply(&mut editor, Op::Undo);
    apply(&mut editor, Op::Redo);
    editor
}

/// Two overlapping shapes merged into one, the merged one duplicated, the copy turned and
/// moved aside, the original deleted; undo.
fn arrange_and_merge() -> Editor {
    let camera = Camera::default();
    let mut editor = Editor::new();
    apply(&mut editor, create(&circle(CENTRE, 150.0), camera));
    apply(
        &mut editor,
        create(&circle(CENTRE + DVec2::new(300.0, 0.0), 100.0), camera),
    );
    let at = |x: f64| {
        camera
            .point_on_target_plane(CENTRE + DVec2::new(x, 0.0), VIEWPORT)
            .unwrap()
    };
    // 60 px of overlap.
    apply(
        &mut editor,
        Op::Transform(TransformInput {
            model: 1,
            matrix: DMat4::from_translation(at(190.0) - at(300.0)).to_cols_array(),
        }),
    );
    apply(&mut editor, Op::Merge(MergeInput { models: [1, 0] }));
    assert_eq!(editor.document().models.len(), 1, "the two became one");
    apply(
        &mut editor,
        Op::Duplicate(DuplicateInput {
            model: 0,
            beside: None,
        }),
    );
    let models = &editor.document().models;
    assert_eq!(models[1].mesh.n_vertices(), models[0].mesh.n_vertices());
    let copied = models[1].mesh.position(VertexId(0));
    let turn = DMat4::from_translation(DVec3::new(0.5, 1.0, -1.0))
        * DMat4::from_rotation_y(0.6)
        * DMat4::from_scale(DVec3::splat(0.8));
    apply(
        &mut editor,
        Op::Transform(TransformInput {
            model: 1,
            matrix: turn.to_cols_array(),
        }),
    );
    let moved = &editor.document().models[1].mesh;
    let expected = turn.transform_point3(copied);
    assert!(moved.position(VertexId(0)).distance(expected) < 1e-12);
    apply(&mut editor, Op::Delete(ModelInput { model: 0 }));
    assert_eq!(editor.document().models.len(), 1);
    apply(&mut editor, Op::Undo);
    editor
}

/// How many vertices of `after` lie off every vertex of `before` (moved, or made by an
/// op that splits the surface), and the largest such distance.
fn moved_vertices(before: &Mesh, after: &Mesh) -> (usize, f64) {
    let moves: Vec<f64> = (after.positions().iter())
        .map(|p| {
            (before.positions().iter())
                .map(|q| p.distance(*q))
                .fold(f64::INFINITY, f64::min)
        })
        .filter(|&d| d > 1e-9)
        .collect();
    (moves.len(), moves.iter().copied().fold(0.0, f64::max))
}

/// A scan-like sphere (its vertices jittered) evened out by mesh optimization, a ridge
/// sketched across it, then a region around a reference curve lifted and turned.
fn optimize_feature_region() -> Editor {
    let camera = Camera::default();
    let mut editor = Editor::new();
    let mut sphere = primitives::icosphere(1.0, 3);
    for (k, p) in sphere.positions_mut().iter_mut().enumerate() {
        let k = k as f64;
        *p += 0.02 * DVec3::new((1.7 * k).sin(), (2.3 * k).cos(), (0.9 * k).sin());
    }
    apply(&mut editor, import_mesh("rough.glb", &sphere));
    let rough = editor.document().models[0].mesh.clone();
    apply(
        &mut editor,
        Op::Optimize(OptimizeInput {
            model: 0,
            settings: OptimizeParams::default(),
            region: None,
            painted: Vec::new(),
            painted_features: Vec::new(),
        }),
    );
    let report = quality_report(&rough, editor.document().models[0].mesh.positions());
    assert!(
        report.mean_radius_ratio > report.input_mean_radius_ratio,
        "the triangles got better: {report:?}"
    );

    let centre = screen(&camera, SQUARE, DVec3::ZERO).unwrap();
    let before = editor.document().models[0].mesh.clone();
    let ridge = stroke_input(
        SQUARE,
        camera,
        &segment(
            centre - DVec2::new(120.0, 0.0),
            centre + DVec2::new(120.0, 0.0),
        ),
    );
    apply(
        &mut editor,
        Op::SketchFeature(SketchFeatureInput {
            viewport: ridge.viewport,
            camera,
            stroke: ridge.stroke,
            kind: FeatureKind::Ridge,
            amount: Some(3.0),
            region: None,
        }),
    );
    let (moved, farthest) = moved_vertices(&before, &editor.document().models[0].mesh);
    assert!(
        moved > 8 && moved < before.n_vertices() / 4 && farthest > 0.01,
        "a ridge along the sketch: {moved} vertices moved, up to {farthest}"
    );

    let before = editor.document().models[0].mesh.clone();
    let reference = stroke_input(
        SQUARE,
        camera,
        &segment(
            centre + DVec2::new(-60.0, -100.0),
            centre + DVec2::new(60.0, -100.0),
        ),
    );
    let mut ring = circle(centre - DVec2::new(0.0, 100.0), 100.0);
    ring.pop();
    let lift = DMat4::from_translation(DVec3::Y * 0.3) * DMat4::from_rotation_z(0.3);
    apply(
        &mut editor,
        Op::RegionEdit(RegionEditInput {
            viewport: reference.viewport,
            camera,
            reference: reference.stroke,
            boundary: stroke_input(SQUARE, camera, &ring).stroke,
            levels: None,
            areas: Vec::new(),
            transform: Some(lift.to_cols_array()),
            handles: None,
            profile: None,
            remesh: false,
        }),
    );
    let (moved, farthest) = moved_vertices(&before, &editor.document().models[0].mesh);
    assert!(
        moved > 20 && moved < before.n_vertices() / 2 && farthest > 0.1,
        "the region moves, the rest stays: {moved} vertices moved, up to {farthest}"
    );
    editor
}

/// A bar with a surface handle and a skeleton handle along it, linked at one end; the
/// surface handle's end lifted, the skeleton twisted and scaled, the first handle deleted.
fn curve_handles() -> Editor {
    let camera = Camera {
        eye: DVec3::new(0.0, 0.0, 3.5),
        ..Camera::default()
    };
    let mut editor = Editor::new();
    apply(
        &mut editor,
        import_mesh("bar.glb", &primitives::capsule(0.2, 1.0, 20, 80)),
    );
    let handle = |kind: HandleKind| {
        let from = screen(&camera, VIEWPORT, DVec3::new(-0.9, 0.0, 0.0)).unwrap();
        let to = screen(&camera, VIEWPORT, DVec3::new(0.9, 0.0, 0.0)).unwrap();
        let stroke = stroke_input(VIEWPORT, camera, &segment(from, to));
        Op::CurveHandle(CurveHandleInput {
            viewport: stroke.viewport,
            camera,
            stroke: stroke.stroke,
            kind,
            control_points: 4,
            rigid: false,
        })
    };
    apply(&mut editor, handle(HandleKind::Surface));
    apply(&mut editor, handle(HandleKind::Skeleton));
    assert_eq!(editor.document().handles.len(), 2);
    apply(
        &mut editor,
        Op::LinkHandles(LinkHandlesInput {
            a: (0, 0),
            b: (1, 0),
        }),
    );
    assert_eq!(editor.document().handles[0].links, vec![(0, 1, 0)]);
    let before = editor.document().models[0].mesh.clone();
    apply(
        &mut editor,
        Op::HandleEdit(HandleEditInput {
            handle: 0,
            point: 3,
            translate: Some([0.0, 0.3, 0.0]),
            twist_deg: None,
            scale: None,
            spread: 1,
        }),
    );
    let highest = |mesh: &Mesh| {
        mesh.positions()
            .iter()
            .map(|p| p.y)
            .fold(f64::MIN, f64::max)
    };
    let lifted = highest(&editor.document().models[0].mesh);
    assert!(lifted > highest(&before) + 0.2, "the end rose: {lifted}");
    apply(
        &mut editor,
        Op::HandleEdit(HandleEditInput {
            handle: 1,
            point: 2,
            translate: None,
            twist_deg: Some(45.0),
            scale: Some([1.2, 0.8]),
            spread: 2,
        }),
    );
    let twist = editor.document().handles[1].curve.twist[2];
    assert!(
        (twist - 45f64.to_radians()).abs() < 1e-12,
        "twisted by {twist}"
    );
    apply(
        &mut editor,
        Op::DeleteHandle(DeleteHandleInput { handle: 0 }),
    );
    let left = &editor.document().handles;
    assert!(left.len() == 1 && left[0].id == 1 && left[0].links.is_empty());
    apply(&mut editor, Op::Undo);
    apply(&mut editor, Op::Redo);
    editor
}

/// A capsule posed at three key frames: at rest, bent by a control curve redrawn from
/// above (its right three quarters swung round a quarter circle toward +z, its left end
/// held), then its left end lifted by the scripted volumetric deformation; the middle key
/// deleted, and the capsule posed half way between the two left.
fn deform_and_keyframes() -> Editor {
    let key = |time: f64| KeyframeInput { time };
    let mut editor = Editor::new();
    apply(
        &mut editor,
        import_mesh("capsule.glb", &primitives::capsule(0.5, 3.0, 20, 60)),
    );
    let rest = editor.document().models[0].mesh.clone();
    apply(&mut editor, Op::Keyframe(key(0.0)));

    apply(&mut editor, Op::CurveDeform(quarter_bend()));
    let swung = (editor.document().models[0].mesh.positions().iter())
        .map(|p| p.z)
        .fold(f64::MIN, f64::max);
    assert!(swung > 1.5, "the right end swung toward +z: {swung}");
    apply(&mut editor, Op::Keyframe(key(1.0)));

    let lift = DMat4::from_translation(DVec3::Y * 0.6);
    apply(
        &mut editor,
        Op::Deform(DeformInput {
            method: DeformMethod::Volumetric,
            model: 0,
            handles: vec![DeformHandleInput {
                sphere: [-3.2, 0.0, 0.0, 0.6],
                matrix: lift.to_cols_array(),
            }],
            fixed: vec![[-0.8, 0.0, 0.0, 0.6]],
        }),
    );
    let end = (editor.document().models[0].mesh.positions().iter())
        .filter(|p| p.x < -3.0)
        .map(|p| p.y)
        .fold(f64::MIN, f64::max);
    assert!(end > 0.9, "the left end rose: {end}");
    apply(&mut editor, Op::Keyframe(key(2.0)));
    assert_eq!(editor.document().models[0].keyframes().count(), 3);
    apply(&mut editor, Op::DeleteKeyframe(key(1.0)));
    let times: Vec<f64> = (editor.document().models[0].keyframes())
        .map(|k| k.time)
        .collect();
    assert_eq!(times, [0.0, 2.0]);
    let posed = editor.document().models[0].mesh.clone();
    apply(&mut editor, Op::PoseAt(key(1.0)));
    let half = &editor.document().models[0].mesh;
    let [rest_z, posed_z, half_z] =
        [&rest, &posed, half].map(|m| m.positions().iter().map(|p| p.z).fold(f64::MIN, f64::max));
    assert!(
        rest_z < half_z && half_z < posed_z,
        "half way between the keys: {rest_z} < {half_z} < {posed_z}"
    );
    apply(&mut editor, Op::Undo);
    apply(&mut editor, Op::Redo);
    editor
}

/// Issue 23: after a curve op that remeshes, Laplacian mesh optimization (curve vertices
/// sliding along their curves) tidies the triangles the remesh left poor. In these sessions
/// the add-curve ops left worst radius ratios of 0.249, 0.034 and 0.213 before the tidy-up.
#[test]
fn curve_ops_leave_no_poor_triangles() {
    use sketchmesh_core::optimize::quality::radius_ratio;
    for (name, ops) in [("closed_curve_and_rub", 3), ("curve_tools", 4)] {
        let json = std::fs::read_to_string(fixture_dir().join(format!("{name}.json"))).unwrap();
        let session = Session::from_json(&json).unwrap();
        let mut editor = Editor::new();
        for op in session.ops.into_iter().take(ops) {
            let op_name = op.name();
            editor.apply(op).unwrap();
            for model in &editor.document().models {
                let mesh = &model.mesh;
                let worst = (mesh.faces())
                    .map(|f| radius_ratio(mesh.face_positions(f)))
                    .fold(1.0, f64::min);
                assert!(
                    worst > 0.3,
                    "{name}, after {op_name}: worst radius ratio {worst}"
                );
            }
        }
    }
}

/// Symmetric modelling: a body drawn across the plane and a blob beside it made with
/// symmetry on (symmetric, and mirror twins), a pull, a curve, a limb and a cut each made
/// once and acting on both sides, a mirrored duplicate, and a shape made symmetric about a
/// tilted plane off its centre.
fn symmetric_modelling() -> Editor {
    let plane = MirrorPlane::default();
    let mirrored = |op: Op| op.mirrored(plane);
    let camera = Camera::default();
    let mut editor = Editor::new();
    let body = outline(
        CENTRE,
        150.0,
        &[(2, 0.12, 0.4), (3, 0.06, 1.1)],
        0.8,
        0.0,
        90,
    );
    apply(&mut editor, mirrored(create(&body, camera)));
    let blob = circle(CENTRE + DVec2::new(290.0, -170.0), 60.0);
    apply(&mut editor, mirrored(create(&blob, camera)));
    let doc = editor.document();
    assert!(partners(&doc.models[0].mesh, &plane).is_some());
    assert!(are_twins(&doc.models[1].mesh, &doc.models[2].mesh, &plane));

    let right = |editor: &Editor| {
        let model = &editor.document().models[0];
        let points = model.curves[0].points(&model.mesh);
        let far = points.iter().copied().max_by(|a, b| a.x.total_cmp(&b.x));
        screen(&camera, VIEWPORT, far.unwrap()).unwrap()
    };
    let from = right(&editor);
    let pull = stroke_input(
        VIEWPORT,
        camera,
        &segment(from, from + DVec2::new(50.0, -20.0)),
    );
    apply(&mut editor, mirrored(Op::Pull(pull)));
    let body_right = CENTRE + DVec2::new(80.0, 0.0);
    let across = segment(
        body_right - DVec2::new(30.0, 50.0),
        body_right + DVec2::new(30.0, 50.0),
    );
    apply(
        &mut editor,
        mirrored(add_curve(VIEWPORT, camera, &across, false, false)),
    );
    let base: Vec<DVec2> = circle(body_right + DVec2::new(40.0, 30.0), 22.0);
    let silhouette: Vec<DVec2> = (0..=60)
        .map(|i| {
            let a = std::f64::consts::PI * (f64::from(i) / 60.0 - 0.5);
            body_right + DVec2::new(40.0, 30.0) + DVec2::new(140.0 * a.cos(), 22.0 * a.sin())
        })
        .collect();
    let strokes = [
        stroke_input(VIEWPORT, camera, &base),
        stroke_input(VIEWPORT, camera, &silhouette),
    ];
    apply(
        &mut editor,
        mirrored(Op::Extrude(StrokePairInput { strokes })),
    );
    let (lo, hi) = editor.document().models[0].mesh.bounding_box().unwrap();
    assert!((lo.x + hi.x).abs() < 1e-9, "a limb on each side: {lo} {hi}");
    let blob_x = CENTRE.x + 315.0;
    let cut = segment(DVec2::new(blob_x, 20.0), DVec2::new(blob_x, 300.0));
    apply(
        &mut editor,
        mirrored(Op::Cut(stroke_input(VIEWPORT, camera, &cut))),
    );
    let duplicate = DuplicateInput {
        model: 1,
        beside: None,
    };
    apply(&mut editor, mirrored(Op::Duplicate(duplicate)));
    let n = editor.document().models.len();
    let doc = editor.document();
    assert!(are_twins(
        &doc.models[1].mesh,
        &doc.models[n - 1].mesh,
        &plane
    ));

    let lower = outline(
        CENTRE + DVec2::new(60.0, 200.0),
        70.0,
        &[(2, 0.1, 0.3)],
        0.7,
        0.2,
        60,
    );
    apply(&mut editor, create(&lower, camera));
    let (lo, hi) = editor.document().models[n].mesh.bounding_box().unwrap();
    let tilted = MirrorPlane::through(0.5 * (lo + hi) + DVec3::X * 0.1, DVec3::new(1.0, 0.25, 0.0));
    let symmetrize = SymmetrizeInput {
        model: n,
        plane: tilted.unwrap(),
        keep: Side::Negative,
    };
    // The plane moved and turned (Arrange's handles on it), then the lower body made
    // symmetric about it and optimized with symmetry on: both sides move alike.
    let tilted = tilted.unwrap();
    apply(&mut editor, Op::SymmetryPlane(PlaneInput { plane: tilted }));
    assert_eq!(editor.document().symmetry, Some(tilted));
    apply(&mut editor, Op::Symmetrize(symmetrize));
    let optimize = OptimizeInput {
        model: n,
        settings: OptimizeParams::default(),
        region: None,
        painted: Vec::new(),
        painted_features: Vec::new(),
    };
    apply(&mut editor, Op::Optimize(optimize).mirrored(tilted));
    assert!(partners(&editor.document().models[n].mesh, &tilted).is_some());
    editor
}

/// Colour: a soft brush stroke with pressure, a second model filled and given a material,
/// a mirrored stroke on a symmetric model, a cut that carries the paint onto new triangles,
/// and an undo and redo of the fill.
fn painted() -> Editor {
    let plane = MirrorPlane::default();
    let camera = Camera::default();
    let mut editor = Editor::new();
    apply(
        &mut editor,
        create(&circle(CENTRE, 120.0), camera).mirrored(plane),
    );
    let brush = |points: &[DVec2], color: [f64; 3]| PaintInput {
        viewport: VIEWPORT.to_array(),
        camera,
        stroke: (points.iter().enumerate())
            .map(|(k, p)| [p.x, p.y, 0.2 + 0.6 * k as f64 / points.len() as f64])
            .collect(),
        color,
        radius: 24.0,
        hardness: 0.3,
        opacity: 0.8,
    };
    let band = segment(
        CENTRE + DVec2::new(-80.0, -40.0),
        CENTRE + DVec2::new(80.0, -30.0),
    );
    apply(&mut editor, Op::Paint(brush(&band, [0.9, 0.2, 0.1])));
    let side = segment(
        CENTRE + DVec2::new(40.0, 30.0),
        CENTRE + DVec2::new(70.0, 70.0),
    );
    apply(
        &mut editor,
        Op::Paint(brush(&side, [0.1, 0.3, 0.9])).mirrored(plane),
    );
    let other = CENTRE + DVec2::new(-260.0, 150.0);
    apply(&mut editor, create(&circle(other, 60.0), camera));
    let fill = FillInput {
        model: 1,
        color: [0.2, 0.7, 0.3],
    };
    apply(&mut editor, Op::Fill(fill));
    apply(&mut editor, Op::Undo);
    apply(&mut editor, Op::Redo);
    let material = MaterialInput {
        model: 1,
        base_color: [1.0, 0.9, 0.8, 1.0],
        roughness: 0.3,
        metalness: 0.7,
    };
    apply(&mut editor, Op::Material(material));
    let cut = segment(DVec2::new(470.0, 120.0), DVec2::new(470.0, 480.0));
    apply(&mut editor, Op::Cut(stroke_input(VIEWPORT, camera, &cut)));
    assert!(editor.document().models[0].vertex_colors().is_some());
    editor
}

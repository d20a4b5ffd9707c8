//! Runs the built `sketchmesh` binary on session files in a temporary directory.

#![allow(clippy::unwrap_used)] // A panic is a test failure with a location.

use std::path::PathBuf;
use std::process::{Command, Output};

const SESSION: &str = r#"{"format":"sketchmesh-session","version":1,"ops":[
{"op":"stroke","viewport":[800.0,600.0],"camera":{"eye":[0.0,0.0,5.0],"target":[0.0,0.0,0.0],"up":[0.0,1.0,0.0],"fov_y_deg":45.0},"stroke":[[300.0,300.0,0.5],[400.0,280.0,0.6],[500.0,300.0,0.7]]},
{"op":"stroke","viewport":[800.0,600.0],"camera":{"eye":[5.0,0.0,0.0],"target":[0.0,0.0,0.0],"up":[0.0,1.0,0.0],"fov_y_deg":45.0},"stroke":[[400.0,200.0,0.5],[400.0,400.0,0.5]]},
{"op":"undo"},
{"op":"redo"}
]}
"#;

/// A fresh directory under the system temp dir, unique per test and process.
fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("sketchmesh-cli-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn sketchmesh(args: &[&std::ffi::OsStr]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_sketchmesh"))
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn replay_then_info() {
    let dir = temp_dir("replay");
    let session = dir.join("session.json");
    let glb = dir.join("out.glb");
    std::fs::write(&session, SESSION).unwrap();

    let stdout = succeed("replay", &session, &glb, &[]);
    assert!(
        stdout.starts_with("Replayed 4 ops: 0 models, 0 vertices, 0 triangles, 2 curves"),
        "{stdout}"
    );
    assert_eq!(stdout.lines().count(), 1);
    let bytes = std::fs::read(&glb).unwrap();
    assert!(bytes.starts_with(b"glTF"));

    let output = sketchmesh(&["info".as_ref(), glb.as_os_str()]);
    assert_eq!(
        output.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let info: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(info["sketches"], 2);
    assert_eq!(info["triangles"], 0);
    assert_eq!(info["genus"], serde_json::Value::Null);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn refusals_exit_1_with_a_sentence() {
    let dir = temp_dir("refusals");
    let session = dir.join("bad.json");
    let glb = dir.join("never.glb");
    let bad = SESSION.replace(r#"{"op":"undo"}"#, r#"{"op":"frobnicate"}"#);
    std::fs::write(&session, bad).unwrap();

    let output = sketchmesh(&[
        "replay".as_ref(),
        session.as_os_str(),
        "-o".as_ref(),
        glb.as_os_str(),
    ]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1));
    assert!(
        stderr.contains("op 2: unknown op \"frobnicate\""),
        "{stderr}"
    );
    assert!(output.stdout.is_empty());
    assert!(!glb.exists());

    let not_glb = dir.join("not.glb");
    std::fs::write(&not_glb, b"hello").unwrap();
    let output = sketchmesh(&["info".as_ref(), not_glb.as_os_str()]);
    assert_eq!(output.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&output.stderr).contains("not valid glTF"));

    let output = sketchmesh(&["frobnicate".as_ref()]);
    assert_eq!(output.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&output.stderr).contains("Usage"));

    let output = sketchmesh(&["--help".as_ref()]);
    assert_eq!(output.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&output.stdout).contains("sketchmesh replay"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A session whose one op inflates a closed outline (an ellipse, 48 samples).
fn create_session() -> String {
    let stroke: Vec<String> = (0..=48)
        .map(|i| {
            let a = std::f64::consts::TAU * f64::from(i) / 48.0;
            format!(
                "[{},{},0.5]",
                400.0 + 150.0 * a.cos(),
                300.0 + 100.0 * a.sin()
            )
        })
        .collect();
    format!(
        r#"{{"format":"sketchmesh-session","version":1,"ops":[
{{"op":"create","viewport":[800.0,600.0],"camera":{{"eye":[0.0,1.0,5.0],"target":[0.0,0.0,0.0],"up":[0.0,1.0,0.0],"fov_y_deg":45.0}},"stroke":[{}]}}
]}}"#,
        stroke.join(",")
    )
}

#[test]
fn a_created_shape_replays_to_the_same_closed_genus_0_mesh() {
    let dir = temp_dir("create");
    let session = dir.join("create.json");
    std::fs::write(&session, create_session()).unwrap();
    let replay = |name: &str| {
        let glb = dir.join(name);
        let output = sketchmesh(&[
            "replay".as_ref(),
            session.as_os_str(),
            "-o".as_ref(),
            glb.as_os_str(),
        ]);
        assert_eq!(
            output.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&output.stderr)
        );
        (glb.clone(), std::fs::read(&glb).unwrap())
    };
    let (glb, first) = replay("first.glb");
    let (_, second) = replay("second.glb");
    assert_eq!(first, second, "replay is deterministic to the byte");

    let output = sketchmesh(&["info".as_ref(), glb.as_os_str()]);
    assert_eq!(output.status.code(), Some(0));
    let info: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    assert!(info["vertices"].as_u64().unwrap() > 1000, "{info}");
    assert_eq!(info["closed"], true, "{info}");
    assert_eq!(info["manifold"], true, "{info}");
    assert_eq!(info["genus"], 0, "{info}");
    assert_eq!(info["components"], 1, "{info}");
    assert_eq!(info["control_curves"], 1, "{info}");
}

#[test]
fn a_session_of_every_topology_op_replays_to_the_same_mesh_every_time() {
    // Recorded by the core's topology suite: create, extrude twice, tunnel, cut, create a
    // second shape, move it into the first, merge.
    let session = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../tests/fixtures/topology-session.json");
    let dir = temp_dir("topology");
    let (first, second) = (dir.join("first.glb"), dir.join("second.glb"));
    succeed("replay", &session, &first, &[]);
    succeed("replay", &session, &second, &[]);
    assert_eq!(
        std::fs::read(&first).unwrap(),
        std::fs::read(&second).unwrap(),
        "replay is deterministic to the byte"
    );
    let output = sketchmesh(&["info".as_ref(), first.as_os_str()]);
    assert_eq!(output.status.code(), Some(0));
    let info: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(info["closed"], true, "{info}");
    assert_eq!(info["manifold"], true, "{info}");
    assert_eq!(info["genus"], 1, "the tunnel's hole: {info}");
    assert_eq!(info["components"], 1, "{info}");
    // The same mesh as the core's replay and the page's.
    let expected: serde_json::Value =
        serde_json::from_slice(&std::fs::read(session.with_extension("expected.json")).unwrap())
            .unwrap();
    for key in ["vertices", "triangles"] {
        assert_eq!(info[key], expected[key], "{key}: {info} against {expected}");
    }
    assert_eq!(info["control_curves"], expected["curves"], "{info}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Runs `sketchmesh COMMAND INPUT -o OUTPUT [EXTRA...]`, expects success and returns what
/// it printed.
fn succeed(
    command: &str,
    input: &std::path::Path,
    output: &std::path::Path,
    extra: &[&str],
) -> String {
    let mut args: Vec<&std::ffi::OsStr> = vec![
        command.as_ref(),
        input.as_os_str(),
        "-o".as_ref(),
        output.as_os_str(),
    ];
    args.extend(extra.iter().map(std::ffi::OsStr::new));
    let run = sketchmesh(&args);
    assert_eq!(
        run.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    String::from_utf8_lossy(&run.stdout).into_owned()
}

#[test]
fn convert_round_trips_and_sessions_import_files_beside_them() {
    let dir = temp_dir("convert");
    let session = dir.join("create.json");
    std::fs::write(&session, create_session()).unwrap();
    let created = dir.join("created.glb");
    succeed("replay", &session, &created, &[]);
    let converted = dir.join("converted.glb");
    succeed("convert", &created, &converted, &[]);
    assert_eq!(
        std::fs::read(&converted).unwrap(),
        std::fs::read(&created).unwrap(),
        "importing a Sketchmesh file and exporting it again changes nothing"
    );
    // A session that imports that file by name, then undoes and redoes the import.
    let import_session = dir.join("import.json");
    std::fs::write(
        &import_session,
        r#"{"format":"sketchmesh-session","version":1,"ops":[
{"op":"import","files":[{"name":"created.glb"}]},{"op":"undo"},{"op":"redo"}]}"#,
    )
    .unwrap();
    let replayed = dir.join("replayed.glb");
    succeed("replay", &import_session, &replayed, &[]);
    assert_eq!(
        std::fs::read(&replayed).unwrap(),
        std::fs::read(&created).unwrap()
    );
    // Refusals: exit 1 and one sentence naming the problem.
    let broken = dir.join("broken.glb");
    let mut bytes = std::fs::read(&created).unwrap();
    bytes.truncate(bytes.len() / 2);
    std::fs::write(&broken, bytes).unwrap();
    let output = sketchmesh(&[
        "convert".as_ref(),
        broken.as_os_str(),
        "-o".as_ref(),
        dir.join("never.glb").as_os_str(),
    ]);
    assert_eq!(output.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("not valid glTF"), "{stderr}");
    assert!(!dir.join("never.glb").exists());
}

/// `../shared/testdata/meshes/NAME`, or a loud failure when the shared data is missing.
fn testdata_mesh(name: &str) -> PathBuf {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/testdata/meshes")
        .join(name);
    assert!(
        path.is_file(),
        "the shared test data is missing: {} does not exist",
        path.display()
    );
    path
}

#[test]
fn optimize_improves_the_triangles_of_a_scan_and_reports_it() {
    let dir = temp_dir("optimize");
    let out = dir.join("spot.glb");
    let input = testdata_mesh("spot.glb");
    let stdout = succeed("optimize", &input, &out, &["--weights", "cdf", "--report"]);
    let json_start = stdout.find('[').unwrap();
    let reports: serde_json::Value = serde_json::from_str(&stdout[json_start..]).unwrap();
    let report = &reports[0];
    let number = |key: &str| report[key].as_f64().unwrap();
    assert!(
        number("mean_radius_ratio") > number("input_mean_radius_ratio"),
        "{report}"
    );
    assert!(number("hausdorff_relative") < 0.005, "{report}");
    assert!(std::fs::read(&out).unwrap().starts_with(b"glTF"));
}

#[test]
fn optimize_smooths_with_each_feature_falloff() {
    let dir = temp_dir("optimize-falloff");
    let input = testdata_mesh("suzanne.glb");
    for falloff in ["linear", "cdf", "gaussian"] {
        let out = dir.join(format!("{falloff}.glb"));
        let args = [
            "--mode",
            "smooth",
            "--features",
            "--feature-falloff",
            falloff,
        ];
        succeed("optimize", &input, &out, &args);
        assert!(
            std::fs::read(&out).unwrap().starts_with(b"glTF"),
            "{falloff}"
        );
    }
}

#[test]
fn optimize_refuses_bad_options_with_a_sentence() {
    let input = testdata_mesh("suzanne.glb");
    for (args, says) in [
        (vec!["--mode", "sharpen"], "--mode"),
        (vec!["--scale", "lots"], "--scale takes a number"),
        (vec!["--wobble"], "I don't know the option --wobble"),
        (
            vec!["--features", "--feature-falloff", "sharp"],
            "--feature-falloff",
        ),
    ] {
        let mut all: Vec<&std::ffi::OsStr> = vec![
            "optimize".as_ref(),
            input.as_os_str(),
            "-o".as_ref(),
            "x.glb".as_ref(),
        ];
        all.extend(args.iter().map(std::ffi::OsStr::new));
        let output = sketchmesh(&all);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(1), "{args:?}");
        assert!(stderr.contains(says), "{args:?}: {stderr}");
    }
}

#[test]
fn convert_writes_stl_and_obj_by_the_extension_in_the_unit_asked_for() {
    let dir = temp_dir("export");
    let input = testdata_mesh("spot.glb");
    let stl = dir.join("spot.stl");
    let stdout = succeed("convert", &input, &stl, &[]);
    assert!(stdout.contains("spot.stl in mm"), "{stdout}");
    let bytes = std::fs::read(&stl).unwrap();
    assert!(!bytes.starts_with(b"glTF") && !bytes.starts_with(b"solid"));
    let count = u32::from_le_bytes(bytes[80..84].try_into().unwrap()) as usize;
    assert_eq!(count, 5856, "spot's triangles");
    assert_eq!(bytes.len(), 84 + 50 * count);
    // The same in inches: every coordinate 25.4 times smaller.
    let inches = dir.join("spot-in.stl");
    succeed("convert", &input, &inches, &["--unit", "in"]);
    let inches = std::fs::read(&inches).unwrap();
    let coordinate =
        |bytes: &[u8], at: usize| f32::from_le_bytes(bytes[at..at + 4].try_into().unwrap());
    for at in [84 + 12, 84 + 50 * 100 + 28] {
        let (mm, inch) = (coordinate(&bytes, at), coordinate(&inches, at));
        assert!(
            (mm / 25.4 - inch).abs() < 1e-4 * mm.abs().max(1.0),
            "{mm} mm against {inch} in"
        );
    }

    let obj = dir.join("spot.obj");
    let stdout = succeed("convert", &input, &obj, &[]);
    assert!(stdout.contains("spot.mtl in m"), "{stdout}");
    let text = std::fs::read_to_string(&obj).unwrap();
    assert!(text.contains("\nmtllib spot.mtl\n"));
    assert_eq!(text.lines().filter(|l| l.starts_with("f ")).count(), 5856);
    assert_eq!(text.lines().filter(|l| l.starts_with("v ")).count(), 2930);
    let mtl = std::fs::read_to_string(dir.join("spot.mtl")).unwrap();
    assert_eq!(mtl.lines().filter(|l| l.starts_with("newmtl ")).count(), 1);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn an_output_it_cannot_write_is_refused_and_nothing_is_written() {
    let dir = temp_dir("export-refusals");
    let input = testdata_mesh("spot.glb");
    for (out, extra, says) in [
        ("spot.ply", vec![], "Sketchmesh cannot write"),
        ("spot", vec![], "name the output .glb (glTF), .stl or .obj"),
        ("spot.gltf", vec![], "Sketchmesh cannot write"),
        ("spot.glb", vec!["--unit", "mm"], "glTF is always in metres"),
        (
            "spot.stl",
            vec!["--unit", "ft"],
            "\"ft\" is not a unit of length",
        ),
        ("spot.stl", vec!["--scale", "2"], "the only one is --unit"),
    ] {
        let out = dir.join(out);
        let mut args: Vec<&std::ffi::OsStr> = vec![
            "convert".as_ref(),
            input.as_os_str(),
            "-o".as_ref(),
            out.as_os_str(),
        ];
        args.extend(extra.iter().map(std::ffi::OsStr::new));
        let output = sketchmesh(&args);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(1), "{out:?}: {stderr}");
        assert!(stderr.contains(says), "{out:?}: {stderr}");
        assert!(!out.exists(), "{out:?} was written");
    }
    // A document without triangles: the replayed strokes are sketches only.
    let session = dir.join("strokes.json");
    std::fs::write(&session, SESSION).unwrap();
    let stl = dir.join("strokes.stl");
    let output = sketchmesh(&[
        "replay".as_ref(),
        session.as_os_str(),
        "-o".as_ref(),
        stl.as_os_str(),
    ]);
    assert_eq!(output.status.code(), Some(1));
    assert!(
        String::from_utf8_lossy(&output.stderr)
            .contains("The document has no triangles to write to STL."),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    assert!(!stl.exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Runs `sketchmesh check ARGS...`: its exit status and what it printed.
fn check(args: &[&std::ffi::OsStr]) -> (Option<i32>, String, String) {
    let mut all: Vec<&std::ffi::OsStr> = vec!["check".as_ref()];
    all.extend(args);
    let output = sketchmesh(&all);
    (
        output.status.code(),
        String::from_utf8_lossy(&output.stdout).into_owned(),
        String::from_utf8_lossy(&output.stderr).into_owned(),
    )
}

#[test]
fn check_says_what_would_print_and_exits_accordingly() {
    // Spot, about 1.5 m long in its file: closed, and thick everywhere.
    let spot = testdata_mesh("spot.glb");
    let (code, stdout, stderr) = check(&[spot.as_os_str()]);
    assert_eq!(code, Some(0), "{stdout}{stderr}");
    let lines: Vec<&str> = stdout.lines().collect();
    assert_eq!(lines[0], "Closed and manifold.");
    assert_eq!(lines[1], "The surface does not cross itself.");
    assert!(lines[2].contains("above the 1 mm minimum"), "{stdout}");
    assert!(
        lines[3].starts_with("Size ") && lines[3].ends_with(" mm."),
        "{stdout}"
    );
    // In centimetres, against a wall thicker than spot's legs.
    let (code, stdout, _) = check(&[
        spot.as_os_str(),
        "--unit".as_ref(),
        "cm".as_ref(),
        "--min-wall".as_ref(),
        "500".as_ref(),
    ]);
    assert_eq!(code, Some(1), "{stdout}");
    assert!(stdout.contains("under the 500 cm minimum"), "{stdout}");
    // The bunny scan is open at the base.
    let bunny = testdata_mesh("stanford_bunny.glb");
    let (code, stdout, _) = check(&[bunny.as_os_str()]);
    assert_eq!(code, Some(1));
    assert!(stdout.starts_with("Not closed: "), "{stdout}");
    // A session's document.
    let dir = temp_dir("check");
    let session = dir.join("create.json");
    std::fs::write(&session, create_session()).unwrap();
    let (code, stdout, stderr) = check(&[session.as_os_str()]);
    assert_eq!(code, Some(0), "{stdout}{stderr}");
    assert!(stdout.starts_with("Closed and manifold.\n"), "{stdout}");
    // No check: 2, with a sentence.
    let missing = dir.join("missing.glb");
    for (args, says) in [
        (
            vec![spot.as_os_str(), "--min-wall".as_ref(), "thin".as_ref()],
            "--min-wall takes a length",
        ),
        (
            vec![spot.as_os_str(), "--wobble".as_ref()],
            "I don't know the option --wobble",
        ),
        (vec![], "Name the glTF or session file to check."),
        (vec![missing.as_os_str()], "Could not read"),
    ] {
        let (code, stdout, stderr) = check(&args);
        assert_eq!(code, Some(2), "{args:?}: {stdout}{stderr}");
        assert!(stderr.contains(says), "{args:?}: {stderr}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

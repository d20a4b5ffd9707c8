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

//! `cargo xtask test`: every check CI runs (`.ci/run`), in order, stopping at the first failure.
//!
//! fmt, clippy, native tests, the page as it ships (`release` wasm, wasm-opt) with a size budget, the browser
//! suite (`tests/e2e/run.mjs`) on WebGL2 and then, for the cases that can differ, on WebGPU against an
//! in-process server, the Khronos glTF validator on every exported `.glb` (browser exports and a
//! CLI replay), and three.js's STL and OBJ loaders on the CLI's conversions.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};

use anyhow::{Context as _, bail};

use crate::build::{self, WebBuild};
use crate::serve::StaticServer;
use crate::setup::{self, Needs};
use crate::{Steps, Workspace, cargo, format_size, run};

/// Budget for the gzip-compressed wasm: the page that ships, which is the one tested.
const WASM_GZIP_BUDGET: u64 = 3_500_000;
/// The session the CLI replays into `tests/out/replay.glb` for the validator.
const REPLAY_FIXTURE: &str = "tests/fixtures/two-strokes-undo-redo.json";
/// A session with paint, a fill and a material, replayed into `tests/out/painted.glb` for the
/// validator (the golden session of the core's tests).
const PAINTED_FIXTURE: &str = "crates/core/tests/fixtures/sessions/painted.json";
/// A session with three key frames (0, 1 and 2 s), replayed into `tests/out/animation.glb`
/// for the validator and the three.js playback check.
const ANIMATION_FIXTURE: &str = "tests/fixtures/animation-three-keys.json";
/// The scan the CLI converts to STL and OBJ for three.js's loaders: a clean closed surface.
const EXPORT_SCAN: &str = "../shared/testdata/meshes/spot.glb";
/// The session replayed and converted likewise: create, extrude, tunnel, cut, merge (closed,
/// genus 1).
const EXPORT_SESSION: &str = "tests/fixtures/topology-session.json";
/// What three.js must play from it: seconds, and frames (the keys and 12 in-betweens a
/// second).
const ANIMATION_PLAYBACK: (u32, u32) = (2, 25);
/// The GPU paths of the browser suite: `SKETCHMESH_GPU` values understood by `tests/e2e/lib.mjs`.
/// The first runs every case; the second only the cases whose outcome can differ between the
/// paths (`gpu: true` in `tests/e2e/run.mjs`).
pub const GPU_PASSES: [&str; 2] = ["webgl2", "webgpu"];

/// Runs everything; prints a summary with the time of each step.
///
/// The page is built by a second xtask process while the native tests build and run: its last
/// minutes (wasm-opt, the thin-LTO link) use one core, and the native build's tail another. The
/// two cargo builds lock different profile folders (`debug` against `release` and the wasm
/// target), so neither waits for the other.
pub fn test_command(workspace: &Workspace) -> anyhow::Result<()> {
    let root = &workspace.root;
    let mut steps = Steps::default();
    steps.step("setup", || setup::setup(workspace, Needs::ALL))?;
    steps.step("cargo fmt --check", || {
        run(
            "cargo fmt (run `cargo fmt --all` to fix)",
            cargo().current_dir(root).args(["fmt", "--all", "--check"]),
        )
    })?;
    steps.step("doc references", || {
        crate::doc_check::docs_command(workspace)
    })?;
    steps.step("layer rules", || crate::layers::layers_command(workspace))?;
    let web_build = steps.step("start build-web", || WebBuildProcess::start(workspace))?;
    steps.step("build tests with clippy", || {
        run(
            "clippy over every target, building the tests",
            with_clippy(cargo().current_dir(root))
                .args(NATIVE_TESTS)
                .args(["--all-targets", "--no-run"]),
        )?;
        run(
            "clippy over xtask, building its tests",
            with_clippy(cargo().current_dir(root))
                .args(XTASK_TESTS)
                .arg("--no-run"),
        )
    })?;
    steps.step("cargo test", || {
        run(
            "cargo test",
            with_clippy(cargo().current_dir(root)).args(NATIVE_TESTS),
        )?;
        run(
            "cargo test (xtask)",
            with_clippy(cargo().current_dir(root)).args(XTASK_TESTS),
        )
    })?;
    let web = steps.step("build-web (rest, after the native tests)", || {
        web_build.wait()
    })?;
    // `cargo test` built the CLI with the whole workspace's features; `cargo run -p` would
    // rebuild the core with the CLI's own feature set, which takes minutes from cold.
    let cli = workspace.target_dir.join("debug").join("sketchmesh");
    browser_checks(workspace, &mut steps, &web, Some(&cli))?;
    steps.print_summary();
    println!("xtask: all checks passed");
    Ok(())
}

/// The workspace's tests but xtask's, in the test profile (built with `--all-targets`, so clippy
/// sees the benches and examples too; run without, so the benches are not run once each).
const NATIVE_TESTS: &[&str] = &["test", "--workspace", "--exclude", "xtask"];
/// xtask's own tests, in the profile `cargo xtask` is built with: its dependencies (the
/// wasm-bindgen library among them) are then compiled once, not once more for the tests.
const XTASK_TESTS: &[&str] = &["test", "-p", "xtask", "--profile", "xtask"];

/// `cargo xtask build-web` running beside the native build, its output kept in a log that is
/// printed when it is waited for; killed if the test run stops before that.
struct WebBuildProcess {
    child: Option<Child>,
    log: PathBuf,
    dist: PathBuf,
}

impl WebBuildProcess {
    fn start(workspace: &Workspace) -> anyhow::Result<Self> {
        let web_dir = workspace.target_dir.join("web");
        fs::create_dir_all(&web_dir).with_context(|| format!("creating {}", web_dir.display()))?;
        let log = web_dir.join("build-web.log");
        let out = fs::File::create(&log).with_context(|| format!("creating {}", log.display()))?;
        let err = out.try_clone()?;
        let xtask = std::env::current_exe().context("finding the running xtask")?;
        println!("xtask: $ {} build-web > {}", xtask.display(), log.display());
        let child = Command::new(&xtask)
            .current_dir(&workspace.root)
            .arg("build-web")
            .stdin(Stdio::null())
            .stdout(out)
            .stderr(err)
            .spawn()
            .context("starting `xtask build-web`")?;
        Ok(Self {
            child: Some(child),
            log,
            dist: workspace.dist(),
        })
    }

    /// Waits for the build, prints its log, and reads what it wrote into `dist/`.
    fn wait(mut self) -> anyhow::Result<WebBuild> {
        let status = self
            .child
            .take()
            .map(|mut child| child.wait())
            .transpose()?;
        let log = fs::read_to_string(&self.log).unwrap_or_default();
        print!("{log}");
        if !status.is_some_and(|status| status.success()) {
            bail!("the web build failed ({status:?}); its log is above");
        }
        WebBuild::in_dist(&self.dist)
    }
}

impl Drop for WebBuildProcess {
    fn drop(&mut self) {
        if let Some(child) = self.child.as_mut() {
            let _ = child.kill();
            let _ = child.wait();
        }
    }
}

/// Makes `command` lint the workspace's crates with clippy (`-D warnings`) while it builds
/// them, as `cargo clippy` does, but in a real build: the dependencies are compiled once, for
/// the tests, instead of once more in check mode (that second build cost minutes on 2 cores).
/// `RUSTC_WORKSPACE_WRAPPER` and `CLIPPY_ARGS` are what `cargo clippy` itself sets; the same
/// values on the test run keep cargo's fingerprints, so nothing is rebuilt.
fn with_clippy(command: &mut Command) -> &mut Command {
    command.env("RUSTC_WORKSPACE_WRAPPER", "clippy-driver").env(
        "CLIPPY_ARGS",
        "-D__CLIPPY_HACKERY__warnings__CLIPPY_HACKERY__",
    )
}

/// `cargo xtask e2e`: only the web build, the browser suite and the glTF validation.
pub fn e2e_command(workspace: &Workspace) -> anyhow::Result<()> {
    let mut steps = Steps::default();
    steps.step("setup", || setup::setup(workspace, Needs::ALL))?;
    let web = steps.step("build-web", || build::build_web(workspace))?;
    browser_checks(workspace, &mut steps, &web, None)?;
    steps.print_summary();
    println!("xtask: browser checks passed");
    Ok(())
}

/// The web build's size budget, the browser suite on each GPU path, and the glTF validator on
/// the exports and on a CLI replay (with the `cli` binary when given, else through `cargo run`).
fn browser_checks(
    workspace: &Workspace,
    steps: &mut Steps,
    web: &WebBuild,
    cli: Option<&Path>,
) -> anyhow::Result<()> {
    let root = &workspace.root;
    steps.step("wasm size budget", || {
        println!(
            "xtask: {} is {} gzipped (budget {})",
            web.wasm.display(),
            format_size(web.wasm_gzip_size),
            format_size(WASM_GZIP_BUDGET)
        );
        if web.wasm_gzip_size > WASM_GZIP_BUDGET {
            bail!(
                "the wasm is {} gzipped, over the {} budget",
                format_size(web.wasm_gzip_size),
                format_size(WASM_GZIP_BUDGET)
            );
        }
        Ok(())
    })?;

    let out = workspace.tests().join("out");
    if out.exists() {
        fs::remove_dir_all(&out).with_context(|| format!("emptying {}", out.display()))?;
    }
    fs::create_dir_all(&out).with_context(|| format!("creating {}", out.display()))?;
    let server = steps.step("start server", || StaticServer::start(&workspace.dist(), 0))?;
    println!("xtask: serving dist/ at {}", server.url());
    for gpu in GPU_PASSES {
        steps.step(&format!("browser suite ({gpu})"), || {
            run(
                &format!("the browser suite on {gpu} (screenshots in tests/out/)"),
                Command::new("node")
                    .current_dir(root)
                    .arg("tests/e2e/run.mjs")
                    .env("SKETCHMESH_URL", server.url())
                    .env("SKETCHMESH_GPU", gpu),
            )
        })?;
    }
    drop(server);

    let replay_glb = out.join("replay.glb");
    let animation_glb = out.join("animation.glb");
    steps.step("cli replay", || {
        for (fixture, glb) in [
            (REPLAY_FIXTURE, &replay_glb),
            (ANIMATION_FIXTURE, &animation_glb),
            (PAINTED_FIXTURE, &out.join("painted.glb")),
        ] {
            let mut command = cli_command(root, cli);
            command.args(["replay", fixture, "-o"]).arg(glb);
            run(&format!("replaying {fixture} with the CLI"), &mut command)?;
        }
        Ok(())
    })?;
    steps.step("STL and OBJ exports in three.js", || {
        check_exports(workspace, &out, cli)
    })?;
    steps.step("three.js playback", || {
        let (duration, frames) = ANIMATION_PLAYBACK;
        run(
            "playing the animation export in three.js",
            Command::new("node")
                .current_dir(root)
                .arg("tests/three-playback.mjs")
                .arg(relative_to(&animation_glb, root))
                .args([duration.to_string(), frames.to_string()]),
        )
    })?;
    steps.step("gltf-validator", || {
        // `exportGlb()`'s file, written on the path that runs every case, must be there.
        let mut files = vec![
            out.join(format!("{}-export.glb", GPU_PASSES[0])),
            replay_glb.clone(),
        ];
        // Also any other .glb the suite wrote.
        for entry in fs::read_dir(&out)? {
            let path = entry?.path();
            if path.extension().is_some_and(|ext| ext == "glb") && !files.contains(&path) {
                files.push(path);
            }
        }
        validate_gltf(workspace, &files)
    })?;

    Ok(())
}

/// A command running the CLI: the `cli` binary when given, else through `cargo run`.
fn cli_command(root: &Path, cli: Option<&Path>) -> Command {
    let mut command = match cli {
        Some(binary) => Command::new(binary),
        None => {
            let mut c = cargo();
            c.args(["run", "-p", "sketchmesh-cli", "--"]);
            c
        }
    };
    command.current_dir(root);
    command
}

/// The CLI converts a real scan ([`EXPORT_SCAN`]) and a replayed session
/// ([`EXPORT_SESSION`]) to STL (mm) and OBJ (m) in `out`, and `tests/check-exports.mjs`
/// reads them with three.js's loaders against the glTF they came from: triangle counts,
/// bounds in the unit, watertightness. The scan is shared test data beside the repository:
/// its absence fails loudly unless `SKETCHMESH_NO_TESTDATA=1` says it is expected.
fn check_exports(workspace: &Workspace, out: &Path, cli: Option<&Path>) -> anyhow::Result<()> {
    let root = &workspace.root;
    let mut cases = Vec::new();
    let scan = root.join(EXPORT_SCAN);
    if scan.is_file() {
        cases.push(("spot", scan.clone()));
    } else if std::env::var_os("SKETCHMESH_NO_TESTDATA").is_some() {
        println!(
            "xtask: WARNING: the shared test data is missing ({} does not exist); SKETCHMESH_NO_TESTDATA is set, so only the session's exports are checked",
            scan.display()
        );
    } else {
        bail!(
            "the shared test data is missing: {} does not exist (set SKETCHMESH_NO_TESTDATA=1 to skip on purpose)",
            scan.display()
        );
    }
    let session_glb = out.join("export-session.glb");
    run(
        &format!("replaying {EXPORT_SESSION} with the CLI"),
        cli_command(root, cli)
            .args(["replay", EXPORT_SESSION, "-o"])
            .arg(&session_glb),
    )?;
    cases.push(("export-session", session_glb));
    let mut json = Vec::new();
    for (name, source) in &cases {
        let mut files = Vec::new();
        for (extension, unit, per_metre) in [("stl", "mm", 1000.0), ("obj", "m", 1.0)] {
            let file = out.join(format!("{name}.{extension}"));
            run(
                &format!(
                    "converting {} to .{extension} with the CLI",
                    source.display()
                ),
                cli_command(root, cli)
                    .arg("convert")
                    .arg(source)
                    .arg("-o")
                    .arg(&file)
                    .args(["--unit", unit]),
            )?;
            files.push(serde_json::json!({
                "path": relative_to(&file, root),
                "per_metre": per_metre,
            }));
        }
        json.push(serde_json::json!({
            "source": relative_to(source, root),
            "watertight": true,
            "files": files,
        }));
    }
    let cases_file = out.join("exports.json");
    fs::write(&cases_file, serde_json::to_string_pretty(&json)?)
        .with_context(|| format!("writing {}", cases_file.display()))?;
    run(
        "reading the STL and OBJ exports with three.js",
        Command::new("node")
            .current_dir(root)
            .arg("tests/check-exports.mjs")
            .arg(relative_to(&cases_file, root)),
    )
}

/// Runs the Khronos glTF validator on `files`; any error or warning (or a missing file) fails.
pub fn validate_gltf(workspace: &Workspace, files: &[PathBuf]) -> anyhow::Result<()> {
    if let Some(missing) = files.iter().find(|file| !file.is_file()) {
        bail!("{} was not written", missing.display());
    }
    let script = workspace.tests().join("validate-gltf.mjs");
    run(
        "gltf-validator",
        Command::new("node")
            .current_dir(&workspace.root)
            .arg(&script)
            .args(files.iter().map(|file| relative_to(file, &workspace.root))),
    )
}

fn relative_to(path: &Path, base: &Path) -> PathBuf {
    path.strip_prefix(base).unwrap_or(path).to_path_buf()
}

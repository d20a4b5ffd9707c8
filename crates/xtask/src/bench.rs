//! `cargo xtask bench`: criterion benches of `sketchmesh-core`, the Laplacian-editing engine
//! side by side with libigl (PyPI, in a venv under the target directory), then page timings
//! in headless Chromium (`tests/e2e/page-bench.mjs`), summarised as markdown in
//! `target/bench-summary.md`.

use std::fmt::Write as _;
use std::fs;
use std::path::Path;
use std::process::Command;
use std::time::SystemTime;

use anyhow::{Context as _, bail};
use serde_json::Value;

use crate::build;
use crate::serve::StaticServer;
use crate::setup::{self, Needs};
use crate::{Steps, Workspace, cargo, format_size, run};

/// Runs the benches and writes the summary.
pub fn bench_command(workspace: &Workspace) -> anyhow::Result<()> {
    let mut steps = Steps::default();
    steps.step("setup", || setup::setup(workspace, Needs::ALL))?;
    let started = SystemTime::now();
    steps.step("cargo bench", || {
        run(
            "cargo bench",
            cargo()
                .current_dir(&workspace.root)
                .args(["bench", "-p", "sketchmesh-core"]),
        )
    })?;
    let mut summary = String::from("# Sketchmesh benchmarks\n\n## sketchmesh-core (criterion)\n\n");
    summary += &criterion_table(&workspace.target_dir.join("criterion"), started)?;
    let libigl = steps.step("libigl comparison", || {
        libigl_comparison(workspace, "deform_export", "libigl_compare.py")
    })?;
    summary += "\n## Laplacian editing against libigl (same mesh, ROI and handles)\n\n";
    summary += &libigl;
    let libigl = steps.step("libigl comparison, optimize", || {
        libigl_comparison(workspace, "optimize_export", "libigl_optimize.py")
    })?;
    summary += "\n## Laplacian mesh optimization against libigl (same normal equations)\n\n";
    summary += &libigl;
    let libigl = steps.step("libigl comparison, feature", || {
        libigl_comparison(workspace, "feature_export", "libigl_feature.py")
    })?;
    summary += "\n## Feature sketching's region system against libigl\n\n";
    summary += &libigl;
    let libigl = steps.step("libigl comparison, volumetric", || {
        libigl_comparison(workspace, "volumetric_export", "libigl_volumetric.py")
    })?;
    summary += "\n## The volumetric graph Laplacian's frame against libigl\n\n";
    summary += &libigl;

    let web = steps.step("build-web", || build::build_web(workspace))?;
    let (pulls, torus, bar, capsule) = steps.step("fixtures", || bench_fixtures(workspace))?;
    let server = steps.step("start server", || StaticServer::start(&workspace.dist(), 0))?;
    let page = steps.step("page bench", || {
        let out = Command::new("node")
            .current_dir(&workspace.root)
            .arg("tests/e2e/page-bench.mjs")
            .env("SKETCHMESH_URL", server.url())
            .env("SKETCHMESH_GPU", "webgl2")
            .env("SKETCHMESH_PULL_FIXTURES", &pulls)
            .env("SKETCHMESH_OVERSKETCH_FIXTURE", &torus)
            .env("SKETCHMESH_BEND_FIXTURE", &bar)
            .env("SKETCHMESH_POSE_FIXTURE", &capsule)
            .env(
                "SKETCHMESH_OPTIMIZE_FIXTURE",
                workspace.root.join(OPTIMIZE_SCAN),
            )
            .output()
            .context("starting node tests/e2e/page-bench.mjs")?;
        eprint!("{}", String::from_utf8_lossy(&out.stderr));
        if !out.status.success() {
            bail!("page-bench.mjs failed ({})", out.status);
        }
        let text = String::from_utf8_lossy(&out.stdout);
        // The report is the last line; earlier lines are progress.
        let last = text.lines().rev().find(|line| !line.trim().is_empty());
        serde_json::from_str::<Value>(last.unwrap_or_default())
            .with_context(|| format!("page-bench.mjs printed no JSON report:\n{text}"))
    })?;
    drop(server);
    summary += "\n## Page (the shipped build; headless Chromium)\n\n";
    summary += &page_table(&page, web.wasm_gzip_size);

    let file = workspace.target_dir.join("bench-summary.md");
    fs::write(&file, &summary).with_context(|| format!("writing {}", file.display()))?;
    println!("\n{summary}");
    println!("xtask: written to {}", file.display());
    steps.print_summary();
    Ok(())
}

/// The Python packages of the libigl comparison, pinned so that runs compare alike.
const LIBIGL_PACKAGES: &[&str] = &["libigl==2.6.3", "numpy<3", "scipy<2"];

/// One of our solves (`examples/<example>.rs`, which writes the problem and our solution) and
/// libigl's `min_quad_with_fixed` on the same problem (`benches/<script>`, which fails when
/// the solutions differ by more than 1e-6 of the diagonal): both programs' reports, as
/// markdown lines. The problems: the linear exact-handle Laplacian edit (`deform_export`,
/// `libigl_compare.py`), the Laplacian mesh optimization (`optimize_export`,
/// `libigl_optimize.py`) and feature sketching's region system (`feature_export`,
/// `libigl_feature.py`).
fn libigl_comparison(workspace: &Workspace, example: &str, script: &str) -> anyhow::Result<String> {
    let venv = workspace.target_dir.join("libigl-venv");
    let python = venv.join("bin/python");
    if !python.exists() {
        run(
            "creating the libigl venv",
            Command::new("python3").arg("-m").arg("venv").arg(&venv),
        )?;
        run(
            "installing libigl from PyPI",
            Command::new(&python)
                .args(["-m", "pip", "install", "--quiet"])
                .args(LIBIGL_PACKAGES),
        )?;
    }
    let problem = workspace.target_dir.join(format!("libigl-{example}"));
    let ours = cargo()
        .current_dir(&workspace.root)
        .args(["run", "--release", "-q", "-p", "sketchmesh-core"])
        .args(["--example", example, "--"])
        .arg(&problem)
        .output()
        .with_context(|| format!("running the {example} example"))?;
    let theirs = Command::new(&python)
        .current_dir(&workspace.root)
        .arg(format!("crates/core/benches/{script}"))
        .arg(&problem)
        .output()
        .with_context(|| format!("running benches/{script}"))?;
    let report = [&ours.stdout, &theirs.stdout]
        .iter()
        .flat_map(|out| {
            String::from_utf8_lossy(out)
                .lines()
                .map(str::to_owned)
                .collect::<Vec<_>>()
        })
        .filter(|line| !line.starts_with("wrote "))
        .fold(String::new(), |mut text, line| {
            let _ = writeln!(text, "- {line}");
            text
        });
    eprint!(
        "{}{}",
        String::from_utf8_lossy(&ours.stderr),
        String::from_utf8_lossy(&theirs.stderr)
    );
    if !ours.status.success() || !theirs.status.success() {
        bail!("the libigl comparison failed:\n{report}");
    }
    Ok(report)
}

/// One markdown row per criterion benchmark measured since `since`.
fn criterion_table(criterion: &Path, since: SystemTime) -> anyhow::Result<String> {
    let mut rows = Vec::new();
    let mut dirs = vec![criterion.to_path_buf()];
    while let Some(dir) = dirs.pop() {
        let Ok(entries) = fs::read_dir(&dir) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            if !path.is_dir() {
                continue;
            }
            if path.file_name().is_some_and(|name| name == "new") {
                if let Some(row) = criterion_row(criterion, &path, since)? {
                    rows.push(row);
                }
            } else {
                dirs.push(path);
            }
        }
    }
    if rows.is_empty() {
        bail!("no criterion results under {}", criterion.display());
    }
    // Numeric parameters in numeric order: factor/1024 before factor/10000.
    rows.sort_by_cached_key(|row| {
        let id = row.split('|').nth(1).unwrap_or_default().trim();
        id.split('/')
            .map(|part| (part.parse::<u64>().ok(), part.to_owned()))
            .collect::<Vec<_>>()
    });
    let mut table = String::from(
        "| benchmark | mean | 95% interval of the mean | median |\n| --- | ---: | ---: | ---: |\n",
    );
    for row in rows {
        table += &row;
    }
    Ok(table)
}

fn criterion_row(
    criterion: &Path,
    new: &Path,
    since: SystemTime,
) -> anyhow::Result<Option<String>> {
    let estimates_file = new.join("estimates.json");
    let fresh = estimates_file
        .metadata()
        .and_then(|meta| meta.modified())
        .is_ok_and(|modified| modified >= since);
    if !fresh {
        return Ok(None);
    }
    let estimates = read_json(&estimates_file)?;
    let id = read_json(&new.join("benchmark.json"))
        .ok()
        .and_then(|bench| bench["full_id"].as_str().map(str::to_owned))
        .unwrap_or_else(|| {
            let dir = new.parent().unwrap_or(new);
            dir.strip_prefix(criterion)
                .unwrap_or(dir)
                .display()
                .to_string()
        });
    let ns = |pointer: &str| estimates.pointer(pointer).and_then(Value::as_f64);
    let (Some(mean), Some(low), Some(high), Some(median)) = (
        ns("/mean/point_estimate"),
        ns("/mean/confidence_interval/lower_bound"),
        ns("/mean/confidence_interval/upper_bound"),
        ns("/median/point_estimate"),
    ) else {
        bail!("unexpected layout of {}", estimates_file.display());
    };
    Ok(Some(format!(
        "| {id} | {} | {} .. {} | {} |\n",
        format_ns(mean),
        format_ns(low),
        format_ns(high),
        format_ns(median)
    )))
}

fn read_json(file: &Path) -> anyhow::Result<Value> {
    let text = fs::read_to_string(file).with_context(|| format!("reading {}", file.display()))?;
    serde_json::from_str(&text).with_context(|| format!("parsing {}", file.display()))
}

fn format_ns(ns: f64) -> String {
    if ns < 1e3 {
        format!("{ns:.1} ns")
    } else if ns < 1e6 {
        format!("{:.2} µs", ns / 1e3)
    } else if ns < 1e9 {
        format!("{:.2} ms", ns / 1e6)
    } else {
        format!("{:.3} s", ns / 1e9)
    }
}

/// Vertex counts of the shapes whose curves the page bench pulls.
const PULL_SIZES: [usize; 2] = [10_000, 40_000];

/// The page bench's fixtures as .glb files (the page makes shapes at its default resolution
/// only): FiberMesh shapes of [`PULL_SIZES`] vertices to pull, comma-separated, and the
/// bumpy torus to over-sketch, the bar to bend and the capsule to pose.
fn bench_fixtures(workspace: &Workspace) -> anyhow::Result<(String, String, String, String)> {
    let dir = workspace.target_dir.join("bench-fixtures");
    fs::create_dir_all(&dir).with_context(|| format!("creating {}", dir.display()))?;
    let fixture = |args: &[&str]| {
        run(
            "fixture_glb example",
            cargo()
                .current_dir(&workspace.root)
                .args(["run", "--release", "-q", "-p", "sketchmesh-core"])
                .args(["--example", "fixture_glb", "--"])
                .args(args),
        )
    };
    let mut pulls = Vec::new();
    for size in PULL_SIZES {
        let path = dir.join(format!("fibermesh-{size}.glb"));
        let path = path.to_string_lossy().into_owned();
        fixture(&["fibermesh", &size.to_string(), &path])?;
        pulls.push(path);
    }
    let torus = dir.join("bumpy-torus.glb").to_string_lossy().into_owned();
    fixture(&["bumpy-torus", &torus])?;
    let bar = dir.join("bar.glb").to_string_lossy().into_owned();
    fixture(&["bar", &bar])?;
    let capsule = dir.join("capsule.glb").to_string_lossy().into_owned();
    fixture(&["capsule", &capsule])?;
    Ok((pulls.join(","), torus, bar, capsule))
}

/// The scan the page bench optimizes (the shared test data, beside the repository; the page
/// bench says so loudly when it is missing).
const OPTIMIZE_SCAN: &str = "../shared/testdata/meshes/stanford_bunny.glb";

/// The page-bench JSON report as a markdown table.
fn page_table(page: &Value, wasm_gzip_size: u64) -> String {
    let ms = |pointer: &str| {
        page.pointer(pointer)
            .and_then(Value::as_f64)
            .map_or_else(|| "n/a".to_owned(), |ms| format!("{ms:.1} ms"))
    };
    let text = |pointer: &str| {
        page.pointer(pointer).map_or_else(
            || "n/a".to_owned(),
            |value| value.to_string().replace('"', ""),
        )
    };
    let mut table = String::from("| measure | value |\n| --- | ---: |\n");
    let rows = [
        ("wasm, gzip -9", format_size(wasm_gzip_size)),
        ("GPU backend", text("/backend")),
        ("time to interactive", ms("/time_to_interactive_ms")),
        ("frames while stroking", text("/stroke/frames")),
        ("frame time, mean", ms("/stroke/frame_ms/mean")),
        ("frame time, median", ms("/stroke/frame_ms/p50")),
        ("frame time, 95th percentile", ms("/stroke/frame_ms/p95")),
        ("frame time, max", ms("/stroke/frame_ms/max")),
        ("import .glb, triangles", text("/import_glb/triangles")),
        ("import .glb, time in page", ms("/import_glb/ms")),
    ];
    let pulls = page.pointer("/pulls").and_then(Value::as_array);
    let pull_rows = pulls.into_iter().flatten().flat_map(|pull| {
        let vertices = pull
            .pointer("/vertices")
            .map_or(0, |v| v.as_u64().unwrap_or(0));
        let ms = |pointer: &str| {
            pull.pointer(pointer)
                .and_then(Value::as_f64)
                .map_or_else(|| "n/a".to_owned(), |ms| format!("{ms:.1} ms"))
        };
        [
            (
                format!("pull at {vertices} vertices, frame mean"),
                ms("/frame_ms/mean"),
            ),
            (
                format!("pull at {vertices} vertices, frame 95th percentile"),
                ms("/frame_ms/p95"),
            ),
            (
                format!("pull at {vertices} vertices, frame max"),
                ms("/frame_ms/max"),
            ),
            (
                format!("pull at {vertices} vertices, preview in the worker, median"),
                ms("/preview_ms/p50"),
            ),
            (
                format!("pull at {vertices} vertices, preview in the worker, max"),
                ms("/preview_ms/max"),
            ),
            (
                format!("pull at {vertices} vertices, grab (pointer-down)"),
                ms("/grab_ms"),
            ),
            (
                format!("pull at {vertices} vertices, release: in the page's frames"),
                ms("/release_ms"),
            ),
            (
                format!("pull at {vertices} vertices, release: in the worker, the page drawing"),
                ms("/release_worker_ms"),
            ),
            (
                format!("cut at {vertices} vertices, the op in the worker"),
                ms("/cut_worker_ms"),
            ),
            (
                format!("tunnel at {vertices} vertices, the op in the worker"),
                ms("/tunnel_worker_ms"),
            ),
            (
                format!("extrude at {vertices} vertices, the op in the worker"),
                ms("/extrude_worker_ms"),
            ),
            (
                format!("merge of two {vertices}-vertex shapes, replayed op"),
                ms("/merge_ms"),
            ),
        ]
    });
    let vertices = text("/oversketch/vertices");
    let oversketch_rows = [
        (
            format!("over-sketch at {vertices} vertices, release to result shown"),
            ms("/oversketch/release_to_shown_ms"),
        ),
        (
            format!("over-sketch at {vertices} vertices, the op alone"),
            ms("/oversketch/op_ms"),
        ),
    ];
    let vertices = text("/optimize/vertices");
    let optimize_rows = [
        (
            format!("optimize at {vertices} vertices, tap: in the frame"),
            ms("/optimize/first_ms"),
        ),
        (
            format!(
                "optimize at {vertices} vertices, tap to first preview in the worker (weights, factor, solve)"
            ),
            ms("/optimize/first_preview_ms"),
        ),
        (
            format!("optimize at {vertices} vertices, slider: frame's own work, max"),
            ms("/optimize/step_ms/max"),
        ),
        (
            format!("optimize at {vertices} vertices, slider: preview in the worker, median"),
            ms("/optimize/preview_ms/p50"),
        ),
        (
            format!("optimize at {vertices} vertices, Apply: in the frame"),
            ms("/optimize/apply_ms"),
        ),
        (
            format!("optimize at {vertices} vertices, Apply: in the worker (exact solve)"),
            ms("/optimize/apply_worker_ms"),
        ),
    ];
    let feature_rows = [
        (
            "feature (bump on the bunny), first drag step (place, embed, factor, solve)",
            ms("/feature/first_ms"),
        ),
        (
            "feature, drag step (solutions re-weighed), median",
            ms("/feature/step_ms/p50"),
        ),
        ("feature, drag step, max", ms("/feature/step_ms/max")),
        (
            "feature, frame while dragging, median",
            ms("/feature/drag_frame_ms/p50"),
        ),
        (
            "feature, frame while dragging, max",
            ms("/feature/drag_frame_ms/max"),
        ),
        (
            "region (lift on the bunny), first drag step (place, weigh)",
            ms("/region/first_ms"),
        ),
        (
            "region, drag step (the region moved), median",
            ms("/region/step_ms/p50"),
        ),
        ("region, drag step, max", ms("/region/step_ms/max")),
        (
            "region, frame while dragging, median",
            ms("/region/drag_frame_ms/p50"),
        ),
        (
            "bend (handle on a 500k bar), handle placed",
            ms("/bend/place_ms"),
        ),
        (
            "bend, first drag step (every vertex bound)",
            ms("/bend/first_ms"),
        ),
        (
            "bend, drag step (every vertex rebuilt), median",
            ms("/bend/step_ms/p50"),
        ),
        ("bend, drag step, max", ms("/bend/step_ms/max")),
        (
            "bend, frame while dragging, median",
            ms("/bend/drag_frame_ms/p50"),
        ),
        ("bend, release to committed", ms("/bend/apply_ms")),
        (
            "pose (curve on a capsule, 28.6k graph points), first step (curve picked, graph)",
            ms("/pose/first_ms"),
        ),
        ("pose, drag step in the frame, max", ms("/pose/step_ms/max")),
        (
            "pose, drag step in the frame, median",
            ms("/pose/step_ms/p50"),
        ),
        (
            "pose, preview in the worker (graph, factor, then back-substitutions), median",
            ms("/pose/preview_ms/p50"),
        ),
        (
            "pose, preview in the worker, max",
            ms("/pose/preview_ms/max"),
        ),
        (
            "pose, frame while drawing, median",
            ms("/pose/drag_frame_ms/p50"),
        ),
        ("pose, release to committed", ms("/pose/apply_ms")),
        ("pose, the commit in the worker", ms("/pose/worker_ms")),
        (
            "Move tool drag of 100k triangles, frame interval, median",
            ms("/gizmo/interval_ms/p50"),
        ),
        (
            "Move tool drag of 100k triangles, the app's time per drag step, max",
            ms("/gizmo/drag_frame_ms/max"),
        ),
    ]
    .map(|(name, value)| (name.to_owned(), value));
    let rows = rows
        .into_iter()
        .map(|(name, value)| (name.to_owned(), value))
        .chain(pull_rows)
        .chain(oversketch_rows)
        .chain(optimize_rows)
        .chain(feature_rows);
    for (name, value) in rows {
        // Writing to a String cannot fail.
        let _ = writeln!(table, "| {name} | {value} |");
    }
    table
}

#[cfg(test)]
mod tests {
    use super::*;

    fn temp_path(name: &str) -> std::path::PathBuf {
        std::env::temp_dir().join(format!("xtask-bench-{}-{name}", std::process::id()))
    }

    #[test]
    fn nanoseconds_pick_a_unit() {
        assert_eq!(format_ns(512.0), "512.0 ns");
        assert_eq!(format_ns(1_500.0), "1.50 µs");
        assert_eq!(format_ns(2_250_000.0), "2.25 ms");
        assert_eq!(format_ns(3.5e9), "3.500 s");
    }

    #[test]
    fn criterion_results_become_rows() {
        let root = temp_path("criterion");
        let before = SystemTime::now() - std::time::Duration::from_secs(5);
        let small = root.join("solve").join("factor").join("200").join("new");
        fs::create_dir_all(&small).unwrap();
        fs::write(
            small.join("estimates.json"),
            r#"{"mean":{"confidence_interval":{"lower_bound":1.0,"upper_bound":3.0},"point_estimate":2.0},
                "median":{"point_estimate":2.0}}"#,
        )
        .unwrap();
        let new = root.join("solve").join("factor").join("1000").join("new");
        fs::create_dir_all(&new).unwrap();
        fs::write(
            new.join("estimates.json"),
            r#"{"mean":{"confidence_interval":{"confidence_level":0.95,"lower_bound":1900.0,"upper_bound":2100.0},"point_estimate":2000.0,"standard_error":50.0},
                "median":{"confidence_interval":{"confidence_level":0.95,"lower_bound":1.0,"upper_bound":2.0},"point_estimate":1950.0,"standard_error":1.0}}"#,
        )
        .unwrap();
        fs::write(
            new.join("benchmark.json"),
            r#"{"group_id":"solve","function_id":"factor","value_str":"1000","full_id":"solve/factor/1000"}"#,
        )
        .unwrap();
        let table = criterion_table(&root, before).unwrap();
        assert!(
            table.contains("| solve/factor/1000 | 2.00 µs | 1.90 µs .. 2.10 µs | 1.95 µs |"),
            "{table}"
        );
        let small = table.find("| solve/factor/200 |").unwrap();
        let large = table.find("solve/factor/1000 ").unwrap();
        assert!(small < large, "numeric order: {table}");
        // Results older than the run are left out.
        let later = SystemTime::now() + std::time::Duration::from_secs(60);
        assert!(criterion_table(&root, later).is_err());
        fs::remove_dir_all(&root).unwrap();
    }

    #[test]
    fn page_report_becomes_a_table() {
        let page: Value = serde_json::from_str(
            r#"{"backend":"WebGL2","time_to_interactive_ms":1834.26,
                "stroke":{"frames":60,"frame_ms":{"mean":16.7,"p50":16.6,"p95":18.0,"max":33.4}},
                "import_glb":{"triangles":1002528,"ms":912.34}}"#,
        )
        .unwrap();
        let table = page_table(&page, 2_000_000);
        assert!(table.contains("| GPU backend | WebGL2 |"), "{table}");
        assert!(
            table.contains("| time to interactive | 1834.3 ms |"),
            "{table}"
        );
        assert!(
            table.contains("| frame time, 95th percentile | 18.0 ms |"),
            "{table}"
        );
        assert!(table.contains("| frames while stroking | 60 |"), "{table}");
        assert!(
            table.contains("| import .glb, time in page | 912.3 ms |"),
            "{table}"
        );
    }
}

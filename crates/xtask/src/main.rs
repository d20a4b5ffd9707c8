//! Helper tasks for Sketchmesh, run as `cargo xtask <command>` (the alias lives in
//! `.cargo/config.toml`), after egui's `xtask/src/main.rs`.
//!
//! `setup` installs what the other commands need, `build-web` builds the wasm page into `dist/`,
//! `serve` ships it on <http://127.0.0.1:8080/>, `test` runs every check CI runs (`.ci/run`),
//! `bench` runs the criterion benches plus a page timing in headless Chromium, `fuzz`
//! fuzzes the glTF importer, `docs` checks the names the docs give in backticks, and `layers`
//! checks the imports against ARCHITECTURE.md's layers.

// Tests may unwrap: a panic is a test failure with a location.
#![cfg_attr(test, allow(clippy::unwrap_used))]

mod bench;
mod build;
mod doc_check;
mod fuzz;
mod guide_page;
mod layers;
mod serve;
mod setup;
mod test;

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

use anyhow::{Context as _, bail};

const HELP: &str = "\
Usage: cargo xtask <command>

Commands:
  setup                        Install the wasm target, Chromium and the npm test tools (idempotent)
  build-web                    Build the page into dist/: release profile, wasm-opt -O1 (cached);
                               the one build that is served, tested and benchmarked
  serve [--port N]             Build the page, then serve dist/ on http://127.0.0.1:8080/
                               (or port N)
  test                         fmt, doc references, clippy, native tests, wasm build, browser suite
                               (WebGL2 and WebGPU), glTF validation: everything CI runs
  docs                         Check that the paths and items ARCHITECTURE.md and docs/guide.md
                               name in backticks exist
  e2e                          Only the web build, the browser suite and glTF validation
  bench                        Criterion benches of sketchmesh-core plus page timings in Chromium;
                               summary in target/bench-summary.md
  fuzz [--seconds N]           Fuzz the glTF importer with cargo-fuzz for N seconds (default 60)
  layers                       Check the imports of crates/core and crates/app against the layer
                               tables in ARCHITECTURE.md, and that no files import each other
";

fn main() {
    if let Err(err) = try_main() {
        eprintln!("xtask: error: {err:#}");
        std::process::exit(1);
    }
}

fn try_main() -> anyhow::Result<()> {
    let arg_strings: Vec<String> = std::env::args().skip(1).collect();
    let args: Vec<&str> = arg_strings.iter().map(String::as_str).collect();
    let workspace = Workspace::locate();

    match args.as_slice() {
        [] | ["-h" | "--help" | "help"] => {
            print!("{HELP}");
            Ok(())
        }
        ["setup"] => setup::setup(&workspace, setup::Needs::ALL),
        ["build-web"] => build::build_web(&workspace).map(drop),
        ["serve", options @ ..] => serve::serve_command(&workspace, options),
        ["test"] => test::test_command(&workspace),
        ["docs"] => doc_check::docs_command(&workspace),
        ["e2e"] => test::e2e_command(&workspace),
        ["bench"] => bench::bench_command(&workspace),
        ["fuzz", options @ ..] => fuzz::fuzz_command(&workspace, options),
        ["layers"] => layers::layers_command(&workspace),
        other => bail!("unknown arguments {other:?}\n\n{HELP}"),
    }
}

/// Where things are: the workspace root and the cargo target directory.
pub struct Workspace {
    /// The repository root (holds the workspace `Cargo.toml`).
    pub root: PathBuf,
    /// `$CARGO_TARGET_DIR`, or `<root>/target`.
    pub target_dir: PathBuf,
}

impl Workspace {
    fn locate() -> Self {
        // crates/xtask -> repository root.
        let root = Path::new(env!("CARGO_MANIFEST_DIR"))
            .ancestors()
            .nth(2)
            .unwrap_or(Path::new("."))
            .to_path_buf();
        let target_dir = match std::env::var_os("CARGO_TARGET_DIR") {
            Some(dir) if !dir.is_empty() => {
                let dir = PathBuf::from(dir);
                if dir.is_absolute() {
                    dir
                } else {
                    root.join(dir)
                }
            }
            _ => root.join("target"),
        };
        Self { root, target_dir }
    }

    /// `dist/`, the web page as served.
    pub fn dist(&self) -> PathBuf {
        self.root.join("dist")
    }

    /// `tests/`, the npm package with the browser suite.
    pub fn tests(&self) -> PathBuf {
        self.root.join("tests")
    }

    /// A binary from `tests/node_modules/.bin`.
    pub fn node_bin(&self, name: &str) -> PathBuf {
        self.tests().join("node_modules").join(".bin").join(name)
    }
}

/// A `cargo` command, using the cargo that runs this xtask.
pub fn cargo() -> Command {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| env!("CARGO").into());
    Command::new(cargo)
}

/// Runs `cmd` with inherited stdio and fails with `what` unless it exits successfully.
pub fn run(what: &str, cmd: &mut Command) -> anyhow::Result<()> {
    println!("xtask: $ {}", display_command(cmd));
    let status = cmd
        .status()
        .with_context(|| format!("{what}: could not start `{}`", display_command(cmd)))?;
    if !status.success() {
        bail!("{what} failed ({status}): `{}`", display_command(cmd));
    }
    Ok(())
}

/// Runs `cmd` quietly and returns its stdout, or `None` when it cannot start or fails.
pub fn output_of(cmd: &mut Command) -> Option<String> {
    let out = cmd.output().ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).into_owned())
}

fn display_command(cmd: &Command) -> String {
    let mut text = cmd.get_program().to_string_lossy().into_owned();
    for arg in cmd.get_args() {
        text.push(' ');
        text.push_str(&arg.to_string_lossy());
    }
    text
}

/// `1234567` -> `"1.23 MB (1234567 B)"`.
pub fn format_size(bytes: u64) -> String {
    format!("{:.2} MB ({bytes} B)", bytes as f64 / 1e6)
}

/// `83.4 s`, `2 min 05 s`.
pub fn format_duration(duration: Duration) -> String {
    let secs = duration.as_secs_f64();
    if secs < 60.0 {
        format!("{secs:.1} s")
    } else {
        let whole = duration.as_secs();
        format!("{} min {:02} s", whole / 60, whole % 60)
    }
}

/// Times named steps and prints a summary table.
#[derive(Default)]
pub struct Steps {
    done: Vec<(String, Duration)>,
}

impl Steps {
    /// Runs one step, prints its banner and records its time; a failure names the step.
    pub fn step<T>(
        &mut self,
        name: &str,
        body: impl FnOnce() -> anyhow::Result<T>,
    ) -> anyhow::Result<T> {
        println!("\n==== xtask: {name} ====");
        let start = Instant::now();
        let result = body();
        let elapsed = start.elapsed();
        match result {
            Ok(value) => {
                println!(
                    "==== xtask: {name}: ok in {} ====",
                    format_duration(elapsed)
                );
                self.done.push((name.to_owned(), elapsed));
                Ok(value)
            }
            Err(err) => {
                self.print_summary();
                println!("FAILED  {name} after {}", format_duration(elapsed));
                Err(err.context(format!("step `{name}` failed")))
            }
        }
    }

    /// Prints each finished step with its time, and the total.
    pub fn print_summary(&self) {
        println!("\n==== xtask summary ====");
        let width = self
            .done
            .iter()
            .map(|(name, _)| name.len())
            .max()
            .unwrap_or(0);
        for (name, elapsed) in &self.done {
            println!("ok      {name:<width$}  {}", format_duration(*elapsed));
        }
        let total: Duration = self.done.iter().map(|(_, elapsed)| *elapsed).sum();
        println!("total   {:<width$}  {}", "", format_duration(total));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn durations_read_well() {
        assert_eq!(format_duration(Duration::from_millis(8_400)), "8.4 s");
        assert_eq!(format_duration(Duration::from_secs(125)), "2 min 05 s");
    }

    #[test]
    fn sizes_show_megabytes_and_bytes() {
        assert_eq!(format_size(2_435_734), "2.44 MB (2435734 B)");
    }

    #[test]
    fn workspace_root_holds_the_workspace_manifest() {
        let workspace = Workspace::locate();
        assert!(workspace.root.join("Cargo.toml").is_file());
        assert!(workspace.root.join("crates").join("xtask").is_dir());
    }
}

//! The `sketchmesh` command: replay sessions headlessly and inspect glTF files.
//!
//! Arguments are matched by hand on the argument slice (as egui's xtask does); any refusal
//! prints one sentence on stderr and exits with status 1.

use std::io::Write as _;
use std::path::Path;
use std::process::ExitCode;

use anyhow::{Context as _, bail};
use sketchmesh_core::document::Editor;
use sketchmesh_core::io::{inspect_glb, write_glb};

const USAGE: &str = "\
Usage:
  sketchmesh replay SESSION.json -o OUT.glb   Replay a session and write the document as glTF.
  sketchmesh info FILE.glb                    Print what a glTF file contains, as JSON.
  sketchmesh --help                           Show this help.

Session files are described in docs/session-format.md.";

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match try_main(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("sketchmesh: {error:#}");
            ExitCode::FAILURE
        }
    }
}

fn try_main(args: &[String]) -> anyhow::Result<()> {
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    match args.as_slice() {
        [] | ["--help" | "-h" | "help"] => print_out(USAGE),
        ["replay", session, "-o", out] | ["replay", "-o", out, session] => {
            replay(Path::new(session), Path::new(out))
        }
        ["info", file] => info(Path::new(file)),
        _ => bail!("I don't understand the arguments {args:?}.\n{USAGE}"),
    }
}

fn replay(session_path: &Path, out_path: &Path) -> anyhow::Result<()> {
    let json = std::fs::read_to_string(session_path)
        .with_context(|| format!("Could not read the session file {}", session_path.display()))?;
    let editor = Editor::replay_json(&json)
        .with_context(|| format!("Could not replay {}", session_path.display()))?;
    let bytes = write_glb(editor.document());
    std::fs::write(out_path, &bytes)
        .with_context(|| format!("Could not write {}", out_path.display()))?;
    let stats = editor.document().stats();
    print_out(&format!(
        "Replayed {} ops: {} models, {} vertices, {} triangles, {} curves; wrote {} ({} bytes).",
        editor.ops().len(),
        stats.models,
        stats.vertices,
        stats.triangles,
        stats.curves,
        out_path.display(),
        bytes.len()
    ))
}

fn info(path: &Path) -> anyhow::Result<()> {
    let bytes =
        std::fs::read(path).with_context(|| format!("Could not read {}", path.display()))?;
    let info = inspect_glb(&bytes)
        .with_context(|| format!("Could not read {} as glTF", path.display()))?;
    print_out(&serde_json::to_string_pretty(&info)?)
}

/// Prints a line on stdout; a closed pipe (`sketchmesh info x.glb | head`) is not an error.
fn print_out(text: &str) -> anyhow::Result<()> {
    match writeln!(std::io::stdout(), "{text}") {
        Err(error) if error.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        result => result.context("Could not write to standard output"),
    }
}

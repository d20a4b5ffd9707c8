//! The `sketchmesh` command: replay sessions headlessly, convert glTF files to glTF, STL or
//! OBJ, check them for printing, inspect and optimize them.
//!
//! Arguments are matched by hand on the argument slice (as egui's xtask does); any refusal
//! prints one sentence on stderr and exits with status 1 (`check` says 1 for "not printable",
//! so its refusals exit with 2).

mod check;
mod export;
mod optimize;

use std::io::Write as _;
use std::path::Path;
use std::process::ExitCode;

use anyhow::{Context as _, bail};
use std::sync::Arc;

use sketchmesh_core::document::{Editor, FileInput, ImportInput, Op, Session};
use sketchmesh_core::io::{ImportFile, inspect_gltf, referenced_files};

use export::Output;

const USAGE: &str = "\
Usage:
  sketchmesh replay SESSION.json -o OUT.glb|OUT.stl|OUT.obj [--unit mm|cm|m|in]
                                              Replay a session and write the document.
  sketchmesh convert IN.glb|IN.gltf -o OUT.glb|OUT.stl|OUT.obj [--unit mm|cm|m|in]
                                              Import a glTF file and export it as Sketchmesh
                                              does: the file type follows OUT's extension
                                              (an .obj gets its .mtl beside it); STL is in
                                              mm and OBJ in m unless --unit says otherwise.
  sketchmesh check IN.glb|IN.gltf|SESSION.json [--min-wall W] [--unit mm|cm|m|in]
                                              Check every model for 3D printing: closed and
                                              manifold, self-intersections, the thinnest wall
                                              against a minimum of W (in --unit, 1 mm by
                                              default) and the size. Exits with 0 when
                                              printable, 1 when not, 2 when it cannot check.
  sketchmesh info FILE.glb|FILE.gltf          Print what a glTF file contains, as JSON.
  sketchmesh optimize IN.glb -o OUT.glb [--mode shape|smooth] [--weights const|linear|cdf]
      [--scale S] [--laplacian uniform|cotan|cotan-curvature] [--tangent-plane] [--quality]
      [--features [--feature-falloff linear|cdf|gaussian]] [--report]
                                              Laplacian mesh optimization of every model;
                                              --report prints radius ratios and the
                                              Hausdorff distance as JSON.
  sketchmesh --help                           Show this help.

A .gltf file's .bin and image files are read from beside it. Import ops in a session
that carry only a file name read that file from beside the session.
Session files are described in docs/session-format.md.";

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match try_main(&args) {
        Ok(code) => code,
        Err(error) => {
            eprintln!("sketchmesh: {error:#}");
            ExitCode::FAILURE
        }
    }
}

fn try_main(args: &[String]) -> anyhow::Result<ExitCode> {
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    match args.as_slice() {
        [] | ["--help" | "-h" | "help"] => print_out(USAGE),
        ["replay", session, "-o", out, options @ ..]
        | ["replay", "-o", out, session, options @ ..] => {
            replay(Path::new(session), &output(out, options)?)
        }
        ["convert", input, "-o", out, options @ ..]
        | ["convert", "-o", out, input, options @ ..] => {
            convert(Path::new(input), &output(out, options)?)
        }
        ["check", rest @ ..] => return Ok(check::run(rest)),
        ["info", file] => info(Path::new(file)),
        ["optimize", rest @ ..] => optimize::run(rest),
        _ => bail!("I don't understand the arguments {args:?}.\n{USAGE}"),
    }
    .map(|()| ExitCode::SUCCESS)
}

/// The output file `out` with the options after it (only `--unit U`), checked before any
/// work is done.
fn output(out: &str, options: &[&str]) -> anyhow::Result<Output> {
    let unit = match options {
        [] => None,
        ["--unit", unit] => Some(*unit),
        _ => {
            bail!("I don't understand the options {options:?}; the only one is --unit mm|cm|m|in.")
        }
    };
    Output::new(Path::new(out), unit)
}

fn replay(session_path: &Path, out: &Output) -> anyhow::Result<()> {
    let editor = replay_session(session_path)?;
    let what = format!("Replayed {} ops", editor.ops().len());
    write_document(&editor, out, &what)
}

/// The editor after replaying the session file at `session_path`, with the files it
/// imports read from beside it.
fn replay_session(session_path: &Path) -> anyhow::Result<Editor> {
    let json = std::fs::read_to_string(session_path)
        .with_context(|| format!("Could not read the session file {}", session_path.display()))?;
    let mut session = Session::from_json(&json)
        .with_context(|| format!("Could not replay {}", session_path.display()))?;
    load_import_files(
        &mut session,
        session_path.parent().unwrap_or(Path::new(".")),
    )?;
    Editor::replay(&session).with_context(|| format!("Could not replay {}", session_path.display()))
}

/// Fills in the contents of import files the session names without carrying them.
fn load_import_files(session: &mut Session, dir: &Path) -> anyhow::Result<()> {
    let files = session.ops.iter_mut().flat_map(|op| match op {
        Op::Import(input) => input.files.iter_mut(),
        _ => [].iter_mut(),
    });
    for file in files.filter(|file| file.data.is_none()) {
        let path = dir.join(&file.name);
        let bytes = std::fs::read(&path).with_context(|| {
            format!(
                "Could not read {}, which the session imports",
                path.display()
            )
        })?;
        file.data = Some(Arc::new(bytes));
    }
    Ok(())
}

/// Reads a glTF file and the files it refers to from beside it (missing ones are left for
/// the importer to name).
fn read_gltf(path: &Path) -> anyhow::Result<Vec<FileInput>> {
    let bytes =
        std::fs::read(path).with_context(|| format!("Could not read {}", path.display()))?;
    let dir = path.parent().unwrap_or(Path::new("."));
    let mut files = vec![FileInput {
        name: path
            .file_name()
            .map_or_else(String::new, |n| n.to_string_lossy().into_owned()),
        data: None,
    }];
    files.extend(referenced_files(&bytes).into_iter().filter_map(|name| {
        let data = std::fs::read(dir.join(&name)).ok()?;
        Some(FileInput {
            name,
            data: Some(Arc::new(data)),
        })
    }));
    files[0].data = Some(Arc::new(bytes));
    Ok(files)
}

fn convert(in_path: &Path, out: &Output) -> anyhow::Result<()> {
    let editor = import_gltf_file(in_path)?;
    let what = format!("Converted {}", in_path.display());
    write_document(&editor, out, &what)
}

/// An editor holding what the glTF file at `path` (and the files beside it) imports to.
fn import_gltf_file(path: &Path) -> anyhow::Result<Editor> {
    let files = read_gltf(path)?;
    let mut editor = Editor::new();
    editor
        .apply(Op::Import(ImportInput {
            files,
            beside: false,
        }))
        .with_context(|| format!("Could not import {}", path.display()))?;
    Ok(editor)
}

/// Writes the document as `out` says and prints one line saying what is in it.
fn write_document(editor: &Editor, out: &Output, what: &str) -> anyhow::Result<()> {
    let written = out.write(editor.document())?;
    let stats = editor.document().stats();
    print_out(&format!(
        "{what}: {} models, {} vertices, {} triangles, {} curves; wrote {written}.",
        stats.models, stats.vertices, stats.triangles, stats.curves,
    ))
}

fn info(path: &Path) -> anyhow::Result<()> {
    let files = read_gltf(path)?;
    let import_files: Vec<ImportFile> = files
        .iter()
        .map(|file| ImportFile {
            name: &file.name,
            bytes: file.data.as_deref().map_or(&[], Vec::as_slice),
        })
        .collect();
    let info = inspect_gltf(&import_files[0], &import_files[1..])
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

//! The `sketchmesh` command: replay sessions headlessly, convert, inspect and optimize glTF
//! files.
//!
//! Arguments are matched by hand on the argument slice (as egui's xtask does); any refusal
//! prints one sentence on stderr and exits with status 1.

mod optimize;

use std::io::Write as _;
use std::path::Path;
use std::process::ExitCode;

use anyhow::{Context as _, bail};
use std::sync::Arc;

use sketchmesh_core::document::{Editor, FileInput, ImportInput, Op, Session};
use sketchmesh_core::io::{ImportFile, inspect_gltf, referenced_files, write_glb};

const USAGE: &str = "\
Usage:
  sketchmesh replay SESSION.json -o OUT.glb   Replay a session and write the document as glTF.
  sketchmesh convert IN.glb|IN.gltf -o OUT.glb Import a glTF file and export it as Sketchmesh does.
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
        ["convert", input, "-o", out] | ["convert", "-o", out, input] => {
            convert(Path::new(input), Path::new(out))
        }
        ["info", file] => info(Path::new(file)),
        ["optimize", rest @ ..] => optimize::run(rest),
        _ => bail!("I don't understand the arguments {args:?}.\n{USAGE}"),
    }
}

fn replay(session_path: &Path, out_path: &Path) -> anyhow::Result<()> {
    let json = std::fs::read_to_string(session_path)
        .with_context(|| format!("Could not read the session file {}", session_path.display()))?;
    let mut session = Session::from_json(&json)
        .with_context(|| format!("Could not replay {}", session_path.display()))?;
    load_import_files(
        &mut session,
        session_path.parent().unwrap_or(Path::new(".")),
    )?;
    let editor = Editor::replay(&session)
        .with_context(|| format!("Could not replay {}", session_path.display()))?;
    let what = format!("Replayed {} ops", editor.ops().len());
    write_document(&editor, out_path, &what)
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

fn convert(in_path: &Path, out_path: &Path) -> anyhow::Result<()> {
    let files = read_gltf(in_path)?;
    let mut editor = Editor::new();
    editor
        .apply(Op::Import(ImportInput {
            files,
            beside: false,
        }))
        .with_context(|| format!("Could not import {}", in_path.display()))?;
    let what = format!("Converted {}", in_path.display());
    write_document(&editor, out_path, &what)
}

/// Writes the document as .glb and prints one line saying what is in it.
fn write_document(editor: &Editor, out_path: &Path, what: &str) -> anyhow::Result<()> {
    let bytes = write_glb(editor.document());
    std::fs::write(out_path, &bytes)
        .with_context(|| format!("Could not write {}", out_path.display()))?;
    let stats = editor.document().stats();
    print_out(&format!(
        "{what}: {} models, {} vertices, {} triangles, {} curves; wrote {} ({} bytes).",
        stats.models,
        stats.vertices,
        stats.triangles,
        stats.curves,
        out_path.display(),
        bytes.len()
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

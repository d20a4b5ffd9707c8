//! `sketchmesh optimize`: Laplacian mesh optimization of every model of a glTF file, as the
//! `optimize` op does in the app.

use std::path::Path;

use anyhow::{Context as _, bail};
use serde_json::{Value, json};
use sketchmesh_core::document::{Editor, ImportInput, Op, OptimizeInput};
use sketchmesh_core::optimize::{OptimizeParams, quality_report};

use crate::export::Output;
use crate::{print_out, read_gltf, write_document};

/// What the command line asked for.
struct Request<'a> {
    input: &'a str,
    output: Output,
    settings: OptimizeParams,
    report: bool,
}

/// Runs `sketchmesh optimize IN -o OUT.glb [options]`.
pub fn run(args: &[&str]) -> anyhow::Result<()> {
    let request = parse(args)?;
    let files = read_gltf(Path::new(request.input))?;
    let mut editor = Editor::new();
    editor
        .apply(Op::Import(ImportInput {
            files,
            beside: false,
        }))
        .with_context(|| format!("Could not import {}", request.input))?;
    let mut reports = Vec::new();
    for model in 0..editor.document().models.len() {
        let before = editor.document().models[model].mesh.clone();
        editor
            .apply(Op::Optimize(OptimizeInput {
                model,
                settings: request.settings,
                ..OptimizeInput::default()
            }))
            .with_context(|| format!("Could not optimize model {model} of {}", request.input))?;
        let after = editor.document().models[model].mesh.positions();
        reports.push(quality_report(&before, after));
    }
    let what = format!("Optimized {}", request.input);
    write_document(&editor, &request.output, &what)?;
    if request.report {
        print_out(&serde_json::to_string_pretty(&reports)?)?;
    }
    Ok(())
}

/// The request, or a sentence saying which argument is wrong.
fn parse<'a>(args: &[&'a str]) -> anyhow::Result<Request<'a>> {
    let (mut input, mut output, mut report) = (None, None, false);
    let mut settings = json!({});
    let mut rest = args.iter();
    while let Some(&arg) = rest.next() {
        let mut value = || {
            rest.next()
                .copied()
                .with_context(|| format!("{arg} needs a value."))
        };
        match arg {
            "-o" => output = Some(value()?),
            "--mode" | "--weights" | "--laplacian" | "--feature-falloff" => {
                let key = arg.trim_start_matches("--").replace('-', "_");
                settings[key.as_str()] = Value::String(value()?.replace('-', "_"));
            }
            "--scale" => {
                let text = value()?;
                let scale: f64 = text
                    .parse()
                    .with_context(|| format!("--scale takes a number, not {text:?}."))?;
                settings["scale"] = json!(scale);
            }
            "--tangent-plane" => settings["tangent_plane"] = json!(true),
            "--quality" => settings["quality"] = json!(true),
            "--features" => settings["features"] = json!(true),
            "--report" => report = true,
            _ if arg.starts_with('-') => bail!("I don't know the option {arg}."),
            _ if input.is_none() => input = Some(arg),
            _ => bail!("Give one input file, not {arg:?} as well."),
        }
    }
    let settings: OptimizeParams = serde_json::from_value(settings)
        .context("One of --mode (shape, smooth), --weights (const, linear, cdf), --laplacian (uniform, cotan, cotan-curvature) or --feature-falloff (linear, cdf, gaussian) has a value I don't know")?;
    Ok(Request {
        input: input.context("Name the glTF file to optimize.")?,
        output: Output::new(
            Path::new(output.context("Name the output with -o OUT.glb.")?),
            None,
        )?,
        settings,
        report,
    })
}

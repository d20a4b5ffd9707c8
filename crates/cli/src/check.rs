//! `sketchmesh check`: the print check of every model of a glTF file or a replayed session,
//! in the words the app shows before an STL export.

use std::path::Path;
use std::process::ExitCode;

use anyhow::{Context as _, bail};
use sketchmesh_core::print_check::{DEFAULT_MIN_WALL, PrintCheck};
use sketchmesh_core::unit::Unit;

use crate::{import_gltf_file, print_out, replay_session};

/// Exit status when the models would not print.
const NOT_PRINTABLE: u8 = 1;
/// Exit status when there was no check: bad arguments or an input that cannot be read.
const NOT_CHECKED: u8 = 2;

/// What the command line asked for.
struct Request<'a> {
    input: &'a str,
    min_wall: f64,
    unit: Unit,
}

/// Runs `sketchmesh check IN [--min-wall W] [--unit U]`: prints the check's sentences and
/// exits with 0 when printable, 1 when not, 2 when it could not check (said on stderr).
pub fn run(args: &[&str]) -> ExitCode {
    let checked = parse(args).and_then(|request| {
        let check = check(&request)?;
        for sentence in check.sentences(request.unit) {
            print_out(&sentence)?;
        }
        Ok(check.is_printable())
    });
    match checked {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(NOT_PRINTABLE),
        Err(error) => {
            eprintln!("sketchmesh: {error:#}");
            ExitCode::from(NOT_CHECKED)
        }
    }
}

fn check(request: &Request) -> anyhow::Result<PrintCheck> {
    let path = Path::new(request.input);
    let is_session = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("json"));
    let editor = if is_session {
        replay_session(path)?
    } else {
        import_gltf_file(path)?
    };
    Ok(PrintCheck::of_document(editor.document(), request.min_wall))
}

/// The request, or a sentence saying which argument is wrong.
fn parse<'a>(args: &[&'a str]) -> anyhow::Result<Request<'a>> {
    let (mut input, mut min_wall, mut unit) = (None, None, Unit::Millimetre);
    let mut rest = args.iter();
    while let Some(&arg) = rest.next() {
        let mut value = || {
            rest.next()
                .copied()
                .with_context(|| format!("{arg} needs a value."))
        };
        match arg {
            "--min-wall" => {
                let text = value()?;
                let wall: f64 = text
                    .parse()
                    .ok()
                    .filter(|w: &f64| w.is_finite() && *w >= 0.0)
                    .with_context(|| format!("--min-wall takes a length, not {text:?}."))?;
                min_wall = Some(wall);
            }
            "--unit" => unit = value()?.parse()?,
            option if option.starts_with("--") => {
                bail!(
                    "I don't know the option {option}; check takes --min-wall W and --unit mm|cm|m|in."
                )
            }
            file if input.is_none() => input = Some(file),
            _ => bail!("Give one input file, not {arg:?} as well."),
        }
    }
    Ok(Request {
        input: input.context("Name the glTF or session file to check.")?,
        // The minimum wall is given in the unit the report speaks.
        min_wall: min_wall.map_or(DEFAULT_MIN_WALL, |wall| unit.to_metres(wall)),
        unit,
    })
}

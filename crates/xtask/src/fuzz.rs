//! `cargo xtask fuzz [--seconds N]`: runs the cargo-fuzz target of the glTF importer for a
//! bounded time (default 60 s), installing cargo-fuzz when it is missing.
//!
//! The target lives in `fuzz/` (its own workspace; libFuzzer needs a nightly toolchain). The
//! corpus starts from the Khronos validator's test assets in `../shared/testdata` when they
//! are there, and grows in `target/fuzz-corpus/`; crashes land in `fuzz/artifacts/`.

use std::path::Path;
use std::process::Command;

use anyhow::{Context as _, bail};

use crate::{Workspace, cargo, output_of, run};

/// Runs the importer fuzz target for `options` (`--seconds N`).
pub fn fuzz_command(workspace: &Workspace, options: &[&str]) -> anyhow::Result<()> {
    let seconds: u64 = match options {
        [] => 60,
        ["--seconds", n] => n
            .parse()
            .with_context(|| format!("--seconds {n}: not a number"))?,
        other => bail!("unknown fuzz options {other:?}; use --seconds N"),
    };
    if output_of(nightly_cargo().arg("--version")).is_none() {
        bail!("cargo fuzz needs a nightly toolchain: run `rustup toolchain install nightly`");
    }
    if output_of(nightly_cargo().args(["fuzz", "--version"])).is_none() {
        run(
            "installing cargo-fuzz",
            cargo().args(["install", "cargo-fuzz", "--locked"]),
        )?;
    }
    let corpus = workspace.target_dir.join("fuzz-corpus");
    std::fs::create_dir_all(&corpus)?;
    let seeds = workspace
        .root
        .join("../shared/testdata/gltf/validator-suite");
    let n_seeds = copy_seeds(&seeds, &corpus)?;
    if n_seeds == 0 {
        println!(
            "xtask: WARNING: no seed files in {} (the shared test data is missing); fuzzing from an empty corpus",
            seeds.display()
        );
    }
    run(
        "cargo fuzz",
        nightly_cargo()
            .current_dir(workspace.root.join("fuzz"))
            .args(["fuzz", "run", "import_gltf"])
            .arg(&corpus)
            .arg("--")
            .arg(format!("-max_total_time={seconds}"))
            .arg("-rss_limit_mb=2048")
            .arg("-timeout=10"),
    )?;
    println!("xtask: the importer survived {seconds} s of fuzzing");
    Ok(())
}

/// The nightly toolchain's cargo, through rustup (the cargo running the xtask is stable).
fn nightly_cargo() -> Command {
    let mut command = Command::new("rustup");
    command.args(["run", "nightly", "cargo"]);
    command
}

/// Copies every .gltf/.glb under `from` into `to`; returns how many.
fn copy_seeds(from: &Path, to: &Path) -> anyhow::Result<usize> {
    let Ok(entries) = std::fs::read_dir(from) else {
        return Ok(0);
    };
    let mut n = 0;
    for entry in entries {
        let path = entry?.path();
        if path.is_dir() {
            n += copy_seeds(&path, to)?;
        } else if matches!(
            path.extension().and_then(|e| e.to_str()),
            Some("gltf" | "glb")
        ) {
            let name = path
                .strip_prefix(from)
                .unwrap_or(&path)
                .to_string_lossy()
                .replace('/', "_");
            let parent = from
                .file_name()
                .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
            std::fs::copy(&path, to.join(format!("{parent}_{name}")))?;
            n += 1;
        }
    }
    Ok(n)
}

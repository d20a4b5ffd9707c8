//! `cargo xtask build-web`: wasm build of `sketchmesh-app`, JS bindings, static files, wasm-opt
//! and precompressed `.gz` files, all into `dist/`.
//!
//! The bindings come from `wasm-bindgen-cli-support` linked into this binary, so their version is
//! the one pinned in `Cargo.toml` (it must equal the `wasm-bindgen` in `Cargo.lock`). wasm-opt is
//! the npm `binaryen` one: Debian's wasm-opt 108 writes modules that fail at start-up. wasm-opt
//! takes minutes, so its output is cached in `target/web/wasm-opt/`, keyed by a hash of its input.

use std::fs;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{Context as _, bail};
use flate2::Compression;
use flate2::write::GzEncoder;

use crate::guide_page;
use crate::setup::{self, Needs};
use crate::{Workspace, cargo, format_size, run};

/// The wasm-bindgen `out_name`: `dist/sketchmesh_app.js` and `dist/sketchmesh_app_bg.wasm`.
pub const OUT_NAME: &str = "sketchmesh_app";
const PACKAGE: &str = "sketchmesh-app";
const WASM_TARGET: &str = "wasm32-unknown-unknown";
/// The `release` profile: the one page that is served, tested and measured (see the profile
/// in `Cargo.toml` for which crates are optimized for speed and which for size).
const CARGO_PROFILE: &str = "release";
/// A speed level. `-O1` against `-O2` on the same build (2026-12-06, BENCHMARKS.md): the
/// page bench's frames and solves within noise of each other, the page 104 kB smaller
/// gzipped (3.33 against 3.43 MB: `-O2` inlines more, in code LLVM has optimized already),
/// so it starts sooner, and wasm-opt takes 28 s instead of 94 (npm's binaryen runs
/// single-threaded under Node, beside the native build in CI).
const WASM_OPT_ARGS: &[&str] = &["-O1"];

/// What a web build produced.
pub struct WebBuild {
    /// `dist/sketchmesh_app_bg.wasm`.
    pub wasm: PathBuf,
    /// Size of the wasm after gzip -9, as served to browsers that accept gzip.
    pub wasm_gzip_size: u64,
}

impl WebBuild {
    /// The build `dist` holds (written by [`build_web`], maybe by another xtask process).
    pub fn in_dist(dist: &Path) -> anyhow::Result<Self> {
        let wasm = dist.join(format!("{OUT_NAME}_bg.wasm"));
        let mut gz = wasm.clone().into_os_string();
        gz.push(".gz");
        Ok(Self {
            wasm_gzip_size: file_size(Path::new(&gz))?,
            wasm,
        })
    }
}

/// Builds the page into `dist/` (emptied first) and prints the sizes.
pub fn build_web(workspace: &Workspace) -> anyhow::Result<WebBuild> {
    setup::setup(
        workspace,
        Needs {
            wasm_target: true,
            chromium: false,
            npm: true,
        },
    )?;
    let index_html = workspace.root.join("index.html");
    if !index_html.is_file() {
        bail!(
            "{} is missing: the page has no entry point",
            index_html.display()
        );
    }

    run(
        "building the wasm",
        cargo()
            .current_dir(&workspace.root)
            .args(["build", "-p", PACKAGE, "--lib", "--target", WASM_TARGET])
            .args(["--profile", CARGO_PROFILE]),
    )?;
    let cargo_wasm = workspace
        .target_dir
        .join(WASM_TARGET)
        .join(CARGO_PROFILE)
        .join(format!("{OUT_NAME}.wasm"));

    let web_dir = workspace.target_dir.join("web");
    let bindgen_dir = web_dir.join(CARGO_PROFILE);
    recreate_dir(&bindgen_dir)?;
    wasm_bindgen_cli_support::Bindgen::new()
        .input_path(&cargo_wasm)
        .web(true)?
        .typescript(false)
        // The library's default is `true`, which leaves `init()` without a default wasm URL.
        .omit_default_module_path(false)
        .out_name(OUT_NAME)
        .generate(&bindgen_dir)
        .with_context(|| format!("wasm-bindgen on {}", cargo_wasm.display()))?;
    let bindgen_wasm = bindgen_dir.join(format!("{OUT_NAME}_bg.wasm"));

    let dist = workspace.dist();
    recreate_dir(&dist)?;
    copy_dir(&bindgen_dir, &dist)?;
    let wasm = dist.join(format!("{OUT_NAME}_bg.wasm"));
    let optimized = wasm_opt_cached(workspace, &bindgen_wasm, &web_dir.join("wasm-opt"))?;
    fs::copy(&optimized, &wasm).context("copying the optimized wasm into dist/")?;
    fs::copy(&index_html, dist.join("index.html")).context("copying index.html")?;
    let static_dir = workspace.root.join("web");
    if static_dir.is_dir() {
        copy_dir(&static_dir, &dist)?;
    }
    guide_page::write_guide(&workspace.root, &dist)?;

    write_service_worker(&dist)?;

    let js = dist.join(format!("{OUT_NAME}.js"));
    let wasm_gzip_size = gzip_next_to(&wasm)?;
    let js_gzip_size = gzip_next_to(&js)?;
    println!("xtask: web build ({CARGO_PROFILE}) in {}", dist.display());
    println!("  cargo output  {}", format_size(file_size(&cargo_wasm)?));
    println!("  wasm-bindgen  {}", format_size(file_size(&bindgen_wasm)?));
    println!(
        "  wasm-opt {}  {}",
        WASM_OPT_ARGS.join(" "),
        format_size(file_size(&wasm)?)
    );
    println!("  wasm gzip -9  {}", format_size(wasm_gzip_size));
    println!("  js            {}", format_size(file_size(&js)?));
    println!("  js gzip -9    {}", format_size(js_gzip_size));
    Ok(WebBuild {
        wasm,
        wasm_gzip_size,
    })
}

/// Runs npm binaryen's `wasm-opt` on `input` unless `cache` already holds the output for the
/// same input bytes; returns the optimized file.
fn wasm_opt_cached(workspace: &Workspace, input: &Path, cache: &Path) -> anyhow::Result<PathBuf> {
    let bytes = fs::read(input).with_context(|| format!("reading {}", input.display()))?;
    let key = format!("{:016x} {}", fnv1a64(&bytes), WASM_OPT_ARGS.join(" "));
    let key_file = cache.join("input-hash");
    let output = cache.join(format!("{OUT_NAME}_bg.wasm"));
    if output.is_file() && fs::read_to_string(&key_file).is_ok_and(|old| old == key) {
        println!("xtask: wasm-opt skipped: input unchanged ({key})");
        return Ok(output);
    }
    let wasm_opt = workspace.node_bin("wasm-opt");
    if !wasm_opt.is_file() {
        bail!(
            "{} is missing (npm binaryen); run `cargo xtask setup`",
            wasm_opt.display()
        );
    }
    fs::create_dir_all(cache).with_context(|| format!("creating {}", cache.display()))?;
    // Another xtask may be optimizing at the same time: remove the key first, write to a file of
    // our own, then rename it into place, so the cache never pairs a key with a partial file.
    let _ = fs::remove_file(&key_file);
    let partial = cache.join(format!("{OUT_NAME}_bg.wasm.{}.partial", std::process::id()));
    println!(
        "xtask: wasm-opt {} (takes a few minutes)",
        WASM_OPT_ARGS.join(" ")
    );
    let optimized = run(
        "wasm-opt",
        Command::new(&wasm_opt)
            .args(WASM_OPT_ARGS)
            .arg(input)
            .arg("-o")
            .arg(&partial),
    );
    if optimized.is_err() {
        let _ = fs::remove_file(&partial);
    }
    optimized?;
    fs::rename(&partial, &output).context("moving the wasm-opt output into the cache")?;
    // Written last, so an interrupted wasm-opt is redone next time.
    fs::write(&key_file, key).context("writing the wasm-opt cache key")?;
    Ok(output)
}

/// The service worker (`web/sw.js`, copied into `dist/`) caches the page's files for offline
/// use: fills in the list of those files and a version that changes whenever one of them
/// does, so that browsers fetch the new ones (and only then).
fn write_service_worker(dist: &Path) -> anyhow::Result<()> {
    let worker = dist.join("sw.js");
    let template = fs::read_to_string(&worker).context("reading web/sw.js")?;
    let mut files = Vec::new();
    list_files(dist, "", &mut files)?;
    files.retain(|name| name != "sw.js" && !name.ends_with(".gz"));
    files.sort();
    // The hash of each file's name and contents' hash.
    let mut listing = String::new();
    for name in &files {
        let bytes = fs::read(dist.join(name)).with_context(|| format!("reading dist/{name}"))?;
        listing.push_str(&format!("{name} {:016x}\n", fnv1a64(&bytes)));
    }
    let version = fnv1a64(listing.as_bytes());
    let urls: Vec<String> = std::iter::once(String::from("./")).chain(files).collect();
    let filled = template
        .replace("__SKETCHMESH_VERSION__", &format!("{version:016x}"))
        .replace("__SKETCHMESH_FILES__", &serde_json::to_string(&urls)?);
    if filled == template {
        bail!("web/sw.js has no __SKETCHMESH_VERSION__ or __SKETCHMESH_FILES__ to fill in");
    }
    fs::write(&worker, filled).context("writing dist/sw.js")
}

/// The files under `dir`, as paths relative to it with `/` between folders (the examples
/// are in a folder of their own), after `prefix`.
fn list_files(dir: &Path, prefix: &str, files: &mut Vec<String>) -> anyhow::Result<()> {
    for entry in fs::read_dir(dir).with_context(|| format!("listing {}", dir.display()))? {
        let entry = entry?;
        let name = format!("{prefix}{}", entry.file_name().to_string_lossy());
        if entry.file_type()?.is_dir() {
            list_files(&entry.path(), &format!("{name}/"), files)?;
        } else {
            files.push(name);
        }
    }
    Ok(())
}

/// 64-bit FNV-1a: a cache key, not a defence against collisions made on purpose.
fn fnv1a64(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |hash, &byte| {
        (hash ^ u64::from(byte)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// Writes `<file>.gz` (gzip level 9) and returns its size.
fn gzip_next_to(file: &Path) -> anyhow::Result<u64> {
    let bytes = fs::read(file).with_context(|| format!("reading {}", file.display()))?;
    let mut encoder = GzEncoder::new(Vec::new(), Compression::best());
    encoder.write_all(&bytes)?;
    let compressed = encoder.finish()?;
    let mut gz_name = file.as_os_str().to_owned();
    gz_name.push(".gz");
    fs::write(&gz_name, &compressed)
        .with_context(|| format!("writing {}", Path::new(&gz_name).display()))?;
    Ok(compressed.len() as u64)
}

fn file_size(file: &Path) -> anyhow::Result<u64> {
    Ok(fs::metadata(file)
        .with_context(|| format!("reading the size of {}", file.display()))?
        .len())
}

fn recreate_dir(dir: &Path) -> anyhow::Result<()> {
    if dir.exists() {
        fs::remove_dir_all(dir).with_context(|| format!("removing {}", dir.display()))?;
    }
    fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))
}

/// Copies the contents of `from` into `to`, recursively.
fn copy_dir(from: &Path, to: &Path) -> anyhow::Result<()> {
    fs::create_dir_all(to).with_context(|| format!("creating {}", to.display()))?;
    for entry in fs::read_dir(from).with_context(|| format!("listing {}", from.display()))? {
        let entry = entry?;
        let target = to.join(entry.file_name());
        if entry.file_type()?.is_dir() {
            copy_dir(&entry.path(), &target)?;
        } else {
            fs::copy(entry.path(), &target)
                .with_context(|| format!("copying {}", entry.path().display()))?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv1a64_matches_reference_values() {
        // Published FNV-1a 64 test vectors.
        assert_eq!(fnv1a64(b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv1a64(b"a"), 0xaf63_dc4c_8601_ec8c);
        assert_eq!(fnv1a64(b"foobar"), 0x8594_4171_f739_67e8);
    }

    #[test]
    fn wasm_opt_runs_once_per_input() {
        let root = std::env::temp_dir().join(format!("xtask-wasm-opt-{}", std::process::id()));
        recreate_dir(&root).unwrap();
        let workspace = Workspace {
            root: root.clone(),
            target_dir: root.join("target"),
        };
        // A stand-in wasm-opt that logs each call and copies its input (`-O1 IN -o OUT`).
        let bin = workspace.node_bin("wasm-opt");
        fs::create_dir_all(bin.parent().unwrap()).unwrap();
        let calls = root.join("calls.log");
        fs::write(
            &bin,
            format!(
                "#!/bin/sh\necho \"$@\" >> '{}'\ncp \"$2\" \"$4\"\n",
                calls.display()
            ),
        )
        .unwrap();
        Command::new("chmod").arg("+x").arg(&bin).status().unwrap();
        let input = root.join("in.wasm");
        let cache = root.join("target").join("cache");
        let count_calls = || {
            fs::read_to_string(&calls)
                .unwrap_or_default()
                .lines()
                .count()
        };

        fs::write(&input, b"\0asm first").unwrap();
        let out = wasm_opt_cached(&workspace, &input, &cache).unwrap();
        assert_eq!(fs::read(&out).unwrap(), b"\0asm first");
        assert_eq!(count_calls(), 1);
        wasm_opt_cached(&workspace, &input, &cache).unwrap();
        assert_eq!(count_calls(), 1, "same input: cached");
        fs::write(&input, b"\0asm second").unwrap();
        let out = wasm_opt_cached(&workspace, &input, &cache).unwrap();
        assert_eq!(fs::read(&out).unwrap(), b"\0asm second");
        assert_eq!(count_calls(), 2, "new input: optimized again");
        let leftovers: Vec<_> = fs::read_dir(&cache)
            .unwrap()
            .map(|entry| entry.unwrap().file_name())
            .collect();
        assert_eq!(
            leftovers.len(),
            2,
            "only the output and its key: {leftovers:?}"
        );
        fs::remove_dir_all(&root).unwrap();
    }

    #[test]
    fn the_service_worker_lists_the_files_and_versions_their_contents() {
        let dist = std::env::temp_dir().join(format!("xtask-sw-{}", std::process::id()));
        let template =
            "const VERSION = \"__SKETCHMESH_VERSION__\";\nconst FILES = __SKETCHMESH_FILES__;\n";
        let build = |wasm: &[u8]| {
            recreate_dir(&dist).unwrap();
            fs::write(dist.join("sw.js"), template).unwrap();
            fs::write(dist.join("index.html"), "<html>").unwrap();
            fs::write(dist.join("app_bg.wasm"), wasm).unwrap();
            fs::write(dist.join("app_bg.wasm.gz"), b"gz").unwrap();
            fs::create_dir(dist.join("examples")).unwrap();
            fs::write(dist.join("examples").join("a.json"), b"{}").unwrap();
            write_service_worker(&dist).unwrap();
            fs::read_to_string(dist.join("sw.js")).unwrap()
        };
        let first = build(b"\0asm one");
        assert!(
            first.contains(r#"const FILES = ["./","app_bg.wasm","examples/a.json","index.html"];"#),
            "no .gz, no sw.js: {first}"
        );
        let version = |text: &str| text.lines().next().unwrap_or_default().to_owned();
        assert_eq!(version(&first).len(), "const VERSION = \"\";".len() + 16);
        assert_eq!(version(&build(b"\0asm one")), version(&first), "same files");
        assert_ne!(
            version(&build(b"\0asm two")),
            version(&first),
            "a changed file"
        );
        fs::write(dist.join("sw.js"), "no placeholders").unwrap();
        assert!(write_service_worker(&dist).is_err());
        fs::remove_dir_all(&dist).unwrap();
    }

    #[test]
    fn gzip_round_trips() {
        use std::io::Read as _;
        let dir = std::env::temp_dir().join(format!("xtask-gzip-{}", std::process::id()));
        recreate_dir(&dir).unwrap();
        let file = dir.join("a.js");
        let text = "export function start() {}\n".repeat(1000);
        fs::write(&file, &text).unwrap();
        let size = gzip_next_to(&file).unwrap();
        let gz = fs::read(dir.join("a.js.gz")).unwrap();
        assert_eq!(size, gz.len() as u64);
        assert!(size < text.len() as u64 / 10);
        let mut unpacked = String::new();
        flate2::read::GzDecoder::new(&gz[..])
            .read_to_string(&mut unpacked)
            .unwrap();
        assert_eq!(unpacked, text);
        fs::remove_dir_all(&dir).unwrap();
    }
}

//! `cargo xtask setup`: the wasm target, Chromium (Debian packages) and the npm test tools.
//!
//! Every part checks first and does nothing when already done, so the other commands call this
//! on each run; a finished setup costs one `rustup` call and a few `stat`s.

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::SystemTime;

use anyhow::{Context as _, bail};

use crate::{Workspace, output_of, run};

const WASM_TARGET: &str = "wasm32-unknown-unknown";
const CHROMIUM: &str = "/usr/bin/chromium";

/// Debian packages for headless Chromium with WebGL2 (SwiftShader) and WebGPU (SwiftShader Vulkan),
/// and for native wgpu tests on lavapipe.
const CHROMIUM_PACKAGES: &[&str] = &[
    "chromium",
    "chromium-driver",
    "fonts-dejavu-core",
    "mesa-vulkan-drivers",
    "libvulkan1",
    "libegl-mesa0",
];

/// Which parts of the setup a command needs.
#[derive(Clone, Copy)]
pub struct Needs {
    /// The `wasm32-unknown-unknown` rustup target.
    pub wasm_target: bool,
    /// `/usr/bin/chromium` and the GPU emulation packages.
    pub chromium: bool,
    /// `tests/node_modules` (playwright-core, binaryen's wasm-opt, gltf-validator, pngjs, three).
    pub npm: bool,
}

impl Needs {
    /// Everything.
    pub const ALL: Self = Self {
        wasm_target: true,
        chromium: true,
        npm: true,
    };
}

/// Installs whatever of `needs` is missing.
pub fn setup(workspace: &Workspace, needs: Needs) -> anyhow::Result<()> {
    if needs.wasm_target {
        ensure_wasm_target()?;
    }
    if needs.chromium {
        ensure_chromium()?;
    }
    if needs.npm {
        ensure_npm_packages(&workspace.tests())?;
    }
    Ok(())
}

fn ensure_wasm_target() -> anyhow::Result<()> {
    let installed = output_of(Command::new("rustup").args(["target", "list", "--installed"]));
    match installed {
        Some(list) if list.lines().any(|line| line.trim() == WASM_TARGET) => Ok(()),
        Some(_) => run(
            "adding the wasm target",
            Command::new("rustup").args(["target", "add", WASM_TARGET]),
        ),
        // Without rustup (a distro toolchain), let cargo report a missing target itself.
        None => {
            eprintln!("xtask: rustup not found; assuming the toolchain has {WASM_TARGET}");
            Ok(())
        }
    }
}

fn ensure_chromium() -> anyhow::Result<()> {
    let mut packages = missing_packages();
    if output_of(Command::new("node").arg("--version")).is_none() {
        packages.extend(["nodejs", "npm"]);
    }
    if packages.is_empty() {
        return Ok(());
    }
    let is_root = output_of(Command::new("id").arg("-u")).is_some_and(|uid| uid.trim() == "0");
    let apt = |args: &[&str]| -> Command {
        let mut cmd = if is_root {
            Command::new("apt-get")
        } else {
            let mut sudo = Command::new("sudo");
            sudo.args(["-n", "apt-get"]);
            sudo
        };
        cmd.args(args).env("DEBIAN_FRONTEND", "noninteractive");
        cmd
    };
    let install = || -> anyhow::Result<()> {
        run("apt-get update", &mut apt(&["update"]))?;
        let mut args = vec!["install", "-y"];
        args.extend(&packages);
        run("installing Chromium", &mut apt(&args))
    };
    install().with_context(|| {
        format!(
            "Chromium, its GPU emulation or node is missing and could not be installed (needs root \
             or password-less sudo). Install by hand: apt-get install -y {}",
            packages.join(" ")
        )
    })?;
    if !Path::new(CHROMIUM).exists() {
        bail!("installed the Chromium packages, but {CHROMIUM} is still missing");
    }
    Ok(())
}

/// The packages of [`CHROMIUM_PACKAGES`] that dpkg does not list as installed (without dpkg:
/// all of them if Chromium is missing, else none).
fn missing_packages() -> Vec<&'static str> {
    // dpkg-query exits with 1 when some package is unknown to it; its list is still right.
    let listed = Command::new("dpkg-query")
        .args(["-W", "-f", "${db:Status-Abbrev} ${Package}\\n"])
        .args(CHROMIUM_PACKAGES)
        .stderr(Stdio::null())
        .output();
    match listed {
        Ok(listed) => {
            let listed = String::from_utf8_lossy(&listed.stdout);
            let installed: Vec<&str> = listed
                .lines()
                .filter(|line| line.starts_with("ii"))
                .filter_map(|line| line.split_whitespace().nth(1))
                .collect();
            CHROMIUM_PACKAGES
                .iter()
                .copied()
                .filter(|package| !installed.contains(package))
                .collect()
        }
        // Not a Debian system.
        Err(_) if Path::new(CHROMIUM).exists() => Vec::new(),
        Err(_) => CHROMIUM_PACKAGES.to_vec(),
    }
}

fn ensure_npm_packages(tests: &Path) -> anyhow::Result<()> {
    let lockfile = tests.join("package-lock.json");
    // npm writes this file on each install; it is the install's time stamp.
    let installed = modified(&tests.join("node_modules").join(".package-lock.json"));
    let up_to_date = match installed {
        Some(installed) => [lockfile.clone(), tests.join("package.json")]
            .iter()
            .all(|file| modified(file).is_none_or(|changed| changed <= installed)),
        None => false,
    };
    if up_to_date {
        return Ok(());
    }
    let verb = if lockfile.is_file() { "ci" } else { "install" };
    run(
        "installing the npm test tools",
        Command::new("npm")
            .args([verb, "--no-audit", "--no-fund"])
            .current_dir(tests),
    )
}

fn modified(path: &Path) -> Option<SystemTime> {
    path.metadata().and_then(|meta| meta.modified()).ok()
}

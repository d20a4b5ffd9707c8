//! Import over real files nobody here made (`../shared/testdata`): scanned meshes, real-world
//! glTF files, files with validator errors that loaders still open, and the Khronos
//! validator's own test corpus.
//!
//! The data lives outside the repository. When it is missing these tests fail loudly, unless
//! `SKETCHMESH_NO_TESTDATA=1` says that is expected (then they print why they did nothing).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::common::testdata;
use sketchmesh_core::io::{
    GltfError, ImportFile, ImportLimits, Imported, TransferSource, decode_imported,
    encode_imported, import_gltf, inspect_gltf,
};

/// The file and every other file in its directory (a .gltf's .bin and images).
fn load(path: &Path) -> (Vec<u8>, Vec<(String, Vec<u8>)>) {
    let main = std::fs::read(path).unwrap();
    let others = std::fs::read_dir(path.parent().unwrap())
        .unwrap()
        .map(|entry| entry.unwrap().path())
        .filter(|other| other != path && other.is_file())
        .map(|other| {
            let name = other.file_name().unwrap().to_string_lossy().into_owned();
            (name, std::fs::read(&other).unwrap())
        })
        .collect();
    (main, others)
}

fn files<'a>(
    path: &'a Path,
    main: &'a [u8],
    others: &'a [(String, Vec<u8>)],
) -> (ImportFile<'a>, Vec<ImportFile<'a>>) {
    let name = path.file_name().unwrap().to_str().unwrap();
    let others = others
        .iter()
        .map(|(name, bytes)| ImportFile { name, bytes })
        .collect();
    (ImportFile { name, bytes: main }, others)
}

/// Triangle counts (over all node instances) and world bounds, as trimesh 4 computes them
/// (`trimesh.load(f, force="scene", process=False)`, geometry transformed per node).
const REAL: &[(&str, usize, [f64; 3], [f64; 3])] = &[
    (
        "meshes/igea.glb",
        268686,
        [-0.03456, -0.04967, -0.04954],
        [0.03456, 0.04967, 0.04954],
    ),
    (
        "meshes/nefertiti.glb",
        99938,
        [-119.323, -181.293, -247.26801],
        [119.363, 181.241, 247.33701],
    ),
    (
        "meshes/spot.glb",
        5856,
        [-0.47155, -0.73678, -0.66891],
        [0.47155, 0.95365, 1.049],
    ),
    (
        "meshes/stanford_bunny.glb",
        69451,
        [-0.09469, 0.03299, -0.06187],
        [0.06101, 0.18732, 0.0588],
    ),
    (
        "meshes/suzanne.glb",
        968,
        [-3.86125, 0.26731, 3.25233],
        [-1.12688, 2.23606, 4.95545],
    ),
    ("gltf/real/BoxInterleaved.glb", 12, [-0.5; 3], [0.5; 3]),
    ("gltf/real/BoxTextured.glb", 12, [-0.5; 3], [0.5; 3]),
    (
        "gltf/real/CesiumMilkTruck.glb",
        3624,
        [-2.43091, 0.00145, -1.396],
        [2.438, 2.58437, 1.396],
    ),
    (
        "gltf/real/Duck.glb",
        4212,
        [-0.69298, 0.09929, -0.61328],
        [0.9618, 1.6397, 0.53925],
    ),
    (
        "gltf/real/Mesh_PrimitiveMode_04.gltf",
        2,
        [-0.5, -0.5, 0.0],
        [0.5, 0.5, 0.0],
    ),
    ("gltf/real/cubevc.glb", 48, [-1.0; 3], [1.0; 3]),
    (
        "gltf/real/monkey.glb",
        968,
        [-1.36719, -0.98438, -0.85156],
        [1.36719, 0.98438, 0.85156],
    ),
    (
        "gltf/real/nested.glb",
        36,
        [-1.16701, -2.3366, -0.26938],
        [0.26938, 1.0, 0.26938],
    ),
    (
        "gltf/real/no_indices_3storybuilding.glb",
        72,
        [-23.20714, 0.0, 0.0],
        [32.873, 9.0, 63.36141],
    ),
    (
        "gltf/real/rgb_cube_with_primitives.gltf",
        12,
        [-1.0; 3],
        [1.0; 3],
    ),
    ("gltf/real/tinygltf/Cube.gltf", 12, [-1.0; 3], [1.0; 3]),
    (
        "gltf/real/tinygltf/singleBlendshapeCube_sparse.glb",
        12,
        [-0.005; 3],
        [0.005; 3],
    ),
];

#[test]
fn real_files_load_with_the_right_triangles_and_bounds() {
    let Some(root) = testdata() else { return };
    for &(file, triangles, lo, hi) in REAL {
        let path = root.join(file);
        let (main, others) = load(&path);
        let (main, others) = files(&path, &main, &others);
        let info = inspect_gltf(&main, &others).unwrap_or_else(|e| panic!("{file}: {e}"));
        assert_eq!(info.triangles, triangles, "{file}");
        let (got_lo, got_hi) = (info.bbox_min.unwrap(), info.bbox_max.unwrap());
        let diagonal = (0..3).map(|k| (hi[k] - lo[k]).powi(2)).sum::<f64>().sqrt();
        for k in 0..3 {
            assert!(
                (got_lo[k] - lo[k]).abs() <= 1e-4 * diagonal,
                "{file}: min {got_lo:?} vs {lo:?}"
            );
            assert!(
                (got_hi[k] - hi[k]).abs() <= 1e-4 * diagonal,
                "{file}: max {got_hi:?} vs {hi:?}"
            );
        }
        let imported = import_gltf(&main, &others, &ImportLimits::default())
            .unwrap_or_else(|e| panic!("{file}: {e}"));
        let faces: usize = imported.models.iter().map(|m| m.mesh.n_faces()).sum();
        // Repair may drop degenerate and duplicate triangles, never more than a few.
        assert!(
            faces <= triangles && faces * 100 >= triangles * 98,
            "{file}: {faces} of {triangles}"
        );
        for model in &imported.models {
            model
                .mesh
                .validate()
                .unwrap_or_else(|e| panic!("{file}: {e}"));
        }
        assert_crosses_unchanged(&imported, file);
    }
    // A file whose nodes hold nothing is refused with a sentence.
    let path = root.join("gltf/real/empty_nodes.glb");
    let (main, others) = load(&path);
    let (main, others) = files(&path, &main, &others);
    assert_eq!(
        import_gltf(&main, &others, &ImportLimits::default()).unwrap_err(),
        GltfError::NothingToImport
    );
}

/// Imports every glTF file under `dir`, asserting no panic, no hang and a sentence for every
/// refusal. Returns (file, result) for the caller's own checks.
fn import_all(dir: &Path) -> Vec<(String, Result<usize, GltfError>)> {
    let mut paths: Vec<PathBuf> = walk(dir)
        .into_iter()
        .filter(|p| matches!(p.extension().and_then(|e| e.to_str()), Some("gltf" | "glb")))
        .collect();
    paths.sort();
    assert!(!paths.is_empty(), "no glTF files under {}", dir.display());
    paths
        .iter()
        .map(|path| {
            let (main, others) = load(path);
            let (main, others) = files(path, &main, &others);
            let start = Instant::now();
            let result =
                std::panic::catch_unwind(|| import_gltf(&main, &others, &ImportLimits::default()))
                    .unwrap_or_else(|_| panic!("{} made the importer panic", path.display()));
            assert!(
                start.elapsed() < Duration::from_secs(10),
                "{} took {:?}",
                path.display(),
                start.elapsed()
            );
            if let Ok(imported) = &result {
                assert_crosses_unchanged(imported, &path.display().to_string());
            }
            if let Err(error) = &result {
                let sentence = error.to_string();
                assert!(
                    sentence.ends_with('.') && sentence.len() > 20,
                    "{}: not a sentence: {sentence}",
                    path.display()
                );
            }
            let name = path
                .strip_prefix(dir)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            (name, result.map(|imported| imported.models.len()))
        })
        .collect()
}

/// What the page's worker sends of `imported` arrives as it was (`io::transfer`), and the
/// same buffer cut short anywhere is refused, never decoded into something else.
fn assert_crosses_unchanged(imported: &Imported, file: &str) {
    let bytes = encode_imported(imported);
    let arrived = decode_imported(&bytes).unwrap_or_else(|e| panic!("{file}: {e}"));
    assert_eq!(arrived.models, imported.models, "{file}");
    assert_eq!(arrived.sketches, imported.sketches, "{file}");
    assert_eq!(arrived.point_clouds, imported.point_clouds, "{file}");
    assert_eq!(arrived.notes, imported.notes, "{file}");
    assert_eq!(
        distinct_images(&arrived),
        distinct_images(imported),
        "{file}: shared images stay shared"
    );
    for cut in [0, 7, bytes.len() / 3, bytes.len() - 1] {
        assert!(
            decode_imported(&bytes[..cut]).is_err(),
            "{file} cut at {cut}"
        );
    }
    // As the page decodes it, from the buffer where it arrived: every byte is copied out of
    // it exactly once.
    let counted = Counted {
        bytes: &bytes,
        copied: std::cell::RefCell::new(vec![0_u8; bytes.len()]),
    };
    let arrived = decode_imported(&counted).unwrap_or_else(|e| panic!("{file}: {e}"));
    assert_eq!(arrived.models, imported.models, "{file}");
    let copied = counted.copied.into_inner();
    assert!(
        copied.iter().all(|&n| n == 1),
        "{file}: a byte copied twice or never"
    );
}

/// A buffer that counts how often each of its bytes is copied out.
struct Counted<'a> {
    bytes: &'a [u8],
    copied: std::cell::RefCell<Vec<u8>>,
}

impl TransferSource for Counted<'_> {
    fn size(&self) -> usize {
        self.bytes.len()
    }

    fn copy_out(&self, at: usize, into: &mut [u8]) {
        self.bytes.copy_out(at, into);
        for n in &mut self.copied.borrow_mut()[at..at + into.len()] {
            *n += 1;
        }
    }
}

/// How many distinct images (by address) the textures of `imported` use.
fn distinct_images(imported: &Imported) -> usize {
    let mut seen: Vec<*const sketchmesh_core::model::Image> = Vec::new();
    let looks = imported.models.iter().flat_map(|m| {
        let as_imported = m.as_imported.as_ref().and_then(|a| a.appearance.clone());
        [m.appearance.clone(), as_imported]
    });
    for look in looks.flatten() {
        for texture in look
            .materials
            .iter()
            .filter_map(|m| m.base_color_texture.as_ref())
        {
            let at = std::sync::Arc::as_ptr(&texture.image);
            if !seen.contains(&at) {
                seen.push(at);
            }
        }
    }
    seen.len()
}

fn walk(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            out.extend(walk(&path));
        } else {
            out.push(path);
        }
    }
    out
}

#[test]
fn lenient_and_broken_files_load_or_are_refused_with_a_sentence() {
    let Some(root) = testdata() else { return };
    let lenient = import_all(&root.join("gltf/real-lenient"));
    assert_eq!(lenient.len(), 2);
    let broken = import_all(&root.join("gltf/bad-tinygltf"));
    assert!(
        broken.iter().any(|(_, result)| result.is_err()),
        "{broken:?}"
    );
}

#[test]
fn the_validator_corpus_never_panics_and_valid_assets_are_not_refused() {
    let Some(root) = testdata() else { return };
    let dir = root.join("gltf/validator-suite");
    let index: serde_json::Value =
        serde_json::from_slice(&std::fs::read(dir.join("INDEX.json")).unwrap()).unwrap();
    let results = import_all(&dir);
    let mut n_valid = 0;
    let mut wrongly_refused: Vec<String> = Vec::new();
    for entry in index.as_array().unwrap() {
        let file = entry["file"].as_str().unwrap();
        let Some((_, result)) = results.iter().find(|(name, _)| name == file) else {
            continue;
        };
        if entry["expect_errors"] == false {
            n_valid += 1;
            // A valid asset may be refused only for having no triangle data.
            match result {
                Err(error)
                    if !matches!(error, GltfError::NothingToImport | GltfError::NoBinaryData) =>
                {
                    wrongly_refused.push(format!("{file}: {error}"));
                }
                _ => {}
            }
        }
    }
    assert!(
        wrongly_refused.is_empty(),
        "valid assets refused:\n{}",
        wrongly_refused.join("\n")
    );
    assert!(n_valid > 50, "only {n_valid} valid assets were checked");
    let loaded = results.iter().filter(|(_, r)| r.is_ok()).count();
    eprintln!(
        "validator corpus: {} files, {loaded} loaded, {} refused",
        results.len(),
        results.len() - loaded
    );
}

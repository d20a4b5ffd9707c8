//! Feeds arbitrary bytes to the glTF importer, as a .glb or .gltf with one extra file: it must
//! return a model or a sentence, never panic, hang or allocate without bound.
#![no_main]

use libfuzzer_sys::fuzz_target;
use sketchmesh_core::io::{ImportFile, ImportLimits, import_gltf};

fuzz_target!(|data: &[u8]| {
    // Small limits keep each run fast; the checks they exercise are the same.
    let limits = ImportLimits {
        max_file_bytes: 1 << 20,
        max_vertices: 100_000,
        max_triangles: 200_000,
    };
    let split = data.first().map_or(0, |&b| usize::from(b)).min(data.len());
    let (main, extra) = data.split_at(split.max(data.len() / 2));
    let main = ImportFile { name: "fuzz.gltf", bytes: main };
    let extra = ImportFile { name: "fuzz.bin", bytes: extra };
    if let Ok(imported) = import_gltf(&main, &[extra], &limits) {
        for model in &imported.models {
            assert!(model.mesh.validate().is_ok());
        }
    }
});

//! The shared test data's scans, for benches and the libigl comparisons.

use std::path::Path;

use sketchmesh_core::io::{ImportFile, ImportLimits, import_gltf};
use sketchmesh_core::mesh::Mesh;

/// The first mesh of a test-data file, or `None` (said loudly) when the data is missing.
pub fn scan(name: &str) -> Option<Mesh> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/testdata/meshes")
        .join(name);
    let Ok(bytes) = std::fs::read(&path) else {
        eprintln!(
            "WARNING: {} is missing; this case is skipped",
            path.display()
        );
        return None;
    };
    let file = ImportFile {
        name,
        bytes: &bytes,
    };
    let imported = import_gltf(&file, &[], &ImportLimits::default()).ok()?;
    imported.models.into_iter().next().map(|m| m.mesh)
}

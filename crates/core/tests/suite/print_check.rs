//! The print check on real scans and models (`../shared/testdata`): what it finds on each,
//! and how long it takes (printed; run with `--nocapture` to read the times).
//!
//! Spot is a clean closed surface; the Stanford bunny's scan is open at the base; Igea
//! (270k vertices) is above `MAX_SAMPLES`, so its walls are measured at a subset.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::time::Instant;

use crate::common::testdata;
use sketchmesh_core::io::{ImportFile, import_gltf};
use sketchmesh_core::model::Model;
use sketchmesh_core::print_check::{DEFAULT_MIN_WALL, MAX_SAMPLES, PrintCheck};
use sketchmesh_core::unit::Unit;

/// The models of a test file as the import makes them (`None` as [`testdata`] says).
fn models(name: &str) -> Option<Vec<Model>> {
    let path = testdata()?.join("meshes").join(name);
    let bytes = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let file = ImportFile {
        name,
        bytes: &bytes,
    };
    let imported = import_gltf(&file, &[], &Default::default())
        .unwrap_or_else(|e| panic!("{name} does not import: {e}"));
    Some(imported.models)
}

/// Checks the one model of `name`, printing the time and the sentences.
fn check(name: &str) -> Option<(Model, PrintCheck)> {
    let model = models(name)?.remove(0);
    let start = Instant::now();
    let check = PrintCheck::of_model(&model, DEFAULT_MIN_WALL);
    eprintln!(
        "{name}: {} vertices, {} triangles, checked in {:.0} ms: {:?}",
        model.mesh.n_vertices(),
        model.mesh.n_faces(),
        start.elapsed().as_secs_f64() * 1e3,
        check.sentences(Unit::Millimetre)
    );
    Some((model, check))
}

#[test]
fn spot_is_closed_manifold_and_does_not_cross_itself() {
    let Some((model, check)) = check("spot.glb") else {
        return;
    };
    let found = &check.models[0];
    assert!(found.holes.is_empty());
    assert!(!found.is_repaired);
    assert_eq!(found.crossings.n_places, 0, "{:?}", found.crossings.pairs);
    assert_eq!(found.thickness.n_sampled, model.mesh.n_vertices());
    // Spot is about a unit across: in metres, far thicker than a millimetre anywhere.
    assert!(found.thickness.thin_vertices.is_empty());
    assert!(
        check.is_printable(),
        "{:?}",
        check.sentences(Unit::Millimetre)
    );
}

#[test]
fn the_bunny_scan_is_open_and_says_so() {
    let Some((_, check)) = check("stanford_bunny.glb") else {
        return;
    };
    assert!(check.n_holes() > 0);
    assert!(!check.is_printable());
    let sentences = check.sentences(Unit::Millimetre);
    assert!(sentences[0].starts_with("Not closed: "), "{sentences:?}");
}

#[test]
fn igea_is_sampled_and_every_vertex_still_has_a_thickness() {
    let Some((model, check)) = check("igea.glb") else {
        return;
    };
    let thickness = &check.models[0].thickness;
    assert!(model.mesh.n_vertices() > MAX_SAMPLES);
    assert!(thickness.n_sampled <= MAX_SAMPLES);
    assert!(thickness.n_sampled > MAX_SAMPLES / 2);
    let with_value = thickness.per_vertex.iter().filter(|t| t.is_some()).count();
    assert!(
        with_value > model.mesh.n_vertices() * 9 / 10,
        "{with_value}"
    );
    assert!(check.sentences(Unit::Millimetre)[2].contains(&format!(
        "(measured at {} of {} vertices)",
        thickness.n_sampled,
        model.mesh.n_vertices()
    )));
}

//! Writes a benchmark fixture to a .glb, for the page benchmark to load:
//! - `fibermesh N OUT.glb`: a FiberMesh shape of about N vertices with its outline as
//!   control curve, whose curves the page pulls (the page creates shapes at its default
//!   resolution only);
//! - `bumpy-torus OUT.glb`: the 36,864-vertex bumpy torus the page over-sketches
//!   ([`primitives::bumpy_torus`], as in `benches/oversketch.rs`);
//! - `bar OUT.glb`: the 500,002-vertex bar the page bends with a curve handle (as in
//!   `benches/skeleton.rs`).
//!
//! Run: `cargo run --release -p sketchmesh-core --example fixture_glb -- fibermesh 10000 out.glb`

use std::path::PathBuf;
use std::sync::Arc;

use sketchmesh_core::document::{Document, Model};
use sketchmesh_core::io::write_glb;
use sketchmesh_core::mesh::primitives;

#[path = "../benches/common/fibermesh_shape.rs"]
mod fibermesh_shape;

const USAGE: &str = "usage: fixture_glb fibermesh VERTICES OUT.glb | fixture_glb bumpy-torus OUT.glb | fixture_glb bar OUT.glb | fixture_glb capsule OUT.glb";

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (document, path) = match args.as_slice() {
        [kind, vertices, path] if kind == "fibermesh" => {
            (fibermesh_shape::ellipse_document(vertices.parse()?)?, path)
        }
        [kind, path] if kind == "bumpy-torus" || kind == "bar" || kind == "capsule" => {
            let mesh = match kind.as_str() {
                "bar" => primitives::capsule(0.2, 1.0, 500, 1001),
                // The volumetric bench's capsule: 5,252 vertices, 28.6k graph points.
                "capsule" => primitives::capsule(0.5, 3.0, 42, 126),
                _ => primitives::bumpy_torus(0.03, 384, 96),
            };
            let model = Model {
                mesh,
                ..Model::default()
            };
            let document = Document {
                models: vec![Arc::new(model)],
                ..Document::default()
            };
            (document, path)
        }
        _ => return Err(USAGE.into()),
    };
    std::fs::write(PathBuf::from(path), write_glb(&document))?;
    let stats = document.stats();
    println!(
        "{path}: {} vertices, {} curves",
        stats.vertices, stats.curves
    );
    Ok(())
}

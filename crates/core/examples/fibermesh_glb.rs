//! Writes a FiberMesh shape of about N vertices, with its outline as control curve, to a
//! .glb: the fixture the page benchmark pulls curves of (the page creates shapes at its
//! default resolution only).
//!
//! Run: `cargo run --release -p sketchmesh-core --example fibermesh_glb -- 10000 out.glb`

use std::path::PathBuf;

use sketchmesh_core::io::write_glb;

#[path = "../benches/common/fibermesh_shape.rs"]
mod fibermesh_shape;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let (Some(vertices), Some(path)) = (args.next(), args.next()) else {
        return Err("usage: fibermesh_glb VERTICES OUT.glb".into());
    };
    let document = fibermesh_shape::ellipse_document(vertices.parse()?)?;
    std::fs::write(PathBuf::from(&path), write_glb(&document))?;
    let stats = document.stats();
    println!(
        "{path}: {} vertices, {} curves",
        stats.vertices, stats.curves
    );
    Ok(())
}

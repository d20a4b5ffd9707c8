//! Writing a mesh and its region for the libigl comparisons that read OFF files
//! (`examples/deform_export.rs`, `examples/feature_export.rs`).

use std::fmt::Write as _;

use sketchmesh_core::mesh::Mesh;

use crate::export::vectors;

/// Writes `mesh.off` and `roi.txt` (0 or 1 per vertex) to `dir`.
pub fn write_mesh_and_roi(dir: &std::path::Path, mesh: &Mesh, roi: &[bool]) -> std::io::Result<()> {
    let mut off = format!("OFF\n{} {} 0\n", mesh.n_vertices(), mesh.n_faces());
    off += &vectors(mesh.positions());
    for [a, b, c] in mesh.triangles() {
        let _ = writeln!(off, "3 {a} {b} {c}");
    }
    std::fs::write(dir.join("mesh.off"), off)?;
    let flags: String = roi.iter().map(|&r| if r { "1\n" } else { "0\n" }).collect();
    std::fs::write(dir.join("roi.txt"), flags)
}

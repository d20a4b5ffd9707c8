//! Cutting a shape (Teddy; FiberMesh, Nealen's thesis §3.2.1, §3.3.3): a stroke drawn
//! across a shape from beside it to beside it cuts it with the surface the view rays through
//! the stroke sweep. The part that covers less of the screen is removed, and each opening is
//! closed by a flat cap on the cutting surface, whose rim becomes a sharp control curve.
//!
//! The cut reuses the cross section's level set (`add_curve`): every edge the cutting
//! surface crosses is split at the crossing, so each face lies on one side, and the loops
//! between the sides are the rims. The caps are meshed in 2D on the cutting surface laid
//! flat (`cap.rs`), and the kept faces and the caps are built into one closed mesh, so a cut
//! that would leave anything else (a ring-shaped or folded section, a bowtie where the
//! surface touches the cut, a cap through another part of the shape) is refused instead.

mod cap;
mod error;

pub use error::CutError;

use glam::DVec2;

use crate::camera::Camera;
use crate::curve::polyline::{contains, self_crossings};
use crate::fibermesh::add_curve::{Slice, Split, slice};
use crate::geometry::Bvh;
use crate::mesh::{Mesh, TriSoup, VertexId};
use cap::{Unrolling, mesh_cap};

/// A shape after a cut.
#[derive(Clone, Debug)]
pub struct Cut {
    /// The kept part, closed by its caps.
    pub mesh: Mesh,
    /// Each cap's rim, a closed chain of `mesh` vertices on the cutting surface.
    pub rims: Vec<Vec<VertexId>>,
    /// Whether each vertex of `mesh` lies inside a cap (not on its rim).
    pub is_cap: Vec<bool>,
    /// Every edge the cut split, in the numbering of the input mesh with the split vertices
    /// appended (as in [`crate::fibermesh::add_curve::Embedded::split_edges`]).
    pub split_edges: Vec<(VertexId, VertexId, VertexId)>,
    /// Where each vertex of that numbering went in `mesh`, `None` for removed ones.
    pub remap: Vec<Option<VertexId>>,
}

/// Cuts the closed `mesh` with the surface swept by `stroke` (screen points in CSS px, y
/// down, in a `viewport` of `[width, height]` px seen through `camera`). See the module docs.
///
/// Errors: [`CutError`], as sentences for the user.
pub fn cut(
    mesh: &Mesh,
    camera: &Camera,
    viewport: DVec2,
    stroke: &[DVec2],
) -> Result<Cut, CutError> {
    if !mesh.is_closed() {
        return Err(CutError::NotClosed);
    }
    let Slice {
        split:
            Split {
                mesh: split,
                split_edges,
                zero_set,
            },
        polyline,
    } = slice(mesh, camera, viewport, stroke).map_err(|_| CutError::DoesNotCross)?;
    let keep_positive = keeps_positive(&split, &zero_set.is_positive, camera, viewport)?;
    let depth = mean_depth(&split, &zero_set.loops, camera, viewport)?;
    let unrolling = Unrolling::new(camera, viewport, &polyline, depth);
    let outlines = flat_outlines(&split, &zero_set.loops, &unrolling)?;
    let mut positions = split.positions().to_vec();
    // Rim vertices lie on the cutting surface up to the linear interpolation along edges
    // and the snapping onto near vertices; put them on it, so that nothing is left beyond.
    for (rim, outline) in zero_set.loops.iter().zip(&outlines) {
        for (&v, &q) in rim.iter().zip(outline) {
            positions[v.index()] = unrolling.lift(q);
        }
    }
    let mut triangles: Vec<[u32; 3]> = split
        .triangles()
        .iter()
        .zip(&zero_set.is_positive)
        .filter(|&(_, &positive)| positive == keep_positive)
        .map(|(&t, _)| t)
        .collect();
    let first_cap_vertex = positions.len();
    for (rim, outline) in zero_set.loops.iter().zip(&outlines) {
        let cap = mesh_cap(outline, &unrolling, keep_positive)?;
        let base = positions.len() as u32;
        let corner = |i: u32| match rim.get(i as usize) {
            Some(v) => v.0,
            None => base + i - rim.len() as u32,
        };
        positions.extend(cap.interior);
        triangles.extend(cap.triangles.iter().map(|t| t.map(corner)));
    }
    let mut soup = TriSoup {
        positions,
        triangles,
    };
    let kept = soup.remove_unreferenced_vertices();
    let mesh = Mesh::from_soup(&soup).map_err(CutError::Broken)?;
    if !mesh.is_closed() {
        return Err(CutError::DoesNotCross);
    }
    let remap: Vec<Option<VertexId>> = kept.iter().map(|k| k.map(VertexId)).collect();
    let mut is_cap = vec![false; mesh.n_vertices()];
    for v in remap[first_cap_vertex..].iter().flatten() {
        is_cap[v.index()] = true;
    }
    let in_cap = |f| {
        mesh.face_vertices(f)
            .iter()
            .any(|v: &VertexId| is_cap[v.index()])
    };
    if !Bvh::new(&mesh).crossing_faces(&mesh, in_cap).is_empty() {
        return Err(CutError::CapCrosses);
    }
    let rims = zero_set
        .loops
        .iter()
        .map(|rim| rim.iter().filter_map(|v| remap[v.index()]).collect())
        .collect();
    Ok(Cut {
        mesh,
        rims,
        is_cap,
        split_edges,
        remap: remap[..first_cap_vertex].to_vec(),
    })
}

/// Whether the positive side is kept: the side whose front faces cover more of the screen
/// (the removed part is the smaller one as seen). Errors when a side is empty.
fn keeps_positive(
    mesh: &Mesh,
    is_positive: &[bool],
    camera: &Camera,
    viewport: DVec2,
) -> Result<bool, CutError> {
    let mut area = [0.0f64; 2];
    let mut count = [0usize; 2];
    for (f, &positive) in mesh.faces().zip(is_positive) {
        count[positive as usize] += 1;
        let corners = mesh
            .face_positions(f)
            .map(|p| camera.screen_from_world(p, viewport));
        if let [Some(a), Some(b), Some(c)] = corners {
            // y points down on screen, so a front face (counter-clockwise in the world) turns
            // clockwise there: its signed area is negative.
            let signed = (b - a).truncate().perp_dot((c - a).truncate());
            area[positive as usize] += (-0.5 * signed).max(0.0);
        }
    }
    if count.contains(&0) {
        return Err(CutError::DoesNotCross);
    }
    Ok(area[1] >= area[0])
}

/// The mean view depth of the rims' vertices.
fn mean_depth(
    mesh: &Mesh,
    loops: &[Vec<VertexId>],
    camera: &Camera,
    viewport: DVec2,
) -> Result<f64, CutError> {
    let depths: Vec<f64> = loops
        .iter()
        .flatten()
        .map(|&v| {
            camera
                .screen_from_world(mesh.position(v), viewport)
                .map(|s| s.z)
        })
        .collect::<Option<_>>()
        .ok_or(CutError::DoesNotCross)?;
    Ok(depths.iter().sum::<f64>() / depths.len().max(1) as f64)
}

/// Each rim laid flat; errors when one folds over itself or lies inside another.
fn flat_outlines(
    mesh: &Mesh,
    loops: &[Vec<VertexId>],
    unrolling: &Unrolling,
) -> Result<Vec<Vec<DVec2>>, CutError> {
    let outlines: Vec<Vec<DVec2>> = loops
        .iter()
        .map(|rim| {
            rim.iter()
                .map(|&v| unrolling.flat(mesh.position(v)))
                .collect()
        })
        .collect::<Option<_>>()
        .ok_or(CutError::DoesNotCross)?;
    if outlines.iter().any(|o| !self_crossings(o, true).is_empty()) {
        return Err(CutError::FoldedSection);
    }
    for (i, a) in outlines.iter().enumerate() {
        for (j, b) in outlines.iter().enumerate() {
            if i != j && contains(a, b[0]) {
                return Err(CutError::RingSection);
            }
        }
    }
    Ok(outlines)
}

#[cfg(test)]
mod tests;

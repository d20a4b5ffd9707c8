//! The thickness of a model's walls: the shape diameter function at its vertices.
//!
//! At each vertex the SDF ([`shape_diameter`]) casts rays into the volume in a cone around
//! the inward normal and averages their lengths: the local thickness. Two choices make it a
//! print check:
//!
//! - **Sampling.** Sixteen rays a vertex cost about 10 µs, so a scan of 500,000 vertices would
//!   take seconds. Above [`MAX_SAMPLES`] vertices the SDF is computed at every k-th vertex
//!   only (k the smallest stride that keeps it under), which is deterministic; every other
//!   vertex takes the value of its nearest sampled vertex along edges (a breadth-first search
//!   from all samples at once), so the app can still colour each vertex. A wall narrower than
//!   the spacing of samples can be missed: the report says how many vertices were sampled.
//! - **A robust minimum.** The smallest value at any vertex is not the thinnest wall: in a
//!   sharp concave crease (a leg meeting a body) the cone's rays meet the other side of the
//!   crease at once, and a vertex with a poor normal (slivers, scan noise) can read near
//!   zero. Such vertices lie along lines, whose share of the surface shrinks as the mesh is
//!   refined, while a wall too thin to print is an area. So the thinnest wall reported is
//!   the value under which [`THIN_AREA_FRACTION`] of the surface lies, each vertex weighing
//!   its area; the raw minimum is kept beside it, and the vertices under the minimum wall
//!   are listed from the raw values, so that nothing thin goes unshown.

use std::collections::VecDeque;

use crate::geometry::{Bvh, shape_diameter, vertex_areas_barycentric, vertex_normals};
use crate::mesh::{Mesh, VertexId};

/// Above this many vertices the SDF is computed at a subset of them (see the module docs):
/// about half a second on one core.
pub const MAX_SAMPLES: usize = 50_000;

/// The share of the surface, by area, allowed to read thinner than the reported thinnest
/// wall: creases and noisy vertices (see the module docs). 0.2 % of a 80 mm figure's surface is
/// a patch about 3 mm across.
pub const THIN_AREA_FRACTION: f64 = 0.002;

/// A model's wall thickness; lengths in metres, as the document's.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Thickness {
    /// Per vertex: the SDF there (or at its nearest sampled vertex), `None` where no ray met
    /// the surface again (an open mesh seen from outside) or no sample is connected.
    pub per_vertex: Vec<Option<f64>>,
    /// How many vertices the SDF was computed at: all of them up to [`MAX_SAMPLES`].
    pub n_sampled: usize,
    /// The thinnest wall: the robust minimum of the module docs; `None` without any value.
    pub thinnest: Option<f64>,
    /// The smallest value at any vertex, noise included.
    pub smallest: Option<f64>,
    /// The vertices whose value is under the minimum wall asked for.
    pub thin_vertices: Vec<VertexId>,
}

/// Measures `mesh` (whose hierarchy is `bvh`) against a minimum wall of `min_wall` metres.
pub fn thickness(mesh: &Mesh, bvh: &Bvh, min_wall: f64) -> Thickness {
    let n = mesh.n_vertices();
    let stride = n.div_ceil(MAX_SAMPLES).max(1);
    let normals = vertex_normals(mesh);
    let mut per_vertex = vec![None; n];
    let mut samples = Vec::with_capacity(n / stride + 1);
    for v in mesh.vertices().step_by(stride) {
        per_vertex[v.index()] = shape_diameter(mesh, bvh, v, normals[v.index()]);
        samples.push(v);
    }
    if stride > 1 {
        fill_from_nearest_sample(mesh, &samples, &mut per_vertex);
    }
    let areas = vertex_areas_barycentric(mesh);
    let mut weighted: Vec<(f64, f64)> = per_vertex
        .iter()
        .zip(&areas)
        .filter_map(|(value, &area)| value.map(|value| (value, area)))
        .collect();
    weighted.sort_by(|a, b| a.0.total_cmp(&b.0));
    let smallest = weighted.first().map(|&(value, _)| value);
    let total: f64 = weighted.iter().map(|&(_, area)| area).sum();
    let mut below = 0.0;
    let thinnest = weighted
        .iter()
        .find(|&&(_, area)| {
            below += area;
            below > THIN_AREA_FRACTION * total
        })
        .or(weighted.last())
        .map(|&(value, _)| value);
    let thin_vertices = mesh
        .vertices()
        .filter(|v| per_vertex[v.index()].is_some_and(|t| t < min_wall))
        .collect();
    Thickness {
        per_vertex,
        n_sampled: samples.len(),
        thinnest,
        smallest,
        thin_vertices,
    }
}

/// Gives every vertex without a value that of its nearest (in edges) sampled vertex.
fn fill_from_nearest_sample(mesh: &Mesh, samples: &[VertexId], values: &mut [Option<f64>]) {
    let mut is_reached = vec![false; values.len()];
    let mut queue: VecDeque<VertexId> = samples.iter().copied().collect();
    for v in samples {
        is_reached[v.index()] = true;
    }
    while let Some(v) = queue.pop_front() {
        for u in mesh.vertex_neighbors(v) {
            if !std::mem::replace(&mut is_reached[u.index()], true) {
                values[u.index()] = values[v.index()];
                queue.push_back(u);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;

    #[test]
    fn a_sphere_is_as_thick_as_its_diameter_nearly() {
        let mesh = primitives::icosphere(0.01, 3);
        let thickness = thickness(&mesh, &Bvh::new(&mesh), 0.001);
        assert_eq!(thickness.n_sampled, mesh.n_vertices());
        let thinnest = thickness.thinnest.unwrap();
        // Chords in a 30° cone: between 2 r cos 30° and 2 r.
        assert!((0.0170..=0.0201).contains(&thinnest), "{thinnest}");
        assert!(thickness.smallest.unwrap() <= thinnest);
        assert!(thickness.thin_vertices.is_empty());
    }

    #[test]
    fn a_large_mesh_is_sampled_and_every_vertex_gets_a_value() {
        // 163,842 vertices: sampled with stride 4.
        let mesh = primitives::icosphere(0.01, 7);
        let thickness = thickness(&mesh, &Bvh::new(&mesh), 0.025);
        assert_eq!(thickness.n_sampled, mesh.n_vertices().div_ceil(4));
        assert!(
            thickness
                .per_vertex
                .iter()
                .all(|t| t.is_some_and(|t| t > 0.017))
        );
        // Everything is under a 25 mm minimum.
        assert_eq!(thickness.thin_vertices.len(), mesh.n_vertices());
    }
}

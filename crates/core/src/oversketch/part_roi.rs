//! SEED's automatic ROI (Bao & Howard 2014, §4): the part of the model the over-sketched
//! outline belongs to, told apart by thickness, instead of spheres around the handle.
//!
//! 1. The shape diameter function ([`shape_diameter`]) of up to [`BACKGROUND_SAMPLES`]
//!    vertices spread over the mesh, and of the seeds: the handle's vertices, grown ring by
//!    ring to at least [`MIN_SEEDS`] (SEED grows them by geodesic distance on coarse meshes).
//! 2. Two mixtures of 4 Gaussians ([`Mixture`]): the whole model's SDF, the seeds'.
//! 3. Region growing from the seeds (§4.3): a neighbour joins when labelling it foreground
//!    costs less than background, `E = -ln p(sdf) + λ · (share of neighbours labelled the
//!    other way)` with SEED's `λ` = [`PART_SMOOTHNESS`]. SEED defers the terms to Fan et
//!    al.'s paint cutting; this is the reading in the digest: a likelihood data term and a
//!    label-change smoothness term. A vertex is reconsidered when a neighbour joins.
//! 4. Border smoothing (§4.4): an ROI vertex with at most two ROI neighbours leaves, an ROI
//!    vertex with a single outside neighbour takes it in, until neither is left.
//!
//! SDF values are computed only where growth looks (plus the samples), so the cost follows
//! the part's size, not the mesh's. When the grown region covers more than
//! [`MAX_PART_SHARE`] of the mesh, or hardly grows beyond the seeds (a surface of even
//! thickness, where the seeds' mixture is no likelier than the model's), the handle is not
//! on a distinct part (a sphere, a blob) and [`part_roi`] says so instead of moving nearly
//! everything or nearly nothing.

use std::collections::VecDeque;

use super::mixture::Mixture;
use crate::geometry::{Bvh, shape_diameter, vertex_normals};
use crate::mesh::{Mesh, VertexId};

/// Vertices sampled for the whole model's mixture (SEED: 2048).
pub const BACKGROUND_SAMPLES: usize = 2048;

/// The seed region is grown by rings to at least this many vertices.
pub const MIN_SEEDS: usize = 32;

/// SEED's weight of the smoothness term against the data term (`λ`, §4.3).
pub const PART_SMOOTHNESS: f64 = 0.2;

/// A grown region larger than this share of the mesh is not a part.
pub const MAX_PART_SHARE: f64 = 0.5;

/// A part is at least this many times the seeds: on a surface of even thickness the
/// seeds' mixture is no likelier than the whole model's and growth stops at once.
const MIN_GROWTH: usize = 3;

/// Gaussians per mixture (SEED, Table 2).
const COMPONENTS: usize = 4;

/// Lazily computed SDF values: `NaN` when not computed yet, `-1` when no ray came back.
struct Thickness<'a> {
    mesh: &'a Mesh,
    bvh: Bvh,
    normals: Vec<glam::DVec3>,
    values: Vec<f64>,
}

impl<'a> Thickness<'a> {
    fn new(mesh: &'a Mesh) -> Thickness<'a> {
        Thickness {
            mesh,
            bvh: Bvh::new(mesh),
            normals: vertex_normals(mesh),
            values: vec![f64::NAN; mesh.n_vertices()],
        }
    }

    fn at(&mut self, v: VertexId) -> Option<f64> {
        let value = &mut self.values[v.index()];
        if value.is_nan() {
            *value =
                shape_diameter(self.mesh, &self.bvh, v, self.normals[v.index()]).unwrap_or(-1.0);
        }
        (*value >= 0.0).then_some(*value)
    }

    fn mixture_of(&mut self, vertices: impl Iterator<Item = VertexId>) -> Option<Mixture> {
        let samples: Vec<f64> = vertices.filter_map(|v| self.at(v)).collect();
        Mixture::fit(&samples, COMPONENTS)
    }
}

/// The part of `mesh` around `handle_vertices`, as ROI flags; `None` when the handle's
/// thickness does not set a part apart (see the module docs) or no SDF ray comes back.
pub fn part_roi(mesh: &Mesh, handle_vertices: &[VertexId]) -> Option<Vec<bool>> {
    let n = mesh.n_vertices();
    let mut thickness = Thickness::new(mesh);
    let stride = n.div_ceil(BACKGROUND_SAMPLES).max(1);
    let background = thickness.mixture_of(mesh.vertices().step_by(stride))?;
    let seeds = grow_seeds(mesh, handle_vertices);
    let foreground = thickness.mixture_of(seeds.iter().copied())?;

    let mut in_roi = vec![false; n];
    let mut queue = VecDeque::new();
    for &v in &seeds {
        in_roi[v.index()] = true;
    }
    for &v in &seeds {
        queue.extend(mesh.vertex_neighbors(v).filter(|w| !in_roi[w.index()]));
    }
    while let Some(v) = queue.pop_front() {
        if in_roi[v.index()] {
            continue;
        }
        let Some(sdf) = thickness.at(v) else {
            continue;
        };
        let (inside, degree) = mesh
            .vertex_neighbors(v)
            .fold((0usize, 0usize), |(i, d), w| {
                (i + in_roi[w.index()] as usize, d + 1)
            });
        let share_inside = inside as f64 / degree.max(1) as f64;
        let cost_in = foreground.cost(sdf) + PART_SMOOTHNESS * (1.0 - share_inside);
        let cost_out = background.cost(sdf) + PART_SMOOTHNESS * share_inside;
        if cost_in < cost_out {
            in_roi[v.index()] = true;
            queue.extend(mesh.vertex_neighbors(v).filter(|w| !in_roi[w.index()]));
        }
    }
    smooth_border(mesh, &mut in_roi, &seeds);
    let size = in_roi.iter().filter(|&&r| r).count();
    let is_part = size >= MIN_GROWTH * seeds.len() && size as f64 <= MAX_PART_SHARE * n as f64;
    is_part.then_some(in_roi)
}

/// The handle vertices, grown by rings of neighbours to at least [`MIN_SEEDS`] vertices.
fn grow_seeds(mesh: &Mesh, handle_vertices: &[VertexId]) -> Vec<VertexId> {
    let mut is_seed = vec![false; mesh.n_vertices()];
    let mut seeds: Vec<VertexId> = Vec::new();
    for &v in handle_vertices {
        if !std::mem::replace(&mut is_seed[v.index()], true) {
            seeds.push(v);
        }
    }
    let mut ring_start = 0;
    while seeds.len() < MIN_SEEDS && ring_start < seeds.len() {
        let ring_end = seeds.len();
        for k in ring_start..ring_end {
            for w in mesh.vertex_neighbors(seeds[k]) {
                if !std::mem::replace(&mut is_seed[w.index()], true) {
                    seeds.push(w);
                }
            }
        }
        ring_start = ring_end;
    }
    seeds
}

/// SEED §4.4: drops "convex" ROI vertices (at most two ROI neighbours) and fills
/// "concave" ones (a single outside neighbour), re-examining the neighbours of each change.
/// Seeds always stay.
fn smooth_border(mesh: &Mesh, in_roi: &mut [bool], seeds: &[VertexId]) {
    let mut is_seed = vec![false; in_roi.len()];
    for &v in seeds {
        is_seed[v.index()] = true;
    }
    let mut work: VecDeque<VertexId> = mesh.vertices().filter(|v| in_roi[v.index()]).collect();
    // Each change re-queues a one-ring; the guard stops an oscillation (none was seen).
    let mut budget = 8 * in_roi.len();
    while let Some(v) = work.pop_front() {
        if budget == 0 {
            break;
        }
        budget -= 1;
        if !in_roi[v.index()] || is_seed[v.index()] {
            continue;
        }
        let outside: Vec<VertexId> = mesh
            .vertex_neighbors(v)
            .filter(|w| !in_roi[w.index()])
            .collect();
        let inside = mesh.vertex_neighbors(v).count() - outside.len();
        if inside <= 2 {
            in_roi[v.index()] = false;
        } else if outside.len() == 1 {
            in_roi[outside[0].index()] = true;
        } else {
            continue;
        }
        work.extend(mesh.vertex_neighbors(v));
        work.extend(outside);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;

    #[test]
    fn a_sphere_has_no_distinct_part() {
        let mesh = primitives::icosphere(1.0, 4);
        let handle: Vec<VertexId> = mesh.vertex_neighbors(VertexId(0)).collect();
        assert!(part_roi(&mesh, &handle).is_none());
    }

    #[test]
    fn seeds_grow_by_rings_to_the_minimum() {
        let mesh = primitives::icosphere(1.0, 4);
        let seeds = grow_seeds(&mesh, &[VertexId(0)]);
        assert!(seeds.len() >= MIN_SEEDS);
        assert_eq!(seeds[0], VertexId(0));
        // Within a few rings of the start (edges about 0.08 long).
        let ring_max = seeds
            .iter()
            .map(|&v| mesh.position(v).distance(mesh.position(VertexId(0))))
            .fold(0.0, f64::max);
        assert!(ring_max < 0.35, "{ring_max}");
    }
}

//! The region of interest of an over-sketch: grown from the handle vertices over mesh
//! edges, kept inside a union of spheres (SilSketch, Nealen's dissertation §5.4.4).
//!
//! Each handle vertex contributes a sphere centred at its position with radius equal to
//! its displacement `d_{h,s}` times a factor (the thesis found the identity, factor 1,
//! enough): a stroke drawn farther away frees more material. Growth is a breadth-first walk
//! from the handle vertices that only enters vertices inside the union, so a part of the
//! mesh that the union reaches but that is not connected through it stays out.

use glam::DVec3;
use serde::{Deserialize, Serialize};

use crate::mesh::{Mesh, VertexId};

/// Which vertices an over-sketch may move.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum OversketchRoi {
    /// Those near the handle, within spheres as large as its displacements (SilSketch,
    /// [`roi_from_displacements`]): a small change stays local.
    #[default]
    NearHandle,
    /// The part of the model the handle lies on, told apart by thickness (SEED,
    /// [`super::part_roi`]): an ear or a finger bends as a whole, the body stays.
    Part,
}

impl OversketchRoi {
    /// Whether this is the default (for serde's `skip_serializing_if`).
    pub fn is_near_handle(&self) -> bool {
        *self == OversketchRoi::NearHandle
    }
}

/// Radius factor that reproduces the thesis (`r_s = d_{h,s}`).
pub const ROI_RADIUS_FACTOR: f64 = 1.0;

/// Per-vertex ROI flags: the handle vertices, plus every vertex reachable from them over
/// edges through vertices inside the union of spheres centred at each handle vertex with
/// radius `displacement × radius_factor`. Handle ids outside the mesh are ignored.
pub fn roi_from_displacements(
    mesh: &Mesh,
    handle_vertices: &[(VertexId, f64)],
    radius_factor: f64,
) -> Vec<bool> {
    let n = mesh.n_vertices();
    let spheres: Vec<(DVec3, f64)> = handle_vertices
        .iter()
        .filter(|(v, _)| v.index() < n)
        .map(|&(v, displacement)| {
            let radius = (displacement * radius_factor).max(0.0);
            (mesh.position(v), radius * radius)
        })
        .collect();
    let is_inside = |p: DVec3| spheres.iter().any(|&(c, r2)| p.distance_squared(c) <= r2);

    // Every vertex is tested at most once: the union does not depend on the path.
    let mut in_roi = vec![false; n];
    let mut tested = vec![false; n];
    let mut stack = Vec::new();
    for &(v, _) in handle_vertices {
        if v.index() < n && !in_roi[v.index()] {
            in_roi[v.index()] = true;
            tested[v.index()] = true;
            stack.push(v);
        }
    }
    while let Some(v) = stack.pop() {
        for w in mesh.vertex_neighbors(v) {
            if tested[w.index()] {
                continue;
            }
            tested[w.index()] = true;
            if is_inside(mesh.position(w)) {
                in_roi[w.index()] = true;
                stack.push(w);
            }
        }
    }
    in_roi
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::TriSoup;
    use crate::mesh::primitives::icosphere;

    #[test]
    fn one_handle_vertex_selects_its_cap() {
        // A ball meets a sphere in a connected cap, so the ROI is exactly the vertices
        // within the displacement.
        let mesh = icosphere(1.0, 4);
        let handle = VertexId(7);
        let centre = mesh.position(handle);
        for d in [0.0, 0.1, 0.35, 0.8, 1.5, 2.5] {
            let roi = roi_from_displacements(&mesh, &[(handle, d)], ROI_RADIUS_FACTOR);
            let expected: Vec<bool> = mesh
                .positions()
                .iter()
                .map(|p| p.distance(centre) <= d)
                .collect();
            assert_eq!(roi, expected, "d = {d}");
            assert!(roi[handle.index()]);
        }
        // The factor scales the radius.
        let half = roi_from_displacements(&mesh, &[(handle, 0.8)], 0.5);
        let quarter = roi_from_displacements(&mesh, &[(handle, 0.4)], 1.0);
        assert_eq!(half, quarter);
    }

    #[test]
    fn the_union_covers_each_handle_vertex_and_grows_only_through_itself() {
        // Two unit spheres 2.5 apart in one mesh. A handle vertex on the first, nearest the
        // second, with a displacement reaching over the gap: the second sphere's near
        // vertices lie in the ball but are not connected to the handle, so they stay out.
        let sphere = icosphere(1.0, 3).to_soup();
        let mut soup = TriSoup::default();
        soup.append(&sphere);
        let mut other = sphere.clone();
        other.positions.iter_mut().for_each(|p| p.x += 2.5);
        soup.append(&other);
        let mesh = Mesh::from_soup(&soup).expect("two spheres");
        let n_first = sphere.positions.len();
        let handle = (0..n_first)
            .max_by(|&a, &b| mesh.positions()[a].x.total_cmp(&mesh.positions()[b].x))
            .map(|i| VertexId(i as u32))
            .expect("vertices");
        let centre = mesh.position(handle);
        let roi = roi_from_displacements(&mesh, &[(handle, 1.0)], 1.0);
        let reached_by_ball = (n_first..mesh.n_vertices())
            .filter(|&i| mesh.positions()[i].distance(centre) <= 1.0)
            .count();
        assert!(reached_by_ball > 0);
        assert!(roi[n_first..].iter().all(|&inside| !inside));
        for (inside, p) in roi.iter().zip(&mesh.positions()[..n_first]) {
            assert_eq!(*inside, p.distance(centre) <= 1.0);
        }
        // A zero displacement still keeps the handle vertex itself, and a second handle on
        // the other sphere adds its own cap.
        let far = VertexId(n_first as u32);
        let roi = roi_from_displacements(&mesh, &[(handle, 0.0), (far, 0.3)], 1.0);
        let count = roi.iter().filter(|&&b| b).count();
        let far_cap = (0..mesh.n_vertices())
            .filter(|&i| mesh.positions()[i].distance(mesh.position(far)) <= 0.3)
            .count();
        assert!(roi[handle.index()] && roi[far.index()]);
        assert_eq!(count, 1 + far_cap);
    }
}

//! Colours carried onto the new mesh of an op that changed a painted model's triangles (a
//! remesh, a cut, a merge): each new vertex takes the colour of the nearest point of the
//! surfaces it was made from, interpolated across that point's triangle.
//!
//! So a split edge's new vertex, which lies on the old edge, takes the blend of its ends; a
//! collapse's vertex the colour of where it landed; a flip, which moves nothing, keeps every
//! colour exactly; a merge keeps each side's colours, as each vertex lies on its own side's
//! surface. Why not thread colours through every mesh edit instead: remeshing, cutting,
//! tunnelling and merging each build their mesh differently, and an attribute forgotten by
//! one of them is a colour lost; one transfer after the op covers them all, at the cost of a
//! nearest-point query per vertex, and only for painted models.

use glam::DVec3;

use crate::geometry::{Bvh, barycentric};
use crate::mesh::Mesh;

/// The colour of each vertex of `mesh` taken from `sources` (meshes and their colours, one
/// per vertex), by the nearest point of any of them; vertices of an empty source list
/// keep `fallback`.
pub fn carried_colors(
    sources: &[(&Mesh, &[[f32; 3]])],
    mesh: &Mesh,
    fallback: [f32; 3],
) -> Vec<[f32; 3]> {
    let hierarchies: Vec<Bvh> = sources.iter().map(|(mesh, _)| Bvh::new(mesh)).collect();
    mesh.positions()
        .iter()
        .map(|&p| {
            let nearest = (sources.iter().zip(&hierarchies))
                .filter_map(|(&(source, colors), bvh)| {
                    let (q, f) = bvh.nearest(source, p)?;
                    Some((q.distance_squared(p), source, colors, q, f))
                })
                .min_by(|a, b| a.0.total_cmp(&b.0));
            let Some((_, source, colors, q, f)) = nearest else {
                return fallback;
            };
            let weights = barycentric(source.face_positions(f), q);
            let weights = if weights.is_finite() {
                weights.clamp(DVec3::ZERO, DVec3::ONE)
            } else {
                DVec3::splat(1.0 / 3.0)
            };
            let corners = source.face_vertices(f).map(|v| colors[v.index()]);
            let sum = weights.x + weights.y + weights.z;
            std::array::from_fn(|i| {
                let mixed = f64::from(corners[0][i]) * weights.x
                    + f64::from(corners[1][i]) * weights.y
                    + f64::from(corners[2][i]) * weights.z;
                (mixed / sum) as f32
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{HalfedgeId, primitives};

    /// A colour that varies linearly over space, so interpolation reproduces it exactly.
    fn ramp(p: DVec3) -> [f32; 3] {
        [(0.5 + 0.25 * p.x) as f32, (0.5 + 0.25 * p.y) as f32, 0.3]
    }

    #[test]
    fn a_split_edge_takes_the_blend_of_its_ends_and_a_flip_keeps_every_colour() {
        let mesh = primitives::icosphere(1.0, 2);
        let colors: Vec<_> = mesh.positions().iter().map(|&p| ramp(p)).collect();
        let mut edited = mesh.clone();
        let mut splits = Vec::new();
        for h in [0, 30, 61, 95] {
            let h = HalfedgeId(h);
            let (a, b) = (edited.tail(h), edited.head(h));
            let middle = 0.5 * (edited.position(a) + edited.position(b));
            splits.push((edited.split_edge(h, middle), a, b));
        }
        for h in [150, 212, 300] {
            edited.flip_edge(HalfedgeId(h));
        }
        let carried = carried_colors(&[(&mesh, &colors)], &edited, [0.0; 3]);
        for v in 0..mesh.n_vertices() {
            assert_eq!(carried[v], colors[v], "vertex {v} kept through the flips");
        }
        for (m, a, b) in splits {
            let blend: [f32; 3] =
                std::array::from_fn(|i| 0.5 * (colors[a.index()][i] + colors[b.index()][i]));
            let close = (0..3).all(|i| (carried[m.index()][i] - blend[i]).abs() < 1e-6);
            assert!(close, "{:?} against {blend:?}", carried[m.index()]);
        }
    }

    #[test]
    fn each_side_of_two_sources_keeps_its_own_colour() {
        let left = primitives::icosphere(1.0, 2);
        let mut right = left.clone();
        right.positions_mut().iter_mut().for_each(|p| p.x += 3.0);
        let red = vec![[1.0, 0.0, 0.0]; left.n_vertices()];
        let blue = vec![[0.0, 0.0, 1.0]; right.n_vertices()];
        let sources = [(&left, red.as_slice()), (&right, blue.as_slice())];
        let finer = primitives::icosphere(1.0, 3);
        assert!(
            carried_colors(&sources, &finer, [0.0; 3])
                .iter()
                .all(|&c| c == [1.0, 0.0, 0.0])
        );
        assert_eq!(carried_colors(&[], &finer, [0.2; 3])[0], [0.2; 3]);
    }
}

//! Linear BVH construction (Lauterbach et al., "Fast BVH construction on GPUs", 2009;
//! Karras, "Maximizing parallelism in the construction of BVHs, octrees, and k-d trees",
//! 2012): the triangles are sorted along a Morton curve of their centroids, and each node
//! splits its range where the highest bit that differs between its first and last codes
//! flips, which is the middle plane of its octree cell (a spatial median). Boxes come from a
//! bottom-up [`Bvh::refit`](super::Bvh::refit).
//!
//! Why not the surface-area heuristic: binned SAH (Wald 2007) spent 20 ms on 82k triangles
//! here, mostly in per-node bin sweeps, against about a sort's worth for this; on meshes of
//! even triangles the trees differ little, and the few hundred rays of a silhouette frame
//! do not notice.

use super::node::{Aabb, Node, triangle_box};
use crate::mesh::Mesh;

/// Ranges at most this long become leaves.
pub(super) const MAX_LEAF: usize = 4;
/// Grid cells per axis for the Morton codes (10 bits each, 30 in all).
const GRID: f64 = 1024.0;

/// The hierarchy's nodes (depth first, siblings side by side, boxes not yet set) and the
/// permuted face indices.
pub(super) fn build(mesh: &Mesh) -> (Vec<Node>, Vec<u32>) {
    let n = mesh.n_faces();
    let centroids: Vec<glam::DVec3> = (0..n as u32)
        .map(|f| {
            let b = triangle_box(mesh, f);
            0.5 * (b.lo + b.hi)
        })
        .collect();
    let mut bounds = Aabb::EMPTY;
    for &c in &centroids {
        bounds.grow(Aabb { lo: c, hi: c });
    }
    let scale = GRID / (bounds.hi - bounds.lo).max_element().max(f64::MIN_POSITIVE);
    // Code in the high half, face in the low half: one sort, ties broken by face.
    let mut keys: Vec<u64> = centroids
        .iter()
        .enumerate()
        .map(|(f, &c)| {
            let cell = ((c - bounds.lo) * scale).min(glam::DVec3::splat(GRID - 1.0));
            let code = spread_bits(cell.x as u32)
                | spread_bits(cell.y as u32) << 1
                | spread_bits(cell.z as u32) << 2;
            u64::from(code) << 32 | f as u64
        })
        .collect();
    keys.sort_unstable();
    let codes: Vec<u32> = keys.iter().map(|k| (k >> 32) as u32).collect();
    let faces: Vec<u32> = keys.iter().map(|&k| k as u32).collect();

    let mut nodes = Vec::with_capacity(2 * n.div_ceil(MAX_LEAF));
    if n == 0 {
        return (nodes, faces);
    }
    nodes.push(leaf(0, n));
    let mut stack = vec![0usize];
    while let Some(index) = stack.pop() {
        let Node { first, count, .. } = nodes[index];
        let (first, count) = (first as usize, count as usize);
        if count <= MAX_LEAF {
            continue;
        }
        let mid = split_point(&codes[first..first + count]);
        let first_child = nodes.len();
        nodes.push(leaf(first, mid));
        nodes.push(leaf(first + mid, count - mid));
        nodes[index].first = first_child as u32;
        nodes[index].count = 0;
        stack.extend([first_child, first_child + 1]);
    }
    (nodes, faces)
}

fn leaf(first: usize, count: usize) -> Node {
    Node {
        bounds: Aabb::EMPTY,
        first: first as u32,
        count: count as u32,
    }
}

/// Where a sorted run of codes splits: the first code with the highest differing bit set, or
/// the middle when all codes are equal. Always inside `1..codes.len()`.
fn split_point(codes: &[u32]) -> usize {
    let (first, last) = (codes[0], codes[codes.len() - 1]);
    if first == last {
        return codes.len() / 2;
    }
    let bit = 31 - (first ^ last).leading_zeros();
    let prefix = first >> bit;
    codes.partition_point(|&code| code >> bit == prefix)
}

/// Spreads the low 10 bits of `x` to every third bit.
fn spread_bits(x: u32) -> u32 {
    let mut x = x & 0x3ff;
    x = (x | x << 16) & 0x0300_00ff;
    x = (x | x << 8) & 0x0300_f00f;
    x = (x | x << 4) & 0x030c_30c3;
    (x | x << 2) & 0x0924_9249
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn morton_bits_interleave() {
        assert_eq!(spread_bits(0b1), 0b1);
        assert_eq!(spread_bits(0b11), 0b1001);
        assert_eq!(spread_bits(0x3ff), 0x0924_9249);
        // x = 1, y = 1, z = 1 gives the lowest three bits.
        assert_eq!(
            spread_bits(1) | spread_bits(1) << 1 | spread_bits(1) << 2,
            0b111
        );
    }

    #[test]
    fn splits_fall_where_the_top_bit_flips() {
        assert_eq!(split_point(&[0b000, 0b001, 0b100, 0b101]), 2);
        assert_eq!(split_point(&[0b000, 0b001, 0b011, 0b100]), 3);
        assert_eq!(split_point(&[7, 7, 7, 7, 7]), 2);
    }
}

//! A plain triangle soup: positions plus index triples, with no connectivity.
//!
//! The soup is what glTF, the GPU and non-manifold input speak. It may hold anything (repeated
//! triangles, bowties, unused vertices); [`crate::mesh::Mesh::from_soup`] decides whether it is
//! a manifold mesh.

use glam::DVec3;
use serde::{Deserialize, Serialize};

/// Positions and counter-clockwise index triples.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct TriSoup {
    /// Vertex positions.
    pub positions: Vec<DVec3>,
    /// Triangles as indices into `positions`.
    pub triangles: Vec<[u32; 3]>,
}

impl TriSoup {
    /// Appends `other`, offsetting its indices, so several meshes can become one.
    pub fn append(&mut self, other: &TriSoup) {
        let offset = self.positions.len() as u32;
        self.positions.extend_from_slice(&other.positions);
        self.triangles
            .extend(other.triangles.iter().map(|t| t.map(|i| i + offset)));
    }

    /// Drops vertices no triangle uses and renumbers the rest, keeping their order.
    ///
    /// Returns the new index of every old vertex (`None` for dropped ones). Triangles with an
    /// out-of-range index are left untouched, so `from_soup` still reports them.
    pub fn remove_unreferenced_vertices(&mut self) -> Vec<Option<u32>> {
        let n = self.positions.len();
        let mut is_used = vec![false; n];
        for &i in self.triangles.iter().flatten() {
            if let Some(used) = is_used.get_mut(i as usize) {
                *used = true;
            }
        }
        let mut new_from_old = vec![None; n];
        let mut n_kept = 0u32;
        for (old, &used) in is_used.iter().enumerate() {
            if used {
                new_from_old[old] = Some(n_kept);
                self.positions[n_kept as usize] = self.positions[old];
                n_kept += 1;
            }
        }
        self.positions.truncate(n_kept as usize);
        for i in self.triangles.iter_mut().flatten() {
            if let Some(Some(new)) = new_from_old.get(*i as usize) {
                *i = *new;
            }
        }
        new_from_old
    }
}

/// How many pieces `n_vertices` vertices make when the triangles join the vertices they share
/// (union-find with path halving); a vertex in no triangle is a piece of its own.
pub fn count_components(n_vertices: usize, triangles: &[[u32; 3]]) -> usize {
    let mut parent: Vec<usize> = (0..n_vertices).collect();
    fn find(parent: &mut [usize], mut v: usize) -> usize {
        while parent[v] != v {
            parent[v] = parent[parent[v]];
            v = parent[v];
        }
        v
    }
    for triangle in triangles {
        let a = find(&mut parent, triangle[0] as usize);
        for &other in &triangle[1..] {
            let b = find(&mut parent, other as usize);
            parent[b] = a;
        }
    }
    (0..parent.len())
        .filter(|&v| find(&mut parent, v) == v)
        .count()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn append_offsets_indices() {
        let tri = TriSoup {
            positions: vec![DVec3::X, DVec3::Y, DVec3::Z],
            triangles: vec![[0, 1, 2]],
        };
        let mut both = tri.clone();
        both.append(&tri);
        assert_eq!(both.positions.len(), 6);
        assert_eq!(both.triangles, vec![[0, 1, 2], [3, 4, 5]]);
    }

    #[test]
    fn unreferenced_vertices_are_dropped_and_renumbered() {
        let mut soup = TriSoup {
            positions: vec![DVec3::ZERO, DVec3::X, DVec3::ONE, DVec3::Y, DVec3::Z],
            triangles: vec![[1, 3, 4]],
        };
        let map = soup.remove_unreferenced_vertices();
        assert_eq!(map, vec![None, Some(0), None, Some(1), Some(2)]);
        assert_eq!(soup.positions, vec![DVec3::X, DVec3::Y, DVec3::Z]);
        assert_eq!(soup.triangles, vec![[0, 1, 2]]);
    }
}

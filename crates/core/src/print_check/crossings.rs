//! Where a surface passes through itself: the crossing triangle pairs the BVH finds
//! ([`Bvh::crossing_faces`]), gathered into places a person would count.
//!
//! Two spheres pushed into each other cross along one curve, met by two rings of triangles,
//! one on each sphere, and by dozens of pairs: one place. So the faces that cross are joined
//! when they cross each other or share an edge, and each group is a place.

use crate::geometry::Bvh;
use crate::mesh::{FaceId, HalfedgeId, Mesh};

/// The crossings of a surface with itself.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Crossings {
    /// Every pair of triangles that cross, the lower face first, sorted.
    pub pairs: Vec<(FaceId, FaceId)>,
    /// The faces in any pair, sorted, each once: what the app marks.
    pub faces: Vec<FaceId>,
    /// How many separate places the surface crosses itself in (see the module docs).
    pub n_places: usize,
}

/// The crossings of `mesh`, whose hierarchy is `bvh`.
pub fn crossings(mesh: &Mesh, bvh: &Bvh) -> Crossings {
    let pairs = bvh.crossing_faces(mesh, |_| true);
    let mut faces: Vec<FaceId> = pairs.iter().flat_map(|&(f, g)| [f, g]).collect();
    faces.sort_unstable();
    faces.dedup();
    let mut groups = UnionFind::new(mesh.n_faces());
    for &(f, g) in &pairs {
        groups.join(f.index(), g.index());
    }
    let mut is_crossing = vec![false; mesh.n_faces()];
    for f in &faces {
        is_crossing[f.index()] = true;
    }
    for &f in &faces {
        for k in 0..3 {
            let h = HalfedgeId(3 * f.0 + k);
            if let Some(twin) = mesh.twin(h)
                && is_crossing[mesh.face(twin).index()]
            {
                groups.join(f.index(), mesh.face(twin).index());
            }
        }
    }
    let n_places = faces
        .iter()
        .filter(|f| groups.root(f.index()) == f.index())
        .count();
    Crossings {
        pairs,
        faces,
        n_places,
    }
}

/// Disjoint sets over `0..n`, with path halving.
struct UnionFind {
    parent: Vec<usize>,
}

impl UnionFind {
    fn new(n: usize) -> Self {
        Self {
            parent: (0..n).collect(),
        }
    }

    fn root(&mut self, mut i: usize) -> usize {
        while self.parent[i] != i {
            self.parent[i] = self.parent[self.parent[i]];
            i = self.parent[i];
        }
        i
    }

    fn join(&mut self, a: usize, b: usize) {
        let (a, b) = (self.root(a), self.root(b));
        // The lower index is the root, so the count above is deterministic.
        self.parent[a.max(b)] = a.min(b);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives::icosphere;

    #[test]
    fn two_pairs_of_crossing_spheres_cross_in_two_places() {
        let mut soup = icosphere(1.0, 2).to_soup();
        for dx in [1.0, 10.0, 11.0] {
            let mut other = icosphere(1.0, 2).to_soup();
            for p in &mut other.positions {
                p.x += dx;
            }
            soup.append(&other);
        }
        let mesh = Mesh::from_soup(&soup).unwrap();
        let found = crossings(&mesh, &Bvh::new(&mesh));
        assert_eq!(found.n_places, 2);
        assert!(found.pairs.len() > 40, "{}", found.pairs.len());
        assert!(found.faces.windows(2).all(|w| w[0] < w[1]));
        let single = icosphere(1.0, 2);
        assert_eq!(crossings(&single, &Bvh::new(&single)), Crossings::default());
    }
}

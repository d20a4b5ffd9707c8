//! Building a [`Mesh`] from a [`TriSoup`] and back.
//!
//! Twins are found by grouping the half-edges on their undirected edge (a counting sort on
//! the lower vertex), which is deterministic (the same soup always gives the same error),
//! linear and needs no hash map. Each group
//! of equal keys is an edge: one half-edge is a boundary edge, two opposite ones are twins, two
//! in the same direction mean flipped orientation, and three or more are a non-manifold edge.

use super::{INVALID, Mesh, MeshError, TriSoup};

/// The arrays a [`Mesh`] is made of, to move one whole between wasm instances
/// (`io::transfer`) without building its twins again.
#[derive(Debug)]
pub(crate) struct MeshParts<P, T, U> {
    pub positions: P,
    pub triangles: T,
    pub twin: U,
    pub vertex_halfedge: U,
    pub n_dead_vertices: u32,
    pub n_dead_faces: u32,
}

/// [`MeshParts`] holding their arrays.
pub(crate) type OwnedParts = MeshParts<Vec<glam::DVec3>, Vec<[u32; 3]>, Vec<u32>>;

impl Mesh {
    /// Its arrays, borrowed.
    pub(crate) fn parts(&self) -> MeshParts<&[glam::DVec3], &[[u32; 3]], &[u32]> {
        MeshParts {
            positions: &self.positions,
            triangles: &self.triangles,
            twin: &self.twin,
            vertex_halfedge: &self.vertex_halfedge,
            n_dead_vertices: self.n_dead_vertices,
            n_dead_faces: self.n_dead_faces,
        }
    }

    /// The mesh [`Mesh::parts`] gave, not checked yet: nothing may walk it before
    /// [`Mesh::parts_fit`] says it may (a worker's result is decoded in one frame and
    /// checked in the next).
    pub(crate) fn from_parts_unchecked(parts: OwnedParts) -> Mesh {
        Mesh {
            positions: parts.positions,
            triangles: parts.triangles,
            twin: parts.twin,
            vertex_halfedge: parts.vertex_halfedge,
            n_dead_vertices: parts.n_dead_vertices,
            n_dead_faces: parts.n_dead_faces,
        }
    }

    /// Whether the arrays fit together, checked in linear time for what navigation relies
    /// on, so that a corrupt buffer can neither index out of bounds nor make a one-ring walk
    /// loop for ever: every face live (three distinct vertices) or dead (all corners
    /// [`INVALID`]), as many dead as said; twins paired both ways between live faces, each
    /// running the other way along the same edge; each vertex's half-edge leaving it, or
    /// [`INVALID`] for as many dead vertices as said. Not checked: manifoldness and finite
    /// positions, which [`Mesh::validate`] covers; the parts come from this program.
    pub(crate) fn parts_fit(&self) -> bool {
        let parts = self.parts();
        let (n_vertices, n_halfedges) = (parts.positions.len(), 3 * parts.triangles.len());
        let tris = parts.triangles;
        let is_live = |f: usize| tris[f][0] != INVALID;
        let faces_fit = tris.iter().all(|&[a, b, c]| {
            let live = [a, b, c].iter().all(|&v| (v as usize) < n_vertices);
            (live && a != b && b != c && a != c) || [a, b, c] == [INVALID; 3]
        });
        // Face by face, each half-edge against its twin's face (read once): a million
        // triangles' check is a frame's work in the page, where a worker's result lands.
        let twins_fit = |f: usize, tri: &[u32; 3]| {
            (0..3).all(|k| {
                let h = 3 * f + k;
                let t = parts.twin[h] as usize;
                if t == INVALID as usize {
                    return true;
                }
                let Some(other) = tris.get(t / 3) else {
                    return false;
                };
                let (tail, head) = (tri[k], tri[(k + 1) % 3]);
                t != h
                    && parts.twin[t] as usize == h
                    && tri[0] != INVALID
                    && other[0] != INVALID
                    && tail == other[(t % 3 + 1) % 3]
                    && head == other[t % 3]
            })
        };
        faces_fit
            && parts.twin.len() == n_halfedges
            && parts.vertex_halfedge.len() == n_vertices
            && tris.iter().filter(|t| t[0] == INVALID).count() == parts.n_dead_faces as usize
            && tris.iter().enumerate().all(|(f, tri)| twins_fit(f, tri))
            && (parts.vertex_halfedge.iter().enumerate()).all(|(v, &h)| {
                let h = h as usize;
                h == INVALID as usize
                    || (h < n_halfedges && is_live(h / 3) && tris[h / 3][h % 3] as usize == v)
            })
            && (parts.vertex_halfedge.iter())
                .filter(|&&h| h == INVALID)
                .count()
                == parts.n_dead_vertices as usize
    }

    /// Builds the half-edge mesh of an oriented manifold soup.
    ///
    /// Fails on the first problem found: an index out of range, a triangle that repeats a
    /// vertex, a non-finite position, an edge with more than two triangles, two triangles
    /// with opposite orientations, a vertex whose triangles form several fans (a bowtie), or a
    /// vertex used by no triangle.
    pub fn from_soup(soup: &TriSoup) -> Result<Mesh, MeshError> {
        let n_vertices = soup.positions.len();
        check_triangles(&soup.triangles, soup.positions.len())?;
        if let Some(vertex) = soup.positions.iter().position(|p| !p.is_finite()) {
            return Err(MeshError::NonFinitePosition {
                vertex: vertex as u32,
            });
        }
        let twin = match_twins(&soup.triangles)?;
        let mut mesh = Mesh {
            positions: soup.positions.clone(),
            triangles: soup.triangles.clone(),
            twin,
            vertex_halfedge: vec![INVALID; n_vertices],
            n_dead_vertices: 0,
            n_dead_faces: 0,
        };
        let n_outgoing = mesh.assign_vertex_halfedges();
        if let Some(vertex) = mesh.vertex_halfedge.iter().position(|&h| h == INVALID) {
            return Err(MeshError::IsolatedVertex {
                vertex: vertex as u32,
            });
        }
        for v in mesh.vertices() {
            if mesh.outgoing_halfedges(v).count() != n_outgoing[v.index()] as usize {
                return Err(MeshError::NonManifoldVertex { vertex: v.0 });
            }
        }
        debug_assert_eq!(mesh.validate(), Ok(()));
        Ok(mesh)
    }

    /// The positions and triangles, without connectivity.
    pub fn to_soup(&self) -> TriSoup {
        TriSoup {
            positions: self.positions.clone(),
            triangles: self.triangles.clone(),
        }
    }

    /// Picks each vertex's half-edge (a boundary one when there is one) and returns how many
    /// half-edges leave each vertex.
    pub(super) fn assign_vertex_halfedges(&mut self) -> Vec<u32> {
        let mut n_outgoing = vec![0u32; self.n_vertices()];
        for (h, &v) in self.triangles.as_flattened().iter().enumerate() {
            let v = v as usize;
            n_outgoing[v] += 1;
            if self.vertex_halfedge[v] == INVALID || self.twin[h] == INVALID {
                self.vertex_halfedge[v] = h as u32;
            }
        }
        n_outgoing
    }
}

/// Every index in range and no triangle with a repeated corner; shared with `validate`.
pub(super) fn check_triangles(triangles: &[[u32; 3]], n_vertices: usize) -> Result<(), MeshError> {
    for (face, t) in triangles.iter().enumerate() {
        let face = face as u32;
        if let Some(&index) = t.iter().find(|&&i| i as usize >= n_vertices) {
            return Err(MeshError::IndexOutOfRange {
                face,
                index,
                n_vertices,
            });
        }
        if t[0] == t[1] || t[1] == t[2] || t[2] == t[0] {
            return Err(MeshError::DegenerateTriangle { face });
        }
    }
    Ok(())
}

/// Pairs each half-edge with its opposite, or marks it [`INVALID`] on the boundary.
fn match_twins(triangles: &[[u32; 3]]) -> Result<Vec<u32>, MeshError> {
    let corners = triangles.as_flattened();
    let mut twin = vec![INVALID; corners.len()];
    let mut error = None;
    for_each_edge(triangles, |group| {
        if error.is_some() {
            return;
        }
        match *group {
            [_] => {}
            [g, h] => {
                let (a, b) = half_edge(corners, g as usize);
                if half_edge(corners, h as usize) != (b, a) {
                    error = Some(MeshError::InconsistentOrientation { a, b });
                }
                twin[g as usize] = h;
                twin[h as usize] = g;
            }
            _ => {
                let (a, b) = half_edge(corners, group[0] as usize);
                error = Some(MeshError::NonManifoldEdge {
                    a: a.min(b),
                    b: a.max(b),
                });
            }
        }
    });
    match error {
        Some(error) => Err(error),
        None => Ok(twin),
    }
}

/// Tail and head of half-edge `h`.
pub(super) fn half_edge(corners: &[u32], h: usize) -> (u32, u32) {
    let next = if h % 3 == 2 { h - 2 } else { h + 1 };
    (corners[h], corners[next])
}

/// Calls `f` with each group of half-edges that share an undirected edge, in order of the
/// edge's (lower, higher) vertex and, within a group, of half-edge index: deterministic, so
/// the same soup always reports the same problem first.
///
/// Half-edges are bucketed by their lower vertex with a counting sort (linear time, no hash
/// map), and each small bucket is sorted by the higher vertex.
pub(super) fn for_each_edge(triangles: &[[u32; 3]], mut f: impl FnMut(&[u32])) {
    let corners = triangles.as_flattened();
    let n_vertices = corners.iter().max().map_or(0, |&v| v as usize + 1);
    let lower = |h: usize| {
        let (a, b) = half_edge(corners, h);
        a.min(b)
    };
    let higher = |h: usize| {
        let (a, b) = half_edge(corners, h);
        a.max(b)
    };
    let mut start = vec![0u32; n_vertices + 1];
    for h in 0..corners.len() {
        start[lower(h) as usize + 1] += 1;
    }
    for v in 0..n_vertices {
        start[v + 1] += start[v];
    }
    let mut fill = start.clone();
    let mut bucketed = vec![0u32; corners.len()];
    for h in 0..corners.len() {
        let slot = &mut fill[lower(h) as usize];
        bucketed[*slot as usize] = h as u32;
        *slot += 1;
    }
    for v in 0..n_vertices {
        let bucket = &mut bucketed[start[v] as usize..start[v + 1] as usize];
        bucket.sort_unstable_by_key(|&h| (higher(h as usize), h));
        for group in bucket.chunk_by(|&g, &h| higher(g as usize) == higher(h as usize)) {
            f(group);
        }
    }
}

impl From<&Mesh> for TriSoup {
    fn from(mesh: &Mesh) -> TriSoup {
        mesh.to_soup()
    }
}

impl TryFrom<&TriSoup> for Mesh {
    type Error = MeshError;

    fn try_from(soup: &TriSoup) -> Result<Mesh, MeshError> {
        Mesh::from_soup(soup)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{VertexId, primitives};
    use glam::DVec3;

    /// A mesh's parts, after `corrupt` changed them.
    fn rebuilt(mesh: &Mesh, corrupt: impl FnOnce(&mut OwnedParts)) -> Option<Mesh> {
        let parts = mesh.parts();
        let mut owned = MeshParts {
            positions: parts.positions.to_vec(),
            triangles: parts.triangles.to_vec(),
            twin: parts.twin.to_vec(),
            vertex_halfedge: parts.vertex_halfedge.to_vec(),
            n_dead_vertices: parts.n_dead_vertices,
            n_dead_faces: parts.n_dead_faces,
        };
        corrupt(&mut owned);
        let rebuilt = Mesh::from_parts_unchecked(owned);
        rebuilt.parts_fit().then_some(rebuilt)
    }

    #[test]
    fn parts_rebuild_the_mesh_and_corrupt_parts_are_refused() {
        let mesh = primitives::grid(3, 3, 1.0);
        assert_eq!(rebuilt(&mesh, |_| {}).unwrap(), mesh);
        // Two twin pairs: (h, t) and another (k, u), neither sharing a face with the first.
        let pairs = |p: &OwnedParts| {
            let h = p.twin.iter().position(|&t| t != INVALID).unwrap();
            let t = p.twin[h] as usize;
            let k = (0..p.twin.len())
                .find(|&k| ![h / 3, t / 3].contains(&(k / 3)) && p.twin[k] != INVALID)
                .unwrap();
            (h, t, k, p.twin[k] as usize)
        };
        let refused: [&dyn Fn(&mut OwnedParts); 9] = [
            // Half a dead face: navigation would read its invalid corner.
            &|p| p.triangles[0][1] = INVALID,
            // A twin past the end, a twin that is itself.
            &|p| {
                let (h, ..) = pairs(p);
                p.twin[h] = p.twin.len() as u32 + 5;
            },
            &|p| {
                let (h, t, ..) = pairs(p);
                (p.twin[h], p.twin[t]) = (h as u32, INVALID);
            },
            // Twins that point back at each other across edges of other vertices.
            &|p| {
                let (h, t, k, u) = pairs(p);
                (p.twin[h], p.twin[u]) = (u as u32, h as u32);
                (p.twin[k], p.twin[t]) = (t as u32, k as u32);
            },
            // A twin that does not point back: a one-ring walk could loop for ever.
            &|p| {
                let h = p.twin.iter().position(|&t| t != INVALID).unwrap();
                let t = p.twin[h] as usize;
                let other = (0..p.twin.len())
                    .find(|&k| k != h && k != t && p.twin[k] != INVALID)
                    .unwrap();
                p.twin[other] = p.twin[h];
            },
            &|p| p.twin.pop().map(drop).unwrap_or(()),
            &|p| p.vertex_halfedge[0] = p.vertex_halfedge[1],
            &|p| p.n_dead_faces = 1,
            &|p| p.triangles[2] = [0, 0, 1],
        ];
        for (k, corrupt) in refused.iter().enumerate() {
            assert!(rebuilt(&mesh, corrupt).is_none(), "corruption {k} passed");
        }
    }

    fn ids(indices: &[u32]) -> Vec<VertexId> {
        indices.iter().map(|&i| VertexId(i)).collect()
    }

    fn soup(n_vertices: usize, triangles: &[[u32; 3]]) -> TriSoup {
        let positions = (0..n_vertices)
            .map(|i| DVec3::new(i as f64, (i * i) as f64, 0.5))
            .collect();
        TriSoup {
            positions,
            triangles: triangles.to_vec(),
        }
    }

    #[test]
    fn round_trip_through_soup_is_exact() {
        let mesh = primitives::torus(2.0, 0.5, 12, 8);
        let again = Mesh::from_soup(&mesh.to_soup()).unwrap();
        assert_eq!(again, mesh);
    }

    #[test]
    fn rejects_an_edge_with_three_faces() {
        // Three fins on the edge 0-1.
        let err = Mesh::from_soup(&soup(5, &[[0, 1, 2], [1, 0, 3], [0, 1, 4]])).unwrap_err();
        assert_eq!(err, MeshError::NonManifoldEdge { a: 0, b: 1 });
    }

    #[test]
    fn rejects_a_bowtie_vertex() {
        // Two triangles touching only at vertex 0.
        let err = Mesh::from_soup(&soup(5, &[[0, 1, 2], [0, 3, 4]])).unwrap_err();
        assert_eq!(err, MeshError::NonManifoldVertex { vertex: 0 });
    }

    #[test]
    fn rejects_two_closed_fans_at_one_vertex() {
        // Two tetrahedra glued at vertex 0: every edge is manifold, the vertex is not.
        let tets = [
            [0, 2, 1],
            [0, 1, 3],
            [0, 3, 2],
            [1, 2, 3],
            [0, 5, 4],
            [0, 4, 6],
            [0, 6, 5],
            [4, 5, 6],
        ];
        let err = Mesh::from_soup(&soup(7, &tets)).unwrap_err();
        assert_eq!(err, MeshError::NonManifoldVertex { vertex: 0 });
    }

    #[test]
    fn rejects_out_of_range_degenerate_flipped_isolated_and_nan() {
        let err = Mesh::from_soup(&soup(3, &[[0, 1, 3]])).unwrap_err();
        assert_eq!(
            err,
            MeshError::IndexOutOfRange {
                face: 0,
                index: 3,
                n_vertices: 3
            }
        );
        let err = Mesh::from_soup(&soup(3, &[[0, 1, 2], [0, 2, 2]])).unwrap_err();
        assert_eq!(err, MeshError::DegenerateTriangle { face: 1 });
        let err = Mesh::from_soup(&soup(4, &[[0, 1, 2], [0, 1, 3]])).unwrap_err();
        assert_eq!(err, MeshError::InconsistentOrientation { a: 0, b: 1 });
        let err = Mesh::from_soup(&soup(4, &[[0, 1, 2]])).unwrap_err();
        assert_eq!(err, MeshError::IsolatedVertex { vertex: 3 });
        let mut nan = soup(3, &[[0, 1, 2]]);
        nan.positions[1].y = f64::NAN;
        assert_eq!(
            Mesh::from_soup(&nan).unwrap_err(),
            MeshError::NonFinitePosition { vertex: 1 }
        );
    }

    #[test]
    fn errors_read_as_sentences() {
        let err = MeshError::NonManifoldEdge { a: 3, b: 7 };
        assert_eq!(
            err.to_string(),
            "The edge between vertices 3 and 7 is shared by more than two triangles."
        );
    }

    #[test]
    fn single_triangle_and_empty_soup_build() {
        let mesh = Mesh::from_soup(&soup(3, &[[0, 1, 2]])).unwrap();
        assert_eq!(
            (mesh.n_vertices(), mesh.n_edges(), mesh.n_faces()),
            (3, 3, 1)
        );
        assert_eq!(
            mesh.vertex_neighbors(VertexId(0)).collect::<Vec<_>>(),
            ids(&[1, 2])
        );
        let empty = Mesh::from_soup(&TriSoup::default()).unwrap();
        assert_eq!(empty.n_vertices(), 0);
        assert!(empty.is_closed());
    }
}

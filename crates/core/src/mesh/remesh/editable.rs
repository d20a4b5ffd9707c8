//! A mutable copy of a [`Mesh`] for remeshing: the same corner-table layout (half-edge
//! `h = 3 f + k`), plus tombstones, so edge splits, collapses and flips are O(1) edits.
//!
//! A deleted face has [`INVALID`] corners, a deleted vertex an [`INVALID`] half-edge. Slots are
//! never reused: a split pass visits the faces it appends, which reuse of lower slots would
//! hide, and [`EditableMesh::to_soup`] drops the tombstones once at the end. Boundary status
//! never changes under the three edits (splits of boundary edges make boundary vertices,
//! collapses keep the surviving vertex's status), so it is stored per vertex, and only
//! boundary vertices pay for keeping their half-edge the boundary one.

use glam::DVec3;

use crate::mesh::{INVALID, Mesh, TriSoup};

/// The next half-edge around the same face.
pub(super) fn next(h: u32) -> u32 {
    if h % 3 == 2 { h - 2 } else { h + 1 }
}

/// The previous half-edge around the same face.
pub(super) fn prev(h: u32) -> u32 {
    if h.is_multiple_of(3) { h + 2 } else { h - 1 }
}

/// Corner-table half-edge mesh with tombstones; see the module docs.
#[derive(Clone, Debug)]
pub(super) struct EditableMesh {
    pub(super) positions: Vec<DVec3>,
    /// Tail vertex of every half-edge; [`INVALID`] for the corners of deleted faces.
    corners: Vec<u32>,
    /// Opposite half-edge, or [`INVALID`] on the boundary.
    twin: Vec<u32>,
    /// One outgoing half-edge per vertex (the boundary one on the boundary), or [`INVALID`].
    vertex_halfedge: Vec<u32>,
    is_boundary: Vec<bool>,
}

impl EditableMesh {
    pub(super) fn new(mesh: &Mesh) -> EditableMesh {
        let is_boundary = mesh
            .vertices()
            .map(|v| mesh.is_boundary_vertex(v))
            .collect();
        EditableMesh {
            positions: mesh.positions.clone(),
            corners: mesh.triangles_flat().to_vec(),
            twin: mesh.twin.clone(),
            vertex_halfedge: mesh.vertex_halfedge.clone(),
            is_boundary,
        }
    }

    /// Number of half-edge slots, deleted ones included.
    pub(super) fn n_halfedge_slots(&self) -> u32 {
        self.corners.len() as u32
    }

    /// Number of vertex slots, deleted ones included.
    pub(super) fn n_vertex_slots(&self) -> u32 {
        self.positions.len() as u32
    }

    pub(super) fn is_live_halfedge(&self, h: u32) -> bool {
        self.corners[h as usize] != INVALID
    }

    pub(super) fn is_live_vertex(&self, v: u32) -> bool {
        self.vertex_halfedge[v as usize] != INVALID
    }

    pub(super) fn tail(&self, h: u32) -> u32 {
        self.corners[h as usize]
    }

    pub(super) fn head(&self, h: u32) -> u32 {
        self.corners[next(h) as usize]
    }

    /// The corner opposite `h` in its face.
    pub(super) fn opposite(&self, h: u32) -> u32 {
        self.corners[prev(h) as usize]
    }

    /// The opposite half-edge, or `None` on the boundary.
    pub(super) fn twin(&self, h: u32) -> Option<u32> {
        let t = self.twin[h as usize];
        (t != INVALID).then_some(t)
    }

    pub(super) fn is_boundary_vertex(&self, v: u32) -> bool {
        self.is_boundary[v as usize]
    }

    pub(super) fn position(&self, v: u32) -> DVec3 {
        self.positions[v as usize]
    }

    /// Outgoing half-edges of `v`, counter-clockwise from its boundary one.
    pub(super) fn outgoing(&self, v: u32) -> Outgoing<'_> {
        let start = self.vertex_halfedge[v as usize];
        Outgoing {
            mesh: self,
            start,
            current: (start != INVALID).then_some(start),
        }
    }

    /// Calls `visit` on every neighbour of `v`, counter-clockwise.
    pub(super) fn for_each_neighbor(&self, v: u32, mut visit: impl FnMut(u32)) {
        let mut last = INVALID;
        for h in self.outgoing(v) {
            visit(self.head(h));
            last = h;
        }
        // A boundary fan has one more neighbour than outgoing half-edges.
        if self.is_boundary_vertex(v) && last != INVALID {
            visit(self.opposite(last));
        }
    }

    pub(super) fn valence(&self, v: u32) -> usize {
        self.outgoing(v).count() + usize::from(self.is_boundary_vertex(v))
    }

    pub(super) fn is_neighbor(&self, v: u32, w: u32) -> bool {
        let mut found = false;
        self.for_each_neighbor(v, |u| found |= u == w);
        found
    }

    /// A half-edge of the edge `a–b` (either direction), if there is such an edge.
    pub(super) fn find_halfedge(&self, a: u32, b: u32) -> Option<u32> {
        let from = |u: u32, w: u32| self.outgoing(u).find(|&h| self.head(h) == w);
        from(a, b).or_else(|| from(b, a))
    }

    /// Sets the half-edge of `v` to `h` (which leaves `v`), turned clockwise to the boundary
    /// one if `v` is on the boundary, as the counter-clockwise walks require.
    fn set_outgoing(&mut self, v: u32, mut h: u32) {
        debug_assert_eq!(self.tail(h), v);
        if self.is_boundary_vertex(v) {
            while let Some(t) = self.twin(h) {
                h = next(t);
            }
        }
        self.vertex_halfedge[v as usize] = h;
    }

    fn link_twins(&mut self, h: u32, t: u32) {
        if h != INVALID {
            self.twin[h as usize] = t;
        }
        if t != INVALID {
            self.twin[t as usize] = h;
        }
    }

    fn push_face(&mut self, corners: [u32; 3]) -> u32 {
        let h = self.n_halfedge_slots();
        self.corners.extend(corners);
        self.twin.extend([INVALID; 3]);
        h
    }

    fn push_vertex(&mut self, p: DVec3, is_boundary: bool) -> u32 {
        self.positions.push(p);
        self.vertex_halfedge.push(INVALID);
        self.is_boundary.push(is_boundary);
        self.positions.len() as u32 - 1
    }

    /// Splits the edge of `h` at `p` into two edges and each of its (one or two) faces into
    /// two; returns the new vertex.
    ///
    /// Face `(a, b, c)` of `h = a→b` keeps its slots as `(a, m, c)` and gains `(m, b, c)`; the
    /// twin face `(b, a, d)` becomes `(m, a, d)` and gains `(b, m, d)`.
    pub(super) fn split(&mut self, h: u32, p: DVec3) -> u32 {
        let (h1, h2) = (next(h), prev(h));
        let (a, b, c) = (self.tail(h), self.head(h), self.opposite(h));
        let t = self.twin[h as usize];
        let m = self.push_vertex(p, t == INVALID);
        let outer_bc = self.twin[h1 as usize];
        self.corners[h1 as usize] = m;
        let g = self.push_face([m, b, c]);
        self.link_twins(g + 1, outer_bc);
        self.link_twins(h1, g + 2);
        if t != INVALID {
            let t2 = prev(t);
            let d = self.tail(t2);
            let outer_bd = self.twin[t2 as usize];
            self.corners[t as usize] = m;
            let k = self.push_face([b, m, d]);
            self.link_twins(k + 2, outer_bd);
            self.link_twins(t2, k + 1);
            self.link_twins(g, k);
            self.set_outgoing(d, t2);
        }
        self.set_outgoing(m, g);
        self.set_outgoing(b, g + 1);
        self.set_outgoing(a, h);
        self.set_outgoing(c, h2);
        m
    }

    /// Collapses the edge of `h` by removing its end `r` (either one) with its one or two
    /// faces on the edge; `r`'s edges join the other end `k`, which keeps its position. The
    /// caller checks the link condition and valences, so every vertex keeps a face.
    pub(super) fn collapse(&mut self, h: u32, r: u32) {
        let k = if self.tail(h) == r {
            self.head(h)
        } else {
            self.tail(h)
        };
        let t = self.twin[h as usize];
        // Renaming the tails of `r`'s outgoing half-edges renames it in every face.
        let start = self.vertex_halfedge[r as usize];
        let mut g = start;
        loop {
            self.corners[g as usize] = k;
            match self.twin(prev(g)) {
                Some(u) if u != start => g = u,
                _ => break,
            }
        }
        self.vertex_halfedge[r as usize] = INVALID;
        let (c, c_out, mut k_out) = self.remove_face(h);
        let d_fan = (t != INVALID).then(|| self.remove_face(t));
        if let Some((d, d_out, k_out_d)) = d_fan {
            self.set_outgoing(d, d_out);
            k_out = k_out_d;
        }
        self.set_outgoing(c, c_out);
        self.set_outgoing(k, k_out);
    }

    /// Deletes the face of `h` (whose edge collapses, tails already renamed to the kept
    /// vertex `k`) and glues the twins of its two other edges; returns the face's third
    /// vertex `c`, a surviving half-edge leaving `c` and one leaving `k`.
    fn remove_face(&mut self, h: u32) -> (u32, u32, u32) {
        let (h1, h2) = (next(h), prev(h));
        let c = self.opposite(h);
        // `outer_1` runs c→k and `outer_2` k→c; at least one exists since `c` keeps a face.
        let (outer_1, outer_2) = (self.twin[h1 as usize], self.twin[h2 as usize]);
        self.link_twins(outer_1, outer_2);
        for slot in [h, h1, h2] {
            self.corners[slot as usize] = INVALID;
            self.twin[slot as usize] = INVALID;
        }
        let c_out = if outer_1 != INVALID {
            outer_1
        } else {
            next(outer_2)
        };
        let k_out = if outer_2 != INVALID {
            outer_2
        } else {
            next(outer_1)
        };
        (c, c_out, k_out)
    }

    /// Flips the interior edge of `h = a→b` between faces `(a, b, c)` and `(b, a, d)` into the
    /// edge `c–d`, leaving faces `(a, d, c)` and `(b, c, d)` in the same slots.
    pub(super) fn flip(&mut self, h: u32) {
        let Some(t) = self.twin(h) else { return };
        let (h1, h2, t1, t2) = (next(h), prev(h), next(t), prev(t));
        let (a, b, c, d) = (
            self.tail(h),
            self.head(h),
            self.opposite(h),
            self.opposite(t),
        );
        let [outer_bc, outer_ca, outer_ad, outer_db] =
            [h1, h2, t1, t2].map(|s| self.twin[s as usize]);
        for (slot, v) in [(h, d), (h1, c), (h2, a), (t, c), (t1, d), (t2, b)] {
            self.corners[slot as usize] = v;
        }
        self.link_twins(h1, outer_ca);
        self.link_twins(h2, outer_ad);
        self.link_twins(t1, outer_db);
        self.link_twins(t2, outer_bc);
        self.set_outgoing(a, h2);
        self.set_outgoing(b, t2);
        self.set_outgoing(c, h1);
        self.set_outgoing(d, t1);
    }

    /// The live triangles and vertices with compact indices, and the new index of every old
    /// vertex ([`INVALID`] for removed ones).
    pub(super) fn to_soup(&self) -> (TriSoup, Vec<u32>) {
        let mut new_from_old = vec![INVALID; self.positions.len()];
        let mut positions = Vec::new();
        for (v, &h) in self.vertex_halfedge.iter().enumerate() {
            if h != INVALID {
                new_from_old[v] = positions.len() as u32;
                positions.push(self.positions[v]);
            }
        }
        let triangles = self
            .corners
            .chunks_exact(3)
            .filter(|t| t[0] != INVALID)
            .map(|t| [t[0], t[1], t[2]].map(|v| new_from_old[v as usize]))
            .collect();
        (
            TriSoup {
                positions,
                triangles,
            },
            new_from_old,
        )
    }

    /// Whether twins pair opposite half-edges and every live vertex's half-edge leaves it
    /// (the boundary one on the boundary); for `debug_assert!` after each pass.
    pub(super) fn is_consistent(&self) -> bool {
        let twins_match = (0..self.n_halfedge_slots())
            .filter(|&h| self.is_live_halfedge(h))
            .all(|h| match self.twin(h) {
                Some(t) => {
                    self.twin(t) == Some(h)
                        && self.tail(t) == self.head(h)
                        && self.head(t) == self.tail(h)
                }
                None => true,
            });
        let fans_match = (0..self.n_vertex_slots())
            .filter(|&v| self.is_live_vertex(v))
            .all(|v| {
                let h = self.vertex_halfedge[v as usize];
                self.is_live_halfedge(h)
                    && self.tail(h) == v
                    && (self.twin(h).is_none() == self.is_boundary_vertex(v))
            });
        twins_match && fans_match
    }
}

/// Outgoing half-edges of a vertex, counter-clockwise; see [`EditableMesh::outgoing`].
pub(super) struct Outgoing<'a> {
    mesh: &'a EditableMesh,
    start: u32,
    current: Option<u32>,
}

impl Iterator for Outgoing<'_> {
    type Item = u32;

    fn next(&mut self) -> Option<u32> {
        let h = self.current?;
        self.current = self.mesh.twin(prev(h)).filter(|&t| t != self.start);
        Some(h)
    }
}

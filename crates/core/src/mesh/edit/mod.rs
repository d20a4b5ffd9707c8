//! Changing a [`Mesh`]'s topology in place: the edits every technique that remeshes, embeds a
//! curve, cuts or joins builds on.
//!
//! Each edit is O(1) or O(size of what it touches) and leaves [`Mesh::validate`] true:
//! - [`Mesh::split_edge`], [`Mesh::split_face`] and [`Mesh::flip_edge`] only append, so
//!   every vertex and face keeps its id;
//! - [`Mesh::collapse_edge`] and [`Mesh::delete_faces`] leave *tombstones* (a deleted face has
//!   [`INVALID`] corners, a deleted vertex an [`INVALID`] half-edge), so that ids stay stable
//!   during a pass; [`Mesh::compact`] drops them once at the end and says where every vertex
//!   went;
//! - [`Mesh::fill_boundary_loop`] and [`Mesh::add_component`] append faces and vertices.
//!
//! Slots are never reused: a pass that visits the faces it appends would otherwise miss some.
//! Until [`Mesh::compact`], counts (`n_vertices`, `n_faces`) are slot counts and the global
//! queries (`boundary_loops`, `genus`, ...) expect a compact mesh; navigation works on the
//! live part at any time.
//!
//! The one rule the edits share is kept by `Mesh::set_vertex_halfedge`: a boundary vertex's
//! half-edge is its boundary one, so the counter-clockwise walks see the whole fan.

mod collapse;
mod compact;
mod delete;
mod fill;
mod flip;
mod split;

pub use compact::Remap;

use glam::DVec3;

use super::{FaceId, HalfedgeId, INVALID, Mesh, VertexId};

impl Mesh {
    /// Whether face `f` is alive (not deleted by a collapse or [`Mesh::delete_faces`]).
    pub fn is_live_face(&self, f: FaceId) -> bool {
        self.triangles[f.index()][0] != INVALID
    }

    /// Whether vertex `v` is alive (still has a face).
    pub fn is_live_vertex(&self, v: VertexId) -> bool {
        self.vertex_halfedge[v.index()] != INVALID
    }

    /// Whether the mesh holds no tombstones, so every slot is a vertex or face.
    pub fn is_compact(&self) -> bool {
        self.n_dead_vertices == 0 && self.n_dead_faces == 0
    }

    /// Points `v` at its outgoing half-edge `h`, turned clockwise to the boundary half-edge
    /// when `v` lies on the boundary, as the counter-clockwise walks require. O(valence):
    /// for edits that change where the boundary runs.
    fn set_vertex_halfedge(&mut self, v: VertexId, h: HalfedgeId) {
        debug_assert_eq!(self.tail(h), v);
        let mut g = h;
        while let Some(t) = self.twin(g) {
            g = self.next(t);
            if g == h {
                // Around the whole fan: an interior vertex, any half-edge will do.
                break;
            }
        }
        self.vertex_halfedge[v.index()] = g.0;
    }

    /// [`Mesh::set_vertex_halfedge`] for a vertex whose boundary status the caller knows
    /// (splits, flips and collapses keep it): O(1) inside, where remeshing spends its time.
    fn set_vertex_halfedge_on(&mut self, v: VertexId, h: HalfedgeId, is_boundary: bool) {
        if is_boundary {
            self.set_vertex_halfedge(v, h);
        } else {
            self.vertex_halfedge[v.index()] = h.0;
        }
    }

    /// Makes `h` and `t` twins; either may be [`INVALID`] (a boundary edge).
    fn link_twins(&mut self, h: u32, t: u32) {
        if h != INVALID {
            self.twin[h as usize] = t;
        }
        if t != INVALID {
            self.twin[t as usize] = h;
        }
    }

    /// Appends a face with no twins yet; returns its first half-edge.
    fn push_face(&mut self, corners: [VertexId; 3]) -> HalfedgeId {
        let h = HalfedgeId(3 * self.triangles.len() as u32);
        self.triangles.push(corners.map(|v| v.0));
        self.twin.extend([INVALID; 3]);
        h
    }

    /// Appends a vertex with no half-edge yet.
    fn push_vertex(&mut self, p: DVec3) -> VertexId {
        self.positions.push(p);
        self.vertex_halfedge.push(INVALID);
        VertexId(self.positions.len() as u32 - 1)
    }

    /// Sets corner `h`'s vertex (the tail of half-edge `h`).
    fn set_tail(&mut self, h: HalfedgeId, v: VertexId) {
        self.triangles[h.index() / 3][h.index() % 3] = v.0;
    }

    /// Turns face `f` into a tombstone; its vertices' half-edges are the caller's to fix.
    fn kill_face(&mut self, f: FaceId) {
        self.triangles[f.index()] = [INVALID; 3];
        self.twin[3 * f.index()..3 * f.index() + 3].fill(INVALID);
        self.n_dead_faces += 1;
    }

    /// Turns vertex `v` into a tombstone.
    fn kill_vertex(&mut self, v: VertexId) {
        self.vertex_halfedge[v.index()] = INVALID;
        self.n_dead_vertices += 1;
    }
}

#[cfg(test)]
mod tests {
    use crate::mesh::{HalfedgeId, Mesh, primitives};

    /// A deterministic pseudo-random index below `n` (a 64-bit LCG).
    fn pick(state: &mut u64, n: usize) -> usize {
        *state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((*state >> 33) % n as u64) as usize
    }

    fn live_halfedge(mesh: &Mesh, state: &mut u64) -> HalfedgeId {
        loop {
            let h = HalfedgeId(pick(state, mesh.n_halfedges()) as u32);
            if mesh.is_live_face(mesh.face(h)) {
                return h;
            }
        }
    }

    /// Random splits, flips, deletions and fills on a closed and an open mesh: after every
    /// edit the mesh validates, and compacting keeps it valid with the same Euler
    /// characteristic.
    #[test]
    fn random_edit_sequences_keep_the_mesh_valid() {
        for (seed, start) in [
            (1u64, primitives::icosphere(1.0, 1)),
            (7, primitives::grid(4, 3, 1.0)),
        ] {
            let mut state = seed;
            let mut mesh = start;
            for step in 0..300 {
                let h = live_halfedge(&mesh, &mut state);
                let (a, b) = (mesh.tail(h), mesh.head(h));
                match pick(&mut state, 5) {
                    0 => {
                        let p = mesh.position(a).lerp(mesh.position(b), 0.4);
                        mesh.split_edge(h, p);
                    }
                    1 => {
                        let f = mesh.face(h);
                        let [p, q, r] = mesh.face_positions(f);
                        mesh.split_face(f, (p + q + r) / 3.0);
                    }
                    2 => {
                        let c = mesh.opposite_vertex(h);
                        let d = mesh.twin(h).map(|t| mesh.opposite_vertex(t));
                        if d.is_some_and(|d| mesh.find_edge(c, d).is_none()) {
                            mesh.flip_edge(h);
                        }
                    }
                    3 => {
                        // A refused deletion (a bowtie) must leave the mesh as it was.
                        let before = mesh.clone();
                        if mesh.delete_faces(&[mesh.face(h)]).is_err() {
                            assert_eq!(mesh, before);
                        }
                    }
                    _ => {
                        let boundary = (0..mesh.n_halfedges() as u32).map(HalfedgeId).find(|&g| {
                            mesh.is_live_face(mesh.face(g)) && mesh.is_boundary_halfedge(g)
                        });
                        if let Some(g) = boundary {
                            mesh.fill_boundary_loop(g);
                        }
                    }
                }
                mesh.validate()
                    .unwrap_or_else(|e| panic!("seed {seed}, step {step}: {e}"));
                assert!(mesh.positions().iter().all(|p| p.is_finite()));
            }
            let mut compacted = mesh.clone();
            compacted.compact();
            compacted.validate().unwrap();
            assert!(compacted.is_compact());
            assert_eq!(
                compacted.n_faces(),
                mesh.faces().filter(|&f| mesh.is_live_face(f)).count()
            );
        }
    }
}

//! The four passes of one remeshing iteration and the checks that keep each edit safe.
//!
//! Every edit is checked locally before it is made, so a pass never has to undo one: the
//! link condition and valences guard the topology, normals and a triangle quality measure
//! guard the geometry. Scratch buffers live in [`Remesher`] and grow only with the mesh.

use std::collections::BinaryHeap;

use glam::DVec3;

use super::chains::{ChainNetwork, Role};
use crate::mesh::{HalfedgeId, Mesh, VertexId};

/// Least cosine between a changed triangle's normal and its normal before the edit (60°):
/// larger turns fold the surface or change its shape more than remeshing should.
const MIN_NORMAL_COS: f64 = 0.5;

/// Triangles of lower quality ([`quality_sq`], unsquared) count as near-degenerate; an edit
/// may create one only in place of a worse one.
const MIN_QUALITY: f64 = 0.05;

/// Least cosine of the turn at a boundary vertex that may be collapsed away (about 25°):
/// sharper boundary corners are features and stay.
const BOUNDARY_CORNER_COS: f64 = 0.9;

/// Least valence after any edit, so no vertex is left on a spike or a flat fold.
const MIN_VALENCE: u32 = 3;

/// Fraction of the way to the tangential centroid moved per relaxation sweep: all of it, as
/// Gauss–Seidel sweeps of the uniform Laplacian do not overshoot.
const RELAXATION_STEP: f64 = 1.0;

/// Relaxation sweeps per iteration; the next iteration's sweep continues the smoothing.
const RELAXATION_SWEEPS: usize = 1;

/// Twice the area vector of a triangle (its unnormalized normal).
fn area_vector([a, b, c]: [DVec3; 3]) -> DVec3 {
    (b - a).cross(c - a)
}

/// The square of `4√3 · area / (sum of squared edges)`, which is 1 for an equilateral
/// triangle and 0 for a degenerate one. Scale-free, and squared to need no square root:
/// these checks run for every triangle an edit or a relaxation move touches.
fn quality_sq([a, b, c]: [DVec3; 3], area_vector: DVec3) -> f64 {
    let sum_sq = a.distance_squared(b) + b.distance_squared(c) + c.distance_squared(a);
    if sum_sq > 0.0 {
        12.0 * area_vector.length_squared() / (sum_sq * sum_sq)
    } else {
        0.0
    }
}

/// Whether the angle between two (unnormalized) normals is below `acos(MIN_NORMAL_COS)`.
fn turns_little(normal: DVec3, reference: DVec3) -> bool {
    let dot = normal.dot(reference);
    dot > 0.0
        && dot * dot
            >= MIN_NORMAL_COS
                * MIN_NORMAL_COS
                * normal.length_squared()
                * reference.length_squared()
}

/// Running verdict over the triangles an edit changes: no normal turns too far, and each new
/// triangle is decent or better than the one it replaces.
#[derive(Clone, Copy)]
struct EditCheck {
    is_ok: bool,
}

impl EditCheck {
    fn new() -> EditCheck {
        EditCheck { is_ok: true }
    }

    /// Adds one triangle changing from `old` to `new` corners; its new normal is also
    /// compared with `other_normals` (of the other triangles the edit replaces).
    fn add(&mut self, old: [DVec3; 3], new: [DVec3; 3], other_normals: &[DVec3]) {
        if !self.is_ok {
            return;
        }
        let (old_normal, new_normal) = (area_vector(old), area_vector(new));
        let new_quality_sq = quality_sq(new, new_normal);
        // The old quality only matters, and is only computed, for a poor new triangle.
        self.is_ok = turns_little(new_normal, old_normal)
            && other_normals.iter().all(|&n| turns_little(new_normal, n))
            && (new_quality_sq >= MIN_QUALITY * MIN_QUALITY
                || new_quality_sq > quality_sq(old, old_normal));
    }

    fn is_ok(&self) -> bool {
        self.is_ok
    }
}

/// An edge waiting for a split, ordered by length.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
struct LongEdge {
    length_sq_bits: u64,
    a: u32,
    b: u32,
}

/// The mesh, its chains and the edge length bounds of one remesh.
pub(super) struct Remesher {
    pub(super) mesh: Mesh,
    pub(super) chains: ChainNetwork,
    /// Per vertex slot, whether remeshing may change it (its position, its edges); vertices
    /// made by splits are.
    pub(super) is_editable: Vec<bool>,
    /// Per vertex slot, whether it lies on the boundary: no edit here changes that, and the
    /// flip pass asks for every edge's four vertices, so it is kept rather than looked up.
    is_boundary: Vec<bool>,
    /// Squared length above which edges split (`(4/3 L)²`).
    high_sq: f64,
    /// Squared length below which edges collapse (`(4/5 L)²`).
    low_sq: f64,
    /// Per-vertex marks for the link condition, equal to `stamp` when marked.
    marks: Vec<u32>,
    stamp: u32,
    /// Per-vertex valences during the flip pass.
    valences: Vec<u32>,
    /// Edges waiting for a split, longest on top.
    long_edges: BinaryHeap<LongEdge>,
}

impl Remesher {
    /// A remesher changing only the vertices with `is_editable[v]` (one entry per vertex).
    pub(super) fn new(
        mesh: Mesh,
        chains: ChainNetwork,
        target_edge: f64,
        is_editable: Vec<bool>,
    ) -> Remesher {
        let is_boundary = mesh
            .vertices()
            .map(|v| mesh.is_boundary_vertex(v))
            .collect();
        Remesher {
            mesh,
            chains,
            is_boundary,
            is_editable,
            high_sq: (4.0 / 3.0 * target_edge).powi(2),
            low_sq: (4.0 / 5.0 * target_edge).powi(2),
            marks: Vec::new(),
            stamp: 0,
            valences: Vec::new(),
            long_edges: BinaryHeap::new(),
        }
    }

    /// Every half-edge slot, deleted ones included: a pass visits the ones it appends.
    fn halfedges(&self) -> impl Iterator<Item = HalfedgeId> + use<> {
        (0..self.mesh.n_halfedges() as u32).map(HalfedgeId)
    }

    fn is_live(&self, h: HalfedgeId) -> bool {
        self.mesh.is_live_face(self.mesh.face(h))
    }

    /// One Botsch–Kobbelt iteration.
    pub(super) fn iterate(&mut self) {
        self.split_long_edges();
        debug_assert_eq!(self.mesh.validate(), Ok(()), "split broke the mesh");
        self.collapse_short_edges();
        debug_assert_eq!(self.mesh.validate(), Ok(()), "collapse broke the mesh");
        self.equalize_valences();
        debug_assert_eq!(self.mesh.validate(), Ok(()), "flip broke the mesh");
        for _ in 0..RELAXATION_SWEEPS {
            self.relax_tangentially();
        }
    }

    fn are_editable(&self, vertices: &[VertexId]) -> bool {
        vertices.iter().all(|&v| self.is_editable[v.index()])
    }

    fn edge_length_sq(&self, h: HalfedgeId) -> f64 {
        let m = &self.mesh;
        m.position(m.tail(h))
            .distance_squared(m.position(m.head(h)))
    }

    /// Splits every edge longer than `4/3 L`, longest first, at its midpoint or, on a chain,
    /// halfway along the input curve.
    ///
    /// Longest first is Rivara's longest-edge bisection: the new edges of a split are shorter
    /// than the split edge, so the pass ends. In index order, the medians a split creates
    /// may split before the longer sides and cascade into ever more slivers.
    fn split_long_edges(&mut self) {
        let mut queue = std::mem::take(&mut self.long_edges);
        queue.clear();
        for h in self.halfedges() {
            let is_first = self.mesh.twin(h).is_none_or(|t| h < t);
            if self.is_live(h) && is_first {
                self.queue_if_long(&mut queue, self.mesh.tail(h), self.mesh.head(h));
            }
        }
        while let Some(LongEdge { a, b, .. }) = queue.pop() {
            // Other splits may have replaced the edge; its length cannot have changed.
            let (a, b) = (VertexId(a), VertexId(b));
            let Some(h) = self.mesh.find_edge(a, b) else {
                continue;
            };
            let p = self
                .chains
                .split_point(a.0, b.0)
                .unwrap_or_else(|| self.mesh.position(a).midpoint(self.mesh.position(b)));
            let m = self.mesh.split_edge(h, p);
            debug_assert_eq!(m.index(), self.is_editable.len());
            self.is_editable.push(true);
            self.is_boundary.push(self.mesh.is_boundary_vertex(m));
            self.chains.insert_split(a.0, b.0, m.0);
            for w in self.mesh.vertex_neighbors(m) {
                self.queue_if_long(&mut queue, m, w);
            }
        }
        self.long_edges = queue;
    }

    fn queue_if_long(&self, queue: &mut BinaryHeap<LongEdge>, a: VertexId, b: VertexId) {
        if !self.are_editable(&[a, b]) {
            return;
        }
        let length_sq = self
            .mesh
            .position(a)
            .distance_squared(self.mesh.position(b));
        if length_sq > self.high_sq {
            // Non-negative floats order as their bit patterns do.
            queue.push(LongEdge {
                length_sq_bits: length_sq.to_bits(),
                a: a.0,
                b: b.0,
            });
        }
    }

    /// Collapses edges shorter than `4/5 L` where the chains, the boundary, the topology and
    /// the geometry allow it; the removed vertex goes, the kept one stays put.
    fn collapse_short_edges(&mut self) {
        self.marks.resize(self.mesh.n_vertices(), 0);
        for h in self.halfedges() {
            if !self.is_live(h) || self.edge_length_sq(h) >= self.low_sq {
                continue;
            }
            let (u, v) = (self.mesh.tail(h), self.mesh.head(h));
            if !self.are_editable(&[u, v]) {
                continue;
            }
            // Prefer removing a free vertex: it carries no constraint.
            let order = if self.chains.is_on_chain(u.0) && !self.chains.is_on_chain(v.0) {
                [(v, u), (u, v)]
            } else {
                [(u, v), (v, u)]
            };
            if let Some(&(r, _)) = order.iter().find(|&&(r, k)| self.is_collapse_ok(h, r, k)) {
                let role = self.chains.role(r.0);
                self.mesh.collapse_edge(h, r);
                if let Role::Interior(node) = role {
                    self.chains.remove(node);
                }
            }
        }
    }

    /// Whether `r` may disappear into `k` along the edge of `h`.
    fn is_collapse_ok(&mut self, h: HalfedgeId, r: VertexId, k: VertexId) -> bool {
        let is_boundary_edge = self.mesh.twin(h).is_none();
        let may_go = match self.chains.role(r.0) {
            Role::Free => true,
            Role::Interior(node) => self.chains.can_collapse_onto(node, k.0),
            Role::Pinned => false,
        };
        // Boundary vertices slide only along the boundary, and corners stay.
        let keeps_boundary =
            !self.is_boundary[r.index()] || (is_boundary_edge && !self.is_boundary_corner(r));
        // Cheapest and most often failing first: a collapse at the target length usually
        // fails for an edge that would get too long.
        may_go
            && keeps_boundary
            && self.are_new_edges_short(r, k)
            && self.are_valences_ok_after_collapse(h, r, k)
            && self.is_link_condition_ok(r, k, if is_boundary_edge { 1 } else { 2 })
            && self.is_collapse_geometry_ok(r, k)
    }

    fn is_boundary_corner(&self, v: VertexId) -> bool {
        let m = &self.mesh;
        let mut outgoing = m.outgoing_halfedges(v);
        let Some(first) = outgoing.next() else {
            return true;
        };
        let last = outgoing.last().unwrap_or(first);
        let p = m.position(v);
        let after = m.position(m.head(first));
        let before = m.position(m.opposite_vertex(last));
        let turn = (p - before)
            .normalize_or_zero()
            .dot((after - p).normalize_or_zero());
        turn < BOUNDARY_CORNER_COS
    }

    fn are_valences_ok_after_collapse(&self, h: HalfedgeId, r: VertexId, k: VertexId) -> bool {
        let m = &self.mesh;
        let valence = |v: VertexId| m.valence(v) as u32;
        let opposite_ok = |g: HalfedgeId| valence(m.opposite_vertex(g)) > MIN_VALENCE;
        let n_faces_lost = 1 + u32::from(m.twin(h).is_some());
        let merged = valence(r) + valence(k);
        opposite_ok(h)
            && m.twin(h).is_none_or(opposite_ok)
            && merged >= MIN_VALENCE + 2 + n_faces_lost
    }

    /// The link condition: `r` and `k` share exactly the neighbours opposite their edge, so
    /// the collapse pinches nothing and keeps the topology.
    fn is_link_condition_ok(&mut self, r: VertexId, k: VertexId, n_opposite: usize) -> bool {
        self.stamp = self.stamp.wrapping_add(1);
        if self.stamp == 0 {
            self.marks.fill(0);
            self.stamp = 1;
        }
        for w in self.mesh.vertex_neighbors(r) {
            self.marks[w.index()] = self.stamp;
        }
        let n_common = self
            .mesh
            .vertex_neighbors(k)
            .filter(|w| self.marks[w.index()] == self.stamp)
            .count();
        n_common == n_opposite
    }

    /// Whether no edge longer than `4/3 L` appears when `r` joins `k`.
    fn are_new_edges_short(&self, r: VertexId, k: VertexId) -> bool {
        let m = &self.mesh;
        let p_k = m.position(k);
        m.vertex_neighbors(r)
            .all(|w| m.position(w).distance_squared(p_k) <= self.high_sq)
    }

    /// Whether `r`'s remaining triangles, moved onto `k`, neither turn too far nor degenerate.
    fn is_collapse_geometry_ok(&self, r: VertexId, k: VertexId) -> bool {
        let m = &self.mesh;
        let (p_r, p_k) = (m.position(r), m.position(k));
        let mut check = EditCheck::new();
        for g in m.outgoing_halfedges(r) {
            let (x, y) = (m.head(g), m.opposite_vertex(g));
            if x != k && y != k {
                let (p_x, p_y) = (m.position(x), m.position(y));
                check.add([p_r, p_x, p_y], [p_k, p_x, p_y], &[]);
            }
        }
        check.is_ok()
    }

    /// Flips interior edges off the chains where that brings the valences of the four
    /// vertices closer to 6 (4 on the boundary).
    fn equalize_valences(&mut self) {
        let m = &self.mesh;
        self.valences.clear();
        self.valences
            .extend(m.vertices().map(|v| m.valence(v) as u32));
        for h in self.halfedges() {
            if self.is_flip_ok(h) {
                let m = &mut self.mesh;
                let Some(t) = m.twin(h) else { continue };
                let (a, b, c, d) = (
                    m.tail(h),
                    m.head(h),
                    m.opposite_vertex(h),
                    m.opposite_vertex(t),
                );
                m.flip_edge(h);
                for (v, delta) in [(a, -1), (b, -1), (c, 1), (d, 1)] {
                    self.valences[v.index()] =
                        self.valences[v.index()].saturating_add_signed(delta);
                }
            }
        }
    }

    fn target_valence(&self, v: VertexId) -> i64 {
        if self.is_boundary[v.index()] { 4 } else { 6 }
    }

    fn is_flip_ok(&self, h: HalfedgeId) -> bool {
        let m = &self.mesh;
        let Some(t) = m.twin(h) else { return false };
        if h > t || !self.is_live(h) {
            return false;
        }
        let (a, b, c, d) = (
            m.tail(h),
            m.head(h),
            m.opposite_vertex(h),
            m.opposite_vertex(t),
        );
        let valence = |v: VertexId| i64::from(self.valences[v.index()]);
        let deviation =
            |v: VertexId, change: i64| (valence(v) + change - self.target_valence(v)).abs();
        let before: i64 = [a, b, c, d].iter().map(|&v| deviation(v, 0)).sum();
        let after = deviation(a, -1) + deviation(b, -1) + deviation(c, 1) + deviation(d, 1);
        after < before
            && valence(a) > i64::from(MIN_VALENCE)
            && valence(b) > i64::from(MIN_VALENCE)
            && c != d
            && self.are_editable(&[a, b, c, d])
            && !self.chains.is_chain_edge(a.0, b.0)
            && !m.vertex_neighbors(c).any(|w| w == d)
            && self.is_flip_geometry_ok([a, b, c, d].map(|v| m.position(v)))
    }

    /// Faces `(a, b, c)`, `(b, a, d)` become `(a, d, c)`, `(b, c, d)`: each new normal stays
    /// near both old ones (which also rejects a non-convex quad), and no sliver appears.
    fn is_flip_geometry_ok(&self, [a, b, c, d]: [DVec3; 4]) -> bool {
        let (left, right) = ([a, b, c], [b, a, d]);
        let mut check = EditCheck::new();
        check.add(left, [a, d, c], &[area_vector(right)]);
        check.add(right, [b, c, d], &[area_vector(left)]);
        check.is_ok()
    }

    /// Moves every free interior vertex part of the way to the centroid of its one-ring,
    /// within its tangent plane, unless that would fold or degrade one of its triangles.
    fn relax_tangentially(&mut self) {
        for v in self.mesh.vertices() {
            if !self.mesh.is_live_vertex(v)
                || !self.is_editable[v.index()]
                || self.is_boundary[v.index()]
                || self.chains.is_on_chain(v.0)
            {
                continue;
            }
            let Some(q) = self.relaxed_position(v) else {
                continue;
            };
            if self.is_move_ok(v, q) {
                self.mesh.positions_mut()[v.index()] = q;
            }
        }
    }

    fn relaxed_position(&self, v: VertexId) -> Option<DVec3> {
        let m = &self.mesh;
        let p = m.position(v);
        let (mut sum, mut normal, mut n) = (DVec3::ZERO, DVec3::ZERO, 0.0);
        for g in m.outgoing_halfedges(v) {
            let (x, y) = (m.position(m.head(g)), m.position(m.opposite_vertex(g)));
            sum += x;
            normal += (x - p).cross(y - p);
            n += 1.0;
        }
        let normal = normal.try_normalize()?;
        let step = sum / n - p;
        let q = p + RELAXATION_STEP * (step - normal * normal.dot(step));
        q.is_finite().then_some(q)
    }

    fn is_move_ok(&self, v: VertexId, q: DVec3) -> bool {
        let m = &self.mesh;
        let p = m.position(v);
        let mut check = EditCheck::new();
        for g in m.outgoing_halfedges(v) {
            let (x, y) = (m.position(m.head(g)), m.position(m.opposite_vertex(g)));
            check.add([p, x, y], [q, x, y], &[]);
        }
        check.is_ok()
    }
}

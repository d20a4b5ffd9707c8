//! The plane walk of open and closed curves: between two consecutive surface samples the
//! curve is the mesh's cut with the plane through both that contains the view ray, traced
//! triangle by triangle from the vertex the walk stands on.
//!
//! Every edge crossing becomes a vertex (a split, or an existing vertex when the crossing
//! is within [`SNAP_CROSSING`] of it). Samples are not inserted: where a sample falls
//! inside a triangle the walk turns onto the next segment's plane there, so the curve
//! bends inside the triangle and its vertices lie exactly on the swept planes. Only the
//! curve's two ends become vertices of their own.

use glam::DVec3;
use rustc_hash::FxHashSet;

use super::embedding::Embedding;
use super::project::SurfacePoint;
use crate::geometry::barycentric;
use crate::mesh::{FaceId, Mesh, VertexId};

/// Crossings this close to an edge's end (fraction of the edge) snap onto that vertex,
/// which avoids slivers and moves the curve off its plane by at most this fraction.
const SNAP_CROSSING: f64 = 0.02;
/// Barycentric snap of the curve's ends onto a corner or an edge of their triangle.
const SNAP_END: f64 = 0.1;
/// Walk steps per stroke segment before the walk counts as lost.
const MAX_STEPS_PER_SEGMENT: usize = 64;

/// The curve's vertices in stroke order (for a closed curve, not repeating the first), or
/// `None` if the walk lost its way (a stroke over a fold or a silhouette).
pub(super) fn walk(
    embedding: &mut Embedding,
    samples: &[SurfacePoint],
    is_closed: bool,
) -> Option<Vec<VertexId>> {
    let first = samples.first()?;
    let n_segments = if is_closed {
        samples.len()
    } else {
        samples.len() - 1
    };
    let start = embedding.insert_point(first.face, first.barycentric, SNAP_END)?;
    let start_point = embedding.mesh.position(start);
    // Where segment k ends; a closed curve's last segment ends on its first vertex.
    let end_of = |k: usize| samples.get(k + 1).map_or(start_point, |s| s.point);
    let cut_of = |k: usize| Cut::new(samples[k].point, end_of(k), samples[k].ray_dir);
    let mut chain = Chain::new(start);
    let (mut at, mut k) = (start, 0);
    for _ in 0..MAX_STEPS_PER_SEGMENT * n_segments {
        let is_closing = is_closed && k + 1 == n_segments;
        let mesh = &embedding.mesh;
        if is_closing && (at == start || mesh.find_halfedge(at, start).is_some()) {
            return Some(chain.into_closed());
        }
        let mut cut = cut_of(k)?;
        let mut from = mesh.position(at);
        let mut exit = exit_from_vertex(mesh, at, &cut)?;
        // Segments ending before the exit end inside its triangle: turn there.
        while cut.progress(from, end_of(k)) < cut.progress(from, exit.point) {
            let end = end_of(k);
            if k + 1 == n_segments {
                if !is_closed {
                    let bary = barycentric(mesh.face_positions(exit.face), end);
                    chain.push(embedding.insert_point(exit.face, bary, SNAP_END)?);
                    return Some(chain.vertices);
                }
                if mesh.face_vertices(exit.face).contains(&start) {
                    return Some(chain.into_closed());
                }
                break;
            }
            k += 1;
            (cut, from) = (cut_of(k)?, end);
            exit = match exit_from_point(mesh, exit.face, from, &cut) {
                Some(exit) => exit,
                None => {
                    from = mesh.position(at);
                    exit_from_vertex(mesh, at, &cut)?
                }
            };
        }
        at = match exit.crossing {
            Crossing::Vertex(v) => v,
            Crossing::Edge(a, b, t) => {
                let m = embedding.split_edge(a, b, t)?;
                chain.on_split(a, b, m);
                m
            }
        };
        chain.push(at);
    }
    None
}

/// The cut of one stroke segment: the plane through its two surface points that contains
/// the view ray (for a perspective camera, the plane through the eye and both points).
struct Cut {
    origin: DVec3,
    /// Unit normal.
    normal: DVec3,
    /// Unit direction from the segment's start to its end.
    dir: DVec3,
}

impl Cut {
    /// `None` for a segment of zero length or one along the view ray.
    fn new(from: DVec3, to: DVec3, ray_dir: DVec3) -> Option<Self> {
        let along = to - from;
        let normal = along.cross(ray_dir).try_normalize()?;
        Some(Self {
            origin: from,
            normal,
            dir: along.try_normalize()?,
        })
    }

    fn side(&self, p: DVec3) -> f64 {
        self.normal.dot(p - self.origin)
    }

    /// How far `p` lies ahead of `from` along the segment.
    fn progress(&self, from: DVec3, p: DVec3) -> f64 {
        self.dir.dot(p - from)
    }
}

/// Where the walk leaves a triangle: through a vertex or across an edge at `a + t (b − a)`.
#[derive(Clone, Copy, Debug)]
enum Crossing {
    Vertex(VertexId),
    Edge(VertexId, VertexId, f64),
}

#[derive(Clone, Copy, Debug)]
struct Exit {
    face: FaceId,
    crossing: Crossing,
    point: DVec3,
}

/// Where the cut crosses the edge `b`–`c`, snapped onto an end within [`SNAP_CROSSING`].
fn edge_crossing(mesh: &Mesh, face: FaceId, b: VertexId, c: VertexId, cut: &Cut) -> Option<Exit> {
    let (pb, pc) = (mesh.position(b), mesh.position(c));
    let (sb, sc) = (cut.side(pb), cut.side(pc));
    if sb == sc || (sb > 0.0) == (sc > 0.0) && sb != 0.0 && sc != 0.0 {
        return None;
    }
    let t = sb / (sb - sc);
    let (crossing, point) = if t < SNAP_CROSSING {
        (Crossing::Vertex(b), pb)
    } else if t > 1.0 - SNAP_CROSSING {
        (Crossing::Vertex(c), pc)
    } else {
        (Crossing::Edge(b, c, t), pb.lerp(pc, t))
    };
    Some(Exit {
        face,
        crossing,
        point,
    })
}

/// The next crossing from vertex `v`: on the far edges of its fan (treating `v` as on the
/// cut), the one best aligned with the segment's direction.
fn exit_from_vertex(mesh: &Mesh, v: VertexId, cut: &Cut) -> Option<Exit> {
    let from = mesh.position(v);
    let alignment = |exit: &Exit| {
        let offset = exit.point - from;
        cut.dir.dot(offset) / offset.length()
    };
    mesh.outgoing_halfedges(v)
        .filter_map(|h| {
            let (b, c) = (mesh.head(h), mesh.opposite_vertex(h));
            edge_crossing(mesh, mesh.face(h), b, c, cut)
        })
        .map(|exit| (alignment(&exit), exit))
        .filter(|(alignment, _)| *alignment > 0.0)
        .max_by(|x, y| x.0.total_cmp(&y.0))
        .map(|(_, exit)| exit)
}

/// Where the cut leaves triangle `face` ahead of `from`, a point on the cut in (or just
/// before) the triangle.
fn exit_from_point(mesh: &Mesh, face: FaceId, from: DVec3, cut: &Cut) -> Option<Exit> {
    let [a, b, c] = mesh.face_vertices(face);
    [(a, b), (b, c), (c, a)]
        .into_iter()
        .filter_map(|(p, q)| edge_crossing(mesh, face, p, q, cut))
        .map(|exit| (cut.progress(from, exit.point), exit))
        .filter(|(progress, _)| *progress > 0.0)
        .max_by(|x, y| x.0.total_cmp(&y.0))
        .map(|(_, exit)| exit)
}

/// The curve as it grows: its vertices and its edges, so that a later split of one of
/// its own edges (a stroke crossing itself) inserts the new vertex into it.
struct Chain {
    vertices: Vec<VertexId>,
    edges: FxHashSet<(VertexId, VertexId)>,
}

fn edge_key(a: VertexId, b: VertexId) -> (VertexId, VertexId) {
    (a.min(b), a.max(b))
}

impl Chain {
    fn new(start: VertexId) -> Self {
        Self {
            vertices: vec![start],
            edges: FxHashSet::default(),
        }
    }

    /// Appends `v` unless the walk stayed on the last vertex.
    fn push(&mut self, v: VertexId) {
        let Some(&last) = self.vertices.last() else {
            return;
        };
        if last != v {
            self.edges.insert(edge_key(last, v));
            self.vertices.push(v);
        }
    }

    /// Puts `m` between `a` and `b` if they are consecutive on the chain.
    fn on_split(&mut self, a: VertexId, b: VertexId, m: VertexId) {
        if !self.edges.remove(&edge_key(a, b)) {
            return;
        }
        let is_edge = |w: &[VertexId]| edge_key(w[0], w[1]) == edge_key(a, b);
        if let Some(i) = self.vertices.windows(2).position(is_edge) {
            self.vertices.insert(i + 1, m);
            self.edges.extend([edge_key(a, m), edge_key(m, b)]);
        }
    }

    /// The vertices of a closed curve, without repeating the first at the end.
    fn into_closed(mut self) -> Vec<VertexId> {
        if self.vertices.len() > 1 && self.vertices.first() == self.vertices.last() {
            self.vertices.pop();
        }
        self.vertices
    }
}

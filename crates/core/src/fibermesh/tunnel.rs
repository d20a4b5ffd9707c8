//! Tunnels (FiberMesh, Nealen's thesis §3.2.1, Fig. 3.3): a closed loop drawn on a shape and
//! a second one on the far side (after orbiting) drill a hole between them, raising the
//! genus by one.
//!
//! Each loop is embedded as a closed curve (`add_curve`), and the disk it bounds is removed:
//! of the two sides of a loop, the one with less area (on a shape, the loop's inside). The
//! two holes are joined by a tube (`rings.rs`) with rings about an edge length apart, its
//! ends faired into the surface (the squared Laplacians there least). The straight way between
//! the loops' middles must stay inside the shape, and the result must be closed, manifold
//! and free of crossing triangles: anything else is refused.

mod error;

pub use error::TunnelError;

use glam::DVec3;
use rustc_hash::FxHashSet;

use super::opening::{disk, kept_forward, middle};
use super::rings::tube;
use crate::fibermesh::ViewedStroke;
use crate::fibermesh::add_curve::{CurveShape, add_curve};
use crate::geometry::{Bvh, segment_crosses_triangle};
use crate::mesh::{FaceId, Mesh, TriSoup, VertexId};
use crate::solve::{SolveError, Triplets, solve_least_squares};

/// A shape with a tunnel.
#[derive(Clone, Debug)]
pub struct Tunnel {
    /// The shape with the tube in place (straight: the caller settles it).
    pub mesh: Mesh,
    /// The two loops, closed chains of `mesh` vertices at the tube's ends.
    pub loops: [Vec<VertexId>; 2],
    /// Whether each vertex of `mesh` is one of the tube's inner rings.
    pub is_tube: Vec<bool>,
    /// Every edge the loops split, in the numbering of the input mesh with the split
    /// vertices appended.
    pub split_edges: Vec<(VertexId, VertexId, VertexId)>,
    /// Where each vertex of that numbering went in `mesh`, `None` for removed ones.
    pub remap: Vec<Option<VertexId>>,
}

/// Drills a tunnel through the closed `mesh` between the loops `first` and `second`. See the
/// module docs.
///
/// Errors: [`TunnelError`], as sentences for the user.
pub fn tunnel(
    mesh: &Mesh,
    first: ViewedStroke,
    second: ViewedStroke,
) -> Result<Tunnel, TunnelError> {
    if !mesh.is_closed() {
        return Err(TunnelError::NotClosed);
    }
    let embed = |mesh: &Mesh, s: ViewedStroke| {
        add_curve(mesh, s.camera, s.viewport, s.stroke, CurveShape::Closed)
            .map_err(TunnelError::Loop)
    };
    let a = embed(mesh, first)?;
    let b = embed(&a.mesh, second)?;
    let on_a: FxHashSet<VertexId> = a.chain.iter().copied().collect();
    let b_splits_a = b
        .split_edges
        .iter()
        .any(|(p, q, _)| on_a.contains(p) && on_a.contains(q));
    if b_splits_a || b.chain.iter().any(|v| on_a.contains(v)) {
        return Err(TunnelError::LoopsTouch);
    }
    let split = b.mesh;
    let disk_a = disk(&split, &a.chain);
    let disk_b = disk(&split, &b.chain);
    if disk_a.iter().any(|f| disk_b.contains(f)) {
        return Err(TunnelError::LoopsTouch);
    }
    let removed: FxHashSet<FaceId> = disk_a.iter().chain(&disk_b).copied().collect();
    let kept: Vec<[u32; 3]> = split
        .faces()
        .filter(|f| !removed.contains(f))
        .map(|f| split.triangles()[f.index()])
        .collect();
    let rim_a = kept_forward(&split, &removed, &a.chain);
    let rim_b = kept_forward(&split, &removed, &b.chain);
    check_facing(&split, &removed, &rim_a, &rim_b)?;
    // The tube's rings run as the first rim does; the second rim, seen from the tube, runs
    // the other way round.
    let rim_b_along: Vec<VertexId> = rim_b.iter().rev().copied().collect();
    let positions = |rim: &[VertexId]| rim.iter().map(|&v| split.position(v)).collect::<Vec<_>>();
    let (first_ring, second_ring) = (positions(&rim_a), positions(&rim_b_along));
    let length = middle(&first_ring).distance(middle(&second_ring));
    let inner = ((length / split.mean_edge_length()).round() as usize)
        .saturating_sub(1)
        .max(1);
    let (inner_positions, tube_triangles) = tube(&first_ring, &second_ring, inner);
    let n_split = split.n_vertices();
    let n_first = rim_a.len() as u32;
    let n_inner = inner_positions.len() as u32;
    let corner = |i: u32| {
        if i < n_first {
            rim_a[i as usize].0
        } else if i < n_first + n_inner {
            n_split as u32 + i - n_first
        } else {
            rim_b_along[(i - n_first - n_inner) as usize].0
        }
    };
    let mut soup = TriSoup {
        positions: split.positions().to_vec(),
        triangles: kept,
    };
    soup.positions.extend(inner_positions);
    soup.triangles
        .extend(tube_triangles.iter().map(|t| t.map(corner)));
    let kept_vertices = soup.remove_unreferenced_vertices();
    let mut result = Mesh::from_soup(&soup).map_err(|e| TunnelError::Broken(Some(e)))?;
    let remap: Vec<Option<VertexId>> = kept_vertices.iter().map(|k| k.map(VertexId)).collect();
    let mut is_tube = vec![false; result.n_vertices()];
    for v in remap[n_split..].iter().flatten() {
        is_tube[v.index()] = true;
    }
    let loops: [Vec<VertexId>; 2] =
        [&rim_a, &rim_b].map(|rim| rim.iter().filter_map(|v| remap[v.index()]).collect());
    let mut near_ends = vec![false; result.n_vertices()];
    let mut front: Vec<VertexId> = loops.iter().flatten().copied().collect();
    for _ in 0..FAIRED_RINGS {
        let mut next = Vec::new();
        for v in front {
            for w in result.vertex_neighbors(v) {
                if is_tube[w.index()] && !near_ends[w.index()] {
                    near_ends[w.index()] = true;
                    next.push(w);
                }
            }
        }
        front = next;
    }
    fair(&mut result, &near_ends).map_err(|_| TunnelError::Broken(None))?;
    let in_tube = |f: FaceId| {
        result
            .face_vertices(f)
            .iter()
            .any(|v: &VertexId| is_tube[v.index()])
    };
    let genus_up = result
        .genus()
        .zip(mesh.genus())
        .is_some_and(|(g, h)| g == h + 1);
    let crossing = !Bvh::new(&result)
        .crossing_faces(&result, in_tube)
        .is_empty();
    if !result.is_closed() || !genus_up || crossing {
        return Err(TunnelError::Broken(None));
    }
    let mut split_edges = a.split_edges;
    split_edges.extend(b.split_edges);
    Ok(Tunnel {
        loops,
        mesh: result,
        is_tube,
        split_edges,
        remap: remap[..n_split].to_vec(),
    })
}

/// The tube's rings this close to either loop are faired; the middle stays a straight
/// tube. Fairing all of it made a minimal-surface-like neck, which on a long tube pinches
/// shut (a catenoid does not span two rings farther apart than about 1.3 radii).
const FAIRED_RINGS: usize = 2;

/// Moves the `free` vertices to where the squared uniform Laplacians of them and of their
/// neighbours are least (a discrete biharmonic fill): the tube's ends round off into the
/// surface around the loops without a crease.
fn fair(mesh: &mut Mesh, free: &[bool]) -> Result<(), SolveError> {
    let mut rows: Vec<VertexId> = mesh.vertices().filter(|v| free[v.index()]).collect();
    let mut in_rows: FxHashSet<VertexId> = rows.iter().copied().collect();
    for v in rows.clone() {
        for w in mesh.vertex_neighbors(v) {
            if in_rows.insert(w) {
                rows.push(w);
            }
        }
    }
    let mut triplets = Triplets::with_capacity(rows.len(), mesh.n_vertices(), 8 * rows.len());
    for (i, &v) in rows.iter().enumerate() {
        let valence = mesh.valence(v) as f64;
        triplets.push(i, v.index(), 1.0);
        for w in mesh.vertex_neighbors(v) {
            triplets.push(i, w.index(), -1.0 / valence);
        }
    }
    let fixed: Vec<bool> = free.iter().map(|&f| !f).collect();
    let zeros = vec![DVec3::ZERO; rows.len()];
    let positions = solve_least_squares(&triplets.build(), &zeros, &fixed, mesh.positions())?;
    mesh.positions_mut().copy_from_slice(&positions);
    Ok(())
}

/// Refuses loops whose straight way from one middle to the other leaves the shape: the
/// segment between them must pass through no kept face, and its points at a quarter, half
/// and three quarters of the way must lie inside the shape.
fn check_facing(
    mesh: &Mesh,
    removed: &FxHashSet<FaceId>,
    rim_a: &[VertexId],
    rim_b: &[VertexId],
) -> Result<(), TunnelError> {
    let ring = |rim: &[VertexId]| rim.iter().map(|&v| mesh.position(v)).collect::<Vec<_>>();
    let (from, to) = (middle(&ring(rim_a)), middle(&ring(rim_b)));
    if from.distance(to) <= 0.0 {
        return Err(TunnelError::LoopsTouch);
    }
    let blocked = mesh.faces().filter(|f| !removed.contains(f)).any(|f| {
        let [p, q, r] = mesh.face_positions(f);
        segment_crosses_triangle(from, to, p, q, r)
    });
    let bvh = Bvh::new(mesh);
    let outside = [0.25, 0.5, 0.75]
        .iter()
        .any(|&t| !bvh.contains(mesh, from.lerp(to, t)));
    if blocked || outside {
        return Err(TunnelError::NotFacing);
    }
    Ok(())
}

#[cfg(test)]
mod tests;

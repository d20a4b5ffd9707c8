//! Control curves from a Sketchmesh node's extras, made chains of the imported mesh's
//! vertices.
//!
//! The extras keep a curve as world-space points (`docs/gltf-extras.md`), so that other
//! readers need no vertex numbering; a model's curve is a chain of its mesh's vertices. A
//! file Sketchmesh wrote has a vertex under every curve point: the points are the curve
//! vertices' `f64` positions and the mesh stores them rounded to `f32`. Those curves are
//! found again by comparing positions at `f32` precision, and their vertices get back the
//! exact `f64` positions the extras keep, so exporting the import again gives the same file.
//!
//! A point that is not a vertex (extras written by hand or by another tool, or a mesh
//! changed in one) goes to the nearest vertex, and vertices that end up apart are joined by
//! the shortest edge path between them: every curve becomes an edge chain, as the
//! FiberMesh solver and the curve tools need. A point farther from every vertex than the
//! mesh's longest edge is not on the surface; its curve is left out.

use std::collections::HashMap;

use glam::DVec3;
use rustc_hash::FxHashMap;

use super::extras::CurveExtras;
use crate::mesh::{Mesh, VertexId};
use crate::model::{ControlCurve, CurveKind};

/// The curves found on a model, and how many needed help.
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct AttachedCurves {
    /// The curves, in file order, without the ones left out.
    pub(super) curves: Vec<ControlCurve>,
    /// Curves whose points were not all vertices joined by edges: moved onto the mesh.
    pub(super) snapped: usize,
    /// Curves left out: off the surface, or too short once on it.
    pub(super) dropped: usize,
}

/// Makes the extras' `curves` chains of `mesh`'s vertices (see the module docs); vertices
/// found at a curve point's `f32` position are moved to its exact position.
pub(super) fn attach_curves(mesh: &mut Mesh, curves: &[CurveExtras]) -> AttachedCurves {
    let mut attached = AttachedCurves::default();
    if curves.is_empty() || mesh.n_vertices() == 0 {
        attached.dropped = curves.len();
        return attached;
    }
    let mut snap = Snap::new(mesh);
    for curve in curves {
        let points: Vec<DVec3> = curve.points.iter().map(|&p| DVec3::from(p)).collect();
        let Some(found) = points
            .iter()
            .map(|&p| snap.vertex_at(mesh, p))
            .collect::<Option<Vec<(VertexId, bool)>>>()
        else {
            attached.dropped += 1;
            continue;
        };
        for (&(v, exact), &p) in found.iter().zip(&points) {
            if exact {
                mesh.positions_mut()[v.index()] = p;
            }
        }
        let vertices: Vec<VertexId> = found.iter().map(|&(v, _)| v).collect();
        let Some(chain) = edge_chain(mesh, &vertices, curve.closed) else {
            attached.dropped += 1;
            continue;
        };
        let is_exact = found.iter().all(|&(_, exact)| exact) && chain == vertices;
        if !is_exact {
            attached.snapped += 1;
        }
        attached.curves.push(ControlCurve {
            vertices: chain,
            is_closed: curve.closed,
            kind: if curve.sharp {
                CurveKind::Sharp
            } else {
                CurveKind::Smooth
            },
        });
    }
    attached
}

/// Finds the vertex under a point: by exact `f32` position, else the nearest one.
struct Snap {
    /// The vertex at each `f32` position (the first, where several share one).
    at_f32: HashMap<[u32; 3], VertexId>,
    /// The vertices by grid cell, built when a point is not at a vertex.
    grid: Option<Grid>,
}

impl Snap {
    fn new(mesh: &Mesh) -> Self {
        let mut at_f32 = HashMap::with_capacity(mesh.n_vertices());
        for v in mesh.vertices() {
            at_f32.entry(f32_key(mesh.position(v))).or_insert(v);
        }
        Snap { at_f32, grid: None }
    }

    /// The vertex at `p`'s `f32` position (with `true`), else the nearest vertex within
    /// the longest edge (with `false`); `None` when `p` is farther from every vertex.
    fn vertex_at(&mut self, mesh: &Mesh, p: DVec3) -> Option<(VertexId, bool)> {
        if let Some(&v) = self.at_f32.get(&f32_key(p)) {
            return Some((v, true));
        }
        let grid = self.grid.get_or_insert_with(|| Grid::new(mesh));
        grid.nearest(mesh, p).map(|v| (v, false))
    }
}

fn f32_key(p: DVec3) -> [u32; 3] {
    p.as_vec3().to_array().map(f32::to_bits)
}

/// The mesh vertices in cubic cells as wide as the longest edge: a point on the surface is
/// within that distance of a vertex (of the triangle it lies in), so the nearest vertex of
/// such a point is in its own cell or a neighbouring one.
struct Grid {
    cell: f64,
    vertices: FxHashMap<[i64; 3], Vec<VertexId>>,
}

impl Grid {
    fn new(mesh: &Mesh) -> Self {
        let cell = mesh
            .faces()
            .flat_map(|f| {
                let [a, b, c] = mesh.face_positions(f);
                [a.distance(b), b.distance(c), c.distance(a)]
            })
            .fold(0.0, f64::max);
        let mut vertices: FxHashMap<[i64; 3], Vec<VertexId>> = FxHashMap::default();
        if cell > 0.0 && cell.is_finite() {
            for v in mesh.vertices() {
                vertices
                    .entry(cell_of(mesh.position(v), cell))
                    .or_default()
                    .push(v);
            }
        }
        Grid { cell, vertices }
    }

    /// The vertex nearest to `p` within one cell width, if any.
    fn nearest(&self, mesh: &Mesh, p: DVec3) -> Option<VertexId> {
        if !p.is_finite() || self.vertices.is_empty() {
            return None;
        }
        let [x, y, z] = cell_of(p, self.cell);
        let mut best: Option<(f64, VertexId)> = None;
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    let key = [
                        x.saturating_add(dx),
                        y.saturating_add(dy),
                        z.saturating_add(dz),
                    ];
                    for &v in self.vertices.get(&key).into_iter().flatten() {
                        let d = mesh.position(v).distance(p);
                        if d <= self.cell && best.is_none_or(|(b, _)| d < b) {
                            best = Some((d, v));
                        }
                    }
                }
            }
        }
        best.map(|(_, v)| v)
    }
}

fn cell_of(p: DVec3, cell: f64) -> [i64; 3] {
    // `as` saturates: points beyond the i64 range share the outermost cells.
    (p / cell).floor().to_array().map(|c| c as i64)
}

/// `vertices` as an edge chain: repeats dropped, and vertices that are not neighbours
/// joined by the shortest edge path between them (the closing pair too, if `closed`).
/// `None` when two of them are not connected, or when fewer vertices remain than the curve
/// needs (two, three if closed).
fn edge_chain(mesh: &Mesh, vertices: &[VertexId], closed: bool) -> Option<Vec<VertexId>> {
    let mut chain: Vec<VertexId> = Vec::with_capacity(vertices.len());
    for &v in vertices {
        join(mesh, &mut chain, v)?;
    }
    if closed {
        while chain.len() > 1 && chain.last() == chain.first() {
            chain.pop();
        }
        if let (Some(&first), Some(&last)) = (chain.first(), chain.last())
            && chain.len() > 1
            && !is_edge(mesh, last, first)
        {
            join(mesh, &mut chain, first)?;
            chain.pop();
        }
    }
    let needed = if closed { 3 } else { 2 };
    (chain.len() >= needed).then_some(chain)
}

/// Appends `v` to `chain`, through the shortest edge path from the chain's last vertex.
fn join(mesh: &Mesh, chain: &mut Vec<VertexId>, v: VertexId) -> Option<()> {
    match chain.last() {
        None => chain.push(v),
        Some(&last) if last == v => {}
        Some(&last) if is_edge(mesh, last, v) => chain.push(v),
        Some(&last) => {
            let length = |a: VertexId, b: VertexId| mesh.position(a).distance(mesh.position(b));
            let path = mesh.shortest_path(last, v, |_| true, length)?;
            chain.extend(path.into_iter().skip(1));
        }
    }
    Some(())
}

fn is_edge(mesh: &Mesh, a: VertexId, b: VertexId) -> bool {
    mesh.vertex_neighbors(a).any(|w| w == b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;

    fn extras(mesh: &Mesh, vertices: &[u32], closed: bool) -> CurveExtras {
        CurveExtras {
            closed,
            sharp: false,
            points: vertices
                .iter()
                .map(|&v| mesh.position(VertexId(v)).to_array())
                .collect(),
        }
    }

    /// A closed edge loop of the grid's vertices around its centre.
    fn ring(nx: u32) -> Vec<u32> {
        let at = |i: u32, j: u32| j * (nx + 1) + i;
        vec![
            at(3, 3),
            at(4, 3),
            at(5, 3),
            at(5, 4),
            at(5, 5),
            at(4, 5),
            at(3, 5),
            at(3, 4),
        ]
    }

    #[test]
    fn points_at_vertices_are_found_exactly_and_get_their_f64_positions() {
        let mut mesh = primitives::grid(8, 8, 1.0);
        let ring = ring(8);
        let mut curve = extras(&mesh, &ring, true);
        // The file's mesh positions are f32; the extras keep the f64 values.
        let exact = curve.points[2];
        for p in mesh.positions_mut() {
            *p = p.as_vec3().as_dvec3();
        }
        curve.points[2] = [exact[0] + 1e-9, exact[1], exact[2]];
        let attached = attach_curves(&mut mesh, &[curve.clone()]);
        assert_eq!((attached.snapped, attached.dropped), (0, 0));
        let found = &attached.curves[0];
        assert_eq!(
            found.vertices,
            ring.iter().map(|&v| VertexId(v)).collect::<Vec<_>>()
        );
        assert!(found.is_closed && !found.is_sharp());
        let points: Vec<[f64; 3]> = found.points(&mesh).iter().map(|p| p.to_array()).collect();
        assert_eq!(points, curve.points);
    }

    #[test]
    fn points_between_vertices_snap_and_gaps_become_edge_paths() {
        let mut mesh = primitives::grid(8, 8, 1.0);
        let ring = ring(8);
        // Every other ring vertex, nudged off it: the chain must come back whole.
        let mut curve = extras(
            &mesh,
            &ring[..].iter().step_by(2).copied().collect::<Vec<_>>(),
            true,
        );
        for p in &mut curve.points {
            p[0] += 0.01;
            p[2] += 0.01;
        }
        let attached = attach_curves(&mut mesh, &[curve]);
        assert_eq!((attached.snapped, attached.dropped), (1, 0));
        let chain = &attached.curves[0].vertices;
        assert_eq!(chain.len(), ring.len());
        let n = chain.len();
        for k in 0..n {
            assert!(is_edge(&mesh, chain[k], chain[(k + 1) % n]));
        }
    }

    #[test]
    fn curves_off_the_surface_or_too_short_are_left_out() {
        let mut mesh = primitives::grid(8, 8, 1.0);
        let mut far = extras(&mesh, &[0, 1, 2], false);
        far.points[1][1] += 10.0;
        let single = extras(&mesh, &[5, 5], false);
        let kept = extras(&mesh, &[0, 1, 2], false);
        let attached = attach_curves(&mut mesh, &[far, single, kept]);
        assert_eq!((attached.snapped, attached.dropped), (0, 2));
        assert_eq!(attached.curves.len(), 1);
        assert_eq!(attached.curves[0].vertices.len(), 3);
    }
}

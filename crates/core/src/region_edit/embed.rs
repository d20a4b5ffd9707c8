//! The region's two curves embedded in the mesh as vertices of their own (Bujans §4.1,
//! step 3): the reference curve becomes an edge chain lying exactly under the sketch, so it
//! moves exactly as drawn; the boundary becomes a closed edge chain that stays, so the edit
//! ends on the loop the user drew, not on the ragged edge of the triangles inside it.
//!
//! Both are FiberMesh's curve embedding ([`crate::fibermesh::add_curve`]): the plane walk
//! between samples cast onto the surface, every edge crossing a new vertex on that edge.
//! Splits only append, so every vertex of the input keeps its id and its position. A boundary
//! that leaves the visible surface (drawn around an ear, past the model's outline) cannot be
//! walked as a loop: its runs over the surface are embedded one by one as open curves, each
//! reaching out to the outline where it runs off, and where the loop is off the model the
//! outline bounds the region anyway. A curve that cannot be walked at all (the reference
//! curve over a fold) is traced over the edges as before: the edit still works, with that
//! curve on the mesh's edges.

use glam::DVec2;

use super::RegionSketch;
use crate::fibermesh::add_curve::{CurveShape, add_curve};
use crate::geometry::Bvh;
use crate::mesh::{Mesh, VertexId};

/// The mesh with the curves that could be embedded, and the edges split on the way.
#[derive(Clone, Debug)]
pub(super) struct Embedded {
    pub mesh: Mesh,
    /// The reference curve's vertices, first to last, when it was embedded.
    pub reference: Option<Vec<VertexId>>,
    /// The boundary's embedded pieces: the whole loop, or its runs over the surface (none
    /// when no part of it could be embedded).
    pub boundary: Vec<Vec<VertexId>>,
    /// Every edge split, in order, as `(a, b, new)`: `new` lies between `a` and `b`.
    pub splits: Vec<(VertexId, VertexId, VertexId)>,
}

/// `mesh` with `sketch`'s reference curve and then its boundary (`boundary`, the loop
/// without a repeated last point) embedded where each can be.
pub(super) fn embed(mesh: &Mesh, sketch: &RegionSketch, boundary: &[DVec2]) -> Embedded {
    let mut embedded = Embedded::unchanged(mesh);
    embedded.reference = embedded.walk(sketch, &sketch.reference, CurveShape::Open);
    embedded.boundary = match embedded.walk(sketch, boundary, CurveShape::Closed) {
        Some(chain) => vec![chain],
        None => runs_on_surface(&embedded.mesh, sketch, boundary)
            .iter()
            .filter_map(|run| embedded.walk(sketch, run, CurveShape::Open))
            .collect(),
    };
    // The boundary encloses the reference curve, so it cannot have split one of its edges;
    // should it have (a loop drawn through the curve's end), the curve is traced instead.
    let still_a_chain = |chain: &Vec<VertexId>| {
        (chain.windows(2)).all(|w| embedded.mesh.find_edge(w[0], w[1]).is_some())
    };
    if !embedded.reference.as_ref().is_none_or(still_a_chain) {
        embedded.reference = None;
    }
    embedded
}

impl Embedded {
    /// `mesh` with no curve embedded.
    pub fn unchanged(mesh: &Mesh) -> Self {
        Embedded {
            mesh: mesh.clone(),
            reference: None,
            boundary: Vec::new(),
            splits: Vec::new(),
        }
    }

    /// Embeds one curve into the mesh; its chain, or `None` (nothing changed) where the
    /// walk cannot place it.
    fn walk(
        &mut self,
        sketch: &RegionSketch,
        stroke: &[DVec2],
        shape: CurveShape,
    ) -> Option<Vec<VertexId>> {
        let placed = add_curve(&self.mesh, &sketch.camera, sketch.viewport, stroke, shape).ok()?;
        self.mesh = placed.mesh;
        self.splits.extend(placed.split_edges);
        Some(placed.chain)
    }
}

/// The runs of the closed `boundary` whose points lie over `mesh` as seen, each with the
/// point before and after it off the mesh (so that its walk reaches out to the outline), in
/// loop order. A loop wholly over the mesh (on several sheets: it crosses an outline inside
/// the model) is one run, opened at its first point.
fn runs_on_surface(mesh: &Mesh, sketch: &RegionSketch, boundary: &[DVec2]) -> Vec<Vec<DVec2>> {
    let bvh = Bvh::new(mesh);
    let hits: Vec<bool> = (boundary.iter())
        .map(|&p| {
            let (origin, dir) = sketch.camera.ray_in_world(p, sketch.viewport);
            bvh.raycast(mesh, origin, dir).is_some()
        })
        .collect();
    let Some(start) = hits.iter().position(|&hit| !hit) else {
        let mut looped = boundary.to_vec();
        looped.extend(boundary.first());
        return vec![looped];
    };
    // From a point off the mesh around the loop and back to it.
    let n = boundary.len();
    let around: Vec<usize> = (0..=n).map(|k| (start + k) % n).collect();
    let mut runs = Vec::new();
    let mut run: Vec<DVec2> = Vec::new();
    for pair in around.windows(2) {
        let (before, at) = (pair[0], pair[1]);
        match (hits[before], hits[at]) {
            (false, true) => run = vec![boundary[before], boundary[at]],
            (true, true) => run.push(boundary[at]),
            (true, false) => {
                run.push(boundary[at]);
                runs.push(std::mem::take(&mut run));
            }
            (false, false) => {}
        }
    }
    runs
}

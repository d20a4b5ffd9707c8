//! The region's two curves embedded in the mesh as vertices of their own (Bujans §4.1,
//! step 3): the reference curve becomes an edge chain lying exactly under the sketch, so it
//! moves exactly as drawn; the boundary becomes a closed edge chain that stays, so the edit
//! ends on the loop the user drew, not on the ragged edge of the triangles inside it.
//!
//! Both are FiberMesh's curve embedding ([`crate::fibermesh::add_curve`]): the plane walk
//! between samples cast onto the surface, every edge crossing a new vertex on that edge.
//! Splits only append, so every vertex of the input keeps its id and its position. A curve
//! that cannot be walked (the boundary runs off the model, the reference curve crosses a
//! fold) is left out and traced over the edges as before: the edit still works, with that
//! curve on the mesh's edges.

use glam::DVec2;

use super::RegionSketch;
use crate::fibermesh::add_curve::{CurveShape, add_curve};
use crate::mesh::{Mesh, VertexId};

/// The mesh with the curves that could be embedded, and the edges split on the way.
#[derive(Clone, Debug)]
pub(super) struct Embedded {
    pub mesh: Mesh,
    /// The reference curve's vertices, first to last, when it was embedded.
    pub reference: Option<Vec<VertexId>>,
    /// The boundary's vertices around the loop, when it was embedded.
    pub boundary: Option<Vec<VertexId>>,
    /// Every edge split, in order, as `(a, b, new)`: `new` lies between `a` and `b`.
    pub splits: Vec<(VertexId, VertexId, VertexId)>,
}

/// `mesh` with `sketch`'s reference curve and then its boundary (`boundary`, the loop
/// without a repeated last point) embedded where each can be.
pub(super) fn embed(mesh: &Mesh, sketch: &RegionSketch, boundary: &[DVec2]) -> Embedded {
    let mut embedded = Embedded::unchanged(mesh);
    embedded.reference = embedded.walk(sketch, &sketch.reference, CurveShape::Open);
    embedded.boundary = embedded.walk(sketch, boundary, CurveShape::Closed);
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
            boundary: None,
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

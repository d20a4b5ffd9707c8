//! Whether a model would print: closed and manifold, free of self-intersections, walls thick
//! enough, and how big, reported in plain words before an STL export (issue 51). Problems
//! are reported with where they are, so the app can show them, and never fixed.
//!
//! - **Closed:** no boundary loops ([`Mesh::boundary_loops`]); each loop is a hole a slicer
//!   has to guess across.
//! - **Manifold:** a [`Mesh`] is an edge- and vertex-manifold by construction (its half-edge
//!   invariants, [`Mesh::validate`]), so a model made here always is. An imported file that
//!   was not (edges with three triangles, triangles turned against their neighbours) was
//!   repaired into its mesh on import ([`crate::mesh::make_manifold`]), splitting it where it
//!   was not manifold; the file's own triangles stay beside it ([`Model::as_imported`]). The
//!   check counts the file's bad edges and then looks at the repaired mesh, which is what the
//!   STL export writes: the splits show up as holes.
//! - **Self-intersections:** crossing triangle pairs ([`crossings`]), grouped into places.
//! - **Thinnest wall:** the shape diameter function ([`thickness`]).
//! - **Size:** the bounding box.
//!
//! Lengths are in metres, as the document's; [`PrintCheck::sentences`] says them in a unit.
//!
//! A current limitation: separate models that overlap are not checked against each other
//! (slicers merge overlapping shells), nor are walls between two models measured.

mod crossings;
mod sentences;
mod thickness;

use glam::DVec3;
use rustc_hash::FxHashMap;

use crate::geometry::Bvh;
use crate::mesh::{TriSoup, VertexId};
use crate::model::{Document, Model};

pub use crossings::{Crossings, crossings};
pub use thickness::{MAX_SAMPLES, Thickness, thickness};

/// The minimum wall a print check uses unless the user sets another: 1 mm, in metres.
pub const DEFAULT_MIN_WALL: f64 = 0.001;

/// What the check found on one model.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ModelCheck {
    /// The model's index in its document (0 for [`PrintCheck::of_model`]).
    pub index: usize,
    /// The mesh's boundary loops, as vertex cycles: its holes.
    pub holes: Vec<Vec<VertexId>>,
    /// Whether the mesh was repaired from an imported file that was not manifold.
    pub is_repaired: bool,
    /// Edges of that file with more than two triangles or whose two triangles disagree on
    /// their winding; 0 when the mesh was not repaired.
    pub file_non_manifold_edges: usize,
    /// Where the surface crosses itself.
    pub crossings: Crossings,
    /// Its wall thickness.
    pub thickness: Thickness,
    /// Its bounding box, `None` without vertices.
    pub bounds: Option<(DVec3, DVec3)>,
    /// Its number of triangles.
    pub n_triangles: usize,
}

impl ModelCheck {
    /// Checks `model` against a minimum wall of `min_wall` metres.
    pub fn new(index: usize, model: &Model, min_wall: f64) -> Self {
        let mesh = &model.mesh;
        let bvh = Bvh::new(mesh);
        let soup = model.as_imported().map(|imported| &imported.soup);
        Self {
            index,
            holes: mesh.boundary_loops(),
            is_repaired: soup.is_some(),
            file_non_manifold_edges: soup.map_or(0, non_manifold_edges),
            crossings: crossings(mesh, &bvh),
            thickness: thickness(mesh, &bvh, min_wall),
            bounds: mesh.bounding_box(),
            n_triangles: mesh.n_faces(),
        }
    }
}

/// The print check of one model or a document's models.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PrintCheck {
    /// One check per model that has triangles.
    pub models: Vec<ModelCheck>,
    /// The minimum wall checked against, in metres.
    pub min_wall: f64,
}

impl PrintCheck {
    /// Checks one model against a minimum wall of `min_wall` metres
    /// ([`DEFAULT_MIN_WALL`] unless the user sets another).
    pub fn of_model(model: &Model, min_wall: f64) -> Self {
        Self {
            models: vec![ModelCheck::new(0, model, min_wall)],
            min_wall,
        }
    }

    /// Checks every model of `doc` that has triangles, each on its own.
    pub fn of_document(doc: &Document, min_wall: f64) -> Self {
        let models = doc
            .models
            .iter()
            .enumerate()
            .filter(|(_, model)| model.mesh.n_faces() > 0)
            .map(|(index, model)| ModelCheck::new(index, model, min_wall))
            .collect();
        Self { models, min_wall }
    }

    /// Whether there is something to print and nothing against it: every model closed, none
    /// crossing itself, and every thinnest wall at least the minimum.
    pub fn is_printable(&self) -> bool {
        !self.models.is_empty()
            && self.n_holes() == 0
            && self.n_crossing_places() == 0
            && self.thinnest().is_some_and(|t| t >= self.min_wall)
    }

    /// Holes over all models.
    pub fn n_holes(&self) -> usize {
        self.models.iter().map(|m| m.holes.len()).sum()
    }

    /// Places where a surface crosses itself, over all models.
    pub fn n_crossing_places(&self) -> usize {
        self.models.iter().map(|m| m.crossings.n_places).sum()
    }

    /// The thinnest wall of any model (robust, see [`Thickness::thinnest`]), in metres.
    pub fn thinnest(&self) -> Option<f64> {
        self.models
            .iter()
            .filter_map(|m| m.thickness.thinnest)
            .min_by(f64::total_cmp)
    }

    /// The bounding box of all models, in metres.
    pub fn bounds(&self) -> Option<(DVec3, DVec3)> {
        self.models
            .iter()
            .filter_map(|m| m.bounds)
            .reduce(|(lo, hi), (a, b)| (lo.min(a), hi.max(b)))
    }
}

/// Edges of `soup` with more than two triangles, or with two that run along it the same
/// way (their windings disagree).
fn non_manifold_edges(soup: &TriSoup) -> usize {
    // Per undirected edge: how many triangles run along it low to high, and high to low.
    let mut edges: FxHashMap<(u32, u32), (u32, u32)> = FxHashMap::default();
    for t in &soup.triangles {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            let entry = edges.entry((a.min(b), a.max(b))).or_default();
            if a < b {
                entry.0 += 1;
            } else {
                entry.1 += 1;
            }
        }
    }
    edges
        .values()
        .filter(|&&(up, down)| up + down > 2 || up > 1 || down > 1)
        .count()
}

#[cfg(test)]
mod tests;

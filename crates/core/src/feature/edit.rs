//! A feature sketch, embedded and factored once, shaped for any amount by weighing a few
//! fixed solutions (see `targets.rs`): a drag frame costs a pass over the region.

use glam::DVec3;

use super::placement::{Placed, place};
use super::targets::{Rows, bases, coefficients};
use super::{FeatureError, FeatureKind, Sketch, embedding};
use crate::deform::{DeformError, EditParams, HandleFit, LaplacianEdit, Rotations};
use crate::geometry::{Bvh, vertex_normals};
use crate::mesh::{Mesh, VertexId};

/// Halvings of the amount's distance from neutral that bound an amount folding triangles:
/// the amount used is within 1/1024 of the largest safe one.
const BOUND_STEPS: u32 = 10;

/// A face whose normal turns further than this from its embedded one counts as folding
/// (cosine of 80°): a steeper wall is a fold on screen, and the ridge or ravine it belongs
/// to is taller than five times its foot is wide.
const FOLD_COS: f64 = 0.174;

/// Places `sketch` on `mesh` and embeds it: where it lies and every vertex's position with
/// the path on the sketch.
///
/// Errors: the sketch's refusals (see [`FeatureError`]), or a relaxation that cannot be
/// solved.
fn embed(mesh: &Mesh, sketch: &Sketch) -> Result<(Placed, Vec<DVec3>), FeatureError> {
    let normals = vertex_normals(mesh);
    let placed = place(mesh, &Bvh::new(mesh), &normals, sketch)?;
    let targets = embedding::on_sketch(mesh, &normals, sketch, &placed.points, &placed.path);
    let embedded = embedding::relax(mesh, &placed.region, &placed.path, &targets)
        .map_err(DeformError::from)?;
    Ok((placed, embedded))
}

/// A sketch on the surface made part of the mesh (§4.4.1): the edge path under it, and every
/// vertex's position with the path moved onto the sketch and its surroundings relaxed. What
/// a feature starts from, and the manual over-sketch's curve on the surface.
#[derive(Clone, Debug, PartialEq)]
pub struct Embedded {
    /// The edge path, from the sketch's first point to its last.
    pub path: Vec<VertexId>,
    /// Every vertex of the mesh.
    pub positions: Vec<DVec3>,
}

/// Embeds `sketch` in `mesh`; see [`Embedded`].
///
/// Errors: the sketch's refusals (see [`FeatureError`]), or a relaxation that cannot be
/// solved.
pub fn embed_sketch(mesh: &Mesh, sketch: &Sketch) -> Result<Embedded, FeatureError> {
    let (placed, positions) = embed(mesh, sketch)?;
    Ok(Embedded {
        path: placed.path,
        positions,
    })
}

/// The edge path under `sketch` on `mesh`, from its first point to its last (the path a
/// feature is embedded along, §4.4.1 step 2), without moving anything.
///
/// Errors: the sketch's refusals (see [`FeatureError`]).
pub fn pick_path(mesh: &Mesh, sketch: &Sketch) -> Result<Vec<VertexId>, FeatureError> {
    let normals = vertex_normals(mesh);
    Ok(place(mesh, &Bvh::new(mesh), &normals, sketch)?.path)
}

/// A feature sketch on one mesh, ready to shape: see the [module docs](super).
#[derive(Clone, Debug)]
pub struct FeatureEdit {
    kind: FeatureKind,
    /// Every vertex with the sketch embedded: the shape at the neutral amount.
    embedded: Vec<DVec3>,
    path: Vec<VertexId>,
    /// The vertices that may move.
    roi: Vec<VertexId>,
    /// For each vector of the kind's Laplacian change, how the region moves (one entry per
    /// ROI vertex).
    solutions: Vec<Vec<DVec3>>,
    /// The corners of the faces touching the region, with their embedded normals (not
    /// normalised).
    faces: Vec<([u32; 3], DVec3)>,
}

/// A shape for one amount.
#[derive(Clone, Debug, PartialEq)]
pub struct Shaped {
    /// Every vertex of the mesh.
    pub positions: Vec<DVec3>,
    /// The amount used, when the one asked for would have folded triangles over.
    pub limited_to: Option<f64>,
}

impl FeatureEdit {
    /// Places `sketch` on `mesh`, embeds it and factors the region for `kind`.
    ///
    /// Errors: the sketch's refusals (see [`FeatureError`]), or a region that cannot be
    /// solved.
    pub fn new(mesh: &Mesh, sketch: &Sketch, kind: FeatureKind) -> Result<Self, FeatureError> {
        let (placed, embedded) = embed(mesh, sketch)?;
        let mut shaped = mesh.clone();
        shaped.positions_mut().copy_from_slice(&embedded);
        let normals = vertex_normals(&shaped);
        let mut system = region_system(&shaped, &placed.region)?;
        let rows: Vec<(VertexId, DVec3)> = system.laplacian_rows().collect();
        let rows = Rows {
            rows: &rows,
            region: &placed.region,
            normals: &normals,
        };
        let solutions = bases(kind, &shaped, &sketch.camera, &rows, &placed.path)
            .iter()
            .map(|change| system.prescribed_displacement(change))
            .collect::<Result<Vec<_>, _>>()
            .map_err(DeformError::from)?;
        let roi = system.roi_vertices().to_vec();
        Ok(FeatureEdit {
            kind,
            faces: touching_faces(&shaped, &placed.region),
            embedded,
            path: placed.path,
            roi,
            solutions,
        })
    }

    /// The region's Laplacian system on `mesh` (the mesh the edit was made for) with the
    /// sketch embedded, as this edit factored it: to check it against another solver, or to
    /// prescribe other Laplacians on the same region.
    ///
    /// Errors: [`DeformError`] when it cannot be factored (it could when the edit was made).
    pub fn region_system(&self, mesh: &Mesh) -> Result<LaplacianEdit, DeformError> {
        let mut shaped = mesh.clone();
        shaped.positions_mut().copy_from_slice(&self.embedded);
        let mut region = vec![false; mesh.n_vertices()];
        self.roi.iter().for_each(|v| region[v.index()] = true);
        region_system(&shaped, &region)
    }

    /// The kind of feature.
    pub fn kind(&self) -> FeatureKind {
        self.kind
    }

    /// Every vertex with the sketch embedded, before any amount.
    pub fn embedded(&self) -> &[DVec3] {
        &self.embedded
    }

    /// The edge path the sketch became, from its first point to its last.
    pub fn path(&self) -> &[VertexId] {
        &self.path
    }

    /// The vertices that may move.
    pub fn roi(&self) -> &[VertexId] {
        &self.roi
    }

    /// The shape at `amount` (a factor; degrees for suggestive contours; ignored when
    /// flattening), cut back toward neutral as far as needed to fold no triangle over (turn
    /// none by more than 80°).
    ///
    /// Errors: [`FeatureError::AmountNotFinite`].
    pub fn shape(&self, amount: f64) -> Result<Shaped, FeatureError> {
        let mut positions = self.embedded.clone();
        let limited_to = self.shape_into(amount, &mut positions)?;
        Ok(Shaped {
            positions,
            limited_to,
        })
    }

    /// [`FeatureEdit::shape`] into `out` (every vertex; only the region is written, so `out`
    /// must hold [`FeatureEdit::embedded`] elsewhere): allocates nothing, for a drag frame.
    /// Returns the amount used when it had to be cut back.
    ///
    /// Errors: [`FeatureError::AmountNotFinite`].
    pub fn shape_into(&self, amount: f64, out: &mut [DVec3]) -> Result<Option<f64>, FeatureError> {
        if !amount.is_finite() {
            return Err(FeatureError::AmountNotFinite);
        }
        self.write(amount, 1.0, out);
        if !self.folds(out) {
            return Ok(None);
        }
        let (mut safe, mut unsafe_) = (0.0, 1.0);
        for _ in 0..BOUND_STEPS {
            let mid = 0.5 * (safe + unsafe_);
            self.write(amount, mid, out);
            if self.folds(out) {
                unsafe_ = mid;
            } else {
                safe = mid;
            }
        }
        self.write(amount, safe, out);
        let neutral = self.kind.neutral_amount();
        Ok(Some(neutral + safe * (amount - neutral)))
    }

    /// Writes the region's positions for `amount` brought `fraction` of the way from neutral.
    fn write(&self, amount: f64, fraction: f64, out: &mut [DVec3]) {
        let weights = coefficients(self.kind, amount, fraction);
        for (k, &v) in self.roi.iter().enumerate() {
            let moved: DVec3 = (weights.iter().zip(&self.solutions))
                .map(|(&c, solution)| c * solution[k])
                .sum();
            out[v.index()] = self.embedded[v.index()] + moved;
        }
    }

    /// Whether any face touching the region turned over, or nearly (see [`FOLD_COS`]).
    fn folds(&self, positions: &[DVec3]) -> bool {
        self.faces.iter().any(|&(corners, before)| {
            let [a, b, c] = corners.map(|v| positions[v as usize]);
            let after = (b - a).cross(c - a);
            after.dot(before) <= FOLD_COS * after.length() * before.length()
        })
    }
}

/// The Laplacian system of `region` on `mesh`, anchored by the rest: no handles, no
/// rotations (the feature prescribes the Laplacians itself).
fn region_system(mesh: &Mesh, region: &[bool]) -> Result<LaplacianEdit, DeformError> {
    let params = EditParams {
        fit: HandleFit::Exact,
        rotations: Rotations::None,
    };
    LaplacianEdit::new(mesh, region, &[], params)
}

/// The faces of `mesh` with a vertex in `region`: their corners and normals.
fn touching_faces(mesh: &Mesh, region: &[bool]) -> Vec<([u32; 3], DVec3)> {
    mesh.faces()
        .filter(|&f| mesh.face_vertices(f).iter().any(|v| region[v.index()]))
        .map(|f| {
            let [a, b, c] = mesh.face_positions(f);
            (mesh.triangles()[f.index()], (b - a).cross(c - a))
        })
        .collect()
}

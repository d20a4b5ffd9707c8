//! FiberMesh creation: a closed stroke becomes a rotund closed surface that keeps the stroke
//! as a smooth control curve (Nealen, Igarashi, Sorkine, Alexa 2007; Nealen's thesis ch. 3).
//!
//! Pipeline of [`create_from_stroke`] (one file each):
//! 1. **Outline** (`outline.rs`): the stroke (screen px) is resampled at 2 px. An open
//!    stroke is refused ("Close the outline: end the stroke near where it started.")
//!    unless its ends are within [`CreateParams::close_tolerance_px`] (and 15% of its
//!    length); the small gap is then closed. Self-crossings: an *overshoot* (the end
//!    crossing the start, cutting off at most [`MAX_OVERSHOOT`] of the stroke) is trimmed
//!    at the crossing; any other crossing is refused with a sentence, not repaired:
//!    guessing which loop of a figure eight the user meant is worse than asking for a
//!    clean outline. Specks (below [`MIN_AREA_PX2`]) and slivers (`4π area / perimeter²`
//!    below [`MIN_ROUNDNESS`]) are refused. The loop is mapped onto the [`DrawingPlane`]
//!    (through the camera target, facing the camera), resampled at the mesh spacing `h`,
//!    smoothed (two Taubin passes) and resampled again.
//! 2. **Connectivity** (`triangulate.rs`, `inflate.rs`): a triangular lattice of spacing
//!    `h` inside the outline, joined to it by a constrained Delaunay triangulation and
//!    relaxed (the file says why); front and back copies share the outline vertices,
//!    giving a closed genus-0 manifold. `h` follows from the area `A`, perimeter `P` and
//!    [`CreateParams::target_vertices`] `N`: `2 A / (√3/2 h²) + P / h = N`.
//! 3. **Seed** (`inflate.rs`): a Poisson problem `-Δu = 1` inside the outline gives every
//!    vertex a local radius, and the disk's stereographic map onto a hemisphere, applied
//!    with that radius, lifts and spreads the vertices; a circle starts as the sphere. The
//!    thesis does not say how the first iteration gets normals: a flat start has none
//!    along the outline and zero Laplacian magnitudes everywhere (a fixed point of the
//!    optimization). With the seed every vertex has a meaningful normal and magnitude, so
//!    the first iteration is like every other one; no second factorization is spent on a
//!    special first iteration.
//! 4. **Fair surface** ([`FairSurface`], Eqs. 3.6–3.10, `fair_surface.rs`): two
//!    prefactored systems, iterated with back-substitutions only; curve vertices are
//!    fixed unknowns, so the curve stays exactly on the surface. Measured: 4–10
//!    iterations to a step below 0.1% of the size (thesis: 5–10).
//!
//! Progressive display: [`seed_from_stroke`] stops after step 3 and costs no
//! factorization (the seed is already rotund), so it is the first frame;
//! [`SeedShape::into_creation`] factors both systems and runs one iteration (the costly
//! part, about 5× the seed at 10k vertices; [`first_iteration`]), and the steps of
//! [`CreateParams::refinement`] (a [`Convergence`]) refine over the next frames.
//! [`create_from_stroke`] and [`create_converged_from_stroke`] chain them, and so does the
//! document's `create` op, one step at a time (`crate::document::Edit`).
//!
//! Sign conventions: `L v_i = v_i - mean_j v_j` (as in [`crate::geometry`]) and outward
//! normals, so Laplacian magnitudes are positive on convex parts (`measure.rs`).
//!
//! Limits: the result depends on the tessellation (the uniform Laplacian stands for the
//! mean-curvature normal, as in the thesis); the Laplacian magnitudes are measured once on
//! the seed and kept, so the seed decides how fat a shape gets (a long strip ends about
//! as tall as wide); where an outline is about one spacing `h` wide (tips of thin arms,
//! narrow necks) front and back meet at a visible angle (up to about 95° at 1500
//! vertices) instead of rounding off.

pub mod add_curve;
pub mod curve_pull;
pub mod curve_tools;
pub mod cut;
mod error;
pub mod extrude;
mod fair_surface;
mod fair_systems;
mod inflate;
mod measure;
pub mod merge;
mod opening;
mod outline;
mod plane;
mod region;
mod rings;
mod triangulate;
pub mod tunnel;

use glam::DVec2;

pub use error::CreateError;
pub use fair_surface::{Convergence, FairSurface, RunSummary};
pub use opening::ViewedStroke;
pub use outline::{FINE_SPACING_PX, MAX_OVERSHOOT, MIN_AREA_PX2, MIN_ROUNDNESS};
pub use plane::DrawingPlane;
pub use region::{Region, nearest_vertices, region_around};

use crate::camera::Camera;
use crate::curve::StrokePoint;
use crate::curve::polyline::{perimeter, signed_area};
use crate::mesh::{Mesh, VertexId};
use crate::model::{ControlCurve, CurveKind};

/// Settings of a creation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CreateParams {
    /// About how many vertices the closed mesh gets; the resolution setting.
    pub target_vertices: usize,
    /// How far apart (CSS px) the stroke's ends may be for it to count as closed.
    pub close_tolerance_px: f64,
    /// Iteration cap of a creation, its [`first_iteration`] included (see
    /// [`CreateParams::refinement`]).
    pub max_iterations: usize,
    /// Convergence: no vertex moves more than this fraction of the bounding-box diagonal.
    pub tolerance: f64,
}

impl Default for CreateParams {
    fn default() -> Self {
        CreateParams {
            target_vertices: 2500,
            close_tolerance_px: 40.0,
            max_iterations: 15,
            tolerance: 1e-3,
        }
    }
}

impl CreateParams {
    /// The run that refines a creation after its [`first_iteration`]: the rest of
    /// `max_iterations`, to `tolerance`, with [`FairSurface::run`]'s rule and divergence guard.
    pub fn refinement(&self) -> Convergence {
        Convergence::new(self.max_iterations.saturating_sub(1), self.tolerance)
    }
}

/// The first display of a new shape: connectivity and seed, before any factorization.
#[derive(Clone, Debug)]
pub struct SeedShape {
    /// The closed mesh with the seed geometry (already rotund; a circle gives a sphere).
    pub mesh: Mesh,
    /// The control curve's vertices: a closed chain in stroke order.
    pub curve_vertices: Vec<VertexId>,
    /// The plane the stroke was drawn on.
    pub plane: DrawingPlane,
}

impl SeedShape {
    /// The control curve as the optimization sees it (a closed smooth curve).
    pub fn control_curve(&self) -> ControlCurve {
        ControlCurve {
            vertices: self.curve_vertices.clone(),
            is_closed: true,
            kind: CurveKind::Smooth,
        }
    }

    /// Factors the fair-surface systems and runs one iteration ([`first_iteration`]).
    ///
    /// Errors: [`CreateError::Solve`] if a factorization fails (a bug for a seed built by
    /// [`seed_from_stroke`]).
    pub fn into_creation(self) -> Result<Creation, CreateError> {
        let curve = self.control_curve();
        let SeedShape {
            mut mesh,
            curve_vertices,
            plane,
        } = self;
        let surface = first_iteration(&mut mesh, &curve)?;
        Ok(Creation {
            mesh,
            curve_vertices,
            surface,
            plane,
        })
    }
}

/// Factors the fair-surface systems of a new shape (a seed's `mesh` and its outline `curve`)
/// and runs the first iteration on `mesh`; [`CreateParams::refinement`] goes on from there.
///
/// Errors: [`CreateError::Solve`] if a factorization fails.
pub fn first_iteration(mesh: &mut Mesh, curve: &ControlCurve) -> Result<FairSurface, CreateError> {
    let mut surface =
        FairSurface::new(mesh, std::slice::from_ref(curve)).map_err(CreateError::Solve)?;
    surface
        .iterate(mesh.positions_mut())
        .map_err(CreateError::Solve)?;
    Ok(surface)
}

/// A new shape: its mesh, its control curve and the optimization to continue.
#[derive(Debug)]
pub struct Creation {
    /// The closed mesh, displayable (seeded and optimized at least once).
    pub mesh: Mesh,
    /// The control curve's vertices: a closed chain in stroke order.
    pub curve_vertices: Vec<VertexId>,
    /// The fair-surface optimization of `mesh`, to iterate on.
    pub surface: FairSurface,
    /// The plane the stroke was drawn on.
    pub plane: DrawingPlane,
}

impl Creation {
    /// The control curve as the optimization sees it (a closed smooth curve).
    pub fn control_curve(&self) -> ControlCurve {
        ControlCurve {
            vertices: self.curve_vertices.clone(),
            is_closed: true,
            kind: CurveKind::Smooth,
        }
    }

    /// Iterates the fair surface until converged (see [`FairSurface::run`]).
    ///
    /// Errors: [`CreateError::Solve`] (only on a length mismatch, which is a bug).
    pub fn converge(
        &mut self,
        max_iterations: usize,
        tolerance: f64,
    ) -> Result<RunSummary, CreateError> {
        self.surface
            .run(self.mesh.positions_mut(), max_iterations, tolerance)
            .map_err(CreateError::Solve)
    }
}

/// The fast first display of a closed stroke drawn in `camera`'s view (`viewport` in CSS
/// px): outline, connectivity and seed, with no factorization. See the module docs.
///
/// Errors: the stroke's problems as sentences ([`CreateError`]).
pub fn seed_from_stroke(
    stroke: &[StrokePoint],
    camera: &Camera,
    viewport: DVec2,
    params: &CreateParams,
) -> Result<SeedShape, CreateError> {
    let plane = DrawingPlane::facing(camera).ok_or(CreateError::BadView)?;
    let loop_in_screen = outline::closed_loop_in_screen(stroke, params.close_tolerance_px)?;
    let loop_on_plane = outline::loop_on_plane(&loop_in_screen, camera, viewport, &plane)
        .ok_or(CreateError::BadView)?;
    let spacing = spacing_for(&loop_on_plane, params.target_vertices);
    let boundary = outline::even_outline(&loop_on_plane, spacing)?;
    let planar = triangulate::triangulate(&boundary, spacing)?;
    let (mesh, curve_vertices) = inflate::inflate(&planar, &plane)?;
    Ok(SeedShape {
        mesh,
        curve_vertices,
        plane,
    })
}

/// Builds a shape from a closed stroke: [`seed_from_stroke`], then
/// [`SeedShape::into_creation`] (both factorizations and one iteration).
///
/// Errors: the stroke's problems as sentences ([`CreateError`]).
pub fn create_from_stroke(
    stroke: &[StrokePoint],
    camera: &Camera,
    viewport: DVec2,
    params: &CreateParams,
) -> Result<Creation, CreateError> {
    seed_from_stroke(stroke, camera, viewport, params)?.into_creation()
}

/// [`create_from_stroke`], then iterates to convergence with `params.max_iterations` and
/// `params.tolerance` (counting the first iteration); returns the creation and what the
/// iterations did.
///
/// Errors: those of [`create_from_stroke`].
pub fn create_converged_from_stroke(
    stroke: &[StrokePoint],
    camera: &Camera,
    viewport: DVec2,
    params: &CreateParams,
) -> Result<(Creation, RunSummary), CreateError> {
    let mut creation = create_from_stroke(stroke, camera, viewport, params)?;
    let mut run = params.refinement();
    while !run
        .step(&mut creation.surface, creation.mesh.positions_mut())
        .map_err(CreateError::Solve)?
    {}
    let mut summary = run.summary();
    summary.iterations += 1;
    Ok((creation, summary))
}

/// The lattice spacing that gives about `target_vertices` vertices: front and back
/// interiors of `A / (√3/2 h²)` each plus `P / h` on the outline. At least 12 outline
/// vertices.
fn spacing_for(outline: &[DVec2], target_vertices: usize) -> f64 {
    let area = signed_area(outline).abs();
    let length = perimeter(outline);
    let a = 2.0 * area / (3f64.sqrt() / 2.0);
    let n = target_vertices.max(1) as f64;
    // a x² + P x - N = 0 for x = 1 / h.
    let x = (-length + (length * length + 4.0 * a * n).sqrt()) / (2.0 * a);
    (1.0 / x).min(length / 12.0)
}

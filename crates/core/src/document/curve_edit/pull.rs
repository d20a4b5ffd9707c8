//! The deform tool (thesis §3.2.2): grab a curve point, drag it parallel to the screen; the
//! curve peels and the surface follows.
//!
//! The committed op ([`pull_op`]) deforms the curves for the release point, re-optimizes the
//! surface around the grabbed point with a fresh factorization, and remeshes there. While
//! the pointer is down, a `pull` edit begun as a gesture
//! ([`Editor::begin_gesture`](crate::document::Editor::begin_gesture)) shows a
//! [`PullPreview`] instead: the curve deformation is the same (it depends on the target
//! only), and the surface is solved in a region around the grabbed point, factored once by
//! the edit's first step, with every other vertex held; each later step follows the latest
//! pointer sample with one back-substitution. At 40k vertices one back-substitution of the
//! whole mesh costs ~34 ms in wasm, too slow for 30 fps. The preview region is the
//! [`PREVIEW_VERTICES`] nearest vertices (the whole shape at 10k vertices), so its cost does
//! not grow with the mesh, and it is refactored only when the peel outgrows it: a refactor
//! is a frame of 50–250 ms in the page.
//!
//! One iteration per followed sample lags a fast drag: at 40k vertices with the worker's
//! samples 5 apart, 2,000–18,000 triangles were folded over in the preview, which shows
//! until the committed pull lands (issue 49: an inside-out fold for 2.5 s). A step whose
//! surface folds a triangle (against the model at rest) iterates up to
//! [`UNFOLDING_ITERATIONS`] more times, and if it still folds, the preview shows the surface
//! as far towards it as folds nothing (the solve goes on from the folded one at the next sample).

use std::sync::Arc;

use glam::{DVec2, DVec3};

use super::settle::{Change, remesh_and_settle, settle};
use super::shared::{CurvePick, bounding_diagonal, pick_curve_vertex, replaced, screen_stroke};
use crate::camera::Camera;
use crate::document::{CommandError, Document, Model, StrokeInput};
use crate::fibermesh::curve_pull::{CurveNetwork, CurvePull, PullParams};
use crate::fibermesh::{FairSurface, nearest_vertices, region_around};
use crate::geometry::flipped_faces;
use crate::mesh::VertexId;
use crate::model::ControlCurve;

/// The region solved while dragging reaches this many peel radii from the grabbed point.
const REGION_PER_PEEL: f64 = 2.5;

/// The smallest region, as a fraction of the model's bounding-box diagonal.
const MIN_REGION: f64 = 0.25;

/// The most vertices the preview solves at pointer-down.
const PREVIEW_VERTICES: usize = 5_000;

/// The preview region must reach this many peel radii from the grabbed point (the peeled
/// curve and some surface beyond its ends); past that it is refactored larger.
const PREVIEW_REACH_PER_PEEL: f64 = 1.25;

/// How much farther than needed a refactored preview region reaches, so that a drag
/// refactors a few times, not every frame.
const PREVIEW_GROWTH: f64 = 1.3;

/// Surface iterations per followed sample (one step, so one frame).
const ITERATIONS_PER_FRAME: usize = 1;

/// The most iterations a step adds while its surface folds a triangle over.
const UNFOLDING_ITERATIONS: usize = 3;

/// How finely a folded step's shown surface is placed between the last unfolded one and the
/// folded one (halvings: 1/32 of the way).
const FOLD_BISECTIONS: usize = 5;

/// Applies a `pull` op: returns the index of the pulled model and its new version.
///
/// Errors: the stroke's, [`CommandError::NoCurveHere`] when the first sample is not over a
/// visible curve point, and failures of the deformation, remesher or solver.
pub fn pull_op(doc: &Document, input: &StrokeInput) -> Result<(usize, Model), CommandError> {
    let stroke = screen_stroke(input, 1)?;
    let pick = pick_curve_vertex(doc, input, stroke[0])?;
    let model = &doc.models[pick.model];
    let curves = &model.curves;
    let (mut pull, node_vertices) = curve_pull(model, curves, pick)?;
    let Some(&release) = stroke.last() else {
        return Err(CommandError::StrokeTooShort);
    };
    let target = drag_target(input, model.mesh.position(pick.vertex), release)?;
    let mut nodes = vec![DVec3::ZERO; node_vertices.len()];
    let peel = pull.pull_to(target, &mut nodes)?;
    let mut mesh = model.mesh.clone();
    for (&v, &p) in node_vertices.iter().zip(&nodes) {
        mesh.positions_mut()[v.index()] = p;
    }
    let change = Change {
        around: &[pick.vertex],
        radius: region_radius(&model.mesh, peel.radius),
    };
    settle(&mut mesh, curves, model.mesh.positions(), change, false)?;
    let (mesh, curves) = remesh_and_settle(&mesh, curves, change)?;
    Ok((pick.model, replaced(model, mesh, curves)))
}

/// The live preview of a `pull` op while the pointer is down; see the module docs.
#[derive(Debug)]
pub(in crate::document) struct PullPreview {
    /// The view the drag happens in (the op's first sample is the grab).
    view: StrokeInput,
    model_index: usize,
    model: Arc<Model>,
    curves: Vec<ControlCurve>,
    grabbed: DVec3,
    grabbed_vertex: VertexId,
    pull: CurvePull,
    /// The mesh vertex of each node of the curve network.
    node_vertices: Vec<VertexId>,
    nodes: Vec<DVec3>,
    positions: Vec<DVec3>,
    /// The last of `positions` that folded no triangle over: what is shown.
    unfolded: Vec<DVec3>,
    /// Scratch for [`show_towards_folded`]'s trials, kept between steps.
    trial: Vec<DVec3>,
    /// The surface of the preview region; `None` until the first step factors it.
    surface: Option<FairSurface>,
    /// How far from the grabbed point the preview region reaches.
    reach: f64,
    /// How many samples of the drag the preview has followed (the grab is the first).
    followed: usize,
}

impl PullPreview {
    /// Grabs the nearest visible curve point under `input`'s first sample; cheap (no
    /// factorization yet), so a pull that grabs nothing is refused at once.
    ///
    /// Errors: [`CommandError::NoCurveHere`] and the stroke's errors, as the `pull` op.
    pub(in crate::document) fn start(
        doc: &Document,
        input: &StrokeInput,
    ) -> Result<PullPreview, CommandError> {
        let stroke = screen_stroke(input, 1)?;
        let pick = pick_curve_vertex(doc, input, stroke[0])?;
        let model = Arc::clone(&doc.models[pick.model]);
        let curves = model.curves.clone();
        let (pull, node_vertices) = curve_pull(&model, &curves, pick)?;
        Ok(PullPreview {
            view: StrokeInput {
                stroke: input.stroke[..1].to_vec(),
                ..input.clone()
            },
            model_index: pick.model,
            grabbed: model.mesh.position(pick.vertex),
            grabbed_vertex: pick.vertex,
            curves,
            nodes: vec![DVec3::ZERO; node_vertices.len()],
            positions: model.mesh.positions().to_vec(),
            unfolded: model.mesh.positions().to_vec(),
            trial: Vec::new(),
            model,
            pull,
            node_vertices,
            surface: None,
            reach: 0.0,
            followed: 1,
        })
    }

    /// One chunk of work for the drag so far (`stroke`, the grab first): factors the
    /// preview region (the first call), or moves the grabbed point under the latest sample,
    /// deforming the curves and letting the region follow by one back-substitution. Earlier
    /// samples not followed yet are skipped: the preview follows the pointer, not its path.
    /// Returns `None` when there was nothing to do, else whether more work is ready.
    ///
    /// Errors: a sample that does not project into the scene, or a failed solve.
    pub(in crate::document) fn step(
        &mut self,
        stroke: &[[f64; 3]],
    ) -> Result<Option<bool>, CommandError> {
        let Some(surface) = &mut self.surface else {
            let region = nearest_vertices(
                &self.model.mesh,
                &[self.grabbed_vertex],
                f64::INFINITY,
                PREVIEW_VERTICES,
            );
            self.surface = Some(regional_surface(&self.model, &self.curves, &region.mask)?);
            self.reach = region.reach;
            return Ok(Some(stroke.len() > self.followed));
        };
        let Some(&[x, y, _]) = stroke.last().filter(|_| stroke.len() > self.followed) else {
            return Ok(None);
        };
        let target = drag_target(&self.view, self.grabbed, DVec2::new(x, y))?;
        let peel = self.pull.pull_to(target, &mut self.nodes)?;
        let needed = PREVIEW_REACH_PER_PEEL * peel.radius;
        if needed > self.reach {
            let reach = PREVIEW_GROWTH * needed;
            let region = region_around(&self.model.mesh, &[self.grabbed_vertex], reach);
            *surface = regional_surface(&self.model, &self.curves, &region)?;
            self.reach = reach;
        }
        for (&v, &p) in self.node_vertices.iter().zip(&self.nodes) {
            self.positions[v.index()] = p;
        }
        let mesh = &self.model.mesh;
        let folds =
            |positions: &[DVec3]| flipped_faces(mesh.triangles(), mesh.positions(), positions) > 0;
        let mut iterations = 0;
        while iterations < ITERATIONS_PER_FRAME
            || (iterations < ITERATIONS_PER_FRAME + UNFOLDING_ITERATIONS && folds(&self.positions))
        {
            surface
                .iterate(&mut self.positions)
                .map_err(CommandError::Surface)?;
            iterations += 1;
        }
        if !folds(&self.positions) {
            self.unfolded.copy_from_slice(&self.positions);
        } else {
            show_towards_folded(&mut self.unfolded, &mut self.trial, &self.positions, folds);
        }
        self.followed = stroke.len();
        Ok(Some(false))
    }

    /// The index of the model being pulled and the previewed positions of its vertices: the
    /// last that folded no triangle over (see [`show_towards_folded`]).
    pub(in crate::document) fn moved(&self) -> (usize, &[DVec3]) {
        (self.model_index, &self.unfolded)
    }

    /// [`PullPreview::moved`], kept when the drag ends (shown until the result lands).
    pub(in crate::document) fn into_moved(self) -> (usize, Vec<DVec3>) {
        (self.model_index, self.unfolded)
    }
}

/// How far from the grabbed point (along the surface) a pull with a peel of `peel_radius`
/// moves the surface: [`REGION_PER_PEEL`] peel radii, at least [`MIN_REGION`] of the
/// model's size.
pub(super) fn region_radius(mesh: &crate::mesh::Mesh, peel_radius: f64) -> f64 {
    (REGION_PER_PEEL * peel_radius).max(MIN_REGION * bounding_diagonal(mesh))
}

/// A pull of `model`'s curve network grabbed at `pick`, and the mesh vertex of each node.
fn curve_pull(
    model: &Model,
    curves: &[ControlCurve],
    pick: CurvePick,
) -> Result<(CurvePull, Vec<VertexId>), CommandError> {
    let chains: Vec<(&[VertexId], bool)> = curves
        .iter()
        .map(|curve| (curve.vertices.as_slice(), curve.is_closed))
        .collect();
    let network = CurveNetwork::new(model.mesh.positions(), &chains);
    let node = network
        .node_of(pick.vertex)
        .ok_or(CommandError::NoCurveHere)?;
    let node_vertices = (0..network.n_nodes())
        .map(|node| network.mesh_vertex(node))
        .collect();
    let pull = CurvePull::new(network, node, PullParams::default());
    Ok((pull, node_vertices))
}

/// The fair surface of `model` solved only in `region` (a vertex mask), aiming for the
/// magnitudes the model has now.
fn regional_surface(
    model: &Model,
    curves: &[ControlCurve],
    region: &[bool],
) -> Result<FairSurface, CommandError> {
    let mut surface = FairSurface::new_regional(&model.mesh, curves, region, &[])
        .map_err(CommandError::Surface)?;
    surface
        .measure_magnitudes(model.mesh.positions())
        .map_err(CommandError::Surface)?;
    Ok(surface)
}

/// Where the grabbed point goes for a pointer at `screen`: on the plane through its rest
/// position `grabbed` facing the camera (the thesis: "always parallel to the screen").
fn drag_target(input: &StrokeInput, grabbed: DVec3, screen: DVec2) -> Result<DVec3, CommandError> {
    plane_point(&input.camera, input.viewport_size(), grabbed, screen).ok_or(CommandError::BadView)
}

/// The point under `screen` on the plane through `on_plane` facing `camera`.
fn plane_point(camera: &Camera, viewport: DVec2, on_plane: DVec3, screen: DVec2) -> Option<DVec3> {
    let (origin, dir) = camera.ray_in_world(screen, viewport);
    let normal = camera.forward();
    let facing = dir.dot(normal);
    if !screen.is_finite() || facing.abs() < 1e-12 {
        return None;
    }
    let t = (on_plane - origin).dot(normal) / facing;
    let point = origin + t * dir;
    point.is_finite().then_some(point)
}

/// Moves `shown` (which folds nothing) as far towards the `folded` surface as it can go
/// without a fold, bisecting the straight path between them, so a fast drag's preview still
/// follows the pen part of the way instead of standing still. `trial` is scratch.
fn show_towards_folded(
    shown: &mut [DVec3],
    trial: &mut Vec<DVec3>,
    folded: &[DVec3],
    folds: impl Fn(&[DVec3]) -> bool,
) {
    let (mut unfolded_at, mut folded_at) = (0.0, 1.0);
    trial.clear();
    trial.extend_from_slice(shown);
    for _ in 0..FOLD_BISECTIONS {
        let t = 0.5 * (unfolded_at + folded_at);
        for ((p, &from), &to) in trial.iter_mut().zip(&*shown).zip(folded) {
            *p = from.lerp(to, t);
        }
        match folds(trial) {
            true => folded_at = t,
            false => unfolded_at = t,
        }
    }
    if unfolded_at > 0.0 {
        for (p, &to) in shown.iter_mut().zip(folded) {
            *p = p.lerp(to, unfolded_at);
        }
    }
}

//! The `deform` op (a scripted large deformation of one model by sphere handles, through the
//! volumetric graph Laplacian or, for comparison, the surface editor:
//! [`crate::volumetric::deform_with_spheres`]) and the `curve_deform` op (a control curve
//! picked on the surface and redrawn in its editing plane: [`crate::volumetric::CurveEdit`]).
//!
//! The volumetric graph depends only on the model's surface, so the last one built is kept
//! (one per thread, keyed by the surface's positions and triangles): the ops and drag frames
//! on one model revision build it once.

use std::cell::RefCell;
use std::hash::{Hash, Hasher};
use std::sync::Arc;

use glam::{DMat4, DVec2, DVec3};
use serde::{Deserialize, Serialize};

use super::next::{target, with_positions};
use super::{CommandError, Document, Model};
use crate::camera::Camera;
use crate::curve::polyline::contains;
use crate::feature::Sketch;
use crate::mesh::{Mesh, VertexId};
use crate::model::positions_hash;
use crate::volumetric::{
    CoarsePlaneCurve, CurveEdit, Falloff, Method, Plane, Sphere, SphereHandle, VolumetricError,
    VolumetricGraph, VolumetricParams, curve_targets, deform_with_spheres, editing_plane,
    pick_curve,
};

thread_local! {
    /// The last volumetric graph built, with the key of the surface it was built for.
    static LAST_GRAPH: RefCell<Option<(u64, Arc<VolumetricGraph>)>> = const { RefCell::new(None) };
}

/// The volumetric graph of `mesh`, built or the one kept for the same surface.
///
/// Errors: those of [`VolumetricGraph::build`].
pub(super) fn graph_of(mesh: &Mesh) -> Result<Arc<VolumetricGraph>, VolumetricError> {
    let mut hasher = std::collections::hash_map::DefaultHasher::new();
    positions_hash(mesh).hash(&mut hasher);
    mesh.triangles().hash(&mut hasher);
    let key = hasher.finish();
    let kept = LAST_GRAPH.with_borrow(|last| {
        last.as_ref()
            .filter(|(k, _)| *k == key)
            .map(|(_, graph)| Arc::clone(graph))
    });
    if let Some(graph) = kept {
        return Ok(graph);
    }
    let graph = Arc::new(VolumetricGraph::build(mesh)?);
    LAST_GRAPH.set(Some((key, Arc::clone(&graph))));
    Ok(graph)
}

/// `{"op":"deform","method":…,"model":i,"handles":[…],"fixed":[…]}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DeformInput {
    /// How the points that follow are solved for.
    pub method: DeformMethod,
    /// The model's index.
    pub model: usize,
    /// What moves: the points inside each sphere, exactly by its matrix.
    pub handles: Vec<DeformHandleInput>,
    /// What stays: the points inside these spheres `[x, y, z, r]`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub fixed: Vec<[f64; 4]>,
}

/// The `"method"` of a `deform` op.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum DeformMethod {
    /// The volumetric graph Laplacian.
    #[default]
    Volumetric,
    /// The surface Laplacian editor with rotations.
    Surface,
}

/// One handle of a `deform` op.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DeformHandleInput {
    /// The sphere `[x, y, z, r]` whose points it moves.
    pub sphere: [f64; 4],
    /// The 4×4 affine matrix, column by column, that moves them.
    pub matrix: [f64; 16],
}

/// The index of the model and the model with its vertices moved; its triangles, curves and
/// appearance stay.
///
/// Errors: [`CommandError::NoSuchModel`], and the deformation's refusal (an open model,
/// a handle that holds nothing, a fixed sphere over a handle, a bad matrix).
pub(super) fn deform_op(
    doc: &Document,
    input: &DeformInput,
) -> Result<(usize, Model), CommandError> {
    let mesh = &target(doc, input.model)?.mesh;
    let handles: Vec<SphereHandle> = input
        .handles
        .iter()
        .map(|h| SphereHandle {
            sphere: sphere(h.sphere),
            matrix: DMat4::from_cols_array(&h.matrix),
        })
        .collect();
    let fixed: Vec<Sphere> = input.fixed.iter().map(|&s| sphere(s)).collect();
    let method = match input.method {
        DeformMethod::Volumetric => Method::Volumetric(VolumetricParams::default()),
        DeformMethod::Surface => Method::Surface,
    };
    let graph = match method {
        Method::Volumetric(_) => Some(graph_of(mesh)?),
        Method::Surface => None,
    };
    let positions = deform_with_spheres(mesh, graph.as_deref(), &handles, &fixed, method)?;
    Ok((input.model, with_positions(doc, input.model, &positions)))
}

fn sphere([x, y, z, radius]: [f64; 4]) -> Sphere {
    Sphere {
        centre: DVec3::new(x, y, z),
        radius,
    }
}

/// `{"op":"curve_deform",...}`: a control curve drawn along model `model`'s surface, and the
/// curve it becomes, drawn in its editing plane.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CurveDeformInput {
    /// The model's index.
    pub model: usize,
    /// Viewport size `[width, height]` in CSS px.
    pub viewport: [f64; 2],
    /// The camera both strokes were drawn with.
    pub camera: Camera,
    /// Raw samples `[x, y, pressure]` of the stroke along the surface: the control curve is
    /// the edge path under it. Empty when `path` names the curve.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub curve: Vec<[f64; 3]>,
    /// The control curve as its vertices' indices, in order, each joined to the next by an
    /// edge: a curve picked before (a deformation keeps the vertices), edited again.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub path: Option<Vec<u32>>,
    /// Other control curves, as vertex chains, that keep their place while this one moves.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub held: Vec<Vec<u32>>,
    /// Raw samples `[x, y, pressure]` of the new curve, drawn on the editing plane.
    pub stroke: Vec<[f64; 3]>,
    /// The camera the new curve was drawn with, when the view turned to face the editing
    /// plane after the curve was picked; left out, `camera`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stroke_camera: Option<Camera>,
    /// The editing plane's normal; left out, the plane is chosen from the curve's average
    /// normal and principal direction.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plane: Option<[f64; 3]>,
    /// A closed lasso `[x, y, pressure]` around the part that holds still.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fixed: Option<Vec<[f64; 3]>>,
    /// How the curve's turns fade: `"linear"` (left out), `"constant"` or `"gaussian"`.
    #[serde(default, skip_serializing_if = "is_linear")]
    pub falloff: Falloff,
    /// The new shape by the curve's coarse spline instead of a sketch: `stroke` is then the
    /// drag of one of its control points.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub coarse: Option<CoarseInput>,
}

/// A `curve_deform`'s coarse edit: the curve's projection onto its plane fitted by a cubic
/// B-spline with these knots, one control point dragged.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CoarseInput {
    /// The spline's interior knots, increasing inside (0, 1): `knots.len() + 4` control
    /// points.
    pub knots: Vec<f64>,
    /// The control point dragged: it moves by the stroke's last point less its first, on
    /// the plane.
    pub control: usize,
}

fn is_linear(falloff: &Falloff) -> bool {
    *falloff == Falloff::Linear
}

impl CurveDeformInput {
    fn viewport_size(&self) -> Result<DVec2, CommandError> {
        let viewport = DVec2::from(self.viewport);
        let usable = viewport.is_finite() && viewport.x > 0.0 && viewport.y > 0.0;
        let cameras_valid =
            self.camera.is_valid() && self.stroke_camera.is_none_or(|c| c.is_valid());
        if usable && cameras_valid {
            Ok(viewport)
        } else {
            Err(CommandError::BadView)
        }
    }
}

/// The screen points of raw samples.
fn screen_points(samples: &[[f64; 3]]) -> Vec<DVec2> {
    samples.iter().map(|&[x, y, _]| DVec2::new(x, y)).collect()
}

/// `mesh`'s vertices `ids`, when each exists and is joined to the next by an edge.
fn vertex_chain(mesh: &Mesh, ids: &[u32]) -> Result<Vec<VertexId>, VolumetricError> {
    let n = mesh.n_vertices();
    let chain: Vec<VertexId> = ids.iter().map(|&i| VertexId(i)).collect();
    let joined = chain
        .windows(2)
        .all(|w| mesh.find_edge(w[0], w[1]).is_some());
    if ids.iter().all(|&i| (i as usize) < n) && joined {
        Ok(chain)
    } else {
        Err(VolumetricError::BadPath)
    }
}

/// The picked curve's editing plane: the given normal through the curve's centroid, or the
/// one chosen for it.
fn plane_for(mesh: &Mesh, path: &[VertexId], normal: Option<[f64; 3]>) -> Plane {
    let chosen = editing_plane(mesh, path);
    match normal.map(DVec3::from).and_then(DVec3::try_normalize) {
        Some(normal) => Plane { normal, ..chosen },
        None => chosen,
    }
}

/// The index of the model and the model with the curve moved.
///
/// Errors: [`CommandError::NoSuchModel`], [`CommandError::BadView`], and the deformation's
/// refusal (an open model, a curve stroke that misses the surface, a new curve drawn on a
/// plane seen edge-on or of fewer than two points).
pub(super) fn curve_deform_op(
    doc: &Document,
    input: &CurveDeformInput,
) -> Result<(usize, Model), CommandError> {
    let picked = PickedCurve::new(doc, input)?;
    let mut edit = picked.edit(input)?;
    let positions = picked.deform(&mut edit, input)?.to_vec();
    Ok((input.model, with_positions(doc, input.model, &positions)))
}

/// A `curve_deform`'s control curve on its model, with its plane and graph.
#[derive(Debug)]
struct PickedCurve {
    path: Vec<VertexId>,
    /// The held curves' vertices, one list.
    held: Vec<VertexId>,
    plane: Plane,
    graph: Arc<VolumetricGraph>,
    /// The model, shared with the document (not a copy of its mesh).
    model: Arc<Model>,
    viewport: DVec2,
}

impl PickedCurve {
    /// Picks the curve of `input` and gets its model's graph (built or kept).
    ///
    /// Errors: as [`curve_deform_op`].
    fn new(doc: &Document, input: &CurveDeformInput) -> Result<PickedCurve, CommandError> {
        let model = doc
            .models
            .get(input.model)
            .ok_or(CommandError::NoSuchModel(input.model))?;
        let mesh = &model.mesh;
        let viewport = input.viewport_size()?;
        let path = match (&input.path, input.curve.is_empty()) {
            (Some(ids), true) => vertex_chain(mesh, ids)?,
            (None, false) => {
                let sketch = Sketch {
                    camera: input.camera,
                    viewport,
                    points: screen_points(&input.curve),
                    region: None,
                };
                pick_curve(mesh, &sketch)?
            }
            _ => return Err(VolumetricError::BadPath.into()),
        };
        let mut held = Vec::new();
        for chain in &input.held {
            held.extend(vertex_chain(mesh, chain)?);
        }
        let plane = plane_for(mesh, &path, input.plane);
        Ok(PickedCurve {
            graph: graph_of(mesh)?,
            path,
            held,
            plane,
            model: Arc::clone(model),
            viewport,
        })
    }

    /// The factored edit of the curve with `input`'s fixed part and fall-off.
    ///
    /// Errors: the solve's.
    fn edit(&self, input: &CurveDeformInput) -> Result<CurveEdit, CommandError> {
        let lasso = input.fixed.as_deref().map(screen_points);
        let fixed: Vec<bool> = (self.graph.points().iter())
            .map(|&p| {
                let on_screen = input.camera.screen_from_world(p, self.viewport);
                match (&lasso, on_screen) {
                    (Some(lasso), Some(s)) => contains(lasso, s.truncate()),
                    _ => false,
                }
            })
            .collect();
        Ok(CurveEdit::new(
            &self.model.mesh,
            &self.graph,
            &self.path,
            &self.held,
            &fixed,
            input.falloff,
        )?)
    }

    /// The mesh's positions with the curve given `input`'s new shape.
    ///
    /// Errors: a new curve on a plane seen edge-on, or of fewer than two points.
    fn deform<'e>(
        &self,
        edit: &'e mut CurveEdit,
        input: &CurveDeformInput,
    ) -> Result<&'e [DVec3], CommandError> {
        let camera = input.stroke_camera.unwrap_or(input.camera);
        let drawn = screen_points(&input.stroke)
            .into_iter()
            .map(|p| {
                let (origin, dir) = camera.ray_in_world(p, self.viewport);
                self.plane.hit(origin, dir)
            })
            .collect::<Option<Vec<DVec3>>>()
            .ok_or(VolumetricError::EdgeOnPlane)?;
        let targets = match (&input.coarse, drawn.as_slice()) {
            (Some(coarse), [first, .., last] | [first @ last]) => {
                CoarsePlaneCurve::new(edit.rest(), &self.plane, &coarse.knots)?
                    .targets(coarse.control, *last - *first)?
            }
            (None, [_, _, ..]) => curve_targets(edit.rest(), &self.plane, &drawn),
            _ => return Err(VolumetricError::CurveTooShort.into()),
        };
        Ok(edit.deform(&targets)?)
    }
}

/// A `curve_deform` while its new curve is drawn: the curve picked and its graph got in a
/// first step, factored in a second, then each step back-substitutes for the stroke so far.
#[derive(Debug, Default)]
pub(super) struct CurvePreview {
    picked: Option<PickedCurve>,
    edit: Option<CurveEdit>,
    /// The number of stroke samples the shown positions are for.
    shown_for: usize,
    shown: Vec<DVec3>,
}

impl CurvePreview {
    /// One step toward showing `input`'s stroke so far: `Some(true)` while setting up,
    /// `Some(false)` after a new shape, `None` when it is shown already (or the stroke
    /// has fewer than two samples).
    ///
    /// Errors: as [`curve_deform_op`].
    pub(super) fn step(
        &mut self,
        base: &Document,
        input: &CurveDeformInput,
    ) -> Result<Option<bool>, CommandError> {
        let Some(picked) = &self.picked else {
            self.picked = Some(PickedCurve::new(base, input)?);
            return Ok(Some(true));
        };
        let Some(edit) = &mut self.edit else {
            self.edit = Some(picked.edit(input)?);
            return Ok(Some(true));
        };
        if input.stroke.len() < 2 || input.stroke.len() == self.shown_for {
            return Ok(None);
        }
        let positions = picked.deform(edit, input)?;
        self.shown.clear();
        self.shown.extend_from_slice(positions);
        self.shown_for = input.stroke.len();
        Ok(Some(false))
    }

    /// The model and the positions shown, once there are some.
    pub(super) fn moved(&self, input: &CurveDeformInput) -> Option<(usize, &[DVec3])> {
        (!self.shown.is_empty()).then_some((input.model, self.shown.as_slice()))
    }

    /// The committed result: the kept edit solved for the whole stroke, bit for bit what
    /// [`curve_deform_op`] computes (the same factorization, built the same way).
    ///
    /// Errors: as [`curve_deform_op`].
    pub(super) fn result(
        &mut self,
        base: &Document,
        input: &CurveDeformInput,
    ) -> Result<(usize, Model), CommandError> {
        let (Some(picked), Some(edit)) = (&self.picked, &mut self.edit) else {
            return curve_deform_op(base, input);
        };
        let positions = picked.deform(edit, input)?.to_vec();
        Ok((input.model, with_positions(base, input.model, &positions)))
    }
}

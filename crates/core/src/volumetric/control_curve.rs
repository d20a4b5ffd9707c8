//! Deforming by a control curve (Zhou et al. 2005, §3.3 and §4.1): a curve picked on the
//! surface, edited in a plane, drives the deformation.
//!
//! - **Picking.** A stroke along the surface becomes the cheapest edge path under it, the
//!   same path a feature sketch is embedded along (`feature`'s placement: edge costs are
//!   their ends' screen distances to the stroke).
//! - **The editing plane** contains the curve's average normal and its first principal
//!   direction (normal `n̄ × e₁`), so bending the curve off the surface is drawn side on;
//!   when the average normal nearly vanishes (a closed planar curve) it is the plane of the
//!   two principal directions. The user may give the plane's normal instead.
//! - **Sketch mode.** The new curve, drawn in the plane, replaces the curve's projection by
//!   arc-length correspondence; each curve vertex keeps its offset from the plane.
//! - **WIRE transforms.** At each curve vertex the turn taking its tangent to the new
//!   tangent (about their cross product), without WIRE's scale (see [`wire_transforms`]); every graph
//!   point takes the transform of its nearest curve vertex (geodesically, over the graph:
//!   the paper's closest-curve-point weighting), blended toward the identity by the
//!   strength field: with a fixed region `t = d_F / (d_F + d_C)`, else `t = 1 − d_C / R`
//!   with `R` the curve's length.
//! - **Coarse mode.** The curve's projection is fitted by a cubic B-spline (knots the user
//!   may add); moving a control point reshapes the projection with its detail kept
//!   ([`CoarseCurve`]), and each vertex keeps its offset from the plane.
//! - **Several curves.** Other picked curves may be *held*: their vertices are pulled to
//!   where they are (α rows, as the edited curve's) and count with the fixed region in the
//!   strength field, so the bend fades toward them too and the parts they run along keep
//!   their pose.
//! - The curve vertices are pulled to their new places by the energy's α rows; the fixed
//!   region's points hold still. Factored once per curve, held curves and fixed region;
//!   each new curve is a back-substitution.

use glam::{DQuat, DVec2, DVec3};

use super::coarse_curve::CoarseCurve;
use super::{
    Constraints, Falloff, Similarity, VolumetricEdit, VolumetricError, VolumetricGraph,
    VolumetricParams,
};
use crate::curve::bspline::valid_knots;
use crate::curve::polyline::{cumulative_lengths, point_at};
use crate::feature::{Sketch, pick_path};
use crate::geometry::vertex_normals;
use crate::mesh::{Mesh, VertexId, shortest_paths};

/// How small the average normal may be, next to the unit normals it averages, before the
/// plane is taken from the two principal directions.
const FLAT_NORMAL: f64 = 0.2;

/// A plane seen this nearly edge-on (cosine between the view ray and the plane) cannot
/// take a stroke.
const EDGE_ON: f64 = 0.1;

/// The control points a picked curve's coarse spline starts with: enough to bend a limb at
/// two places and keep its ends.
pub const COARSE_CONTROLS: usize = 6;

/// A plane through `origin` with unit `normal`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    /// A point on it.
    pub origin: DVec3,
    /// Its unit normal.
    pub normal: DVec3,
}

impl Plane {
    /// Where the ray from `origin` along `dir` meets the plane; `None` when it runs nearly
    /// along it.
    pub fn hit(&self, origin: DVec3, dir: DVec3) -> Option<DVec3> {
        let along = dir.normalize().dot(self.normal);
        if along.abs() < EDGE_ON {
            return None;
        }
        let t = (self.origin - origin).dot(self.normal) / dir.dot(self.normal);
        Some(origin + dir * t)
    }

    /// `p` in the plane's own 2D coordinates (its projection), and its offset along the
    /// normal.
    fn flat(&self, p: DVec3) -> (DVec2, f64) {
        let (u, w) = self.normal.any_orthonormal_pair();
        let d = p - self.origin;
        (DVec2::new(d.dot(u), d.dot(w)), d.dot(self.normal))
    }

    /// The point at 2D coordinates `q` on the plane, lifted by `offset` along its normal.
    fn lift(&self, q: DVec2, offset: f64) -> DVec3 {
        let (u, w) = self.normal.any_orthonormal_pair();
        self.origin + u * q.x + w * q.y + self.normal * offset
    }
}

/// The edge path under a stroke drawn along `mesh`'s surface.
///
/// Errors: [`VolumetricError::Curve`] with the placement's reason (the stroke misses or
/// leaves the surface, is too short, folds back).
pub fn pick_curve(mesh: &Mesh, stroke: &Sketch) -> Result<Vec<VertexId>, VolumetricError> {
    Ok(pick_path(mesh, stroke)?)
}

/// The curve's editing plane through its centroid; see the module docs.
pub fn editing_plane(mesh: &Mesh, path: &[VertexId]) -> Plane {
    let points: Vec<DVec3> = path.iter().map(|&v| mesh.position(v)).collect();
    let n = points.len().max(1) as f64;
    let origin = points.iter().sum::<DVec3>() / n;
    let normals = vertex_normals(mesh);
    let average = path.iter().map(|&v| normals[v.index()]).sum::<DVec3>() / n;
    let [first, second, third] = principal_directions(&points, origin);
    let normal = if average.length() > FLAT_NORMAL {
        average.cross(first).try_normalize().unwrap_or(third)
    } else {
        first.cross(second).try_normalize().unwrap_or(third)
    };
    Plane { origin, normal }
}

/// The principal directions of `points` about `origin`, by decreasing spread.
fn principal_directions(points: &[DVec3], origin: DVec3) -> [DVec3; 3] {
    let mut covariance = glam::DMat3::ZERO;
    for &p in points {
        let d = p - origin;
        covariance += glam::DMat3::from_cols(d * d.x, d * d.y, d * d.z);
    }
    // Power iterations on the 3x3 covariance: the first direction, then the second in the
    // plane orthogonal to it.
    let dominant = |m: glam::DMat3, start: DVec3| {
        let mut v = start;
        for _ in 0..64 {
            match (m * v).try_normalize() {
                Some(next) => v = next,
                None => break,
            }
        }
        v
    };
    let spread = points.last().map_or(DVec3::X, |&p| {
        (p - points[0]).try_normalize().unwrap_or(DVec3::X)
    });
    let first = dominant(covariance, spread);
    let deflate = |v: DVec3| v - first * first.dot(v);
    let projector = glam::DMat3::IDENTITY
        - glam::DMat3::from_cols(first * first.x, first * first.y, first * first.z);
    let start = deflate(first.any_orthonormal_vector()).normalize();
    let second = deflate(dominant(projector * covariance * projector, start))
        .try_normalize()
        .unwrap_or(start);
    [first, second, first.cross(second)]
}

/// Where each curve vertex (at `rest`) goes when the curve's projection onto `plane` is replaced by
/// `drawn` (points on the plane, in drawing order): the drawn curve at the vertex's share
/// of the projection's arc length, plus the vertex's offset from the plane. A curve drawn
/// from the far end is taken the other way round.
pub fn curve_targets(rest: &[DVec3], plane: &Plane, drawn: &[DVec3]) -> Vec<DVec3> {
    let projected: Vec<DVec2> = rest.iter().map(|&p| plane.flat(p).0).collect();
    let mut drawn: Vec<DVec2> = drawn.iter().map(|&p| plane.flat(p).0).collect();
    let (first, last) = (projected[0], projected[projected.len() - 1]);
    let straight = first.distance(drawn[0]) + last.distance(drawn[drawn.len() - 1]);
    let reversed = first.distance(drawn[drawn.len() - 1]) + last.distance(drawn[0]);
    if reversed < straight {
        drawn.reverse();
    }
    let along = cumulative_lengths(&projected);
    let total = along[along.len() - 1].max(f64::MIN_POSITIVE);
    let drawn_along = cumulative_lengths(&drawn);
    let drawn_total = drawn_along[drawn_along.len() - 1];
    rest.iter()
        .zip(&along)
        .map(|(&p, &s)| {
            let q = point_at(&drawn, &drawn_along, s / total * drawn_total);
            plane.lift(q, plane.flat(p).1)
        })
        .collect()
}

/// A curve's coarse shape in its editing plane: the spline with interior `knots` fitted to
/// the projection of the curve vertices at `rest`.
#[derive(Clone, Debug)]
pub struct CoarsePlaneCurve {
    plane: Plane,
    coarse: CoarseCurve,
    rest: Vec<DVec3>,
}

impl CoarsePlaneCurve {
    /// Fits the spline.
    ///
    /// Errors: [`VolumetricError::BadSpline`] for knots that are not increasing inside
    /// (0, 1), [`VolumetricError::CurveTooShort`], the fit's.
    pub fn new(
        rest: &[DVec3],
        plane: &Plane,
        knots: &[f64],
    ) -> Result<CoarsePlaneCurve, VolumetricError> {
        if !valid_knots(knots) {
            return Err(VolumetricError::BadSpline {
                controls: knots.len() + 4,
            });
        }
        if rest.len() < 2 {
            return Err(VolumetricError::CurveTooShort);
        }
        let projected: Vec<DVec2> = rest.iter().map(|&p| plane.flat(p).0).collect();
        Ok(CoarsePlaneCurve {
            plane: *plane,
            coarse: CoarseCurve::fit(&projected, knots)?,
            rest: rest.to_vec(),
        })
    }

    /// The spline's control points, on the plane.
    pub fn controls(&self) -> Vec<DVec3> {
        let controls = &self.coarse.spline().controls;
        controls.iter().map(|&c| self.plane.lift(c, 0.0)).collect()
    }

    /// Where each curve vertex goes when control point `k` moves by `shift` (its part along
    /// the plane counts): on the reshaped projection at its share of the arc length (as a
    /// sketched curve; the spline alone would bunch the vertices near a moved end and
    /// stretch the edges there many times over, and WIRE would scale the part with them),
    /// plus its offset from the plane.
    ///
    /// Errors: [`VolumetricError::BadSpline`] for a control point the spline lacks, the
    /// solve's.
    pub fn targets(&self, k: usize, shift: DVec3) -> Result<Vec<DVec3>, VolumetricError> {
        let mut controls = self.coarse.spline().controls.clone();
        let n = controls.len();
        let control = controls
            .get_mut(k)
            .ok_or(VolumetricError::BadSpline { controls: n })?;
        let (to, _) = self.plane.flat(self.plane.origin + shift);
        *control += to;
        let moved: Vec<DVec3> = (self.coarse.reshape(&controls)?.iter())
            .map(|&q| self.plane.lift(q, 0.0))
            .collect();
        Ok(curve_targets(&self.rest, &self.plane, &moved))
    }
}

/// WIRE's transform at each curve vertex from its rest position to `moved`: the turn of its
/// tangent. WIRE's scale (the ratio of the edges' lengths) is left at 1: a curve drawn
/// longer then stretches its part along itself instead of fattening it all round (with the
/// scale, a capsule's curve dragged 17% longer grew the capsule's volume by 48%).
pub fn wire_transforms(rest: &[DVec3], moved: &[DVec3]) -> Vec<Similarity> {
    let n = rest.len();
    let tangent =
        |x: &[DVec3], i: usize| (x[(i + 1).min(n - 1)] - x[i.saturating_sub(1)]).try_normalize();
    (0..n)
        .map(|i| match (tangent(rest, i), tangent(moved, i)) {
            (Some(t), Some(t_moved)) => Similarity {
                rotation: DQuat::from_rotation_arc(t, t_moved),
                scale: 1.0,
            },
            _ => Similarity::IDENTITY,
        })
        .collect()
}

/// A volumetric edit driven by one control curve, factored once; see the module docs.
#[derive(Debug)]
pub struct CurveEdit {
    edit: VolumetricEdit,
    /// The curve vertices' rest positions.
    rest: Vec<DVec3>,
    /// The α rows' targets: the edited curve's, then the held curves' rest positions.
    soft_targets: Vec<DVec3>,
    /// Per graph point: the index along the curve of its nearest curve vertex (`u32::MAX` where
    /// none is reached) and the strength there.
    nearest: Vec<(u32, f64)>,
    transforms: Vec<Similarity>,
    positions: Vec<DVec3>,
}

impl CurveEdit {
    /// The edit of `mesh` through `graph` by the curve `path`, with the vertices of other
    /// curves, `held`, pulled to where they are and the graph points for which `fixed`
    /// holds still.
    ///
    /// Errors: [`VolumetricError::CurveTooShort`], the solve's.
    pub fn new(
        mesh: &Mesh,
        graph: &VolumetricGraph,
        path: &[VertexId],
        held: &[VertexId],
        fixed: &[bool],
        falloff: Falloff,
    ) -> Result<CurveEdit, VolumetricError> {
        if path.len() < 2 {
            return Err(VolumetricError::CurveTooShort);
        }
        let mut on_curve = vec![false; graph.n_points()];
        for &v in path {
            on_curve[v.index()] = true;
        }
        let held: Vec<VertexId> = held
            .iter()
            .copied()
            .filter(|v| !std::mem::replace(&mut on_curve[v.index()], true))
            .collect();
        let seeds: Vec<u32> = path.iter().map(|v| v.0).collect();
        let reached = shortest_paths(
            graph.n_points(),
            &seeds,
            f64::INFINITY,
            |i| graph.edges_from(mesh, i),
            |_, _| false,
        );
        let fixed_seeds: Vec<u32> = (0..graph.n_points() as u32)
            .filter(|&i| fixed[i as usize])
            .chain(held.iter().map(|v| v.0))
            .collect();
        let to_fixed = (!fixed_seeds.is_empty()).then(|| graph.distances(mesh, &fixed_seeds));
        let rest: Vec<DVec3> = path.iter().map(|&v| mesh.position(v)).collect();
        let soft_targets = (rest.iter().copied())
            .chain(held.iter().map(|&v| mesh.position(v)))
            .collect();
        let reach: f64 = rest.windows(2).map(|w| w[0].distance(w[1])).sum();
        let nearest = (0..graph.n_points())
            .map(|i| {
                let d = reached.distance[i];
                let t = match &to_fixed {
                    Some(to_fixed) => to_fixed[i] / (to_fixed[i] + d),
                    None => 1.0 - d / reach,
                };
                let t = if t.is_finite() { t } else { 0.0 };
                (reached.seed[i], falloff.strength(t))
            })
            .collect();
        let constraints = Constraints {
            hard: fixed.to_vec(),
            soft: path.iter().chain(&held).copied().collect(),
        };
        let edit = VolumetricEdit::new(mesh, graph, &constraints, VolumetricParams::default())?;
        Ok(CurveEdit {
            rest,
            soft_targets,
            nearest,
            transforms: vec![Similarity::IDENTITY; graph.n_points()],
            positions: vec![DVec3::ZERO; graph.n_points()],
            edit,
        })
    }

    /// The curve's vertices' rest positions.
    pub fn rest(&self) -> &[DVec3] {
        &self.rest
    }

    /// The mesh's vertex positions with the curve moved to `targets` (one per curve
    /// vertex).
    ///
    /// Errors: [`VolumetricError::Solve`] for the wrong number of targets.
    pub fn deform(&mut self, targets: &[DVec3]) -> Result<&[DVec3], VolumetricError> {
        crate::solve::check_len("curve targets", self.rest.len(), targets.len())?;
        let at_vertex = wire_transforms(&self.rest, targets);
        for (t, &(seed, strength)) in self.transforms.iter_mut().zip(&self.nearest) {
            *t = at_vertex
                .get(seed as usize)
                .map_or(Similarity::IDENTITY, |s| s.part(strength));
        }
        self.soft_targets[..targets.len()].copy_from_slice(targets);
        self.edit.deform(
            &self.transforms,
            |_, rest| rest,
            &self.soft_targets,
            &mut self.positions,
        )?;
        Ok(&self.positions[..self.edit.n_mesh()])
    }
}

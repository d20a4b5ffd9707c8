//! A region found once for a pair of curves, moved by any transform in one pass.

use glam::{DVec2, DVec3};

use super::disc::Flattening;
use super::embed::{Embedded, embed};
use super::falloff::closeness;
use super::profile::cross_section;
use super::{
    Area, Handle, HandleFrame, HandleRail, Levels, Motion, Profile, ProfileChange, RegionError,
    RegionSketch,
};
use crate::curve::polyline::contains;
use crate::feature::{Placed, Sketch, place};
use crate::geometry::{Bvh, vertex_normals};
use crate::mesh::{Mesh, VertexId};

/// A boundary's last points this near (CSS px) its first close it: they are dropped.
const CLOSED_PX: f64 = 1.0;

/// A region of one mesh with its fall-off: see the [module docs](super).
#[derive(Clone, Debug)]
pub struct RegionEdit {
    /// The mesh the region was found on, the curves embedded in it when they could be:
    /// what every motion moves.
    mesh: Mesh,
    /// The edges split to embed the curves, in order, as `(a, b, new)`.
    splits: Vec<(VertexId, VertexId, VertexId)>,
    /// The vertices that may move, in increasing order.
    vertices: Vec<VertexId>,
    /// Each one's closeness to the reference curve, in [0, 1].
    closeness: Vec<f64>,
    /// Each one's weight: its closeness read through the levels.
    weights: Vec<f64>,
    /// Each one's nearest vertex of the reference path along edges, as an index into it.
    nearest: Vec<u32>,
    /// Each one where it was seen when the curves were drawn (CSS px), for areas' lassos.
    seen: Vec<DVec2>,
    /// The edge path under the reference curve: its embedded chain when it has one.
    reference: Vec<VertexId>,
    /// Where each path vertex sits along the reference curve (its nearest point of the
    /// rail), from 0 to 1.
    params: Vec<f64>,
    /// The reference curve on the surface: the sketch's samples cast onto it, smooth where
    /// the edge path zig-zags.
    rail: HandleRail,
}

impl RegionEdit {
    /// Places `sketch`'s curves on `mesh`, embeds them in a copy of it (see
    /// [`super::embed`]) and weighs the region found there with `levels`.
    ///
    /// Errors: the curves' refusals (see [`RegionError`]).
    pub fn new(mesh: &Mesh, sketch: &RegionSketch, levels: &Levels) -> Result<Self, RegionError> {
        Self::found(mesh, sketch, levels, true)
    }

    /// As [`RegionEdit::new`], the curves traced over `mesh`'s edges instead of embedded:
    /// for a model whose imported look (UVs, colours) belongs to its triangles as they are.
    ///
    /// Errors: as [`RegionEdit::new`].
    pub fn on_edges(
        mesh: &Mesh,
        sketch: &RegionSketch,
        levels: &Levels,
    ) -> Result<Self, RegionError> {
        Self::found(mesh, sketch, levels, false)
    }

    /// The region of `sketch` on `input`, with the curves embedded when `embeds` asks: the
    /// steps of a [`Finding`] taken at once.
    fn found(
        input: &Mesh,
        sketch: &RegionSketch,
        levels: &Levels,
        embeds: bool,
    ) -> Result<Self, RegionError> {
        Ok(RegionEdit::finding(input, sketch, embeds)?.weigh(input, levels))
    }

    /// The first step of finding the region of `sketch` on `mesh`: the curves placed (checked,
    /// the region grown, the rail cast). The curves are embedded (when `embeds` asks; see
    /// [`RegionEdit::on_edges`]) and the region weighed in the next steps, so that a page
    /// spreads the work over frames.
    ///
    /// The curves are placed before anything is embedded: a refused sketch costs no
    /// embedding, and no ray is cast along an embedded curve, where it would pass exactly
    /// through the new vertices and could slip between their triangles.
    ///
    /// Errors: the curves' refusals (see [`RegionError`]).
    pub fn finding(
        mesh: &Mesh,
        sketch: &RegionSketch,
        embeds: bool,
    ) -> Result<Finding, RegionError> {
        let boundary = closed_boundary(sketch)?;
        let normals = vertex_normals(mesh);
        let bvh = Bvh::new(mesh);
        let placed = place(
            mesh,
            &bvh,
            &normals,
            &Sketch {
                camera: sketch.camera,
                viewport: sketch.viewport,
                points: sketch.reference.clone(),
                region: Some(boundary.clone()),
            },
        )?;
        let rail = cast_rail(mesh, &bvh, &normals, sketch, &placed.points, &placed.path);
        Ok(Finding {
            sketch: sketch.clone(),
            boundary,
            embeds,
            placed,
            rail,
            embedded: None,
        })
    }

    /// The mesh the region was found on: the input with the curves embedded    /// The mesh the region was found on: the input with the curves embedded (new vertices
    /// after the input's, every input vertex where it was). Every motion moves this mesh.
    pub fn mesh(&self) -> &Mesh {
        &self.mesh
    }

    /// The edges split to embed the curves, in order: `(a, b, new)` put `new` between `a`
    /// and `b`, so a control curve along `a`–`b` gets `new` too.
    pub fn splits(&self) -> &[(VertexId, VertexId, VertexId)] {
        &self.splits
    }

    /// The vertices that may move, in increasing order.
    pub fn vertices(&self) -> &[VertexId] {
        &self.vertices
    }

    /// Each region vertex's weight, in the order of [`RegionEdit::vertices`]: 1 moves fully,
    /// 0 stays.
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The edge path under the reference curve.
    pub fn reference(&self) -> &[VertexId] {
        &self.reference
    }

    /// Where each vertex of [`RegionEdit::reference`] sits along it by arclength, from 0 to 1.
    pub fn reference_params(&self) -> &[f64] {
        &self.params
    }

    /// The reference curve on the surface the edit was found on, with its frames: where
    /// handles sit and profiles are cut.
    pub fn rail(&self) -> &HandleRail {
        &self.rail
    }

    /// The region's cross-section across the reference curve at `at` (0 its first end, 1 its
    /// last), on [`RegionEdit::mesh`]; see [`super::profile`].
    ///
    /// Errors: [`RegionError::NoProfile`].
    pub fn profile(&self, at: f64) -> Result<Profile, RegionError> {
        self.cross_section_in(&self.mesh, self.rail.frame_at(at.clamp(0.0, 1.0)))
    }

    /// The region's cross-section in the plane of `frame` (its first axis the plane's
    /// normal), on `mesh` with the region's vertices: after an edit moved them, in the
    /// plane the profile was drawn in.
    ///
    /// Errors: [`RegionError::NoProfile`].
    pub fn cross_section_in(
        &self,
        mesh: &Mesh,
        frame: HandleFrame,
    ) -> Result<Profile, RegionError> {
        let mut weight_of = vec![f64::NAN; mesh.n_vertices()];
        for (v, &w) in self.vertices.iter().zip(&self.weights) {
            weight_of[v.index()] = w;
        }
        cross_section(mesh, &weight_of, frame)
    }

    /// Every vertex of [`RegionEdit::mesh`] with the cross-section at `at` re-sketched as
    /// `stroke` (in the profile's plane) and the change swept along the curve (see
    /// [`super::profile`]).
    ///
    /// Errors: [`RegionError::NoProfile`], [`RegionError::BadProfileStroke`].
    pub fn profile_applied(&self, at: f64, stroke: &[DVec2]) -> Result<Vec<DVec3>, RegionError> {
        let mesh = &self.mesh;
        let change = ProfileChange::new(&self.profile(at)?, stroke)?;
        let mut out = mesh.positions().to_vec();
        for (&v, &w) in self.vertices.iter().zip(&self.weights) {
            // Each vertex in the frame of its nearest point of the curve.
            let p = mesh.position(v);
            let frame = self.rail.frame_at(self.rail.nearest_param(p));
            let [_, up, across] = frame.axes;
            let Some((rise, weight_there)) = change.rise_at((p - frame.origin).dot(across)) else {
                continue;
            };
            let share = if weight_there > 1e-9 {
                (w / weight_there).min(1.0)
            } else {
                0.0
            };
            out[v.index()] = p + up * (rise * share);
        }
        Ok(out)
    }

    /// The motion of `handles` on the reference curve (see [`Motion`]).
    ///
    /// Errors: [`RegionError::BadHandles`], or a handle's transform refused as
    /// [`super::checked_transform`] refuses one.
    pub fn motion(&self, handles: &[Handle]) -> Result<Motion, RegionError> {
        Motion::blended(handles, &self.params)
    }

    /// Each region vertex's place in the unit disc, in the order of
    /// [`RegionEdit::vertices`]: the region laid flat for the fall-off panel (see
    /// [`super::disc`]). One sparse solve; found on demand, not with the region.
    ///
    /// Errors: [`RegionError::NotADisc`].
    pub fn disc(&self) -> Result<Vec<DVec2>, RegionError> {
        self.flattening()?.finish()
    }

    /// The first half of [`RegionEdit::disc`]: the region's rim on the circle and the
    /// system for the rest analysed, to be solved by [`Flattening::finish`].
    ///
    /// Errors: [`RegionError::NotADisc`].
    pub fn flattening(&self) -> Result<Flattening, RegionError> {
        let mut region = vec![false; self.mesh.n_vertices()];
        for v in &self.vertices {
            region[v.index()] = true;
        }
        super::disc::flattening(&self.mesh, &region, &self.vertices)
    }

    /// Each region vertex's closeness to the reference curve (1 on it, 0 at the boundary),
    /// in the order of [`RegionEdit::vertices`].
    pub fn closeness(&self) -> &[f64] {
        &self.closeness
    }

    /// Every vertex's weight, 0 outside the region: what the fall-off overlay shows.
    pub fn weight_per_vertex(&self, n_vertices: usize) -> Vec<f64> {
        let mut all = vec![0.0; n_vertices];
        for (v, &w) in self.vertices.iter().zip(&self.weights) {
            all[v.index()] = w;
        }
        all
    }

    /// Weighs the region again with other levels (a level handle dragged): the region and
    /// the closeness stay.
    pub fn set_levels(&mut self, levels: &Levels) {
        self.set_falloff(levels, &[]);
    }

    /// Weighs the region again with `levels`, and within each of `areas` (a later one over
    /// an earlier one where they overlap) with its own levels.
    pub fn set_falloff(&mut self, levels: &Levels, areas: &[Area]) {
        let moved = self.weights.iter_mut().zip(&self.closeness).zip(&self.seen);
        for ((w, &s), &p) in moved {
            let inside = areas.iter().rev().find(|a| contains(&a.lasso, p));
            *w = inside.map_or(levels, |a| &a.levels).weight(s);
        }
    }

    /// Moves each region vertex of `base` to `(w ⊙ T) p` in `out`, `T` the motion's
    /// transform at its nearest point of the reference curve (`out` the same length; the
    /// vertices outside the region are not written). Allocates nothing: a drag frame.
    pub fn apply_into(&self, motion: &Motion, base: &[DVec3], out: &mut [DVec3]) {
        let moved = self.vertices.iter().zip(&self.weights).zip(&self.nearest);
        for ((v, &w), &k) in moved {
            out[v.index()] = motion.at(k).apply(w, base[v.index()]);
        }
    }

    /// Every vertex of [`RegionEdit::mesh`] with the region moved by `motion`.
    pub fn applied(&self, motion: &Motion) -> Vec<DVec3> {
        let mut out = self.mesh.positions().to_vec();
        self.apply_into(motion, self.mesh.positions(), &mut out);
        out
    }
}

/// `sketch`'s boundary as a loop: a loop drawn back to its start may end on it or just short
/// of it, and those last points go.
///
/// Errors: [`RegionError::BoundaryCrosses`] for a point that is not finite.
/// A region being found, one step at a time: the curves placed (see
/// [`RegionEdit::finding`]), then embedded ([`Finding::embed`]), then the region weighed
/// ([`Finding::weigh`]). Each step takes the mesh the first was given.
#[derive(Debug)]
pub struct Finding {
    sketch: RegionSketch,
    /// The boundary as a loop, its repeated last points dropped.
    boundary: Vec<DVec2>,
    embeds: bool,
    placed: Placed,
    rail: HandleRail,
    embedded: Option<Embedded>,
}

impl Finding {
    /// Whether the curves are embedded (the next step weighs the region).
    pub fn is_embedded(&self) -> bool {
        self.embedded.is_some()
    }

    /// The second step: the curves embedded in a copy of `mesh` where each can be (see
    /// [`super::embed`]), or `mesh` as it is when they are traced over its edges.
    pub fn embed(&mut self, mesh: &Mesh) {
        if self.embedded.is_none() {
            self.embedded = Some(if self.embeds {
                embed(mesh, &self.sketch, &self.boundary)
            } else {
                Embedded::unchanged(mesh)
            });
        }
    }

    /// The last step: the region weighed with `levels` on the embedded mesh (embedding
    /// first if that step was not taken). The embedding adds only the curves' own vertices,
    /// so the region carries over: `mesh`'s vertices as placed, the reference chain in, the
    /// boundary chain out (its vertices stay, and the fall-off reaches 0 on the drawn loop).
    pub fn weigh(mut self, mesh: &Mesh, levels: &Levels) -> RegionEdit {
        self.embed(mesh);
        let Finding {
            sketch,
            placed,
            rail,
            embedded,
            ..
        } = self;
        let Embedded {
            mesh,
            reference,
            boundary: boundary_pieces,
            splits,
        } = embedded.expect("embedded above");
        let mut region = placed.region;
        region.resize(mesh.n_vertices(), false);
        for v in boundary_pieces.iter().flatten() {
            region[v.index()] = false;
        }
        let path = match reference {
            Some(chain) => {
                for v in &chain {
                    region[v.index()] = true;
                }
                chain
            }
            None => placed.path,
        };
        let vertices: Vec<VertexId> = mesh.vertices().filter(|v| region[v.index()]).collect();
        let found = closeness(&mesh, &region, &vertices, &path);
        let weights = found.closeness.iter().map(|&s| levels.weight(s)).collect();
        let params = (path.iter())
            .map(|&v| rail.nearest_param(mesh.position(v)))
            .collect();
        let seen = vertices
            .iter()
            .map(|&v| {
                (sketch
                    .camera
                    .screen_from_world(mesh.position(v), sketch.viewport))
                .map_or(DVec2::NAN, |p| p.truncate())
            })
            .collect();
        RegionEdit {
            mesh,
            splits,
            vertices,
            closeness: found.closeness,
            weights,
            nearest: found.nearest,
            seen,
            params,
            rail,
            reference: path,
        }
    }
}

fn closed_boundary(sketch: &RegionSketch) -> Result<Vec<DVec2>, RegionError> {
    let mut boundary = sketch.boundary.clone();
    while boundary.len() > 3 && boundary[0].distance(boundary[boundary.len() - 1]) < CLOSED_PX {
        boundary.pop();
    }
    if boundary.iter().any(|p| !p.is_finite()) {
        return Err(RegionError::BoundaryCrosses);
    }
    Ok(boundary)
}

/// The reference curve on the surface: each of the sketch's resampled `points` (screen px)
/// cast onto `mesh` along its view ray, with the normal interpolated there; a sample that
/// misses (at a silhouette) is left out, and where fewer than two hit, the edge `path`
/// stands in.
fn cast_rail(
    mesh: &Mesh,
    bvh: &Bvh,
    normals: &[DVec3],
    sketch: &RegionSketch,
    points: &[DVec2],
    path: &[VertexId],
) -> HandleRail {
    let (mut at, mut up) = (Vec::new(), Vec::new());
    for &p in points {
        let (origin, dir) = sketch.camera.ray_in_world(p, sketch.viewport);
        let Some(hit) = bvh.raycast(mesh, origin, dir) else {
            continue;
        };
        let corners = mesh.face_vertices(hit.face);
        let b = hit.barycentric;
        let normal = normals[corners[0].index()] * b.x
            + normals[corners[1].index()] * b.y
            + normals[corners[2].index()] * b.z;
        at.push(origin + dir * hit.distance);
        up.push(normal.normalize_or(DVec3::Z));
    }
    if at.len() < 2 {
        at = path.iter().map(|&v| mesh.position(v)).collect();
        up = path.iter().map(|&v| normals[v.index()]).collect();
    }
    HandleRail::new(at, up)
}

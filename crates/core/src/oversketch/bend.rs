//! Bending a mesh so that a handle lands on a stroke: targets, ROI and the edit, shared by
//! the automatic over-sketch ([`super::oversketch`]) and the manual one
//! ([`super::oversketch_manual`]).
//!
//! 1. Targets: each handle point goes to the stroke point at the same relative arclength
//!    ([`map_to_stroke`]) and is unprojected at its own depth, onto the plane through its
//!    world position facing the camera. A silhouette piece is blended back towards where it
//!    is at the ends ([`blend_weight`], a smoothstep; SEED Eq. 6); unlike SEED's fixed
//!    [`BLEND_WIDTH`], each end blends over `BLEND_WIDTH × min(1, gap / BLEND_GAP_PX)` of the
//!    handle, at least [`MIN_BLEND_PX`], `gap` being how far the stroke's end lies from the
//!    handle's, so a stroke that starts on the outline is followed almost from its start.
//!    Blending starts from the handle point's *unsmoothed* projection (its world position on
//!    screen): the middle lands on the stroke exactly and the ends stay where they were.
//! 2. The ROI grown within spheres of radius [`ROI_FACTOR`] times the handle displacements,
//!    at least [`MIN_ROI_EDGES`] edges, never [`ROI_REACH_PX`] past the stroke
//!    ([`roi_from_displacements`]), or the part the handle lies on ([`part_roi`]).
//! 3. Constraints: for a silhouette, not the crossing points themselves but the band of
//!    vertices around them ([`band_handles`]), translated with the nearby handle points, so
//!    the contour generator moves with the band instead of sliding across the bent surface.
//!    Pinning only the crossing points (as SilSketch pins its handle vertices) puts them on
//!    the stroke, but the new outline runs elsewhere: on a bumpy torus, 2.35 px off the
//!    stroke by the smoothed silhouette and 3.3 px by the rendered outline (edge
//!    silhouettes), even after matching and pinning the bent outline a second time; with
//!    the band, 1.83 px by the rendered outline. A curve on the surface is pinned as the
//!    manual handle resolved it (its embedded path's vertices, or points inside triangles).
//! 4. A detail-preserving edit with rotations ([`EditParams::default`]), exact or soft.
//! 5. With exact handles on a silhouette, the outline as rendered is snapped onto the stroke
//!    (see `Snap`): its vertices along the handle were pinned with the band, and those on the
//!    bent outline get targets on the stroke for one more solve with the same factorization.

use glam::{DVec2, DVec3};

use super::{
    BLEND_WIDTH, OversketchError, OversketchRoi, blend_weight, map_to_stroke, part_roi,
    roi_from_displacements,
};
use crate::camera::Camera;
use crate::curve::polyline::{
    closest_point, cumulative_lengths, distance_to_polyline, length, point_at, relative_arclengths,
};
use crate::deform::{DeformError, EditParams, HandleFit, HandlePoint, LaplacianEdit};
use crate::geometry::Bvh;
use crate::mesh::{Mesh, VertexId};
use crate::silhouette::{SilhouettePoint, outline_edges_touching};

/// The ROI grows within spheres of this many times each handle displacement: twice the
/// thesis's radius ([`super::ROI_RADIUS_FACTOR`]). The band of `band_handles` moves
/// rigidly, about two edges wide, so with the thesis's radius the whole falloff from the
/// handle's motion to rest is squeezed into a few edges beyond it, and the bumps there
/// change more than under a naive falloff (measured on the bumpy torus: relative Laplacian
/// change 2.30 against 2.11 naive at radius 1, 1.28 at 1.5, 0.80 at 2).
pub const ROI_FACTOR: f64 = 2.0;

/// The ROI reaches at least this many mean edge lengths from the handle. Spheres as large
/// as the displacements alone hold hardly more than the band on a coarse scan pushed a few
/// pixels (spot's back pushed in 8 px: 113 vertices, all of them band), so nothing is free
/// to bend, and edges just outside the ROI stay sticking out of the new outline (5 px).
pub const MIN_ROI_EDGES: f64 = 3.0;

/// A handle on the mesh as the user sees it: what an over-sketch moves onto its stroke.
pub(super) struct HandleCurve {
    /// The constrained points, in order along the handle.
    pub points: Vec<HandlePoint>,
    /// Each point's position on the mesh.
    pub worlds: Vec<DVec3>,
    /// Where each point is drawn on screen (CSS px); smoothed for a silhouette.
    pub screen: Vec<DVec2>,
    /// A silhouette piece blends into the untouched outline at its ends and moves with the
    /// band around it ([`band_handles`]); a curve on the surface goes onto the stroke whole.
    pub is_silhouette: bool,
}

impl HandleCurve {
    /// The handle of silhouette points, each inside its edge.
    pub(super) fn of_silhouette(points: &[SilhouettePoint]) -> HandleCurve {
        HandleCurve {
            points: points
                .iter()
                .map(|p| HandlePoint::on_edge(p.edge[0], p.edge[1], p.t))
                .collect(),
            worlds: points.iter().map(|p| p.world).collect(),
            screen: points.iter().map(|p| p.screen).collect(),
            is_silhouette: true,
        }
    }

    /// The same handle run the other way.
    pub(super) fn reversed(mut self) -> HandleCurve {
        self.points.reverse();
        self.worlds.reverse();
        self.screen.reverse();
        self
    }
}

/// How an over-sketch bends: the handles' fit and the region that may move.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BendOptions {
    /// Exact or soft handles.
    pub fit: HandleFit,
    /// Near the handle or its part.
    pub roi: OversketchRoi,
}

impl BendOptions {
    /// Exact handles, the region near the handle: [`super::oversketch`]'s choice.
    pub const EXACT: BendOptions = BendOptions {
        fit: HandleFit::Exact,
        roi: OversketchRoi::NearHandle,
    };
}

/// Bends `mesh` so that `handle` lands on `stroke` (simplified, screen CSS px): the new
/// positions and the ROI (one flag per vertex).
///
/// Errors: [`OversketchError::LowConfidence`] when the handle runs [`ROI_REACH_PX`] or
/// farther from the stroke, [`OversketchError::NoPart`] when a part ROI is asked for and
/// none stands out, [`OversketchError::Deform`] when the edit fails.
pub(super) fn bend(
    mesh: &Mesh,
    camera: &Camera,
    viewport: DVec2,
    handle: &HandleCurve,
    stroke: &[DVec2],
    options: BendOptions,
) -> Result<(Vec<DVec3>, Vec<bool>), OversketchError> {
    if handle
        .screen
        .iter()
        .any(|&p| distance_to_polyline(p, stroke) >= ROI_REACH_PX)
    {
        return Err(OversketchError::LowConfidence);
    }
    let targets = handle_targets(camera, viewport, handle, stroke);
    let least_reach = MIN_ROI_EDGES * mesh.mean_edge_length() / ROI_FACTOR;
    let displaced: Vec<(VertexId, f64)> = handle
        .points
        .iter()
        .zip(&targets)
        .flat_map(|(point, target)| {
            let displacement = target.distance(point.position(mesh.positions()));
            point
                .vertices()
                .map(move |v| (v, displacement.max(least_reach)))
        })
        .collect();
    let roi = match options.roi {
        OversketchRoi::NearHandle => {
            let mut roi = roi_from_displacements(mesh, &displaced, ROI_FACTOR);
            keep_near(mesh, camera, viewport, stroke, &mut roi);
            roi
        }
        OversketchRoi::Part => {
            let vertices: Vec<VertexId> = displaced.iter().map(|&(v, _)| v).collect();
            part_roi(mesh, &vertices).ok_or(OversketchError::NoPart)?
        }
    };
    // Only an exact silhouette handle snaps the outline, which needs a BVH.
    let bvh = (handle.is_silhouette && options.fit == HandleFit::Exact).then(|| Bvh::new(mesh));
    let (points, targets) = if let Some(bvh) = &bvh {
        let (points, band) = band_handles(mesh, &roi, &handle.points, &targets);
        let outline = outline_vertices(mesh, bvh, camera, viewport, &roi);
        let motions = HandleMotions {
            points: &handle.points,
            targets: &targets,
        };
        // Only the outline along the handle: elsewhere (the far side of a bent horn) the
        // outline runs over other vertices once bent.
        let along = outline
            .iter()
            .filter(|&&(_, screen, _)| {
                distance_to_polyline(screen, &handle.screen) <= SNAP_REACH_PX
            })
            .map(|&(v, _, _)| v);
        motions.with_outline(mesh, along, points, band)
    } else if handle.is_silhouette {
        band_handles(mesh, &roi, &handle.points, &targets)
    } else {
        (handle.points.clone(), targets)
    };
    let params = EditParams {
        fit: options.fit,
        ..EditParams::default()
    };
    let mut edit = LaplacianEdit::new(mesh, &roi, &points, params)?;
    let mut positions = vec![DVec3::ZERO; mesh.n_vertices()];
    edit.deform(&targets, &mut positions)
        .map_err(DeformError::from)?;
    if let Some(bvh) = bvh {
        let mut snap = Snap {
            bent: mesh.clone(),
            bvh,
            roi: &roi,
            widths: blend_widths(camera, viewport, handle, stroke),
            handle_of: points
                .iter()
                .enumerate()
                .map(|(k, point)| (point.vertices()[0], k))
                .collect(),
        };
        let mut targets = targets;
        for _ in 0..SNAP_PASSES {
            snap.retarget(camera, viewport, stroke, &positions, &mut targets);
            edit.deform(&targets, &mut positions)
                .map_err(DeformError::from)?;
        }
    }
    Ok((positions, roi))
}

/// A near-handle ROI never reaches this far (px on screen) from the stroke, and a handle
/// that does is refused. A stroke drawn over two pieces of outline at once (both ears of the
/// bunny, whose outline jumps between them) matched a handle whose displacements were large,
/// and their spheres moved the whole face.
pub const ROI_REACH_PX: f64 = 150.0;

/// Takes out of `roi` the vertices drawn [`ROI_REACH_PX`] or farther from `stroke`.
fn keep_near(mesh: &Mesh, camera: &Camera, viewport: DVec2, stroke: &[DVec2], roi: &mut [bool]) {
    for v in mesh.vertices() {
        if roi[v.index()] {
            roi[v.index()] = camera
                .screen_from_world(mesh.position(v), viewport)
                .is_some_and(|p| distance_to_polyline(p.truncate(), stroke) < ROI_REACH_PX);
        }
    }
}

/// Passes of [`snap_outline`] after the bend.
const SNAP_PASSES: usize = 1;

/// Outline vertices farther than this from the stroke (px) are other parts of the outline
/// and are left to the Laplacian.
const SNAP_REACH_PX: f64 = 8.0;

/// Puts the outline as rendered onto the stroke. The bend moves the smooth silhouette's
/// crossing points and the band around them; the rendered outline is made of whole mesh
/// edges whose ends can sit several pixels off the smooth silhouette on a coarse scan
/// (spot's back: up to 5 px), and the band carries that offset along. The band's vertices
/// that are on the bent mesh's visible edge silhouettes near the stroke are retargeted onto
/// it (blended as the targets are at the stroke's ends), and the edit is solved again with
/// the same factorization: a back-substitution, not a new edit.
struct Snap<'a> {
    /// The mesh with the bent positions of the last solve.
    bent: Mesh,
    /// Its BVH, refitted to them.
    bvh: Bvh,
    /// The region that may move.
    roi: &'a [bool],
    /// The blend widths of the handle's ends.
    widths: [f64; 2],
    /// The handle index of each band vertex.
    handle_of: std::collections::BTreeMap<VertexId, usize>,
}

impl Snap<'_> {
    /// New targets for the band vertices on the outline of `positions`.
    fn retarget(
        &mut self,
        camera: &Camera,
        viewport: DVec2,
        stroke: &[DVec2],
        positions: &[DVec3],
        targets: &mut [DVec3],
    ) {
        self.bent.positions_mut().copy_from_slice(positions);
        self.bvh.refit(&self.bent);
        let cumulative = cumulative_lengths(stroke);
        let total = cumulative[cumulative.len() - 1];
        let forward = camera.forward();
        let outline = outline_vertices(&self.bent, &self.bvh, camera, viewport, self.roi);
        for (v, screen, spacing) in outline {
            let Some(&k) = self.handle_of.get(&v) else {
                continue;
            };
            let closest = closest_point(stroke, &cumulative, screen);
            if closest.distance > SNAP_REACH_PX {
                continue;
            }
            // Outline edges are chords of the stroke: a vertex on the stroke leaves each
            // chord's middle inside the bend by its sagitta. Moving the vertex outwards by
            // half of it halves the worst gap. `bulge` is the sagitta of a chord twice as
            // long, four times an edge's, so half an edge's sagitta is an eighth of it.
            let s = closest.arclength;
            let chord_middle = 0.5
                * (point_at(stroke, &cumulative, s - spacing)
                    + point_at(stroke, &cumulative, s + spacing));
            let on_stroke = closest.point + (closest.point - chord_middle) / 8.0;
            let target = screen.lerp(on_stroke, blend_at(s / total, self.widths));
            targets[k] =
                unproject_at_depth(camera, viewport, target, positions[v.index()], forward);
        }
    }
}

/// The vertices of `roi` on the visible outline of `mesh` (`bvh` fitted to it), each with
/// where it is drawn and the mean screen length of its outline edges, in vertex order.
fn outline_vertices(
    mesh: &Mesh,
    bvh: &Bvh,
    camera: &Camera,
    viewport: DVec2,
    roi: &[bool],
) -> Vec<(VertexId, DVec2, f64)> {
    let mut ends: std::collections::BTreeMap<VertexId, (DVec2, f64, f64)> = Default::default();
    let edges = outline_edges_touching(mesh, bvh, camera, viewport, |v| roi[v.index()]);
    for edge in edges {
        let length = edge.screen[0].distance(edge.screen[1]);
        for (v, screen) in edge.vertices.into_iter().zip(edge.screen) {
            if roi[v.index()] {
                let entry = ends.entry(v).or_insert((screen, 0.0, 0.0));
                entry.1 += length;
                entry.2 += 1.0;
            }
        }
    }
    ends.into_iter()
        .map(|(v, (screen, sum, count))| (v, screen, sum / count))
        .collect()
}

/// The handle points of a silhouette and their targets, before the band spreads them.
struct HandleMotions<'a> {
    points: &'a [HandlePoint],
    targets: &'a [DVec3],
}

impl HandleMotions<'_> {
    /// `points` and `targets` (the band's) with the `outline` vertices that are not handles
    /// yet added, each moved as the handle point nearest it, so that the snap can later put
    /// them onto the stroke without a new factorization.
    fn with_outline(
        &self,
        mesh: &Mesh,
        outline: impl Iterator<Item = VertexId>,
        mut points: Vec<HandlePoint>,
        mut targets: Vec<DVec3>,
    ) -> (Vec<HandlePoint>, Vec<DVec3>) {
        let taken: std::collections::BTreeSet<VertexId> =
            points.iter().map(|p| p.vertices()[0]).collect();
        let worlds: Vec<DVec3> = self
            .points
            .iter()
            .map(|p| p.position(mesh.positions()))
            .collect();
        for v in outline.filter(|v| !taken.contains(v)) {
            let p = mesh.position(v);
            let nearest = (0..worlds.len())
                .min_by(|&a, &b| {
                    worlds[a]
                        .distance_squared(p)
                        .total_cmp(&worlds[b].distance_squared(p))
                })
                .unwrap_or(0);
            points.push(HandlePoint::vertex(v));
            targets.push(p + self.targets[nearest] - worlds[nearest]);
        }
        (points, targets)
    }
}

/// Each handle point's target: the stroke point at the same relative arclength, blended at
/// the ends for a silhouette ([`outline_targets`]), at the handle point's depth.
fn handle_targets(
    camera: &Camera,
    viewport: DVec2,
    handle: &HandleCurve,
    stroke: &[DVec2],
) -> Vec<DVec3> {
    if handle.is_silhouette {
        return outline_targets(camera, viewport, &handle.worlds, &handle.screen, stroke);
    }
    let forward = camera.forward();
    map_to_stroke(&handle.screen, stroke)
        .into_iter()
        .zip(&handle.worlds)
        .map(|(target, &world)| unproject_at_depth(camera, viewport, target, world, forward))
        .collect()
}

/// Where a piece of outline goes when `stroke` (screen CSS px) redraws it: each point
/// (`worlds`, drawn at `screen`, in the stroke's direction) to the stroke point at the same
/// relative arclength, blended into where it is now at the ends ([`blend_weight`], over
/// [`end_widths`]), on the plane through it facing the camera.
pub fn outline_targets(
    camera: &Camera,
    viewport: DVec2,
    worlds: &[DVec3],
    screen: &[DVec2],
    stroke: &[DVec2],
) -> Vec<DVec3> {
    let mapped = map_to_stroke(screen, stroke);
    let projected = projected_points(camera, viewport, worlds, screen);
    let widths = end_widths(&projected, &mapped);
    let forward = camera.forward();
    relative_arclengths(screen)
        .into_iter()
        .enumerate()
        .map(|(k, r)| {
            let target = projected[k].lerp(mapped[k], blend_at(r, widths));
            unproject_at_depth(camera, viewport, target, worlds[k], forward)
        })
        .collect()
}

/// Where each of `worlds` is drawn now: unsmoothed, unlike a silhouette point's `screen`
/// (used where a point does not project).
fn projected_points(
    camera: &Camera,
    viewport: DVec2,
    worlds: &[DVec3],
    screen: &[DVec2],
) -> Vec<DVec2> {
    worlds
        .iter()
        .zip(screen)
        .map(|(&world, &screen)| {
            camera
                .screen_from_world(world, viewport)
                .map_or(screen, |p| p.truncate())
        })
        .collect()
}

/// Vertex handles for the band around the handle points: the ends of each point's edge and
/// their neighbours, each moved by the distance-weighted mean of the motions of the handle
/// points whose edges it touches. Inside the band the surface only translates, so the vertex
/// normals at the edges' ends, and with them the contour's crossings, keep their places
/// relative to the moved points: the outline lands on the stroke instead of sliding off it
/// as it does when only the crossing points are pinned. Vertices outside `roi` stay.
fn band_handles(
    mesh: &Mesh,
    roi: &[bool],
    points: &[HandlePoint],
    targets: &[DVec3],
) -> (Vec<HandlePoint>, Vec<DVec3>) {
    let mut sums: std::collections::BTreeMap<VertexId, (DVec3, f64)> = Default::default();
    for (point, target) in points.iter().zip(targets) {
        let world = point.position(mesh.positions());
        let motion = *target - world;
        let [a, b, _] = point.vertices();
        let band = [a, b]
            .into_iter()
            .chain(mesh.vertex_neighbors(a))
            .chain(mesh.vertex_neighbors(b));
        for v in band.filter(|v| roi[v.index()]) {
            let d = mesh.position(v).distance(world);
            let weight = 1.0 / (d * d).max(1e-24);
            let entry = sums.entry(v).or_insert((DVec3::ZERO, 0.0));
            entry.0 += weight * motion;
            entry.1 += weight;
        }
    }
    sums.into_iter()
        .map(|(v, (sum, weight))| (HandlePoint::vertex(v), mesh.position(v) + sum / weight))
        .unzip()
}

/// A gap (px) between a handle end and the stroke end at least this wide blends over the
/// full [`BLEND_WIDTH`]; narrower gaps blend over proportionally less.
pub const BLEND_GAP_PX: f64 = 10.0;

/// Each end blends over at least this many px of the handle (at most [`BLEND_WIDTH`] of
/// it): a stroke that starts right on the outline but leaves it at an angle would otherwise
/// make a corner there.
pub const MIN_BLEND_PX: f64 = 20.0;

/// The blend widths (fractions of the handle's arclength) at its two ends:
/// `BLEND_WIDTH × min(1, gap / BLEND_GAP_PX)`, at least [`MIN_BLEND_PX`] and at most
/// [`BLEND_WIDTH`], with `gap` the distance between where the handle's end is drawn
/// (`projected`) and its target on the stroke (`mapped`): a stroke that starts on the
/// outline is followed almost from its start.
fn end_widths(projected: &[DVec2], mapped: &[DVec2]) -> [f64; 2] {
    let least = MIN_BLEND_PX / length(projected).max(f64::MIN_POSITIVE);
    let gaps = [
        projected[0].distance(mapped[0]),
        projected[projected.len() - 1].distance(mapped[mapped.len() - 1]),
    ];
    gaps.map(|gap| {
        (BLEND_WIDTH * (gap / BLEND_GAP_PX).min(1.0))
            .max(least)
            .min(BLEND_WIDTH)
    })
}

/// [`end_widths`] of a silhouette handle and its stroke.
fn blend_widths(
    camera: &Camera,
    viewport: DVec2,
    handle: &HandleCurve,
    stroke: &[DVec2],
) -> [f64; 2] {
    let mapped = map_to_stroke(&handle.screen, stroke);
    let projected = projected_points(camera, viewport, &handle.worlds, &handle.screen);
    end_widths(&projected, &mapped)
}

/// SEED's blend weight at relative arclength `r`, with the blend `widths` at the two ends.
fn blend_at(r: f64, [start_width, end_width]: [f64; 2]) -> f64 {
    if r < 0.5 {
        blend_weight(r, start_width)
    } else {
        blend_weight(r, end_width)
    }
}

/// The point on the picking ray through `screen` at the depth of `world`: on the plane
/// through `world` facing the camera (`forward` its normal). `world` when the ray runs
/// parallel to that plane.
fn unproject_at_depth(
    camera: &Camera,
    viewport: DVec2,
    screen: DVec2,
    world: DVec3,
    forward: DVec3,
) -> DVec3 {
    let (origin, dir) = camera.ray_in_world(screen, viewport);
    let denominator = dir.dot(forward);
    if denominator.abs() < 1e-12 {
        return world;
    }
    origin + dir * ((world - origin).dot(forward) / denominator)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unprojection_keeps_depth_and_lands_on_the_pixel() {
        let camera = Camera::default();
        let viewport = DVec2::new(800.0, 600.0);
        let world = DVec3::new(0.3, -0.2, 0.4);
        let screen = DVec2::new(520.0, 260.0);
        let p = unproject_at_depth(&camera, viewport, screen, world, camera.forward());
        let projected = camera.screen_from_world(p, viewport).unwrap();
        let depth = camera.screen_from_world(world, viewport).unwrap().z;
        assert!((projected.truncate() - screen).length() < 1e-9);
        assert!((projected.z - depth).abs() < 1e-12);
    }

    #[test]
    fn blend_weights_vanish_at_the_ends_only() {
        let handle: Vec<DVec2> = (0..11).map(|i| DVec2::new(20.0 * i as f64, 0.0)).collect();
        // A handle 200 px long whose targets lie `gaps` above its ends.
        let blend_weights = |handle: &[DVec2], gaps: [f64; 2]| -> Vec<f64> {
            let mut mapped = handle.to_vec();
            mapped[0].y += gaps[0];
            mapped[10].y += gaps[1];
            let widths = end_widths(handle, &mapped);
            relative_arclengths(handle)
                .into_iter()
                .map(|r| blend_at(r, widths))
                .collect()
        };
        let w = blend_weights(&handle, [BLEND_GAP_PX, 2.0 * BLEND_GAP_PX]);
        assert_eq!(w[0], 0.0);
        assert_eq!(w[10], 0.0);
        assert_eq!(w[5], 1.0);
        assert!((w[1] - 0.5).abs() < 1e-12);
        // Half the gap, half the blend; no gap, the least blend: MIN_BLEND_PX, one point.
        let w = blend_weights(&handle, [0.5 * BLEND_GAP_PX, 0.0]);
        assert_eq!(w[0], 0.0);
        assert_eq!(w[1], 1.0);
        assert_eq!(w[10], 0.0);
        assert_eq!(w[9], 1.0);
    }
}

//! Bending a mesh so that a handle lands on a stroke: targets, ROI and the edit, shared by
//! the automatic over-sketch ([`super::oversketch`]) and the manual one
//! ([`super::oversketch_manual`]).
//!
//! 1. Targets: each handle point goes to the stroke point at the same relative arclength
//!    ([`map_to_stroke`]) and is unprojected at its own depth, onto the plane through its
//!    world position facing the camera. A silhouette piece is blended back towards where it
//!    is at the ends ([`blend_weight`], SEED Eq. 6); unlike SEED's fixed [`BLEND_WIDTH`],
//!    each end blends over `BLEND_WIDTH × min(1, gap / BLEND_GAP_PX)` of the handle, `gap`
//!    being how far the stroke's end lies from the handle's, so a stroke that starts on the
//!    outline is followed right from its start. Blending starts from the handle point's
//!    *unsmoothed* projection (its world position on screen): the middle lands on the stroke
//!    exactly and the ends stay exactly where they were.
//! 2. The ROI grown within spheres of radius [`ROI_FACTOR`] times the handle displacements
//!    ([`roi_from_displacements`]), or the part the handle lies on ([`part_roi`]).
//! 3. Constraints: for a silhouette, not the crossing points themselves but the band of
//!    vertices around them ([`band_handles`]), translated with the nearby handle points, so
//!    the contour generator moves with the band instead of sliding across the bent surface.
//!    Pinning only the crossing points (as SilSketch pins its handle vertices) puts them on
//!    the stroke, but the new outline runs elsewhere: on a bumpy torus, 2.35 px off the
//!    stroke by the smoothed silhouette and 3.3 px by the rendered outline (edge
//!    silhouettes), even after matching and pinning the bent outline a second time; with
//!    the band, 1.83 px by the rendered outline. A curve on the surface is pinned as drawn,
//!    each point inside its triangle (Eq. 4.2).
//! 4. A detail-preserving edit with rotations ([`EditParams::default`]), exact or soft.

use glam::{DVec2, DVec3};

use super::{
    BLEND_WIDTH, OversketchError, OversketchRoi, blend_weight, map_to_stroke, part_roi,
    roi_from_displacements,
};
use crate::camera::Camera;
use crate::curve::polyline::relative_arclengths;
use crate::deform::{DeformError, EditParams, HandleFit, HandlePoint, LaplacianEdit};
use crate::mesh::{Mesh, VertexId};
use crate::silhouette::SilhouettePoint;

/// The ROI grows within spheres of this many times each handle displacement: twice the
/// thesis's radius ([`super::ROI_RADIUS_FACTOR`]). The band of `band_handles` moves
/// rigidly, about two edges wide, so with the thesis's radius the whole falloff from the
/// handle's motion to rest is squeezed into a few edges beyond it, and the bumps there
/// change more than under a naive falloff (measured on the bumpy torus: relative Laplacian
/// change 2.30 against 2.11 naive at radius 1, 1.28 at 1.5, 0.80 at 2).
pub const ROI_FACTOR: f64 = 2.0;

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
/// positions and the ROI size.
///
/// Errors: [`OversketchError::NoPart`] when a part ROI is asked for and none stands out,
/// [`OversketchError::Deform`] when the edit fails.
pub(super) fn bend(
    mesh: &Mesh,
    camera: &Camera,
    viewport: DVec2,
    handle: &HandleCurve,
    stroke: &[DVec2],
    options: BendOptions,
) -> Result<(Vec<DVec3>, usize), OversketchError> {
    let targets = handle_targets(camera, viewport, handle, stroke);
    let displaced: Vec<(VertexId, f64)> = handle
        .points
        .iter()
        .zip(&targets)
        .flat_map(|(point, target)| {
            let displacement = target.distance(point.position(mesh.positions()));
            point.vertices().map(|v| (v, displacement))
        })
        .collect();
    let roi = match options.roi {
        OversketchRoi::NearHandle => roi_from_displacements(mesh, &displaced, ROI_FACTOR),
        OversketchRoi::Part => {
            let vertices: Vec<VertexId> = displaced.iter().map(|&(v, _)| v).collect();
            part_roi(mesh, &vertices).ok_or(OversketchError::NoPart)?
        }
    };
    let roi_size = roi.iter().filter(|&&r| r).count();
    let (points, targets) = if handle.is_silhouette {
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
    Ok((positions, roi_size))
}

/// Each handle point's target: the stroke point at the same relative arclength, blended at
/// the ends for a silhouette, at the handle point's depth.
fn handle_targets(
    camera: &Camera,
    viewport: DVec2,
    handle: &HandleCurve,
    stroke: &[DVec2],
) -> Vec<DVec3> {
    let mapped = map_to_stroke(&handle.screen, stroke);
    // Unsmoothed: where each world point is drawn now.
    let projected: Vec<DVec2> = handle
        .worlds
        .iter()
        .zip(&handle.screen)
        .map(|(&world, &screen)| {
            camera
                .screen_from_world(world, viewport)
                .map_or(screen, |p| p.truncate())
        })
        .collect();
    let weights = if handle.is_silhouette {
        let gaps = [
            projected[0].distance(mapped[0]),
            projected[projected.len() - 1].distance(mapped[mapped.len() - 1]),
        ];
        blend_weights(&handle.screen, gaps)
    } else {
        vec![1.0; mapped.len()]
    };
    let forward = camera.forward();
    (0..handle.worlds.len())
        .map(|k| {
            let target_screen = projected[k].lerp(mapped[k], weights[k]);
            unproject_at_depth(camera, viewport, target_screen, handle.worlds[k], forward)
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

/// SEED's blend weight at each point's relative arclength along `handle`, with the blend
/// width at each end scaled by that end's gap (px) between the handle and the stroke: a
/// stroke that starts on the outline needs no blend there and is followed all the way.
fn blend_weights(handle: &[DVec2], gaps: [f64; 2]) -> Vec<f64> {
    let [start_width, end_width] = gaps.map(|gap| BLEND_WIDTH * (gap / BLEND_GAP_PX).min(1.0));
    relative_arclengths(handle)
        .into_iter()
        .map(|r| {
            if r < 0.5 {
                blend_weight(r, start_width)
            } else {
                blend_weight(r, end_width)
            }
        })
        .collect()
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
        let handle: Vec<DVec2> = (0..11).map(|i| DVec2::new(i as f64, 0.0)).collect();
        let w = blend_weights(&handle, [BLEND_GAP_PX, 2.0 * BLEND_GAP_PX]);
        assert_eq!(w[0], 0.0);
        assert_eq!(w[10], 0.0);
        assert_eq!(w[5], 1.0);
        assert!((w[1] - 0.5f64.sqrt()).abs() < 1e-12);
        // Half the gap, half the blend; no gap, no blend.
        let w = blend_weights(&handle, [0.5 * BLEND_GAP_PX, 0.0]);
        assert_eq!(w[0], 0.0);
        assert_eq!(w[1], 1.0);
        assert_eq!(w[10], 1.0);
    }
}

//! From a stroke over the object to a handle's control points (Blanco §3.1, §4.1–4.2).
//!
//! The stroke is filtered (Alg. 1) and sampled at `n` points evenly by arclength (Alg. 4–5);
//! each sample is cast onto the shape along its view ray, the nearest hit winning. Triangles
//! are hit exactly (Möller–Trumbore on those whose screen box holds the sample); a point
//! cloud is hit on its splats, discs facing the camera with the cloud's typical spacing as
//! radius (widened where the cloud is sparser), at the depth of the point. A surface handle's control points are these hits. A
//! skeleton handle's are the centroids of the region's vertices in the `n` slices that
//! planes across the surface curve, halfway between its control points, cut (§4.2; the end
//! slices are half as wide).

use glam::{DVec2, DVec3};

use super::error::SkeletonError;
use super::filter::{JITTER_PX, filter_jitter};
use super::frames::rest_frames;
use super::segment::{Part, segment};
use super::shape::Shape;
use crate::camera::Camera;
use crate::curve::polyline;
use crate::geometry::intersect_triangle;
use crate::model::{HandleCurve, HandleKind};

/// A stroke shorter than this (CSS px, after filtering) makes no handle.
const SHORTEST_PX: f64 = 12.0;

/// The stroke of a new handle, in the view it was drawn in.
#[derive(Clone, Copy, Debug)]
pub struct HandleStroke<'a> {
    /// The raw screen samples, CSS px.
    pub points: &'a [DVec2],
    /// The camera it was drawn with.
    pub camera: &'a Camera,
    /// The viewport size, CSS px.
    pub viewport: DVec2,
}

/// The curve of a new handle of `kind` with `control_points` points under `stroke`.
///
/// Errors: fewer than two control points; a stroke too short, or one whose samples do not
/// all lie over the object; a skeleton with no region.
pub fn place_handle(
    shape: &Shape,
    stroke: &HandleStroke,
    kind: HandleKind,
    control_points: usize,
    is_rigid: bool,
) -> Result<HandleCurve, SkeletonError> {
    if control_points < 2 {
        return Err(SkeletonError::TooFewPoints);
    }
    let filtered = filter_jitter(stroke.points, JITTER_PX);
    let cumulative = polyline::cumulative_lengths(&filtered);
    let total = cumulative.last().copied().unwrap_or(0.0);
    if total.is_nan() || total < SHORTEST_PX {
        return Err(SkeletonError::StrokeTooShort);
    }
    let samples: Vec<DVec2> = (0..control_points)
        .map(|k| {
            let s = total * k as f64 / (control_points - 1) as f64;
            polyline::point_at(&filtered, &cumulative, s)
        })
        .collect();
    let rays: Vec<(DVec3, DVec3)> = samples
        .iter()
        .map(|&s| stroke.camera.ray_in_world(s, stroke.viewport))
        .collect();
    let hits = if shape.triangles.is_empty() {
        splat_hits(shape, &rays)
    } else {
        triangle_hits(shape, stroke, &samples, &rays)
    };
    let points: Vec<DVec3> = hits
        .into_iter()
        .collect::<Option<_>>()
        .ok_or(SkeletonError::StrokeMisses)?;
    if points.windows(2).any(|pair| pair[0] == pair[1]) {
        return Err(SkeletonError::StrokeTooShort);
    }
    let surface = HandleCurve::new(points, is_rigid);
    match kind {
        HandleKind::Surface => Ok(surface),
        HandleKind::Skeleton => skeleton_of(shape, &surface),
    }
}

/// The nearest triangle hit of each ray (sample `i` on screen at `samples[i]`).
fn triangle_hits(
    shape: &Shape,
    stroke: &HandleStroke,
    samples: &[DVec2],
    rays: &[(DVec3, DVec3)],
) -> Vec<Option<DVec3>> {
    let on_screen: Vec<DVec3> = shape
        .positions
        .iter()
        .map(|&p| {
            stroke
                .camera
                .screen_from_world(p, stroke.viewport)
                .unwrap_or(DVec3::NAN)
        })
        .collect();
    let mut best: Vec<Option<f64>> = vec![None; samples.len()];
    for t in shape.triangles {
        let s = t.map(|i| on_screen[i as usize].truncate());
        let (lo, hi) = (
            s[0].min(s[1]).min(s[2]) - 0.5,
            s[0].max(s[1]).max(s[2]) + 0.5,
        );
        for (i, sample) in samples.iter().enumerate() {
            if sample.cmplt(lo).any() || sample.cmpgt(hi).any() {
                continue;
            }
            let [a, b, c] = t.map(|i| shape.positions[i as usize]);
            let (origin, dir) = rays[i];
            if let Some((distance, _, _)) = intersect_triangle(origin, dir, a, b, c)
                && best[i].is_none_or(|d| distance < d)
            {
                best[i] = Some(distance);
            }
        }
    }
    best.iter()
        .zip(rays)
        .map(|(d, (origin, dir))| d.map(|d| *origin + d * *dir))
        .collect()
}

/// The nearest splat hit of each ray: a disc around each point facing the camera, its
/// radius the cloud's typical spacing, widened where the cloud is sparser along the ray (the
/// nearest point to the ray sets the floor), so a cloud sampled unevenly has no holes; a ray
/// farther than four spacings from every point misses.
fn splat_hits(shape: &Shape, rays: &[(DVec3, DVec3)]) -> Vec<Option<DVec3>> {
    let spacing = 0.5 * shape.reach();
    rays.iter()
        .map(|&(origin, dir)| {
            let off_ray = |p: DVec3| {
                let along = (p - origin).dot(dir);
                (along > 0.0).then(|| (along, (p - origin - along * dir).length()))
            };
            let nearest = shape
                .positions
                .iter()
                .filter_map(|&p| off_ray(p))
                .map(|(_, off)| off)
                .fold(f64::INFINITY, f64::min);
            if nearest > 4.0 * spacing {
                return None;
            }
            let radius = nearest + spacing;
            let front = shape
                .positions
                .iter()
                .filter_map(|&p| off_ray(p))
                .filter(|&(_, off)| off <= radius)
                .map(|(along, _)| along)
                .fold(f64::INFINITY, f64::min);
            Some(origin + front * dir)
        })
        .collect()
}

/// A skeleton handle from a surface one: centroids of the region's slices (§4.2).
fn skeleton_of(shape: &Shape, surface: &HandleCurve) -> Result<HandleCurve, SkeletonError> {
    let frames = rest_frames(&surface.spline(), surface.shaping());
    let parts = segment(shape, &shape.neighbours(), &frames)?;
    let spline = surface.spline();
    let n = surface.points.len();
    let cuts: Vec<(DVec3, DVec3)> = (0..n - 1)
        .map(|j| {
            let (p, d) = spline.eval((j as f64 + 0.5) / (n - 1) as f64);
            (p, d.normalize_or_zero())
        })
        .collect();
    let mut sums = vec![(DVec3::ZERO, 0usize); n];
    for (x, part) in shape.positions.iter().zip(&parts) {
        if *part == Part::Region {
            let slice = cuts
                .iter()
                .filter(|(p, u)| (*x - *p).dot(*u) >= 0.0)
                .count();
            sums[slice].0 += *x;
            sums[slice].1 += 1;
        }
    }
    let points = sums
        .iter()
        .zip(&surface.points)
        .map(|(&(sum, count), &on_surface)| {
            if count == 0 {
                on_surface
            } else {
                sum / count as f64
            }
        })
        .collect();
    Ok(HandleCurve::new(points, surface.is_rigid))
}

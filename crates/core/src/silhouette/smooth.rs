//! Silhouette smoothing on screen, each point held near the part of its edge that is nearly
//! silhouette (after SEED, Bao and Howard 2014, §3.1).
//!
//! SEED slides each silhouette point ("snaxel") along its edge to straighten the curve while
//! keeping `|n_z| < ε = 0.2`, since people drawing a silhouette ignore fine detail. Here each
//! point moves along the curve's screen normal towards a Gaussian average of its neighbours
//! over screen arc length (σ = [`SMOOTHING_SIGMA_PX`](super::SMOOTHING_SIGMA_PX), each
//! neighbour weighted by the length it stands for), but only within its *band*: how far
//! across the curve the screen image of its edge reaches where the interpolated cosine
//! between normal and view ray, `n·(v − eye) / |v − eye|` (or `n·forward`), stays within
//! `±ε`.
//!
//! Why this filter: a zig-zag at the scale of the triangles is gone (its wavelength of two
//! points, about 5 px, passes the Gaussian at `exp(−(2πσ/λ)²/2) ≈ 10⁻³`), a circle of radius
//! `R` shrinks only by about `σ² / 2R` (0.03 px at R = 150 px), and the arc-length weights
//! make it indifferent to uneven spacing. Uniform-weight filters (the umbrella operator,
//! Taubin's λ|μ, bending-energy descent) read uneven spacing along a circle as wiggles and
//! moved a coarse sphere's outline by a pixel; moving points along their edges' images rather
//! than along the normal also slides them along the curve where an edge runs obliquely.
//!
//! The world point and edge parameter of a [`SilhouettePoint`] stay those of the exact zero
//! crossing; only the screen position moves. A limitation: unlike SEED, a point never moves
//! on to a neighbouring edge, so on a coarse mesh the band, not the filter, bounds the
//! smoothing.

use glam::{DVec2, DVec3};

use super::points::SilhouettePoint;
use crate::camera::Camera;
use crate::mesh::Mesh;

/// SEED's bound on `|cos|` between normal and view ray for a smoothed point.
pub(super) const COSINE_BOUND: f64 = 0.2;
/// The screen images of the two ends of the part of a point's edge where the linearly
/// interpolated cosine is within [`COSINE_BOUND`] (always including the point itself).
/// `None` when an end lies behind the eye.
pub(super) fn edge_band_ends(
    mesh: &Mesh,
    g: &[f64],
    camera: &Camera,
    viewport: DVec2,
    point: &SilhouettePoint,
) -> Option<[DVec2; 2]> {
    let [a, b] = point.edge;
    let (pa, pb) = (mesh.position(a), mesh.position(b));
    let cosine = |g: f64, p: DVec3| match camera.ortho_height {
        Some(_) => g,
        None => g / p.distance(camera.eye),
    };
    let (ca, cb) = (cosine(g[a.index()], pa), cosine(g[b.index()], pb));
    // The point is a sign change, so `ca` and `cb` differ.
    let t_at = |c: f64| ((c - ca) / (cb - ca)).clamp(0.0, 1.0);
    let (t0, t1) = (t_at(-COSINE_BOUND), t_at(COSINE_BOUND));
    let lo = t0.min(t1).min(point.t);
    let hi = t0.max(t1).max(point.t);
    let end = |t: f64| camera.screen_from_world(pa.lerp(pb, t), viewport);
    Some([end(lo)?.truncate(), end(hi)?.truncate()])
}

/// Moves each point of a screen polyline along the polyline's normal towards the Gaussian
/// average (σ = `sigma` px of arc length) of its neighbours, by no more than its band ends
/// `ends[i]` reach across the polyline (`None` holds it in place); the ends of an open
/// polyline stay fixed.
pub(super) fn smooth_across(
    points: &mut [DVec2],
    ends: &[Option<[DVec2; 2]>],
    is_closed: bool,
    sigma: f64,
) {
    debug_assert_eq!(points.len(), ends.len());
    let n = points.len();
    if n < 3 || sigma.is_nan() || sigma <= 0.0 {
        return;
    }
    let start = points.to_vec();
    // `segment[i]` joins points i and i + 1 (and the last the first, on a closed polyline).
    let segment: Vec<f64> = (0..n)
        .map(|i| start[i].distance(start[(i + 1) % n]))
        .collect();
    let length_of = |j: usize| match (is_closed, j) {
        (false, 0) => 0.5 * segment[0],
        (false, j) if j == n - 1 => 0.5 * segment[n - 2],
        _ => 0.5 * (segment[(j + n - 1) % n] + segment[j]),
    };
    let reach = 3.0 * sigma;
    let inner = if is_closed { 0..n } else { 1..n - 1 };
    for i in inner {
        let Some(ends) = ends[i] else {
            continue;
        };
        let normal = (start[(i + 1) % n] - start[(i + n - 1) % n])
            .perp()
            .normalize_or_zero();
        let (mut sum, mut total) = (length_of(i) * start[i], length_of(i));
        // Walk both ways; a closed polyline shares its other points between the two walks.
        let forward_steps = if is_closed { (n - 1) / 2 } else { n - 1 - i };
        let backward_steps = if is_closed { n - 1 - forward_steps } else { i };
        for (steps, is_forward) in [(forward_steps, true), (backward_steps, false)] {
            let (mut j, mut s) = (i, 0.0);
            for _ in 0..steps {
                s += if is_forward {
                    segment[j]
                } else {
                    segment[(j + n - 1) % n]
                };
                j = if is_forward {
                    (j + 1) % n
                } else {
                    (j + n - 1) % n
                };
                if s > reach {
                    break;
                }
                let weight = (-0.5 * (s / sigma).powi(2)).exp() * length_of(j);
                sum += weight * start[j];
                total += weight;
            }
        }
        if total > 0.0 {
            let [a, b] = ends.map(|e| (e - start[i]).dot(normal));
            let (lo, hi) = (a.min(b).min(0.0), a.max(b).max(0.0));
            let offset = (sum / total - start[i]).dot(normal).clamp(lo, hi);
            points[i] = start[i] + offset * normal;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn zigzag() -> Vec<DVec2> {
        (0..20)
            .map(|k| DVec2::new(k as f64, if k % 2 == 0 { 0.5 } else { -0.5 }))
            .collect()
    }

    #[test]
    fn a_zigzag_within_its_bands_straightens() {
        // Each point free to move vertically between y = −1 and 1.
        let mut points = zigzag();
        let ends: Vec<_> = points
            .iter()
            .map(|p| Some([DVec2::new(p.x, -1.0), DVec2::new(p.x, 1.0)]))
            .collect();
        smooth_across(&mut points, &ends, true, 3.0);
        // The seam of the closed zig-zag is a jump of 19 px, so look away from it.
        for p in &points[8..12] {
            assert!(p.y.abs() < 0.01, "{p}");
        }
    }

    #[test]
    fn an_unevenly_sampled_circle_stays_put() {
        // Steps alternating 1° and 4° on a circle of 150 px.
        let mut angle: f64 = 0.0;
        let mut points = Vec::new();
        while angle < 359.0 {
            points.push(150.0 * DVec2::from_angle(angle.to_radians()));
            angle += if points.len() % 2 == 0 { 1.0 } else { 4.0 };
        }
        let ends: Vec<_> = points.iter().map(|&p| Some([0.9 * p, 1.1 * p])).collect();
        smooth_across(&mut points, &ends, true, 3.0);
        for p in &points {
            // About σ² / 2R = 0.03 px inwards (none where both neighbours are out of reach).
            let error = p.length() - 150.0;
            assert!((-0.06..=0.0).contains(&error), "{error}");
        }
    }

    #[test]
    fn bands_bound_the_motion() {
        let original = zigzag();
        let mut points = original.clone();
        // Oblique band ends: only their reach across the curve (y) counts.
        let ends: Vec<_> = points
            .iter()
            .map(|p| Some([*p, DVec2::new(p.x + 3.0, 0.4 * p.y)]))
            .collect();
        smooth_across(&mut points, &ends, false, 3.0);
        for (p, q) in points.iter().zip(&original) {
            // Same x, same side, between 0.4 and 1 times the start.
            let ratio = p.y / q.y;
            assert!(
                p.x == q.x && (0.4 - 1e-12..=1.0).contains(&ratio),
                "{p} {q}"
            );
        }
        // Pulled towards the axis as far as the bands allow.
        for p in &points[2..18] {
            assert!((p.y.abs() - 0.2).abs() < 1e-12, "{p}");
        }
        assert_eq!((points[0], points[19]), (original[0], original[19]));
        let mut held = original.clone();
        smooth_across(&mut held, &vec![None; 20], true, 3.0);
        assert_eq!(held, original);
    }
}

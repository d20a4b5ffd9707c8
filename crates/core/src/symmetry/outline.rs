//! An outline drawn across the symmetry plane made even: its two halves averaged.

use glam::DVec2;

use crate::camera::Camera;
use crate::curve::polyline::{cumulative_lengths, point_at};
use crate::model::MirrorPlane;

/// How nearly the view must lie in the plane (the eye on it, the view direction along it),
/// relative to the eye's distance, for the plane to project to a line on screen.
const IN_PLANE: f64 = 1e-6;

/// The closed `stroke` (`[x, y, pressure]` samples in the view of `camera`) made mirror
/// symmetric about `plane` by averaging its halves: each point with the mirror image of the
/// point as far round the outline the other way from where it crosses the plane, so a
/// hand-drawn body comes out even and meets the plane square. Only for a view that lies in
/// the plane (the front view of the default plane, say), where the mirror image of a stroke
/// on screen is its reflection across the plane's line; `None` for any other view, or a
/// stroke that does not cross that line.
pub fn symmetric_outline(
    stroke: &[[f64; 3]],
    camera: &Camera,
    viewport: DVec2,
    plane: &MirrorPlane,
) -> Option<Vec<[f64; 3]>> {
    let scale = camera.distance().max(f64::MIN_POSITIVE);
    let in_plane = plane.signed_distance(camera.eye).abs() <= IN_PLANE * scale
        && plane.normal().dot(camera.forward()).abs() <= IN_PLANE;
    if !in_plane || stroke.len() < 4 {
        return None;
    }
    let on_line = plane.project(camera.target);
    let along = plane.project(on_line + camera.up) - on_line;
    let a = camera.screen_from_world(on_line, viewport)?.truncate();
    let b = camera
        .screen_from_world(on_line + along, viewport)?
        .truncate();
    let direction = (b - a).try_normalize()?;
    let reflect = |p: DVec2| {
        let d = p - a;
        a + 2.0 * d.dot(direction) * direction - d
    };
    let side = |p: DVec2| direction.perp_dot(p - a);
    let points: Vec<DVec2> = stroke.iter().map(|s| DVec2::new(s[0], s[1])).collect();
    let n = points.len();
    // Start where the stroke crosses the line, so that t and -t are mirror places.
    let crossing = (0..n).find(|&i| side(points[i]) * side(points[(i + 1) % n]) < 0.0)?;
    let (p, q) = (points[crossing], points[(crossing + 1) % n]);
    let start = p.lerp(q, side(p) / (side(p) - side(q)));
    let mut ring = vec![start];
    ring.extend((1..=n).map(|k| points[(crossing + k) % n]));
    ring.push(start);
    let lengths = cumulative_lengths(&ring);
    let total = *lengths.last()?;
    if total <= 0.0 {
        return None;
    }
    let at = |t: f64| point_at(&ring, &lengths, t.rem_euclid(1.0) * total);
    Some(
        (0..n)
            .map(|k| {
                let t = k as f64 / n as f64;
                let even = 0.5 * (at(t) + reflect(at(-t)));
                [even.x, even.y, stroke[(crossing + k) % n][2]]
            })
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn a_lopsided_outline_comes_out_mirror_symmetric_on_screen() {
        let viewport = DVec2::new(800.0, 600.0);
        let stroke: Vec<[f64; 3]> = (0..90)
            .map(|i| {
                let a = std::f64::consts::TAU * f64::from(i) / 90.0;
                let r = 150.0 * (1.0 + 0.2 * (2.0 * a + 0.5).cos());
                [430.0 + r * a.cos(), 300.0 + 0.8 * r * a.sin(), 0.5]
            })
            .collect();
        let plane = MirrorPlane::default();
        let even = symmetric_outline(&stroke, &Camera::default(), viewport, &plane).unwrap();
        // Screen x = 400 is the plane; every point has its mirror image on the outline.
        for p in &even {
            let image = DVec2::new(800.0 - p[0], p[1]);
            let nearest = even
                .iter()
                .map(|q| DVec2::new(q[0], q[1]).distance(image))
                .fold(f64::MAX, f64::min);
            assert!(nearest < 1e-6, "{p:?} has no mirror image ({nearest} px)");
        }
        let turned = Camera {
            eye: DVec3::new(3.0, 0.0, 4.0),
            ..Camera::default()
        };
        assert!(symmetric_outline(&stroke, &turned, viewport, &plane).is_none());
    }
}

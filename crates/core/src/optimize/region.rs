//! Restricting an optimization to what the user marks on screen: the vertices inside a lasso,
//! or under a painted brush stroke (which also tags features to keep). Marked vertices are
//! those that face the camera: back-facing ones stay out, so a mark over the front of a
//! model does not reach through to its back; there is no depth test, so a front-facing part
//! hidden behind another (an ear behind the head) is marked too.

use glam::DVec2;

use crate::camera::Camera;
use crate::curve::StrokePoint;
use crate::curve::polyline::{contains, distance_to_segment};
use crate::geometry::vertex_normals;
use crate::mesh::Mesh;

/// Which vertices of `mesh` lie inside the closed `lasso` (screen points, seen through
/// `camera` in a `viewport`) and face the camera.
pub fn lasso_vertices(mesh: &Mesh, camera: &Camera, viewport: DVec2, lasso: &[DVec2]) -> Vec<bool> {
    marked_vertices(mesh, camera, viewport, |s| contains(lasso, s))
}

/// Which vertices of `mesh` a brush stroke painted over them on screen covers (and face the
/// camera): those within the brush's radius of the stroke. The radius is `radius` CSS px at
/// a mouse's pressure (0.5), from half of it at the lightest touch of a pen to one and a half
/// times it at full pressure.
pub fn brushed_vertices(
    mesh: &Mesh,
    camera: &Camera,
    viewport: DVec2,
    stroke: &[StrokePoint],
    radius: f64,
) -> Vec<bool> {
    let width = |p: &StrokePoint| radius * (0.5 + p.pressure.clamp(0.0, 1.0));
    let segments: Vec<(DVec2, DVec2, f64)> = match stroke {
        [only] => vec![(only.pos, only.pos, width(only))],
        _ => stroke
            .windows(2)
            .map(|w| (w[0].pos, w[1].pos, width(&w[0]).max(width(&w[1]))))
            .collect(),
    };
    marked_vertices(mesh, camera, viewport, |s| {
        segments
            .iter()
            .any(|&(a, b, r)| distance_to_segment(s, a, b) <= r)
    })
}

/// The vertices of `mesh` that face the camera and whose screen position `is_marked` takes.
fn marked_vertices(
    mesh: &Mesh,
    camera: &Camera,
    viewport: DVec2,
    is_marked: impl Fn(DVec2) -> bool,
) -> Vec<bool> {
    let normals = vertex_normals(mesh);
    mesh.positions()
        .iter()
        .zip(&normals)
        .map(|(&p, &normal)| {
            let faces_the_eye = normal.dot(camera.eye - p) > 0.0;
            let on_screen = camera.screen_from_world(p, viewport);
            faces_the_eye && on_screen.is_some_and(|s| is_marked(s.truncate()))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::mesh::primitives;

    fn centre(camera: &Camera, viewport: DVec2) -> DVec2 {
        camera
            .screen_from_world(DVec3::ZERO, viewport)
            .unwrap()
            .truncate()
    }

    #[test]
    fn a_lasso_over_the_front_of_a_sphere_takes_the_front_cap_only() {
        let mesh = primitives::icosphere(1.0, 3);
        let camera = Camera::default();
        let viewport = DVec2::new(800.0, 600.0);
        let centre = centre(&camera, viewport);
        let square = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
            .map(|(x, y)| centre + 40.0 * DVec2::new(x, y));
        let inside = lasso_vertices(&mesh, &camera, viewport, &square);
        let count = inside.iter().filter(|&&i| i).count();
        assert!(
            count > 3 && count < mesh.n_vertices() / 4,
            "{count} vertices"
        );
        for (p, &is_inside) in mesh.positions().iter().zip(&inside) {
            if is_inside {
                assert!(p.dot(camera.eye) > 0.0, "a vertex on the back side: {p}");
                let s = camera.screen_from_world(*p, viewport).unwrap();
                assert!((s.truncate() - centre).abs().max_element() <= 40.0);
            }
        }
    }

    /// A horizontal brush stroke across the front of a sphere marks a band as wide as the
    /// brush: every marked vertex within the radius of the stroke on screen, and more of them
    /// under a pen pressed harder.
    #[test]
    fn a_brush_stroke_marks_a_band_as_wide_as_the_brush() {
        let mesh = primitives::icosphere(1.0, 4);
        let camera = Camera::default();
        let viewport = DVec2::new(800.0, 600.0);
        let centre = centre(&camera, viewport);
        let stroke = |pressure: f64| -> Vec<StrokePoint> {
            (-4..=4)
                .map(|i| StrokePoint::new(centre + DVec2::new(10.0 * f64::from(i), 0.0), pressure))
                .collect()
        };
        let radius = 12.0;
        let count = |marked: &[bool]| marked.iter().filter(|&&m| m).count();
        let band = brushed_vertices(&mesh, &camera, viewport, &stroke(0.5), radius);
        assert!(count(&band) > 10, "{} vertices", count(&band));
        for (p, &marked) in mesh.positions().iter().zip(&band) {
            let s = camera.screen_from_world(*p, viewport).unwrap().truncate() - centre;
            let inside = s.x.abs() <= 40.0 + radius && s.y.abs() <= radius;
            if marked {
                assert!(inside && p.dot(camera.eye) > 0.0, "{p} marked at {s}");
            } else if s.x.abs() <= 40.0 && s.y.abs() < radius - 1e-9 {
                assert!(p.dot(camera.eye) <= 0.0, "{p} at {s} not marked");
            }
        }
        let pressed = brushed_vertices(&mesh, &camera, viewport, &stroke(1.0), radius);
        assert!(count(&pressed) > count(&band));
    }
}

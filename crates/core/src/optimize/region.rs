//! Restricting an optimization to a region the user lassoes on screen: the vertices inside
//! the lasso move, the rest keep their place (fixed unknowns of the same system).

use glam::{DVec2, DVec3};

use crate::camera::Camera;
use crate::curve::polyline::contains;
use crate::geometry::vertex_normals;
use crate::mesh::Mesh;

/// Which vertices of `mesh` lie inside the closed `lasso` (screen points, seen through
/// `camera` in a `viewport`) and face the camera. Back-facing vertices stay out, so a lasso
/// over the front of a model does not reach through to its back; there is no depth test, so
/// a front-facing part hidden behind another (an ear behind the head) is inside too.
pub fn lasso_vertices(mesh: &Mesh, camera: &Camera, viewport: DVec2, lasso: &[DVec2]) -> Vec<bool> {
    let normals = vertex_normals(mesh);
    mesh.positions()
        .iter()
        .zip(&normals)
        .map(|(&p, &normal)| {
            let faces_the_eye = normal.dot(camera.eye - p) > 0.0;
            let on_screen = camera.screen_from_world(p, viewport);
            faces_the_eye && on_screen.is_some_and(|s: DVec3| contains(lasso, s.truncate()))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;

    #[test]
    fn a_lasso_over_the_front_of_a_sphere_takes_the_front_cap_only() {
        let mesh = primitives::icosphere(1.0, 3);
        let camera = Camera::default();
        let viewport = DVec2::new(800.0, 600.0);
        let centre = camera
            .screen_from_world(DVec3::ZERO, viewport)
            .unwrap()
            .truncate();
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
}

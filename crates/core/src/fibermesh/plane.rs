//! The plane a creation stroke is drawn on, and its frame.

use glam::{DVec2, DVec3};

use crate::camera::Camera;

/// The plane a creation stroke is drawn on: through the camera target, facing the camera.
///
/// Its frame is right-handed: `right` and `up` are the screen's directions, `normal` points
/// towards the camera, so a counter-clockwise polygon in plane coordinates is
/// counter-clockwise on the screen (with y up).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DrawingPlane {
    /// A point on the plane (the camera target).
    pub origin: DVec3,
    /// Unit direction of the plane's x axis: the screen's right.
    pub right: DVec3,
    /// Unit direction of the plane's y axis: the screen's up.
    pub up: DVec3,
    /// Unit normal, towards the camera.
    pub normal: DVec3,
}

impl DrawingPlane {
    /// The plane through `camera.target` facing the camera; `None` for an invalid camera.
    pub fn facing(camera: &Camera) -> Option<DrawingPlane> {
        if !camera.is_valid() {
            return None;
        }
        let forward = camera.forward();
        let right = forward.cross(camera.up).normalize();
        let up = right.cross(forward);
        Some(DrawingPlane {
            origin: camera.target,
            right,
            up,
            normal: -forward,
        })
    }

    /// Plane coordinates of a world point (its projection onto the plane).
    pub fn plane_from_world(&self, p: DVec3) -> DVec2 {
        let d = p - self.origin;
        DVec2::new(d.dot(self.right), d.dot(self.up))
    }

    /// The world point at plane coordinates `p`, `height` along the normal.
    pub fn world_from_plane(&self, p: DVec2, height: f64) -> DVec3 {
        self.origin + p.x * self.right + p.y * self.up + height * self.normal
    }

    /// Signed distance of a world point from the plane, positive towards the camera.
    pub fn height(&self, p: DVec3) -> f64 {
        (p - self.origin).dot(self.normal)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plane_frame_matches_the_screen() {
        let camera = Camera::default();
        let plane = DrawingPlane::facing(&camera).unwrap();
        assert!((plane.normal - DVec3::Z).length() < 1e-15);
        assert!(
            (plane.right - DVec3::X).length() < 1e-15 && (plane.up - DVec3::Y).length() < 1e-15
        );
        let p = plane.world_from_plane(DVec2::new(0.5, -0.25), 0.1);
        assert!((plane.plane_from_world(p) - DVec2::new(0.5, -0.25)).length() < 1e-15);
        assert!((plane.height(p) - 0.1).abs() < 1e-15);
    }
}

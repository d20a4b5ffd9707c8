//! The orbit camera: turns navigation gestures into a [`Camera`] for rendering and tools.
//!
//! The camera circles a target at a distance, with yaw about world +Y and a pitch kept
//! short of the poles so "up" stays meaningful. Pan speed is scaled so that the point under
//! the fingers follows them on the target's depth plane, as users expect from map apps.

use glam::{DVec2, DVec3};
use sketchmesh_core::camera::Camera;

use crate::input::gestures::NavAction;

/// Radians of orbit per point of drag.
const ORBIT_SPEED: f64 = 0.008;
/// Pitch limit, just short of straight up or down.
const MAX_PITCH: f64 = 1.5;
/// Wheel points per doubling of the distance.
const WHEEL_POINTS_PER_DOUBLING: f64 = 400.0;

/// A perspective camera orbiting a target.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct OrbitCamera {
    /// Point looked at and orbited around.
    pub target: DVec3,
    /// Distance from eye to target.
    pub distance: f64,
    /// Angle about world +Y, radians.
    pub yaw: f64,
    /// Elevation, radians, positive looks down from above.
    pub pitch: f64,
    /// Vertical field of view in degrees.
    pub fov_y_deg: f64,
}

impl Default for OrbitCamera {
    fn default() -> Self {
        Self {
            target: DVec3::ZERO,
            distance: 6.0,
            yaw: 0.0,
            // A little from above, so the ground grid reads as a floor, not a line.
            pitch: 0.3,
            fov_y_deg: 45.0,
        }
    }
}

impl OrbitCamera {
    /// The camera in the document's terms, as stored with every stroke.
    pub fn camera(&self) -> Camera {
        let offset = DVec3::new(
            self.pitch.cos() * self.yaw.sin(),
            self.pitch.sin(),
            self.pitch.cos() * self.yaw.cos(),
        ) * self.distance;
        Camera {
            eye: self.target + offset,
            target: self.target,
            up: DVec3::Y,
            fov_y_deg: self.fov_y_deg,
            ortho_height: None,
        }
    }

    /// The orbit camera that looks as `camera` does (a stroke's camera, to see it as it was
    /// drawn); an orbit camera's own camera comes back as it was.
    pub fn looking_as(camera: &Camera) -> OrbitCamera {
        let offset = camera.eye - camera.target;
        let distance = offset.length().max(1e-9);
        OrbitCamera {
            target: camera.target,
            distance,
            yaw: offset.x.atan2(offset.z),
            pitch: (offset.y / distance).clamp(-1.0, 1.0).asin(),
            fov_y_deg: camera.fov_y_deg,
        }
    }

    /// Applies one navigation action; `viewport_height` is in points.
    pub fn apply(&mut self, action: NavAction, viewport_height: f64) {
        match action {
            NavAction::Orbit(d) => self.orbit(DVec2::new(d.x.into(), d.y.into())),
            NavAction::Pan(d) => self.pan(DVec2::new(d.x.into(), d.y.into()), viewport_height),
            NavAction::Zoom { factor } => self.dolly(factor.into()),
        }
    }

    /// Turns by a drag delta in points: right drag turns the model right, down tilts it down.
    pub fn orbit(&mut self, delta: DVec2) {
        self.yaw -= delta.x * ORBIT_SPEED;
        self.pitch = (self.pitch + delta.y * ORBIT_SPEED).clamp(-MAX_PITCH, MAX_PITCH);
    }

    /// Slides the view so the target plane follows a drag delta in points.
    pub fn pan(&mut self, delta: DVec2, viewport_height: f64) {
        let camera = self.camera();
        let forward = camera.forward();
        let right = forward.cross(DVec3::Y).normalize_or_zero();
        let up = right.cross(forward);
        let world_per_point = self.world_per_point(viewport_height);
        self.target += (-right * delta.x + up * delta.y) * world_per_point;
    }

    /// Multiplies the distance by `factor` (below 1 comes closer).
    pub fn dolly(&mut self, factor: f64) {
        if factor.is_finite() && factor > 0.0 {
            self.distance = (self.distance * factor).clamp(1e-3, 1e5);
        }
    }

    /// Zooms for a wheel or trackpad scroll of `points` (positive scrolls up, comes closer).
    pub fn wheel(&mut self, points: f64) {
        self.dolly((-points / WHEEL_POINTS_PER_DOUBLING).exp2());
    }

    /// Frames the box `min..max` so it fills most of a view `aspect` times as wide as it is
    /// tall: its bounding sphere fits the narrower of the two fields of view (a phone's
    /// upright view is narrower across than up).
    pub fn frame(&mut self, min: DVec3, max: DVec3, aspect: f64) {
        let radius = ((max - min).length() * 0.5).max(1e-3);
        self.target = (min + max) * 0.5;
        let half_fov_y = self.fov_y_deg.to_radians() * 0.5;
        let half_fov_x = (half_fov_y.tan() * aspect.max(1e-3)).atan();
        self.distance = radius / half_fov_y.min(half_fov_x).sin() * 1.1;
    }

    /// Looks at `point` along `normal` (from the side of it the eye is on now), keeping the
    /// distance: a plane through `point` with that normal is then seen face on.
    pub fn face(&mut self, point: DVec3, normal: DVec3) {
        let Some(normal) = normal.try_normalize() else {
            return;
        };
        let eye = self.camera().eye;
        let toward_eye = if (eye - point).dot(normal) >= 0.0 {
            normal
        } else {
            -normal
        };
        self.target = point;
        self.pitch = toward_eye
            .y
            .clamp(-1.0, 1.0)
            .asin()
            .clamp(-MAX_PITCH, MAX_PITCH);
        self.yaw = toward_eye.x.atan2(toward_eye.z);
    }

    /// World units per screen point at the target's depth.
    pub fn world_per_point(&self, viewport_height: f64) -> f64 {
        2.0 * self.distance * (self.fov_y_deg.to_radians() * 0.5).tan() / viewport_height.max(1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_camera_looks_at_the_origin_from_the_front_and_above() {
        let c = OrbitCamera::default().camera();
        assert!(((c.eye - c.target).length() - 6.0).abs() < 1e-12);
        assert!(c.eye.y > 0.0 && c.eye.z > 0.0 && c.eye.x.abs() < 1e-12);
        assert!((c.forward() - (c.target - c.eye).normalize()).length() < 1e-12);
    }

    #[test]
    fn an_orbit_cameras_camera_comes_back_as_it_was() {
        let mut cam = OrbitCamera::default();
        cam.orbit(DVec2::new(130.0, -40.0));
        cam.pan(DVec2::new(12.0, 7.0), 600.0);
        let back = OrbitCamera::looking_as(&cam.camera());
        assert!((back.camera().eye - cam.camera().eye).length() < 1e-12);
        assert_eq!(back.camera().target, cam.camera().target);
    }

    #[test]
    fn pan_moves_the_target_under_the_finger() {
        let mut cam = OrbitCamera::default();
        let viewport = DVec2::new(800.0, 600.0);
        let before = cam.camera();
        let grabbed = before
            .screen_from_world(DVec3::ZERO, viewport)
            .expect("visible");
        cam.pan(DVec2::new(40.0, -25.0), viewport.y);
        let after = cam.camera();
        let moved = after
            .screen_from_world(DVec3::ZERO, viewport)
            .expect("visible");
        let shift = DVec2::new(moved.x - grabbed.x, moved.y - grabbed.y);
        assert!((shift - DVec2::new(40.0, -25.0)).length() < 1e-6, "{shift}");
    }

    #[test]
    fn orbit_keeps_distance_and_clamps_pitch() {
        let mut cam = OrbitCamera::default();
        cam.orbit(DVec2::new(123.0, 10_000.0));
        let c = cam.camera();
        assert!(((c.eye - c.target).length() - 6.0).abs() < 1e-9);
        assert!(cam.pitch <= MAX_PITCH);
    }

    #[test]
    fn wheel_up_comes_closer_and_frame_fits_the_box() {
        let mut cam = OrbitCamera::default();
        cam.wheel(400.0);
        assert!((cam.distance - 3.0).abs() < 1e-9);
        // A square view, a wide one and a phone's upright one.
        for viewport in [
            DVec2::new(600.0, 600.0),
            DVec2::new(1280.0, 620.0),
            DVec2::new(390.0, 700.0),
        ] {
            cam.frame(
                DVec3::splat(-1.0),
                DVec3::splat(1.0),
                viewport.x / viewport.y,
            );
            let c = cam.camera();
            for corner in [
                DVec3::splat(-1.0),
                DVec3::splat(1.0),
                DVec3::new(1.0, -1.0, 1.0),
                DVec3::new(-1.0, 1.0, -1.0),
            ] {
                let p = c.screen_from_world(corner, viewport).expect("in front");
                let inside = p.x > 0.0 && p.x < viewport.x && p.y > 0.0 && p.y < viewport.y;
                assert!(inside, "{p} outside {viewport}");
            }
        }
    }
}

//! A look-at camera: view and projection matrices, picking rays and projection to the screen.
//!
//! Spaces (see the style guide): `world` is the document's space (right-handed, +Y up by
//! default); `view` is right-handed with the camera at the origin looking down −Z; `clip` and
//! `ndc` follow WebGPU (x and y in −1..1 with y up, depth in 0..1); `screen` is CSS pixels with
//! the origin at the top-left corner and y pointing down, as egui and pointer events report it.
//!
//! The camera stores only what a user controls (eye, target, up, field of view); near and far
//! planes are derived from the eye–target distance ([`Camera::near_far`]) so that an object
//! around the target never clips. A limitation: objects more than [`FAR_FACTOR`] times the
//! eye–target distance away are clipped.

use glam::{DMat4, DVec2, DVec3, DVec4};
use serde::{Deserialize, Serialize};

/// Near plane distance as a fraction of the eye–target distance.
pub const NEAR_FACTOR: f64 = 0.01;
/// Far plane distance as a multiple of the eye–target distance.
pub const FAR_FACTOR: f64 = 100.0;

/// A look-at camera with a perspective or orthographic lens.
///
/// JSON: `{"eye":[0,0,5],"target":[0,0,0],"up":[0,1,0],"fov_y_deg":45.0}`, plus
/// `"ortho_height"` for an orthographic camera.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Camera {
    /// Position of the camera in world space.
    pub eye: DVec3,
    /// The point the camera looks at, in world space; orbiting turns around it.
    pub target: DVec3,
    /// The world direction that appears upwards on screen; need not be orthogonal to the view.
    pub up: DVec3,
    /// Vertical field of view in degrees (perspective lens).
    pub fov_y_deg: f64,
    /// Height in world units of the visible region; `Some` selects an orthographic lens.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ortho_height: Option<f64>,
}

impl Default for Camera {
    fn default() -> Self {
        Self {
            eye: DVec3::new(0.0, 0.0, 5.0),
            target: DVec3::ZERO,
            up: DVec3::Y,
            fov_y_deg: 45.0,
            ortho_height: None,
        }
    }
}

/// Orthonormal camera frame in world space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// Right on screen.
    pub right: DVec3,
    /// Up on screen.
    pub up: DVec3,
    /// Into the screen.
    pub forward: DVec3,
}

impl Camera {
    /// Whether every number is finite, eye and target differ, `up` is not parallel to the view
    /// direction and the lens is sensible (0 < fov < 180°, ortho height > 0).
    ///
    /// The matrices and rays of an invalid camera contain NaN.
    pub fn is_valid(&self) -> bool {
        let finite = self.eye.is_finite()
            && self.target.is_finite()
            && self.up.is_finite()
            && self.fov_y_deg.is_finite();
        let lens_ok = match self.ortho_height {
            Some(height) => height.is_finite() && height > 0.0,
            None => self.fov_y_deg > 0.0 && self.fov_y_deg < 180.0,
        };
        let distance = self.distance();
        let up_length = self.up.length();
        finite
            && lens_ok
            && distance > 0.0
            && up_length > 0.0
            && self.forward().cross(self.up / up_length).length() > 1e-9
    }

    /// Distance from the eye to the target.
    pub fn distance(&self) -> f64 {
        (self.target - self.eye).length()
    }

    /// Unit view direction, from the eye towards the target.
    pub fn forward(&self) -> DVec3 {
        (self.target - self.eye).normalize()
    }

    /// Near and far clip distances, from the eye–target distance.
    pub fn near_far(&self) -> (f64, f64) {
        let distance = self.distance();
        (distance * NEAR_FACTOR, distance * FAR_FACTOR)
    }

    /// The camera's right, up and forward directions.
    pub fn frame(&self) -> Frame {
        let forward = self.forward();
        let right = forward.cross(self.up).normalize();
        let up = right.cross(forward);
        Frame { right, up, forward }
    }

    /// The world-from-view transform (camera pose): view x → right, y → up, −z → forward.
    pub fn world_from_view(&self) -> DMat4 {
        let Frame { right, up, forward } = self.frame();
        DMat4::from_cols(
            right.extend(0.0),
            up.extend(0.0),
            (-forward).extend(0.0),
            self.eye.extend(1.0),
        )
    }

    /// The right-handed look-at view matrix (the inverse of [`Camera::world_from_view`]).
    pub fn view_from_world(&self) -> DMat4 {
        let Frame { right, up, forward } = self.frame();
        let back = -forward;
        // The inverse of a rigid transform: transposed rotation, rotated negated translation.
        DMat4::from_cols(
            DVec4::new(right.x, up.x, back.x, 0.0),
            DVec4::new(right.y, up.y, back.y, 0.0),
            DVec4::new(right.z, up.z, back.z, 0.0),
            DVec4::new(
                -right.dot(self.eye),
                -up.dot(self.eye),
                -back.dot(self.eye),
                1.0,
            ),
        )
    }

    /// The projection for a viewport of the given width / height, with WebGPU's depth range
    /// 0..1 (0 at the near plane).
    pub fn clip_from_view(&self, aspect: f64) -> DMat4 {
        let (near, far) = self.near_far();
        match self.ortho_height {
            Some(height) => {
                let half_height = 0.5 * height;
                let half_width = half_height * aspect;
                glam::dcamera::rh::proj::directx::orthographic(
                    -half_width,
                    half_width,
                    -half_height,
                    half_height,
                    near,
                    far,
                )
            }
            None => glam::dcamera::rh::proj::directx::perspective(
                self.fov_y_deg.to_radians(),
                aspect,
                near,
                far,
            ),
        }
    }

    /// `clip_from_view(aspect) * view_from_world()`.
    pub fn clip_from_world(&self, aspect: f64) -> DMat4 {
        self.clip_from_view(aspect) * self.view_from_world()
    }

    /// The picking ray through a screen position (CSS px, y down, origin top-left) of a
    /// viewport of the given size in CSS px: `(origin, unit direction)` in world space.
    ///
    /// A perspective ray starts at the eye; an orthographic ray starts on the plane through
    /// the eye facing the view direction and runs along [`Camera::forward`].
    pub fn ray_in_world(&self, pos_in_screen: DVec2, viewport: DVec2) -> (DVec3, DVec3) {
        let Frame { right, up, forward } = self.frame();
        let aspect = viewport.x / viewport.y;
        let ndc_x = 2.0 * pos_in_screen.x / viewport.x - 1.0;
        let ndc_y = 1.0 - 2.0 * pos_in_screen.y / viewport.y;
        match self.ortho_height {
            Some(height) => {
                let half_height = 0.5 * height;
                let origin =
                    self.eye + right * (ndc_x * half_height * aspect) + up * (ndc_y * half_height);
                (origin, forward)
            }
            None => {
                let tan_half = (0.5 * self.fov_y_deg.to_radians()).tan();
                let dir = forward + right * (ndc_x * tan_half * aspect) + up * (ndc_y * tan_half);
                (self.eye, dir.normalize())
            }
        }
    }

    /// The world length one CSS pixel spans at `depth` in front of the eye (along
    /// [`Camera::forward`]): how big a brush of so many pixels is where it touches.
    pub fn world_per_pixel(&self, depth: f64, viewport: DVec2) -> f64 {
        let height = match self.ortho_height {
            Some(height) => height,
            None => 2.0 * depth * (0.5 * self.fov_y_deg.to_radians()).tan(),
        };
        height / viewport.y
    }

    /// Projects a world point to the screen: `(x px, y px, depth)` with x and y in CSS px (y
    /// down, origin top-left) and depth the distance in front of the eye along
    /// [`Camera::forward`], in world units. `None` when the point is not in front of the eye.
    pub fn screen_from_world(&self, p: DVec3, viewport: DVec2) -> Option<DVec3> {
        let point_in_view = self.view_from_world().transform_point3(p);
        let depth = -point_in_view.z;
        if depth.is_nan() || depth <= 0.0 {
            return None;
        }
        let aspect = viewport.x / viewport.y;
        let clip = self.clip_from_view(aspect) * point_in_view.extend(1.0);
        let ndc_x = clip.x / clip.w;
        let ndc_y = clip.y / clip.w;
        let x = 0.5 * (ndc_x + 1.0) * viewport.x;
        let y = 0.5 * (1.0 - ndc_y) * viewport.y;
        Some(DVec3::new(x, y, depth))
    }

    /// Where the picking ray through a screen position meets the plane through the target
    /// facing the camera (the plane a new stroke is drawn on). `None` if it misses (a ray
    /// parallel to the plane or one pointing away, which a valid camera never produces).
    pub fn point_on_target_plane(&self, pos_in_screen: DVec2, viewport: DVec2) -> Option<DVec3> {
        self.point_on_plane_through(self.target, pos_in_screen, viewport)
    }

    /// Where the picking ray through a screen position meets the plane through `through`
    /// facing the camera; `None` as for [`Camera::point_on_target_plane`].
    pub fn point_on_plane_through(
        &self,
        through: DVec3,
        pos_in_screen: DVec2,
        viewport: DVec2,
    ) -> Option<DVec3> {
        let (origin, dir) = self.ray_in_world(pos_in_screen, viewport);
        let normal = self.forward();
        let denominator = dir.dot(normal);
        let t = (through - origin).dot(normal) / denominator;
        let point = origin + dir * t;
        (denominator > 0.0 && t > 0.0 && point.is_finite()).then_some(point)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tilted() -> Camera {
        Camera {
            eye: DVec3::new(3.0, 2.0, 4.0),
            target: DVec3::new(0.5, -0.25, 0.0),
            up: DVec3::new(0.1, 1.0, 0.0),
            fov_y_deg: 50.0,
            ortho_height: None,
        }
    }

    fn ortho() -> Camera {
        Camera {
            ortho_height: Some(3.0),
            ..tilted()
        }
    }

    #[test]
    fn json_shape() {
        let json = serde_json::to_string(&Camera::default()).unwrap();
        assert_eq!(
            json,
            r#"{"eye":[0.0,0.0,5.0],"target":[0.0,0.0,0.0],"up":[0.0,1.0,0.0],"fov_y_deg":45.0}"#
        );
        // docs/session-format.md shows exactly this.
        assert!(include_str!("../../../docs/session-format.md").contains(&json));
        let parsed: Camera = serde_json::from_str(
            r#"{"eye":[1,2,3],"target":[0,0,0],"up":[0,1,0],"fov_y_deg":30,"ortho_height":2.5}"#,
        )
        .unwrap();
        assert_eq!(parsed.eye, DVec3::new(1.0, 2.0, 3.0));
        assert_eq!(parsed.ortho_height, Some(2.5));
        let round_trip: Camera =
            serde_json::from_str(&serde_json::to_string(&parsed).unwrap()).unwrap();
        assert_eq!(round_trip, parsed);
        let unknown = serde_json::from_str::<Camera>(
            r#"{"eye":[1,2,3],"target":[0,0,0],"up":[0,1,0],"fov_y_deg":30,"zoom":2}"#,
        );
        assert!(unknown.is_err());
    }

    #[test]
    fn view_matrix_matches_frame() {
        for camera in [Camera::default(), tilted()] {
            let view_from_world = camera.view_from_world();
            // The eye maps to the origin and the target onto −Z at its distance.
            let eye_in_view = view_from_world.transform_point3(camera.eye);
            assert!(eye_in_view.length() < 1e-12);
            let target_in_view = view_from_world.transform_point3(camera.target);
            let expected = DVec3::new(0.0, 0.0, -camera.distance());
            assert!((target_in_view - expected).length() < 1e-12);
            let product = view_from_world * camera.world_from_view();
            assert!(product.abs_diff_eq(DMat4::IDENTITY, 1e-12));
            // Same as glam's look-at.
            let glam_view = glam::dcamera::rh::view::look_at_mat4(
                camera.eye,
                camera.target,
                camera.up.normalize(),
            );
            assert!(view_from_world.abs_diff_eq(glam_view, 1e-12));
        }
    }

    #[test]
    fn depth_range_is_zero_to_one() {
        for camera in [tilted(), ortho()] {
            let (near, far) = camera.near_far();
            let clip_from_world = camera.clip_from_world(1.5);
            let forward = camera.forward();
            let at_near = clip_from_world.project_point3(camera.eye + forward * near);
            let at_far = clip_from_world.project_point3(camera.eye + forward * far);
            assert!(at_near.z.abs() < 1e-9, "{at_near}");
            assert!((at_far.z - 1.0).abs() < 1e-9, "{at_far}");
            let at_target = clip_from_world.project_point3(camera.target);
            assert!(at_target.x.abs() < 1e-12 && at_target.y.abs() < 1e-12);
        }
    }

    #[test]
    fn ray_then_project_returns_the_pixel() {
        let viewport = DVec2::new(800.0, 600.0);
        for camera in [Camera::default(), tilted(), ortho()] {
            for pixel in [
                DVec2::new(400.0, 300.0),
                DVec2::new(0.0, 0.0),
                DVec2::new(799.0, 17.5),
                DVec2::new(123.25, 590.0),
            ] {
                let (origin, dir) = camera.ray_in_world(pixel, viewport);
                assert!((dir.length() - 1.0).abs() < 1e-12);
                for t in [0.5, 5.0, 40.0] {
                    let projected = camera
                        .screen_from_world(origin + dir * t, viewport)
                        .unwrap();
                    assert!(
                        (projected.truncate() - pixel).length() < 1e-9,
                        "{projected} {pixel}"
                    );
                    let expected_depth = (origin + dir * t - camera.eye).dot(camera.forward());
                    assert!((projected.z - expected_depth).abs() < 1e-9);
                }
            }
        }
    }

    #[test]
    fn centre_ray_hits_target_and_screen_is_y_down() {
        let camera = Camera::default();
        let viewport = DVec2::new(640.0, 480.0);
        let centre = camera
            .point_on_target_plane(DVec2::new(320.0, 240.0), viewport)
            .unwrap();
        assert!(centre.length() < 1e-12);
        // The top edge of the view at the target is tan(22.5°)·5 above it.
        let top = camera
            .point_on_target_plane(DVec2::new(320.0, 0.0), viewport)
            .unwrap();
        let expected = 5.0 * (22.5f64).to_radians().tan();
        assert!((top - DVec3::new(0.0, expected, 0.0)).length() < 1e-12);
        // Right on screen is +X for a camera on +Z looking at the origin.
        let right = camera
            .point_on_target_plane(DVec2::new(640.0, 240.0), viewport)
            .unwrap();
        assert!((right.x - expected * 640.0 / 480.0).abs() < 1e-12);
    }

    #[test]
    fn behind_the_camera_is_none() {
        let camera = tilted();
        let behind = camera.eye - camera.forward();
        assert_eq!(
            camera.screen_from_world(behind, DVec2::new(100.0, 100.0)),
            None
        );
        assert_eq!(
            camera.screen_from_world(camera.eye, DVec2::new(100.0, 100.0)),
            None
        );
    }

    #[test]
    fn validity() {
        assert!(Camera::default().is_valid());
        assert!(ortho().is_valid());
        let degenerate = [
            Camera {
                eye: DVec3::ZERO,
                ..Camera::default()
            },
            Camera {
                up: DVec3::Z,
                ..Camera::default()
            },
            Camera {
                up: DVec3::ZERO,
                ..Camera::default()
            },
            Camera {
                fov_y_deg: 180.0,
                ..Camera::default()
            },
            Camera {
                ortho_height: Some(0.0),
                ..Camera::default()
            },
            Camera {
                eye: DVec3::new(f64::NAN, 0.0, 5.0),
                ..Camera::default()
            },
        ];
        for camera in degenerate {
            assert!(!camera.is_valid(), "{camera:?}");
        }
    }
}

//! The move tool's handles as geometry (issue 16): a ring around a model's middle on screen
//! turns it about the view axis, a square beside the ring scales it, and the inside of the
//! ring (or the model itself) moves it in the plane through its middle facing the camera.
//! A drag of a handle from one screen point to another is the matrix of a `transform` op, so
//! what the tool previews is what the op commits and replays.
//!
//! Every handle is a touch-sized target: a finger's 44 px.

use glam::{DMat4, DQuat, DVec2, DVec3};

use super::{Document, Model};
use crate::camera::Camera;
use crate::model::MirrorPlane;

/// Half a touch target (px): how far from a handle a press still takes it.
pub const HANDLE_REACH_PX: f64 = 22.0;

/// The ring's radius on screen is the model's projected half-diagonal, kept within these
/// bounds (px), so that the ring can be reached around small and large models alike.
const RING_RADIUS_PX: (f64, f64) = (70.0, 160.0);

/// The scale square sits this far (px) outside the ring, down and to the right.
const SCALE_GAP_PX: f64 = 30.0;

/// A scale drag is held between these factors, so that a model cannot vanish.
const SCALE_LIMITS: (f64, f64) = (0.05, 20.0);

/// A handle of the move tool.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GizmoHandle {
    /// Move in the plane through the model's middle facing the camera.
    Move,
    /// Turn about the view axis through the model's middle.
    Turn,
    /// Scale about the model's middle, the same in every direction.
    Scale,
}

/// The move tool's handles around one model, as seen.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gizmo {
    /// The model's middle (its bounding box's centre), which turning and scaling keep.
    pub pivot: DVec3,
    /// The pivot on screen (px).
    pub centre: DVec2,
    /// The ring's radius on screen (px).
    pub radius: f64,
}

impl Gizmo {
    /// The handles of `model` seen through `camera` in a viewport of `viewport` px; `None`
    /// when its middle is not in front of the camera.
    pub fn of(model: &Model, camera: &Camera, viewport: DVec2) -> Option<Gizmo> {
        let (lo, hi) = model.mesh.bounding_box()?;
        let pivot = 0.5 * (lo + hi);
        let centre = camera.screen_from_world(pivot, viewport)?.truncate();
        let corners = [
            lo,
            hi,
            DVec3::new(lo.x, hi.y, lo.z),
            DVec3::new(hi.x, lo.y, hi.z),
        ];
        let reach = corners
            .iter()
            .filter_map(|&c| camera.screen_from_world(c, viewport))
            .map(|s| s.truncate().distance(centre))
            .fold(0.0, f64::max);
        Some(Gizmo {
            pivot,
            centre,
            radius: reach.clamp(RING_RADIUS_PX.0, RING_RADIUS_PX.1),
        })
    }

    /// The handles of the symmetry plane `plane` in `doc`, seen through `camera`: a ring of
    /// the smallest size about the plane's point nearest `near` (where the last drag left
    /// the ring), else nearest the models' middle (the view's target when there are none).
    /// Its inside moves the plane, its ring turns it; a plane has no scale. `None` when that
    /// point is not in front of the camera.
    pub fn of_plane(
        plane: &MirrorPlane,
        near: Option<DVec3>,
        doc: &Document,
        camera: &Camera,
        viewport: DVec2,
    ) -> Option<Gizmo> {
        let middle = || {
            let boxes = doc.models.iter().filter_map(|m| m.mesh.bounding_box());
            boxes
                .reduce(|(lo, hi), (l, h)| (lo.min(l), hi.max(h)))
                .map_or(camera.target, |(lo, hi)| 0.5 * (lo + hi))
        };
        let pivot = plane.project(near.unwrap_or_else(middle));
        Some(Gizmo {
            pivot,
            centre: camera.screen_from_world(pivot, viewport)?.truncate(),
            radius: RING_RADIUS_PX.0,
        })
    }

    /// Where the scale square is on screen.
    pub fn scale_handle(&self) -> DVec2 {
        self.centre + DVec2::ONE.normalize() * (self.radius + SCALE_GAP_PX)
    }

    /// The handle a press at `at` (px) takes, if any: the scale square, else the ring, else
    /// the inside of the ring.
    pub fn handle_at(&self, at: DVec2) -> Option<GizmoHandle> {
        let from_centre = at.distance(self.centre);
        if at.distance(self.scale_handle()) <= HANDLE_REACH_PX {
            Some(GizmoHandle::Scale)
        } else if (from_centre - self.radius).abs() <= HANDLE_REACH_PX {
            Some(GizmoHandle::Turn)
        } else if from_centre < self.radius {
            Some(GizmoHandle::Move)
        } else {
            None
        }
    }

    /// The matrix a drag of `handle` from `from` to `to` (px) applies to the model, seen
    /// through `camera` in a viewport of `viewport` px.
    pub fn drag(
        &self,
        handle: GizmoHandle,
        camera: &Camera,
        viewport: DVec2,
        from: DVec2,
        to: DVec2,
    ) -> DMat4 {
        let about_pivot = |linear: DMat4| {
            DMat4::from_translation(self.pivot) * linear * DMat4::from_translation(-self.pivot)
        };
        match handle {
            GizmoHandle::Move => {
                let on_plane = |screen| self.on_pivot_plane(camera, viewport, screen);
                DMat4::from_translation(on_plane(to) - on_plane(from))
            }
            GizmoHandle::Turn => {
                let angle = |p: DVec2| (p - self.centre).to_angle();
                // Screen y points down, so a turn that looks clockwise is a positive angle,
                // which is a right-handed turn about the axis pointing into the screen.
                let turn = angle(to) - angle(from);
                about_pivot(DMat4::from_quat(DQuat::from_axis_angle(
                    camera.forward(),
                    turn,
                )))
            }
            GizmoHandle::Scale => {
                let reach = |p: DVec2| p.distance(self.centre).max(1.0);
                let factor = (reach(to) / reach(from)).clamp(SCALE_LIMITS.0, SCALE_LIMITS.1);
                about_pivot(DMat4::from_scale(DVec3::splat(factor)))
            }
        }
    }

    /// The matrix two fingers moving from `from` to `to` (px) apply to the model: what lies
    /// under the fingers' midpoint (at the pivot's depth) follows it, the model turns about
    /// the view axis as the line between the fingers turns, and scales as their spread
    /// changes (within the scale limits), as a photo does under two fingers.
    pub fn two_fingers(
        &self,
        camera: &Camera,
        viewport: DVec2,
        from: [DVec2; 2],
        to: [DVec2; 2],
    ) -> DMat4 {
        let middle = |p: [DVec2; 2]| self.on_pivot_plane(camera, viewport, 0.5 * (p[0] + p[1]));
        let (line_from, line_to) = (from[1] - from[0], to[1] - to[0]);
        let factor =
            (line_to.length() / line_from.length().max(1.0)).clamp(SCALE_LIMITS.0, SCALE_LIMITS.1);
        // Screen y points down: see the turn handle.
        let turn = line_to.to_angle() - line_from.to_angle();
        let linear = DMat4::from_quat(DQuat::from_axis_angle(camera.forward(), turn))
            * DMat4::from_scale(DVec3::splat(factor));
        DMat4::from_translation(middle(to)) * linear * DMat4::from_translation(-middle(from))
    }

    /// Where the view ray through `screen` meets the plane through the pivot facing the
    /// camera.
    fn on_pivot_plane(&self, camera: &Camera, viewport: DVec2, screen: DVec2) -> DVec3 {
        camera
            .point_on_plane_through(self.pivot, screen, viewport)
            .unwrap_or(self.pivot)
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;
    use crate::mesh::primitives::icosphere;

    const VIEWPORT: DVec2 = DVec2::new(800.0, 600.0);

    fn gizmo() -> (Model, Camera, Gizmo) {
        let model = Model {
            mesh: icosphere(1.0, 2),
            ..Model::default()
        };
        let camera = Camera::default();
        let gizmo = Gizmo::of(&model, &camera, VIEWPORT).unwrap();
        (model, camera, gizmo)
    }

    fn screen(camera: &Camera, p: DVec3) -> DVec2 {
        camera.screen_from_world(p, VIEWPORT).unwrap().truncate()
    }

    #[test]
    fn handles_are_found_where_they_are_drawn() {
        let (_, _, g) = gizmo();
        assert!((g.centre - DVec2::new(400.0, 300.0)).length() < 1e-9);
        assert_eq!(g.handle_at(g.centre), Some(GizmoHandle::Move));
        let on_ring = g.centre + DVec2::new(0.0, g.radius + 10.0);
        assert_eq!(g.handle_at(on_ring), Some(GizmoHandle::Turn));
        assert_eq!(g.handle_at(g.scale_handle()), Some(GizmoHandle::Scale));
        assert_eq!(g.handle_at(g.centre + DVec2::X * (g.radius + 40.0)), None);
    }

    #[test]
    fn the_plane_handles_sit_on_the_plane_and_move_and_turn_it() {
        let (model, camera, _) = gizmo();
        let doc = Document {
            models: vec![std::sync::Arc::new(model)],
            ..Document::default()
        };
        let plane = MirrorPlane::default();
        let g = Gizmo::of_plane(&plane, None, &doc, &camera, VIEWPORT).unwrap();
        assert!(plane.signed_distance(g.pivot).abs() < 1e-12);
        let to = g.centre + DVec2::new(50.0, 0.0);
        let moved = plane
            .transformed(g.drag(GizmoHandle::Move, &camera, VIEWPORT, g.centre, to))
            .unwrap();
        assert!(
            moved.offset() > 0.1 && moved.normal() == DVec3::X,
            "{moved:?}"
        );
        let ring = |a: f64| g.centre + g.radius * DVec2::from_angle(a);
        let turn = g.drag(GizmoHandle::Turn, &camera, VIEWPORT, ring(0.0), ring(0.3));
        let turned = plane.transformed(turn).unwrap();
        assert!((turned.normal().angle_between(DVec3::X) - 0.3).abs() < 1e-9);
        assert!(
            turned.signed_distance(g.pivot).abs() < 1e-12,
            "turned about its dot"
        );
        // Where a drag left the ring, it stays: the turned plane's ring is about the same dot.
        let kept = Gizmo::of_plane(&turned, Some(g.pivot), &doc, &camera, VIEWPORT).unwrap();
        assert!((kept.pivot - g.pivot).length() < 1e-12);
    }

    #[test]
    fn a_move_drag_keeps_the_pivot_under_the_pointer() {
        let (_, camera, g) = gizmo();
        let to = g.centre + DVec2::new(60.0, -25.0);
        let m = g.drag(GizmoHandle::Move, &camera, VIEWPORT, g.centre, to);
        let moved = m.transform_point3(g.pivot);
        assert!((screen(&camera, moved) - to).length() < 1e-9);
        let depth = |p: DVec3| camera.screen_from_world(p, VIEWPORT).unwrap().z;
        assert!(
            (depth(moved) - depth(g.pivot)).abs() < 1e-9,
            "it stays at its depth"
        );
    }

    #[test]
    fn a_quarter_turn_around_the_ring_turns_the_model_a_quarter_about_the_view_axis() {
        let (_, camera, g) = gizmo();
        let from = g.centre + DVec2::X * g.radius;
        let to = g.centre + DVec2::Y * g.radius;
        let m = g.drag(GizmoHandle::Turn, &camera, VIEWPORT, from, to);
        // A point right of the middle goes below it on screen, as the pointer did.
        let right = screen(&camera, m.transform_point3(DVec3::X * 0.5));
        assert!(
            (right.x - g.centre.x).abs() < 1e-6 && right.y > g.centre.y + 10.0,
            "{right}"
        );
        assert!((m.transform_point3(g.pivot) - g.pivot).length() < 1e-12);
    }

    #[test]
    fn two_fingers_keep_what_is_under_them_under_them_while_they_move_turn_and_spread() {
        let (_, camera, g) = gizmo();
        let from = [g.centre - DVec2::X * 40.0, g.centre + DVec2::X * 40.0];
        // Moved 50 px right, turned a quarter and spread to twice as far apart.
        let middle = g.centre + DVec2::X * 50.0;
        let to = [middle - DVec2::Y * 80.0, middle + DVec2::Y * 80.0];
        let m = g.two_fingers(&camera, VIEWPORT, from, to);
        assert!((screen(&camera, m.transform_point3(g.pivot)) - middle).length() < 1e-6);
        // A point under the right finger at the pivot's depth ends under it.
        let under = camera
            .point_on_plane_through(g.pivot, from[1], VIEWPORT)
            .unwrap();
        let moved = screen(&camera, m.transform_point3(under));
        assert!((moved - to[1]).length() < 1e-6, "{moved} against {}", to[1]);
        assert!((m.transform_vector3(DVec3::X).length() - 2.0).abs() < 1e-9);
    }

    #[test]
    fn a_scale_drag_scales_by_the_ratio_of_reaches_within_limits() {
        let (_, camera, g) = gizmo();
        let from = g.scale_handle();
        let to = g.centre + (from - g.centre) * 1.5;
        let m = g.drag(GizmoHandle::Scale, &camera, VIEWPORT, from, to);
        assert!((m.transform_vector3(DVec3::X).length() - 1.5).abs() < 1e-12);
        let collapsed = g.drag(GizmoHandle::Scale, &camera, VIEWPORT, from, g.centre);
        assert!(collapsed.transform_vector3(DVec3::X).length() >= 0.05 - 1e-12);
    }
}

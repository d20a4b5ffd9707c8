//! The region tool's direct handles (Bujans §7): 3-axis handles on the reference curve.
//! Pressing the inner third of an axis and dragging translates the handle along it, the
//! middle third scales along it, the outer third turns about it; tapping the curve away from
//! the handles adds one there (taking the transform the curve has there, so nothing moves).
//! The handles start at the curve's two ends and its middle, so dragging the middle one
//! bends the region with its ends pinned. The core blends the handles' transforms along the
//! curve ([`sketchmesh_core::region_edit::Motion`]); this module only turns pointer
//! positions into transforms.

use glam::{DMat3, DMat4, DQuat, DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::polyline::distance_to_segment;
use sketchmesh_core::document::{AreaInput, HandleInput, RegionEditInput};
use sketchmesh_core::geometry::log_affine;
use sketchmesh_core::region_edit::{Handle, HandleFrame, HandleRail, blend_at};

/// An axis' length on screen, in CSS px, when it lies in the view plane.
const AXIS_PX: f64 = 66.0;
/// An axis seen shorter than this (pointing at the viewer) is not drawn or pressed.
const SHORTEST_AXIS_PX: f64 = 14.0;
/// How near (CSS px) a press must come to an axis, or to the curve to add a handle.
const PRESS_PX: f64 = 14.0;
/// CSS px along an axis that double the size along it.
const PX_PER_DOUBLING: f64 = 120.0;
/// Degrees of turn per CSS px of drag across an axis.
const TURN_DEGREES_PER_PX: f64 = 0.5;
/// The largest turn one drag makes: short of half a turn, where blending has no meaning.
const MAX_TURN_DEGREES: f64 = 170.0;
/// A new handle keeps at least this far (along the curve, 0..1) from the others.
const MIN_HANDLE_GAP: f64 = 0.04;

/// Which third of an axis was pressed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    /// The inner third: moves the handle along the axis.
    Translate,
    /// The middle third: scales along the axis about the handle.
    Scale,
    /// The outer third: turns about the axis through the handle.
    Rotate,
}

/// One handle axis as seen: the handle, which axis (tangent, normal, binormal), and its
/// ends on screen (CSS px, relative to the viewport).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AxisMark {
    /// The handle, in order along the curve.
    pub handle: usize,
    /// 0 the curve's tangent, 1 the surface normal, 2 the binormal.
    pub axis: usize,
    /// Where the handle is.
    pub from: DVec2,
    /// Where the axis ends.
    pub to: DVec2,
    /// The part being dragged, when this axis is.
    pub dragged: Option<Part>,
}

/// A drag on one axis, from where it was pressed.
#[derive(Clone, Debug)]
struct AxisDrag {
    handle: usize,
    axis: usize,
    part: Part,
    from: DVec2,
    /// The handle's transform and its moved frame when pressed.
    start: DMat4,
    frame: HandleFrame,
    /// The axis on screen when pressed: unit direction and CSS px per world unit along it.
    direction: DVec2,
    px_per_unit: f64,
}

/// The handles of one region edit and the drag on them.
#[derive(Clone, Debug)]
pub struct HandleSession {
    input: RegionEditInput,
    rail: HandleRail,
    handles: Vec<Handle>,
    drag: Option<AxisDrag>,
}

/// What a press on the handles did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pressed {
    /// It took an axis: the drag begins.
    Axis,
    /// It added a handle on the curve.
    Added,
    /// It missed the handles and the curve.
    Nothing,
}

impl HandleSession {
    /// Handles at the ends and the middle of `rail`, the curve of `input`, none moved.
    pub fn new(input: RegionEditInput, rail: HandleRail) -> Self {
        let still = |at| Handle {
            at,
            transform: DMat4::IDENTITY,
        };
        HandleSession {
            input,
            rail,
            handles: vec![still(0.0), still(0.5), still(1.0)],
            drag: None,
        }
    }

    /// The op as the handles stand.
    pub fn input(&self) -> RegionEditInput {
        let handles = self.handles.iter().map(|h| HandleInput {
            at: h.at,
            transform: h.transform.to_cols_array(),
        });
        RegionEditInput {
            transform: None,
            handles: Some(handles.collect()),
            profile: None,
            ..self.input.clone()
        }
    }

    /// The curves and levels, as the handles found them (the transform the identity).
    pub fn curves(&self) -> &RegionEditInput {
        &self.input
    }

    /// The fall-off's levels and areas change.
    pub fn set_falloff(&mut self, levels: &[f64], areas: Vec<AreaInput>) {
        self.input.levels = Some(levels.to_vec());
        self.input.areas = areas;
    }

    /// Whether any handle has moved.
    pub fn moved(&self) -> bool {
        self.handles.iter().any(|h| h.transform != DMat4::IDENTITY)
    }

    /// Every axis of every handle where it is now, as seen through `camera`.
    pub fn axes(&self, camera: &Camera, viewport: DVec2) -> Vec<AxisMark> {
        let mut marks = Vec::new();
        for (i, handle) in self.handles.iter().enumerate() {
            let frame = moved_frame(&self.rail, handle);
            for axis in 0..3 {
                let Some((from, to)) = axis_on_screen(&frame, axis, camera, viewport) else {
                    continue;
                };
                let dragged = (self.drag.as_ref())
                    .filter(|d| d.handle == i && d.axis == axis)
                    .map(|d| d.part);
                marks.push(AxisMark {
                    handle: i,
                    axis,
                    from,
                    to,
                    dragged,
                });
            }
        }
        marks
    }

    /// A press at `at` (CSS px in the viewport): takes the nearest axis within reach, or adds
    /// a handle where the curve passes within reach.
    pub fn press(&mut self, at: DVec2, camera: &Camera, viewport: DVec2) -> Pressed {
        let nearest = self
            .axes(camera, viewport)
            .into_iter()
            .map(|mark| (mark, distance_to_segment(at, mark.from, mark.to)))
            .filter(|(_, d)| *d < PRESS_PX)
            .min_by(|a, b| a.1.total_cmp(&b.1));
        if let Some((mark, _)) = nearest {
            let along =
                (at - mark.from).dot(mark.to - mark.from) / mark.from.distance_squared(mark.to);
            let part = match along {
                x if x < 1.0 / 3.0 => Part::Translate,
                x if x < 2.0 / 3.0 => Part::Scale,
                _ => Part::Rotate,
            };
            let handle = self.handles[mark.handle];
            let frame = moved_frame(&self.rail, &handle);
            let length = mark.from.distance(mark.to);
            self.drag = Some(AxisDrag {
                handle: mark.handle,
                axis: mark.axis,
                part,
                from: at,
                start: handle.transform,
                frame,
                direction: (mark.to - mark.from) / length,
                px_per_unit: length / axis_length(&frame, camera, viewport),
            });
            return Pressed::Axis;
        }
        match self.curve_at(at, camera, viewport) {
            Some(place)
                if self
                    .handles
                    .iter()
                    .all(|h| (h.at - place).abs() >= MIN_HANDLE_GAP) =>
            {
                let Ok(transform) = blend_at(&self.handles, place) else {
                    return Pressed::Nothing;
                };
                self.handles.push(Handle {
                    at: place,
                    transform,
                });
                self.handles.sort_by(|a, b| a.at.total_cmp(&b.at));
                Pressed::Added
            }
            _ => Pressed::Nothing,
        }
    }

    /// The pointer of the drag is at `at`: the dragged handle's transform follows.
    pub fn drag_to(&mut self, at: DVec2) {
        let Some(drag) = &self.drag else {
            return;
        };
        let offset = at - drag.from;
        let along = offset.dot(drag.direction);
        let across = drag.direction.perp_dot(offset);
        let axis = drag.frame.axes[drag.axis];
        let about = |m: DMat4| {
            DMat4::from_translation(drag.frame.origin)
                * m
                * DMat4::from_translation(-drag.frame.origin)
        };
        let change = match drag.part {
            Part::Translate => DMat4::from_translation(axis * (along / drag.px_per_unit)),
            Part::Scale => {
                let k = (along / PX_PER_DOUBLING).exp2() - 1.0;
                let stretch = DMat3::from_cols(axis * axis.x, axis * axis.y, axis * axis.z);
                about(DMat4::from_mat3(DMat3::IDENTITY + stretch * k))
            }
            Part::Rotate => {
                let degrees =
                    (across * TURN_DEGREES_PER_PX).clamp(-MAX_TURN_DEGREES, MAX_TURN_DEGREES);
                about(DMat4::from_quat(DQuat::from_axis_angle(
                    axis,
                    degrees.to_radians(),
                )))
            }
        };
        // A drag that would take the handle past half a turn holds it where it was last.
        let transform = change * drag.start;
        if log_affine(transform).is_some() {
            self.handles[drag.handle].transform = transform;
        }
    }

    /// The drag ends; the handles stay where it left them.
    pub fn release(&mut self) {
        self.drag = None;
    }

    /// Whether an axis is being dragged.
    pub fn dragging(&self) -> bool {
        self.drag.is_some()
    }

    /// Where along the curve (0..1) it passes nearest to `at` as now seen, if within reach.
    fn curve_at(&self, at: DVec2, camera: &Camera, viewport: DVec2) -> Option<f64> {
        const STEPS: usize = 200;
        (0..=STEPS)
            .map(|i| i as f64 / STEPS as f64)
            .filter_map(|place| {
                let handle = Handle {
                    at: place,
                    transform: blend_at(&self.handles, place).ok()?,
                };
                let seen =
                    camera.screen_from_world(moved_frame(&self.rail, &handle).origin, viewport)?;
                Some((place, seen.truncate().distance(at)))
            })
            .filter(|(_, d)| *d < PRESS_PX)
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(place, _)| place)
    }
}

/// `handle`'s frame on `rail`, moved by its transform.
fn moved_frame(rail: &HandleRail, handle: &Handle) -> HandleFrame {
    let frame = rail.frame_at(handle.at);
    let t = handle.transform;
    HandleFrame {
        origin: t.transform_point3(frame.origin),
        axes: frame.axes.map(|a| t.transform_vector3(a).normalize_or(a)),
    }
}

/// The world length of an axis: [`AXIS_PX`] on screen at the handle's depth.
fn axis_length(frame: &HandleFrame, camera: &Camera, viewport: DVec2) -> f64 {
    let up = camera.frame().up;
    let probe = 1e-3 * (camera.eye - frame.origin).length().max(1e-9);
    let seen = |p: DVec3| camera.screen_from_world(p, viewport).map(|s| s.truncate());
    match (seen(frame.origin), seen(frame.origin + up * probe)) {
        (Some(a), Some(b)) if a.distance(b) > 0.0 => AXIS_PX * probe / a.distance(b),
        _ => probe,
    }
}

/// An axis' ends on screen, when it is seen long enough to press.
fn axis_on_screen(
    frame: &HandleFrame,
    axis: usize,
    camera: &Camera,
    viewport: DVec2,
) -> Option<(DVec2, DVec2)> {
    let length = axis_length(frame, camera, viewport);
    let from = camera.screen_from_world(frame.origin, viewport)?.truncate();
    let to = camera
        .screen_from_world(frame.origin + frame.axes[axis] * length, viewport)?
        .truncate();
    (from.distance(to) >= SHORTEST_AXIS_PX).then_some((from, to))
}

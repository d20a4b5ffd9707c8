//! From a pointer stroke to a closed, simple, evenly sampled outline on the drawing plane.
//!
//! The screen-space part ([`closed_loop_in_screen`]) decides whether the stroke is a usable
//! outline: it resamples at [`FINE_SPACING_PX`], trims an overshoot where the end crosses
//! the start, closes a small gap, and refuses open strokes, loops that cross themselves
//! elsewhere and outlines with almost no area. The plane part ([`even_outline`]) resamples
//! the loop at the mesh spacing, smooths it and resamples again, because smoothing evens
//! out the pointer's jitter but also the spacing.
//!
//! Screen to plane is a similarity (the plane faces the camera), so lengths and areas
//! measured in pixels and in plane units differ by one scale factor.

use glam::DVec2;

use super::CreateError;
use super::plane::DrawingPlane;
use crate::camera::Camera;
use crate::curve::polyline::{
    perimeter, resample, resample_closed, segment_crossing, self_crossings, signed_area,
};
use crate::curve::{StrokePoint, is_closed_loop, smooth_closed, validate_stroke};

/// Spacing, in CSS px, of the first resampling used for the closure and crossing checks.
pub const FINE_SPACING_PX: f64 = 2.0;
/// At most this fraction of the stroke may be cut away as overshoot around the closure.
pub const MAX_OVERSHOOT: f64 = 0.25;
/// Outlines enclosing less than this many square CSS px are refused.
pub const MIN_AREA_PX2: f64 = 100.0;
/// Outlines with `4π area / perimeter²` below this are refused as slivers (a circle has 1,
/// a 1:100 ellipse about 0.025).
pub const MIN_ROUNDNESS: f64 = 0.02;
/// Taubin smoothing passes on the outline at the mesh spacing (FiberMesh §3.3.3 smooths
/// the resampled stroke once by midpoints; Taubin's filter does not shrink it).
const OUTLINE_SMOOTHING: usize = 2;

/// The closed loop a stroke outlines, in screen px, without repeating the first point.
///
/// Errors: the stroke's own problems ([`CreateError::Stroke`]), [`CreateError::NotClosed`]
/// when the ends are further apart than `close_tolerance_px` (or 15% of the length),
/// [`CreateError::SelfCrossing`] for any crossing other than an overshoot at the closure,
/// and [`CreateError::NoArea`] for slivers and specks.
pub(crate) fn closed_loop_in_screen(
    stroke: &[StrokePoint],
    close_tolerance_px: f64,
) -> Result<Vec<DVec2>, CreateError> {
    validate_stroke(stroke).map_err(CreateError::Stroke)?;
    let mut fine: Vec<DVec2> = resample(stroke, FINE_SPACING_PX)
        .iter()
        .map(|p| p.pos)
        .collect();
    fine.dedup();
    if fine.len() < 4 {
        return Err(CreateError::NoArea);
    }
    let crossings = self_crossings(&fine, false);
    let loop_points = if crossings.is_empty() {
        if !is_closed_loop(stroke, close_tolerance_px) {
            return Err(CreateError::NotClosed);
        }
        if fine.first() == fine.last() {
            fine.pop();
        }
        fine
    } else {
        trim_overshoot(&fine, &crossings)?
    };
    // The closing edge must not cross the rest either.
    if !self_crossings(&loop_points, true).is_empty() {
        return Err(CreateError::SelfCrossing);
    }
    let area = signed_area(&loop_points).abs();
    let length = perimeter(&loop_points);
    if area < MIN_AREA_PX2 || 4.0 * std::f64::consts::PI * area < MIN_ROUNDNESS * length * length {
        return Err(CreateError::NoArea);
    }
    Ok(loop_points)
}

/// The loop between the crossing that encloses the longest stretch of the stroke, if the
/// cut-off head and tail are short and no other crossing lies inside the loop.
fn trim_overshoot(
    points: &[DVec2],
    crossings: &[(usize, usize)],
) -> Result<Vec<DVec2>, CreateError> {
    let Some(&(a, b)) = crossings.iter().max_by_key(|&&(a, b)| b - a) else {
        return Err(CreateError::SelfCrossing);
    };
    let kept = (b - a) as f64;
    let total = (points.len() - 1) as f64;
    // A touch at a vertex shows up as up to four pairs of neighbouring segments.
    let is_same = |c: usize, d: usize| c.abs_diff(a) <= 1 && d.abs_diff(b) <= 1;
    let is_inner = |&&(c, d): &&(usize, usize)| !is_same(c, d) && c >= a && d <= b;
    if kept < (1.0 - MAX_OVERSHOOT) * total || crossings.iter().any(|pair| is_inner(&pair)) {
        return Err(CreateError::SelfCrossing);
    }
    let (a0, a1) = (points[a], points[a + 1]);
    let t = segment_crossing(a0, a1, points[b], points[b + 1]).unwrap_or(0.0);
    let mut loop_points = vec![a0.lerp(a1, t)];
    loop_points.extend_from_slice(&points[a + 1..=b]);
    Ok(loop_points)
}

/// Maps a screen loop onto the drawing plane; `None` if a ray misses the plane.
pub(crate) fn loop_on_plane(
    loop_in_screen: &[DVec2],
    camera: &Camera,
    viewport: DVec2,
    plane: &DrawingPlane,
) -> Option<Vec<DVec2>> {
    loop_in_screen
        .iter()
        .map(|&p| {
            camera
                .point_on_target_plane(p, viewport)
                .map(|w| plane.plane_from_world(w))
        })
        .collect()
}

/// The final outline at the mesh spacing: resampled, smoothed, resampled again and checked
/// to be simple (smoothing a very narrow neck can make it cross itself).
pub(crate) fn even_outline(
    loop_on_plane: &[DVec2],
    spacing: f64,
) -> Result<Vec<DVec2>, CreateError> {
    let even = resample_closed(loop_on_plane, spacing);
    let as_points: Vec<StrokePoint> = even.iter().map(|&p| StrokePoint::new(p, 0.5)).collect();
    let smooth: Vec<DVec2> = smooth_closed(&as_points, OUTLINE_SMOOTHING)
        .iter()
        .map(|p| p.pos)
        .collect();
    let outline = resample_closed(&smooth, spacing);
    if outline.len() < 3 {
        return Err(CreateError::NoArea);
    }
    if !self_crossings(&outline, true).is_empty() {
        return Err(CreateError::SelfCrossing);
    }
    Ok(outline)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::TAU;

    fn stroke(points: impl IntoIterator<Item = DVec2>) -> Vec<StrokePoint> {
        points
            .into_iter()
            .map(|p| StrokePoint::new(p, 0.5))
            .collect()
    }

    /// A circle of radius 100 px drawn over `turns` of a full turn.
    fn circle(turns: f64) -> Vec<StrokePoint> {
        let n = 200;
        stroke((0..=n).map(|k| {
            let a = turns * TAU * k as f64 / n as f64;
            DVec2::new(400.0 + 100.0 * a.cos(), 300.0 + 100.0 * a.sin())
        }))
    }

    #[test]
    fn a_nearly_closed_circle_is_closed() {
        let points = closed_loop_in_screen(&circle(0.97), 40.0).unwrap();
        let area = signed_area(&points).abs();
        assert!(
            (area - 0.5 * TAU * 100.0 * 100.0).abs() < 0.05 * area,
            "{area}"
        );
    }

    #[test]
    fn an_open_arc_is_refused_with_a_sentence() {
        let err = closed_loop_in_screen(&circle(0.6), 40.0).unwrap_err();
        assert_eq!(err, CreateError::NotClosed);
        assert_eq!(
            err.to_string(),
            "Close the outline: end the stroke near where it started."
        );
    }

    /// A circle of radius 100 px that starts 10 px outside and ends 8 px outside, so the
    /// last tenth of a turn crosses the first.
    fn overshooting_circle() -> Vec<StrokePoint> {
        let n = 220;
        stroke((0..=n).map(|k| {
            let turns = 1.1 * k as f64 / n as f64;
            let r = 100.0 + 10.0 * (1.0 - turns / 0.1).max(0.0) + 80.0 * (turns - 1.0).max(0.0);
            DVec2::new(400.0, 300.0) + r * DVec2::from_angle(TAU * turns)
        }))
    }

    #[test]
    fn an_overshoot_is_trimmed() {
        let points = closed_loop_in_screen(&overshooting_circle(), 40.0).unwrap();
        let length = perimeter(&points);
        assert!((length - TAU * 100.0).abs() < 0.01 * length, "{length}");
    }

    #[test]
    fn loops_and_slivers_are_refused() {
        // Two turns of a spiral: the closing edge crosses the inner turn.
        let spiral = stroke((0..=400).map(|k| {
            let turns = 2.0 * k as f64 / 400.0;
            (100.0 - 10.0 * turns) * DVec2::from_angle(TAU * turns + 0.3)
        }));
        assert_eq!(
            closed_loop_in_screen(&spiral, 40.0),
            Err(CreateError::SelfCrossing)
        );
        // A figure eight: its single crossing sits in the middle of the stroke.
        let eight = stroke((0..=200).map(|k| {
            let t = TAU * k as f64 / 200.0;
            DVec2::new(100.0 * t.sin(), 50.0 * (2.0 * t).sin())
        }));
        assert_eq!(
            closed_loop_in_screen(&eight, 40.0),
            Err(CreateError::SelfCrossing)
        );
        // There and back along a line.
        let sliver = stroke([DVec2::ZERO, DVec2::new(200.0, 1.0), DVec2::new(0.0, 2.0)]);
        assert_eq!(
            closed_loop_in_screen(&sliver, 40.0),
            Err(CreateError::NoArea)
        );
    }

    #[test]
    fn even_outline_has_even_steps() {
        let ellipse: Vec<DVec2> = (0..50)
            .map(|k| DVec2::from_angle(TAU * k as f64 / 50.0) * DVec2::new(1.0, 0.5))
            .collect();
        let square: Vec<DVec2> = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
            .map(|(x, y)| DVec2::new(x, y))
            .into();
        // Chords across the square's corners (rounded by the smoothing) are shorter.
        for (outline, tolerance) in [(ellipse, 0.03), (square, 0.15)] {
            let outline = even_outline(&outline, 0.05).unwrap();
            let n = outline.len();
            let mean = perimeter(&outline) / n as f64;
            for i in 0..n {
                let step = outline[i].distance(outline[(i + 1) % n]);
                assert!(
                    (step / mean - 1.0).abs() < tolerance,
                    "step {step}, mean {mean}"
                );
            }
        }
    }
}

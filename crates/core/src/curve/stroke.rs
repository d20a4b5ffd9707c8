//! Stroke points, validation and the standard stroke clean-up.

use super::error::{MIN_STROKE_LENGTH_PX, StrokeError};
use super::point::StrokePoint;
use super::polyline::{self, PolylinePoint, resample};
use super::smooth;

/// Spacing of the resampled stroke, in CSS px.
pub const SAMPLE_SPACING_PX: f64 = 4.0;
/// Taubin smoothing iterations applied by [`process_stroke`].
pub const SMOOTHING_ITERATIONS: usize = 2;

/// Arc length of a stroke in CSS px.
fn arc_length(points: &[StrokePoint]) -> f64 {
    polyline::length(points.iter().map(StrokePoint::position))
}

/// Whether a stroke ends near where it started, so that it reads as a closed loop.
///
/// The gap between the ends must be at most `tolerance_px` and at most 15% of the stroke's
/// length, so a short dash whose ends both lie within the tolerance is not a loop.
pub fn is_closed_loop(points: &[StrokePoint], tolerance_px: f64) -> bool {
    let (Some(first), Some(last)) = (points.first(), points.last()) else {
        return false;
    };
    let gap = first.pos.distance(last.pos);
    let length = arc_length(points);
    length > 0.0 && gap <= tolerance_px && gap <= 0.15 * length
}

/// Checks that a stroke has at least two points, only finite numbers and an arc length of at
/// least [`MIN_STROKE_LENGTH_PX`].
pub fn validate_stroke(points: &[StrokePoint]) -> Result<(), StrokeError> {
    if let Some(index) = points
        .iter()
        .position(|point| !point.pos.is_finite() || !point.pressure.is_finite())
    {
        return Err(StrokeError::NonFinite { index });
    }
    if points.len() < 2 {
        return Err(StrokeError::TooFewPoints {
            count: points.len(),
        });
    }
    let length_px = arc_length(points);
    if length_px < MIN_STROKE_LENGTH_PX {
        return Err(StrokeError::TooShort { length_px });
    }
    Ok(())
}

/// The standard clean-up of a raw stroke: validates it ([`validate_stroke`]), clamps
/// pressure to 0..=1, resamples to [`SAMPLE_SPACING_PX`] and applies
/// [`SMOOTHING_ITERATIONS`] of Taubin smoothing with fixed ends.
///
/// Linear in the number of points, so the app can run it on the live stroke every frame.
pub fn process_stroke(raw: &[StrokePoint]) -> Result<Vec<StrokePoint>, StrokeError> {
    validate_stroke(raw)?;
    let clamped: Vec<StrokePoint> = raw
        .iter()
        .map(|point| StrokePoint::new(point.pos, point.pressure.clamp(0.0, 1.0)))
        .collect();
    let even = resample(&clamped, SAMPLE_SPACING_PX);
    Ok(smooth(&even, SMOOTHING_ITERATIONS))
}

#[cfg(test)]
mod tests {
    use glam::DVec2;

    use super::*;

    fn line(points: &[(f64, f64)]) -> Vec<StrokePoint> {
        points
            .iter()
            .map(|&(x, y)| StrokePoint::new(DVec2::new(x, y), 0.5))
            .collect()
    }

    #[test]
    fn resampling_interpolates_pressure() {
        let mut raw = line(&[(0.0, 0.0), (10.0, 0.0), (10.0, 10.0)]);
        raw[1].pressure = 1.0;
        let even = resample(&raw, 5.0);
        let pressures: Vec<f64> = even.iter().map(|p| p.pressure).collect();
        assert_eq!(pressures, vec![0.5, 0.75, 1.0, 0.75, 0.5]);
        assert_eq!(even[3].pos, DVec2::new(10.0, 5.0));
    }

    #[test]
    fn refuses_bad_strokes() {
        assert_eq!(
            process_stroke(&line(&[(1.0, 1.0)])),
            Err(StrokeError::TooFewPoints { count: 1 })
        );
        assert_eq!(
            process_stroke(&line(&[(0.0, 0.0), (f64::NAN, 1.0), (9.0, 9.0)])),
            Err(StrokeError::NonFinite { index: 1 })
        );
        let mut infinite_pressure = line(&[(0.0, 0.0), (10.0, 0.0)]);
        infinite_pressure[1].pressure = f64::INFINITY;
        assert_eq!(
            process_stroke(&infinite_pressure),
            Err(StrokeError::NonFinite { index: 1 })
        );
        assert_eq!(
            process_stroke(&line(&[(0.0, 0.0), (3.0, 0.0)])),
            Err(StrokeError::TooShort { length_px: 3.0 })
        );
        // The messages are sentences.
        let message = StrokeError::TooShort { length_px: 3.0 }.to_string();
        assert_eq!(
            message,
            "The stroke is 3.0 px long; at least 4 px are needed."
        );
    }

    #[test]
    fn straight_stroke_stays_straight_and_even() {
        let raw = line(&[(0.0, 0.0), (7.0, 0.0), (7.5, 0.0), (30.0, 0.0), (40.0, 0.0)]);
        let processed = process_stroke(&raw).unwrap();
        assert_eq!(processed.len(), 11);
        for (k, point) in processed.iter().enumerate() {
            assert!((point.pos - DVec2::new(4.0 * k as f64, 0.0)).length() < 1e-12);
        }
        assert_eq!(processed[0].pos, DVec2::ZERO);
        assert_eq!(processed[10].pos, DVec2::new(40.0, 0.0));
    }

    #[test]
    fn pressure_is_clamped() {
        let mut raw = line(&[(0.0, 0.0), (10.0, 0.0)]);
        raw[0].pressure = -1.0;
        raw[1].pressure = 3.0;
        let processed = process_stroke(&raw).unwrap();
        assert!(processed.iter().all(|p| (0.0..=1.0).contains(&p.pressure)));
        assert_eq!(processed[0].pressure, 0.0);
        assert_eq!(processed.last().unwrap().pressure, 1.0);
    }

    #[test]
    fn closed_loops() {
        let circle: Vec<StrokePoint> = (0..=40)
            .map(|k| {
                let angle = k as f64 / 40.0 * std::f64::consts::TAU * 0.98;
                StrokePoint::new(DVec2::new(100.0 * angle.cos(), 100.0 * angle.sin()), 0.5)
            })
            .collect();
        assert!(is_closed_loop(&circle, 20.0));
        assert!(!is_closed_loop(&circle, 5.0));
        // A short dash has both ends within the tolerance but is not a loop.
        assert!(!is_closed_loop(&line(&[(0.0, 0.0), (8.0, 0.0)]), 20.0));
        assert!(!is_closed_loop(&[], 20.0));
    }
}

//! Arclength: total length, the cumulative table, and lookups by arclength or by fractional
//! point index.

use std::borrow::Borrow;

use glam::DVec2;

/// Length of the polyline through `points` (0 for fewer than two).
///
/// Takes any sequence of points, so that a slice (`length(&points)`) and positions read out
/// of richer samples (`length(stroke.iter().map(|p| p.pos))`) both work without copying.
pub fn length<P: Borrow<DVec2>>(points: impl IntoIterator<Item = P>) -> f64 {
    let mut points = points.into_iter();
    let Some(first) = points.next() else {
        return 0.0;
    };
    let mut previous = *first.borrow();
    let mut total = 0.0;
    for p in points {
        let p = *p.borrow();
        total += previous.distance(p);
        previous = p;
    }
    total
}

/// Arclength at each point, starting at 0; the last entry is the [`length`].
pub fn cumulative_lengths(points: &[DVec2]) -> Vec<f64> {
    let mut out = Vec::with_capacity(points.len());
    let mut total = 0.0;
    for (i, p) in points.iter().enumerate() {
        if i > 0 {
            total += p.distance(points[i - 1]);
        }
        out.push(total);
    }
    out
}

/// Relative arclength of each point, in `[0, 1]`; spread evenly by index when the length is
/// zero.
pub fn relative_arclengths(points: &[DVec2]) -> Vec<f64> {
    let cumulative = cumulative_lengths(points);
    let Some(&length) = cumulative.last() else {
        return Vec::new();
    };
    if length > 0.0 {
        cumulative.iter().map(|s| s / length).collect()
    } else {
        let last = (points.len() - 1).max(1) as f64;
        (0..points.len()).map(|i| i as f64 / last).collect()
    }
}

/// The segment `i` (from point `i` to `i + 1`) that contains arclength `s`, clamped to the
/// polyline; at a point shared by two segments, the later one. `cumulative` is a
/// [`cumulative_lengths`] table of at least two points.
pub fn segment_at(cumulative: &[f64], s: f64) -> usize {
    let after = cumulative.partition_point(|&c| c <= s);
    after
        .saturating_sub(1)
        .min(cumulative.len().saturating_sub(2))
}

/// Fractional point index at arclength `s` (clamped): `i + t` on segment `i`.
pub fn index_at(cumulative: &[f64], s: f64) -> f64 {
    if cumulative.len() < 2 {
        return 0.0;
    }
    let i = segment_at(cumulative, s);
    let length = cumulative[i + 1] - cumulative[i];
    let t = if length > 0.0 {
        ((s - cumulative[i]) / length).clamp(0.0, 1.0)
    } else {
        0.0
    };
    i as f64 + t
}

/// The point at arclength `s` (clamped to the polyline), with `cumulative` its
/// [`cumulative_lengths`]. The origin for no points.
pub fn point_at(points: &[DVec2], cumulative: &[f64], s: f64) -> DVec2 {
    if points.len() < 2 {
        return points.first().copied().unwrap_or(DVec2::ZERO);
    }
    point_at_index(points, index_at(cumulative, s))
}

/// The point at fractional index `t` (clamped): `t = i + f` lies a fraction `f` of the way
/// from point `i` to point `i + 1`. The origin for no points.
pub fn point_at_index(points: &[DVec2], t: f64) -> DVec2 {
    if points.len() < 2 {
        return points.first().copied().unwrap_or(DVec2::ZERO);
    }
    let t = t.clamp(0.0, (points.len() - 1) as f64);
    let i = (t.floor() as usize).min(points.len() - 2);
    points[i].lerp(points[i + 1], t - i as f64)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An L: 3 along x, then 1 along y.
    fn l_shape() -> [DVec2; 3] {
        [DVec2::ZERO, DVec2::new(3.0, 0.0), DVec2::new(3.0, 1.0)]
    }

    #[test]
    fn lengths_of_known_polylines() {
        let points = [DVec2::ZERO, DVec2::new(3.0, 4.0), DVec2::new(3.0, 10.0)];
        assert_eq!(length(points), 11.0);
        assert_eq!(length(points.iter().map(|p| 2.0 * *p)), 22.0);
        assert_eq!(length(&points[..1]), 0.0);
        assert_eq!(length(&[] as &[DVec2]), 0.0);
        assert_eq!(cumulative_lengths(&points), vec![0.0, 5.0, 11.0]);
        assert!(cumulative_lengths(&[]).is_empty());
    }

    #[test]
    fn relative_arclengths_by_length_or_by_index() {
        assert_eq!(relative_arclengths(&l_shape()), vec![0.0, 0.75, 1.0]);
        assert_eq!(relative_arclengths(&[DVec2::ONE; 3]), vec![0.0, 0.5, 1.0]);
        assert_eq!(relative_arclengths(&[DVec2::ONE]), vec![0.0]);
        assert!(relative_arclengths(&[]).is_empty());
    }

    #[test]
    fn lookups_on_an_uneven_l_shape() {
        let points = l_shape();
        let cumulative = cumulative_lengths(&points);
        assert_eq!(cumulative, vec![0.0, 3.0, 4.0]);
        assert_eq!(segment_at(&cumulative, 3.0), 1);
        assert_eq!(segment_at(&cumulative, -1.0), 0);
        assert_eq!(segment_at(&cumulative, 9.0), 1);
        assert_eq!(index_at(&cumulative, 1.5), 0.5);
        assert_eq!(index_at(&cumulative, 3.5), 1.5);
        assert_eq!(index_at(&cumulative, 9.0), 2.0);
        assert_eq!(point_at(&points, &cumulative, 3.25), DVec2::new(3.0, 0.25));
        assert_eq!(point_at(&points, &cumulative, -2.0), DVec2::ZERO);
        assert_eq!(point_at_index(&points, 1.25), DVec2::new(3.0, 0.25));
        assert_eq!(point_at_index(&points, 7.0), DVec2::new(3.0, 1.0));
        assert_eq!(point_at(&points[..1], &cumulative[..1], 1.0), DVec2::ZERO);
        assert_eq!(point_at_index(&[], 1.0), DVec2::ZERO);
    }
}

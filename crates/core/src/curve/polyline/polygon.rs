//! Closed polygons: perimeter, signed area, centroid and containment.

use std::borrow::Borrow;
use std::iter::once;

use glam::DVec2;

/// Length of a closed polygon, closing edge included (added last). Like
/// [`super::length`], takes any sequence of points.
pub fn perimeter<P: Borrow<DVec2>>(points: impl IntoIterator<Item = P>) -> f64 {
    let mut points = points.into_iter().map(|p| *p.borrow());
    let Some(first) = points.next() else {
        return 0.0;
    };
    super::length(once(first).chain(points).chain(once(first)))
}

/// Signed area of a closed polygon (shoelace formula): positive when it runs
/// counter-clockwise with y up, that is clockwise on a y-down screen.
pub fn signed_area(points: &[DVec2]) -> f64 {
    let n = points.len();
    0.5 * (0..n)
        .map(|i| points[i].perp_dot(points[(i + 1) % n]))
        .sum::<f64>()
}

/// Area centroid of a closed polygon; the vertex mean when the area vanishes (the origin
/// for no points).
pub fn centroid(points: &[DVec2]) -> DVec2 {
    let n = points.len();
    let area = signed_area(points);
    if area.abs() < 1e-300 {
        return points.iter().copied().sum::<DVec2>() / n.max(1) as f64;
    }
    let sum: DVec2 = (0..n)
        .map(|i| {
            let (a, b) = (points[i], points[(i + 1) % n]);
            (a + b) * a.perp_dot(b)
        })
        .sum();
    sum / (6.0 * area)
}

/// Whether `p` lies inside the closed polygon (even-odd rule, so the holes of a
/// self-crossing polygon are outside). Points on the boundary may count either way.
pub fn contains(points: &[DVec2], p: DVec2) -> bool {
    let n = points.len();
    let mut inside = false;
    for i in 0..n {
        let (a, b) = (points[i], points[(i + 1) % n]);
        if (a.y > p.y) != (b.y > p.y) {
            let x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
            if p.x < x {
                inside = !inside;
            }
        }
    }
    inside
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> Vec<DVec2> {
        vec![
            DVec2::new(0.0, 0.0),
            DVec2::new(2.0, 0.0),
            DVec2::new(2.0, 2.0),
            DVec2::new(0.0, 2.0),
        ]
    }

    #[test]
    fn area_perimeter_centroid_and_containment_of_a_square() {
        let s = square();
        assert_eq!(signed_area(&s), 4.0);
        assert_eq!(perimeter(&s), 8.0);
        assert_eq!(perimeter(s.iter().map(|p| 3.0 * *p)), 24.0);
        assert!((centroid(&s) - DVec2::ONE).length() < 1e-15);
        assert!(contains(&s, DVec2::new(0.5, 1.5)));
        assert!(!contains(&s, DVec2::new(2.5, 1.0)));
        assert!(!contains(&s, DVec2::new(1.0, -0.5)));
        let reversed: Vec<DVec2> = s.iter().rev().copied().collect();
        assert_eq!(signed_area(&reversed), -4.0);
    }

    #[test]
    fn a_triangle_and_degenerate_polygons() {
        let triangle = [DVec2::ZERO, DVec2::new(3.0, 0.0), DVec2::new(0.0, 4.0)];
        assert_eq!(signed_area(&triangle), 6.0);
        assert_eq!(perimeter(triangle), 12.0);
        assert!((centroid(&triangle) - DVec2::new(1.0, 4.0 / 3.0)).length() < 1e-15);
        // A flat polygon has no area; its centroid is the vertex mean.
        let flat = [DVec2::ZERO, DVec2::new(4.0, 0.0), DVec2::new(2.0, 0.0)];
        assert_eq!(signed_area(&flat), 0.0);
        assert_eq!(centroid(&flat), DVec2::new(2.0, 0.0));
        assert_eq!(perimeter([DVec2::ONE]), 0.0);
        assert_eq!(perimeter(&[] as &[DVec2]), 0.0);
        assert_eq!(centroid(&[]), DVec2::ZERO);
        assert!(!contains(&[], DVec2::ZERO));
    }

    #[test]
    fn an_l_shaped_polygon_leaves_its_notch_out() {
        let l = [(0, 0), (4, 0), (4, 1), (1, 1), (1, 4), (0, 4)]
            .map(|(x, y)| DVec2::new(x as f64, y as f64));
        assert_eq!(signed_area(&l), 7.0);
        assert!(contains(&l, DVec2::new(0.5, 3.0)));
        assert!(contains(&l, DVec2::new(3.0, 0.5)));
        assert!(!contains(&l, DVec2::new(2.0, 2.0)));
    }
}

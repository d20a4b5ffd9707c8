//! The point of a triangle nearest to a point, for distances to a surface (Hausdorff
//! distances, snapping).

use glam::DVec3;

/// Barycentric coordinates of `p` projected onto the triangle's plane.
pub fn barycentric([a, b, c]: [DVec3; 3], p: DVec3) -> DVec3 {
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d00, d01, d11) = (ab.dot(ab), ab.dot(ac), ac.dot(ac));
    let (d20, d21) = (ap.dot(ab), ap.dot(ac));
    let denominator = d00 * d11 - d01 * d01;
    let v = (d11 * d20 - d01 * d21) / denominator;
    let w = (d00 * d21 - d01 * d20) / denominator;
    DVec3::new(1.0 - v - w, v, w)
}

/// The point of triangle `[a, b, c]` nearest to `p`, by the Voronoi regions of its corners,
/// edges and face (Ericson, *Real-Time Collision Detection*, §5.1.5). Degenerate triangles
/// give a point on one of their edges.
pub fn closest_point_on_triangle(p: DVec3, [a, b, c]: [DVec3; 3]) -> DVec3 {
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(ap), ac.dot(ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return a;
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(bp), ac.dot(bp));
    if d3 >= 0.0 && d4 <= d3 {
        return b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return a + ab * (d1 / (d1 - d3));
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(cp), ac.dot(cp));
    if d6 >= 0.0 && d5 <= d6 {
        return c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return a + ac * (d2 / (d2 - d6));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 {
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    let denominator = va + vb + vc;
    if denominator == 0.0 {
        // A degenerate triangle: its nearest edge point.
        let on = |u: DVec3, v: DVec3| {
            let t = ((p - u).dot(v - u) / (v - u).length_squared()).clamp(0.0, 1.0);
            if t.is_finite() { u.lerp(v, t) } else { u }
        };
        return [on(a, b), on(b, c), on(c, a)]
            .into_iter()
            .min_by(|x, y| x.distance_squared(p).total_cmp(&y.distance_squared(p)))
            .unwrap_or(a);
    }
    a + ab * (vb / denominator) + ac * (vc / denominator)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nearest_points_in_each_region() {
        let t = [DVec3::ZERO, DVec3::X, DVec3::Y];
        let cases = [
            (DVec3::new(0.2, 0.3, 5.0), DVec3::new(0.2, 0.3, 0.0)),
            (DVec3::new(-1.0, -1.0, 0.0), DVec3::ZERO),
            (DVec3::new(3.0, -1.0, 1.0), DVec3::X),
            (DVec3::new(0.5, -2.0, 0.0), DVec3::new(0.5, 0.0, 0.0)),
            (DVec3::new(1.0, 1.0, 0.0), DVec3::new(0.5, 0.5, 0.0)),
            (DVec3::new(-3.0, 0.4, 0.0), DVec3::new(0.0, 0.4, 0.0)),
        ];
        for (p, expected) in cases {
            let q = closest_point_on_triangle(p, t);
            assert!(q.distance(expected) < 1e-12, "{p} -> {q}, not {expected}");
        }
        let flat = [DVec3::ZERO, DVec3::X, DVec3::X * 2.0];
        let q = closest_point_on_triangle(DVec3::new(1.5, 1.0, 0.0), flat);
        assert!(q.distance(DVec3::new(1.5, 0.0, 0.0)) < 1e-12);
    }
}

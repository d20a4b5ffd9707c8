//! Ray casting against a mesh: which surface point lies under the pointer.
//!
//! A linear scan over the triangles with the Möller–Trumbore test. It runs once per
//! gesture (to decide whether a stroke starts on a model), not per frame, so a scan of a
//! few hundred thousand triangles is cheap enough; [`Bvh`](super::Bvh) answers the many rays
//! per frame of silhouette visibility, and this scan is its reference in tests.

use glam::DVec3;

use crate::mesh::{FaceId, Mesh};

/// Where a ray meets a mesh.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RayHit {
    /// Distance along the (unit) ray direction.
    pub distance: f64,
    /// The triangle hit.
    pub face: FaceId,
    /// Barycentric coordinates of the hit in that triangle's corner order.
    pub barycentric: DVec3,
}

/// The nearest hit of the ray `origin + t·dir` (`t > 0`) with any triangle, front or back.
pub fn raycast(mesh: &Mesh, origin: DVec3, dir: DVec3) -> Option<RayHit> {
    let mut best: Option<RayHit> = None;
    for f in mesh.faces() {
        let [a, b, c] = mesh.face_positions(f);
        let Some((t, u, v)) = intersect_triangle(origin, dir, a, b, c) else {
            continue;
        };
        if best.is_none_or(|h| t < h.distance) {
            best = Some(RayHit {
                distance: t,
                face: f,
                barycentric: DVec3::new(1.0 - u - v, u, v),
            });
        }
    }
    best
}

/// Whether the segment from `from` to `to` passes through the triangle `a b c` (a touch at
/// `from` does not count).
pub(crate) fn segment_crosses_triangle(
    from: DVec3,
    to: DVec3,
    a: DVec3,
    b: DVec3,
    c: DVec3,
) -> bool {
    intersect_triangle(from, to - from, a, b, c).is_some_and(|(t, _, _)| t <= 1.0)
}

/// Möller–Trumbore: `(t, u, v)` with the hit at `a + u (b − a) + v (c − a)`.
pub(crate) fn intersect_triangle(
    origin: DVec3,
    dir: DVec3,
    a: DVec3,
    b: DVec3,
    c: DVec3,
) -> Option<(f64, f64, f64)> {
    let (ab, ac) = (b - a, c - a);
    let p = dir.cross(ac);
    let det = ab.dot(p);
    if det.abs() < 1e-14 * ab.length_squared().max(ac.length_squared()) {
        return None;
    }
    let inv = 1.0 / det;
    let s = origin - a;
    let u = s.dot(p) * inv;
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    let q = s.cross(ab);
    let v = dir.dot(q) * inv;
    if v < 0.0 || u + v > 1.0 {
        return None;
    }
    let t = ac.dot(q) * inv;
    (t > 0.0).then_some((t, u, v))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives::icosphere;

    #[test]
    fn ray_through_a_sphere_hits_its_near_side() {
        let sphere = icosphere(2.0, 3);
        let hit = raycast(&sphere, DVec3::new(0.1, 0.2, 10.0), DVec3::NEG_Z).expect("hit");
        // The polyhedron lies inside the sphere, so the hit is within a few percent of z = 2.
        let z = 10.0 - hit.distance;
        assert!((z - 2.0).abs() < 0.05, "hit at z = {z}");
        assert!((hit.barycentric.element_sum() - 1.0).abs() < 1e-12);
        assert!(hit.barycentric.min_element() >= 0.0);
    }

    #[test]
    fn ray_beside_or_away_misses() {
        let sphere = icosphere(1.0, 2);
        assert!(raycast(&sphere, DVec3::new(3.0, 0.0, 10.0), DVec3::NEG_Z).is_none());
        assert!(raycast(&sphere, DVec3::new(0.0, 0.0, 10.0), DVec3::Z).is_none());
    }
}

//! Hidden-part removal: one occlusion ray per silhouette point, then runs of equal
//! visibility.
//!
//! A point is visible when the segment from the eye (for an orthographic camera, from its
//! foot on the plane through the eye facing the view direction) to the point crosses no
//! triangle. The ray grazes the surface at a silhouette, and on a polyhedron with noisy
//! normals the zero crossing may sit an edge or two past the true contour, on the far side,
//! where the ray cuts the surface just before reaching it (a point an angle `δ` behind the
//! contour of a sphere of radius `R` is hidden by a chord of length `2Rδ`). So the ray aims at
//! the point moved outwards along its interpolated normal (which is perpendicular to the view
//! ray) by [`OFFSET_EDGES`] lengths of its edge, which clears a sphere for `δ` up to
//! `√(2·offset/R)`, and hits within [`MARGIN_EDGES`] edge lengths of that target do not count.
//! The price: an occluder that covers the silhouette by less than the offset, or lies closer
//! than the margin (a fold of the size of a triangle), is missed.
//!
//! Hertzmann and Zorin, and SEED (§3.2), note that visibility changes only at cusps and
//! crossings of curves; testing every point instead finds those changes without locating
//! cusps, to within the point spacing.

use glam::DVec3;

use super::points::SilhouettePoint;
use crate::camera::Camera;
use crate::geometry::Bvh;
use crate::mesh::Mesh;

/// The ray aims this many lengths of the point's edge outside the surface.
pub(super) const OFFSET_EDGES: f64 = 0.25;
/// Hits closer to the target than this many lengths of its edge do not hide it.
pub(super) const MARGIN_EDGES: f64 = 1.0;

/// Whether the viewer sees the point, by one ray through the hierarchy; `normals` are the
/// mesh's unit vertex normals.
pub(super) fn is_visible(
    mesh: &Mesh,
    bvh: &Bvh,
    camera: &Camera,
    normals: &[DVec3],
    point: &SilhouettePoint,
) -> bool {
    let [a, b] = point.edge;
    let edge_length = mesh.position(a).distance(mesh.position(b));
    let normal = normals[a.index()]
        .lerp(normals[b.index()], point.t)
        .normalize_or_zero();
    let target = point.world + OFFSET_EDGES * edge_length * normal;
    !bvh.occluded(
        mesh,
        ray_origin(camera, target),
        target,
        MARGIN_EDGES * edge_length,
    )
}

/// Where the sight line to `target` starts: the eye, or for an orthographic camera the
/// target's foot on the plane through the eye facing the view direction.
pub(super) fn ray_origin(camera: &Camera, target: DVec3) -> DVec3 {
    match camera.ortho_height {
        Some(_) => {
            let forward = camera.forward();
            target - forward * (target - camera.eye).dot(forward)
        }
        None => camera.eye,
    }
}

/// Flips every flag whose two neighbours both disagree with it: a single ray that grazes a
/// triangle edge, not a change of visibility.
pub(super) fn drop_lone_flips(flags: &mut [bool], is_closed: bool) {
    let n = flags.len();
    if n < 3 {
        return;
    }
    let original = flags.to_vec();
    let inner = if is_closed { 0..n } else { 1..n - 1 };
    for i in inner {
        let (previous, next) = (original[(i + n - 1) % n], original[(i + 1) % n]);
        if previous == next && previous != original[i] {
            flags[i] = previous;
        }
    }
}

/// The maximal runs of consecutive `Some` items, each with whether it is closed (only a
/// closed sequence with no `None` stays closed). A closed sequence's run that wraps past its
/// end comes out in one piece.
pub(super) fn split_runs<T: Copy>(items: &[Option<T>], is_closed: bool) -> Vec<(Vec<T>, bool)> {
    let n = items.len();
    // Start a closed sequence right after a `None` so that no run wraps around.
    let start = match items.iter().position(Option::is_none) {
        None => {
            let all: Vec<T> = items.iter().flatten().copied().collect();
            return if all.is_empty() {
                Vec::new()
            } else {
                vec![(all, is_closed)]
            };
        }
        Some(first_none) if is_closed => first_none + 1,
        Some(_) => 0,
    };
    let mut runs = Vec::new();
    let mut current = Vec::new();
    for k in 0..n {
        match items[(start + k) % n] {
            Some(item) => current.push(item),
            None if !current.is_empty() => runs.push((std::mem::take(&mut current), false)),
            None => {}
        }
    }
    if !current.is_empty() {
        runs.push((current, false));
    }
    runs
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn runs_of_a_closed_sequence_wrap_around() {
        let items = [Some(0), Some(1), None, Some(3), None, Some(5)];
        let runs = split_runs(&items, true);
        assert_eq!(runs, vec![(vec![3], false), (vec![5, 0, 1], false)]);
        let runs = split_runs(&items, false);
        assert_eq!(
            runs,
            vec![(vec![0, 1], false), (vec![3], false), (vec![5], false)]
        );
        let all = [Some(0), Some(1), Some(2)];
        assert_eq!(split_runs(&all, true), vec![(vec![0, 1, 2], true)]);
        assert!(split_runs(&[None::<u8>; 6], true).is_empty());
    }

    #[test]
    fn lone_flips_are_dropped_but_ends_of_open_runs_kept() {
        let mut flags = [true, false, true, true, false, false, true, false];
        drop_lone_flips(&mut flags, false);
        assert_eq!(flags, [true, true, true, true, false, false, false, false]);
        let mut flags = [false, true, true, true, true, true];
        drop_lone_flips(&mut flags, true);
        assert_eq!(flags, [true; 6]);
    }
}

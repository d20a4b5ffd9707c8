//! Stroke samples on the visible surface: resampled at about the mesh's edge length on
//! screen, each cast along its view ray onto the front-most triangle.

use glam::{DVec2, DVec3};

use crate::camera::Camera;
use crate::curve::polyline::resample;
use crate::geometry::Bvh;
use crate::mesh::{FaceId, Mesh};

/// Sample spacing as a fraction of the on-screen edge length: fine enough that the walk
/// between two samples stays on the sheet they lie on, coarse enough to stay cheap.
const SPACING_PER_EDGE: f64 = 0.75;
/// Spacing (px) of the samples that look for the stroke's first hit.
const SEARCH_SPACING_PX: f64 = 2.0;
/// The coarsest sample spacing (px), so that thin parts of coarse meshes get samples.
const MAX_SPACING_PX: f64 = 8.0;
/// Bisection steps of [`Projector::edge_of_surface`]: the sample spacing over 4096.
const BISECTIONS: usize = 12;
/// Two consecutive hits farther apart than this many edge lengths lie on different sheets
/// (the stroke passed over a silhouette onto a part behind).
const MAX_JUMP_EDGES: f64 = 4.0;

/// A stroke sample projected onto the surface.
#[derive(Clone, Copy, Debug)]
pub(super) struct SurfacePoint {
    /// The point on the surface.
    pub point: DVec3,
    /// The input triangle it lies in.
    pub face: FaceId,
    /// Its barycentric coordinates in that triangle.
    pub barycentric: DVec3,
    /// The unit view ray direction through the sample.
    pub ray_dir: DVec3,
}

/// Casts stroke points onto a mesh with one camera.
pub(super) struct Projector<'a> {
    pub mesh: &'a Mesh,
    pub bvh: Bvh,
    pub camera: &'a Camera,
    pub viewport: DVec2,
}

impl Projector<'_> {
    /// The front-most surface point under a screen point, if the ray hits.
    pub fn cast(&self, screen: DVec2) -> Option<SurfacePoint> {
        let (origin, ray_dir) = self.camera.ray_in_world(screen, self.viewport);
        let hit = self.bvh.raycast(self.mesh, origin, ray_dir)?;
        Some(SurfacePoint {
            point: origin + ray_dir * hit.distance,
            face: hit.face,
            barycentric: hit.barycentric,
            ray_dir,
        })
    }

    /// The stroke resampled at [`SPACING_PER_EDGE`] of the on-screen edge length where it
    /// first meets the surface (at most [`MAX_SPACING_PX`]), each sample with its hit (`None` where it misses). `None`
    /// overall when no point of the stroke hits.
    pub fn samples(&self, stroke: &[DVec2]) -> Option<Vec<(DVec2, Option<SurfacePoint>)>> {
        let first_hit = resample(stroke, SEARCH_SPACING_PX)
            .into_iter()
            .find_map(|s| self.cast(s))?;
        let spacing =
            (SPACING_PER_EDGE * self.edge_length_on_screen(first_hit.face)).min(MAX_SPACING_PX);
        Some(
            resample(stroke, spacing)
                .into_iter()
                .map(|s| (s, self.cast(s)))
                .collect(),
        )
    }

    /// The last hit on the way from a screen point that hits to one that misses, found by
    /// bisection: where the stroke leaves the visible surface.
    pub fn edge_of_surface(&self, hit: DVec2, miss: DVec2) -> Option<SurfacePoint> {
        let (mut inside, mut outside) = (hit, miss);
        let mut last = self.cast(inside)?;
        for _ in 0..BISECTIONS {
            let middle = 0.5 * (inside + outside);
            match self.cast(middle) {
                Some(point) => (inside, last) = (middle, point),
                None => outside = middle,
            }
        }
        Some(last)
    }

    /// Whether two consecutive hits lie on one sheet (no jump over a silhouette).
    pub fn is_continuous(&self, p: &SurfacePoint, q: &SurfacePoint) -> bool {
        p.point.distance(q.point) <= MAX_JUMP_EDGES * self.edge_length(p.face)
    }

    /// The mean edge length of an input triangle in world units.
    fn edge_length(&self, face: FaceId) -> f64 {
        let [a, b, c] = self.mesh.face_positions(face);
        (a.distance(b) + b.distance(c) + c.distance(a)) / 3.0
    }

    /// The mean edge length of an input triangle on the screen, in px (at least 1).
    fn edge_length_on_screen(&self, face: FaceId) -> f64 {
        let corners = self
            .mesh
            .face_positions(face)
            .map(|p| self.camera.screen_from_world(p, self.viewport));
        let [Some(a), Some(b), Some(c)] = corners else {
            return 1.0;
        };
        let (a, b, c) = (a.truncate(), b.truncate(), c.truncate());
        ((a.distance(b) + b.distance(c) + c.distance(a)) / 3.0).max(1.0)
    }
}

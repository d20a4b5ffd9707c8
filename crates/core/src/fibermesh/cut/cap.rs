//! The cap that closes a cut: the section laid flat, meshed in 2D, and put back on the
//! cutting surface (FiberMesh §3.3.3: "the cut section is flattened (it is always
//! developable) and meshed in 2D").
//!
//! The cutting surface is swept by the view rays through the stroke, so a point on it has
//! two coordinates: the arclength `u` (px) of its screen position along the stroke, the
//! stroke's ends extended straight, and its depth `d` along the view direction. Laying the
//! surface flat as `(u · scale, d)`, with `scale` the world size of a pixel at the section's
//! depth, is exact for an orthographic camera (the surface is a generalised cylinder, and
//! this is its development) and close for a perspective one over the depth of a shape; the
//! way back, [`Unrolling::lift`], is exact either way, so every cap vertex lies on the
//! cutting surface.

use glam::{DVec2, DVec3};

use super::CutError;
use crate::camera::Camera;
use crate::curve::polyline::{closest_point, cumulative_lengths, point_at, signed_area};
use crate::fibermesh::triangulate::triangulate;

/// How far (in stroke lengths) the stroke's ends are extended, so that every point of the
/// section finds its arclength on the extended line rather than at an end.
const EXTENSION_LENGTHS: f64 = 100.0;

/// The cutting surface's flat coordinates; see the module docs.
pub(super) struct Unrolling<'a> {
    camera: &'a Camera,
    viewport: DVec2,
    /// The stroke with its ends extended.
    line: Vec<DVec2>,
    cumulative: Vec<f64>,
    /// Arclength of the stroke's first point on `line`.
    start: f64,
    /// World units per px at the section's depth.
    scale: f64,
}

impl<'a> Unrolling<'a> {
    /// The unrolling of the surface swept by `polyline` (at least two distinct points),
    /// with the scale taken at `depth`.
    pub fn new(camera: &'a Camera, viewport: DVec2, polyline: &[DVec2], depth: f64) -> Self {
        let n = polyline.len();
        let length = cumulative_lengths(polyline)[n - 1];
        let reach = EXTENSION_LENGTHS * length;
        let head = (polyline[0] - polyline[1]).normalize_or_zero() * reach;
        let tail = (polyline[n - 1] - polyline[n - 2]).normalize_or_zero() * reach;
        let mut line = vec![polyline[0] + head];
        line.extend_from_slice(polyline);
        line.push(polyline[n - 1] + tail);
        let cumulative = cumulative_lengths(&line);
        let mut unrolling = Unrolling {
            camera,
            viewport,
            start: cumulative[1],
            line,
            cumulative,
            scale: 1.0,
        };
        let centre = 0.5 * viewport;
        let one_px =
            unrolling.at_depth(centre + DVec2::X, depth) - unrolling.at_depth(centre, depth);
        unrolling.scale = one_px.length();
        unrolling
    }

    /// The flat coordinates of a point on the cutting surface; `None` behind the eye.
    pub fn flat(&self, p: DVec3) -> Option<DVec2> {
        let screen = self.camera.screen_from_world(p, self.viewport)?;
        let u = closest_point(&self.line, &self.cumulative, screen.truncate()).arclength;
        Some(DVec2::new((u - self.start) * self.scale, screen.z))
    }

    /// The point of the cutting surface at flat coordinates `q`.
    pub fn lift(&self, q: DVec2) -> DVec3 {
        let screen = point_at(&self.line, &self.cumulative, q.x / self.scale + self.start);
        self.at_depth(screen, q.y)
    }

    /// The point at view depth `depth` on the ray through `screen`.
    fn at_depth(&self, screen: DVec2, depth: f64) -> DVec3 {
        let (origin, dir) = self.camera.ray_in_world(screen, self.viewport);
        origin + dir * (depth / dir.dot(self.camera.forward()))
    }
}

/// A cap over one rim: new interior points and triangles whose corners index the rim
/// (`0..rim.len()`) and then the interior points.
pub(super) struct Cap {
    pub interior: Vec<DVec3>,
    pub triangles: Vec<[u32; 3]>,
}

/// Meshes the cap over a rim laid flat as `outline`, oriented so that it traverses each rim
/// edge against the kept faces: those hold `rim[k] → rim[k + 1]` when `kept_forward`.
///
/// Errors: [`CutError::ThinSection`] when the section cannot be meshed.
pub(super) fn mesh_cap(
    outline: &[DVec2],
    unrolling: &Unrolling,
    kept_forward: bool,
) -> Result<Cap, CutError> {
    let n = outline.len();
    let spacing = (0..n)
        .map(|k| outline[k].distance(outline[(k + 1) % n]))
        .sum::<f64>()
        / n as f64;
    let planar = triangulate(outline, spacing).map_err(|_| CutError::ThinSection)?;
    let interior = planar.points[n..]
        .iter()
        .map(|&q| unrolling.lift(q))
        .collect();
    // A counter-clockwise outline has its inside to the left of rim[k] → rim[k + 1], so the
    // planar triangles run forward along the rim; the cap must run against the kept faces.
    let cap_forward = signed_area(outline) > 0.0;
    let flip = cap_forward == kept_forward;
    let triangles = planar
        .triangles
        .iter()
        .map(|&[a, b, c]| if flip { [a, c, b] } else { [a, b, c] })
        .collect();
    Ok(Cap {
        interior,
        triangles,
    })
}

//! Extrusion (FiberMesh, Nealen's thesis §3.2.1, Fig. 3.3; Teddy's extrusion): a closed loop
//! drawn on a shape, then a stroke from near one side of it out beside the shape and back to
//! near the other side, grows a limb whose silhouette is that stroke.
//!
//! The loop is embedded (`add_curve`) and the disk it bounds removed, as for a tunnel. The
//! silhouette stroke is laid on the plane through the loop's middle facing its camera and
//! split at its arclength middle into two sides, paired by arclength fraction, with the
//! rest of the way from the loop's vertices under the stroke's ends to the stroke's ends
//! faded out along the limb. Each pair places a ring (`limb.rs`): a copy of the loop moved,
//! turned and scaled so that those two loop vertices land on the pair. The rings end at the
//! stroke's middle, the tip. The loop's vertex under the stroke's start, the rings' vertices
//! on the left side, the tip, and the right side back to the loop form the silhouette
//! chain. The limb is a sweep, not a fair surface: the caller re-optimizes it. The tip must
//! lie outside the shape, and the result must be closed, manifold and free of crossing
//! triangles: anything else is refused.

mod error;
mod limb;

pub use error::ExtrudeError;

use glam::{DVec2, DVec3};
use rustc_hash::FxHashSet;

use super::opening::{disk, kept_forward, middle};
use crate::curve::polyline::{cumulative_lengths, point_at};
use crate::fibermesh::ViewedStroke;
use crate::fibermesh::add_curve::{CurveShape, add_curve};
use crate::geometry::Bvh;
use crate::mesh::{FaceId, Mesh, TriSoup, VertexId};

/// How far (CSS px) the silhouette's ends may be from the base loop on screen.
pub const NEAR_BASE_PX: f64 = 40.0;

/// A shape with a limb.
#[derive(Clone, Debug)]
pub struct Extrusion {
    /// The shape with the limb in place (swept: the caller settles it).
    pub mesh: Mesh,
    /// The base loop, a closed chain of `mesh` vertices where the limb meets the shape.
    pub base: Vec<VertexId>,
    /// The silhouette, an open chain of `mesh` vertices from the base over the tip back to
    /// the base.
    pub silhouette: Vec<VertexId>,
    /// Whether each vertex of `mesh` is one of the limb's (not the base loop's).
    pub is_limb: Vec<bool>,
    /// Every edge the base loop split, in the numbering of the input mesh with the split
    /// vertices appended.
    pub split_edges: Vec<(VertexId, VertexId, VertexId)>,
    /// Where each vertex of that numbering went in `mesh`, `None` for removed ones.
    pub remap: Vec<Option<VertexId>>,
}

/// Grows a limb out of the closed `mesh` at the loop `base` with the silhouette
/// `silhouette`. See the module docs.
///
/// Errors: [`ExtrudeError`], as sentences for the user.
pub fn extrude(
    mesh: &Mesh,
    base: ViewedStroke,
    silhouette: ViewedStroke,
) -> Result<Extrusion, ExtrudeError> {
    if !mesh.is_closed() {
        return Err(ExtrudeError::NotClosed);
    }
    let embedded = add_curve(
        mesh,
        base.camera,
        base.viewport,
        base.stroke,
        CurveShape::Closed,
    )
    .map_err(ExtrudeError::Base)?;
    let split = embedded.mesh;
    let removed: FxHashSet<FaceId> = disk(&split, &embedded.chain).into_iter().collect();
    let rim = kept_forward(&split, &removed, &embedded.chain);
    let rim_positions: Vec<DVec3> = rim.iter().map(|&v| split.position(v)).collect();
    let ends = silhouette_ends(&rim_positions, silhouette)?;
    let spacing = split.mean_edge_length();
    let sides = sides(&rim_positions, ends, silhouette, spacing)?;
    let tip = sides[sides.len() - 1].0;
    if Bvh::new(&split).contains(&split, tip) {
        return Err(ExtrudeError::Inward);
    }
    let limb = limb::limb(&rim_positions, ends, &sides, spacing);
    let n_split = split.n_vertices();
    let n_rim = rim.len() as u32;
    let corner = |i: u32| {
        if i < n_rim {
            rim[i as usize]
        } else {
            VertexId(n_split as u32 + i - n_rim)
        }
    };
    let mut soup = TriSoup {
        positions: split.positions().to_vec(),
        triangles: (split.faces())
            .filter(|f| !removed.contains(f))
            .map(|f| split.triangles()[f.index()])
            .collect(),
    };
    soup.positions.extend(&limb.positions);
    soup.triangles
        .extend(limb.triangles.iter().map(|t| t.map(|i| corner(i).0)));
    let kept_vertices = soup.remove_unreferenced_vertices();
    let result = Mesh::from_soup(&soup).map_err(|e| ExtrudeError::Broken(Some(e)))?;
    let remap: Vec<Option<VertexId>> = kept_vertices.iter().map(|k| k.map(VertexId)).collect();
    let mut is_limb = vec![false; result.n_vertices()];
    for v in remap[n_split..].iter().flatten() {
        is_limb[v.index()] = true;
    }
    let mapped = |v: VertexId| remap[v.index()];
    let base: Vec<VertexId> = rim.iter().filter_map(|&v| mapped(v)).collect();
    let silhouette: Vec<VertexId> = (limb.silhouette.iter())
        .filter_map(|&i| mapped(corner(i)))
        .collect();
    let on_limb = |f: FaceId| {
        result
            .face_vertices(f)
            .iter()
            .any(|v: &VertexId| is_limb[v.index()])
    };
    let same_genus = result.genus().is_some() && result.genus() == mesh.genus();
    let crossing = !Bvh::new(&result)
        .crossing_faces(&result, on_limb)
        .is_empty();
    if !result.is_closed() || !same_genus || crossing {
        return Err(ExtrudeError::Broken(None));
    }
    Ok(Extrusion {
        mesh: result,
        base,
        silhouette,
        is_limb,
        split_edges: embedded.split_edges,
        remap: remap[..n_split].to_vec(),
    })
}

/// The rim vertices nearest on screen to the silhouette's start and end.
///
/// Errors: [`ExtrudeError::NotNearBase`] when either end is farther than [`NEAR_BASE_PX`]
/// from the rim, or both are nearest to one vertex.
fn silhouette_ends(rim: &[DVec3], silhouette: ViewedStroke) -> Result<[usize; 2], ExtrudeError> {
    let on_screen: Vec<Option<DVec2>> = (rim.iter())
        .map(|&p| {
            let screen = silhouette.camera.screen_from_world(p, silhouette.viewport);
            screen.map(|s| s.truncate())
        })
        .collect();
    let nearest = |target: Option<&DVec2>| {
        let target = *target?;
        (on_screen.iter().enumerate())
            .filter_map(|(i, p)| p.map(|p| (p.distance(target), i)))
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .filter(|&(distance, _)| distance <= NEAR_BASE_PX)
            .map(|(_, i)| i)
    };
    match (
        nearest(silhouette.stroke.first()),
        nearest(silhouette.stroke.last()),
    ) {
        (Some(a), Some(b)) if a != b => Ok([a, b]),
        _ => Err(ExtrudeError::NotNearBase),
    }
}

/// The silhouette's (left, right) pairs, about `spacing` apart along the limb, from the
/// rim's `ends` to the tip, on the plane through the rim's middle facing the silhouette's
/// camera. The gap between each rim end and the stroke end near it fades out with the
/// square of the way along, so the first pair is the rim's ends.
fn sides(
    rim: &[DVec3],
    ends: [usize; 2],
    silhouette: ViewedStroke,
    spacing: f64,
) -> Result<Vec<(DVec3, DVec3)>, ExtrudeError> {
    let stroke = silhouette.stroke;
    let cumulative = cumulative_lengths(stroke);
    let half = 0.5 * cumulative[cumulative.len() - 1];
    let through = middle(rim);
    let on_plane = |s: f64| {
        let screen = point_at(stroke, &cumulative, s);
        (silhouette.camera)
            .point_on_plane_through(through, screen, silhouette.viewport)
            .ok_or(ExtrudeError::Broken(None))
    };
    let (left_start, right_start) = (on_plane(0.0)?, on_plane(2.0 * half)?);
    let gaps = (rim[ends[0]] - left_start, rim[ends[1]] - right_start);
    let pair = |t: f64| -> Result<(DVec3, DVec3), ExtrudeError> {
        let fade = (1.0 - t) * (1.0 - t);
        let left = on_plane(t * half)? + fade * gaps.0;
        let right = on_plane(2.0 * half - t * half)? + fade * gaps.1;
        Ok((left, right))
    };
    let fine = (0..=AXIS_SAMPLES)
        .map(|i| pair(i as f64 / AXIS_SAMPLES as f64).map(|(l, r)| 0.5 * (l + r)))
        .collect::<Result<Vec<DVec3>, _>>()?;
    let axis_length: f64 = fine.windows(2).map(|w| w[0].distance(w[1])).sum();
    let steps = ((axis_length / spacing).round() as usize).max(2);
    (0..=steps).map(|k| pair(k as f64 / steps as f64)).collect()
}

/// Samples along the silhouette's sides for measuring the limb's length.
const AXIS_SAMPLES: usize = 64;

#[cfg(test)]
mod tests;

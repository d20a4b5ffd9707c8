//! View-dependent silhouettes of a mesh, the curves a user over-sketches.
//!
//! Object-space smooth silhouettes (Hertzmann and Zorin 2000; Nealen's thesis §4.3, SEED
//! §3.1): the per-vertex function `g(v) = n(v)·(v − eye)` (orthographic: `n(v)·forward`) is
//! interpolated linearly along edges, its zero crossings are chained face to face into
//! curves (`contour.rs`), the points are thinned to about [`SPACING_PX`] on screen
//! (`spacing.rs`), the parts hidden behind the mesh are cut away with one occlusion ray per
//! point through a [`Bvh`] (`visibility.rs`), pieces shorter than [`MIN_LENGTH_PX`] are
//! dropped, and the screen curve is smoothed with every point held near its edge, after SEED
//! (`smooth.rs`).
//!
//! Unlike image-space extraction (SilSketch, Nealen §5.4.1, which traces depth-map
//! discontinuities), every point here keeps the mesh edge it lies on, which is what a
//! deformation needs to turn a sketch into constraints.
//!
//! Limitations: the mesh boundary of an open surface is not an outline here (a contour
//! simply ends there), and neither are sharp creases (edge silhouettes, Nealen §4.3): both
//! would give points on edges where `g` does not change sign. Visibility changes are found
//! to within the point spacing, not at the exact cusp or crossing, and a piece may stop a few
//! px short of the curve that hides it. A rough surface adds small closed loops around bumps
//! (a matcher should prefer long curves).
//!
//! Cost: about 2–3.5 ms natively for 35–40k vertices (BENCHMARKS.md), mostly the occlusion
//! rays and the vertex normals.

mod contour;
mod edges;
mod points;
mod smooth;
mod spacing;
mod visibility;

use glam::DVec2;

pub use edges::{
    OutlineChain, OutlineEdge, edge_silhouettes, outline_chains, outline_edges,
    outline_edges_touching,
};
pub use points::{Silhouette, SilhouettePoint};

use crate::camera::Camera;
use crate::geometry::{Bvh, vertex_normals};
use crate::mesh::Mesh;

/// Target screen distance between consecutive silhouette points, in CSS px.
pub const SPACING_PX: f64 = 2.5;
/// Visible pieces shorter than this on screen (CSS px) are dropped.
pub const MIN_LENGTH_PX: f64 = 4.0;
/// Width (standard deviation, CSS px of arc length) of the Gaussian that smooths silhouettes
/// on screen.
pub const SMOOTHING_SIGMA_PX: f64 = 3.0;

/// The visible smooth silhouettes of `mesh` seen by `camera` in a viewport of `viewport` CSS
/// px; `bvh` must be built (or refitted) for the mesh's current positions. Empty for an
/// invalid camera.
pub fn silhouettes(mesh: &Mesh, bvh: &Bvh, camera: &Camera, viewport: DVec2) -> Vec<Silhouette> {
    if !camera.is_valid() {
        return Vec::new();
    }
    let normals = vertex_normals(mesh);
    let g = contour::view_function(mesh, &normals, camera);
    let mut curves = Vec::new();
    for chain in contour::contour_chains(mesh, &g) {
        let in_front: Vec<Option<SilhouettePoint>> = chain
            .crossings
            .iter()
            .map(|c| {
                let projected = camera.screen_from_world(c.world, viewport)?;
                Some(SilhouettePoint {
                    screen: projected.truncate(),
                    depth: projected.z,
                    world: c.world,
                    edge: c.edge,
                    t: c.t,
                })
            })
            .collect();
        for (run, is_closed) in visibility::split_runs(&in_front, chain.is_closed) {
            let screen: Vec<DVec2> = run.iter().map(|p| p.screen).collect();
            let picked: Vec<SilhouettePoint> = spacing::pick_evenly(&screen, is_closed, SPACING_PX)
                .into_iter()
                .map(|i| run[i])
                .collect();
            let mut is_seen: Vec<bool> = picked
                .iter()
                .map(|p| visibility::is_visible(mesh, bvh, camera, &normals, p))
                .collect();
            visibility::drop_lone_flips(&mut is_seen, is_closed);
            let seen: Vec<Option<SilhouettePoint>> = picked
                .iter()
                .zip(&is_seen)
                .map(|(&p, &is_seen)| is_seen.then_some(p))
                .collect();
            for (points, closed) in visibility::split_runs(&seen, is_closed) {
                let mut curve = Silhouette { points, closed };
                if curve.screen_length() >= MIN_LENGTH_PX {
                    smooth_curve(mesh, &g, camera, viewport, &mut curve);
                    curves.push(curve);
                }
            }
        }
    }
    curves
}

fn smooth_curve(mesh: &Mesh, g: &[f64], camera: &Camera, viewport: DVec2, curve: &mut Silhouette) {
    let ends: Vec<Option<[DVec2; 2]>> = curve
        .points
        .iter()
        .map(|p| smooth::edge_band_ends(mesh, g, camera, viewport, p))
        .collect();
    let mut screen: Vec<DVec2> = curve.points.iter().map(|p| p.screen).collect();
    smooth::smooth_across(&mut screen, &ends, curve.closed, SMOOTHING_SIGMA_PX);
    for (point, smoothed) in curve.points.iter_mut().zip(screen) {
        point.screen = smoothed;
    }
}

//! How each kind of feature changes the region's Laplacian coordinates (§4.4.2, §4.4.3),
//! written as `Δδ = Σ_k c_k(amount) · b_k`: a few fixed vectors `b_k` (one entry per row of
//! the Laplacian system) and coefficients of the amount. The system is linear, so the
//! solution is the same sum over the solutions of the `b_k`: solved once each, a drag only
//! weighs them.
//!
//! - **Ridge** (sharp, on the path) and **bump** (smooth, on the whole region): the factor
//!   `a` gives `δ'_i = δ_i + (a − 1)·s·n_i`, where `s` is the mean of the Laplacians' normal
//!   parts `δ·n` over the path (the region, for a bump) and `n_i` the vertex normal. So 1
//!   changes nothing, 0 takes away the mean curvature there (flattens what is evenly
//!   curved), a negative factor turns a ridge into a ravine, and above 1 scales it up. This
//!   is Nealen's scaled Laplacian with his two fixes folded in: scaled normals where the
//!   Laplacian vanishes, and one amount for the whole sketch (his absolute variant), which
//!   suits a sketch along which curvature varies and keeps a scan's noise from being scaled
//!   with it. `|s|` is at least [`FLAT_LAPLACIAN`] times the mean length of the path's edges
//!   (the sign kept, raising on a flat part): the Laplacian of a gentle curve at that
//!   sampling. A feature's height then grows with the band's width, not with the mesh's
//!   resolution (a line of Laplacian `t` per vertex raises a tent about `2 t w / h` high over
//!   a band `w` wide with edges `h` long, and `t` grows with `h`).
//! - **Flatten**: `δ' = 0` on the region.
//! - **Suggestive**: each Laplacian turns by the angle `θ` about the axis `r̂` of the radial
//!   plane of its path vertex (through the path vertex, spanned by its normal and the view
//!   ray), the path vertex being the one minimising the distance to that plane plus the
//!   distance to the vertex. The part of `δ` along `r̂` (tangent to the surface, no
//!   curvature) is scaled by `cos θ` rather than kept, so that `δ' = cos θ·δ + sin θ·(r̂ ×
//!   δ)`: continuous in `θ`, linear in `(cos θ, sin θ)`, and a turn by π is exactly a
//!   scaling by −1, as Nealen notes it should be.

use glam::DVec3;

use super::FeatureKind;
use super::placement::toward_eye;
use crate::camera::Camera;
use crate::mesh::{Mesh, VertexId};

/// The least normal Laplacian `|s|` of a ridge or bump, per length of a path edge.
pub const FLAT_LAPLACIAN: f64 = 0.05;

/// The system's rows, as the feature sees them.
pub(super) struct Rows<'a> {
    /// The row vertices (the region, then its first anchor ring) and their rest Laplacian
    /// coordinates.
    pub rows: &'a [(VertexId, DVec3)],
    /// One entry per mesh vertex: whether it is in the region (not an anchor).
    pub region: &'a [bool],
    /// Unit vertex normals of the mesh.
    pub normals: &'a [DVec3],
}

/// The vectors `b_k` of `kind` for a sketch embedded as `path` in `mesh`.
pub(super) fn bases(
    kind: FeatureKind,
    mesh: &Mesh,
    camera: &Camera,
    rows: &Rows<'_>,
    path: &[VertexId],
) -> Vec<Vec<DVec3>> {
    let in_region = |v: VertexId| rows.region[v.index()];
    let each = |f: &dyn Fn(VertexId, DVec3) -> DVec3| -> Vec<DVec3> {
        rows.rows.iter().map(|&(v, delta)| f(v, delta)).collect()
    };
    let on_path = {
        let mut mask = vec![false; mesh.n_vertices()];
        path.iter().for_each(|v| mask[v.index()] = true);
        mask
    };
    let least = FLAT_LAPLACIAN * mean_edge(mesh, path);
    let raised = |inside: &dyn Fn(VertexId) -> bool| {
        let s = normal_part(rows, inside, least);
        each(&|v, _| {
            if inside(v) {
                s * rows.normals[v.index()]
            } else {
                DVec3::ZERO
            }
        })
    };
    match kind {
        FeatureKind::Ridge => vec![raised(&|v| on_path[v.index()])],
        FeatureKind::Bump => vec![raised(&in_region)],
        FeatureKind::Flatten => vec![each(&|v, d| if in_region(v) { -d } else { DVec3::ZERO })],
        FeatureKind::Suggestive => {
            let axes = radial_axes(mesh, camera, rows.normals, path);
            let turned = |v: VertexId, d: DVec3| {
                let p = mesh.position(v);
                let nearest = axes.iter().min_by(|a, b| {
                    let cost = |(origin, axis): &(DVec3, DVec3)| {
                        axis.dot(p - *origin).abs() + origin.distance(p)
                    };
                    cost(a).total_cmp(&cost(b))
                });
                nearest.map_or(DVec3::ZERO, |(_, axis)| axis.cross(d))
            };
            vec![
                each(&|v, d| if in_region(v) { d } else { DVec3::ZERO }),
                each(&|v, d| {
                    if in_region(v) {
                        turned(v, d)
                    } else {
                        DVec3::ZERO
                    }
                }),
            ]
        }
    }
}

/// The coefficients `c_k` of `kind` at `amount` (a factor, or an angle in degrees for
/// suggestive contours), brought `fraction` of the way from the neutral amount.
/// Kinds with one vector use the first coefficient only.
pub(super) fn coefficients(kind: FeatureKind, amount: f64, fraction: f64) -> [f64; 2] {
    match kind {
        FeatureKind::Ridge | FeatureKind::Bump => [fraction * (amount - 1.0), 0.0],
        FeatureKind::Flatten => [fraction, 0.0],
        FeatureKind::Suggestive => {
            let angle = (fraction * amount).to_radians();
            [angle.cos() - 1.0, angle.sin()]
        }
    }
}

/// Each path vertex and the unit axis of its radial plane, `(v − eye) × n` (§4.4.3).
fn radial_axes(
    mesh: &Mesh,
    camera: &Camera,
    normals: &[DVec3],
    path: &[VertexId],
) -> Vec<(DVec3, DVec3)> {
    path.iter()
        .map(|&v| {
            let p = mesh.position(v);
            let axis = (-toward_eye(camera, p)).cross(normals[v.index()]);
            (p, axis.normalize_or_zero())
        })
        .collect()
}

/// The mean of `δ·n` over the rows `inside` takes, at least `least` in size (its sign kept;
/// positive when it is zero).
fn normal_part(rows: &Rows<'_>, inside: &dyn Fn(VertexId) -> bool, least: f64) -> f64 {
    let (sum, count) = (rows.rows.iter())
        .filter(|(v, _)| inside(*v))
        .fold((0.0, 0usize), |(sum, count), &(v, delta)| {
            (sum + delta.dot(rows.normals[v.index()]), count + 1)
        });
    let mean = sum / count.max(1) as f64;
    if mean.abs() >= least {
        mean
    } else if mean < 0.0 {
        -least
    } else {
        least
    }
}

/// The mean length of the path's edges.
fn mean_edge(mesh: &Mesh, path: &[VertexId]) -> f64 {
    let total: f64 = path
        .windows(2)
        .map(|w| mesh.position(w[0]).distance(mesh.position(w[1])))
        .sum();
    total / (path.len().saturating_sub(1)).max(1) as f64
}

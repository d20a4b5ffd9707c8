//! Bujans' profile editor (§6): the region's cross-section in the plane across the
//! reference curve at a slider position, and a re-sketched cross-section turned into vertex
//! motion (the thesis does not say how; this is our rule).
//!
//! - **The frame.** At the slider's point of the reference curve: the curve's tangent is the
//!   plane's normal (the thesis' b-plane, across the curve); in the plane, `u` runs along the
//!   binormal (across the curve) and `v` along the surface normal (out of the surface: the
//!   thesis' orientation arrow "towards the outside of the mesh"). Units are the model's.
//! - **The cross-section** is where the region's triangles cross the plane, chained from
//!   the crossing nearest the curve both ways until it leaves the region, in `(u, v)`.
//! - **A re-sketch** is merged into the cross-section as curves are (Baudel's merge, `k =
//!   6`), and read as a height over `u`: the profile's change is `Δv(u)`, the merged curve's
//!   `v` minus the old one's at the same `u` (so a stroke raises, sinks or reshapes the
//!   cross-section; overhangs are beyond it). Each region vertex is swept along the curve:
//!   at its nearest point of the reference path, with that point's own frame, it moves by
//!   `Δv(u) N` for its own `u` across the curve, times how its fall-off weight compares with
//!   the profile's at that `u` (`min(1, w / w_profile(u))`), so past the curve's ends, where
//!   the fall-off runs out toward the boundary, the change runs out with it.

use glam::{DVec2, DVec3};

use super::{HandleFrame, RegionError};
use crate::curve::polyline::{BAUDEL_K, oversketch_merge};
use crate::mesh::{Mesh, VertexId};

/// The region's cross-section at one place along the reference curve.
#[derive(Clone, Debug, PartialEq)]
pub struct Profile {
    /// The plane's frame: `axes[0]` its normal (the curve's tangent), `axes[1]` the surface
    /// normal (`v`), `axes[2]` the binormal (`u`).
    pub frame: HandleFrame,
    /// The cross-section in the plane, `(u, v)` in model units, in order across the curve.
    pub points: Vec<DVec2>,
    /// The fall-off weight at each point.
    pub weights: Vec<f64>,
}

impl Profile {
    /// A point of the plane in the model's space.
    pub fn to_world(&self, p: DVec2) -> DVec3 {
        let [_, up, across] = self.frame.axes;
        self.frame.origin + across * p.x + up * p.y
    }

    /// A point of the model's space in the plane (its distance from the plane dropped).
    pub fn to_plane(&self, p: DVec3) -> DVec2 {
        let [_, up, across] = self.frame.axes;
        let d = p - self.frame.origin;
        DVec2::new(d.dot(across), d.dot(up))
    }
}

/// The region's cross-section in the plane of `frame` (see the module docs).
///
/// Errors: [`RegionError::NoProfile`] when the plane does not cross the region there.
pub(super) fn cross_section(
    mesh: &Mesh,
    weight_of: &[f64],
    frame: HandleFrame,
) -> Result<Profile, RegionError> {
    let normal = frame.axes[0];
    let side = |v: VertexId| (mesh.position(v) - frame.origin).dot(normal);
    let inside = |v: VertexId| weight_of[v.index()].is_finite();
    // Each face of the region that the plane crosses gives a segment between two edges.
    let mut links: rustc_hash::FxHashMap<(u32, u32), Vec<(u32, u32)>> = Default::default();
    for f in mesh.faces() {
        let corners = mesh.face_vertices(f);
        if !corners.iter().all(|&v| inside(v)) {
            continue;
        }
        let crossed: Vec<(u32, u32)> = (0..3)
            .map(|k| (corners[k], corners[(k + 1) % 3]))
            .filter(|&(a, b)| (side(a) >= 0.0) != (side(b) >= 0.0))
            .map(|(a, b)| (a.0.min(b.0), a.0.max(b.0)))
            .collect();
        if let [e, g] = crossed[..] {
            links.entry(e).or_default().push(g);
            links.entry(g).or_default().push(e);
        }
    }
    let crossing = |(a, b): (u32, u32)| {
        let (a, b) = (VertexId(a), VertexId(b));
        let (sa, sb) = (side(a), side(b));
        let t = sa / (sa - sb);
        let p = mesh.position(a).lerp(mesh.position(b), t);
        let w = weight_of[a.index()] * (1.0 - t) + weight_of[b.index()] * t;
        (p, w)
    };
    let start = *links
        .keys()
        .min_by(|a, b| {
            let d = |e: &&(u32, u32)| crossing(**e).0.distance(frame.origin);
            d(a).total_cmp(&d(b))
        })
        .ok_or(RegionError::NoProfile)?;
    // Walk both ways from the start, then join the two halves.
    let walk = |first: Option<(u32, u32)>| {
        let mut chain = Vec::new();
        let (mut previous, mut at) = (start, first);
        while let Some(edge) = at {
            if chain.contains(&edge) || edge == start {
                break;
            }
            chain.push(edge);
            let next = links[&edge].iter().copied().find(|&e| e != previous);
            (previous, at) = (edge, next);
        }
        chain
    };
    let ways = &links[&start];
    let mut chain: Vec<(u32, u32)> = walk(ways.get(1).copied()).into_iter().rev().collect();
    chain.push(start);
    chain.extend(walk(ways.first().copied()));
    let mut profile = Profile {
        frame,
        points: Vec::with_capacity(chain.len()),
        weights: Vec::with_capacity(chain.len()),
    };
    for edge in chain {
        let (p, w) = crossing(edge);
        let at = profile.to_plane(p);
        profile.points.push(at);
        profile.weights.push(w);
    }
    if profile.points.len() < 2 {
        return Err(RegionError::NoProfile);
    }
    if profile.points[0].x > profile.points[profile.points.len() - 1].x {
        profile.points.reverse();
        profile.weights.reverse();
    }
    Ok(profile)
}

/// The change a re-sketch `stroke` (in the profile's plane) makes to `profile`: the merged
/// cross-section, and the rise `Δv` at any `u` (see the module docs).
#[derive(Clone, Debug)]
pub struct ProfileChange {
    /// The cross-section with the stroke merged in.
    pub merged: Vec<DVec2>,
    old: Vec<DVec2>,
    weights: Vec<f64>,
}

impl ProfileChange {
    /// `profile` re-sketched with `stroke`.
    ///
    /// Errors: [`RegionError::BadProfileStroke`]: fewer than two points, or not finite.
    pub fn new(profile: &Profile, stroke: &[DVec2]) -> Result<Self, RegionError> {
        if stroke.len() < 2 || stroke.iter().any(|p| !p.is_finite()) {
            return Err(RegionError::BadProfileStroke);
        }
        Ok(ProfileChange {
            merged: oversketch_merge(&profile.points, stroke, BAUDEL_K),
            old: profile.points.clone(),
            weights: profile.weights.clone(),
        })
    }

    /// How far the cross-section rises at `u`, and the old profile's weight there; `None`
    /// beyond the cross-section's ends.
    pub fn rise_at(&self, u: f64) -> Option<(f64, f64)> {
        let (old, weight) = height_at(&self.old, Some(&self.weights), u, None)?;
        let (new, _) = height_at(&self.merged, None, u, Some(old))?;
        Some((new - old, weight))
    }
}

/// The height `v` of `polyline` over `u` (and `weights` there), on the segment over `u`
/// nearest `near` when several are; `None` where no segment is over `u`.
fn height_at(
    polyline: &[DVec2],
    weights: Option<&[f64]>,
    u: f64,
    near: Option<f64>,
) -> Option<(f64, f64)> {
    let mut best: Option<(f64, f64)> = None;
    for (i, w) in polyline.windows(2).enumerate() {
        let (a, b) = (w[0], w[1]);
        let (lo, hi) = (a.x.min(b.x), a.x.max(b.x));
        if u < lo || u > hi {
            continue;
        }
        let t = if hi > lo {
            (u - a.x) / (b.x - a.x)
        } else {
            0.0
        };
        let v = a.y + (b.y - a.y) * t;
        let weight = weights.map_or(1.0, |ws| ws[i] * (1.0 - t) + ws[i + 1] * t);
        let better = match (best, near) {
            (None, _) => true,
            (Some((v0, _)), Some(n)) => (v - n).abs() < (v0 - n).abs(),
            (Some(_), None) => false,
        };
        if better {
            best = Some((v, weight));
        }
    }
    best
}

//! Every vertex of a handle's region in the frames of its slab (Blanco §5.2), and its
//! reconstruction from new frames, with the stretch ratio.
//!
//! A region vertex `x` lies between frame planes `k − 1` and `k`. Its coordinates are
//! `(β, γ)` in frame `k − 1` (scaled units) of its foot `x_p` on plane `k − 1`, and the
//! ratio `r = α / d` of its height `α` over that plane to the distance `d` from `x_p` along
//! `u_{k−1}` to plane `k`. From new frames: `x'_p = p' + β v' + γ w'`, `d'` the new distance,
//! `x' = x'_p + r d' u'` (Eq. 5.5–5.6, read as the digest explains: `w'` for the misprinted
//! `w`, and `r` scaling the new slab width, so stretching the curve stretches the region).
//! Where the planes meet at `x_p` (no width), the vertex keeps its height instead.
//!
//! The result is added as a displacement, `x + (x'(new) − x'(rest))`: the same frames give
//! the input back bit for bit, and rounding does not creep into vertices that do not move.

use glam::DVec3;

use super::frames::{FRAMES, Frame};
use super::segment::Part;

/// A region vertex bound to its slab.
#[derive(Clone, Copy, Debug)]
pub struct Bound {
    /// The vertex.
    pub vertex: u32,
    /// The slab: between frames `slab − 1` and `slab`.
    slab: u32,
    beta: f64,
    gamma: f64,
    /// `α / d`, or NaN where the slab has no width at the foot (then `alpha` is used).
    ratio: f64,
    /// Whether a fold here counts: the slab is at least half its step wide at the foot at
    /// rest. Where the planes nearly meet already (the inside of a part bent at
    /// rest, a surface curve hugging a thick blob), the smallest change would turn it over
    /// without any new fold in the surface.
    is_watched: bool,
    alpha: f64,
    /// Where the rest frames put it.
    rest: DVec3,
}

/// The slab of a point between the first and last frame planes: the `k` with the point in
/// front of plane `k − 1` and not in front of plane `k` (binary search: the heights fall
/// along a curve that does not fold within the region).
fn slab_of(frames: &[Frame], x: DVec3) -> usize {
    let (mut lo, mut hi) = (0, FRAMES - 1);
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if frames[mid].height(x) >= 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    hi
}

/// Binds the region vertices of `parts` to `frames`.
pub fn bind(positions: &[DVec3], parts: &[Part], frames: &[Frame]) -> Vec<Bound> {
    parts
        .iter()
        .enumerate()
        .filter(|(_, part)| **part == Part::Region)
        .map(|(v, _)| bind_point(frames, v as u32, positions[v]))
        .collect()
}

/// Binds one point to the slab it lies in.
pub fn bind_point(frames: &[Frame], vertex: u32, x: DVec3) -> Bound {
    let slab = slab_of(frames, x);
    let (from, to) = (&frames[slab - 1], &frames[slab]);
    let local = from.to_local(x);
    let foot = from.to_world(0.0, local.y, local.z);
    let width = width_at(from, to, foot);
    let ratio = if width > 1e-12 {
        local.x / width
    } else {
        f64::NAN
    };
    let mut bound = Bound {
        vertex,
        slab: slab as u32,
        beta: local.y,
        gamma: local.z,
        ratio,
        is_watched: width > 0.5 * from.p.distance(to.p),
        alpha: local.x,
        rest: DVec3::ZERO,
    };
    bound.rest = place(&bound, frames).0;
    bound
}

/// The distance from `foot` on `from`'s plane along `from.u` to `to`'s plane.
fn width_at(from: &Frame, to: &Frame, foot: DVec3) -> f64 {
    let cos = from.u.dot(to.u);
    if cos.abs() < 1e-9 {
        return 0.0;
    }
    -to.height(foot) / cos
}

/// Where `frames` put a bound vertex.
fn place(bound: &Bound, frames: &[Frame]) -> (DVec3, bool) {
    let slab = bound.slab as usize;
    let (from, to) = (&frames[slab - 1], &frames[slab]);
    let foot = from.to_world(0.0, bound.beta, bound.gamma);
    if bound.ratio.is_nan() {
        return (foot + bound.alpha * from.u, false);
    }
    let width = width_at(from, to, foot);
    (
        foot + bound.ratio * width * from.u,
        bound.is_watched && width <= 0.0,
    )
}

/// Where `frames` move a bound point that was at `x`, and whether its slab turned inside
/// out there (the planes around it meet on its near side: the surface folds through itself).
pub fn moved(bound: &Bound, x: DVec3, frames: &[Frame]) -> (DVec3, bool) {
    let (placed, is_folded) = place(bound, frames);
    (x + (placed - bound.rest), is_folded)
}

/// The radius of each slab's region across the curve: the farthest its vertices lie from
/// the curve, in world units at rest; index `k` for slab `k`. A slab thinner than the
/// mesh's edges holds no vertex and takes its nearest neighbour's radius; frame 0 takes
/// slab 1's.
pub fn slab_radii(bounds: &[Bound], frames: &[Frame]) -> Vec<f64> {
    let mut radii = vec![0.0f64; FRAMES];
    for b in bounds {
        let f = &frames[b.slab as usize - 1];
        let r = (b.beta * f.scale[0]).hypot(b.gamma * f.scale[1]);
        radii[b.slab as usize] = radii[b.slab as usize].max(r);
    }
    for k in 2..FRAMES {
        if radii[k] == 0.0 {
            radii[k] = radii[k - 1];
        }
    }
    for k in (1..FRAMES - 1).rev() {
        if radii[k] == 0.0 {
            radii[k] = radii[k + 1];
        }
    }
    radii[0] = radii[1];
    radii
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::skeleton::curve::Spline;
    use crate::skeleton::frames::{Shaping, rest_frames};

    #[test]
    fn the_rest_frames_put_every_point_back() {
        let points = [
            DVec3::ZERO,
            DVec3::new(1.0, 0.3, 0.0),
            DVec3::new(2.0, 0.0, 0.4),
        ];
        let (twist, scale) = ([0.0; 3], [[1.0, 1.0]; 3]);
        let frames = rest_frames(
            &Spline::new(&points, false),
            Shaping {
                twist: &twist,
                scale: &scale,
            },
        );
        for x in [
            DVec3::new(0.5, 0.1, 0.1),
            DVec3::new(1.5, -0.1, 0.2),
            DVec3::new(1.0, 0.4, -0.1),
        ] {
            let bound = bind_point(&frames, 0, x);
            assert!(bound.rest.distance(x) < 1e-12);
            assert_eq!(moved(&bound, x, &frames), (x, false));
        }
    }
}

//! Moving a shape with one or more handles at once (Blanco §5.2–5.5).
//!
//! [`Deformation::new`] does everything that depends only on where the handles were:
//! each handle's rest frames, the parts of the shape (§3.1), every region vertex bound to
//! its slab (§5.2), the circles of influence (§5.5) and the Gaussian weights around linked
//! control points (§5.4). [`Deformation::apply_into`] is then one pass over the vertices
//! per new pose: new frames (200 per curve, a few microseconds), then each vertex in
//! closed form. Nothing is solved and nothing is allocated per vertex.
//!
//! Who moves a vertex, first match wins:
//! 1. a handle whose region holds it: its slab's frames;
//! 2. a handle whose unlinked end it lies beyond: that end's frame, rigidly (§3.1.3);
//! 3. linked control points near it: each its frame's rigid motion, weighted by a Gaussian
//!    of the distance, the weights normalised when they sum past 1 (Eq. 5.7, which leaves
//!    several links open). The thesis' `σ = √dist(p, a)` depends on the model's units; `σ`
//!    here is the region's radius at the link (a limb's thickness), cut off at 3σ;
//! 4. nobody: it stays.

use glam::DVec3;

use super::binding::{Bound, bind, bind_point, moved, slab_radii};
use super::error::SkeletonError;
use super::frames::{FRAMES, Frame, deformed_frames, rest_frames};
use super::segment::{Part, segment};
use super::shape::{Neighbours, Shape};
use crate::model::HandleCurve;

/// A handle that moves, as it was, and its links to other handles.
#[derive(Clone, Copy, Debug)]
pub struct Mover<'a> {
    /// Its curve before the move.
    pub rest: &'a HandleCurve,
    /// Its control points linked to other handles.
    pub links: &'a [Link],
}

/// A control point linked to another handle's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Link {
    /// The control point of this handle.
    pub point: usize,
    /// The other handle's place among the movers and its control point; `None` when the
    /// other handle does not move.
    pub partner: Option<(usize, usize)>,
}

/// How far a link's Gaussian reaches, in σ.
const BLEND_REACH: f64 = 3.0;

/// The handles' hold on a shape, ready to follow new poses (see the module docs).
#[derive(Clone, Debug)]
pub struct Deformation {
    handles: Vec<Held>,
    owners: Vec<Owner>,
    /// The (joint, weight) pairs of blended vertices, ranged by [`Owner::Blend`].
    weights: Vec<(u32, f64)>,
    joints: Vec<Joint>,
    seams: Vec<Seam>,
}

#[derive(Clone, Debug)]
struct Held {
    rest_frames: Vec<Frame>,
    bounds: Vec<Bound>,
    radii: Vec<f64>,
    is_start_free: bool,
    is_end_free: bool,
}

#[derive(Clone, Copy, Debug)]
struct Joint {
    handle: u32,
    frame: u32,
    /// The linked handle's mover and frame, if it moves.
    partner: Option<(u32, u32)>,
}

/// A region vertex near a link, shared with the linked handle's motion so the two curves'
/// regions meet without a crack: half each on the link's plane, fading to its own
/// handle's alone over about the region's radius.
#[derive(Clone, Copy, Debug)]
struct Seam {
    vertex: u32,
    joint: u32,
    share: f64,
}

#[derive(Clone, Copy, Debug)]
enum Owner {
    Still,
    Region { handle: u32, bound: u32 },
    Rigid { handle: u32, frame: u32 },
    Blend { from: u32, to: u32 },
}

impl Deformation {
    /// Binds `shape` to the handles in `movers`.
    ///
    /// Errors: [`SkeletonError::TooFewPoints`] for a curve of one point;
    /// [`SkeletonError::NothingUnder`] when a handle has no region.
    pub fn new(shape: &Shape, movers: &[Mover]) -> Result<Deformation, SkeletonError> {
        Self::with_neighbours(shape, &shape.neighbours(), movers)
    }

    /// [`Deformation::new`] with `shape`'s [`Shape::neighbours`] found already (at half a
    /// million points they take as long as the rest, so an interactive edit finds them in a
    /// step of their own).
    ///
    /// Errors: as [`Deformation::new`].
    pub fn with_neighbours(
        shape: &Shape,
        neighbours: &Neighbours,
        movers: &[Mover],
    ) -> Result<Deformation, SkeletonError> {
        let slabs = Self::segmented(shape, neighbours, movers)?.slabs(shape);
        Ok(slabs.bound(shape, movers))
    }

    /// The first of the three parts of [`Deformation::with_neighbours`]: each handle's rest
    /// frames and the part of the shape each point falls in. At half a million points this
    /// and the next two ([`Segmented::slabs`], [`Slabs::bound`]) take about 25, 24 and 11
    /// ms natively (40, 34 and 16 in the page), so an interactive edit takes them in steps
    /// of their own.
    ///
    /// Errors: as [`Deformation::new`].
    pub fn segmented(
        shape: &Shape,
        neighbours: &Neighbours,
        movers: &[Mover],
    ) -> Result<Segmented, SkeletonError> {
        if movers.iter().any(|m| m.rest.points.len() < 2) {
            return Err(SkeletonError::TooFewPoints);
        }
        let handles = movers.iter().map(|mover| {
            let rest_frames = rest_frames(&mover.rest.spline(), mover.rest.shaping());
            let parts = segment(shape, neighbours, &rest_frames)?;
            Ok((rest_frames, parts))
        });
        Ok(Segmented {
            handles: handles.collect::<Result<_, SkeletonError>>()?,
        })
    }
}

/// Each handle's rest frames and parts, as [`Deformation::segmented`] found them.
#[derive(Clone, Debug)]
pub struct Segmented {
    handles: Vec<(Vec<Frame>, Vec<Part>)>,
}

impl Segmented {
    /// The second part of [`Deformation::with_neighbours`]: each handle's region points bound
    /// to the slabs between its rest frames, for the `shape` the first part had.
    pub fn slabs(self, shape: &Shape) -> Slabs {
        let handles = self.handles.into_iter().map(|(rest_frames, parts)| {
            let bounds = bind(shape.positions, &parts, &rest_frames);
            (rest_frames, parts, bounds)
        });
        Slabs {
            handles: handles.collect(),
        }
    }
}

/// Each handle's rest frames, parts and region points bound to its slabs, as
/// [`Segmented::slabs`] found them.
#[derive(Clone, Debug)]
pub struct Slabs {
    handles: Vec<(Vec<Frame>, Vec<Part>, Vec<Bound>)>,
}

impl Slabs {
    /// The last part of [`Deformation::with_neighbours`]: the slabs' radii, and every point
    /// outside the regions made rigid or blended between handles, for the `shape` and
    /// `movers` the first part had.
    pub fn bound(self, shape: &Shape, movers: &[Mover]) -> Deformation {
        let n = shape.positions.len();
        let mut owners = vec![Owner::Still; n];
        let mut handles = Vec::with_capacity(movers.len());
        let mut parts_of = Vec::with_capacity(movers.len());
        let mut joints = Vec::new();
        for (h, (mover, (rest_frames, parts, bounds))) in
            movers.iter().zip(self.handles).enumerate()
        {
            let radii = slab_radii(&bounds, &rest_frames);
            let last = mover.rest.points.len() - 1;
            for (b, bound) in bounds.iter().enumerate() {
                if let Owner::Still = owners[bound.vertex as usize] {
                    owners[bound.vertex as usize] = Owner::Region {
                        handle: h as u32,
                        bound: b as u32,
                    };
                }
            }
            let frame_of = |k: usize, last: usize| {
                ((k as f64 / last as f64) * (FRAMES - 1) as f64).round() as u32
            };
            joints.extend(mover.links.iter().map(|link| Joint {
                handle: h as u32,
                frame: frame_of(link.point, last),
                partner: link.partner.map(|(other, k)| {
                    let other_last = movers[other].rest.points.len() - 1;
                    (other as u32, frame_of(k, other_last))
                }),
            }));
            handles.push(Held {
                rest_frames,
                bounds,
                radii,
                is_start_free: !mover.links.iter().any(|l| l.point == 0),
                is_end_free: !mover.links.iter().any(|l| l.point == last),
            });
            parts_of.push(parts);
        }
        let mut weights = Vec::new();
        for v in 0..n {
            if matches!(owners[v], Owner::Still) {
                let parts = parts_of.iter().map(|parts| parts[v]);
                owners[v] =
                    outside_owner(&handles, &joints, shape.positions[v], parts, &mut weights);
            }
        }
        let seams = seams(&handles, &joints, shape.positions);
        Deformation {
            handles,
            owners,
            weights,
            joints,
            seams,
        }
    }
}

impl Deformation {
    /// The frames of each handle at its new pose `curves` (in the order of the movers).
    pub fn frames(&self, curves: &[HandleCurve]) -> Vec<Vec<Frame>> {
        self.handles
            .iter()
            .zip(curves)
            .map(|(held, curve)| {
                deformed_frames(&curve.spline(), held.rest_frames[0].u, curve.shaping())
            })
            .collect()
    }

    /// Writes where every vertex of `rest` (the positions bound) goes when the handles take
    /// the poses `curves` (in the order of the movers). The rest poses give `rest` bit for
    /// bit. Returns how many region vertices fold: their slab turned inside out (a bend
    /// tighter than the part is thick; see [`Deformation::unfolded`]).
    pub fn apply_into(&self, rest: &[DVec3], curves: &[HandleCurve], out: &mut [DVec3]) -> usize {
        let frames = self.frames(curves);
        let mut folded = 0;
        for (v, (owner, (&x, slot))) in self
            .owners
            .iter()
            .zip(rest.iter().zip(out.iter_mut()))
            .enumerate()
        {
            *slot = match *owner {
                Owner::Still => x,
                Owner::Region { handle, bound } => {
                    let bound = &self.handles[handle as usize].bounds[bound as usize];
                    debug_assert_eq!(bound.vertex as usize, v);
                    let (placed, is_folded) = moved(bound, x, &frames[handle as usize]);
                    folded += usize::from(is_folded);
                    placed
                }
                Owner::Rigid { handle, frame } => {
                    let (h, f) = (handle as usize, frame as usize);
                    rigidly(x, &self.handles[h].rest_frames[f], &frames[h][f])
                }
                Owner::Blend { from, to } => {
                    self.blended(x, &self.weights[from as usize..to as usize], &frames)
                }
            };
        }
        for seam in &self.seams {
            let v = seam.vertex as usize;
            let x = rest[v];
            let joint = self.joints[seam.joint as usize];
            let partner = joint.partner.map_or(DVec3::ZERO, |(h, f)| {
                let (h, f) = (h as usize, f as usize);
                rigidly(x, &self.handles[h].rest_frames[f], &frames[h][f]) - x
            });
            let half = 0.5 * seam.share;
            out[v] = x + (1.0 - half) * (out[v] - x) + half * partner;
        }
        folded
    }

    /// Local self-intersection avoidance, in the form Blanco's §8.2 proposes: the largest
    /// fraction `f ∈ [0, 1]` of a change for which no region vertex folds, found by
    /// bisection (to 1/1024) with `pose(f)` giving the poses at `f`, and the points at it
    /// written to `out`. A change that folds nothing costs one pass.
    pub fn unfolded(
        &self,
        rest: &[DVec3],
        pose: impl Fn(f64) -> Vec<HandleCurve>,
        out: &mut [DVec3],
    ) -> f64 {
        if self.apply_into(rest, &pose(1.0), out) == 0 {
            return 1.0;
        }
        let (mut lo, mut hi) = (0.0, 1.0);
        for _ in 0..10 {
            let mid = 0.5 * (lo + hi);
            if self.apply_into(rest, &pose(mid), out) == 0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        self.apply_into(rest, &pose(lo), out);
        lo
    }

    /// A point blended between its links' rigid motions.
    fn blended(&self, x: DVec3, weights: &[(u32, f64)], frames: &[Vec<Frame>]) -> DVec3 {
        let total: f64 = weights.iter().map(|w| w.1).sum();
        let motion: DVec3 = weights
            .iter()
            .map(|&(j, w)| {
                let joint = self.joints[j as usize];
                let (h, f) = (joint.handle as usize, joint.frame as usize);
                w * (rigidly(x, &self.handles[h].rest_frames[f], &frames[h][f]) - x)
            })
            .sum();
        x + motion / total.max(1.0)
    }

    /// Where the handles' new poses move points that are not vertices (other handles'
    /// control points): the same rules, each point's part found by the planes alone.
    pub fn move_points(&self, points: &[DVec3], curves: &[HandleCurve]) -> Vec<DVec3> {
        let frames = self.frames(curves);
        points
            .iter()
            .map(|&x| self.move_point(x, &frames))
            .collect()
    }

    /// [`Deformation::move_points`] for one point, given the new poses' frames.
    fn move_point(&self, x: DVec3, frames: &[Vec<Frame>]) -> DVec3 {
        for (h, held) in self.handles.iter().enumerate() {
            let (first, last) = (&held.rest_frames[0], &held.rest_frames[FRAMES - 1]);
            if first.height(x) >= 0.0 && last.height(x) <= 0.0 {
                let bound = bind_point(&held.rest_frames, 0, x);
                let near = held
                    .rest_frames
                    .iter()
                    .map(|f| f.p.distance(x))
                    .fold(f64::INFINITY, f64::min);
                if near <= 1.5 * held.radii.iter().copied().fold(0.0, f64::max) {
                    return moved(&bound, x, &frames[h]).0;
                }
            }
        }
        let parts = self.handles.iter().map(|held| {
            let (first, last) = (&held.rest_frames[0], &held.rest_frames[FRAMES - 1]);
            if first.height(x) < 0.0 {
                Part::Start
            } else if last.height(x) > 0.0 {
                Part::End
            } else {
                Part::Region
            }
        });
        let mut weights = Vec::new();
        match outside_owner(&self.handles, &self.joints, x, parts, &mut weights) {
            Owner::Rigid { handle, frame } => {
                let (h, f) = (handle as usize, frame as usize);
                rigidly(x, &self.handles[h].rest_frames[f], &frames[h][f])
            }
            Owner::Blend { .. } => self.blended(x, &weights, frames),
            Owner::Still | Owner::Region { .. } => x,
        }
    }

    /// How many vertices each kind of owner moves: region, rigid, blended (for tests and
    /// the status line).
    pub fn counts(&self) -> [usize; 3] {
        let mut counts = [0; 3];
        for owner in &self.owners {
            match owner {
                Owner::Region { .. } => counts[0] += 1,
                Owner::Rigid { .. } => counts[1] += 1,
                Owner::Blend { .. } => counts[2] += 1,
                Owner::Still => {}
            }
        }
        counts
    }

    /// The region vertices of the mover `handle`.
    pub fn region_of(&self, handle: usize) -> impl Iterator<Item = usize> + '_ {
        self.handles[handle]
            .bounds
            .iter()
            .map(|b| b.vertex as usize)
    }
}

/// Who moves a vertex outside every region: an unlinked end it lies beyond, or the links
/// near it (their weights appended to `weights`).
fn outside_owner(
    handles: &[Held],
    joints: &[Joint],
    x: DVec3,
    parts: impl Iterator<Item = Part>,
    weights: &mut Vec<(u32, f64)>,
) -> Owner {
    for (h, part) in parts.enumerate() {
        let held = &handles[h];
        let frame = match part {
            Part::Start if held.is_start_free => 0,
            Part::End if held.is_end_free => FRAMES - 1,
            _ => continue,
        };
        return Owner::Rigid {
            handle: h as u32,
            frame: frame as u32,
        };
    }
    let from = weights.len() as u32;
    for (j, joint) in joints.iter().enumerate() {
        let held = &handles[joint.handle as usize];
        let sigma = held.radii[joint.frame as usize].max(1e-12);
        let d = x.distance(held.rest_frames[joint.frame as usize].p);
        if d < BLEND_REACH * sigma {
            weights.push((j as u32, (-d * d / (2.0 * sigma * sigma)).exp()));
        }
    }
    let to = weights.len() as u32;
    if from == to {
        Owner::Still
    } else {
        Owner::Blend { from, to }
    }
}

/// The region vertices of every linked handle near its links (see [`Seam`]).
fn seams(handles: &[Held], joints: &[Joint], positions: &[DVec3]) -> Vec<Seam> {
    let mut seams = Vec::new();
    for (j, joint) in joints.iter().enumerate() {
        let held = &handles[joint.handle as usize];
        let plane = &held.rest_frames[joint.frame as usize];
        let sigma = held.radii[joint.frame as usize].max(1e-12);
        for bound in &held.bounds {
            let across = plane.height(positions[bound.vertex as usize]).abs();
            if across < BLEND_REACH * sigma {
                seams.push(Seam {
                    vertex: bound.vertex,
                    joint: j as u32,
                    share: (-across * across / (2.0 * sigma * sigma)).exp(),
                });
            }
        }
    }
    seams
}

/// `x` carried rigidly (with the frame's scale) from frame `from` to frame `to`, as a
/// displacement so that equal frames leave it bit for bit.
fn rigidly(x: DVec3, from: &Frame, to: &Frame) -> DVec3 {
    if from == to {
        return x;
    }
    let local = from.to_local(x);
    x + (to.to_world(local.x, local.y, local.z) - from.to_world(local.x, local.y, local.z))
}

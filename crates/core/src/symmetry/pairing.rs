//! Which vertices pair up across a plane, and making a pairing exact.

use glam::DVec3;

use super::grid::PointGrid;
use super::{EXACT, diagonal};
use crate::mesh::{Mesh, VertexId};
use crate::model::{MirrorPlane, Side};

/// Which half wins when a changed model is made symmetric again.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Keep {
    /// The op acted on this side: its half stays, the other becomes its mirror image.
    Side(Side),
    /// The op acted on both sides alike: each pair meets halfway.
    Average,
}

/// Each vertex's partner across `plane`: the vertex at its mirror image, to [`EXACT`] of the
/// bounding-box diagonal (a vertex on the plane is its own). `None` when a vertex has none
/// or the pairing is not one-to-one: the model is not symmetric about the plane.
pub fn partners(mesh: &Mesh, plane: &MirrorPlane) -> Option<Vec<VertexId>> {
    partners_within(mesh, plane, EXACT)
}

/// [`partners`] to `relative` of the diagonal: a file's 32-bit positions pair up only to
/// about 1e-7.
pub fn partners_within(mesh: &Mesh, plane: &MirrorPlane, relative: f64) -> Option<Vec<VertexId>> {
    let positions = mesh.positions();
    if positions.is_empty() {
        return None;
    }
    let tolerance = relative * diagonal(mesh);
    let grid = PointGrid::new(positions, 2.0 * tolerance);
    let partner = (positions.iter())
        .map(|&p| {
            grid.nearest_within(plane.reflect(p), tolerance)
                .map(VertexId)
        })
        .collect::<Option<Vec<_>>>()?;
    let is_involution = (partner.iter().enumerate()).all(|(v, w)| partner[w.index()].index() == v);
    is_involution.then_some(partner)
}

/// Whether `b` is `a`'s mirror image about `plane`, vertex for vertex, to [`EXACT`] of `a`'s
/// diagonal (as [`super::mirrored_model`] makes it).
pub fn are_twins(a: &Mesh, b: &Mesh, plane: &MirrorPlane) -> bool {
    are_twins_within(a, b, plane, EXACT)
}

/// [`are_twins`] to `relative` of `a`'s diagonal.
pub fn are_twins_within(a: &Mesh, b: &Mesh, plane: &MirrorPlane, relative: f64) -> bool {
    let tolerance = relative * diagonal(a);
    a.n_vertices() == b.n_vertices()
        && a.n_faces() == b.n_faces()
        && (a.positions().iter().zip(b.positions()))
            .all(|(&p, &q)| plane.reflect(p).distance(q) <= tolerance)
}

/// The side all of a model's vertices lie on (some may lie on the plane, to [`EXACT`]);
/// `None` when it crosses the plane or lies in it.
pub fn side_of_model(mesh: &Mesh, plane: &MirrorPlane) -> Option<Side> {
    let tolerance = EXACT * diagonal(mesh);
    let (mut positive, mut negative) = (false, false);
    for &p in mesh.positions() {
        let s = plane.signed_distance(p);
        positive |= s > tolerance;
        negative |= s < -tolerance;
    }
    match (positive, negative) {
        (true, false) => Some(Side::Positive),
        (false, true) => Some(Side::Negative),
        _ => None,
    }
}

/// Makes `positions` exactly symmetric under the pairing `partners`: with [`Keep::Side`],
/// each pair's vertex on that side (by `sides_from`, the positions before the op) stays and
/// the other moves to its mirror image; with [`Keep::Average`] both meet halfway. A vertex
/// that is its own partner moves onto the plane.
pub fn mirror_positions(
    sides_from: &[DVec3],
    positions: &mut [DVec3],
    partners: &[VertexId],
    plane: &MirrorPlane,
    keep: Keep,
) {
    for (v, w) in partners.iter().map(|w| w.index()).enumerate() {
        if w == v {
            positions[v] = plane.project(positions[v]);
            continue;
        }
        if w < v {
            continue;
        }
        let (leader, follower) = match keep {
            Keep::Average => {
                positions[v] = 0.5 * (positions[v] + plane.reflect(positions[w]));
                (v, w)
            }
            Keep::Side(side) => {
                let kept = |u: usize| side.sign() * plane.signed_distance(sides_from[u]);
                if kept(v) >= kept(w) { (v, w) } else { (w, v) }
            }
        };
        positions[follower] = plane.reflect(positions[leader]);
    }
}

/// Where an op changed a model, `base` before and `next` after: the side that moved much
/// more (vertices displaced, or for a new topology, vertices made or removed), or
/// [`Keep::Average`] when both sides changed alike.
pub fn changed_side(base: &Mesh, next: &Mesh, plane: &MirrorPlane) -> Keep {
    if base.triangles() == next.triangles() {
        return moved_side(base.positions(), next.positions(), plane);
    }
    let tolerance = EXACT * diagonal(base);
    let (before, after) = (base.positions(), next.positions());
    let (in_before, in_after) = (
        PointGrid::new(before, 2.0 * tolerance),
        PointGrid::new(after, 2.0 * tolerance),
    );
    let made = after
        .iter()
        .filter(|&&q| in_before.nearest_within(q, tolerance).is_none());
    let removed = before
        .iter()
        .filter(|&&p| in_after.nearest_within(p, tolerance).is_none());
    let mut change = Change::default();
    for &p in made.chain(removed) {
        change.add(plane.signed_distance(p), 1.0);
    }
    change.keep()
}

/// Where the vertices at `base` moved to `moved` (the same vertices): the side whose
/// vertices moved much more, or [`Keep::Average`] when both moved alike.
pub fn moved_side(base: &[DVec3], moved: &[DVec3], plane: &MirrorPlane) -> Keep {
    let mut change = Change::default();
    for (&p, &q) in base.iter().zip(moved) {
        change.add(plane.signed_distance(p), p.distance(q));
    }
    change.keep()
}

/// How much changed on each side of a plane.
#[derive(Default)]
struct Change {
    positive: f64,
    negative: f64,
}

impl Change {
    /// Adds `amount` at signed distance `s` (nothing on the plane).
    fn add(&mut self, s: f64, amount: f64) {
        if s > 0.0 {
            self.positive += amount;
        } else if s < 0.0 {
            self.negative += amount;
        }
    }

    /// The side that changed at least twice as much as the other, or both alike.
    fn keep(&self) -> Keep {
        if self.positive > 2.0 * self.negative {
            Keep::Side(Side::Positive)
        } else if self.negative > 2.0 * self.positive {
            Keep::Side(Side::Negative)
        } else {
            Keep::Average
        }
    }
}

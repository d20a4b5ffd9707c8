//! The region a handle moves, and the two sides it leaves (Blanco §3.1.2–3.1.3, Alg. 2–3).
//!
//! The cutting planes are the curve's first and last frame planes, so the region is exactly
//! what lies between the frames that carry it. It is grown from the vertices nearest the
//! curve, over triangles (and, for pieces and clouds, over distance, see
//! [`super::shape`]), through vertices between the planes only: of two parts that lie
//! under the stroke, the one the curve is on. The rest takes the side of the plane it first
//! meets, grown outwards from the region's border (Alg. 3); what no growth reaches goes by
//! the side of the planes it lies on.

use glam::DVec3;

use super::error::SkeletonError;
use super::frames::{FRAMES, Frame};
use super::shape::{Neighbours, PointGrid, Shape};

/// Where a vertex lies for one handle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    /// Before the first cutting plane: moves with the curve's start.
    Start,
    /// Between the planes, on the curve's part: carried by the frames.
    Region,
    /// Past the last cutting plane: moves with the curve's end.
    End,
}

/// How many curve points the region is grown from.
const SEEDS: usize = 16;

/// The part of every vertex of `shape` for the curve of `frames`.
///
/// Errors: [`SkeletonError::NothingUnder`] when no vertex lies between the planes.
pub fn segment(
    shape: &Shape,
    neighbours: &Neighbours,
    frames: &[Frame],
) -> Result<Vec<Part>, SkeletonError> {
    let (first, last) = (frames[0], frames[FRAMES - 1]);
    let positions = shape.positions;
    let between = |x: DVec3| first.height(x) >= 0.0 && last.height(x) <= 0.0;
    let mut parts: Vec<Option<Part>> = vec![None; positions.len()];
    let mut stack = seeds(positions, frames, &between);
    if stack.is_empty() {
        return Err(SkeletonError::NothingUnder);
    }
    for &s in &stack {
        parts[s] = Some(Part::Region);
    }
    let grid = (!neighbours.is_one_piece).then(|| {
        let reach = shape.reach();
        (
            PointGrid::new(positions, reach, |i| between(positions[i])),
            reach,
        )
    });
    while let Some(v) = stack.pop() {
        let mut visit = |u: usize| {
            if parts[u].is_none() && between(positions[u]) {
                parts[u] = Some(Part::Region);
                stack.push(u);
            }
        };
        neighbours.of(v).iter().for_each(|&u| visit(u as usize));
        if let Some((grid, reach)) = &grid {
            grid.around(positions[v], |u| {
                if positions[v].distance(positions[u as usize]) <= *reach {
                    visit(u as usize);
                }
            });
        }
    }
    grow_sides(positions, neighbours, &first, &mut parts);
    Ok(parts
        .iter()
        .zip(positions)
        .map(|(part, &x)| part.unwrap_or_else(|| side_of(x, &first, &last)))
        .collect())
}

/// The vertex between the planes nearest each of [`SEEDS`] curve points.
fn seeds(positions: &[DVec3], frames: &[Frame], between: &impl Fn(DVec3) -> bool) -> Vec<usize> {
    let points: Vec<DVec3> = (0..SEEDS)
        .map(|i| frames[i * (FRAMES - 1) / (SEEDS - 1)].p)
        .collect();
    let mut best = vec![(f64::INFINITY, usize::MAX); SEEDS];
    for (v, &x) in positions.iter().enumerate() {
        if !between(x) {
            continue;
        }
        for (slot, &p) in best.iter_mut().zip(&points) {
            let d = x.distance_squared(p);
            if d < slot.0 {
                *slot = (d, v);
            }
        }
    }
    let mut seeds: Vec<usize> = best
        .iter()
        .filter(|b| b.1 != usize::MAX)
        .map(|b| b.1)
        .collect();
    seeds.sort_unstable();
    seeds.dedup();
    seeds
}

/// Alg. 3: the vertices next to the region take the side of the plane they lie beyond, and
/// pass it on to the vertices next to them.
fn grow_sides(
    positions: &[DVec3],
    neighbours: &Neighbours,
    first: &Frame,
    parts: &mut [Option<Part>],
) {
    let mut stack = Vec::new();
    for v in 0..positions.len() {
        if parts[v] != Some(Part::Region) {
            continue;
        }
        for &u in neighbours.of(v) {
            let u = u as usize;
            if parts[u].is_none() {
                let side = if first.height(positions[u]) < 0.0 {
                    Part::Start
                } else {
                    Part::End
                };
                parts[u] = Some(side);
                stack.push(u);
            }
        }
    }
    while let Some(v) = stack.pop() {
        let side = parts[v];
        for &u in neighbours.of(v) {
            if parts[u as usize].is_none() {
                parts[u as usize] = side;
                stack.push(u as usize);
            }
        }
    }
}

/// The side of a vertex no growth reached: the plane it lies beyond, or between them the
/// nearer one.
fn side_of(x: DVec3, first: &Frame, last: &Frame) -> Part {
    let (before, after) = (first.height(x), last.height(x));
    if before < 0.0 && (after <= 0.0 || -before >= after) {
        Part::Start
    } else if after > 0.0 {
        Part::End
    } else if before <= -after {
        Part::Start
    } else {
        Part::End
    }
}

//! Control curves made symmetric: the kept side's pieces and their mirror images, joined
//! where they meet on the plane.

use crate::mesh::VertexId;
use crate::model::ControlCurve;

/// Where a curve's vertex lies when a model is made symmetric.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Place {
    /// On the kept side.
    Kept,
    /// On the plane: its own partner.
    OnPlane,
    /// On the other side: replaced by the mirror image of the kept side.
    Gone,
}

/// The curves of a model made symmetric: every piece of `curves` on the kept side (and on
/// the plane), with its mirror image through `partner`; a piece that ends on the plane is
/// joined with its image there (a curve across the plane stays one curve, closed if it was
/// closed). Pieces on the other side go: their images come from the kept side.
pub fn mirrored_curves(
    curves: &[ControlCurve],
    place: impl Fn(VertexId) -> Place,
    partner: impl Fn(VertexId) -> VertexId,
) -> Vec<ControlCurve> {
    let mut mirrored = Vec::new();
    for curve in curves {
        let with_kind = |vertices: Vec<VertexId>, is_closed: bool| ControlCurve {
            vertices,
            is_closed,
            kind: curve.kind,
        };
        let image = |run: &[VertexId]| run.iter().map(|&v| partner(v)).collect::<Vec<_>>();
        let mut chain = curve.vertices.clone();
        let gone = chain.iter().position(|&v| place(v) == Place::Gone);
        if curve.is_closed {
            match gone {
                Some(first) => chain.rotate_left(first),
                None => {
                    let on_plane = chain.iter().all(|&v| place(v) == Place::OnPlane);
                    mirrored.push(curve.clone());
                    if !on_plane {
                        mirrored.push(with_kind(image(&chain), true));
                    }
                    continue;
                }
            }
        }
        for (first, last) in runs(&chain, &place) {
            let run = &chain[first..=last];
            if run.len() < 2 {
                continue;
            }
            // A run joins its image at an end on the plane, or at an end whose next vertex
            // along the curve is its own partner (the edge between them crosses the plane).
            let next_to = |at: usize, step: isize| {
                let n = chain.len() as isize;
                let index = at as isize + step;
                (curve.is_closed || (0..n).contains(&index))
                    .then(|| chain[index.rem_euclid(n) as usize])
            };
            let joins = |at: usize, step| {
                place(chain[at]) == Place::OnPlane || next_to(at, step) == Some(partner(chain[at]))
            };
            let (starts, ends) = (joins(first, -1), joins(last, 1));
            let on_plane = |v: &&VertexId| place(**v) == Place::OnPlane;
            let shared_start = usize::from(starts && on_plane(&&run[0]));
            let shared_end = usize::from(ends && on_plane(&&run[run.len() - 1]));
            let imaged = &run[shared_start..run.len() - shared_end];
            let reversed_image = image(imaged).into_iter().rev();
            if run.iter().all(|v| on_plane(&v)) {
                mirrored.push(with_kind(run.to_vec(), false));
            } else if starts && ends {
                let loop_ = run.iter().copied().chain(reversed_image);
                mirrored.push(with_kind(loop_.collect(), true));
            } else if ends {
                let through = run.iter().copied().chain(reversed_image);
                mirrored.push(with_kind(through.collect(), false));
            } else if starts {
                let through = reversed_image.chain(run.iter().copied());
                mirrored.push(with_kind(through.collect(), false));
            } else {
                mirrored.push(with_kind(run.to_vec(), false));
                mirrored.push(with_kind(image(run), false));
            }
        }
    }
    mirrored
}

/// The first and last index of each run of `chain`'s vertices that are not gone.
fn runs(chain: &[VertexId], place: &impl Fn(VertexId) -> Place) -> Vec<(usize, usize)> {
    let mut runs = Vec::new();
    let mut start = None;
    for (index, &v) in chain.iter().enumerate() {
        match (place(v) == Place::Gone, start) {
            (false, None) => start = Some(index),
            (true, Some(first)) => {
                runs.push((first, index - 1));
                start = None;
            }
            _ => {}
        }
    }
    if let Some(first) = start {
        runs.push((first, chain.len() - 1));
    }
    runs
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::CurveKind;

    /// Vertices 0..10 on a line across x = 0: 0..4 at x < 0, 5 at x = 0, 6..10 at x > 0;
    /// vertex `v`'s partner is `10 - v`.
    fn place(v: VertexId) -> Place {
        match v.0 {
            0..5 => Place::Gone,
            5 => Place::OnPlane,
            _ => Place::Kept,
        }
    }

    fn partner(v: VertexId) -> VertexId {
        VertexId(10 - v.0)
    }

    fn curve(ids: &[u32], is_closed: bool) -> ControlCurve {
        ControlCurve {
            vertices: ids.iter().map(|&v| VertexId(v)).collect(),
            is_closed,
            kind: CurveKind::Sharp,
        }
    }

    #[test]
    fn a_curve_across_the_plane_becomes_the_kept_half_and_its_image() {
        let made = mirrored_curves(&[curve(&[2, 3, 4, 5, 6, 7], false)], place, partner);
        assert_eq!(made, [curve(&[3, 4, 5, 6, 7], false)]);
        let made = mirrored_curves(&[curve(&[7, 6, 5, 4], false)], place, partner);
        assert_eq!(made, [curve(&[7, 6, 5, 4, 3], false)]);
    }

    #[test]
    fn a_closed_curve_across_the_plane_stays_closed_and_a_side_curve_gets_a_twin() {
        // A loop 5 → 6 → 7 → 8, across the plane by the edge 8–2, and 2 → 3 → 4 back.
        let made = mirrored_curves(&[curve(&[5, 6, 7, 8, 2, 1, 4], true)], place, partner);
        assert_eq!(made, [curve(&[5, 6, 7, 8, 2, 3, 4], true)]);
        let made = mirrored_curves(
            &[curve(&[6, 7], false), curve(&[1, 2], false)],
            place,
            partner,
        );
        assert_eq!(made, [curve(&[6, 7], false), curve(&[4, 3], false)]);
    }
}

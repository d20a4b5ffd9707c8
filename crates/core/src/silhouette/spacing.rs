//! Even screen spacing by picking crossings, so every kept point still lies on its edge.
//!
//! Interpolating between crossings would give exact spacing, but an interpolated point lies
//! inside a face, not on an edge, and over-sketching needs the edge. So the points are
//! thinned instead: from each kept crossing the next kept one is the farthest that is still
//! within [`MAX_GAP`] spacings, unless that one is closer than [`MIN_GAP`] spacings, in which
//! case the first crossing beyond is kept. Gaps thus lie between the two bounds, except where
//! crossings on screen are further apart than that and the mesh sets the spacing.

use glam::DVec2;

/// The largest gap, in spacings, that thinning may open.
const MAX_GAP: f64 = 1.5;
/// The smallest gap, in spacings, that thinning keeps when it could skip the point.
const MIN_GAP: f64 = 0.5;

/// Indices of the points to keep (see the module docs): always the first, and the last of
/// an open polyline (replacing a kept point closer than [`MIN_GAP`] spacings). A closed
/// polyline is thinned as if its first point were repeated at the end, so its closing gap
/// obeys the same bounds.
pub(super) fn pick_evenly(screen: &[DVec2], is_closed: bool, spacing: f64) -> Vec<usize> {
    let Some(&first) = screen.first() else {
        return Vec::new();
    };
    if !is_closed {
        return pick_evenly_open(screen, spacing);
    }
    let mut round_trip = screen.to_vec();
    round_trip.push(first);
    let mut picked = pick_evenly_open(&round_trip, spacing);
    // Drop the repeated first point (a lone point picks only itself).
    if picked.len() > 1 {
        picked.pop();
    }
    picked
}

fn pick_evenly_open(screen: &[DVec2], spacing: f64) -> Vec<usize> {
    let n = screen.len();
    let (max_gap, min_gap) = (MAX_GAP * spacing, MIN_GAP * spacing);
    let mut picked = vec![0];
    let mut last = 0;
    while last + 1 < n {
        // The farthest run of successors within the largest gap.
        let mut reach = last + 1;
        while reach + 1 < n && screen[reach + 1].distance(screen[last]) <= max_gap {
            reach += 1;
        }
        let is_too_close = screen[reach].distance(screen[last]) < min_gap;
        last = if is_too_close && reach + 1 < n {
            reach + 1
        } else {
            reach
        };
        picked.push(last);
    }
    // A last gap that is too short: re-place the point before it halfway between its
    // neighbours, or drop it.
    let k = picked.len();
    if k > 2 && screen[picked[k - 2]].distance(screen[n - 1]) < min_gap {
        let before = picked[k - 3];
        let (from, to) = (screen[before], screen[n - 1]);
        let balanced = (before + 1..n - 1)
            .filter(|&j| screen[j].distance(from).min(screen[j].distance(to)) >= min_gap)
            .min_by(|&i, &j| {
                let imbalance =
                    |j: usize| (screen[j].distance(from) - screen[j].distance(to)).abs();
                imbalance(i).total_cmp(&imbalance(j))
            });
        match balanced {
            Some(j) => picked[k - 2] = j,
            None => {
                picked.remove(k - 2);
            }
        }
    }
    picked
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dense_points_are_thinned_and_ends_kept() {
        let line: Vec<DVec2> = (0..=100).map(|k| DVec2::new(0.1 * k as f64, 0.0)).collect();
        let picked = pick_evenly(&line, false, 2.5);
        // 0, 3.7, 7.4, 10: as far as 1.5 spacings allow (up to rounding of 0.1 steps).
        assert_eq!(picked.len(), 4, "{picked:?}");
        assert_eq!((picked[0], picked[3]), (0, 100));
        for pair in picked.windows(2) {
            let gap = line[pair[1]].distance(line[pair[0]]);
            assert!((2.5..=3.75).contains(&gap), "{gap}");
        }
    }

    #[test]
    fn sparse_points_are_all_kept_and_a_closed_seam_stays_even() {
        let square = [
            DVec2::ZERO,
            DVec2::X * 5.0,
            DVec2::splat(5.0),
            DVec2::Y * 5.0,
        ];
        assert_eq!(pick_evenly(&square, true, 2.5), vec![0, 1, 2, 3]);
        let circle: Vec<DVec2> = (0..100)
            .map(|k| 10.0 * DVec2::from_angle(std::f64::consts::TAU * k as f64 / 100.0))
            .collect();
        let picked = pick_evenly(&circle, true, 3.0);
        let seam = circle[*picked.last().unwrap()].distance(circle[0]);
        assert!((1.5..=4.5).contains(&seam), "{seam}");
        for pair in picked.windows(2) {
            let gap = circle[pair[0]].distance(circle[pair[1]]);
            assert!((1.5..=4.5).contains(&gap), "{gap}");
        }
        assert!(pick_evenly(&[], true, 1.0).is_empty());
    }

    #[test]
    fn a_point_before_a_wide_gap_is_kept_and_a_crowded_one_skipped() {
        // Skipping the point at 2 would leave a gap of 8; the one at 0.3 is too close to keep.
        let points = [0.0, 2.0, 8.0, 8.3, 14.0, 15.0, 16.5].map(|x| DVec2::new(x, 0.0));
        assert_eq!(pick_evenly(&points, false, 2.5), vec![0, 1, 2, 4, 6]);
    }
}

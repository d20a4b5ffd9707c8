//! Scoring candidate handles for [`super::match_stroke`]: a best-first search that
//! evaluates the turning-angle misfit only while a candidate could still win or change
//! the confidence verdict, and a pattern search that refines the winner's ends.
//!
//! A candidate's proximity cost bounds its total cost from below (the misfit is never
//! negative), so once candidates sorted by proximity reach the cost of the best distinct
//! alternative, or a cost that would leave the best confident anyway, none later can matter.

use super::candidate::{MatchParams, Segment, Target, proximity_cost};
use super::track::Track;
use super::turning::TurningSummary;

/// Scores candidates in order of their proximity cost until none left can beat the best
/// or change whether it is confident. Returns the best and the cost of the best distinct
/// alternative.
pub(super) fn search(
    candidates: &[(Segment, f64)],
    scorer: &Scorer,
) -> Option<(Segment, Option<f64>)> {
    let mut scored: Vec<(Segment, f64)> = Vec::new();
    let mut best: Option<(Segment, f64)> = None;
    let mut second: Option<f64> = None;
    for &(segment, bound) in candidates {
        if let Some((_, best_cost)) = best {
            // A cost beyond `enough` leaves the best confident against it.
            let enough = scorer.params.min_score_ratio.sqrt() * (1.0 + best_cost) - 1.0;
            if bound >= second.unwrap_or(f64::INFINITY).min(enough) {
                break;
            }
        }
        let cost = bound + scorer.params.weight_shape * scorer.misfit(segment);
        scored.push((segment, cost));
        match best {
            Some((kept, best_cost)) if cost >= best_cost => {
                if is_distinct(scorer, kept, segment) {
                    second = Some(second.map_or(cost, |c: f64| c.min(cost)));
                }
            }
            _ => {
                best = Some((segment, cost));
                second = scored
                    .iter()
                    .filter(|(s, _)| is_distinct(scorer, segment, *s))
                    .map(|&(_, c)| c)
                    .min_by(f64::total_cmp);
            }
        }
    }
    best.map(|(segment, _)| (segment, second))
}

/// Different silhouettes, or handles overlapping by less than half the shorter one.
fn is_distinct(scorer: &Scorer, a: Segment, b: Segment) -> bool {
    if a.track != b.track {
        return true;
    }
    let Some(Some(track)) = scorer.tracks.get(a.track) else {
        return true;
    };
    let laps: &[f64] = if track.is_closed() {
        &[-1.0, 0.0, 1.0]
    } else {
        &[0.0]
    };
    let overlap = laps
        .iter()
        .map(|k| {
            let shift = k * track.length();
            (a.hi.min(b.hi + shift) - a.lo.max(b.lo + shift)).max(0.0)
        })
        .fold(0.0, f64::max);
    overlap < 0.5 * (a.hi - a.lo).min(b.hi - b.lo)
}

/// The cost of a candidate, given the prepared silhouettes and stroke.
pub(super) struct Scorer<'a> {
    pub(super) tracks: &'a [Option<Track<'a>>],
    pub(super) summaries: &'a [Option<TurningSummary>],
    pub(super) target: &'a Target,
    pub(super) params: &'a MatchParams,
}

impl Scorer<'_> {
    /// Arclengths of the handle ends under the stroke's first and last points.
    pub(super) fn ends(&self, segment: Segment) -> (f64, f64) {
        if segment.reversed {
            (segment.hi, segment.lo)
        } else {
            (segment.lo, segment.hi)
        }
    }

    fn misfit(&self, segment: Segment) -> f64 {
        let Some(Some(summary)) = self.summaries.get(segment.track) else {
            return 0.0;
        };
        let pattern = if segment.reversed {
            &self.target.backward
        } else {
            &self.target.forward
        };
        summary.misfit(segment.lo, segment.hi, pattern)
    }

    fn cost(&self, segment: Segment) -> f64 {
        let Some(Some(track)) = self.tracks.get(segment.track) else {
            return f64::INFINITY;
        };
        let (first, last) = self.ends(segment);
        let distance_first = self.target.first.distance(track.position(first));
        let distance_last = self.target.last.distance(track.position(last));
        proximity_cost(distance_first, distance_last, self.params)
            + self.params.weight_shape * self.misfit(segment)
    }

    /// Pattern search on the two ends, halving the step from `spacing / 2` to
    /// `spacing / 8`; the length stays within the scale limits and an open track's ends
    /// stay on it.
    pub(super) fn refine(&self, mut segment: Segment, spacing: f64) -> (Segment, f64) {
        let mut cost = self.cost(segment);
        let Some(Some(track)) = self.tracks.get(segment.track) else {
            return (segment, cost);
        };
        let (shortest, longest) = (
            self.target.length / self.params.max_scale,
            self.target.length * self.params.max_scale,
        );
        let upper = if track.is_closed() {
            f64::INFINITY
        } else {
            track.length()
        };
        let lower = if track.is_closed() {
            f64::NEG_INFINITY
        } else {
            0.0
        };
        let mut step = 0.5 * spacing;
        while step >= spacing / 8.0 {
            let mut improved = true;
            while improved {
                improved = false;
                for (d_lo, d_hi) in [(-step, 0.0), (step, 0.0), (0.0, -step), (0.0, step)] {
                    let mut trial = Segment {
                        lo: segment.lo + d_lo,
                        hi: segment.hi + d_hi,
                        ..segment
                    };
                    if track.is_closed() {
                        // Keep `lo` on the first lap, where the summary is defined.
                        let shift = trial.lo.rem_euclid(track.length()) - trial.lo;
                        trial.lo += shift;
                        trial.hi += shift;
                    }
                    let length = trial.hi - trial.lo;
                    if trial.lo < lower
                        || trial.hi > upper
                        || !(shortest..=longest).contains(&length)
                    {
                        continue;
                    }
                    let trial_cost = self.cost(trial);
                    if trial_cost < cost {
                        (segment, cost, improved) = (trial, trial_cost, true);
                    }
                }
            }
            step *= 0.5;
        }
        (segment, cost)
    }
}

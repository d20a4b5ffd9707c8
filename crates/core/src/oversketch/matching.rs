//! Handle estimation: which part of which silhouette a stroke redraws (SilSketch, Nealen's
//! dissertation §5.4.2).
//!
//! Every candidate handle is a silhouette segment whose ends lie near the stroke's ends. Its
//! cost is `c = w_near Prox_near + w_far Prox_far + w_shape R` and its score
//! `1 / (1 + c)²` (Eq. 5.7): the `Prox` terms are the smaller and larger distance between
//! corresponding ends (px), `R` the turning-angle misfit of stroke and segment after the
//! optimal rotation (rad², see [`super::turning`]). Like the thesis we sample the segment's
//! start and length (`β`, `α`) instead of sweeping them exactly: ends every `h ≈ l / 40` px
//! within `max_distance_px` of the stroke's ends, segment lengths within a factor
//! `max_scale` of the stroke's length `l`, both directions of travel, and on closed
//! silhouettes both ways round. Candidates are scored in order of their proximity cost,
//! which bounds the total from below, so the shape term is evaluated only for the few that
//! could still win. The winner's ends are then refined by a pattern search down to `h / 8`.
//!
//! The thesis leaves the weights and the sample density open; ours are in
//! [`MatchParams::default`]. A limitation: a stroke redraws one contiguous piece of one
//! silhouette; strokes that span two silhouettes match only one of them.

use glam::DVec2;

use super::candidate::{MatchParams, Segment, Target, proximity_cost};
use super::scoring::{Scorer, search};
use super::track::Track;
use super::turning::TurningSummary;
use crate::curve::polyline::{cumulative_lengths, simplify};

/// Spacing of the even resampling in [`simplify_stroke`], in px.
pub const STROKE_SPACING_PX: f64 = 2.0;
/// Douglas–Peucker tolerance of [`simplify_stroke`], in px.
pub const STROKE_TOLERANCE_PX: f64 = 1.0;

/// Simplifies a drawn stroke as SilSketch does before matching (Nealen's dissertation §5.4,
/// §5.4.2): even resampling at [`STROKE_SPACING_PX`] (so bursts and gaps of pointer events
/// weigh alike), then Douglas–Peucker at [`STROKE_TOLERANCE_PX`].
///
/// The first and last points are kept exactly. Fewer than two points, or a stroke of zero
/// length, come back as at most one point.
pub fn simplify_stroke(points: &[DVec2]) -> Vec<DVec2> {
    simplify(points, STROKE_SPACING_PX, STROKE_TOLERANCE_PX)
}

/// The handle a stroke redraws.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Match {
    /// Index of the silhouette in the slice given to [`match_stroke`].
    pub silhouette: usize,
    /// Fractional point index (`i + t` lies between points `i` and `i + 1`) of the handle
    /// end that the stroke's first point redraws.
    pub start: f64,
    /// Fractional point index of the handle end that the stroke's last point redraws. The
    /// handle runs from `start` to `end`, backwards along the silhouette when
    /// `start > end`; on a closed silhouette indices past `n − 1` wrap round (see
    /// [`super::handle_points`]).
    pub end: f64,
    /// `1 / (1 + cost)²` in `(0, 1]` (Eq. 5.7); 1 is a perfect fit at zero distance.
    pub score: f64,
    /// False when the match is a guess: its far end is more than
    /// [`MatchParams::confident_distance_px`] away, or a distinct alternative scores within
    /// [`MatchParams::min_score_ratio`] of it.
    pub confident: bool,
}

/// Finds the handle that `stroke` (screen px, in drawing order) redraws among
/// `silhouettes` (screen polylines; a closed one repeats its first point at the end).
///
/// Returns `None` when no silhouette has a segment of fitting length with both ends within
/// [`MatchParams::max_distance_px`] of the stroke's ends, or when the stroke has zero
/// length. The stroke is simplified with [`simplify_stroke`] for the shape comparison.
pub fn match_stroke(
    stroke: &[DVec2],
    silhouettes: &[&[DVec2]],
    params: &MatchParams,
) -> Option<Match> {
    let target = target_of(stroke)?;
    let tracks: Vec<Option<Track>> = silhouettes.iter().map(|s| Track::new(s)).collect();
    let spacing = (target.length / 40.0).clamp(1.0, 8.0);

    let mut candidates = Vec::new();
    let mut summaries = vec![None; tracks.len()];
    for (index, track) in tracks.iter().enumerate() {
        let Some(track) = track else { continue };
        let count = candidates.len();
        push_candidates(index, track, &target, spacing, params, &mut candidates);
        if candidates.len() > count {
            summaries[index] = Some(track.turning_summary(params.silhouette_tolerance_px));
        }
    }
    candidates.sort_unstable_by(|a, b| a.1.total_cmp(&b.1));

    let scorer = Scorer {
        tracks: &tracks,
        summaries: &summaries,
        target: &target,
        params,
    };
    let (best, second) = search(&candidates, &scorer)?;
    let (best, best_cost) = scorer.refine(best, spacing);

    let track = tracks[best.track].as_ref()?;
    let (first, last) = scorer.ends(best);
    let score = 1.0 / (1.0 + best_cost).powi(2);
    let far = target
        .first
        .distance(track.position(first))
        .max(target.last.distance(track.position(last)));
    let distinct = second.is_none_or(|cost| score >= params.min_score_ratio / (1.0 + cost).powi(2));
    Some(Match {
        silhouette: best.track,
        start: track.index(first),
        end: track.index(last),
        score,
        confident: distinct && far <= params.confident_distance_px,
    })
}

/// The stroke prepared for matching; `None` when it has zero length.
fn target_of(stroke: &[DVec2]) -> Option<Target> {
    let simple = simplify_stroke(stroke);
    let cumulative = cumulative_lengths(&simple);
    let length = *cumulative.last()?;
    if length <= 0.0 {
        return None;
    }
    let reversed: Vec<DVec2> = simple.iter().rev().copied().collect();
    let reversed_cumulative = cumulative_lengths(&reversed);
    Some(Target {
        first: *stroke.first()?,
        last: *stroke.last()?,
        length,
        forward: TurningSummary::new(&simple, &cumulative).normalized(),
        backward: TurningSummary::new(&reversed, &reversed_cumulative).normalized(),
    })
}

/// Adds every sampled segment of `track` whose ends lie near the stroke's ends, with its
/// proximity cost.
fn push_candidates(
    index: usize,
    track: &Track,
    target: &Target,
    spacing: f64,
    params: &MatchParams,
    out: &mut Vec<(Segment, f64)>,
) {
    let samples = track.samples(spacing);
    let near = |p: DVec2| -> Vec<(f64, f64)> {
        samples
            .iter()
            .map(|&(s, q)| (s, q.distance(p)))
            .filter(|&(_, d)| d <= params.max_distance_px)
            .collect()
    };
    let (near_first, near_last) = (near(target.first), near(target.last));
    let (shortest, longest) = (
        target.length / params.max_scale,
        target.length * params.max_scale,
    );
    let length = track.length();
    for &(a, distance_a) in &near_first {
        for &(b, distance_b) in &near_last {
            let cost = proximity_cost(distance_a, distance_b, params);
            // The stroke's first point at `a`, its last at `b`.
            let mut push = |lo: f64, hi: f64, reversed: bool| {
                if (shortest..=longest).contains(&(hi - lo)) {
                    let segment = Segment {
                        track: index,
                        lo,
                        hi,
                        reversed,
                    };
                    out.push((segment, cost));
                }
            };
            if track.is_closed() {
                push(a, if b > a { b } else { b + length }, false);
                push(b, if a > b { a } else { a + length }, true);
            } else if a < b {
                push(a, b, false);
            } else if b < a {
                push(b, a, true);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An open wavy curve, 2 px per segment.
    fn wavy() -> Vec<DVec2> {
        (0..=400)
            .map(|i| {
                let x = 2.0 * i as f64;
                DVec2::new(x, 300.0 + 30.0 * (x / 60.0).sin())
            })
            .collect()
    }

    #[test]
    fn simplified_stroke_keeps_ends_and_shape() {
        // A dense, jittery half circle of radius 100 px.
        let raw: Vec<DVec2> = (0..=500)
            .map(|k| {
                let t = std::f64::consts::PI * k as f64 / 500.0;
                (100.0 + 0.2 * (37.0 * t).sin()) * DVec2::new(t.cos(), t.sin())
            })
            .collect();
        let simple = simplify_stroke(&raw);
        assert_eq!(simple.first(), raw.first());
        assert_eq!(simple.last(), raw.last());
        assert!(simple.len() < 40, "{} points", simple.len());
        for p in &simple {
            assert!((p.length() - 100.0).abs() < 1.5);
        }
    }

    #[test]
    fn a_copy_of_a_piece_matches_that_piece_exactly() {
        let silhouette = wavy();
        let piece = &silhouette[100..=300];
        let params = MatchParams::default();
        let found = match_stroke(piece, &[&silhouette], &params).expect("match");
        assert!(found.confident && found.score > 0.9, "{found:?}");
        assert!((found.start - 100.0).abs() < 0.25 && (found.end - 300.0).abs() < 0.25);
        // Drawn backwards, the same piece with the ends swapped.
        let reversed: Vec<DVec2> = piece.iter().rev().copied().collect();
        let found = match_stroke(&reversed, &[&silhouette], &params).expect("match");
        assert!(found.confident && found.score > 0.9, "{found:?}");
        assert!((found.start - 300.0).abs() < 0.25 && (found.end - 100.0).abs() < 0.25);
    }

    #[test]
    fn degenerate_input_matches_nothing() {
        let silhouette = wavy();
        let params = MatchParams::default();
        let dot = [DVec2::new(200.0, 300.0); 5];
        assert_eq!(match_stroke(&dot, &[&silhouette], &params), None);
        assert_eq!(match_stroke(&[], &[&silhouette], &params), None);
        assert_eq!(match_stroke(&silhouette[10..50], &[], &params), None);
        // Silhouettes of one point or of zero length are skipped, not matched.
        let point = [DVec2::new(40.0, 300.0)];
        let found = match_stroke(&silhouette[10..50], &[&point, &dot, &silhouette], &params);
        assert_eq!(found.map(|m| m.silhouette), Some(2));
    }

    #[test]
    fn handles_far_longer_or_shorter_than_the_stroke_are_not_candidates() {
        // A 60 px stroke over the top of a U with 200 px legs: every handle whose ends
        // lie within 40 px of the stroke's ends is at least 380 px long, 6 times the stroke.
        let u = [
            DVec2::new(0.0, 0.0),
            DVec2::new(0.0, 200.0),
            DVec2::new(60.0, 200.0),
            DVec2::new(60.0, 0.0),
        ];
        let stroke = [DVec2::new(0.0, -5.0), DVec2::new(60.0, -5.0)];
        let params = MatchParams {
            max_distance_px: 40.0,
            ..MatchParams::default()
        };
        assert_eq!(match_stroke(&stroke, &[&u], &params), None);
        let wide = MatchParams {
            max_scale: 8.0,
            ..params
        };
        let found = match_stroke(&stroke, &[&u], &wide).expect("match");
        assert!(found.start < 1.0 && found.end > 2.0, "{found:?}");
    }
}

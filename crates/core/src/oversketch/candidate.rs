//! What handle estimation compares ([`super::match_stroke`], SilSketch §5.4.2): candidate
//! segments of a silhouette, the stroke as a target, and the weights of their cost. Both
//! `matching.rs` (which finds the candidates) and `scoring.rs` (which scores them) use these.

use glam::DVec2;

use super::turning::TurningSummary;

/// Weights and limits of [`super::match_stroke`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MatchParams {
    /// Both stroke ends must lie within this distance (px) of the handle's ends, or the
    /// silhouette is not a candidate.
    pub max_distance_px: f64,
    /// A match whose farther end is more than this (px) from the stroke is not confident.
    pub confident_distance_px: f64,
    /// Cost per px of the nearer end's distance (`w₁` of Eq. 5.7).
    pub weight_near: f64,
    /// Cost per px of the farther end's distance (`w₂` of Eq. 5.7).
    pub weight_far: f64,
    /// Cost per rad² of turning-angle misfit (`w₃` of Eq. 5.7).
    pub weight_shape: f64,
    /// The handle's arclength lies within `[l / max_scale, l · max_scale]` for a stroke of
    /// length `l`.
    pub max_scale: f64,
    /// A match is confident only if its score is at least this many times the score of the
    /// best distinct alternative (another silhouette, or a non-overlapping handle).
    pub min_score_ratio: f64,
    /// Douglas–Peucker tolerance (px) of the silhouette delegates whose turning angles are
    /// compared.
    pub silhouette_tolerance_px: f64,
}

impl Default for MatchParams {
    fn default() -> Self {
        MatchParams {
            max_distance_px: 80.0,
            confident_distance_px: 40.0,
            weight_near: 0.04,
            weight_far: 0.06,
            weight_shape: 4.0,
            max_scale: 3.0,
            min_score_ratio: 1.3,
            silhouette_tolerance_px: 1.5,
        }
    }
}

/// A candidate handle: silhouette `track` on arclength `lo..hi` (unrolled; `hi > lo`),
/// travelled from `hi` to `lo` by the stroke when `reversed`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Segment {
    pub(super) track: usize,
    pub(super) lo: f64,
    pub(super) hi: f64,
    pub(super) reversed: bool,
}

/// The stroke as matching sees it.
pub(super) struct Target {
    pub(super) first: DVec2,
    pub(super) last: DVec2,
    pub(super) length: f64,
    pub(super) forward: TurningSummary,
    pub(super) backward: TurningSummary,
}

/// `w_near Prox_near + w_far Prox_far` for the distances of the two corresponding ends.
pub(super) fn proximity_cost(distance_a: f64, distance_b: f64, params: &MatchParams) -> f64 {
    params.weight_near * distance_a.min(distance_b) + params.weight_far * distance_a.max(distance_b)
}

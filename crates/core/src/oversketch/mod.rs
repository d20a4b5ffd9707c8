//! Automatic over-sketching, the screen-space half: which silhouette piece a stroke
//! redraws, where its points go, and which vertices may move.
//!
//! After SilSketch (Nealen, Sorkine, Alexa and Cohen-Or 2005; Nealen's dissertation ch. 5)
//! and SEED (Bao and Howard 2014). The steps, each working on plain screen polylines
//! (CSS px, y down), independent of how silhouettes are extracted:
//! 1. [`simplify_stroke`]: resampling and Douglas–Peucker (§5.4).
//! 2. [`match_stroke`]: the handle, by proximity of the ends and similarity of
//!    turning-angle summaries under sampled scale and shift (§5.4.2, Eqs. 5.3–5.7), with a
//!    `confident` flag instead of a silent guess; [`handle_points`] cuts it out.
//! 3. [`map_to_stroke`] and [`blend_ends`]: targets by relative arclength, blended into the
//!    untouched silhouette at the ends (SEED Eqs. 4–7); [`map_point_to_stroke`] for
//!    points beside the handle (§5.4.3).
//! 4. [`roi_from_displacements`]: the ROI grown within a union of spheres (§5.4.4), or
//!    [`part_roi`]: SEED's part of the model around the handle, by thickness (SEED §4).
//!
//! Edge silhouettes ([`crate::silhouette::edge_silhouettes`]) are the outline as rendered;
//! tests measure against them.
//!
//! [`oversketch`] runs all of it on a mesh: silhouettes, matching, targets unprojected at
//! each handle point's depth, ROI and a detail-preserving [`LaplacianEdit`](crate::deform::LaplacianEdit);
//! [`preview_handle`] shows the would-be handle while the stroke is drawn ([`Outlines`] finds
//! the silhouettes once per stroke).

mod bend;
mod candidate;
mod error;
mod manual;
mod mapping;
mod matching;
mod mixture;
mod part_roi;
mod pipeline;
mod roi;
mod scoring;
mod track;
mod turning;

pub use bend::{
    BLEND_GAP_PX, BendOptions, MIN_BLEND_PX, MIN_ROI_EDGES, ROI_FACTOR, outline_targets,
};
pub use candidate::MatchParams;
pub use error::OversketchError;
pub use manual::{
    ManualHandle, OutlineKind, PICK_DISTANCE_PX, PICK_SHARE, SURFACE_HANDLE_SPACING_PX,
    manual_handle_preview, oversketch_manual, pick_handle,
};
pub use mapping::{BLEND_WIDTH, blend_ends, blend_weight, map_point_to_stroke, map_to_stroke};
pub use matching::{Match, STROKE_SPACING_PX, STROKE_TOLERANCE_PX, match_stroke, simplify_stroke};
pub use mixture::Mixture;
pub use part_roi::{BACKGROUND_SAMPLES, MAX_PART_SHARE, MIN_SEEDS, PART_SMOOTHNESS, part_roi};
pub use pipeline::{
    Outlines, Oversketched, SOFT_FIT_WEIGHT, oversketch, oversketch_with, preview_handle,
};
pub use roi::{OversketchRoi, ROI_RADIUS_FACTOR, roi_from_displacements};
pub use track::{CLOSED_TOLERANCE_PX, handle_points};

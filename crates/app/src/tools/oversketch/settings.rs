//! The over-sketch tool's settings, kept across strokes, and the toolbar panel that sets them.

use sketchmesh_core::document::OversketchFit;
use sketchmesh_core::oversketch::{OutlineKind, OversketchRoi};

/// The user's over-sketch settings, kept across strokes and cancels.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OversketchSettings {
    /// How closely the outline follows the stroke.
    pub fit: OversketchFit,
    /// Pick the handle first instead of letting the stroke find it.
    pub manual: bool,
    /// Which region may move.
    pub roi: OversketchRoi,
    /// Which outline a manual pick takes: the smooth silhouette, or the mesh edges as
    /// rendered (a sharp crest seen edge-on).
    pub outline: OutlineKind,
}

/// The over-sketch mode's switches: manual handle picking, the fit and the region.
pub fn options_ui(ui: &mut egui::Ui, settings: &mut OversketchSettings) {
    let hint = "On: pick what moves first (draw along an outline, or across the model), then \
                draw its new shape. Off: the stroke finds the outline (K)";
    ui.toggle_value(&mut settings.manual, "Pick handle")
        .on_hover_text(hint);
    let hint = "On: the outline lands on the stroke. Off: it follows the stroke as far as the \
                surface detail allows, so a rough stroke bends the shape less";
    let fit = [OversketchFit::Exact, OversketchFit::Soft];
    toggle_between(ui, &mut settings.fit, fit, "Exact fit", hint);
    let hint = "On: the part the outline belongs to bends as a whole (an ear, a finger, told \
                apart by thickness) and the rest stays. Off: only the surface near the outline \
                moves, farther for a longer pull (A)";
    let roi = [OversketchRoi::Part, OversketchRoi::NearHandle];
    toggle_between(ui, &mut settings.roi, roi, "Whole part", hint);
    if settings.manual {
        let hint = "On: pick the outline as drawn, along mesh edges: a sharp crest seen \
                    edge-on, such as a ridge. Off: the smooth silhouette between them";
        let outline = [OutlineKind::Edge, OutlineKind::Smooth];
        toggle_between(ui, &mut settings.outline, outline, "Edge outline", hint);
    }
}

/// A toggle button for a setting with two values, `[on, off]`.
fn toggle_between<T: Copy + PartialEq>(
    ui: &mut egui::Ui,
    value: &mut T,
    [on, off]: [T; 2],
    label: &str,
    hint: &str,
) {
    let mut is_on = *value == on;
    if ui
        .toggle_value(&mut is_on, label)
        .on_hover_text(hint)
        .changed()
    {
        *value = if is_on { on } else { off };
    }
}

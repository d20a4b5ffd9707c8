//! The optimize tool (Nealen's dissertation ch. 6): tap a model (or draw a lasso around part
//! of one), choose the mode and the weights, drag the amount; the model previews each
//! setting, and Apply commits the last one as one undoable `optimize` op.
//!
//! The tap begins an `optimize` edit as a gesture (as a pull is begun at pointer-down);
//! every change in the panel revises its op ([`ToolOutput::Revise`]) and the app's next step
//! solves it. A new amount refactors on the kept analysis; a new mode or weight scheme
//! builds the system again (see `core::optimize::Optimizer`). Apply ends the gesture; the
//! preview of the final settings is the committed result.

use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::StrokePoint;
use sketchmesh_core::document::{
    Document, Op, OptimizeInput, StrokeInput, model_in_lasso, model_under,
};
use sketchmesh_core::optimize::{
    FeatureFalloff, LaplacianKind, Mode as OptimizeMode, OptimizeParams, WeightScheme,
};

use super::context::{ToolOutput, ViewCtx};
use super::draw::{DrawTool, is_tap};
use crate::input::router::ToolEvent;

/// The slider's range for the scale `s` (the thesis's positional weights lie in `[0, s]`).
const SCALE_RANGE: std::ops::RangeInclusive<f64> = 0.05..=4.0;

/// The optimize tool's state: the settings, and the model being previewed.
#[derive(Debug, Default)]
pub struct OptimizeTool {
    draw: DrawTool,
    settings: OptimizeParams,
    /// The model whose preview is open, if any.
    model: Option<usize>,
    /// The lasso bounding what moves, if one was drawn, and its samples for display.
    region: Option<(StrokeInput, Vec<StrokePoint>)>,
}

impl OptimizeTool {
    /// Feeds one event: a tap on a model opens its preview of the whole model, a lasso its
    /// preview of what the lasso holds (an open preview of another model is applied first).
    pub fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        let Some(input) = self.draw.capture(event, view) else {
            return ToolOutput::None;
        };
        let (model, region) = if is_tap(&input) {
            (model_under(doc, &input), None)
        } else {
            (model_in_lasso(doc, &input), Some(input))
        };
        let Some(model) = model else {
            let sentence = "Tap a model, or draw a lasso around part of one, to optimize it.";
            return ToolOutput::Refused(String::from(sentence));
        };
        let unchanged = self.model == Some(model) && region.is_none() && self.region.is_none();
        self.region = region.map(|r| {
            let points = r.points();
            (r, points)
        });
        let is_open = self.model.replace(model) == Some(model);
        match (unchanged, is_open) {
            (true, _) => ToolOutput::None,
            (false, true) => ToolOutput::Revise(self.op(model)),
            (false, false) => ToolOutput::Begin(self.op(model)),
        }
    }

    /// The lasso bounding the preview, for display while the view is the one it was drawn
    /// in (it is kept in screen points).
    pub fn lasso(&self, camera: &Camera) -> Option<&[StrokePoint]> {
        let (input, points) = self.region.as_ref()?;
        (input.camera == *camera).then_some(points.as_slice())
    }

    fn op(&self, model: usize) -> Op {
        Op::Optimize(OptimizeInput {
            model,
            settings: self.settings,
            region: self.region.as_ref().map(|(input, _)| input.clone()),
        })
    }

    /// Multiplies the amount (the scale `s`) by `factor` within the slider's range (the `[`
    /// and `]` keys); the open preview follows.
    pub fn nudge(&mut self, factor: f64) -> ToolOutput {
        let (lo, hi) = (*SCALE_RANGE.start(), *SCALE_RANGE.end());
        self.settings.scale = (self.settings.scale * factor).clamp(lo, hi);
        match self.model {
            Some(model) => ToolOutput::Revise(self.op(model)),
            None => ToolOutput::None,
        }
    }

    /// Applies the open preview, if any.
    pub fn confirm(&mut self) -> ToolOutput {
        self.region = None;
        match self.model.take() {
            Some(_) => ToolOutput::Finish,
            None => ToolOutput::None,
        }
    }

    /// Forgets the open preview (the app cancels its edit).
    pub fn cancel(&mut self) {
        self.draw = DrawTool::Idle;
        self.model = None;
        self.region = None;
    }

    /// What the tool asks for while no model is previewed.
    pub fn hint(&self) -> Option<&'static str> {
        self.model.is_none().then_some(
            "Tap a model, or draw a lasso around part of one, to preview its optimization",
        )
    }

    /// The panel: the settings, and Apply and Cancel while a preview is open.
    pub fn settings_ui(&mut self, ui: &mut egui::Ui) -> ToolOutput {
        let before = self.settings;
        let s = &mut self.settings;
        combo(
            ui,
            "optimize-mode",
            &mut s.mode,
            &[
                (
                    OptimizeMode::Shape,
                    "Better triangles",
                    "Even out the triangles, keep the look (§6.5)",
                ),
                (
                    OptimizeMode::Smooth,
                    "Smooth",
                    "Remove noise; a smaller amount smooths more (§6.6)",
                ),
            ],
        );
        combo(
            ui,
            "optimize-weights",
            &mut s.weights,
            &[
                (
                    WeightScheme::Cdf,
                    "Curvature rank",
                    "Weights from the rank of the curvature: curved places hold most",
                ),
                (
                    WeightScheme::Linear,
                    "Curvature",
                    "Weights linear in the curvature, outliers cut off",
                ),
                (WeightScheme::Const, "Uniform", "The same weight everywhere"),
            ],
        );
        if s.mode == OptimizeMode::Smooth {
            combo(
                ui,
                "optimize-laplacian",
                &mut s.laplacian,
                &[
                    (
                        LaplacianKind::Uniform,
                        "Uniform",
                        "Also evens out the vertex spacing",
                    ),
                    (
                        LaplacianKind::Cotan,
                        "Cotangent",
                        "Follows the geometry, keeps the spacing",
                    ),
                    (
                        LaplacianKind::CotanCurvature,
                        "Curvature flow",
                        "Moves by the mean curvature",
                    ),
                ],
            );
        }
        ui.add(
            egui::Slider::new(&mut s.scale, SCALE_RANGE)
                .logarithmic(true)
                .text("Hold"),
        )
        .on_hover_text("How strongly vertices hold their place (the scale s; [ and ] step it)");
        ui.toggle_value(&mut s.features, "Keep edges")
            .on_hover_text("Sharp features keep their place (§6.5.3)");
        if s.features {
            combo(
                ui,
                "optimize-falloff",
                &mut s.feature_falloff,
                &[
                    (
                        FeatureFalloff::Linear,
                        "Edges: linear",
                        "Hold grows with the curvature (§6.5.3)",
                    ),
                    (
                        FeatureFalloff::Cdf,
                        "Edges: rank",
                        "Hold grows with the curvature's rank",
                    ),
                    (
                        FeatureFalloff::Gaussian,
                        "Edges: soft",
                        "Only the most curved places hold",
                    ),
                ],
            );
        }
        if s.mode == OptimizeMode::Shape {
            ui.toggle_value(&mut s.tangent_plane, "On surface")
                .on_hover_text(
                    "Vertices slide on their tangent planes: closer to the input, slower",
                );
            ui.toggle_value(&mut s.quality, "Fix slivers")
                .on_hover_text("Vertices of poor triangles move more freely (§6.5.2)");
        }
        let Some(model) = self.model else {
            return ToolOutput::None;
        };
        if self.region.is_some()
            && ui
                .button("Whole model")
                .on_hover_text("Drop the lasso: optimize all of the model")
                .clicked()
        {
            self.region = None;
            return ToolOutput::Revise(self.op(model));
        }
        if ui
            .button("Apply")
            .on_hover_text("Keep this result: one undo step (Enter)")
            .clicked()
        {
            return self.confirm();
        }
        if ui
            .button("Cancel")
            .on_hover_text("Leave the model as it was (Esc)")
            .clicked()
        {
            self.cancel();
            return ToolOutput::Cancel;
        }
        if self.settings == before {
            ToolOutput::None
        } else {
            ToolOutput::Revise(self.op(model))
        }
    }
}

/// A drop-down for one setting: `(value, label, hint)` per choice.
fn combo<T: Copy + PartialEq>(
    ui: &mut egui::Ui,
    id: &str,
    value: &mut T,
    choices: &[(T, &str, &str)],
) {
    let selected = choices.iter().find(|c| c.0 == *value).map_or("", |c| c.1);
    egui::ComboBox::from_id_salt(id)
        .selected_text(selected)
        .show_ui(ui, |ui| {
            for &(choice, label, hint) in choices {
                ui.selectable_value(value, choice, label)
                    .on_hover_text(hint);
            }
        });
}

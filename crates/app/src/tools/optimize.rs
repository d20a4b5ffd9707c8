//! The optimize tool (Nealen's dissertation ch. 6): tap a model, choose the mode and the
//! weights, drag the amount; the model previews each setting, and Apply commits the last one
//! as one undoable `optimize` op.
//!
//! The tap begins an `optimize` edit as a gesture (as a pull is begun at pointer-down);
//! every change in the panel revises its op ([`ToolOutput::Revise`]) and the app's next step
//! solves it. A new amount refactors on the kept analysis; a new mode or weight scheme
//! builds the system again (see `core::optimize::Optimizer`). Apply ends the gesture; the
//! preview of the final settings is the committed result.

use sketchmesh_core::document::{Document, Op, OptimizeInput, StrokeInput, model_under};
use sketchmesh_core::optimize::{
    LaplacianKind, Mode as OptimizeMode, OptimizeParams, WeightScheme,
};

use super::context::{ToolOutput, ViewCtx};
use super::draw::DrawTool;
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
}

impl OptimizeTool {
    /// Feeds one event: a tap on a model opens its preview (applying the one open before).
    pub fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        let Some(input) = self.draw.capture(event, view) else {
            return ToolOutput::None;
        };
        self.tap(&input, doc)
    }

    fn tap(&mut self, input: &StrokeInput, doc: &Document) -> ToolOutput {
        match model_under(doc, input) {
            Some(model) if Some(model) == self.model => ToolOutput::None,
            Some(model) => {
                self.model = Some(model);
                ToolOutput::Begin(self.op(model))
            }
            None => ToolOutput::Refused(String::from("Tap a model to optimize it.")),
        }
    }

    fn op(&self, model: usize) -> Op {
        Op::Optimize(OptimizeInput {
            model,
            settings: self.settings,
        })
    }

    /// Applies the open preview, if any.
    pub fn confirm(&mut self) -> ToolOutput {
        match self.model.take() {
            Some(_) => ToolOutput::Finish,
            None => ToolOutput::None,
        }
    }

    /// Forgets the open preview (the app cancels its edit).
    pub fn cancel(&mut self) {
        self.draw = DrawTool::Idle;
        self.model = None;
    }

    /// What the tool asks for while no model is previewed.
    pub fn hint(&self) -> Option<&'static str> {
        self.model
            .is_none()
            .then_some("Tap a model to preview its optimization")
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
        .on_hover_text("How strongly vertices hold their place (the scale s)");
        ui.toggle_value(&mut s.features, "Keep edges")
            .on_hover_text("Sharp features keep their place (§6.5.3)");
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

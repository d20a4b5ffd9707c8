//! The optimize tool (Nealen's dissertation ch. 6): tap a model (or draw a lasso around part
//! of one, or paint over it), choose the mode and the weights, drag the amount; the model
//! previews each setting, and Apply commits the last one as one undoable `optimize` op.
//! Painting with the brush adds to the area that moves, or tags features that hold.
//!
//! The tap begins an `optimize` edit as a gesture (as a pull is begun at pointer-down);
//! every change in the panel revises its op ([`ToolOutput::Revise`]) and the app's next step
//! solves it. A new amount refactors on the kept analysis; a new mode or weight scheme
//! builds the system again (see `core::optimize::Optimizer`). Apply ends the gesture; the
//! preview of the final settings is the committed result.

mod icon;

use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::StrokePoint;
use sketchmesh_core::document::{
    BrushInput, Document, Op, OptimizeInput, StrokeInput, model_in_lasso, model_under,
};
use sketchmesh_core::optimize::{
    FeatureFalloff, LaplacianKind, Mode as OptimizeMode, OptimizeParams, WeightScheme,
    quality_report,
};

use crate::input::router::ToolEvent;
use crate::tools::context::{ToolOutput, ViewCtx};
use crate::tools::draw::{DrawTool, is_tap};
use crate::tools::hint::{Device, Hint};
use crate::tools::tool::{Gestures, Group, Mark, Tool, ToolInfo};
use crate::ui_size::target_size;

/// The optimize tool's name, icon, key and description.
static INFO: ToolInfo = ToolInfo {
    label: "Optimize",
    icon: icon::draw,
    key: egui::Key::M,
    group: Group::Tidy,
    about: "Tap a model: even out its triangles or smooth it, preview the amount, Apply",
    gestures: Gestures {
        pen: "Tap a model, then Apply",
        finger: "Tap a model, then Apply",
        mouse: "Click a model, then Apply (Enter)",
    },
    when: None,
};

/// The slider's range for the scale `s` (the thesis's positional weights lie in `[0, s]`).
const SCALE_RANGE: std::ops::RangeInclusive<f64> = 0.05..=4.0;

/// The brush's radius range in CSS px (at a mouse's pressure; a pen widens and narrows it).
const BRUSH_RANGE: std::ops::RangeInclusive<f64> = 6.0..=80.0;

/// What a stroke that is not a tap does.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
enum StrokeUse {
    /// A closed lasso around what moves (it replaces the previous one).
    #[default]
    Lasso,
    /// Paint over more of what moves.
    PaintArea,
    /// Paint over features that hold their place.
    PaintFeatures,
}

/// The optimize tool's state: the settings, and the model being previewed.
#[derive(Debug)]
pub struct OptimizeTool {
    draw: DrawTool,
    settings: OptimizeParams,
    stroke_use: StrokeUse,
    /// The brush's radius in CSS px.
    brush_radius: f64,
    /// The model whose preview is open, if any.
    model: Option<usize>,
    /// The lasso bounding what moves, if one was drawn, and its samples for display.
    region: Option<(StrokeInput, Vec<StrokePoint>)>,
    /// Brush strokes over more of what moves.
    painted: Vec<BrushInput>,
    /// Brush strokes over features that hold.
    painted_features: Vec<BrushInput>,
}

impl Default for OptimizeTool {
    fn default() -> Self {
        OptimizeTool {
            draw: DrawTool::default(),
            settings: OptimizeParams::default(),
            stroke_use: StrokeUse::default(),
            brush_radius: 20.0,
            model: None,
            region: None,
            painted: Vec::new(),
            painted_features: Vec::new(),
        }
    }
}

impl OptimizeTool {
    /// Feeds one event: a tap on a model opens its preview of the whole model, a lasso its
    /// preview of what the lasso holds, a brush stroke adds to what moves or holds (an open
    /// preview of another model is applied first).
    pub fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        let Some(input) = self.draw.capture(event, view) else {
            return ToolOutput::None;
        };
        let tap = is_tap(&input);
        let model = match tap {
            true => model_under(doc, &input),
            false => model_in_lasso(doc, &input),
        };
        let Some(model) = model else {
            let sentence =
                "Tap a model, or draw a lasso around or paint over part of one, to optimize it.";
            return ToolOutput::Refused(String::from(sentence));
        };
        let is_open = self.model.replace(model) == Some(model);
        if !is_open {
            self.clear_marks();
        }
        let changed = match (tap, self.stroke_use) {
            (true, _) => self.clear_area(),
            (false, StrokeUse::Lasso) => {
                let points = input.points();
                self.region = Some((input, points));
                true
            }
            (false, use_) => {
                let brush = BrushInput {
                    stroke: input,
                    radius: self.brush_radius,
                };
                match use_ {
                    StrokeUse::PaintFeatures => self.painted_features.push(brush),
                    _ => self.painted.push(brush),
                }
                true
            }
        };
        match (is_open, changed) {
            (false, _) => ToolOutput::Begin(self.op(model)),
            (true, true) => ToolOutput::Revise(self.op(model)),
            (true, false) => ToolOutput::None,
        }
    }

    /// Drops the lasso and the painted area, so that all of the model moves; returns whether
    /// either was there.
    fn clear_area(&mut self) -> bool {
        let had = self.region.is_some() || !self.painted.is_empty();
        self.region = None;
        self.painted.clear();
        had
    }

    /// Forgets every mark: lasso, painted area and painted features.
    fn clear_marks(&mut self) {
        self.region = None;
        self.painted.clear();
        self.painted_features.clear();
    }

    /// The lasso and brush strokes of the preview, for display while the view is the one
    /// each was drawn in (they are kept in screen points).
    pub fn marks(&self, camera: &Camera) -> Vec<Mark> {
        let lasso = (self.region.iter())
            .filter(|(input, _)| input.camera == *camera)
            .map(|(_, points)| Mark {
                points: points.clone(),
                radius: None,
                features: false,
            });
        let brush = |features: bool| {
            move |b: &BrushInput| {
                (b.stroke.camera == *camera).then(|| Mark {
                    points: b.stroke.points(),
                    radius: Some(b.radius),
                    features,
                })
            }
        };
        let painting = (self.stroke_use != StrokeUse::Lasso)
            .then(|| self.draw.preview())
            .flatten()
            .map(|points| Mark {
                points: points.to_vec(),
                radius: Some(self.brush_radius),
                features: self.stroke_use == StrokeUse::PaintFeatures,
            });
        lasso
            .chain(self.painted.iter().filter_map(brush(false)))
            .chain(self.painted_features.iter().filter_map(brush(true)))
            .chain(painting)
            .collect()
    }

    /// The lasso being drawn, for live display (a brush stroke being painted is a mark).
    pub fn preview(&self) -> Option<&[StrokePoint]> {
        (self.stroke_use == StrokeUse::Lasso)
            .then(|| self.draw.preview())
            .flatten()
    }

    fn op(&self, model: usize) -> Op {
        Op::Optimize(OptimizeInput {
            model,
            settings: self.settings,
            region: self.region.as_ref().map(|(input, _)| input.clone()),
            painted: self.painted.clone(),
            painted_features: self.painted_features.clone(),
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

    /// Strokes do the next thing: lasso, paint the area, paint features, lasso again.
    pub fn next_stroke_use(&mut self) {
        self.stroke_use = match self.stroke_use {
            StrokeUse::Lasso => StrokeUse::PaintArea,
            StrokeUse::PaintArea => StrokeUse::PaintFeatures,
            StrokeUse::PaintFeatures => StrokeUse::Lasso,
        };
    }

    /// Applies the open preview, if any.
    pub fn confirm(&mut self) -> ToolOutput {
        self.clear_marks();
        match self.model.take() {
            Some(_) => ToolOutput::Finish,
            None => ToolOutput::None,
        }
    }

    /// Forgets the open preview (the app cancels its edit).
    pub fn cancel(&mut self) {
        self.draw = DrawTool::Idle;
        self.model = None;
        self.clear_marks();
    }

    /// What the tool asks for: a model to preview, then to keep or drop the preview.
    pub fn hint(&self) -> &'static str {
        match self.model {
            None => {
                "{Tap} a model, or draw a lasso around or paint over part of one, to preview \
                 better triangles"
            }
            Some(_) => {
                "Compare, then Apply{enter} to keep it or Cancel; draw more to widen what moves"
            }
        }
    }

    /// The panel: the kind and the amount, Apply and Cancel, the strokes' use and brush,
    /// and the finer settings behind ⋯, so that the row fits a desktop's width and a
    /// tablet's shows Apply.
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
        ui.add(
            egui::Slider::new(&mut s.scale, SCALE_RANGE)
                .logarithmic(true)
                .text("Hold"),
        )
        .on_hover_text("How strongly vertices hold their place (the scale s; [ and ] step it)");
        let more = egui::Button::new("⋯").min_size(target_size(ui));
        egui::containers::menu::MenuButton::from_button(more)
            .ui(ui, |ui| finer_settings_ui(ui, s))
            .0
            .on_hover_text("Weights, the Laplacian, edges that hold, sliding on the surface");
        let painting = self.stroke_use != StrokeUse::Lasso;
        combo(
            ui,
            "optimize-strokes",
            &mut self.stroke_use,
            &[
                (
                    StrokeUse::Lasso,
                    "Lasso",
                    "A stroke around part of a model: only that part moves",
                ),
                (
                    StrokeUse::PaintArea,
                    "Paint area",
                    "Strokes over a model paint what moves",
                ),
                (
                    StrokeUse::PaintFeatures,
                    "Paint edges",
                    "Strokes over a model paint features that hold their place",
                ),
            ],
        );
        let brush = egui::Slider::new(&mut self.brush_radius, BRUSH_RANGE).text("Brush");
        ui.add_enabled(painting, brush)
            .on_hover_text("The brush's radius in points; a pen's pressure widens it");
        // The buttons are always there (disabled without a preview), so that the toolbar
        // keeps its height, and the view its place, when a preview opens or is applied.
        let open = self.model.is_some();
        let area_marked = self.region.is_some() || !self.painted.is_empty();
        let whole = button(
            ui,
            open && area_marked,
            "Whole model",
            "Drop the lasso and the painted area: optimize all of the model",
        );
        let clear_edges = button(
            ui,
            open && !self.painted_features.is_empty(),
            "Clear edges",
            "Forget the painted features",
        );
        let apply = button(ui, open, "Apply", "Keep this result: one undo step (Enter)");
        let cancel = button(ui, open, "Cancel", "Leave the model as it was (Esc)");
        let Some(model) = self.model else {
            return ToolOutput::None;
        };
        if apply {
            return self.confirm();
        }
        if cancel {
            self.cancel();
            return ToolOutput::Cancel;
        }
        if whole {
            self.clear_area();
        }
        if clear_edges {
            self.painted_features.clear();
        }
        if whole || clear_edges || self.settings != before {
            ToolOutput::Revise(self.op(model))
        } else {
            ToolOutput::None
        }
    }
}

/// The settings behind the panel's ⋯: the weights, the Laplacian (smoothing), the edges that
/// hold, and for better triangles sliding on the surface and freeing slivers.
fn finer_settings_ui(ui: &mut egui::Ui, s: &mut OptimizeParams) {
    choices_ui(
        ui,
        "Weights",
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
        choices_ui(
            ui,
            "Laplacian",
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
    ui.separator();
    ui.toggle_value(&mut s.features, "Keep edges")
        .on_hover_text("Sharp features keep their place (§6.5.3)");
    if s.features {
        choices_ui(
            ui,
            "Edges",
            &mut s.feature_falloff,
            &[
                (
                    FeatureFalloff::Linear,
                    "Linear",
                    "Hold grows with the curvature (§6.5.3)",
                ),
                (
                    FeatureFalloff::Cdf,
                    "Rank",
                    "Hold grows with the curvature's rank",
                ),
                (
                    FeatureFalloff::Gaussian,
                    "Soft",
                    "Only the most curved places hold",
                ),
            ],
        );
    }
    if s.mode == OptimizeMode::Shape {
        ui.toggle_value(&mut s.tangent_plane, "On surface")
            .on_hover_text("Vertices slide on their tangent planes: closer to the input, slower");
        ui.toggle_value(&mut s.quality, "Fix slivers")
            .on_hover_text("Vertices of poor triangles move more freely (§6.5.2)");
    }
}

/// One setting as a title and a radio button per choice: `(value, label, hint)`, for a
/// menu (where a drop-down's own pop-up would close it).
fn choices_ui<T: Copy + PartialEq>(
    ui: &mut egui::Ui,
    title: &str,
    value: &mut T,
    choices: &[(T, &str, &str)],
) {
    ui.strong(title);
    for &(choice, label, hint) in choices {
        ui.radio_value(value, choice, label).on_hover_text(hint);
    }
}

/// A button that is `enabled` or greyed out; whether it was clicked.
fn button(ui: &mut egui::Ui, enabled: bool, label: &str, hint: &str) -> bool {
    ui.add_enabled(enabled, egui::Button::new(label))
        .on_hover_text(hint)
        .clicked()
}

/// A drop-down for one setting: `(value, label, hint)` per choice.
fn combo<T: Copy + PartialEq>(
    ui: &mut egui::Ui,
    id: &str,
    value: &mut T,
    choices: &[(T, &str, &str)],
) {
    let selected = choices.iter().find(|c| c.0 == *value).map_or("", |c| c.1);
    let response = egui::ComboBox::from_id_salt(id)
        .selected_text(selected)
        .show_ui(ui, |ui| {
            for &(choice, label, hint) in choices {
                ui.selectable_value(value, choice, label)
                    .on_hover_text(hint);
            }
        })
        .response;
    // Screen readers name it by its setting ("optimize-mode": "optimize mode").
    let name = id.replace('-', " ");
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::ComboBox, true, &name));
}

impl Tool for OptimizeTool {
    fn info(&self) -> &'static ToolInfo {
        &INFO
    }

    fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        OptimizeTool::on_event(self, event, view, doc)
    }

    fn cancel(&mut self) -> ToolOutput {
        OptimizeTool::cancel(self);
        ToolOutput::None
    }

    fn panel(&mut self, ui: &mut egui::Ui, _doc: &Document) -> Option<ToolOutput> {
        Some(self.settings_ui(ui))
    }

    /// The optimized model's triangle quality, before and after.
    fn report(&self, op: &Op, before: &Document, after: &Document) -> Option<String> {
        let Op::Optimize(input) = op else {
            return None;
        };
        let (before, after) = (
            before.models.get(input.model)?,
            after.models.get(input.model)?,
        );
        Some(quality_report(&before.mesh, after.mesh.positions()).summary())
    }

    fn hint(&self, _doc: &Document, device: Device) -> Hint {
        device.say(OptimizeTool::hint(self))
    }

    fn preview(&self) -> Option<&[StrokePoint]> {
        OptimizeTool::preview(self)
    }

    fn marks(&self, camera: &Camera) -> Vec<Mark> {
        OptimizeTool::marks(self, camera)
    }

    /// Enter applies the preview; `[` and `]` step the amount; B: strokes lasso, paint the
    /// area or paint features.
    fn keys(&self) -> &'static [egui::Key] {
        &[
            egui::Key::Enter,
            egui::Key::OpenBracket,
            egui::Key::CloseBracket,
            egui::Key::B,
        ]
    }

    fn on_key(&mut self, key: egui::Key, _doc: &Document) -> ToolOutput {
        match key {
            egui::Key::Enter => self.confirm(),
            egui::Key::OpenBracket => self.nudge(1.0 / 1.25),
            egui::Key::CloseBracket => self.nudge(1.25),
            egui::Key::B => {
                self.next_stroke_use();
                ToolOutput::None
            }
            _ => ToolOutput::None,
        }
    }
}

#[cfg(test)]
mod tests {
    use egui::Key;
    use sketchmesh_core::document::Editor;

    use super::*;
    use crate::tools::test_support::{shape, stroke};

    /// The op of an output that opens or revises the preview.
    fn optimize_op(output: &ToolOutput) -> &OptimizeInput {
        match output {
            ToolOutput::Begin(Op::Optimize(input)) | ToolOutput::Revise(Op::Optimize(input)) => {
                input
            }
            other => panic!("not an optimize preview: {other:?}"),
        }
    }

    /// A loop of 200 px around the shape's middle, (400, 340) on screen.
    fn lasso() -> Vec<(f32, f32)> {
        (0..=40)
            .map(|k| {
                let a = std::f32::consts::TAU * k as f32 / 40.0;
                (400.0 + 200.0 * a.cos(), 340.0 + 200.0 * a.sin())
            })
            .collect()
    }

    #[test]
    fn a_tap_on_a_model_opens_its_preview_and_enter_applies_it() {
        let editor = shape();
        let doc = editor.document();
        let mut tool = OptimizeTool::default();
        assert!(
            Tool::hint(&tool, doc, Device::Pen).contains("a model"),
            "it asks for a model"
        );
        let tapped = stroke(&mut tool, doc, &[(400.0, 340.0)]).pop().unwrap();
        let input = optimize_op(&tapped);
        assert!(
            matches!(tapped, ToolOutput::Begin(_)),
            "the tap begins the preview"
        );
        assert_eq!(input.model, 0);
        assert!(input.region.is_none(), "a tap optimizes all of the model");
        assert_eq!(input.settings, OptimizeParams::default());
        assert!(
            Tool::hint(&tool, doc, Device::Pen).contains("Apply"),
            "a preview is open"
        );
        assert_eq!(tool.on_key(Key::Enter, doc), ToolOutput::Finish);
        assert_eq!(
            tool.on_key(Key::Enter, doc),
            ToolOutput::None,
            "nothing left to apply"
        );
    }

    #[test]
    fn a_tap_off_every_model_is_refused() {
        let editor = shape();
        let mut tool = OptimizeTool::default();
        let tapped = stroke(&mut tool, editor.document(), &[(30.0, 80.0)]).pop();
        assert!(matches!(tapped, Some(ToolOutput::Refused(_))), "{tapped:?}");
        let empty = Editor::new();
        let tapped = stroke(&mut tool, empty.document(), &[(400.0, 340.0)]).pop();
        assert!(matches!(tapped, Some(ToolOutput::Refused(_))), "{tapped:?}");
    }

    #[test]
    fn a_lasso_and_the_brackets_revise_the_open_preview() {
        let editor = shape();
        let doc = editor.document();
        let mut tool = OptimizeTool::default();
        stroke(&mut tool, doc, &[(400.0, 340.0)]);
        let lassoed = stroke(&mut tool, doc, &lasso()).pop().unwrap();
        assert!(matches!(lassoed, ToolOutput::Revise(_)), "{lassoed:?}");
        let region = optimize_op(&lassoed)
            .region
            .as_ref()
            .expect("the lasso bounds it");
        assert_eq!(region.stroke.len(), lasso().len());
        assert_eq!(tool.marks(&Camera::default()).len(), 1, "the lasso shows");
        let scale = OptimizeParams::default().scale;
        let more = tool.on_key(Key::CloseBracket, doc);
        assert!((optimize_op(&more).settings.scale - 1.25 * scale).abs() < 1e-12);
        let less = tool.on_key(Key::OpenBracket, doc);
        assert!((optimize_op(&less).settings.scale - scale).abs() < 1e-12);
    }

    #[test]
    fn cancel_forgets_the_preview_and_its_marks() {
        let editor = shape();
        let doc = editor.document();
        let mut tool = OptimizeTool::default();
        stroke(&mut tool, doc, &[(400.0, 340.0)]);
        stroke(&mut tool, doc, &lasso());
        assert_eq!(Tool::cancel(&mut tool), ToolOutput::None);
        assert!(tool.marks(&Camera::default()).is_empty());
        assert_eq!(
            tool.on_key(Key::Enter, doc),
            ToolOutput::None,
            "no preview to apply"
        );
        let tapped = stroke(&mut tool, doc, &[(400.0, 340.0)]).pop().unwrap();
        assert!(
            matches!(tapped, ToolOutput::Begin(_)),
            "a new tap opens a new preview"
        );
    }

    #[test]
    fn the_report_compares_the_optimized_model_with_the_one_before() {
        let mut editor = shape();
        let before = editor.document().clone();
        let mut tool = OptimizeTool::default();
        let tapped = stroke(&mut tool, &before, &[(400.0, 340.0)]).pop().unwrap();
        let ToolOutput::Begin(op) = tapped else {
            panic!("{tapped:?}");
        };
        editor.apply(op.clone()).unwrap();
        let report = tool.report(&op, &before, editor.document());
        let expected = quality_report(
            &before.models[0].mesh,
            editor.document().models[0].mesh.positions(),
        );
        assert_eq!(report, Some(expected.summary()));
        assert_eq!(tool.report(&Op::Undo, &before, editor.document()), None);
    }
}

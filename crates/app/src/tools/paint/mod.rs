//! The paint tool (issue 51): pen strokes paint vertex colours with a round brush whose
//! radius follows the pen's pressure; Fill paints a whole model; Pick takes the colour under
//! a tap; and the model last touched gets its material (base colour, roughness, metalness)
//! from the panel. The brush begins a `paint` edit as a gesture, which previews the colours
//! as the stroke goes (core's `PaintPreview`); the release commits it. With Symmetry on, the
//! app mirrors the op, and the mirror image is painted too.
//!
//! A stroke that begins off every model paints nothing and says nothing (as a brush in the
//! air does), rather than a refusal.

mod icon;

use glam::DVec2;
use sketchmesh_core::document::{
    Document, FillInput, MaterialInput, Op, PaintInput, StrokeInput, surface_at,
};
use sketchmesh_core::model::Finish;
use sketchmesh_core::paint::shown_colors;

use crate::input::router::ToolEvent;
use crate::tools::context::{ToolOutput, ViewCtx};
use crate::tools::draw::point;
use crate::tools::hint::{Device, Hint};
use crate::tools::tool::{Gestures, Group, Tool, ToolInfo};
use crate::ui_size::target_size;

/// The paint tool's name, icon, key and description.
static INFO: ToolInfo = ToolInfo {
    label: "Paint",
    icon: icon::draw,
    key: egui::Key::C,
    group: Group::Colour,
    about: "Paint colour on a model; fill it, pick a colour, set its material",
    gestures: Gestures {
        pen: "Paint over a model; press harder for a wider brush",
        finger: "Paint over a model with one finger",
        mouse: "Left-drag over a model",
    },
    when: None,
};

/// What a stroke or tap does.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
enum Kind {
    /// Strokes paint with the brush.
    #[default]
    Brush,
    /// A tap paints the whole model.
    Fill,
    /// A tap takes the colour under it.
    Pick,
}

/// The most recent colours kept as swatches.
const RECENT: usize = 8;

/// The brush's radius range, in points at full pressure.
const RADIUS_RANGE: std::ops::RangeInclusive<f64> = 2.0..=150.0;

/// The paint tool's state.
#[derive(Debug)]
pub struct PaintTool {
    kind: Kind,
    /// Linear RGB.
    color: [f32; 3],
    radius: f64,
    hardness: f64,
    opacity: f64,
    /// Colours used, newest first.
    recent: Vec<[f32; 3]>,
    /// Whether a brush stroke is being drawn (it began over a model).
    is_painting: bool,
    /// Whether the pointer went down off every model (the stroke is ignored).
    is_ignoring: bool,
    /// The model last painted, filled or picked from, and its material as the panel edits it.
    target: Option<(usize, Finish)>,
    /// Whether the panel changed the material since its last op.
    material_pending: bool,
}

impl Default for PaintTool {
    fn default() -> Self {
        Self {
            kind: Kind::Brush,
            color: [0.8, 0.1, 0.08],
            radius: 20.0,
            hardness: 0.5,
            opacity: 1.0,
            recent: Vec::new(),
            is_painting: false,
            is_ignoring: false,
            target: None,
            material_pending: false,
        }
    }
}

impl PaintTool {
    /// The model under a sample and the point of its surface there.
    fn hit(sample: [f64; 3], view: &ViewCtx, doc: &Document) -> Option<(usize, glam::DVec3)> {
        let stroke = StrokeInput {
            viewport: viewport(view),
            camera: view.camera,
            stroke: vec![sample],
        };
        surface_at(doc, &stroke, DVec2::new(sample[0], sample[1]))
    }

    /// Remembers `color` among the recent ones and `index` as the material's model.
    fn used(&mut self, color: [f32; 3], index: usize, doc: &Document) {
        self.recent.retain(|&c| c != color);
        self.recent.insert(0, color);
        self.recent.truncate(RECENT);
        self.target_model(index, doc);
    }

    fn target_model(&mut self, index: usize, doc: &Document) {
        if let Some(model) = doc.models.get(index) {
            self.target = Some((index, model.finish()));
        }
    }

    /// The brush's op for a stroke beginning at `sample`.
    fn paint_op(&self, sample: [f64; 3], view: &ViewCtx) -> Op {
        Op::Paint(PaintInput {
            viewport: viewport(view),
            camera: view.camera,
            stroke: vec![sample],
            color: self.color.map(f64::from),
            radius: self.radius,
            hardness: self.hardness,
            opacity: self.opacity,
        })
    }

    /// A tap in Fill or Pick.
    fn tap(&mut self, sample: [f64; 3], view: &ViewCtx, doc: &Document) -> ToolOutput {
        let Some((index, at)) = Self::hit(sample, view, doc) else {
            return ToolOutput::None;
        };
        match self.kind {
            Kind::Fill => {
                self.used(self.color, index, doc);
                ToolOutput::Commit(Op::Fill(FillInput {
                    model: index,
                    color: self.color.map(f64::from),
                }))
            }
            Kind::Pick | Kind::Brush => {
                let model = &doc.models[index];
                let nearest = (0..model.mesh.n_vertices()).min_by(|&a, &b| {
                    let d = |v: usize| model.mesh.positions()[v].distance_squared(at);
                    d(a).total_cmp(&d(b))
                });
                if let Some(v) = nearest {
                    self.color = shown_colors(model)[v];
                    self.kind = Kind::Brush;
                    self.target_model(index, doc);
                }
                ToolOutput::None
            }
        }
    }

    fn kinds_ui(&mut self, ui: &mut egui::Ui) {
        let size = target_size(ui);
        for (kind, label, about) in [
            (Kind::Brush, "Brush", "Strokes paint with the brush"),
            (Kind::Fill, "Fill", "Tap a model to paint all of it"),
            (Kind::Pick, "Pick", "Tap a model to take the colour there"),
        ] {
            let button = egui::Button::selectable(self.kind == kind, label).min_size(size);
            if ui.add(button).on_hover_text(about).clicked() {
                self.kind = kind;
            }
        }
    }

    fn colour_ui(&mut self, ui: &mut egui::Ui) {
        let size = target_size(ui);
        ui.spacing_mut().interact_size = size;
        egui::color_picker::color_edit_button_rgb(ui, &mut self.color)
            .on_hover_text("The brush's colour");
        for &color in &self.recent.clone() {
            let [r, g, b] = color;
            let swatch = egui::Button::new("")
                .fill(egui::Color32::from(egui::Rgba::from_rgb(r, g, b)))
                .min_size(egui::vec2(size.y * 0.75, size.y));
            if ui.add(swatch).on_hover_text("A recent colour").clicked() {
                self.color = color;
            }
        }
    }

    fn brush_ui(&mut self, ui: &mut egui::Ui) {
        let is_brush = self.kind == Kind::Brush;
        let sliders = [
            (
                egui::Slider::new(&mut self.radius, RADIUS_RANGE)
                    .logarithmic(true)
                    .text("Size"),
                "The brush's radius in points at full pressure (the mouse and a finger paint at full size)",
            ),
            (
                egui::Slider::new(&mut self.hardness, 0.0..=1.0).text("Hard"),
                "How much of the brush paints at full strength before its edge fades",
            ),
            (
                egui::Slider::new(&mut self.opacity, 0.0..=1.0).text("Opacity"),
                "How much colour one stroke lays down",
            ),
        ];
        for (slider, about) in sliders {
            ui.add_enabled(is_brush, slider).on_hover_text(about);
        }
    }

    /// The material of the model last touched: one `material` op once the pointer is up
    /// after a change (a drag in the colour picker or along a slider is one op, not one a
    /// frame).
    fn material_ui(&mut self, ui: &mut egui::Ui) -> Option<ToolOutput> {
        let Some((index, finish)) = &mut self.target else {
            ui.label("Paint or tap a model to set its material");
            return None;
        };
        let before = *finish;
        ui.label(format!("Model {}:", *index + 1));
        ui.spacing_mut().interact_size = target_size(ui);
        let [r, g, b, a] = finish.base_color;
        let mut base = egui::Rgba::from_rgba_unmultiplied(r, g, b, a);
        egui::color_picker::color_edit_button_rgba(
            ui,
            &mut base,
            egui::color_picker::Alpha::OnlyBlend,
        )
        .on_hover_text("Base colour: it tints the paint (white shows the paint as painted)");
        finish.base_color = base.to_rgba_unmultiplied();
        ui.add(egui::Slider::new(&mut finish.roughness, 0.0..=1.0).text("Rough"));
        ui.add(egui::Slider::new(&mut finish.metalness, 0.0..=1.0).text("Metal"));
        self.material_pending |= *finish != before;
        if !self.material_pending || ui.input(|i| i.pointer.any_down()) {
            return None;
        }
        self.material_pending = false;
        Some(material_op(*index, *finish))
    }
}

/// The op that gives model `index` the material `finish`.
fn material_op(index: usize, finish: Finish) -> ToolOutput {
    let [r, g, b, a] = finish.base_color;
    ToolOutput::Commit(Op::Material(MaterialInput {
        model: index,
        base_color: [r, g, b, a].map(f64::from),
        roughness: finish.roughness.into(),
        metalness: finish.metalness.into(),
    }))
}

/// The view's size, as ops record it.
fn viewport(view: &ViewCtx) -> [f64; 2] {
    let size = view.viewport.size();
    [size.x.into(), size.y.into()]
}

impl Tool for PaintTool {
    fn info(&self) -> &'static ToolInfo {
        &INFO
    }

    fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        let sample = |s| {
            let p = point(s, view);
            [p.pos.x, p.pos.y, p.pressure]
        };
        match event {
            ToolEvent::Begin(s) if self.kind == Kind::Brush => {
                let at = sample(s);
                match Self::hit(at, view, doc) {
                    Some((index, _)) => {
                        self.is_painting = true;
                        self.used(self.color, index, doc);
                        ToolOutput::Begin(self.paint_op(at, view))
                    }
                    None => {
                        self.is_ignoring = true;
                        ToolOutput::None
                    }
                }
            }
            ToolEvent::Move(s) if self.is_painting => ToolOutput::Extend(sample(s)),
            ToolEvent::End(s) if self.is_painting => {
                self.is_painting = false;
                ToolOutput::End(sample(s))
            }
            ToolEvent::End(s) if !self.is_ignoring => self.tap(sample(s), view, doc),
            ToolEvent::End(_) => {
                self.is_ignoring = false;
                ToolOutput::None
            }
            ToolEvent::Cancel => self.cancel(),
            _ => ToolOutput::None,
        }
    }

    fn cancel(&mut self) -> ToolOutput {
        let was_painting = self.is_painting;
        self.is_painting = false;
        self.is_ignoring = false;
        if was_painting {
            ToolOutput::Cancel
        } else {
            ToolOutput::None
        }
    }

    fn panel(&mut self, ui: &mut egui::Ui, doc: &Document) -> Option<ToolOutput> {
        // The material as the document has it now (a first stroke made its base white),
        // unless the panel is changing it.
        if let Some((index, finish)) = &mut self.target
            && !self.material_pending
        {
            match doc.models.get(*index) {
                Some(model) => *finish = model.finish(),
                None => self.target = None,
            }
        }
        self.kinds_ui(ui);
        self.colour_ui(ui);
        self.brush_ui(ui);
        let button = egui::Button::new("Material…").min_size(target_size(ui));
        let (_, inner) = egui::containers::menu::MenuButton::from_button(button)
            .ui(ui, |ui| self.material_ui(ui));
        // The menu closed with a change not yet committed: commit it now.
        let closed_with_change = inner.is_none() && self.material_pending;
        let committed = inner.and_then(|inner| inner.inner).or_else(|| {
            closed_with_change.then(|| {
                self.material_pending = false;
                self.target
                    .map(|(index, finish)| material_op(index, finish))
            })?
        });
        Some(committed.unwrap_or(ToolOutput::None))
    }

    fn hint(&self, _doc: &Document, device: Device) -> Hint {
        device.say(match (self.kind, self.is_painting) {
            (_, true) => "Painting; let go to keep it (undo takes the stroke back)",
            (Kind::Brush, false) => "Paint over a model {with}; {orbit}",
            (Kind::Fill, false) => "Tap a model to paint all of it in the brush's colour",
            (Kind::Pick, false) => "Tap a model to take its colour there",
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tools::test_support::{line, shape, stroke};

    #[test]
    fn a_stroke_over_a_model_paints_it_and_one_off_every_model_is_ignored() {
        let mut editor = shape();
        let mut tool = PaintTool::default();
        let outputs = stroke(
            &mut tool,
            editor.document(),
            &line((340.0, 340.0), (460.0, 340.0), 6),
        );
        let ToolOutput::Begin(Op::Paint(input)) = &outputs[0] else {
            panic!("a stroke over the shape begins a paint: {:?}", outputs[0]);
        };
        assert_eq!(input.stroke[0], [340.0, 300.0, 0.5]);
        assert!(matches!(outputs.last(), Some(ToolOutput::End(_))));
        // The op the gesture makes paints the shape, in the brush's colour.
        let mut op = input.clone();
        op.stroke
            .extend(outputs[1..].iter().filter_map(|o| match o {
                ToolOutput::Extend(s) | ToolOutput::End(s) => Some(*s),
                _ => None,
            }));
        editor.apply(Op::Paint(op)).unwrap();
        let colors = shown_colors(&editor.document().models[0]);
        assert!(colors.contains(&tool.color));
        // Off every model: nothing, and no sentence.
        let off = stroke(
            &mut tool,
            editor.document(),
            &line((20.0, 60.0), (90.0, 60.0), 4),
        );
        assert!(off.iter().all(|o| *o == ToolOutput::None), "{off:?}");
    }

    #[test]
    fn fill_paints_the_model_tapped_and_pick_takes_its_colour() {
        let mut editor = shape();
        let mut tool = PaintTool {
            kind: Kind::Fill,
            color: [0.1, 0.5, 0.2],
            ..PaintTool::default()
        };
        let outputs = stroke(&mut tool, editor.document(), &[(400.0, 340.0)]);
        let Some(ToolOutput::Commit(op)) = outputs.last() else {
            panic!("a tap fills: {outputs:?}");
        };
        assert_eq!(
            *op,
            Op::Fill(FillInput {
                model: 0,
                color: [0.1f32, 0.5, 0.2].map(f64::from),
            })
        );
        editor.apply(op.clone()).unwrap();
        let mut picker = PaintTool {
            kind: Kind::Pick,
            ..PaintTool::default()
        };
        stroke(&mut picker, editor.document(), &[(420.0, 320.0)]);
        assert_eq!(picker.color, [0.1, 0.5, 0.2]);
        assert_eq!(picker.kind, Kind::Brush, "a pick goes back to the brush");
        assert!(matches!(picker.target, Some((0, _))));
    }
}

//! The feature tool (Nealen's dissertation ch. 4, §4.4): sketch on a model, then drag to
//! raise a ridge or cut a ravine along the sketch, raise a bump or valley over its region,
//! or turn its Laplacians into suggestive contours; flattening applies at once.
//!
//! A closed loop drawn first is the region that may move; the next stroke is the sketch.
//! The drag that follows begins a `sketch_feature` edit as a gesture at pointer-down (so the
//! app, which commits or drops what is in progress when a pointer goes down, keeps it), each
//! move revises its amount (the core only re-weighs kept solutions), and release commits the
//! last amount. Dragging up (or right, for suggestive contours) raises: 15 px per unit of the
//! factor, so a drag of 100–150 px raises a ridge about as tall as its band is wide.

mod icon;

use crate::ui_size::target_size;
use glam::DVec2;
use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::{StrokePoint, is_closed_loop};
use sketchmesh_core::document::{
    CLOSE_TOLERANCE_PX, Document, Edit, Op, SketchFeatureInput, model_under,
};
use sketchmesh_core::feature::FeatureKind;

use crate::input::router::ToolEvent;
use crate::tools::context::{ToolOutput, ViewCtx};
use crate::tools::draw::{DrawTool, is_tap, point};
use crate::tools::hint::{Device, Hint};
use crate::tools::tool::{Gestures, Group, Mark, Tool, ToolInfo};

/// The feature tool's name, icon, key and description.
static INFO: ToolInfo = ToolInfo {
    label: "Feature",
    icon: icon::draw,
    key: egui::Key::D,
    group: Group::Reshape,
    about: "Sketch on a model, then drag: a ridge or ravine, a bump or valley, flattening, suggestive contours",
    gestures: Gestures {
        pen: "Draw on a model, then drag up or down",
        finger: "Draw on a model, then drag up or down",
        mouse: "Left-drag on a model, then drag up or down",
    },
    when: Some("For detail along a line: a ridge, a crease, a bump or a flat patch"),
};

/// Drag distance (CSS px) that changes a ridge's or bump's factor by one.
const PX_PER_FACTOR: f64 = 15.0;

/// Degrees a suggestive contour's Laplacians turn per CSS px of drag.
const DEGREES_PER_PX: f64 = 1.0;

/// Where the tool is.
#[derive(Debug, Default)]
enum Stage {
    /// Drawing the sketch (or, first, the region's loop).
    #[default]
    Sketching,
    /// The sketch is drawn: the next drag sets the amount.
    Sketched(SketchFeatureInput),
    /// Dragging the amount from where the pointer went down.
    Dragging(SketchFeatureInput, DVec2),
}

/// The feature tool's state: the kind, the region, the sketch and the drag.
#[derive(Debug, Default)]
pub struct FeatureTool {
    draw: DrawTool,
    kind: FeatureKind,
    /// The region's loop, in the view it was drawn in.
    region: Option<(Camera, Vec<StrokePoint>)>,
    stage: Stage,
}

impl FeatureTool {
    /// Feeds one event: strokes make the region and the sketch, the drag after them the
    /// feature.
    pub fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        match std::mem::take(&mut self.stage) {
            Stage::Sketching => self.sketch(event, view, doc),
            Stage::Sketched(input) => match event {
                ToolEvent::Begin(s) => {
                    let from = point(s, view).pos;
                    self.stage = Stage::Dragging(input.clone(), from);
                    ToolOutput::Begin(Op::SketchFeature(input))
                }
                _ => {
                    self.stage = Stage::Sketched(input);
                    ToolOutput::None
                }
            },
            Stage::Dragging(input, from) => match event {
                ToolEvent::Move(s) => {
                    let op = self.at(&input, point(s, view).pos - from);
                    self.stage = Stage::Dragging(input, from);
                    ToolOutput::Revise(op)
                }
                ToolEvent::End(s) => {
                    self.region = None;
                    ToolOutput::FinishWith(self.at(&input, point(s, view).pos - from))
                }
                ToolEvent::Cancel => {
                    self.region = None;
                    ToolOutput::Cancel
                }
                ToolEvent::Begin(_) => {
                    self.stage = Stage::Dragging(input, from);
                    ToolOutput::None
                }
            },
        }
    }

    /// A finished stroke: the region's loop, or the sketch (flattening applies at once).
    fn sketch(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        let Some(input) = self.draw.capture(event, view) else {
            return ToolOutput::None;
        };
        if is_tap(&input) {
            return ToolOutput::None;
        }
        let points = input.points();
        let region = self.region.as_ref().filter(|(c, _)| *c == input.camera);
        if region.is_none() && is_closed_loop(&points, CLOSE_TOLERANCE_PX) {
            self.region = Some((input.camera, points));
            return ToolOutput::None;
        }
        if model_under(doc, &input).is_none() {
            let sentence = "Start the sketch on a model: the feature goes where you draw on it.";
            return ToolOutput::Refused(String::from(sentence));
        }
        let sketch = SketchFeatureInput {
            viewport: input.viewport,
            camera: input.camera,
            stroke: input.stroke,
            kind: self.kind,
            amount: None,
            region: region.map(|(_, lasso)| loop_points(lasso)),
        };
        if self.kind == FeatureKind::Flatten {
            self.region = None;
            return ToolOutput::Commit(Op::SketchFeature(sketch));
        }
        self.stage = Stage::Sketched(sketch);
        ToolOutput::None
    }

    /// The op of `sketch` at the amount a drag by `offset` (CSS px, y down) sets.
    fn at(&self, sketch: &SketchFeatureInput, offset: DVec2) -> Op {
        let amount = match sketch.kind {
            FeatureKind::Suggestive => (offset.x * DEGREES_PER_PX).clamp(-180.0, 180.0),
            _ => 1.0 - offset.y / PX_PER_FACTOR,
        };
        Op::SketchFeature(SketchFeatureInput {
            amount: Some(amount),
            ..sketch.clone()
        })
    }

    /// Forgets the region, the sketch and the drag (the app cancels its edit).
    pub fn cancel(&mut self) {
        self.draw = DrawTool::Idle;
        self.region = None;
        self.stage = Stage::Sketching;
    }

    /// The stroke being drawn, for live display.
    pub fn preview(&self) -> Option<&[StrokePoint]> {
        self.draw.preview()
    }

    /// The region's loop and the sketch waiting for its drag, while the view is the one
    /// they were drawn in.
    pub fn marks(&self, camera: &Camera) -> Vec<Mark> {
        let region = (self.region.iter())
            .filter(|(c, _)| c == camera)
            .map(|(_, points)| Mark {
                points: points.clone(),
                radius: None,
                features: false,
            });
        let sketch = match &self.stage {
            // While dragging, the sketch gives way to the feature it makes.
            Stage::Sketched(input) if input.camera == *camera => Some(Mark {
                points: input.stroke_input().points(),
                radius: None,
                features: true,
            }),
            _ => None,
        };
        region.chain(sketch).collect()
    }

    /// What the tool asks the user to do next (while dragging, the amount shows instead:
    /// see `feature_amount`).
    pub fn hint(&self) -> &'static str {
        match (&self.stage, &self.region) {
            (Stage::Sketching, None) => {
                "Draw {with} on a model where the feature goes (a closed loop first sets the \
                 part that may move)"
            }
            (Stage::Sketching, Some(_)) => "Now draw the feature inside the loop",
            (Stage::Sketched(input) | Stage::Dragging(input, _), _) => match input.kind {
                FeatureKind::Suggestive => "Drag left or right to turn; let go to apply",
                FeatureKind::Flatten => "Drag to flatten; let go to apply",
                _ => "Drag up to raise, down to lower; let go to apply",
            },
        }
    }

    /// The panel: the kind, and the region's Clear.
    pub fn settings_ui(&mut self, ui: &mut egui::Ui) -> ToolOutput {
        for (kind, label, hint) in [
            (
                FeatureKind::Ridge,
                "Ridge",
                "A sharp ridge along the sketch (drag down: a ravine)",
            ),
            (
                FeatureKind::Bump,
                "Bump",
                "A smooth bump over the region (drag down: a valley)",
            ),
            (FeatureKind::Flatten, "Flatten", "Make the region flat"),
            (
                FeatureKind::Suggestive,
                "Suggestive",
                "Turn the region's curvature: suggestive contours (drag sideways)",
            ),
        ] {
            let button =
                egui::Button::selectable(self.kind == kind, label).min_size(target_size(ui));
            if ui.add(button).on_hover_text(hint).clicked() && self.kind != kind {
                self.kind = kind;
                self.stage = Stage::Sketching;
            }
        }
        let clear = ui.add_enabled(self.region.is_some(), egui::Button::new("Clear region"));
        if clear
            .on_hover_text("Back to a band along the sketch")
            .clicked()
        {
            self.region = None;
        }
        ToolOutput::None
    }
}

/// A loop's samples as the op's region: `[x, y]` each, the closing repeat dropped.
fn loop_points(points: &[StrokePoint]) -> Vec<[f64; 2]> {
    let mut lasso: Vec<[f64; 2]> = points.iter().map(|p| p.pos.to_array()).collect();
    if lasso.len() > 1 && lasso.first() == lasso.last() {
        lasso.pop();
    }
    lasso
}

impl Tool for FeatureTool {
    fn info(&self) -> &'static ToolInfo {
        &INFO
    }

    fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        FeatureTool::on_event(self, event, view, doc)
    }

    fn cancel(&mut self) -> ToolOutput {
        FeatureTool::cancel(self);
        ToolOutput::None
    }

    fn panel(&mut self, ui: &mut egui::Ui, _doc: &Document) -> Option<ToolOutput> {
        Some(self.settings_ui(ui))
    }

    /// A feature drag's amount as the user reads it, and where folding holds it back.
    fn edit_line(&self, edit: &Edit) -> Option<String> {
        feature_amount(edit)
    }

    fn hint(&self, _doc: &Document, device: Device) -> Hint {
        device.say(FeatureTool::hint(self))
    }

    fn preview(&self) -> Option<&[StrokePoint]> {
        FeatureTool::preview(self)
    }

    fn marks(&self, camera: &Camera) -> Vec<Mark> {
        FeatureTool::marks(self, camera)
    }

    fn gesture_refused(&mut self) {
        FeatureTool::cancel(self);
    }
}

/// A feature drag's amount as the user reads it, and where folding holds it back.
fn feature_amount(edit: &Edit) -> Option<String> {
    let Op::SketchFeature(input) = edit.op() else {
        return None;
    };
    let say = |amount: f64| match input.kind {
        FeatureKind::Suggestive => format!("turned {amount:.0}°"),
        FeatureKind::Flatten => String::from("flat"),
        _ if amount >= 1.0 => format!("raised {:.0}%", 100.0 * (amount - 1.0)),
        _ if amount >= 0.0 => format!("softened {:.0}%", 100.0 * (1.0 - amount)),
        _ => String::from("sunk in"),
    };
    let asked = say(input.amount());
    let said = match edit.limited_amount() {
        Some(held) => format!(
            "Held at {}: more would fold the surface over; let go to apply",
            say(held)
        ),
        None => format!(
            "{}{}; let go to apply",
            asked[..1].to_uppercase(),
            &asked[1..]
        ),
    };
    Some(said)
}

#[cfg(test)]
mod tests {
    use super::*;
    use sketchmesh_core::document::StrokeInput;

    fn input(points: &[DVec2]) -> StrokeInput {
        StrokeInput {
            viewport: [800.0, 600.0],
            camera: Camera::default(),
            stroke: points.iter().map(|p| [p.x, p.y, 0.5]).collect(),
        }
    }

    #[test]
    fn dragging_up_raises_and_sideways_turns() {
        let tool = FeatureTool::default();
        let sketch = SketchFeatureInput {
            viewport: [800.0, 600.0],
            camera: Camera::default(),
            stroke: input(&[DVec2::ZERO, DVec2::X]).stroke,
            kind: FeatureKind::Ridge,
            amount: None,
            region: None,
        };
        let amount = |kind, offset| match tool.at(
            &SketchFeatureInput {
                kind,
                ..sketch.clone()
            },
            offset,
        ) {
            Op::SketchFeature(input) => input.amount.unwrap(),
            _ => unreachable!(),
        };
        assert_eq!(amount(FeatureKind::Ridge, DVec2::ZERO), 1.0);
        assert!(amount(FeatureKind::Ridge, DVec2::new(0.0, -60.0)) > 4.0);
        assert!(amount(FeatureKind::Bump, DVec2::new(0.0, 45.0)) < -1.0);
        assert_eq!(amount(FeatureKind::Suggestive, DVec2::new(90.0, 0.0)), 90.0);
        assert_eq!(
            amount(FeatureKind::Suggestive, DVec2::new(900.0, 0.0)),
            180.0
        );
    }
}

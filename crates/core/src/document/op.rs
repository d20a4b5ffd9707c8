//! Session operations: the serializable inputs that change a document.

use glam::DVec2;
use serde::{Deserialize, Serialize};

use crate::camera::Camera;
use crate::curve::StrokePoint;

/// One session op. JSON is internally tagged: `{"op":"stroke",...}`, `{"op":"undo"}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "op", rename_all = "snake_case", deny_unknown_fields)]
pub enum Op {
    /// Draw a sketch stroke on the plane through the camera target facing the camera.
    Stroke(StrokeInput),
    /// Inflate a closed stroke drawn on empty canvas into a new FiberMesh model.
    Create(StrokeInput),
    /// Undo the last change.
    Undo,
    /// Redo the last undone change.
    Redo,
}

impl Op {
    /// The `"op"` tag of every kind of op, as written in session files (in step with
    /// [`Op::name`]; a test checks both against serde).
    pub const NAMES: &'static [&'static str] = &["stroke", "create", "undo", "redo"];

    /// The `"op"` tag of this op.
    pub fn name(&self) -> &'static str {
        match self {
            Op::Stroke(_) => "stroke",
            Op::Create(_) => "create",
            Op::Undo => "undo",
            Op::Redo => "redo",
        }
    }
}

/// A pointer stroke as the app saw it: the viewport and camera at the time, and the raw
/// samples.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StrokeInput {
    /// Viewport size `[width, height]` in CSS px.
    pub viewport: [f64; 2],
    /// The camera the stroke was drawn with.
    pub camera: Camera,
    /// Raw samples `[x, y, pressure]`: CSS px with the origin top-left and y down; pressure
    /// in 0..=1 (0.5 without a pen).
    pub stroke: Vec<[f64; 3]>,
}

impl StrokeInput {
    /// The samples as [`StrokePoint`]s.
    pub fn points(&self) -> Vec<StrokePoint> {
        self.stroke
            .iter()
            .map(|&[x, y, pressure]| StrokePoint::new(DVec2::new(x, y), pressure))
            .collect()
    }

    /// The viewport size in CSS px.
    pub fn viewport_size(&self) -> DVec2 {
        DVec2::from(self.viewport)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_match_serde_tags() {
        let ops = [
            Op::Stroke(StrokeInput {
                viewport: [1.0, 1.0],
                camera: Camera::default(),
                stroke: Vec::new(),
            }),
            Op::Create(StrokeInput {
                viewport: [1.0, 1.0],
                camera: Camera::default(),
                stroke: Vec::new(),
            }),
            Op::Undo,
            Op::Redo,
        ];
        assert_eq!(ops.len(), Op::NAMES.len());
        for (op, name) in ops.iter().zip(Op::NAMES) {
            let value = serde_json::to_value(op).unwrap();
            assert_eq!(value["op"], *name);
            assert_eq!(op.name(), *name);
        }
    }

    #[test]
    fn stroke_json_shape() {
        let op = Op::Stroke(StrokeInput {
            viewport: [800.0, 600.0],
            camera: Camera::default(),
            stroke: vec![[10.0, 20.0, 0.5], [30.5, 40.0, 0.75]],
        });
        let json = serde_json::to_string(&op).unwrap();
        assert_eq!(
            json,
            concat!(
                r#"{"op":"stroke","viewport":[800.0,600.0],"#,
                r#""camera":{"eye":[0.0,0.0,5.0],"target":[0.0,0.0,0.0],"up":[0.0,1.0,0.0],"fov_y_deg":45.0},"#,
                r#""stroke":[[10.0,20.0,0.5],[30.5,40.0,0.75]]}"#
            )
        );
        assert_eq!(serde_json::from_str::<Op>(&json).unwrap(), op);
        assert_eq!(
            serde_json::to_string(&Op::Undo).unwrap(),
            r#"{"op":"undo"}"#
        );
    }
}

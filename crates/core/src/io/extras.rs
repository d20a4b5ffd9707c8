//! The `"sketchmesh"` node extras: control curves and sketches, in full f64 precision.

use serde::{Deserialize, Serialize};

use crate::model::MirrorPlane;

/// Version of the `"sketchmesh"` extras object written by this build.
pub const EXTRAS_VERSION: u32 = 1;

/// The name of the material of models made here, by which import recognizes them (and
/// leaves them without an imported look).
pub(crate) const CLAY_MATERIAL_NAME: &str = "Sketchmesh clay";

/// The name of a material set here (the `material` op), by which import takes it back as
/// the model's finish.
pub(crate) const FINISH_MATERIAL_NAME: &str = "Sketchmesh finish";

/// The value of `extras` on a Sketchmesh node: `{"sketchmesh": {...}}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct NodeExtras {
    pub(crate) sketchmesh: SketchmeshExtras,
}

/// The `"sketchmesh"` object.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct SketchmeshExtras {
    pub(crate) version: u32,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub(crate) curves: Vec<CurveExtras>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub(crate) sketches: Vec<SketchExtras>,
    /// On a model node: the document's symmetry plane and how the model pairs across it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) mirror: Option<MirrorExtras>,
}

/// How a model pairs up across the document's symmetry plane: `{"plane": [nx, ny, nz, d]}`
/// for a symmetric model, with `"twin": j` for one whose mirror twin is model node `j`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct MirrorExtras {
    pub(crate) plane: MirrorPlane,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) twin: Option<usize>,
}

/// One control curve of a model.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct CurveExtras {
    pub(crate) closed: bool,
    pub(crate) sharp: bool,
    pub(crate) points: Vec<[f64; 3]>,
}

/// One sketch curve.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct SketchExtras {
    pub(crate) points: Vec<[f64; 3]>,
    pub(crate) pressures: Vec<f64>,
}

//! Session operations: the serializable inputs that change a document.

use std::sync::Arc;

use glam::DVec2;
use serde::{Deserialize, Serialize};

use super::CommandError;
use super::keyframes::KeyframeInput;
use super::volumetric::{CurveDeformInput, DeformInput};
use crate::camera::Camera;
use crate::curve::StrokePoint;
use crate::deform::HandleFit;
use crate::feature::FeatureKind;
use crate::model::{Finish, MirrorPlane, Side};
use crate::optimize::OptimizeParams;
use crate::oversketch::{ManualHandle, OversketchRoi, SOFT_FIT_WEIGHT};
use crate::paint::Brush;
use crate::skeleton::{HandleKind, PointEdit};

/// Declares [`Op`] from one list of variants, each with its `"op"` tag
/// (`Stroke(StrokeInput) = "stroke"`, `Undo = "undo"`), and derives from it everything that
/// must name every op: serde's tag for each variant, [`Op::NAMES`], [`Op::name`] and
/// [`Op::is_bare`]. Adding an op is one line here and its handler: an arm of
/// `outcome::outcome`, or for an op that [makes one model](Op::makes_one_model) an arm of
/// [`model_op`](super::model_op) and a name in that list.
macro_rules! op_list {
    (
        $(#[$meta:meta])*
        pub enum Op {
            $( $(#[$doc:meta])* $variant:ident $(($input:ty))? = $name:literal, )*
        }
    ) => {
        $(#[$meta])*
        pub enum Op {
            $( $(#[$doc])* #[serde(rename = $name)] $variant $(($input))?, )*
            /// An op made with symmetry on: written as the op with a `"mirror"` field (see
            /// [`Op::to_json`] and the session reader), not by serde.
            #[serde(skip)]
            Mirrored(Box<MirroredOp>),
        }

        impl Op {
            /// The `"op"` tag of every kind of op, as written in session files, in the order
            /// the variants are declared.
            pub const NAMES: &'static [&'static str] = &[$($name),*];

            /// The `"op"` tag of this op.
            pub fn name(&self) -> &'static str {
                match self {
                    $( Op::$variant { .. } => $name, )*
                    Op::Mirrored(mirrored) => mirrored.op.name(),
                }
            }

            /// Whether the op is just its `"op"` tag (undo, redo): serde lets extra fields
            /// of such variants pass, so the session reader refuses them itself.
            pub(super) fn is_bare(&self) -> bool {
                match self {
                    $( Op::$variant { .. } => op_list!(@bare $($input)?), )*
                    Op::Mirrored(_) => false,
                }
            }
        }
    };
    (@bare) => { true };
    (@bare $input:ty) => { false };
}

op_list! {
/// One session op. JSON is internally tagged: `{"op":"stroke",...}`, `{"op":"undo"}`.
///
/// The one list of ops: each variant's `"op"` tag is written beside it, and [`Op::NAMES`],
/// [`Op::name`] and the session's check of unit ops' fields are generated from it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "op", deny_unknown_fields)]
pub enum Op {
    /// Draw a sketch stroke on the plane through the camera target facing the camera.
    Stroke(StrokeInput) = "stroke",
    /// Inflate a closed stroke drawn on empty canvas into a new FiberMesh model.
    Create(CreateInput) = "create",
    /// Add the models, sketches and points of a glTF file.
    Import(ImportInput) = "import",
    /// Redraw part of a model's outline: the silhouette piece the stroke matches moves onto
    /// it and the surface around follows (see [`crate::oversketch::oversketch_with`]).
    Oversketch(OversketchInput) = "oversketch",
    /// Drag a point of a control curve (FiberMesh deform tool): the first sample is where the
    /// curve was grabbed, the last where it was released; the curve peels and the surface
    /// follows.
    Pull(StrokeInput) = "pull",
    /// Put a new smooth control curve on a model: the stroke drawn on it (open), a closed
    /// stroke on it, or a stroke across it (a cross-section loop).
    AddCurve(AddCurveInput) = "add_curve",
    /// Cut a model with the surface swept by a stroke drawn across it from beside it to beside
    /// it: the part smaller on screen goes, the opening gets a flat cap with a sharp rim.
    Cut(StrokeInput) = "cut",
    /// Remove the parts of control curves the stroke passes over; the surface re-optimizes.
    Erase(StrokeInput) = "erase",
    /// Drill a hole through a model between two closed loops drawn on it (usually on
    /// opposite sides, the second after orbiting).
    Tunnel(StrokePairInput) = "tunnel",
    /// Grow a limb out of a model: a closed base loop drawn on it, then the limb's
    /// silhouette from near one side of the loop out and back to near the other.
    Extrude(StrokePairInput) = "extrude",
    /// Join two overlapping models into one along their intersection (the merged model
    /// takes the lower index).
    Merge(MergeInput) = "merge",
    /// Move, rotate, scale or mirror a model by an affine matrix.
    Transform(TransformInput) = "transform",
    /// Remove a model.
    Delete(ModelInput) = "delete",
    /// Add a copy of a model beside it.
    Duplicate(DuplicateInput) = "duplicate",
    /// Make the parts of control curves the stroke passes over sharp or smooth.
    SetCurveType(CurveTypeInput) = "set_curve_type",
    /// Smooth the control curves near the stroke; each back-and-forth pass smooths more.
    Rub(StrokeInput) = "rub",
    /// Move a model's vertices by Laplacian mesh optimization (better triangles, or
    /// smoothing); its triangles and curves stay.
    Optimize(OptimizeInput) = "optimize",
    /// Sketch a feature on a model's surface: a ridge or ravine along the sketch, a bump or
    /// valley, a flattening or suggestive contours over its region.
    SketchFeature(SketchFeatureInput) = "sketch_feature",
    /// Move the region a boundary draws around a reference curve by a transform, with a
    /// fall-off from the curve to the boundary (Bujans' region editor).
    RegionEdit(RegionEditInput) = "region_edit",
    /// Make a curve handle (Blanco) from a stroke over a model or point cloud.
    CurveHandle(CurveHandleInput) = "curve_handle",
    /// Move, twist or scale a curve handle at one control point; the object follows.
    HandleEdit(HandleEditInput) = "handle_edit",
    /// Link two handles' control points into a skeleton.
    LinkHandles(LinkHandlesInput) = "link_handles",
    /// Remove a curve handle.
    DeleteHandle(DeleteHandleInput) = "delete_handle",
    /// A scripted large deformation: sphere handles moved by matrices, fixed spheres, the
    /// rest following through the volumetric graph Laplacian (or the surface editor).
    Deform(DeformInput) = "deform",
    /// Bend a model by a control curve: picked along its surface, redrawn in its editing
    /// plane; the volume follows (the volumetric graph Laplacian).
    CurveDeform(CurveDeformInput) = "curve_deform",
    /// Store every model's current pose as its key frame at a time.
    Keyframe(KeyframeInput) = "keyframe",
    /// Remove the key frames at a time.
    DeleteKeyframe(KeyframeInput) = "delete_keyframe",
    /// Put every animated model in its pose at a time.
    PoseAt(KeyframeInput) = "pose_at",
    /// Make a model mirror-symmetric about a plane, keeping one side.
    Symmetrize(SymmetrizeInput) = "symmetrize",
    /// Move or turn the document's symmetry plane (the Arrange tool's handles on it).
    SymmetryPlane(PlaneInput) = "symmetry_plane",
    /// Paint vertex colours with a round brush along a stroke over a model.
    Paint(PaintInput) = "paint",
    /// Paint a whole model one colour.
    Fill(FillInput) = "fill",
    /// Set a model's material: base colour, roughness, metalness.
    Material(MaterialInput) = "material",
    /// Undo the last change.
    Undo = "undo",
    /// Redo the last undone change.
    Redo = "redo",
}
}

/// An op made with symmetry on, and the plane it mirrors about.
#[derive(Clone, Debug, PartialEq)]
pub struct MirroredOp {
    /// The op as made.
    pub op: Op,
    /// The symmetry plane.
    pub plane: MirrorPlane,
}

/// A `symmetrize` op: `{"op":"symmetrize","model":0,"plane":[1,0,0,0],"keep":"positive"}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SymmetrizeInput {
    /// Index of the model in the document.
    pub model: usize,
    /// The plane `[nx, ny, nz, d]`: `n · x = d`, `n` a unit vector.
    pub plane: MirrorPlane,
    /// The side kept (`"positive"`: where `n · x > d`); the other becomes its mirror image.
    pub keep: Side,
}

/// A `symmetry_plane` op: `{"op":"symmetry_plane","plane":[1,0,0,0.25]}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlaneInput {
    /// The plane `[nx, ny, nz, d]`: `n · x = d`, `n` a unit vector.
    pub plane: MirrorPlane,
}

/// A `paint` op: a brush stroke over a model (the one under the stroke's first sample
/// that lies over one), `{"op":"paint","viewport":[w,h],"camera":{…},"stroke":[[x,y,p],…],
/// "color":[r,g,b],"radius":24,"hardness":0.5,"opacity":1}`. Numbers out of range are
/// clamped.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PaintInput {
    /// Viewport size `[width, height]` in CSS px.
    pub viewport: [f64; 2],
    /// The camera the stroke was drawn with.
    pub camera: Camera,
    /// Raw samples `[x, y, pressure]`, as in [`StrokeInput`].
    pub stroke: Vec<[f64; 3]>,
    /// Linear RGB, each 0..1.
    pub color: [f64; 3],
    /// The brush's radius in CSS px at full pressure (pressure 0.5 and above).
    pub radius: f64,
    /// The part of the radius painted at full strength, 0..1.
    pub hardness: f64,
    /// How much of the colour the stroke lays down, 0..1.
    pub opacity: f64,
}

impl PaintInput {
    /// The stroke part.
    pub fn stroke_input(&self) -> StrokeInput {
        StrokeInput::in_view(self.viewport, self.camera, &self.stroke)
    }

    /// The brush, its numbers clamped to their ranges.
    pub fn brush(&self) -> Brush {
        Brush {
            color: self.color.map(|c| c as f32),
            radius: self.radius,
            hardness: self.hardness,
            opacity: self.opacity,
        }
        .clamped()
    }
}

/// A `fill` op: `{"op":"fill","model":0,"color":[r,g,b]}`, linear RGB, clamped to 0..1.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FillInput {
    /// Index of the model in the document.
    pub model: usize,
    /// Linear RGB, each 0..1.
    pub color: [f64; 3],
}

/// A `material` op: `{"op":"material","model":0,"base_color":[r,g,b,a],"roughness":0.6,
/// "metalness":0}`, linear, each clamped to 0..1.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialInput {
    /// Index of the model in the document.
    pub model: usize,
    /// Linear RGBA base colour; painted colours multiply it.
    pub base_color: [f64; 4],
    /// 0 (smooth) to 1 (rough).
    pub roughness: f64,
    /// 0 (dielectric) to 1 (metal).
    pub metalness: f64,
}

impl MaterialInput {
    /// The finish it sets, clamped to its ranges.
    pub fn finish(&self) -> Finish {
        Finish {
            base_color: self.base_color.map(|c| c as f32),
            roughness: self.roughness as f32,
            metalness: self.metalness as f32,
        }
        .clamped()
    }
}

impl Op {
    /// This op made with symmetry on about `plane` (an op already mirrored keeps its own);
    /// ops that cannot be mirrored (undo, redo, import, symmetrize, moving the plane) stay
    /// as they are.
    pub fn mirrored(self, plane: MirrorPlane) -> Op {
        match self {
            Op::Undo
            | Op::Redo
            | Op::Import(_)
            | Op::Symmetrize(_)
            | Op::SymmetryPlane(_)
            | Op::Mirrored(_) => self,
            op => Op::Mirrored(Box::new(MirroredOp { op, plane })),
        }
    }

    /// The op as made and the plane it mirrors about, if it was made with symmetry on.
    pub fn into_parts(self) -> (Op, Option<MirrorPlane>) {
        match self {
            Op::Mirrored(mirrored) => (mirrored.op, Some(mirrored.plane)),
            op => (op, None),
        }
    }

    /// The op as made, without its symmetry.
    pub fn unmirrored(&self) -> &Op {
        match self {
            Op::Mirrored(mirrored) => &mirrored.op,
            op => op,
        }
    }

    /// The op as one line of session JSON.
    pub fn to_json(&self) -> String {
        if let Op::Import(input) = self {
            return input.to_json();
        }
        if let Op::Mirrored(mirrored) = self {
            let mut json = mirrored.op.to_json();
            let plane = serde_json::to_string(&mirrored.plane).unwrap_or_default();
            json.pop();
            json.push_str(&format!(",\"mirror\":{plane}}}"));
            return json;
        }
        // Serializing these plain structs cannot fail: every map key is a string and
        // serde_json writes non-finite numbers as null (which a refused op never logs anyway).
        serde_json::to_string(self).unwrap_or_else(|error| {
            debug_assert!(false, "op serialization failed: {error}");
            String::from("null")
        })
    }

    /// Whether the op makes one model, new or changed, and reads nothing but the document's
    /// models (a creation, the curve ops, the over-sketch, a curve's volumetric
    /// deformation, an optimization, a feature, a region edit, a scripted deformation, a
    /// merge, whose second model goes when the merged one lands): a pure function of the
    /// models and the op, which the page may compute in its worker
    /// ([`model_op`](super::model_op)).
    pub fn makes_one_model(&self) -> bool {
        matches!(
            self.unmirrored(),
            Op::Create(_)
                | Op::Oversketch(_)
                | Op::Pull(_)
                | Op::AddCurve(_)
                | Op::Cut(_)
                | Op::Tunnel(_)
                | Op::Extrude(_)
                | Op::Erase(_)
                | Op::SetCurveType(_)
                | Op::Rub(_)
                | Op::CurveDeform(_)
                | Op::Optimize(_)
                | Op::SketchFeature(_)
                | Op::RegionEdit(_)
                | Op::Deform(_)
                | Op::Merge(_)
                | Op::Symmetrize(_)
        )
    }

    /// What the op makes or does, as a sentence names it ("Computing the new shape…").
    pub fn title(&self) -> String {
        match self.unmirrored() {
            Op::Create(_) => String::from("new shape"),
            Op::Oversketch(_) => String::from("over-sketch"),
            other => other.name().replace('_', " "),
        }
    }

    /// The raw samples of the op's stroke; `None` for the ops without one (import, the ops
    /// on numbers and indices, undo, redo).
    pub fn stroke(&self) -> Option<&[[f64; 3]]> {
        match self.unmirrored() {
            Op::Stroke(input) | Op::Pull(input) => Some(&input.stroke),
            Op::Create(input) => Some(&input.stroke),
            Op::Erase(input) | Op::Rub(input) | Op::Cut(input) => Some(&input.stroke),
            Op::Oversketch(input) => Some(&input.stroke),
            Op::AddCurve(input) => Some(&input.stroke),
            Op::SetCurveType(input) => Some(&input.stroke),
            Op::SketchFeature(input) => Some(&input.stroke),
            Op::CurveHandle(input) => Some(&input.stroke),
            Op::CurveDeform(input) => Some(&input.stroke),
            Op::Paint(input) => Some(&input.stroke),
            _ => None,
        }
    }

    /// [`Op::stroke`] as [`StrokePoint`]s (none for the ops without a stroke).
    pub fn stroke_points(&self) -> Vec<StrokePoint> {
        self.stroke().map(points_of).unwrap_or_default()
    }

    /// [`Op::stroke`], to extend while the stroke is drawn.
    pub fn stroke_mut(&mut self) -> Option<&mut Vec<[f64; 3]>> {
        match self {
            Op::Mirrored(mirrored) => mirrored.op.stroke_mut(),
            Op::Stroke(input) | Op::Pull(input) => Some(&mut input.stroke),
            Op::Create(input) => Some(&mut input.stroke),
            Op::Erase(input) | Op::Rub(input) | Op::Cut(input) => Some(&mut input.stroke),
            Op::Oversketch(input) => Some(&mut input.stroke),
            Op::AddCurve(input) => Some(&mut input.stroke),
            Op::SetCurveType(input) => Some(&mut input.stroke),
            Op::SketchFeature(input) => Some(&mut input.stroke),
            Op::CurveHandle(input) => Some(&mut input.stroke),
            Op::CurveDeform(input) => Some(&mut input.stroke),
            Op::Paint(input) => Some(&mut input.stroke),
            _ => None,
        }
    }
}

impl Op {
    /// Every stroke the op was drawn with, each in its own view, in the order they were
    /// drawn: what a replay that shows how a document was made draws before applying the op
    /// (a pair's two loops, a region's reference curve then its boundary, a pose's curve
    /// then its new shape). None for the ops made with buttons, numbers or drags of
    /// handles.
    pub fn drawn_strokes(&self) -> Vec<StrokeInput> {
        let drawn = |viewport, camera, stroke: &[[f64; 3]]| {
            (!stroke.is_empty()).then(|| StrokeInput::in_view(viewport, camera, stroke))
        };
        match self.unmirrored() {
            Op::Tunnel(pair) | Op::Extrude(pair) => pair.strokes.to_vec(),
            Op::RegionEdit(input) => {
                let (viewport, camera) = (input.viewport, input.camera);
                [&input.reference, &input.boundary]
                    .into_iter()
                    .chain(input.areas.iter().map(|area| &area.lasso))
                    .filter_map(|stroke| drawn(viewport, camera, stroke))
                    .collect()
            }
            Op::CurveDeform(input) => {
                let (viewport, camera) = (input.viewport, input.camera);
                let redrawn = input.stroke_camera.unwrap_or(camera);
                [
                    input
                        .fixed
                        .as_deref()
                        .and_then(|s| drawn(viewport, camera, s)),
                    drawn(viewport, camera, &input.curve),
                    drawn(viewport, redrawn, &input.stroke),
                ]
                .into_iter()
                .flatten()
                .collect()
            }
            Op::Optimize(input) => (input.region.iter().cloned())
                .chain(input.painted.iter().map(|brush| brush.stroke.clone()))
                .chain(input.painted_features.iter().map(|b| b.stroke.clone()))
                .collect(),
            other => {
                let Some(stroke) = other.stroke() else {
                    return Vec::new();
                };
                let view = match other {
                    Op::Stroke(input) | Op::Pull(input) => Some((input.viewport, input.camera)),
                    Op::Erase(input) | Op::Rub(input) | Op::Cut(input) => {
                        Some((input.viewport, input.camera))
                    }
                    Op::Create(input) => Some((input.viewport, input.camera)),
                    Op::Oversketch(input) => Some((input.viewport, input.camera)),
                    Op::AddCurve(input) => Some((input.viewport, input.camera)),
                    Op::SetCurveType(input) => Some((input.viewport, input.camera)),
                    Op::SketchFeature(input) => Some((input.viewport, input.camera)),
                    Op::CurveHandle(input) => Some((input.viewport, input.camera)),
                    Op::Paint(input) => Some((input.viewport, input.camera)),
                    _ => None,
                };
                view.and_then(|(viewport, camera)| drawn(viewport, camera, stroke))
                    .into_iter()
                    .collect()
            }
        }
    }
}

/// The strokes of a `tunnel` op (`{"op":"tunnel","strokes":[first loop, second loop]}`,
/// each loop a closed stroke on the model) or an `extrude` op
/// (`{"op":"extrude","strokes":[base loop, silhouette]}`), each with its view
/// (`{viewport, camera, stroke}`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StrokePairInput {
    /// The two strokes, in the order they were drawn.
    pub strokes: [StrokeInput; 2],
}

/// A `transform` op: `{"op":"transform","model":0,"matrix":[16 numbers]}`, the matrix
/// column-major (glTF's order), affine and invertible.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TransformInput {
    /// Index of the model in the document.
    pub model: usize,
    /// The 4×4 matrix, column by column.
    pub matrix: [f64; 16],
}

/// A `merge` op: `{"op":"merge","models":[i,j]}`, indices in the document's model order.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MergeInput {
    /// The two models; the merged one takes the lower index, the other goes.
    pub models: [usize; 2],
}

impl MergeInput {
    /// The index the merged model takes and the one of the model that goes.
    pub fn kept_and_gone(&self) -> (usize, usize) {
        let [i, j] = self.models;
        (i.min(j), i.max(j))
    }
}

/// An op on one whole model (`delete`, `duplicate`): `{"op":"delete","model":0}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModelInput {
    /// Index of the model in the document.
    pub model: usize,
}

/// A `duplicate` op: which model, and the direction to place the copy along
/// (`{"op":"duplicate","model":0,"beside":[1.0,0.0,0.0]}`, the screen's right in the app).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DuplicateInput {
    /// Index of the model in the document.
    pub model: usize,
    /// The copy lands along this world direction, at the nearest spot where its bounding
    /// box overlaps no model's; without it (sessions from before), 1.2 of the model's widths
    /// along +x.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub beside: Option<[f64; 3]>,
}

/// An `optimize` op: which model, and the settings at the top level beside it
/// (`{"op":"optimize","model":0,"mode":"shape","weights":"cdf","scale":1.0}`); settings
/// left out take their defaults.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct OptimizeInput {
    /// Index of the model in the document.
    pub model: usize,
    /// How to optimize, written beside `model`.
    #[serde(flatten)]
    pub settings: OptimizeParams,
    /// The closed lasso, in the view it was drawn in, around the vertices that may move; the
    /// rest keep their place. Without it the whole model is optimized.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub region: Option<StrokeInput>,
    /// Brush strokes painted over vertices that may move, added to the lasso's.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub painted: Vec<BrushInput>,
    /// Brush strokes painted over features to keep (see [`crate::optimize::Selection`]).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub painted_features: Vec<BrushInput>,
}

/// A `sketch_feature` op: the sketch on the surface, what it makes, how much, and the
/// optional region.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SketchFeatureInput {
    /// Viewport size `[width, height]` in CSS px.
    pub viewport: [f64; 2],
    /// The camera the sketch was drawn with.
    pub camera: Camera,
    /// Raw samples `[x, y, pressure]` of the sketch on the surface, as in [`StrokeInput`].
    pub stroke: Vec<[f64; 3]>,
    /// What the sketch makes.
    pub kind: FeatureKind,
    /// For a ridge or bump, the factor applied to the Laplacians (1 leaves the surface as
    /// the embedded sketch left it, 0 flattens, a negative factor makes a ravine or
    /// valley); for suggestive contours the angle in degrees; ignored when flattening.
    /// Left out: the neutral amount.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub amount: Option<f64>,
    /// The closed lasso `[[x, y], …]` (first point not repeated) around the region that may
    /// move; left out: a band along the sketch.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub region: Option<Vec<[f64; 2]>>,
}

impl SketchFeatureInput {
    /// The amount, or the kind's neutral one.
    pub fn amount(&self) -> f64 {
        self.amount.unwrap_or(self.kind.neutral_amount())
    }

    /// The sketch's stroke part.
    pub fn stroke_input(&self) -> StrokeInput {
        StrokeInput::in_view(self.viewport, self.camera, &self.stroke)
    }
}

/// A `region_edit` op: the reference curve and the boundary around it, both drawn in one view,
/// the fall-off's levels and the transform.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RegionEditInput {
    /// Viewport size `[width, height]` in CSS px.
    pub viewport: [f64; 2],
    /// The camera both curves were drawn with.
    pub camera: Camera,
    /// Raw samples `[x, y, pressure]` of the reference curve, on the model.
    pub reference: Vec<[f64; 3]>,
    /// Raw samples `[x, y, pressure]` of the closed boundary around it (first point not
    /// repeated).
    pub boundary: Vec<[f64; 3]>,
    /// The fall-off's weights at evenly spaced closeness from the boundary (first) to the
    /// reference curve (last), linear between; left out: `[0, 0.25, 0.5, 0.75, 1]`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub levels: Option<Vec<f64>>,
    /// Parts of the region with levels of their own (Bujans §5.4), later over earlier.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub areas: Vec<AreaInput>,
    /// The 4×4 affine transform, column by column: a vertex of weight `w` moves by `w ⊙ T`.
    /// Exactly one of it and `handles`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub transform: Option<[f64; 16]>,
    /// Handles along the reference curve, each with its own transform, blended along it
    /// ([`crate::region_edit::Motion`]). Exactly one of it and `transform`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub handles: Option<Vec<HandleInput>>,
    /// Or a re-sketched cross-section across the reference curve (Bujans §6; see
    /// [`crate::region_edit::ProfileChange`]). Exactly one of `transform`, `handles` and it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub profile: Option<ProfileInput>,
    /// Whether the region is remeshed after it moved (Bujans §8.1), so stretched parts
    /// keep well-shaped triangles; left out: not. A model with imported texture
    /// coordinates or colours is never remeshed (they would be lost).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub remesh: bool,
}

/// A `curve_handle` op: the stroke over the object, in its view, and what handle it makes.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CurveHandleInput {
    /// Viewport size `[width, height]` in CSS px.
    pub viewport: [f64; 2],
    /// The camera the stroke was drawn with.
    pub camera: Camera,
    /// Raw samples `[x, y, pressure]`, as in [`StrokeInput`].
    pub stroke: Vec<[f64; 3]>,
    /// On the surface (the default) or a skeleton inside.
    #[serde(default)]
    pub kind: HandleKind,
    /// How many control points; left out: 4.
    #[serde(default = "default_control_points")]
    pub control_points: usize,
    /// Rigid limbs between the control points (Blanco §7); left out: a smooth curve.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub rigid: bool,
}

fn default_control_points() -> usize {
    4
}

impl CurveHandleInput {
    /// The stroke part.
    pub fn stroke_input(&self) -> StrokeInput {
        StrokeInput::in_view(self.viewport, self.camera, &self.stroke)
    }
}

/// A `handle_edit` op: at control point `point` of handle `handle`, any of a move, a twist
/// and a scale; a twist or scale reaches `spread` control points on each side, fading.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HandleEditInput {
    /// The handle's number.
    pub handle: u32,
    /// The control point.
    pub point: usize,
    /// Move it by this, in world units (with the control points linked to it).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub translate: Option<[f64; 3]>,
    /// Twist about the curve by this many degrees.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub twist_deg: Option<f64>,
    /// Scale across the curve by these factors (along the frame's two axes).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub scale: Option<[f64; 2]>,
    /// How many control points on each side a twist or scale reaches; left out: 1.
    #[serde(default = "default_spread")]
    pub spread: usize,
}

fn default_spread() -> usize {
    1
}

impl HandleEditInput {
    /// The change at the control point, its twist in radians.
    pub fn change(&self) -> PointEdit {
        PointEdit {
            point: self.point,
            translate: self.translate.map(glam::DVec3::from),
            twist: self.twist_deg.map(f64::to_radians),
            scale: self.scale,
            spread: self.spread,
        }
    }
}

/// A `link_handles` op: `{"a": [h, k], "b": [h2, k2]}`, control point `k` of handle `h`
/// and `k2` of `h2`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LinkHandlesInput {
    /// One handle's number and control point.
    pub a: (u32, usize),
    /// The other's.
    pub b: (u32, usize),
}

/// A `delete_handle` op.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DeleteHandleInput {
    /// The handle's number.
    pub handle: u32,
}

/// The profile of a `region_edit` op: where along the reference curve its plane sits and
/// the new cross-section drawn in it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProfileInput {
    /// The plane's place on the reference curve: 0 at its first end, 1 at its last.
    pub at: f64,
    /// The stroke `[u, v]` in the plane, in model units: `u` across the curve (along the
    /// binormal), `v` out of the surface (along its normal), from the curve's point there.
    pub stroke: Vec<[f64; 2]>,
}

/// An area of a `region_edit` op's fall-off: the region vertices seen inside its lasso (in
/// the op's view) take its levels.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AreaInput {
    /// Raw samples `[x, y, pressure]` of the lasso, closed (first point not repeated).
    pub lasso: Vec<[f64; 3]>,
    /// The levels inside it, as the op's `levels`.
    pub levels: Vec<f64>,
}

/// A handle of a `region_edit` op.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HandleInput {
    /// Where it sits on the reference curve: 0 at its first end, 1 at its last, by
    /// arclength.
    pub at: f64,
    /// Its 4×4 affine transform, column by column.
    pub transform: [f64; 16],
}

impl RegionEditInput {
    /// The reference curve's stroke part.
    pub fn reference_input(&self) -> StrokeInput {
        StrokeInput::in_view(self.viewport, self.camera, &self.reference)
    }

    /// Whether the op moves its region: a transform or a handle's other than the identity,
    /// or a profile.
    pub fn moves_region(&self) -> bool {
        let still = glam::DMat4::IDENTITY.to_cols_array();
        self.profile.is_some()
            || self.transform.is_some_and(|t| t != still)
            || (self.handles.iter().flatten()).any(|h| h.transform != still)
    }
}

/// A brush stroke painted on screen: the stroke in its view, and the brush's radius in CSS px
/// at a mouse's pressure (see [`crate::optimize::region::brushed_vertices`]).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct BrushInput {
    /// The stroke, its view and its samples beside `radius`.
    #[serde(flatten)]
    pub stroke: StrokeInput,
    /// The brush's radius in CSS px.
    pub radius: f64,
}

/// A `create` op: the closed stroke, and how finely the new shape is meshed.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CreateInput {
    /// Viewport size `[width, height]` in CSS px.
    pub viewport: [f64; 2],
    /// The camera the stroke was drawn with.
    pub camera: Camera,
    /// Raw samples `[x, y, pressure]`, as in [`StrokeInput`].
    pub stroke: Vec<[f64; 3]>,
    /// About how many vertices the shape gets; absent (left out of session files): the
    /// default, [`CreateParams::default`](crate::fibermesh::CreateParams)'s 2,500.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub vertices: Option<usize>,
}

impl From<StrokeInput> for CreateInput {
    /// A creation at the default resolution.
    fn from(input: StrokeInput) -> CreateInput {
        CreateInput {
            viewport: input.viewport,
            camera: input.camera,
            stroke: input.stroke,
            vertices: None,
        }
    }
}

/// An `add_curve` op: the stroke and which kind of curve it makes.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AddCurveInput {
    /// Viewport size `[width, height]` in CSS px.
    pub viewport: [f64; 2],
    /// The camera the stroke was drawn with.
    pub camera: Camera,
    /// Raw samples `[x, y, pressure]`, as in [`StrokeInput`].
    pub stroke: Vec<[f64; 3]>,
    /// A closed stroke on the surface (confirmed by a tap) makes a closed curve.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub closed: bool,
    /// A stroke across the model (confirmed by a tap) makes a cross-section loop.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub cross_section: bool,
}

/// An `oversketch` op: the stroke, and how closely the outline follows it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OversketchInput {
    /// Viewport size `[width, height]` in CSS px.
    pub viewport: [f64; 2],
    /// The camera the stroke was drawn with.
    pub camera: Camera,
    /// Raw samples `[x, y, pressure]`, as in [`StrokeInput`].
    pub stroke: Vec<[f64; 3]>,
    /// Exact (the default, left out of session files) or soft.
    #[serde(default, skip_serializing_if = "OversketchFit::is_exact")]
    pub fit: OversketchFit,
    /// The region that may move: near the handle (the default, left out of session files)
    /// or its part (`"part"`).
    #[serde(default, skip_serializing_if = "OversketchRoi::is_near_handle")]
    pub roi: OversketchRoi,
    /// The handle the user picked (manual mode), in the same screen space as the stroke;
    /// left out when matching picks it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub handle: Option<ManualHandle>,
}

/// How closely an over-sketched outline follows the stroke.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum OversketchFit {
    /// The outline lands on the stroke.
    #[default]
    Exact,
    /// The outline is drawn towards the stroke as far as the surface details allow: a
    /// rough stroke bends the shape less and keeps more of its detail.
    Soft,
}

impl OversketchFit {
    /// Whether this is [`OversketchFit::Exact`] (for serde's `skip_serializing_if`).
    pub fn is_exact(&self) -> bool {
        *self == OversketchFit::Exact
    }

    /// The handle fit of the Laplacian edit: soft handles weigh [`SOFT_FIT_WEIGHT`].
    pub fn handle_fit(self) -> HandleFit {
        match self {
            OversketchFit::Exact => HandleFit::Exact,
            OversketchFit::Soft => HandleFit::Soft {
                weight: SOFT_FIT_WEIGHT,
            },
        }
    }
}

/// A `set_curve_type` op: the stroke along the curves and the type they get.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CurveTypeInput {
    /// Viewport size `[width, height]` in CSS px.
    pub viewport: [f64; 2],
    /// The camera the stroke was drawn with.
    pub camera: Camera,
    /// Raw samples `[x, y, pressure]`, as in [`StrokeInput`].
    pub stroke: Vec<[f64; 3]>,
    /// `true`: the curves crease the surface; `false`: the surface is smooth across them.
    pub sharp: bool,
}

/// The files of an import: the .glb or .gltf first, then the files it refers to.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ImportInput {
    /// The files, main file first.
    pub files: Vec<FileInput>,
    /// Whether what the file brings lands beside the document's contents rather than where
    /// the file puts it (the app's imports; sessions from before it was there lack it).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub beside: bool,
}

impl ImportInput {
    /// The op's session JSON, exactly as serde writes it, with each file's base64 written
    /// straight into it: a scan's file is tens of megabytes, and serde would scan its base64
    /// once more for characters to escape (there are none), which doubled the first autosave
    /// after an import.
    fn to_json(&self) -> String {
        let engine = base64::engine::general_purpose::STANDARD;
        let size: usize = (self.files.iter())
            .map(|f| 32 + f.name.len() + f.data.as_ref().map_or(0, |d| d.len().div_ceil(3) * 4))
            .sum();
        let mut json = String::with_capacity(64 + size);
        json.push_str(r#"{"op":"import","files":["#);
        for (i, file) in self.files.iter().enumerate() {
            json.push_str(if i == 0 {
                r#"{"name":"#
            } else {
                r#",{"name":"#
            });
            json.push_str(&serde_json::Value::from(file.name.as_str()).to_string());
            if let Some(data) = &file.data {
                json.push_str(r#","data":""#);
                base64::Engine::encode_string(&engine, data.as_slice(), &mut json);
                json.push('"');
            }
            json.push('}');
        }
        json.push(']');
        if self.beside {
            json.push_str(r#","beside":true"#);
        }
        json.push('}');
        json
    }
}

/// One file of an import: its name and, once loaded, its bytes (base64 in JSON).
///
/// Sessions written by the app carry the bytes, so they replay anywhere; a hand-written
/// session may give only the name, and `sketchmesh replay` reads the file next to the session.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FileInput {
    /// The file name.
    pub name: String,
    /// The contents; `None` until loaded.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        with = "base64_bytes"
    )]
    pub data: Option<Arc<Vec<u8>>>,
}

/// Bytes as a standard base64 string.
mod base64_bytes {
    use std::sync::Arc;

    use base64::Engine as _;
    use serde::{Deserialize as _, Deserializer, Serializer};

    #[allow(clippy::ref_option)] // serde's `with` passes `&Option<T>`.
    pub(super) fn serialize<S: Serializer>(
        bytes: &Option<Arc<Vec<u8>>>,
        serializer: S,
    ) -> Result<S::Ok, S::Error> {
        match bytes {
            Some(bytes) => serializer
                .serialize_str(&base64::engine::general_purpose::STANDARD.encode(bytes.as_slice())),
            None => serializer.serialize_none(),
        }
    }

    pub(super) fn deserialize<'de, D: Deserializer<'de>>(
        deserializer: D,
    ) -> Result<Option<Arc<Vec<u8>>>, D::Error> {
        let text = String::deserialize(deserializer)?;
        base64::engine::general_purpose::STANDARD
            .decode(text)
            .map(|bytes| Some(Arc::new(bytes)))
            .map_err(serde::de::Error::custom)
    }
}

/// Raw samples `[x, y, pressure]` as [`StrokePoint`]s.
fn points_of(stroke: &[[f64; 3]]) -> Vec<StrokePoint> {
    stroke
        .iter()
        .map(|&[x, y, pressure]| StrokePoint::new(DVec2::new(x, y), pressure))
        .collect()
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
    /// The stroke part of a `create` op.
    pub fn of_create(input: &CreateInput) -> StrokeInput {
        StrokeInput::in_view(input.viewport, input.camera, &input.stroke)
    }

    /// The stroke part of an `add_curve` op.
    pub fn of_add_curve(input: &AddCurveInput) -> StrokeInput {
        StrokeInput::in_view(input.viewport, input.camera, &input.stroke)
    }

    /// The stroke part of an `oversketch` op.
    pub fn of_oversketch(input: &OversketchInput) -> StrokeInput {
        StrokeInput::in_view(input.viewport, input.camera, &input.stroke)
    }

    /// The stroke part of a `set_curve_type` op.
    pub fn of_curve_type(input: &CurveTypeInput) -> StrokeInput {
        StrokeInput::in_view(input.viewport, input.camera, &input.stroke)
    }

    /// Samples `stroke` drawn in a viewport of size `viewport` with `camera`: the stroke part
    /// of any op that keeps its view beside other fields.
    pub fn in_view(viewport: [f64; 2], camera: Camera, stroke: &[[f64; 3]]) -> StrokeInput {
        StrokeInput {
            viewport,
            camera,
            stroke: stroke.to_vec(),
        }
    }

    /// The samples as [`StrokePoint`]s.
    pub fn points(&self) -> Vec<StrokePoint> {
        points_of(&self.stroke)
    }

    /// The viewport size in CSS px.
    pub fn viewport_size(&self) -> DVec2 {
        DVec2::from(self.viewport)
    }

    /// The viewport size in CSS px, after checking that it and the camera can project.
    ///
    /// Errors: [`CommandError::BadView`].
    pub fn checked_viewport(&self) -> Result<DVec2, CommandError> {
        let viewport = self.viewport_size();
        let viewport_ok = viewport.is_finite() && viewport.x > 0.0 && viewport.y > 0.0;
        if viewport_ok && self.camera.is_valid() {
            Ok(viewport)
        } else {
            Err(CommandError::BadView)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stroke() -> StrokeInput {
        StrokeInput {
            viewport: [1.0, 1.0],
            camera: Camera::default(),
            stroke: Vec::new(),
        }
    }

    /// Every op's name is its serde tag (the golden sessions check this for every kind of
    /// op, from the ops they replay); the names are unique.
    #[test]
    fn names_are_the_serde_tags() {
        let ops = [
            Op::Pull(stroke()),
            Op::Tunnel(StrokePairInput {
                strokes: [stroke(), stroke()],
            }),
            Op::LinkHandles(LinkHandlesInput {
                a: (0, 3),
                b: (1, 0),
            }),
            Op::PoseAt(KeyframeInput { time: 0.0 }),
            Op::Redo,
        ];
        for op in ops {
            let value = serde_json::to_value(&op).unwrap();
            assert_eq!(value["op"], op.name());
            assert!(Op::NAMES.contains(&op.name()));
            assert_eq!(op.is_bare(), value.as_object().unwrap().len() == 1);
        }
        let mut names = Op::NAMES.to_vec();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), Op::NAMES.len(), "an \"op\" tag given twice");
    }

    #[test]
    fn import_json_carries_bytes_as_base64() {
        let op = Op::Import(ImportInput {
            files: vec![
                FileInput {
                    name: String::from("a.gltf"),
                    data: Some(Arc::new(b"{}".to_vec())),
                },
                FileInput {
                    name: String::from("a.bin"),
                    data: None,
                },
            ],
            beside: false,
        });
        let json = serde_json::to_string(&op).unwrap();
        assert_eq!(
            json,
            r#"{"op":"import","files":[{"name":"a.gltf","data":"e30="},{"name":"a.bin"}]}"#
        );
        assert_eq!(op.to_json(), json, "written by hand as serde writes it");
        let odd = Op::Import(ImportInput {
            files: vec![FileInput {
                name: String::from("\"quoted\" \\ näme\n.glb"),
                data: Some(Arc::new((0..=255).collect())),
            }],
            beside: true,
        });
        assert_eq!(odd.to_json(), serde_json::to_string(&odd).unwrap());
        let none = Op::Import(ImportInput {
            files: Vec::new(),
            beside: false,
        });
        assert_eq!(none.to_json(), serde_json::to_string(&none).unwrap());
        assert_eq!(serde_json::from_str::<Op>(&json).unwrap(), op);
        assert!(
            serde_json::from_str::<Op>(r#"{"op":"import","files":[{"name":"a","data":"!"}]}"#)
                .is_err()
        );
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

    #[test]
    fn an_oversketch_writes_its_fit_only_when_soft() {
        let json = r#"{"op":"oversketch","viewport":[1,1],"camera":"#.to_owned()
            + &serde_json::to_string(&Camera::default()).unwrap()
            + r#","stroke":[]}"#;
        let op: Op = serde_json::from_str(&json).unwrap();
        let Op::Oversketch(input) = &op else {
            panic!("not an oversketch: {op:?}");
        };
        assert_eq!(input.fit, OversketchFit::Exact);
        assert!(!serde_json::to_string(&op).unwrap().contains("fit"));
        let soft = json.replace(r#""stroke":[]"#, r#""stroke":[],"fit":"soft""#);
        let op: Op = serde_json::from_str(&soft).unwrap();
        assert!(matches!(&op, Op::Oversketch(i) if i.fit == OversketchFit::Soft));
        assert!(
            serde_json::to_string(&op)
                .unwrap()
                .contains(r#""fit":"soft""#)
        );
        let unknown = json.replace(r#""stroke":[]"#, r#""stroke":[],"fit":"loose""#);
        assert!(serde_json::from_str::<Op>(&unknown).is_err());
    }
}

//! A property test of the editor: random sequences of ops on random but meaningful strokes
//! keep every invariant the document promises.
//!
//! Each case starts with a creation or an import, then applies up to [`MAX_OPS`] − 1 more
//! ops drawn from every kind in [`Op::NAMES`]: ink stroke, create, import, pull, add_curve
//! (open, closed, cross-section), cut, tunnel, extrude, transform, delete, duplicate, merge,
//! erase, set_curve_type, rub, over-sketch (automatic or with a picked handle, exact or
//! soft, near-handle or part ROI), optimize (whole or lassoed, shape or smooth), feature,
//! region edit, curve handles (made, edited, linked, deleted), volumetric deform (sphere
//! handles at a model's ends), curve deform, key frames (keyed, deleted, posed at), undo
//! and redo; with the default cases every kind is accepted at least once, or the test
//! fails. A step is stored as parameters (an outline's
//! centre and radius, which model, which curve, where along it, how far to drag...) and is
//! turned into an op against the document of the moment: a pull starts on a visible point
//! of an existing curve's screen projection, an erase follows a visible stretch of one, an
//! over-sketch is the model's silhouette pushed out, a curve is drawn across a model's
//! projection. So most ops are accepted, and proptest can still shrink a failure (fewer
//! steps, smaller numbers).
//!
//! After every op:
//! - every model's mesh validates (`Mesh::validate`) and no position or curve point is NaN
//!   or infinite;
//! - an accepted op moves the document along a model of the undo history (a stack of
//!   digests): undo gives back exactly the previous document, redo exactly the undone one,
//!   and `can_undo`/`can_redo` agree with the model;
//! - a refused op changes nothing: document, undo and redo availability, revision, session.
//!
//! After the sequence: undoing k ops and redoing them gives the same document bit for bit;
//! the session (`session_json` → `replay_json`) replays to the live document bit for bit,
//! with the same undo history (checked by undoing both to the start).
//!
//! A step that needs something first makes it first when the document lacks it, as a
//! user would: a handle edit, link or deletion the handles, a key deletion or a pose a
//! key, a merge a second model moved into the first (see [`parts`]).
//!
//! Sizes: 32 cases of up to 10 steps by default (`PROPTEST_CASES` sets the number of
//! cases; an undo-redo step counts as one of the 10 and applies up to 6 undos and redos).
//! An op costs one solve or remesh of a ~2500-vertex shape (tens of ms at the test
//! profile), a case also replays its session and walks its history, and the whole run
//! takes about 7 to 8 s of CPU here (as before the handle, key frame, optimize, curve
//! deform and ink steps were added): well under the minute allowed, while meeting every op
//! kind (the run prints accepted and refused ops per kind, and fails if fewer than 60% are
//! accepted, since then the generators no longer aim well). 12 cases of 6 ops met some op
//! kinds (erase, open curves) not at all. The seed is fixed, so every run is the same;
//! `PROPTEST_RNG_SEED` picks another. `EDITOR_PROPERTIES_VERBOSE=1` prints each refusal
//! with its step. A case takes up to about a second, so shrinking is capped at 256 steps.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a test failure.

use std::cell::RefCell;
use std::collections::BTreeMap;
use std::sync::{Arc, OnceLock};
use std::time::Instant;

use crate::common::{
    Digest, add_curve, digest, import_document, longest_outline, outline, oversketch,
    pushed_stroke, screen, segment, set_type, stroke_input,
};
use glam::{DMat4, DQuat, DVec2, DVec3};
use proptest::prelude::*;
use proptest::test_runner::{Config, FileFailurePersistence, RngSeed, TestRunner};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{
    CommandError, ControlCurve, CurveDeformInput, CurveHandle, CurveHandleInput, DeformHandleInput,
    DeformInput, DeformMethod, DeleteHandleInput, Document, DuplicateInput, Editor, FillInput,
    HandleEditInput, KeyframeInput, LinkHandlesInput, MaterialInput, MergeInput, Model, ModelInput,
    Op, OptimizeInput, OversketchFit, PaintInput, PlaneInput, RegionEditInput, SketchFeatureInput,
    StrokeInput, StrokePairInput, SymmetrizeInput, TransformInput,
};
use sketchmesh_core::feature::FeatureKind;
use sketchmesh_core::geometry::{Bvh, vertex_normals};
use sketchmesh_core::mesh::primitives;
use sketchmesh_core::model::{MirrorPlane, Side};
use sketchmesh_core::optimize::{Mode, OptimizeParams};
use sketchmesh_core::oversketch::{OutlineKind, OversketchRoi, pick_handle};
use sketchmesh_core::skeleton::HandleKind;
use sketchmesh_core::symmetry::{EXACT, are_twins, diagonal, partners};
use sketchmesh_core::volumetric::Falloff;

/// Ops per case at most (the first is a create or an import).
const MAX_OPS: usize = 10;
/// Cases when `PROPTEST_CASES` is not set.
const DEFAULT_CASES: u32 = 32;
/// The seed when `PROPTEST_RNG_SEED` is not set.
const SEED: u64 = 0x005e_ed0f_ed17;

const VIEWPORT: DVec2 = DVec2::new(800.0, 600.0);

// ---------------------------------------------------------------------------------------
// Steps: the random parameters of an op
// ---------------------------------------------------------------------------------------

/// A camera orbiting the origin: `yaw` about +Y, `pitch` up, at the default distance.
#[derive(Clone, Copy, Debug)]
struct View {
    yaw: f64,
    pitch: f64,
}

impl View {
    fn camera(self) -> Camera {
        let base = Camera::default();
        let distance = base.eye.distance(base.target);
        let direction = DVec3::new(
            self.yaw.sin() * self.pitch.cos(),
            self.pitch.sin(),
            self.yaw.cos() * self.pitch.cos(),
        );
        Camera {
            eye: base.target + distance * direction,
            ..base
        }
    }
}

/// A hand-drawn closed outline: an ellipse with waves and a little noise.
#[derive(Clone, Debug)]
struct Outline {
    centre: DVec2,
    radius: f64,
    squash: f64,
    turn: f64,
    waves: Vec<(usize, f64, f64)>,
    noise: f64,
    view: View,
}

#[derive(Clone, Copy, Debug)]
enum CurveKind {
    Open,
    Closed,
    CrossSection,
}

#[derive(Clone, Copy, Debug)]
enum Manual {
    Automatic,
    Silhouette,
    Surface,
}

/// Which stretch of which curve a curve tool follows: fractions of the visible points.
#[derive(Clone, Copy, Debug)]
struct Along {
    model: usize,
    curve: usize,
    at: f64,
    span: f64,
}

#[derive(Clone, Debug)]
enum Step {
    Create(Outline),
    /// 0: a sphere, 1: a created shape with its outline curve, 2: a capsule; moved by
    /// `offset` (world units).
    Import {
        shape: u8,
        offset: DVec2,
    },
    Pull {
        view: View,
        along: Along,
        drag: DVec2,
    },
    AddCurve {
        view: View,
        model: usize,
        kind: CurveKind,
        angle: f64,
        offset: DVec2,
        extent: f64,
        noise: f64,
    },
    /// A straight cut across a model as seen, `offset` (in radii of its projection) from its
    /// centre across the stroke.
    Cut {
        view: View,
        model: usize,
        angle: f64,
        offset: f64,
    },
    /// Loops of `radius` (a fraction of the model's size on screen) around its middle, seen
    /// from the front and from behind.
    Tunnel {
        model: usize,
        radius: f64,
    },
    /// A base loop of a tenth of the model's size on screen, over half way from its middle
    /// toward `angle`, and a silhouette from it out past the model that way and back.
    Extrude {
        model: usize,
        angle: f64,
    },
    /// 0: a transform (turned `angle` about +Y, scaled by `scale`, moved by `shift`, mirrored
    /// in x when `scale` is negative), 1: a delete, 2: a duplicate of a model, 3: a merge of
    /// it and the next.
    Arrange {
        model: usize,
        kind: u8,
        angle: f64,
        scale: f64,
        shift: DVec2,
    },
    Erase {
        view: View,
        along: Along,
    },
    SetType {
        view: View,
        along: Along,
        sharp: bool,
    },
    Rub {
        view: View,
        along: Along,
        passes: usize,
    },
    Oversketch {
        view: View,
        model: usize,
        direction: f64,
        span: f64,
        push: f64,
        soft: bool,
        part: bool,
        manual: Manual,
    },
    /// A feature sketched across the middle of a model as seen.
    Feature {
        view: View,
        model: usize,
        kind: u8,
        direction: f64,
        span: f64,
        amount: f64,
    },
    /// A region around a reference curve across the middle of a model, lifted and turned.
    Region {
        view: View,
        model: usize,
        direction: f64,
        span: f64,
        boundary: f64,
        lift: f64,
        degrees: f64,
    },
    /// A model's far end turned and lifted by the volumetric deformation, its near end
    /// held (sphere handles at the ends of its bounding box along x).
    Deform {
        model: usize,
        degrees: f64,
        lift: f64,
    },
    /// Every model's pose keyed at a time (0), the keys at a time deleted (1: `time` picks
    /// one of the key times there are), or every animated model posed at a time (2).
    Key {
        time: f64,
        kind: u8,
    },
    /// An ink stroke from `from` to `to`, seen with `view`.
    Ink {
        view: View,
        from: DVec2,
        to: DVec2,
    },
    /// A model's mesh optimized (better triangles, or smoothed), the whole of it or the part
    /// inside a lasso around its middle as seen from the front.
    Optimize {
        model: usize,
        smooth: bool,
        lasso: bool,
    },
    /// A curve handle across the middle of a model as seen (a skeleton one when
    /// `skeleton`), with `control_points`; `twice`: a handle of the other kind along the
    /// same stroke too.
    Handle {
        view: View,
        model: usize,
        angle: f64,
        skeleton: bool,
        control_points: usize,
        twice: bool,
    },
    /// A handle's control point moved up by `amount` of its object's size (0), twisted by
    /// `amount` × 90° (1) or scaled by 1 + `amount` across (2); `handle` and `point` pick
    /// among those there are.
    HandleEdit {
        handle: usize,
        point: usize,
        kind: u8,
        amount: f64,
    },
    /// Two handles' control points linked (handle `handle` and the next one).
    LinkHandles {
        handle: usize,
        point: usize,
        other_point: usize,
    },
    /// A handle deleted.
    DeleteHandle {
        handle: usize,
    },
    /// A control curve across the middle of a model as seen from the front, redrawn bent
    /// by `bend` of its length across itself in the plane facing the view.
    CurveDeform {
        model: usize,
        angle: f64,
        bend: f64,
    },
    /// A curve tool or an over-sketch far from every model: refused.
    Stray {
        kind: u8,
    },
    /// Model `model` made symmetric about the plane through its centre facing `normal`,
    /// keeping the positive side or not.
    Symmetrize {
        model: usize,
        normal: DVec3,
        positive: bool,
    },
    Undo,
    Redo,
    /// `undos` undos then `redos` redos, as a user steps back and forth through history
    /// (a lone redo is only accepted right after an undo).
    UndoRedo {
        undos: usize,
        redos: usize,
    },
}

fn view() -> impl Strategy<Value = View> {
    prop_oneof![
        2 => Just(View { yaw: 0.0, pitch: 0.0 }),
        1 => (-0.6..0.6f64, -0.4..0.4f64).prop_map(|(yaw, pitch)| View { yaw, pitch }),
    ]
}

fn outline_step() -> impl Strategy<Value = Outline> {
    (
        (-150.0..150.0f64, -90.0..90.0f64),
        80.0..170.0f64,
        0.55..1.0f64,
        0.0..std::f64::consts::PI,
        prop::collection::vec((2usize..6, 0.0..0.09f64, 0.0..std::f64::consts::TAU), 0..3),
        0.0..1.5f64,
        view(),
    )
        .prop_map(
            |((x, y), radius, squash, turn, waves, noise, view)| Outline {
                centre: VIEWPORT / 2.0 + DVec2::new(x, y),
                radius,
                squash,
                turn,
                waves,
                noise,
                view,
            },
        )
}

fn along() -> impl Strategy<Value = Along> {
    (0usize..8, 0usize..8, 0.0..1.0f64, 0.1..0.6f64).prop_map(|(model, curve, at, span)| Along {
        model,
        curve,
        at,
        span,
    })
}

fn step() -> impl Strategy<Value = Step> {
    let import = (0u8..3, (-1.2..1.2f64, -0.8..0.8f64)).prop_map(|(shape, (x, y))| Step::Import {
        shape,
        offset: DVec2::new(x, y),
    });
    let pull =
        (view(), along(), (-70.0..70.0f64, -70.0..70.0f64)).prop_map(|(view, along, (x, y))| {
            Step::Pull {
                view,
                along,
                drag: DVec2::new(x, y),
            }
        });
    let kind = prop_oneof![
        Just(CurveKind::Open),
        Just(CurveKind::Closed),
        Just(CurveKind::CrossSection)
    ];
    let add = (
        view(),
        0usize..8,
        kind,
        0.0..std::f64::consts::PI,
        (-0.3..0.3f64, -0.3..0.3f64),
        0.3..0.7f64,
        0.0..1.5f64,
    )
        .prop_map(
            |(view, model, kind, angle, (x, y), extent, noise)| Step::AddCurve {
                view,
                model,
                kind,
                angle,
                offset: DVec2::new(x, y),
                extent,
                noise,
            },
        );
    let cut = (view(), 0usize..8, 0.0..std::f64::consts::PI, -0.5..0.5f64).prop_map(
        |(view, model, angle, offset)| Step::Cut {
            view,
            model,
            angle,
            offset,
        },
    );
    let tunnel =
        (0usize..8, 0.1..0.4f64).prop_map(|(model, radius)| Step::Tunnel { model, radius });
    let extrude =
        (0usize..8, -3.2..3.2f64).prop_map(|(model, angle)| Step::Extrude { model, angle });
    let arrange = (
        0usize..8,
        0u8..4,
        -1.0..1.0f64,
        prop_oneof![4 => 0.5..2.0f64, 1 => -1.5..-0.7f64],
        (-1.0..1.0f64, -1.0..1.0f64),
    )
        .prop_map(|(model, kind, angle, scale, (x, y))| Step::Arrange {
            model,
            kind,
            angle,
            scale,
            shift: DVec2::new(x, y),
        });
    let erase = (view(), along()).prop_map(|(view, along)| Step::Erase { view, along });
    let set_type = (view(), along(), any::<bool>())
        .prop_map(|(view, along, sharp)| Step::SetType { view, along, sharp });
    let rub = (view(), along(), 1usize..4).prop_map(|(view, along, passes)| Step::Rub {
        view,
        along,
        passes,
    });
    let manual = prop_oneof![
        3 => Just(Manual::Automatic),
        1 => Just(Manual::Silhouette),
        1 => Just(Manual::Surface),
    ];
    let oversketch = (
        view(),
        0usize..8,
        0.0..std::f64::consts::TAU,
        0.05..0.2f64,
        -15.0..35.0f64,
        any::<bool>(),
        prop::bool::weighted(0.15),
        manual,
    )
        .prop_map(|(view, model, direction, span, push, soft, part, manual)| {
            Step::Oversketch {
                view,
                model,
                direction,
                span,
                push,
                soft,
                part,
                manual,
            }
        });
    let feature = (
        view(),
        0usize..8,
        0u8..4,
        0.0..std::f64::consts::PI,
        0.1..0.6f64,
        -3.0..6.0f64,
    )
        .prop_map(
            |(view, model, kind, direction, span, amount)| Step::Feature {
                view,
                model,
                kind,
                direction,
                span,
                amount,
            },
        );
    let region = (
        view(),
        0usize..8,
        0.0..std::f64::consts::PI,
        0.1..0.4f64,
        0.5..1.2f64,
        -0.3..0.3f64,
        -60.0..60.0f64,
    )
        .prop_map(
            |(view, model, direction, span, boundary, lift, degrees)| Step::Region {
                view,
                model,
                direction,
                span,
                boundary,
                lift,
                degrees,
            },
        );
    let deform =
        (0usize..8, -60.0..60.0f64, -0.3..0.3f64).prop_map(|(model, degrees, lift)| Step::Deform {
            model,
            degrees,
            lift,
        });
    let ink = (
        view(),
        (60.0..740.0f64, 60.0..540.0f64),
        (60.0..740.0f64, 60.0..540.0f64),
    )
        .prop_map(|(view, (x0, y0), (x1, y1))| Step::Ink {
            view,
            from: DVec2::new(x0, y0),
            to: DVec2::new(x1, y1),
        });
    let optimize = (0usize..8, any::<bool>(), any::<bool>()).prop_map(|(model, smooth, lasso)| {
        Step::Optimize {
            model,
            smooth,
            lasso,
        }
    });
    let handle = (
        view(),
        0usize..8,
        0.0..std::f64::consts::PI,
        any::<bool>(),
        2usize..6,
        any::<bool>(),
    )
        .prop_map(
            |(view, model, angle, skeleton, control_points, twice)| Step::Handle {
                view,
                model,
                angle,
                skeleton,
                control_points,
                twice,
            },
        );
    let handle_edit =
        (0usize..4, 0usize..6, 0u8..3, -0.5..0.5f64).prop_map(|(handle, point, kind, amount)| {
            Step::HandleEdit {
                handle,
                point,
                kind,
                amount,
            }
        });
    let link = (0usize..4, 0usize..6, 0usize..6).prop_map(|(handle, point, other_point)| {
        Step::LinkHandles {
            handle,
            point,
            other_point,
        }
    });
    let curve_deform = (0usize..8, 0.0..std::f64::consts::PI, -0.3..0.3f64)
        .prop_map(|(model, angle, bend)| Step::CurveDeform { model, angle, bend });
    prop_oneof![
        2 => outline_step().prop_map(Step::Create),
        1 => import,
        2 => feature,
        1 => region,
        1 => deform,
        2 => (0.0..3.0f64, prop_oneof![2 => Just(0u8), 1 => Just(1u8), 1 => Just(2u8)])
            .prop_map(|(time, kind)| Step::Key { time, kind }),
        1 => ink,
        1 => optimize,
        2 => handle,
        2 => handle_edit,
        1 => link,
        1 => (0usize..4).prop_map(|handle| Step::DeleteHandle { handle }),
        1 => curve_deform,
        3 => pull,
        3 => add,
        2 => cut,
        4 => arrange,
        1 => tunnel,
        2 => extrude,
        2 => erase,
        2 => set_type,
        2 => rub,
        3 => oversketch,
        1 => (0u8..7).prop_map(|kind| Step::Stray { kind }),
        1 => (0usize..4, -0.3..0.3f64, any::<bool>()).prop_map(|(model, tilt, positive)| {
            Step::Symmetrize {
                model,
                normal: DVec3::new(1.0, tilt, 0.0),
                positive,
            }
        }),
        1 => Just(Step::Undo),
        1 => Just(Step::Redo),
        2 => (1usize..4, 1usize..4).prop_map(|(undos, redos)| Step::UndoRedo { undos, redos }),
    ]
}

fn first_step() -> impl Strategy<Value = Step> {
    prop_oneof![
        4 => outline_step().prop_map(Step::Create),
        1 => (0u8..3).prop_map(|shape| Step::Import { shape, offset: DVec2::ZERO }),
    ]
}

fn steps() -> impl Strategy<Value = Vec<Step>> {
    (first_step(), prop::collection::vec(step(), 0..MAX_OPS)).prop_map(|(first, mut rest)| {
        rest.insert(0, first);
        rest
    })
}

// ---------------------------------------------------------------------------------------
// From steps to ops
// ---------------------------------------------------------------------------------------

/// Deterministic hand tremor of amplitude `amount` px.
fn tremble(points: Vec<DVec2>, amount: f64) -> Vec<DVec2> {
    points
        .into_iter()
        .enumerate()
        .map(|(i, p)| {
            let i = i as f64;
            p + amount * DVec2::new((0.71 * i).sin() * (0.13 * i).cos(), (1.37 * i).cos())
        })
        .collect()
}

fn input(camera: Camera, points: &[DVec2]) -> StrokeInput {
    stroke_input(VIEWPORT, camera, points)
}

/// A stroke far from everything, for steps that find nothing to work on (the op is then
/// refused, which exercises refusals too).
fn nowhere() -> Vec<DVec2> {
    segment(DVec2::new(10.0, 10.0), DVec2::new(60.0, 14.0))
}

/// The model `index` picks (modulo the count).
fn pick_model(document: &Document, index: usize) -> Option<&Arc<Model>> {
    let n = document.models.len();
    (n > 0).then(|| &document.models[index % n])
}

/// Screen points of a curve that the camera sees: as the editor decides it, the point
/// lifted off the surface along its normal by a mean edge length is not occluded by its
/// own model.
fn visible_points(model: &Model, curve: &ControlCurve, camera: &Camera) -> Vec<DVec2> {
    let mesh = &model.mesh;
    let bvh = Bvh::new(mesh);
    let normals = vertex_normals(mesh);
    let lift = mesh.mean_edge_length();
    curve
        .vertices
        .iter()
        .filter_map(|&v| {
            let pixel = screen(camera, VIEWPORT, mesh.position(v))?;
            let raised = mesh.position(v) + lift * normals[v.index()];
            let raised_pixel = screen(camera, VIEWPORT, raised)?;
            let (origin, _) = camera.ray_in_world(raised_pixel, VIEWPORT);
            (!bvh.occluded(mesh, origin, raised, 0.5 * lift)).then_some(pixel)
        })
        .collect()
}

/// The visible stretch of a curve that `along` names, as screen points.
fn stretch(document: &Document, along: Along, camera: &Camera) -> Option<Vec<DVec2>> {
    let curved: Vec<&Arc<Model>> = document
        .models
        .iter()
        .filter(|m| m.curves.iter().any(|c| c.vertices.len() >= 2))
        .collect();
    let model = curved.get(along.model % curved.len().max(1))?;
    let curve = &model.curves[along.curve % model.curves.len()];
    let points = visible_points(model, curve, camera);
    if points.len() < 2 {
        return None;
    }
    let n = points.len();
    let count = ((along.span * n as f64).round() as usize).clamp(2, n);
    let start = ((along.at * (n - count) as f64).round() as usize).min(n - count);
    Some(points[start..start + count].to_vec())
}

/// Screen centre and radius of a model's projection.
fn projection(model: &Model, camera: &Camera) -> Option<(DVec2, f64)> {
    let pixels: Vec<DVec2> = model
        .mesh
        .positions()
        .iter()
        .filter_map(|&p| screen(camera, VIEWPORT, p))
        .collect();
    if pixels.is_empty() {
        return None;
    }
    let min = pixels.iter().copied().fold(DVec2::INFINITY, DVec2::min);
    let max = pixels.iter().copied().fold(DVec2::NEG_INFINITY, DVec2::max);
    Some((0.5 * (min + max), 0.5 * (max - min).min_element()))
}

fn imported_shape(shape: u8, offset: DVec2) -> Op {
    static CREATED: OnceLock<Model> = OnceLock::new();
    let mut model = match shape {
        0 => Model {
            mesh: primitives::icosphere(0.8, 2),
            ..Model::default()
        },
        1 => CREATED
            .get_or_init(|| {
                let mut editor = Editor::new();
                let circle = crate::common::circle(VIEWPORT / 2.0, 110.0);
                editor
                    .apply(Op::Create(input(Camera::default(), &circle).into()))
                    .unwrap();
                Model::clone(&editor.document().models[0])
            })
            .clone(),
        _ => Model {
            mesh: primitives::capsule(0.4, 0.5, 20, 12),
            ..Model::default()
        },
    };
    let shift = offset.extend(0.0);
    for p in model.mesh.positions_mut() {
        *p += shift;
    }
    let document = Document {
        models: vec![Arc::new(model)],
        ..Document::default()
    };
    import_document("shape.glb", &document)
}

/// The op a step stands for in the current document.
fn op_for(step: &Step, document: &Document) -> Op {
    match step {
        Step::Create(o) => {
            let points = outline(o.centre, o.radius, &o.waves, o.squash, o.turn, 120);
            Op::Create(input(o.view.camera(), &tremble(points, o.noise)).into())
        }
        Step::Import { shape, offset } => imported_shape(*shape, *offset),
        Step::Pull { view, along, drag } => {
            let camera = view.camera();
            let points = match stretch(document, *along, &camera) {
                Some(points) => {
                    let start = points[points.len() / 2];
                    tremble(segment(start, start + *drag), 0.3)
                }
                None => nowhere(),
            };
            Op::Pull(input(camera, &points))
        }
        Step::AddCurve {
            view,
            model,
            kind,
            angle,
            offset,
            extent,
            noise,
        } => {
            let camera = view.camera();
            let place = pick_model(document, *model).and_then(|m| projection(m, &camera));
            let Some((centre, radius)) = place else {
                return add_curve(VIEWPORT, camera, &nowhere(), false, false);
            };
            let u = DVec2::from_angle(*angle);
            let middle = centre + radius * *offset;
            let (points, closed, cross) = match kind {
                CurveKind::Open => {
                    let half = extent * radius * u;
                    (segment(middle - half, middle + half), false, false)
                }
                CurveKind::Closed => {
                    let r = 0.5 * extent * radius;
                    (outline(middle, r, &[], 0.7, *angle, 60), true, false)
                }
                CurveKind::CrossSection => {
                    let half = 1.4 * radius * u;
                    (segment(middle - half, middle + half), false, true)
                }
            };
            add_curve(VIEWPORT, camera, &tremble(points, *noise), closed, cross)
        }
        Step::Cut {
            view,
            model,
            angle,
            offset,
        } => {
            let camera = view.camera();
            let place = pick_model(document, *model).and_then(|m| projection(m, &camera));
            let Some((centre, radius)) = place else {
                return Op::Cut(input(camera, &nowhere()));
            };
            let u = DVec2::from_angle(*angle);
            let middle = centre + *offset * radius * u.perp();
            let half = 1.6 * radius * u;
            Op::Cut(input(camera, &segment(middle - half, middle + half)))
        }
        Step::Tunnel { model, radius } => {
            let views = [
                View {
                    yaw: 0.0,
                    pitch: 0.0,
                },
                View {
                    yaw: std::f64::consts::PI,
                    pitch: 0.0,
                },
            ];
            let strokes = views.map(|view| {
                let camera = view.camera();
                let place = pick_model(document, *model).and_then(|m| projection(m, &camera));
                let (centre, size) = place.unwrap_or((nowhere()[0], 10.0));
                let ring: Vec<DVec2> = (0..=48)
                    .map(|i| {
                        let a = std::f64::consts::TAU * f64::from(i) / 48.0;
                        centre + radius * size * DVec2::from_angle(a)
                    })
                    .collect();
                input(camera, &ring)
            });
            Op::Tunnel(StrokePairInput { strokes })
        }
        Step::Extrude { model, angle } => {
            let camera = View {
                yaw: 0.0,
                pitch: 0.0,
            }
            .camera();
            let place = pick_model(document, *model).and_then(|m| projection(m, &camera));
            let (centre, size) = place.unwrap_or((nowhere()[0], 10.0));
            let (u, radius) = (DVec2::from_angle(*angle), 0.1 * size);
            let base = centre + 0.55 * size * u;
            let ring: Vec<DVec2> = (0..=48)
                .map(|i| {
                    base + radius * DVec2::from_angle(std::f64::consts::TAU * f64::from(i) / 48.0)
                })
                .collect();
            let silhouette: Vec<DVec2> = (0..=40)
                .map(|i| {
                    let a = std::f64::consts::PI * (f64::from(i) / 40.0 - 0.5);
                    base + radius * a.sin() * u.perp() + size * a.cos() * u
                })
                .collect();
            Op::Extrude(StrokePairInput {
                strokes: [input(camera, &ring), input(camera, &silhouette)],
            })
        }
        Step::Arrange {
            model,
            kind,
            angle,
            scale,
            shift,
        } => {
            let n = document.models.len().max(1);
            let model = model % n;
            match kind {
                0 => {
                    let mirror = DVec3::new(scale.signum(), 1.0, 1.0);
                    let matrix = DMat4::from_scale_rotation_translation(
                        mirror * scale.abs(),
                        DQuat::from_rotation_y(*angle),
                        shift.extend(0.0),
                    );
                    Op::Transform(TransformInput {
                        model,
                        matrix: matrix.to_cols_array(),
                    })
                }
                1 => Op::Delete(ModelInput { model }),
                2 => Op::Duplicate(DuplicateInput {
                    model,
                    beside: Some([1.0, 0.0, -0.5]),
                }),
                _ => Op::Merge(MergeInput {
                    models: [model, (model + 1) % n],
                }),
            }
        }
        Step::Erase { view, along } => {
            let camera = view.camera();
            let points = stretch(document, *along, &camera).unwrap_or_else(nowhere);
            Op::Erase(input(camera, &points))
        }
        Step::SetType { view, along, sharp } => {
            let camera = view.camera();
            let points = stretch(document, *along, &camera).unwrap_or_else(nowhere);
            set_type(VIEWPORT, camera, &points, *sharp)
        }
        Step::Rub {
            view,
            along,
            passes,
        } => {
            let camera = view.camera();
            let points = match stretch(document, *along, &camera) {
                Some(points) => {
                    let mut rub = Vec::new();
                    for pass in 0..*passes {
                        if pass % 2 == 0 {
                            rub.extend(points.iter().copied());
                        } else {
                            rub.extend(points.iter().rev().copied());
                        }
                    }
                    tremble(rub, 0.5)
                }
                None => nowhere(),
            };
            Op::Rub(input(camera, &points))
        }
        Step::Oversketch {
            view,
            model,
            direction,
            span,
            push,
            soft,
            part,
            manual,
        } => {
            let camera = view.camera();
            let fit = if *soft {
                OversketchFit::Soft
            } else {
                OversketchFit::Exact
            };
            let roi = if *part {
                OversketchRoi::Part
            } else {
                OversketchRoi::NearHandle
            };
            let Some(model) = pick_model(document, *model) else {
                return oversketch(VIEWPORT, camera, &nowhere(), fit, roi, None);
            };
            let mesh = &model.mesh;
            let Some(outline) = longest_outline(mesh, &camera, VIEWPORT) else {
                return oversketch(VIEWPORT, camera, &nowhere(), fit, roi, None);
            };
            let direction = DVec2::from_angle(*direction);
            let half_span = ((span * outline.len() as f64) as usize).max(4);
            let stroke = pushed_stroke(&outline, direction, half_span, *push);
            let handle = match manual {
                Manual::Automatic => None,
                Manual::Silhouette => {
                    let on = pushed_stroke(&outline, direction, half_span, 0.0);
                    pick_handle(mesh, &camera, VIEWPORT, &on, OutlineKind::Smooth)
                }
                Manual::Surface => {
                    let (centre, radius) = projection(model, &camera).unwrap_or_default();
                    let half = 0.4 * radius * direction;
                    let line = segment(centre - half, centre + half);
                    let handle = pick_handle(mesh, &camera, VIEWPORT, &line, OutlineKind::Smooth);
                    let moved: Vec<DVec2> =
                        line.iter().map(|&p| p + direction.perp() * *push).collect();
                    return oversketch(VIEWPORT, camera, &moved, fit, roi, handle);
                }
            };
            oversketch(VIEWPORT, camera, &stroke, fit, roi, handle)
        }
        Step::Feature {
            view,
            model,
            kind,
            direction,
            span,
            amount,
        } => {
            let camera = view.camera();
            let kind = FeatureKind::ALL[usize::from(*kind) % FeatureKind::ALL.len()];
            let (centre, radius) = pick_model(document, *model)
                .and_then(|model| projection(model, &camera))
                .unwrap_or((nowhere()[0], 10.0));
            let half = span * radius * DVec2::from_angle(*direction);
            let stroke = input(camera, &segment(centre - half, centre + half));
            let angle = 30.0 * amount;
            Op::SketchFeature(SketchFeatureInput {
                viewport: stroke.viewport,
                camera,
                stroke: stroke.stroke,
                kind,
                amount: Some(if kind == FeatureKind::Suggestive {
                    angle
                } else {
                    *amount
                }),
                region: None,
            })
        }
        Step::Region {
            view,
            model,
            direction,
            span,
            boundary,
            lift,
            degrees,
        } => {
            let camera = view.camera();
            let (centre, radius) = pick_model(document, *model)
                .and_then(|model| projection(model, &camera))
                .unwrap_or((nowhere()[0], 10.0));
            let half = span * radius * DVec2::from_angle(*direction);
            let reference = input(camera, &segment(centre - half, centre + half));
            let mut ring = crate::common::circle(centre, boundary * radius);
            ring.pop();
            let size = pick_model(document, *model)
                .and_then(|model| model.mesh.bounding_box())
                .map_or(1.0, |(lo, hi)| (hi - lo).length());
            let transform = glam::DMat4::from_translation(glam::DVec3::Y * (lift * size))
                * glam::DMat4::from_rotation_z(degrees.to_radians());
            Op::RegionEdit(RegionEditInput {
                viewport: reference.viewport,
                camera,
                reference: reference.stroke,
                boundary: input(camera, &ring).stroke,
                levels: None,
                areas: Vec::new(),
                transform: Some(transform.to_cols_array()),
                handles: None,
                profile: None,
                remesh: false,
            })
        }
        Step::Deform {
            model,
            degrees,
            lift,
        } => {
            let (lo, hi) = pick_model(document, *model)
                .and_then(|m| m.mesh.bounding_box())
                .unwrap_or((DVec3::ZERO, DVec3::ONE));
            let (centre, size) = ((lo + hi) * 0.5, (hi - lo).length());
            let end = |x: f64| [x, centre.y, centre.z, 0.25 * size];
            let transform = DMat4::from_translation(DVec3::Y * (lift * size))
                * DMat4::from_translation(centre)
                * DMat4::from_rotation_z(degrees.to_radians())
                * DMat4::from_translation(-centre);
            Op::Deform(DeformInput {
                method: DeformMethod::Volumetric,
                model: pick_model(document, *model).map_or(0, |_| model % document.models.len()),
                handles: vec![DeformHandleInput {
                    sphere: end(hi.x),
                    matrix: transform.to_cols_array(),
                }],
                fixed: vec![end(lo.x)],
            })
        }
        Step::Key { time, kind } => key_op(document, *time, *kind),
        Step::Ink { view, from, to } => {
            Op::Stroke(input(view.camera(), &tremble(segment(*from, *to), 0.5)))
        }
        Step::Optimize {
            model,
            smooth,
            lasso,
        } => {
            let camera = Camera::default();
            let region = pick_model(document, *model)
                .and_then(|m| projection(m, &camera))
                .filter(|_| *lasso)
                .map(|(centre, radius)| {
                    let mut ring = crate::common::circle(centre, 0.6 * radius);
                    ring.pop();
                    input(camera, &ring)
                });
            Op::Optimize(OptimizeInput {
                model: pick_model(document, *model).map_or(0, |_| model % document.models.len()),
                settings: OptimizeParams {
                    mode: if *smooth { Mode::Smooth } else { Mode::Shape },
                    ..OptimizeParams::default()
                },
                region,
                painted: Vec::new(),
                painted_features: Vec::new(),
            })
        }
        Step::Handle {
            view,
            model,
            angle,
            skeleton,
            control_points,
            ..
        } => handle_op(document, *view, *model, *angle, *skeleton, *control_points),
        Step::HandleEdit {
            handle,
            point,
            kind,
            amount,
        } => {
            let (id, point, size) = match pick_handle_of(document, *handle) {
                Some(h) => (h.id, point % h.curve.points.len(), handle_size(h)),
                None => (0, *point, 1.0),
            };
            Op::HandleEdit(HandleEditInput {
                handle: id,
                point,
                translate: (*kind == 0).then_some([0.0, amount * size, 0.0]),
                twist_deg: (*kind == 1).then_some(90.0 * amount),
                scale: (*kind == 2).then_some([1.0 + amount, 1.0 + 0.5 * amount]),
                spread: 1,
            })
        }
        Step::LinkHandles {
            handle,
            point,
            other_point,
        } => {
            let ends = pick_handle_of(document, *handle).zip(pick_handle_of(document, handle + 1));
            let (a, b) = match ends {
                Some((a, b)) => (
                    (a.id, point % a.curve.points.len()),
                    (b.id, other_point % b.curve.points.len()),
                ),
                None => ((0, *point), (1, *other_point)),
            };
            Op::LinkHandles(LinkHandlesInput { a, b })
        }
        Step::DeleteHandle { handle } => Op::DeleteHandle(DeleteHandleInput {
            handle: pick_handle_of(document, *handle).map_or(0, |h| h.id),
        }),
        Step::CurveDeform { model, angle, bend } => {
            let camera = Camera::default();
            let (centre, radius) = pick_model(document, *model)
                .and_then(|m| projection(m, &camera))
                .unwrap_or((nowhere()[0], 10.0));
            let along = DVec2::from_angle(*angle);
            let half = 0.6 * radius * along;
            let curve = segment(centre - half, centre + half);
            let n = (curve.len() - 1).max(1) as f64;
            let bent: Vec<DVec2> = (curve.iter().enumerate())
                .map(|(k, &p)| {
                    let u = k as f64 / n;
                    p + along.perp() * (bend * 1.2 * radius * (std::f64::consts::PI * u).sin())
                })
                .collect();
            let facing = (camera.eye - camera.target).normalize();
            Op::CurveDeform(CurveDeformInput {
                model: pick_model(document, *model).map_or(0, |_| model % document.models.len()),
                viewport: VIEWPORT.to_array(),
                camera,
                curve: input(camera, &curve).stroke,
                path: None,
                held: Vec::new(),
                stroke: input(camera, &bent).stroke,
                stroke_camera: None,
                plane: Some(facing.to_array()),
                fixed: None,
                falloff: Falloff::Linear,
                coarse: None,
            })
        }
        Step::Stray { kind } => {
            let (camera, points) = (Camera::default(), nowhere());
            match kind {
                0 => Op::Pull(input(camera, &points)),
                1 => add_curve(VIEWPORT, camera, &points, false, false),
                2 => Op::Erase(input(camera, &points)),
                3 => set_type(VIEWPORT, camera, &points, true),
                4 => Op::Rub(input(camera, &points)),
                5 => Op::Cut(input(camera, &points)),
                _ => oversketch(
                    VIEWPORT,
                    camera,
                    &points,
                    OversketchFit::Exact,
                    OversketchRoi::NearHandle,
                    None,
                ),
            }
        }
        Step::Symmetrize {
            model,
            normal,
            positive,
        } => {
            let n = document.models.len().max(1);
            let (lo, hi) = pick_model(document, *model)
                .and_then(|m| m.mesh.bounding_box())
                .unwrap_or_default();
            Op::Symmetrize(SymmetrizeInput {
                model: model % n,
                plane: MirrorPlane::through(0.5 * (lo + hi), *normal).unwrap(),
                keep: if *positive {
                    Side::Positive
                } else {
                    Side::Negative
                },
            })
        }
        Step::Undo | Step::UndoRedo { .. } => Op::Undo,
        Step::Redo => Op::Redo,
    }
}

/// A curve handle across the middle of model `model` as seen from `view`, at `angle`.
fn handle_op(
    document: &Document,
    view: View,
    model: usize,
    angle: f64,
    skeleton: bool,
    control_points: usize,
) -> Op {
    let camera = view.camera();
    let points = match pick_model(document, model).and_then(|m| projection(m, &camera)) {
        Some((centre, radius)) => {
            let half = 0.5 * radius * DVec2::from_angle(angle);
            segment(centre - half, centre + half)
        }
        None => nowhere(),
    };
    let stroke = input(camera, &points);
    Op::CurveHandle(CurveHandleInput {
        viewport: stroke.viewport,
        camera,
        stroke: stroke.stroke,
        kind: if skeleton {
            HandleKind::Skeleton
        } else {
            HandleKind::Surface
        },
        control_points,
        rigid: false,
    })
}

/// The handle `index` picks among the document's (modulo the count).
fn pick_handle_of(document: &Document, index: usize) -> Option<&CurveHandle> {
    let n = document.handles.len();
    (n > 0).then(|| &*document.handles[index % n])
}

/// The extent of a handle's control points, a size to move them by.
fn handle_size(handle: &CurveHandle) -> f64 {
    let points = &handle.curve.points;
    let lo = points.iter().copied().fold(DVec3::INFINITY, DVec3::min);
    let hi = points.iter().copied().fold(DVec3::NEG_INFINITY, DVec3::max);
    (hi - lo).length().max(0.1)
}

/// A key frame op: a key at `time` (kind 0), the deletion of one of the key times there are
/// (1; `time` when there is none, which is refused) or a pose at `time` (2).
fn key_op(document: &Document, time: f64, kind: u8) -> Op {
    let input = KeyframeInput { time };
    match kind {
        0 => Op::Keyframe(input),
        1 => {
            let times: Vec<f64> = (document.models.iter())
                .flat_map(|m| m.keyframes.iter().map(|k| k.time))
                .collect();
            let time = match times.len() {
                0 => time,
                n => times[(time * 1000.0) as usize % n],
            };
            Op::DeleteKeyframe(KeyframeInput { time })
        }
        _ => Op::PoseAt(input),
    }
}

/// The colour op [`Part::ColourOf`] puts before `op`.
fn colour_op(op: &Op) -> Option<Op> {
    let tint = |k: usize| [0.9, 0.2 + 0.1 * (k % 7) as f64, 0.4];
    Some(match op.unmirrored() {
        Op::Pull(input) => Op::Paint(PaintInput {
            viewport: input.viewport,
            camera: input.camera,
            stroke: input.stroke.clone(),
            color: tint(input.stroke.len()),
            radius: 12.0,
            hardness: 0.5,
            opacity: 0.8,
        }),
        Op::Symmetrize(input) => Op::Fill(FillInput {
            model: input.model,
            color: tint(input.model),
        }),
        Op::Transform(input) => Op::Material(MaterialInput {
            model: input.model,
            base_color: [0.8, 0.7, 0.6, 1.0],
            roughness: 0.3,
            metalness: 0.5,
        }),
        _ => return None,
    })
}

/// A part of a step, turned into an op against the document of the moment.
#[derive(Clone, Debug)]
enum Part {
    /// The op of a step.
    Step(Step),
    /// A curve handle across the first model's middle, seen from the front, unless there
    /// are already this many handles.
    HandlesFirst(usize),
    /// Every model's pose keyed at this time, unless a model has a key frame already.
    KeyFirst(f64),
    /// A copy of the only model, when there is one.
    SecondModelFirst,
    /// The model after the one this picks moved to overlap it by most of its size.
    OverlapFirst(usize),
    /// The symmetry plane moved to the one this symmetrize step uses, as a user moves it
    /// with Arrange's handles before symmetrizing about it.
    PlaneOf(Step),
    /// Colour first, so that the ops after meet painted models (without new random draws,
    /// which would change every other case): a pull's stroke painted before it, a
    /// symmetrize's model filled, an arranged model given a material.
    ColourOf(Step),
}

/// The parts of a step: its op; or the undos and redos of [`Step::UndoRedo`]; or a handle
/// of each kind along one stroke for [`Step::Handle`] `twice`; and before a handle edit,
/// link or deletion the handles it needs, before a key deletion or a pose the key it needs,
/// before a merge a second model moved into the first, made first when the document lacks
/// them (as a user would).
fn parts(step: &Step) -> Vec<Part> {
    match step {
        Step::UndoRedo { undos, redos } => {
            let mut parts = vec![Part::Step(Step::Undo); *undos];
            parts.extend(vec![Part::Step(Step::Redo); *redos]);
            parts
        }
        Step::Handle {
            skeleton,
            twice: true,
            ..
        } => {
            let mut other = step.clone();
            if let Step::Handle { skeleton: kind, .. } = &mut other {
                *kind = !skeleton;
            }
            vec![Part::Step(step.clone()), Part::Step(other)]
        }
        Step::HandleEdit { .. } | Step::DeleteHandle { .. } => {
            vec![Part::HandlesFirst(1), Part::Step(step.clone())]
        }
        Step::LinkHandles { .. } => vec![
            Part::HandlesFirst(1),
            Part::HandlesFirst(2),
            Part::Step(step.clone()),
        ],
        Step::Key { time, kind: 1 | 2 } => vec![Part::KeyFirst(*time), Part::Step(step.clone())],
        Step::Arrange { model, kind: 3, .. } => vec![
            Part::SecondModelFirst,
            Part::OverlapFirst(*model),
            Part::Step(step.clone()),
        ],
        Step::Symmetrize { .. } => vec![
            Part::ColourOf(step.clone()),
            Part::PlaneOf(step.clone()),
            Part::Step(step.clone()),
        ],
        Step::Pull { .. } | Step::Arrange { .. } => {
            vec![Part::ColourOf(step.clone()), Part::Step(step.clone())]
        }
        step => vec![Part::Step(step.clone())],
    }
}

/// The op a part stands for in the current document; `None` when what it would make
/// first is there already.
fn op_for_part(part: &Part, document: &Document) -> Option<Op> {
    match part {
        Part::Step(step) => Some(op_for(step, document)),
        Part::PlaneOf(step) => match op_for(step, document) {
            Op::Symmetrize(input) => Some(Op::SymmetryPlane(PlaneInput { plane: input.plane })),
            _ => None,
        },
        Part::ColourOf(step) => colour_op(&op_for(step, document)),
        Part::HandlesFirst(count) => (document.handles.len() < *count).then(|| {
            let front = View {
                yaw: 0.0,
                pitch: 0.0,
            };
            let skeleton = document.handles.len() % 2 == 1;
            handle_op(document, front, 0, 0.0, skeleton, 4)
        }),
        Part::KeyFirst(time) => (document.models.iter())
            .all(|m| m.keyframes.is_empty())
            .then_some(Op::Keyframe(KeyframeInput { time: *time })),
        Part::SecondModelFirst => {
            (document.models.len() == 1).then_some(Op::Duplicate(DuplicateInput {
                model: 0,
                beside: None,
            }))
        }
        Part::OverlapFirst(model) => {
            let n = document.models.len();
            if n < 2 {
                return None;
            }
            let (i, j) = (model % n, (model + 1) % n);
            let bounds = |k: usize| document.models[k].mesh.bounding_box();
            let ((lo, hi), (other_lo, other_hi)) = bounds(i).zip(bounds(j))?;
            let target = 0.5 * (lo + hi) + DVec3::X * (0.3 * (hi - lo).x);
            let shift = target - 0.5 * (other_lo + other_hi);
            Some(Op::Transform(TransformInput {
                model: j,
                matrix: DMat4::from_translation(shift).to_cols_array(),
            }))
        }
    }
}

// ---------------------------------------------------------------------------------------
// The properties
// ---------------------------------------------------------------------------------------

/// Accepted and refused ops by kind, over the whole run.
#[derive(Default)]
struct Tally {
    by_kind: BTreeMap<String, (usize, usize)>,
    /// Accepted ops by name.
    accepted: BTreeMap<&'static str, usize>,
    /// Refusals by op and message.
    reasons: BTreeMap<String, usize>,
}

impl Tally {
    fn refused(&mut self, op: &Op, error: &CommandError) {
        *self
            .reasons
            .entry(format!("{}: {error}", op.name()))
            .or_default() += 1;
    }

    fn count(&mut self, op: &Op, accepted: bool) {
        let key = match op.unmirrored() {
            Op::AddCurve(input) if input.closed => "add_curve closed".to_owned(),
            Op::AddCurve(input) if input.cross_section => "add_curve cross-section".to_owned(),
            Op::Oversketch(input) => format!(
                "oversketch{}{}{}",
                if input.handle.is_some() {
                    " manual"
                } else {
                    ""
                },
                if input.fit == OversketchFit::Soft {
                    " soft"
                } else {
                    ""
                },
                if input.roi == OversketchRoi::Part {
                    " part"
                } else {
                    ""
                },
            ),
            op => op.name().to_owned(),
        };
        let entry = self.by_kind.entry(key).or_default();
        if accepted {
            *self.accepted.entry(op.name()).or_default() += 1;
            entry.0 += 1;
        } else {
            entry.1 += 1;
        }
    }
}

/// After an op made with symmetry on: every model it made or changed is symmetric about
/// x = 0 or has a mirror twin, to [`EXACT`] of its diagonal. (A transform moves a symmetric
/// model as the user asks, off the plane or not: its own test checks it.)
fn check_symmetric(op: &Op, before: &Document, after: &Document) -> Result<(), TestCaseError> {
    let plane = MirrorPlane::default();
    if matches!(op.unmirrored(), Op::Transform(_)) {
        return Ok(());
    }
    for (k, model) in after.models.iter().enumerate() {
        let unchanged = before.models.iter().any(|m| Arc::ptr_eq(m, model));
        let twin = (after.models.iter().enumerate())
            .any(|(j, other)| j != k && are_twins(&model.mesh, &other.mesh, &plane));
        let paired = twin || partners(&model.mesh, &plane).is_some();
        prop_assert!(
            unchanged || paired,
            "model {} is neither symmetric about x = 0 nor a twin (diagonal {}, tolerance {})",
            k,
            diagonal(&model.mesh),
            EXACT
        );
    }
    Ok(())
}

fn check_document(document: &Document) -> Result<(), TestCaseError> {
    for (k, model) in document.models.iter().enumerate() {
        model
            .mesh
            .validate()
            .map_err(|error| TestCaseError::fail(format!("model {k} invalid: {error:?}")))?;
        prop_assert!(
            model.mesh.positions().iter().all(|p| p.is_finite()),
            "model {} has a non-finite position",
            k
        );
        prop_assert!(
            model
                .curves
                .iter()
                .all(|c| c.points(&model.mesh).iter().all(|p| p.is_finite())),
            "model {} has a non-finite curve point",
            k
        );
        for curve in &model.curves {
            let n = curve.vertices.len();
            let closing = usize::from(curve.is_closed && n > 2);
            let joined = (0..n - 1 + closing).all(|i| {
                let (a, b) = (curve.vertices[i], curve.vertices[(i + 1) % n]);
                model.mesh.find_edge(a, b).is_some()
            });
            prop_assert!(joined, "model {} has a curve that is not an edge chain", k);
        }
    }
    Ok(())
}

/// What a refused op must leave as it was.
#[derive(Debug, PartialEq)]
struct Observable {
    digest: Digest,
    can_undo: bool,
    can_redo: bool,
    revision: u64,
    session: String,
}

fn observe(editor: &Editor) -> Observable {
    Observable {
        digest: digest(editor.document()),
        can_undo: editor.can_undo(),
        can_redo: editor.can_redo(),
        revision: editor.revision(),
        session: editor.session_json(),
    }
}

fn run_case(
    steps: &[Step],
    undo_k: usize,
    symmetric: bool,
    tally: &RefCell<Tally>,
) -> Result<(), TestCaseError> {
    let mut editor = Editor::new();
    // The undo history as digests.
    let (mut undo, mut redo): (Vec<Digest>, Vec<Digest>) = (Vec::new(), Vec::new());
    let mut next_index = 0;
    for step in steps {
        for part in parts(step) {
            let Some(op) = op_for_part(&part, editor.document()) else {
                continue;
            };
            // A symmetric case makes every op with symmetry on about x = 0.
            let op = match symmetric {
                true => op.mirrored(MirrorPlane::default()),
                false => op,
            };
            let before_doc = editor.document().clone();
            let index = next_index;
            next_index += 1;
            let name = op.name();
            let before = observe(&editor);
            let result = editor.apply(op.clone());
            tally.borrow_mut().count(&op, result.is_ok());
            match result {
                Ok(()) => {
                    let now = digest(editor.document());
                    match op {
                        Op::Undo => {
                            let expected = undo.pop();
                            prop_assert_eq!(Some(now), expected, "op {}: undo", index);
                            redo.push(before.digest);
                        }
                        Op::Redo => {
                            let expected = redo.pop();
                            prop_assert_eq!(Some(now), expected, "op {}: redo", index);
                            undo.push(before.digest);
                        }
                        _ => {
                            undo.push(before.digest);
                            redo.clear();
                        }
                    }
                    check_document(editor.document()).map_err(|e| {
                        TestCaseError::fail(format!("after op {index} ({name}): {e}"))
                    })?;
                    if matches!(op, Op::Mirrored(_)) {
                        check_symmetric(&op, &before_doc, editor.document()).map_err(|e| {
                            TestCaseError::fail(format!("after op {index} ({name}): {e}"))
                        })?;
                    }
                }
                Err(error) => {
                    tally.borrow_mut().refused(&op, &error);
                    if std::env::var_os("EDITOR_PROPERTIES_VERBOSE").is_some() {
                        eprintln!("op {index} refused ({error}): {step:?}");
                    }
                    let after = observe(&editor);
                    prop_assert!(
                        after == before,
                        "op {} ({}) was refused ({}) but changed the editor",
                        index,
                        name,
                        error
                    );
                    match op {
                        Op::Undo => prop_assert!(undo.is_empty(), "undo refused with history"),
                        Op::Redo => prop_assert!(redo.is_empty(), "redo refused with history"),
                        _ => {}
                    }
                }
            }
            prop_assert_eq!(
                editor.can_undo(),
                !undo.is_empty(),
                "op {}: can_undo",
                index
            );
            prop_assert_eq!(
                editor.can_redo(),
                !redo.is_empty(),
                "op {}: can_redo",
                index
            );
        }
    }

    // Undo k, redo k: the same document.
    let last = digest(editor.document());
    let k = undo_k % (undo.len() + 1);
    let mut walk = editor.clone();
    for j in 0..k {
        walk.undo().unwrap();
        prop_assert_eq!(digest(walk.document()), undo[undo.len() - 1 - j]);
    }
    for _ in 0..k {
        walk.redo().unwrap();
    }
    prop_assert_eq!(digest(walk.document()), last, "undo {} then redo {}", k, k);

    // The session replays to the same document and history.
    let json = editor.session_json();
    let mut replayed = Editor::replay_json(&json)
        .map_err(|error| TestCaseError::fail(format!("the session does not replay: {error}")))?;
    prop_assert_eq!(digest(replayed.document()), last, "replay");
    prop_assert_eq!(replayed.session_json(), json);
    prop_assert_eq!(replayed.can_redo(), editor.can_redo());
    let mut live = editor;
    while live.can_undo() {
        live.undo().unwrap();
        replayed.undo().unwrap();
        prop_assert_eq!(digest(replayed.document()), digest(live.document()));
    }
    prop_assert!(!replayed.can_undo());
    Ok(())
}

fn config() -> Config {
    let from_env = Config::default(); // reads PROPTEST_CASES and PROPTEST_RNG_SEED
    Config {
        cases: std::env::var("PROPTEST_CASES")
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(DEFAULT_CASES),
        rng_seed: match std::env::var("PROPTEST_RNG_SEED") {
            Ok(_) => from_env.rng_seed,
            Err(_) => RngSeed::Fixed(SEED),
        },
        source_file: Some(file!()),
        // Next to this file, as `fibermesh.rs`'s.
        failure_persistence: Some(Box::new(FileFailurePersistence::WithSource(
            "proptest-regressions",
        ))),
        // A case takes up to a second: shrink for a few minutes at most.
        max_shrink_iters: 256,
        ..from_env
    }
}

#[test]
fn random_op_sequences_keep_the_editor_consistent() {
    let tally = RefCell::new(Tally::default());
    let start = Instant::now();
    let mut runner = TestRunner::new(config());
    let cases = runner.config().cases;
    let cases_strategy = (steps(), any::<usize>(), prop::bool::weighted(0.3));
    let result = runner.run(&cases_strategy, |(steps, undo_k, symmetric)| {
        run_case(&steps, undo_k, symmetric, &tally)
    });
    let tally = tally.into_inner();
    let (mut accepted, mut refused) = (0, 0);
    for (kind, (ok, no)) in &tally.by_kind {
        eprintln!("{kind:>28}: {ok} accepted, {no} refused");
        accepted += ok;
        refused += no;
    }
    for (reason, count) in &tally.reasons {
        eprintln!("{count:>4} × {reason}");
    }
    let share = accepted as f64 / (accepted + refused).max(1) as f64;
    eprintln!(
        "{cases} cases, {} ops, {:.0}% accepted, {:.1} s",
        accepted + refused,
        100.0 * share,
        start.elapsed().as_secs_f64()
    );
    if let Err(error) = result {
        panic!("{error}");
    }
    // The default run draws every kind of op, and each is accepted at least once (another
    // seed or fewer cases may miss a rare one).
    let never: Vec<&str> = (Op::NAMES.iter().copied())
        .filter(|name| !tally.accepted.contains_key(name))
        .collect();
    if cases >= DEFAULT_CASES && std::env::var_os("PROPTEST_RNG_SEED").is_none() {
        assert!(never.is_empty(), "ops never accepted: {never:?}");
    }
    if accepted + refused >= 40 {
        assert!(
            share >= 0.6,
            "only {:.0}% of the ops were accepted: the stroke generators no longer fit",
            100.0 * share
        );
    }
}

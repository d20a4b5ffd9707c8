//! The whole over-sketch on generated meshes: a stroke drawn beside part of the outline
//! pulls that part onto it, the rest of the mesh stays, details survive better than under a
//! naive falloff, and the document op replays and undoes exactly.

#![allow(clippy::unwrap_used)] // A panic is a test failure with a location.

use std::f64::consts::{PI, TAU};
use std::sync::Arc;

use glam::{DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::polyline::{
    cumulative_lengths, distance_to_polyline, length, resample,
};
use sketchmesh_core::deform::HandleFit;
use sketchmesh_core::document::{
    CommandError, Document, Editor, FileInput, ImportInput, Model, Op, OversketchFit,
    OversketchInput, StrokeInput,
};
use sketchmesh_core::geometry::{Bvh, cotan_laplacian};
use sketchmesh_core::io::write_glb;
use sketchmesh_core::mesh::{Mesh, primitives};
use sketchmesh_core::oversketch::{
    BendOptions, ManualHandle, OutlineKind, OversketchError, OversketchRoi, Oversketched,
    SOFT_FIT_WEIGHT, manual_handle_preview, oversketch, oversketch_manual, oversketch_with,
    pick_handle, preview_handle,
};
use sketchmesh_core::silhouette::{edge_silhouettes, silhouettes};

const VIEWPORT: DVec2 = DVec2::new(1000.0, 1000.0);

/// `fit` with the region near the handle.
fn near(fit: HandleFit) -> BendOptions {
    BendOptions {
        fit,
        roi: OversketchRoi::NearHandle,
    }
}

/// Screen polylines of the visible silhouettes (closed ones repeat their first point).
fn outlines(mesh: &Mesh, camera: &Camera) -> Vec<Vec<DVec2>> {
    let bvh = Bvh::new(mesh);
    silhouettes(mesh, &bvh, camera, VIEWPORT)
        .iter()
        .map(|s| {
            let mut points: Vec<DVec2> = s.points.iter().map(|p| p.screen).collect();
            if s.closed {
                points.push(points[0]);
            }
            points
        })
        .collect()
}

/// The longest silhouette (the outer outline), closed, without the repeated point.
fn longest_outline(mesh: &Mesh, camera: &Camera) -> Vec<DVec2> {
    let mut all = outlines(mesh, camera);
    all.sort_by(|a, b| length(b).total_cmp(&length(a)));
    let mut outline = all.swap_remove(0);
    assert_eq!(
        outline.first(),
        outline.last(),
        "the outline should be closed"
    );
    outline.pop();
    outline
}

/// A stroke over the part of `outline` around its extreme point in `direction`, `half_span`
/// points either side, pushed outward by `push · sin(π u)` px (0 at the ends), smoothed and
/// resampled every 1 px.
fn pushed_stroke(outline: &[DVec2], direction: DVec2, half_span: usize, push: f64) -> Vec<DVec2> {
    let n = outline.len();
    let centroid = outline.iter().sum::<DVec2>() / n as f64;
    let extreme = (0..n)
        .max_by(|&a, &b| {
            outline[a]
                .dot(direction)
                .total_cmp(&outline[b].dot(direction))
        })
        .unwrap();
    let count = 2 * half_span + 1;
    let piece: Vec<DVec2> = (0..count)
        .map(|k| outline[(extreme + n + k - half_span) % n])
        .collect();
    let pushed: Vec<DVec2> = (0..count)
        .map(|k| {
            let before = piece[k.saturating_sub(1)];
            let after = piece[(k + 1).min(count - 1)];
            let mut normal = (after - before).perp().normalize();
            if normal.dot(piece[k] - centroid) < 0.0 {
                normal = -normal;
            }
            let u = k as f64 / (count - 1) as f64;
            piece[k] + normal * push * (PI * u).sin()
        })
        .collect();
    resample(&smooth(&pushed, 4), 1.0)
}

/// Moving average over `half_window` points either side (fewer near the ends, so the ends
/// stay): offsets of a wavy outline fold where the waves are tighter than the push, and
/// nobody draws those folds.
fn smooth(points: &[DVec2], half_window: usize) -> Vec<DVec2> {
    let n = points.len();
    (0..n)
        .map(|i| {
            let w = half_window.min(i).min(n - 1 - i);
            points[i - w..=i + w].iter().sum::<DVec2>() / (2 * w + 1) as f64
        })
        .collect()
}

/// The largest distance from a stroke point in the middle 80% (by arclength) to the outline
/// of `positions` as rendered: its visible edge silhouettes.
fn worst_middle_distance(
    mesh: &Mesh,
    positions: &[DVec3],
    camera: &Camera,
    stroke: &[DVec2],
) -> f64 {
    let mut moved = mesh.clone();
    moved.positions_mut().copy_from_slice(positions);
    let segments = edge_silhouettes(&moved, &Bvh::new(&moved), camera, VIEWPORT);
    let cumulative = cumulative_lengths(stroke);
    let total = length(stroke);
    let mut worst: f64 = 0.0;
    for (&p, s) in stroke.iter().zip(cumulative) {
        if (0.1 * total..=0.9 * total).contains(&s) {
            let d = segments
                .iter()
                .map(|segment| distance_to_polyline(p, segment))
                .fold(f64::INFINITY, f64::min);
            worst = worst.max(d);
        }
    }
    worst
}

/// Vertices outside the ROI keep their positions bit for bit: at most `roi_size` move, and
/// the ROI is a small part of the mesh.
fn assert_outside_unmoved(mesh: &Mesh, result: &Oversketched) {
    let moved = mesh
        .positions()
        .iter()
        .zip(&result.positions)
        .filter(|(a, b)| a.to_array().map(f64::to_bits) != b.to_array().map(f64::to_bits))
        .count();
    assert!(
        moved > 0 && moved <= result.roi_size,
        "{moved} moved, ROI {}",
        result.roi_size
    );
    assert!(
        result.roi_size < mesh.n_vertices() / 2,
        "ROI {}",
        result.roi_size
    );
}

fn run_case(name: &str, mesh: &Mesh, direction: DVec2, half_span: usize, push: f64) -> f64 {
    let camera = Camera::default();
    let outline = longest_outline(mesh, &camera);
    let stroke = pushed_stroke(&outline, direction, half_span, push);
    let (preview, is_confident) = preview_handle(mesh, &camera, VIEWPORT, &stroke).unwrap();
    assert!(is_confident && preview.len() > 10, "{name}");
    let result = oversketch(mesh, &camera, VIEWPORT, &stroke).unwrap();
    assert_eq!(result.handle, preview);
    assert_outside_unmoved(mesh, &result);
    // The handle's middle is where the stroke's middle was drawn beside.
    let handle_mid = result.handle[result.handle.len() / 2];
    let before = distance_to_polyline(handle_mid, &outline);
    assert!(before < 1.0, "{name}: handle off the outline by {before}");
    let worst = worst_middle_distance(mesh, &result.positions, &camera, &stroke);
    eprintln!(
        "{name}: stroke {:.0} px pushed {push} px, ROI {} vertices, worst distance {worst:.3} px",
        length(&stroke),
        result.roi_size
    );
    worst
}

#[test]
fn sphere_outline_moves_onto_the_stroke() {
    let mesh = primitives::icosphere(1.0, 5);
    let worst = run_case("sphere", &mesh, DVec2::X, 60, 40.0);
    assert!(worst < 2.0, "worst {worst}");
}

/// An ellipsoid: the icosphere scaled by `scale`.
fn ellipsoid(scale: DVec3, subdivisions: u32) -> Mesh {
    let mut mesh = primitives::icosphere(1.0, subdivisions);
    for p in mesh.positions_mut() {
        *p *= scale;
    }
    mesh
}

#[test]
fn ellipsoid_top_moves_onto_the_stroke() {
    let mesh = ellipsoid(DVec3::new(1.6, 0.8, 0.8), 5);
    let worst = run_case("ellipsoid", &mesh, DVec2::NEG_Y, 80, 50.0);
    assert!(worst < 2.0, "worst {worst}");
}

#[test]
fn capsule_side_and_end_move_onto_the_stroke() {
    let mesh = primitives::capsule(0.5, 1.0, 96, 160);
    // Over the straight side, and round the cap.
    let side = run_case("capsule side", &mesh, DVec2::NEG_Y, 60, 30.0);
    assert!(side < 2.0, "side: worst {side}");
    let end = run_case("capsule end", &mesh, DVec2::X, 60, 30.0);
    assert!(end < 2.0, "end: worst {end}");
}

/// The largest displacement in `positions` of a vertex of `mesh` farther than `angle` from
/// the x axis.
fn largest_move_beyond(mesh: &Mesh, positions: &[DVec3], angle: f64) -> f64 {
    mesh.positions()
        .iter()
        .zip(positions)
        .filter(|(a, _)| a.angle_between(DVec3::X) > angle)
        .map(|(a, b)| a.distance(*b))
        .fold(0.0, f64::max)
}

#[test]
fn a_part_roi_bends_the_horn_and_leaves_the_body() {
    let mesh = primitives::horned_sphere(5, 1.2, 0.22);
    let camera = Camera::default();
    // The horn's tip pulled far out: spheres as large as that reach into the body.
    let stroke = pushed_stroke(&longest_outline(&mesh, &camera), DVec2::X, 40, 80.0);
    let part = BendOptions {
        fit: HandleFit::Exact,
        roi: OversketchRoi::Part,
    };
    let by_part = oversketch_with(&mesh, &camera, VIEWPORT, &stroke, part).unwrap();
    let near = oversketch_with(&mesh, &camera, VIEWPORT, &stroke, BendOptions::EXACT).unwrap();
    let worst_part = worst_middle_distance(&mesh, &by_part.positions, &camera, &stroke);
    let worst_near = worst_middle_distance(&mesh, &near.positions, &camera, &stroke);
    // The body: more than 0.8 rad from the axis, where the horn's profile is down to 2e-6.
    let body_part = largest_move_beyond(&mesh, &by_part.positions, 0.8);
    let body_near = largest_move_beyond(&mesh, &near.positions, 0.8);
    eprintln!(
        "horn: part ROI {} vertices, body moves up to {body_part:.4}, worst {worst_part:.2} px; \
         near-handle ROI {}, body moves up to {body_near:.4}, worst {worst_near:.2} px",
        by_part.roi_size, near.roi_size
    );
    assert_outside_unmoved(&mesh, &by_part);
    // Measured 0.0051 against 0.0267 (the part's border lies a little past 0.8 rad).
    assert!(body_part < 0.3 * body_near, "{body_part} vs {body_near}");
    // Measured 5.12 against 8.03 px (7.98 against 9.63 before the outline was snapped): a
    // tip pulled this far does not land within 2 px with either region (the horn's stretched
    // triangles), but the part does no worse.
    assert!(
        worst_part < worst_near + 0.5,
        "{worst_part} vs {worst_near}"
    );
    // The whole horn may bend: the part reaches its base.
    let horn = mesh
        .positions()
        .iter()
        .filter(|p| p.angle_between(DVec3::X) < 0.4)
        .count();
    assert!(by_part.roi_size >= horn, "{} < {horn}", by_part.roi_size);

    // Through the editor: the op carries its region, and the session replays it.
    let mut editor = Editor::new();
    editor.apply(import_op(&mesh)).unwrap();
    // glTF stores f32 positions: the imported mesh is the one to compare against.
    let imported = editor.document().models[0].mesh.clone();
    let expected = oversketch_with(&imported, &camera, VIEWPORT, &stroke, part).unwrap();
    editor.apply(part_op(&stroke)).unwrap();
    let edited = editor.document().clone();
    assert!(edited.models[0].mesh.positions() == &expected.positions[..]);
    let json = editor.session_json();
    assert!(
        json.contains(r#""roi":"part""#),
        "{}",
        &json[json.len() - 200..]
    );
    assert_eq!(*Editor::replay_json(&json).unwrap().document(), edited);
}

/// [`oversketch_op`] with the part ROI.
fn part_op(stroke: &[DVec2]) -> Op {
    let Op::Oversketch(input) = oversketch_op(stroke) else {
        unreachable!("oversketch_op makes an oversketch")
    };
    Op::Oversketch(OversketchInput {
        roi: OversketchRoi::Part,
        ..input
    })
}

#[test]
fn a_part_roi_on_a_sphere_is_refused_and_changes_nothing() {
    let mesh = primitives::icosphere(1.0, 4);
    let camera = Camera::default();
    let stroke = pushed_stroke(&longest_outline(&mesh, &camera), DVec2::X, 40, 30.0);
    let part = BendOptions {
        fit: HandleFit::Exact,
        roi: OversketchRoi::Part,
    };
    assert_eq!(
        oversketch_with(&mesh, &camera, VIEWPORT, &stroke, part).unwrap_err(),
        OversketchError::NoPart
    );
    let mut editor = Editor::new();
    editor.apply(import_op(&mesh)).unwrap();
    let before = editor.document().clone();
    let error = editor.apply(part_op(&stroke)).unwrap_err();
    assert!(error.to_string().contains("No part"), "{error}");
    assert_eq!(*editor.document(), before);
    editor.undo().unwrap();
    assert!(
        editor.document().models.is_empty(),
        "undo still undoes the import"
    );
}

#[test]
fn bumpy_torus_keeps_its_bumps_better_than_a_naive_falloff() {
    let mesh = primitives::bumpy_torus(0.03, 192, 64);
    let camera = Camera::default();
    let worst = run_case("bumpy torus", &mesh, DVec2::X, 50, 40.0);
    // Measured 1.83 px (rendered outline); the bumps make it the hardest of the three.
    assert!(worst < 2.0, "worst {worst}");

    let outline = longest_outline(&mesh, &camera);
    let stroke = pushed_stroke(&outline, DVec2::X, 50, 40.0);
    let result = oversketch(&mesh, &camera, VIEWPORT, &stroke).unwrap();
    let rest = mesh.positions();
    let moved: Vec<usize> = (0..rest.len())
        .filter(|&v| rest[v] != result.positions[v])
        .collect();
    // Handle displacements, approximated by the moved vertices' largest motion near each.
    let handle_like: Vec<(usize, DVec3)> = moved
        .iter()
        .map(|&v| (v, result.positions[v] - rest[v]))
        .filter(|(_, d)| d.length() > 0.0)
        .collect();
    let biggest = handle_like
        .iter()
        .map(|(_, d)| d.length())
        .fold(0.0, f64::max);
    // The naive edit: every moved vertex takes the motion of the farthest-moved vertex
    // nearest to it among the top 5% movers, with a smoothstep falloff of distance over
    // that motion's length (the ROI radius rule).
    let leaders: Vec<&(usize, DVec3)> = handle_like
        .iter()
        .filter(|(_, d)| d.length() > 0.5 * biggest)
        .collect();
    let naive: Vec<DVec3> = (0..rest.len())
        .map(|v| {
            if !moved.contains(&v) {
                return rest[v];
            }
            let (leader, motion) = leaders
                .iter()
                .min_by(|a, b| {
                    rest[a.0]
                        .distance(rest[v])
                        .total_cmp(&rest[b.0].distance(rest[v]))
                })
                .unwrap();
            let t = (rest[*leader].distance(rest[v]) / motion.length()).clamp(0.0, 1.0);
            rest[v] + *motion * (1.0 - t * t * (3.0 - 2.0 * t))
        })
        .collect();
    let ours = detail_change(&mesh, &result.positions, &moved);
    let naive = detail_change(&mesh, &naive, &moved);
    eprintln!("bumpy torus: relative |Lx| change over the ROI: ours {ours:.4}, naive {naive:.4}");
    // Measured: ours 0.80, naive 1.34, over a narrow ROI (727 vertices).
    assert!(ours < 0.8 * naive, "ours {ours}, naive {naive}");
}

/// The relative change of the cotangent Laplacians' lengths (the surface detail) over the
/// vertices `over`, from `mesh` to `positions`.
fn detail_change(mesh: &Mesh, positions: &[DVec3], over: &[usize]) -> f64 {
    let laplacian = cotan_laplacian(mesh);
    let rest = mesh.positions();
    let mut lx = vec![DVec3::ZERO; rest.len()];
    let mut lp = vec![DVec3::ZERO; rest.len()];
    laplacian.mul_dvec3(positions, &mut lx);
    laplacian.mul_dvec3(rest, &mut lp);
    let change: f64 = over
        .iter()
        .map(|&v| (lx[v].length() - lp[v].length()).abs())
        .sum();
    let size: f64 = over.iter().map(|&v| lp[v].length()).sum();
    change / size
}

#[test]
fn a_soft_fit_follows_the_stroke_less_and_keeps_more_detail() {
    let mesh = primitives::bumpy_torus(0.03, 192, 64);
    let camera = Camera::default();
    let outline = longest_outline(&mesh, &camera);
    let stroke = pushed_stroke(&outline, DVec2::X, 50, 40.0);
    let exact = oversketch_with(&mesh, &camera, VIEWPORT, &stroke, BendOptions::EXACT).unwrap();
    let soft = HandleFit::Soft {
        weight: SOFT_FIT_WEIGHT,
    };
    let soft = oversketch_with(&mesh, &camera, VIEWPORT, &stroke, near(soft)).unwrap();
    assert_eq!(soft.handle, exact.handle, "the same outline piece matched");
    let worst =
        |result: &Oversketched| worst_middle_distance(&mesh, &result.positions, &camera, &stroke);
    let (worst_exact, worst_soft) = (worst(&exact), worst(&soft));
    let moved: Vec<usize> = (0..mesh.n_vertices())
        .filter(|&v| mesh.positions()[v] != exact.positions[v])
        .collect();
    let (detail_exact, detail_soft) = (
        detail_change(&mesh, &exact.positions, &moved),
        detail_change(&mesh, &soft.positions, &moved),
    );
    eprintln!(
        "bumpy torus: exact {worst_exact:.2} px, detail change {detail_exact:.3}; \
         soft {worst_soft:.2} px, detail change {detail_soft:.3}"
    );
    // The soft outline still moves most of the way (the stroke is 40 px out).
    assert!(
        worst_soft > worst_exact && worst_soft < 20.0,
        "soft {worst_soft} px"
    );
    assert!(
        detail_soft < detail_exact,
        "soft {detail_soft}, exact {detail_exact}"
    );
}

#[test]
fn far_strokes_are_refused_and_change_nothing() {
    let mesh = primitives::icosphere(1.0, 4);
    let camera = Camera::default();
    let far: Vec<DVec2> = (0..=100)
        .map(|k| DVec2::new(40.0 + 2.0 * k as f64, 60.0))
        .collect();
    assert_eq!(
        oversketch(&mesh, &camera, VIEWPORT, &far),
        Err(OversketchError::NoMatch)
    );
    assert_eq!(preview_handle(&mesh, &camera, VIEWPORT, &far), None);

    let mut editor = Editor::new();
    editor.apply(import_op(&mesh)).unwrap();
    let document = editor.document().clone();
    let op = oversketch_op(&far);
    assert_eq!(
        editor.apply(op),
        Err(CommandError::Oversketch(OversketchError::NoMatch))
    );
    assert_eq!(*editor.document(), document);
    assert_eq!(editor.ops().len(), 1);
    assert!(!editor.can_redo());
    // A stroke whose ends lie 60 px off the outline (within reach of matching, beyond the
    // 40 px of a confident match) is a guess, refused too.
    let outline = longest_outline(&mesh, &camera);
    let centre = outline.iter().sum::<DVec2>() / outline.len() as f64;
    let offset: Vec<DVec2> = pushed_stroke(&outline, DVec2::X, 15, 0.0)
        .iter()
        .map(|&p| p + (p - centre).normalize() * 60.0)
        .collect();
    assert_eq!(
        oversketch(&mesh, &camera, VIEWPORT, &offset),
        Err(OversketchError::LowConfidence)
    );
    assert_eq!(
        preview_handle(&mesh, &camera, VIEWPORT, &offset).map(|(_, is_confident)| is_confident),
        Some(false)
    );
    assert_eq!(
        editor.apply(oversketch_op(&offset)),
        Err(CommandError::Oversketch(OversketchError::LowConfidence))
    );
    assert_eq!(*editor.document(), document);
    assert_eq!(editor.ops().len(), 1);
    // An empty document refuses too.
    assert!(Editor::new().apply(oversketch_op(&far)).is_err());
}

fn import_op(mesh: &Mesh) -> Op {
    let document = Document {
        models: vec![Arc::new(Model {
            mesh: mesh.clone(),
            ..Model::default()
        })],
        ..Document::default()
    };
    Op::Import(ImportInput {
        files: vec![FileInput {
            name: String::from("sphere.glb"),
            data: Some(Arc::new(write_glb(&document))),
        }],
        beside: false,
    })
}

fn oversketch_op(stroke: &[DVec2]) -> Op {
    Op::Oversketch(OversketchInput {
        viewport: VIEWPORT.to_array(),
        camera: Camera::default(),
        stroke: stroke.iter().map(|p| [p.x, p.y, 0.5]).collect(),
        fit: OversketchFit::Exact,
        roi: OversketchRoi::NearHandle,
        handle: None,
    })
}

#[test]
fn oversketch_op_replays_and_undoes_exactly() {
    let sphere = primitives::icosphere(1.0, 4);
    let mut editor = Editor::new();
    editor.apply(import_op(&sphere)).unwrap();
    let before = editor.document().clone();
    let mesh = before.models[0].mesh.clone();
    let outline = longest_outline(&mesh, &Camera::default());
    let stroke = pushed_stroke(&outline, DVec2::new(0.6, -0.8), 50, 40.0);
    editor.apply(oversketch_op(&stroke)).unwrap();
    let after = editor.document().clone();
    let expected = oversketch(&mesh, &Camera::default(), VIEWPORT, &stroke).unwrap();
    assert_eq!(after.models[0].mesh.positions(), &expected.positions[..]);
    assert_ne!(after, before);
    assert_eq!(after.models[0].mesh.triangles(), mesh.triangles());

    let session = editor.session();
    let json = editor.session_json();
    assert_eq!(*Editor::replay(&session).unwrap().document(), after);
    assert_eq!(*Editor::replay_json(&json).unwrap().document(), after);

    editor.undo().unwrap();
    assert_eq!(*editor.document(), before);
    assert!(Arc::ptr_eq(&editor.document().models[0], &before.models[0]));
    editor.redo().unwrap();
    assert_eq!(*editor.document(), after);

    // A soft over-sketch of the same stroke: the op carries its fit through the editor and
    // the session file.
    let Op::Oversketch(exact) = oversketch_op(&stroke) else {
        unreachable!("oversketch_op makes an oversketch")
    };
    let soft = Op::Oversketch(OversketchInput {
        fit: OversketchFit::Soft,
        roi: OversketchRoi::NearHandle,
        ..exact
    });
    editor.undo().unwrap();
    editor.apply(soft).unwrap();
    let fit = HandleFit::Soft {
        weight: SOFT_FIT_WEIGHT,
    };
    let expected =
        oversketch_with(&mesh, &Camera::default(), VIEWPORT, &stroke, near(fit)).unwrap();
    let softened = editor.document().clone();
    assert_eq!(softened.models[0].mesh.positions(), &expected.positions[..]);
    assert_ne!(softened, after);
    assert_eq!(
        *Editor::replay_json(&editor.session_json())
            .unwrap()
            .document(),
        softened
    );
}

#[test]
fn roi_is_bounded_by_the_displacements() {
    // A smaller push frees a smaller region.
    let mesh = primitives::icosphere(1.0, 5);
    let camera = Camera::default();
    let outline = longest_outline(&mesh, &camera);
    let small = oversketch(
        &mesh,
        &camera,
        VIEWPORT,
        &pushed_stroke(&outline, DVec2::X, 60, 20.0),
    )
    .unwrap();
    let large = oversketch(
        &mesh,
        &camera,
        VIEWPORT,
        &pushed_stroke(&outline, DVec2::X, 60, 50.0),
    )
    .unwrap();
    assert!(
        small.roi_size < large.roi_size,
        "{} vs {}",
        small.roi_size,
        large.roi_size
    );
}

/// An editor with one shape created from an ellipse outline (semi-axes `rx`, `ry` px,
/// `n` samples) drawn round the middle of the viewport with the default camera.
fn created(rx: f64, ry: f64, n: usize) -> Editor {
    let outline: Vec<[f64; 3]> = (0..=n)
        .map(|k| {
            let a = TAU * k as f64 / n as f64;
            [500.0 + rx * a.cos(), 500.0 + ry * a.sin(), 0.5]
        })
        .collect();
    let mut editor = Editor::new();
    editor
        .apply(Op::Create(
            StrokeInput {
                viewport: VIEWPORT.to_array(),
                camera: Camera::default(),
                stroke: outline,
            }
            .into(),
        ))
        .unwrap();
    editor
}

#[test]
fn control_curves_follow_their_vertices() {
    // A created model keeps its outline as a control curve through mesh vertices; seen from
    // the camera it was drawn with, that outline is the silhouette.
    let mut editor = created(180.0, 180.0, 120);
    let before = editor.document().models[0].clone();
    assert!(!before.curves.is_empty() && !before.curves[0].vertices.is_empty());
    let outline = longest_outline(&before.mesh, &Camera::default());
    let stroke = pushed_stroke(&outline, DVec2::X, 25, 30.0);
    editor.apply(oversketch_op(&stroke)).unwrap();
    let after = &editor.document().models[0];
    // The curves are chains of the mesh's vertices: they moved with them.
    assert_ne!(
        after.curves[0].points(&after.mesh),
        before.curves[0].points(&before.mesh)
    );
    assert_eq!(after.curves[0].vertices, before.curves[0].vertices);
}

/// The sphere's outline on the right, picked by a stroke along it, then redrawn 40 px out:
/// the manual handle lands on the new stroke as closely as a matched one, and cropping its
/// end moves less of the mesh.
#[test]
fn a_picked_silhouette_piece_moves_onto_its_new_shape_and_crops() {
    let mesh = primitives::icosphere(1.0, 5);
    let camera = Camera::default();
    let outline = longest_outline(&mesh, &camera);
    let along = pushed_stroke(&outline, DVec2::X, 60, 0.0);
    let handle = pick_handle(&mesh, &camera, VIEWPORT, &along, OutlineKind::Smooth).unwrap();
    let ManualHandle::Silhouette { from, .. } = handle else {
        panic!("a stroke along the outline should pick it, got {handle:?}");
    };
    let stroke = pushed_stroke(&outline, DVec2::X, 60, 40.0);
    let fit = HandleFit::Exact;
    let result = oversketch_manual(&mesh, &camera, VIEWPORT, &handle, &stroke, near(fit)).unwrap();
    assert_outside_unmoved(&mesh, &result);
    let worst = worst_middle_distance(&mesh, &result.positions, &camera, &stroke);
    eprintln!("manual silhouette: worst distance {worst:.3} px");
    assert!(worst < 2.0, "worst {worst}");

    // Cropped to the first half: the new shape's first half, and fewer vertices move.
    let half = along[along.len() / 2];
    let cropped = ManualHandle::Silhouette {
        from,
        via: along[along.len() / 4],
        to: half,
        outline: OutlineKind::Smooth,
    };
    let preview = manual_handle_preview(&mesh, &camera, VIEWPORT, &cropped).unwrap();
    assert!(preview.last().unwrap().distance(half) < 3.0);
    let short = &stroke[..stroke.len() / 2];
    let cropped = oversketch_manual(&mesh, &camera, VIEWPORT, &cropped, short, near(fit)).unwrap();
    let moved = |r: &Oversketched| {
        (0..mesh.n_vertices())
            .filter(|&v| r.positions[v] != mesh.positions()[v])
            .count()
    };
    assert!(
        moved(&cropped) < moved(&result),
        "{} vs {}",
        moved(&cropped),
        moved(&result)
    );
    // `via` on the far side of the closed outline picks the long way round.
    let far_side = *outline.iter().min_by(|a, b| a.x.total_cmp(&b.x)).unwrap();
    let long_way = ManualHandle::Silhouette {
        from,
        via: far_side,
        to: half,
        outline: OutlineKind::Smooth,
    };
    let long = manual_handle_preview(&mesh, &camera, VIEWPORT, &long_way).unwrap();
    assert!(
        length(&long) > 3.0 * length(&preview),
        "{} vs {}",
        length(&long),
        length(&preview)
    );
}

/// A curve drawn across the front of the sphere, then drawn again 30 px higher: the curve is
/// embedded (its handle is mesh vertices on it), the surface under the new stroke is where
/// the curve was in depth, and the far side stays.
#[test]
fn a_curve_drawn_on_the_surface_moves_to_its_new_position_at_its_depth() {
    let mesh = primitives::icosphere(1.0, 5);
    let camera = Camera::default();
    let centre = 0.5 * VIEWPORT;
    let line = |dy: f64| -> Vec<DVec2> {
        (0..=100)
            .map(|k| centre + DVec2::new(-100.0 + 2.0 * k as f64, dy))
            .collect()
    };
    let drawn = line(0.0);
    let handle = pick_handle(&mesh, &camera, VIEWPORT, &drawn, OutlineKind::Smooth).unwrap();
    assert!(matches!(handle, ManualHandle::Surface { .. }), "{handle:?}");
    let moved_to = line(-30.0);
    let result = oversketch_manual(
        &mesh,
        &camera,
        VIEWPORT,
        &handle,
        &moved_to,
        BendOptions::EXACT,
    )
    .unwrap();
    assert_outside_unmoved(&mesh, &result);
    // The handle is the curve embedded: mesh vertices moved onto it as drawn.
    for &p in &result.handle {
        assert!(
            distance_to_polyline(p, &drawn) < 0.1,
            "{p} off the drawn curve"
        );
    }
    let mut bent = mesh.clone();
    bent.positions_mut().copy_from_slice(&result.positions);
    let depth = |mesh: &Mesh, p: DVec2| {
        let (origin, dir) = camera.ray_in_world(p, VIEWPORT);
        Bvh::new(mesh).raycast(mesh, origin, dir).unwrap().distance
    };
    // The middle 80% of the curve (its ends sit between constraints). The curve is embedded
    // as a chain of mesh edges, so rays exactly along it could slip between two triangles:
    // they aim a third of a pixel below it.
    let below = DVec2::new(0.0, 0.37);
    for k in 10..=90 {
        let before = depth(&mesh, drawn[k] + below);
        let after = depth(&bent, moved_to[k] + below);
        assert!(
            (after - before).abs() < 0.01,
            "point {k}: depth {before} then {after}"
        );
    }
}

/// A manual over-sketch replays from its session and undoes to the exact mesh; a handle
/// that no longer finds its outline is refused with a sentence and changes nothing.
#[test]
fn a_manual_oversketch_op_replays_and_a_lost_handle_is_refused() {
    let mesh = primitives::icosphere(1.0, 4);
    let camera = Camera::default();
    let outline = longest_outline(&mesh, &camera);
    let along = pushed_stroke(&outline, DVec2::X, 40, 0.0);
    let handle = pick_handle(&mesh, &camera, VIEWPORT, &along, OutlineKind::Smooth).unwrap();
    let stroke = pushed_stroke(&outline, DVec2::X, 40, 30.0);
    let op = |handle: ManualHandle| {
        Op::Oversketch(OversketchInput {
            viewport: VIEWPORT.to_array(),
            camera,
            stroke: stroke.iter().map(|p| [p.x, p.y, 0.5]).collect(),
            fit: OversketchFit::Exact,
            roi: OversketchRoi::NearHandle,
            handle: Some(handle),
        })
    };
    let mut editor = Editor::new();
    editor.apply(import_op(&mesh)).unwrap();
    let before = editor.document().clone();
    editor.apply(op(handle.clone())).unwrap();
    let after = editor.document().clone();
    let imported = &before.models[0].mesh;
    let expected = oversketch_manual(
        imported,
        &camera,
        VIEWPORT,
        &handle,
        &stroke,
        BendOptions::EXACT,
    )
    .unwrap();
    assert!(after.models[0].mesh.positions() == &expected.positions[..]);
    let json = editor.session_json();
    assert!(json.contains("\"silhouette\""), "{json}");
    assert_eq!(*Editor::replay_json(&json).unwrap().document(), after);
    editor.undo().unwrap();
    assert_eq!(*editor.document(), before);

    let nowhere = ManualHandle::Silhouette {
        from: DVec2::new(5.0, 5.0),
        via: DVec2::new(10.0, 5.0),
        to: DVec2::new(15.0, 5.0),
        outline: OutlineKind::Smooth,
    };
    assert_eq!(
        editor.apply(op(nowhere)),
        Err(CommandError::Oversketch(OversketchError::HandleLost))
    );
    assert_eq!(*editor.document(), before);
}

/// The first model of a mesh in the shared test data.
fn scan(name: &str) -> Option<Mesh> {
    let dir = crate::common::testdata()?;
    let bytes = std::fs::read(dir.join("meshes").join(name)).unwrap();
    let file = sketchmesh_core::io::ImportFile {
        name,
        bytes: &bytes,
    };
    let imported = sketchmesh_core::io::import_gltf(&file, &[], &Default::default()).unwrap();
    Some(imported.models[0].mesh.clone())
}

/// A camera looking at the whole of `mesh` from `direction`, its outline filling about
/// half of the viewport.
fn camera_from(mesh: &Mesh, direction: DVec3) -> Camera {
    let (lo, hi) = mesh.bounding_box().unwrap();
    let centre = 0.5 * (lo + hi);
    let radius = 0.5 * (hi - lo).length();
    Camera {
        eye: centre + direction.normalize() * 2.5 * radius,
        target: centre,
        ..Camera::default()
    }
}

/// A stroke over the piece of `outline` (open or closed) centred on its point `anchor`,
/// `half_span` points either side, pushed by `push · sin(π u)` px towards `outward`,
/// smoothed and resampled every 1 px.
fn pushed_piece(
    outline: &[DVec2],
    anchor: usize,
    half_span: usize,
    push: f64,
    outward: DVec2,
) -> Vec<DVec2> {
    let piece =
        &outline[anchor.saturating_sub(half_span)..(anchor + half_span + 1).min(outline.len())];
    let count = piece.len();
    let pushed: Vec<DVec2> = (0..count)
        .map(|k| {
            let before = piece[k.saturating_sub(1)];
            let after = piece[(k + 1).min(count - 1)];
            let mut normal = (after - before).perp().normalize();
            if normal.dot(outward) < 0.0 {
                normal = -normal;
            }
            let u = k as f64 / (count - 1) as f64;
            piece[k] + normal * push * (PI * u).sin()
        })
        .collect();
    resample(&smooth(&pushed, 4), 1.0)
}

/// The topmost point (smallest y) of any of `outlines` among those whose x lies within
/// `[from, to]` of their width: the outline's index and the point's.
fn top_between(outlines: &[Vec<DVec2>], from: f64, to: f64) -> (usize, usize) {
    let (lo, hi) = outlines
        .iter()
        .flatten()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p.x), hi.max(p.x))
        });
    let range = (lo + from * (hi - lo))..=(lo + to * (hi - lo));
    outlines
        .iter()
        .enumerate()
        .flat_map(|(i, outline)| outline.iter().enumerate().map(move |(k, p)| (i, k, *p)))
        .filter(|(_, _, p)| range.contains(&p.x))
        .min_by(|a, b| a.2.y.total_cmp(&b.2.y))
        .map(|(i, k, _)| (i, k))
        .unwrap()
}

/// Redrawing part of the back of spot seen from either side (pushed out and in, short and
/// long strokes), and an ear of the bunny from several sides: the outline as rendered lands
/// within 2 px of the stroke over its middle 80%, as on generated shapes.
#[test]
fn scan_outlines_land_on_the_stroke() {
    // Mesh, view direction, where along the outline's width its top is redrawn, points of
    // outline either side, push (px, outwards).
    let cases = [
        ("spot.glb", DVec3::X, (0.25, 0.45), 25, 12.0),
        ("spot.glb", DVec3::NEG_X, (0.55, 0.75), 25, 12.0),
        ("spot.glb", DVec3::X, (0.25, 0.45), 40, -8.0),
        ("spot.glb", DVec3::NEG_X, (0.55, 0.75), 40, -8.0),
        ("spot.glb", DVec3::NEG_X, (0.55, 0.75), 35, 20.0),
        ("stanford_bunny.glb", DVec3::Z, (0.0, 1.0), 30, 10.0),
        ("stanford_bunny.glb", DVec3::Z, (0.0, 1.0), 20, 20.0),
        ("stanford_bunny.glb", DVec3::X, (0.0, 1.0), 30, 10.0),
        ("stanford_bunny.glb", DVec3::NEG_X, (0.0, 1.0), 30, 15.0),
        (
            "stanford_bunny.glb",
            DVec3::new(1.0, 0.0, 1.0),
            (0.0, 1.0),
            30,
            15.0,
        ),
    ];
    for (name, direction, (from, to), half_span, push) in cases {
        let Some(mesh) = scan(name) else { return };
        let camera = camera_from(&mesh, direction);
        let all = outlines(&mesh, &camera);
        let (which, anchor) = top_between(&all, from, to);
        let stroke = pushed_piece(&all[which], anchor, half_span, push, DVec2::NEG_Y);
        let result = oversketch(&mesh, &camera, VIEWPORT, &stroke)
            .unwrap_or_else(|e| panic!("{name} from {direction}: {e}"));
        let worst = worst_middle_distance(&mesh, &result.positions, &camera, &stroke);
        eprintln!(
            "{name} from {direction}: stroke {:.0} px pushed {push} px, ROI {}, worst {worst:.2} px",
            length(&stroke),
            result.roi_size
        );
        assert!(worst < 2.0, "{name} from {direction}: worst {worst} px");
    }
}

/// The turning (degrees) of `polyline` at arclength `s`: the angle between the chords from
/// `s − half` to `s` and from `s` to `s + half`.
fn turning_at(polyline: &[DVec2], cumulative: &[f64], s: f64, half: f64) -> f64 {
    use sketchmesh_core::curve::polyline::point_at;
    let [a, b, c] = [s - half, s, s + half].map(|t| point_at(polyline, cumulative, t));
    (b - a).angle_to(c - b).abs().to_degrees()
}

/// The largest turning over a `2 · half` px window of the outline piece nearest `at`, within
/// `reach` px of it along the outline.
fn largest_turning_near(outlines: &[Vec<DVec2>], at: DVec2, half: f64, reach: f64) -> f64 {
    use sketchmesh_core::curve::polyline::closest_point;
    let (outline, cumulative, closest) = outlines
        .iter()
        .filter(|o| o.len() >= 2)
        .map(|o| {
            let cumulative = cumulative_lengths(o);
            let closest = closest_point(o, &cumulative, at);
            (o, cumulative, closest)
        })
        .min_by(|a, b| a.2.distance.total_cmp(&b.2.distance))
        .unwrap();
    let steps = (2.0 * reach) as usize;
    (0..=steps)
        .map(|k| closest.arclength - reach + k as f64)
        .map(|s| turning_at(outline, &cumulative, s, half))
        .fold(0.0, f64::max)
}

/// A created ellipse over-sketched with a gentle bump on top: at each end of the stroke the
/// new outline turns no more than 10° beyond the larger of the old outline's turning there
/// and the stroke's own turning over its first (last) 20 px; and the control curve that was
/// the outline is the outline still.
#[test]
fn an_oversketched_ellipse_joins_its_outline_without_a_kink() {
    let mut editor = created(260.0, 140.0, 160);
    let camera = Camera::default();
    let before = outlines(&editor.document().models[0].mesh, &camera);
    let outline = longest_outline(&editor.document().models[0].mesh, &camera);
    // Drawn a little above the outline, as a hand does: its ends start 6 px off it.
    let stroke: Vec<DVec2> = pushed_stroke(&outline, DVec2::NEG_Y, 40, 25.0)
        .into_iter()
        .map(|p| p - DVec2::new(0.0, 6.0))
        .collect();
    editor.apply(oversketch_op(&stroke)).unwrap();
    let model = &editor.document().models[0];
    let after = outlines(&model.mesh, &camera);
    let stroke_cumulative = cumulative_lengths(&stroke);
    let total = length(&stroke);
    for (end, stroke_turning) in [
        (
            stroke[0],
            turning_at(&stroke, &stroke_cumulative, 10.0, 10.0),
        ),
        (
            stroke[stroke.len() - 1],
            turning_at(&stroke, &stroke_cumulative, total - 10.0, 10.0),
        ),
    ] {
        let old = largest_turning_near(&before, end, 5.0, 15.0);
        let new = largest_turning_near(&after, end, 5.0, 15.0);
        eprintln!(
            "end {end}: new outline turns {new:.1}°, old {old:.1}°, stroke {stroke_turning:.1}°"
        );
        assert!(new <= old.max(stroke_turning) + 10.0, "a kink of {new}°");
    }
    let worst = worst_middle_distance(&model.mesh, model.mesh.positions(), &camera, &stroke);
    let curve_off = model.curves[0]
        .points(&model.mesh)
        .iter()
        .filter_map(|&p| camera.screen_from_world(p, VIEWPORT))
        .map(|p| p.truncate())
        .filter(|p| distance_to_polyline(*p, &stroke) < 30.0)
        .map(|p| {
            after
                .iter()
                .map(|o| distance_to_polyline(p, o))
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0, f64::max);
    eprintln!(
        "outline at most {worst:.2} px off the stroke; control curve at most {curve_off:.2} px off the outline"
    );
    assert!(worst < 2.0, "the outline is {worst} px off the stroke");
    assert!(
        curve_off < 1.0,
        "the curve is {curve_off} px off the outline"
    );
}

/// A stroke over both of the bunny's ears at once, whose outline jumps between them: it is
/// refused, or it changes only the outline near it (vertices 150 px or more from the stroke
/// stay exactly where they were).
#[test]
fn a_stroke_over_two_pieces_of_outline_keeps_the_rest() {
    let Some(mesh) = scan("stanford_bunny.glb") else {
        return;
    };
    let camera = camera_from(&mesh, DVec3::Z);
    let all = outlines(&mesh, &camera);
    // The ear behind, then the ear in front, as seen from the side.
    let ears = [(0.15, 0.35), (0.4, 0.6)].map(|(from, to)| top_between(&all, from, to));
    let tips = ears.map(|(which, k)| all[which][k]);
    let mut strokes: Vec<Vec<DVec2>> = [(0.0, 5.0), (3.0, 10.0), (10.0, 20.0), (0.0, 40.0)]
        .into_iter()
        .map(|(lift, bulge)| {
            let arc: Vec<DVec2> = (0..=100)
                .map(|k| {
                    let u = k as f64 / 100.0;
                    tips[0].lerp(tips[1], u) - DVec2::new(0.0, lift + bulge * (PI * u).sin())
                })
                .collect();
            resample(&arc, 1.0)
        })
        .collect();
    // Along the top of each ear, 6 px above, joined across the gap.
    let over_both: Vec<DVec2> = ears
        .iter()
        .flat_map(|&(which, k)| {
            let outline = &all[which];
            outline[k.saturating_sub(12)..(k + 13).min(outline.len())].to_vec()
        })
        .map(|p| p - DVec2::new(0.0, 6.0))
        .collect();
    strokes.push(resample(&over_both, 1.0));
    for stroke in strokes {
        let result = match oversketch(&mesh, &camera, VIEWPORT, &stroke) {
            Ok(result) => result,
            Err(refusal) => {
                eprintln!("refused: {refusal}");
                continue;
            }
        };
        let far_and_moved = mesh
            .vertices()
            .filter(|&v| {
                let p = camera
                    .screen_from_world(mesh.position(v), VIEWPORT)
                    .unwrap();
                distance_to_polyline(p.truncate(), &stroke) >= 150.0
            })
            .filter(|&v| result.positions[v.index()] != mesh.position(v))
            .count();
        eprintln!(
            "applied: ROI {}, {far_and_moved} far vertices moved",
            result.roi_size
        );
        assert_eq!(
            far_and_moved, 0,
            "vertices 150 px or more from the stroke moved"
        );
    }
}

/// The camel-nose workflow (Nealen Fig. 4.2): a ridge sketched down the front of a sphere,
/// then seen from the side, where its crest is the outline as rendered. Picked as an edge
/// outline and redrawn farther out, the rendered outline lands on the new stroke; the far
/// side of the sphere stays.
#[test]
fn a_ridge_seen_edge_on_is_an_outline_the_oversketch_edits() {
    use sketchmesh_core::feature::{FeatureEdit, FeatureKind, Sketch};
    let sphere = primitives::icosphere(1.0, 5);
    let front = Camera::default();
    let centre = 0.5 * VIEWPORT;
    let down: Vec<DVec2> = (0..=60)
        .map(|k| centre + DVec2::new(0.0, -120.0 + 4.0 * k as f64))
        .collect();
    let sketch = Sketch {
        camera: front,
        viewport: VIEWPORT,
        points: down,
        region: None,
    };
    let ridge = FeatureEdit::new(&sphere, &sketch, FeatureKind::Ridge).unwrap();
    let mut mesh = sphere.clone();
    let shaped = ridge.shape(4.0).unwrap();
    mesh.positions_mut().copy_from_slice(&shaped.positions);

    // From the right side the crest is the outline's left edge (the front of the sphere).
    let side = Camera {
        eye: DVec3::new(front.eye.length(), 0.0, 0.0),
        ..front
    };
    let chains =
        sketchmesh_core::silhouette::outline_chains(&mesh, &Bvh::new(&mesh), &side, VIEWPORT);
    let crest: Vec<DVec2> = chains
        .iter()
        .flat_map(|c| c.screen.iter().copied())
        .filter(|p| (p.y - centre.y).abs() < 60.0 && p.x < centre.x)
        .collect();
    let leftmost = crest.iter().map(|p| p.x).fold(f64::INFINITY, f64::min);
    let along: Vec<DVec2> = (0..=40)
        .map(|k| DVec2::new(leftmost + 0.5, centre.y - 40.0 + 2.0 * k as f64))
        .collect();
    let handle = pick_handle(&mesh, &side, VIEWPORT, &along, OutlineKind::Edge).unwrap();
    assert!(
        matches!(
            handle,
            ManualHandle::Silhouette {
                outline: OutlineKind::Edge,
                ..
            }
        ),
        "{handle:?}"
    );
    // The crest pushed 20 px further out, smoothly.
    let redrawn: Vec<DVec2> = along
        .iter()
        .enumerate()
        .map(|(k, &p)| p - DVec2::new(20.0 * (PI * k as f64 / 40.0).sin(), 0.0))
        .collect();
    let result = oversketch_manual(
        &mesh,
        &side,
        VIEWPORT,
        &handle,
        &redrawn,
        BendOptions::EXACT,
    )
    .unwrap();
    assert_outside_unmoved(&mesh, &result);
    let worst = worst_middle_distance(&mesh, &result.positions, &side, &redrawn);
    eprintln!(
        "camel nose: crest at x {leftmost:.1}, ROI {}, worst {worst:.2} px",
        result.roi_size
    );
    assert!(worst < 2.0, "the outline is {worst} px off the stroke");
}

/// At each end of `stroke`: the largest turning of the outlines `after` near it, of the
/// outlines `before` there, and the stroke's own over its first (last) 20 px (degrees).
fn join_turnings(
    before: &[Vec<DVec2>],
    after: &[Vec<DVec2>],
    stroke: &[DVec2],
) -> [(f64, f64, f64); 2] {
    let cumulative = cumulative_lengths(stroke);
    let total = length(stroke);
    [(stroke[0], 10.0), (stroke[stroke.len() - 1], total - 10.0)].map(|(end, s)| {
        (
            largest_turning_near(after, end, 5.0, 15.0),
            largest_turning_near(before, end, 5.0, 15.0),
            turning_at(stroke, &cumulative, s, 10.0),
        )
    })
}

/// Issue 49: a created dome over-sketched across part of its silhouette, the stroke starting
/// and ending on the outline (as the page's case draws it) and bulging out or in: at each
/// join the new outline turns within 10° of the larger of the old outline's turning and the
/// stroke's own there, so no notch.
#[test]
fn an_oversketched_dome_joins_its_outline_without_a_notch() {
    let cases = [
        (170.0, 120.0, 40.0, PI / 3.0),
        (170.0, 170.0, 40.0, PI / 3.0),
        (170.0, 120.0, 20.0, PI / 4.0),
        (170.0, 120.0, -20.0, PI / 3.0),
    ];
    for (rx, ry, bulge, span) in cases {
        let mut editor = created(rx, ry, 60);
        let camera = Camera::default();
        let before = outlines(&editor.document().models[0].mesh, &camera);
        let c = DVec2::new(500.0, 500.0);
        let stroke: Vec<DVec2> = (0..=40)
            .map(|i| {
                let a = -span + 2.0 * span * i as f64 / 40.0;
                let push = bulge * (1.5 * a * (PI / 3.0) / span).cos().powi(2);
                c + DVec2::new((rx + push) * a.cos(), (ry + push) * a.sin())
            })
            .collect();
        editor.apply(oversketch_op(&stroke)).unwrap();
        let after = outlines(&editor.document().models[0].mesh, &camera);
        for (new, old, own) in join_turnings(&before, &after, &stroke) {
            eprintln!(
                "dome {rx}×{ry}, bulge {bulge} px: the join turns {new:.1}° (outline {old:.1}°, stroke {own:.1}°)"
            );
            assert!(new <= old.max(own) + 10.0, "a notch of {new}°");
        }
    }
}

/// Issue 49, on scans: an outline piece redrawn with a stroke that starts and ends on it
/// joins the rest with no notch (as on the dome above).
#[test]
fn a_scan_s_redrawn_outline_joins_without_a_notch() {
    let cases = [
        ("spot.glb", DVec3::X, (0.25, 0.45), 25, 12.0),
        ("stanford_bunny.glb", DVec3::Z, (0.0, 1.0), 30, 10.0),
    ];
    for (name, direction, (from, to), half_span, push) in cases {
        let Some(mesh) = scan(name) else { return };
        let camera = camera_from(&mesh, direction);
        let before = outlines(&mesh, &camera);
        let (which, anchor) = top_between(&before, from, to);
        let stroke = pushed_piece(&before[which], anchor, half_span, push, DVec2::NEG_Y);
        let result =
            oversketch(&mesh, &camera, VIEWPORT, &stroke).unwrap_or_else(|e| panic!("{name}: {e}"));
        let mut moved = mesh.clone();
        moved.positions_mut().copy_from_slice(&result.positions);
        let after = outlines(&moved, &camera);
        for (new, old, own) in join_turnings(&before, &after, &stroke) {
            eprintln!("{name}: the join turns {new:.1}° (outline {old:.1}°, stroke {own:.1}°)");
            assert!(new <= old.max(own) + 10.0, "{name}: a notch of {new}°");
        }
    }
}

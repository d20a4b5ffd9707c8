//! FiberMesh curve editing through the document: curves added on a shape, pulled, erased,
//! switched sharp and rubbed, each one undoable op that replays exactly.

#![allow(clippy::unwrap_used)] // A panic is a test failure with a location.

use std::f64::consts::TAU;

use glam::{DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{
    AddCurveInput, CommandError, CurveTypeInput, Editor, Model, Op, StrokeInput,
};
use sketchmesh_core::geometry::{face_normal, raycast};
use sketchmesh_core::mesh::{HalfedgeId, Mesh};
use sketchmesh_core::solve::SolveError;

#[path = "../../benches/common/fibermesh_shape.rs"]
mod fibermesh_shape;

const VIEWPORT: [f64; 2] = [800.0, 600.0];
const CENTRE: DVec2 = DVec2::new(400.0, 300.0);

fn input(points: impl IntoIterator<Item = DVec2>) -> StrokeInput {
    StrokeInput {
        viewport: VIEWPORT,
        camera: Camera::default(),
        stroke: points.into_iter().map(|p| [p.x, p.y, 0.5]).collect(),
    }
}

fn circle(radius: f64) -> StrokeInput {
    input((0..=80).map(|i| CENTRE + radius * DVec2::from_angle(TAU * f64::from(i) / 80.0)))
}

/// Samples along the segment from `a` to `b`, about every 4 px.
fn segment(a: DVec2, b: DVec2) -> Vec<DVec2> {
    let n = (a.distance(b) / 4.0).ceil().max(1.0) as usize;
    (0..=n).map(|i| a.lerp(b, i as f64 / n as f64)).collect()
}

fn screen(p: DVec3) -> DVec2 {
    Camera::default()
        .screen_from_world(p, DVec2::from(VIEWPORT))
        .unwrap()
        .truncate()
}

/// A created circle (radius 150 px) with an open curve across its front, from 90 px left of
/// the centre to 90 px right.
fn shape_with_front_curve() -> Editor {
    let mut editor = Editor::new();
    editor.apply(Op::Create(circle(150.0).into())).unwrap();
    let across = segment(CENTRE - DVec2::X * 90.0, CENTRE + DVec2::X * 90.0);
    editor
        .apply(Op::AddCurve(add_input(&across, false, false)))
        .unwrap();
    editor
}

fn add_input(points: &[DVec2], closed: bool, cross_section: bool) -> AddCurveInput {
    let stroke = input(points.iter().copied());
    AddCurveInput {
        viewport: stroke.viewport,
        camera: stroke.camera,
        stroke: stroke.stroke,
        closed,
        cross_section,
    }
}

fn model(editor: &Editor) -> &Model {
    &editor.document().models[0]
}

/// The stroke of a drag from the screen position of `from` by `by` px.
fn drag(from: DVec3, by: DVec2) -> StrokeInput {
    let start = screen(from);
    input(segment(start, start + by))
}

/// A stroke along a curve's screen projection, given its points.
fn along(points: &[DVec3]) -> StrokeInput {
    input(points.iter().map(|&p| screen(p)))
}

/// The points of `model`'s curve `k`.
fn points(model: &Model, k: usize) -> Vec<DVec3> {
    model.curves[k].points(&model.mesh)
}

fn assert_closed_manifold(mesh: &Mesh) {
    mesh.validate().unwrap();
    assert!(
        (0..mesh.n_vertices() as u32)
            .all(|v| !mesh.is_boundary_vertex(sketchmesh_core::mesh::VertexId(v))),
        "the surface has a boundary"
    );
}

/// Every curve is a chain of mesh edges.
fn assert_curves_embedded(model: &Model) {
    for curve in &model.curves {
        let n = curve.vertices.len();
        let n_edges = if curve.is_closed { n } else { n - 1 };
        for k in 0..n_edges {
            let (a, b) = (curve.vertices[k], curve.vertices[(k + 1) % n]);
            assert!(
                model.mesh.vertex_neighbors(a).any(|w| w == b),
                "curve vertices {a:?} and {b:?} are not joined by a mesh edge"
            );
        }
    }
}

#[test]
fn an_open_stroke_on_a_shape_becomes_a_smooth_curve_on_it() {
    let editor = shape_with_front_curve();
    let model = model(&editor);
    assert_eq!(model.curves.len(), 2);
    let added = &model.curves[1];
    assert!(!added.is_closed && !added.is_sharp());
    assert_closed_manifold(&model.mesh);
    assert_curves_embedded(model);
    for p in added.points(&model.mesh) {
        let s = screen(p);
        assert!(
            (s.y - CENTRE.y).abs() < 2.0,
            "curve point {s} off the stroke"
        );
        assert!(
            (s.x - CENTRE.x).abs() < 92.0,
            "curve point {s} beyond the stroke"
        );
    }
}

#[test]
fn a_pull_moves_the_grabbed_point_parallel_to_the_screen_and_keeps_other_curves() {
    let mut editor = shape_with_front_curve();
    let before = model(&editor).clone();
    let front = points(&before, 1);
    let middle = front[front.len() / 2];
    let by = DVec2::new(0.0, -60.0);
    editor.apply(Op::Pull(drag(middle, by))).unwrap();
    let after = model(&editor);
    assert_closed_manifold(&after.mesh);
    assert_curves_embedded(after);
    // The grabbed point went 60 px up on the screen, at its depth.
    let target = screen(middle) + by;
    let nearest = points(after, 1)
        .iter()
        .map(|&p| screen(p).distance(target))
        .fold(f64::INFINITY, f64::min);
    assert!(
        nearest < 0.5,
        "no curve point within {nearest} px of the release point"
    );
    // The outline is not connected to the pulled curve: it stays exactly.
    assert_eq!(points(after, 0), points(&before, 0));
    // One undo restores the exact model.
    editor.undo().unwrap();
    assert_eq!(model(&editor), &before);
}

#[test]
fn a_long_pull_on_a_fine_shape_settles_into_an_unfolded_surface() {
    // An ellipse of 10k vertices, its outline pulled out by 150 px (60% of its half-width):
    // the triangles next to the moved outline stretch and invert, and measured on them the
    // optimization ran away to infinite positions (the remesher then refused a NaN length).
    let mut editor = fibermesh_shape::ellipse_editor(10_000).unwrap();
    let viewport = fibermesh_shape::VIEWPORT;
    let grab = viewport / 2.0 + DVec2::new(fibermesh_shape::HALF_AXES.x, 0.0);
    let by = DVec2::new(150.0, 0.0);
    let pull = StrokeInput {
        viewport: viewport.to_array(),
        camera: Camera::default(),
        stroke: segment(grab, grab + by)
            .iter()
            .map(|p| [p.x, p.y, 0.5])
            .collect(),
    };
    let before = model(&editor).clone();
    editor.apply(Op::Pull(pull)).unwrap();
    let after = model(&editor);
    assert_closed_manifold(&after.mesh);
    assert_curves_embedded(after);
    assert_eq!(
        folded_edges(&after.mesh),
        0,
        "the pulled surface folds over itself"
    );
    // The grabbed vertex (the visible outline vertex nearest the grab) went where dragged.
    let on_screen = |p: DVec3| {
        Camera::default()
            .screen_from_world(p, viewport)
            .unwrap()
            .truncate()
    };
    let pulled = points(after, 0);
    let landed = points(&before, 0)
        .into_iter()
        .filter(|&q| on_screen(q).distance(grab) < 16.0)
        .flat_map(|q| pulled.iter().map(move |&p| (p, q)))
        .map(|(p, q)| on_screen(p).distance(on_screen(q) + by))
        .fold(f64::INFINITY, f64::min);
    assert!(
        landed < 0.5,
        "no curve point within {landed} px of a release point"
    );
}

#[test]
fn a_pull_far_past_the_shape_does_not_run_away() {
    // The front curve pulled up past the top of the shape: the surface folds over the top,
    // and fed back, the folds made the optimization run away (to six times the shape's
    // size, or to NaN). Now either the run notices and the op is refused, changing
    // nothing, or the result stays bounded.
    let mut editor = shape_with_front_curve();
    let before = model(&editor).clone();
    let front = points(&before, 1);
    let middle = front[front.len() / 2];
    match editor.apply(Op::Pull(drag(middle, DVec2::new(0.0, -220.0)))) {
        Err(error) => {
            assert_eq!(error, CommandError::Surface(SolveError::Diverged));
            assert_eq!(model(&editor), &before);
            assert_eq!(editor.ops().len(), 2);
        }
        Ok(()) => {
            let after = model(&editor);
            assert_closed_manifold(&after.mesh);
            assert_curves_embedded(after);
            let size = |mesh: &Mesh| {
                let (lo, hi) = mesh.bounding_box().unwrap();
                (hi - lo).length()
            };
            let (size_before, size_after) = (size(&before.mesh), size(&after.mesh));
            assert!(
                size_after < 1.5 * size_before,
                "the surface ran away: size {size_after} from {size_before}"
            );
        }
    }
}

/// Interior edges whose two faces face more than 120° apart: folds, where the surface
/// doubles back on itself.
fn folded_edges(mesh: &Mesh) -> usize {
    (0..mesh.n_halfedges() as u32)
        .map(HalfedgeId)
        .filter_map(|h| mesh.twin(h).filter(|t| h.0 < t.0).map(|t| (h, t)))
        .filter(|&(h, t)| {
            let (f, g) = (mesh.face(h), mesh.face(t));
            face_normal(mesh, f).dot(face_normal(mesh, g)) < -0.5
        })
        .count()
}

#[test]
fn erasing_the_added_curve_after_a_pull_returns_close_to_the_creation() {
    let mut editor = Editor::new();
    editor.apply(Op::Create(circle(150.0).into())).unwrap();
    let created = model(&editor).clone();
    let across = segment(CENTRE - DVec2::X * 90.0, CENTRE + DVec2::X * 90.0);
    editor
        .apply(Op::AddCurve(add_input(&across, false, false)))
        .unwrap();
    let curve = points(model(&editor), 1);
    let middle = curve[curve.len() / 2];
    editor
        .apply(Op::Pull(drag(middle, DVec2::new(0.0, -80.0))))
        .unwrap();
    let pulled = model(&editor).clone();
    let diagonal = bbox_diagonal(&created.mesh);
    let pulled_gap = max_distance(&pulled.mesh, &created.mesh) / diagonal;
    editor.apply(Op::Erase(along(&points(&pulled, 1)))).unwrap();
    let erased = model(&editor);
    assert_eq!(erased.curves.len(), 1, "only the outline is left");
    assert_closed_manifold(&erased.mesh);
    let gap = max_distance(&erased.mesh, &created.mesh) / diagonal;
    eprintln!(
        "largest distance to the creation: pulled {pulled_gap:.4}, erased {gap:.4} of the diagonal"
    );
    assert!(
        gap < ERASE_TOLERANCE,
        "erased shape is {gap} of the diagonal from the creation"
    );
    assert!(gap < 0.5 * pulled_gap);
}

/// How close (largest vertex distance to the creation's surface, over the bounding-box
/// diagonal) erasing brings a pulled shape back to its creation. The test's 80 px pull moves
/// the surface by about 0.09 of the diagonal; erasing leaves 0.02.
const ERASE_TOLERANCE: f64 = 0.03;

#[test]
fn a_sharp_curve_creases_at_least_30_degrees_more_than_smooth() {
    let mut editor = Editor::new();
    editor.apply(Op::Create(circle(150.0).into())).unwrap();
    let right = points(model(&editor), 0)
        .into_iter()
        .max_by(|a, b| a.x.total_cmp(&b.x))
        .unwrap();
    editor
        .apply(Op::Pull(drag(right, DVec2::new(70.0, 0.0))))
        .unwrap();
    let smooth = crease(model(&editor));
    let pulled_outline = points(model(&editor), 0);
    editor
        .apply(Op::SetCurveType(CurveTypeInput {
            sharp: true,
            ..type_input(&pulled_outline)
        }))
        .unwrap();
    assert!(model(&editor).curves.iter().all(|c| c.is_sharp()));
    let sharp = crease(model(&editor));
    eprintln!("crease across the outline: smooth {smooth:.1}°, sharp {sharp:.1}°");
    assert!(sharp >= smooth + 30.0, "smooth {smooth}°, sharp {sharp}°");
    // And back: smooth again.
    editor
        .apply(Op::SetCurveType(CurveTypeInput {
            sharp: false,
            ..type_input(&points(model(&editor), 0))
        }))
        .unwrap();
    assert!(crease(model(&editor)) < sharp - 30.0);
}

fn type_input(curve: &[DVec3]) -> CurveTypeInput {
    let stroke = along(curve);
    CurveTypeInput {
        viewport: stroke.viewport,
        camera: stroke.camera,
        stroke: stroke.stroke,
        sharp: false,
    }
}

#[test]
fn rubbing_smooths_a_wobbly_curve_more_with_more_passes() {
    let wobbly: Vec<DVec2> = (0..=60)
        .map(|i| {
            let x = -90.0 + 3.0 * f64::from(i);
            CENTRE + DVec2::new(x, 6.0 * (f64::from(i) * 1.3).sin())
        })
        .collect();
    let mut editor = Editor::new();
    editor.apply(Op::Create(circle(150.0).into())).unwrap();
    editor
        .apply(Op::AddCurve(add_input(&wobbly, false, false)))
        .unwrap();
    let mut roughness = vec![curve_roughness(&points(model(&editor), 1))];
    for passes in [1, 3] {
        let mut rub = Vec::new();
        for pass in 0..passes {
            let (a, b) = (CENTRE - DVec2::X * 60.0, CENTRE + DVec2::X * 60.0);
            rub.extend(if pass % 2 == 0 {
                segment(a, b)
            } else {
                segment(b, a)
            });
        }
        editor.apply(Op::Rub(input(rub))).unwrap();
        roughness.push(curve_roughness(&points(model(&editor), 1)));
    }
    eprintln!("roughness: {roughness:?}");
    assert!(
        roughness[1] < roughness[0] && roughness[2] < roughness[1],
        "{roughness:?}"
    );
}

#[test]
fn a_session_of_curve_edits_replays_identically() {
    let mut editor = shape_with_front_curve();
    let curve = points(model(&editor), 1);
    let middle = curve[curve.len() / 2];
    editor
        .apply(Op::Pull(drag(middle, DVec2::new(0.0, -40.0))))
        .unwrap();
    let cross = segment(
        CENTRE + DVec2::new(-40.0, -200.0),
        CENTRE + DVec2::new(-40.0, 200.0),
    );
    editor
        .apply(Op::AddCurve(add_input(&cross, false, true)))
        .unwrap();
    let outline = points(model(&editor), 0);
    editor
        .apply(Op::SetCurveType(CurveTypeInput {
            sharp: true,
            ..type_input(&outline)
        }))
        .unwrap();
    editor
        .apply(Op::Erase(along(&points(model(&editor), 1))))
        .unwrap();
    let json = editor.session_json();
    let replayed = Editor::replay_json(&json).unwrap();
    assert_eq!(replayed.document(), editor.document());
    assert_eq!(replayed.session_json(), json);
}

#[test]
fn curve_tools_away_from_curves_are_refused_and_change_nothing() {
    let mut editor = shape_with_front_curve();
    let before = editor.document().clone();
    let far = input(segment(DVec2::new(20.0, 20.0), DVec2::new(60.0, 20.0)));
    assert_eq!(
        editor.apply(Op::Pull(far.clone())),
        Err(CommandError::NoCurveHere)
    );
    assert_eq!(
        editor.apply(Op::Erase(far.clone())),
        Err(CommandError::NoCurveHere)
    );
    assert_eq!(
        editor.apply(Op::Rub(far.clone())),
        Err(CommandError::NoCurveHere)
    );
    assert!(matches!(
        editor.apply(Op::AddCurve(add_input(
            &segment(DVec2::new(20.0, 20.0), DVec2::new(60.0, 20.0)),
            false,
            false
        ))),
        Err(CommandError::NotOnModel)
    ));
    assert_eq!(editor.document(), &before);
    assert_eq!(editor.ops().len(), 2);
}

#[test]
fn erasing_the_last_curve_is_refused() {
    let mut editor = Editor::new();
    editor.apply(Op::Create(circle(150.0).into())).unwrap();
    let outline = points(model(&editor), 0);
    assert_eq!(
        editor.apply(Op::Erase(along(&outline))),
        Err(CommandError::LastCurve)
    );
}

/// The largest angle between the normals of the two faces at an edge of any curve.
fn crease(model: &Model) -> f64 {
    let mesh = &model.mesh;
    let mut worst = 0.0f64;
    for curve in &model.curves {
        let n = curve.vertices.len();
        for k in 0..n - 1 {
            let (a, b) = (curve.vertices[k], curve.vertices[k + 1]);
            let Some(h) = mesh.outgoing_halfedges(a).find(|&h| mesh.head(h) == b) else {
                continue;
            };
            let Some(t) = mesh.twin(h) else { continue };
            let cosine = face_normal(mesh, mesh.face(h)).dot(face_normal(mesh, mesh.face(t)));
            worst = worst.max(cosine.clamp(-1.0, 1.0).acos().to_degrees());
        }
    }
    worst
}

/// Σ‖L₁‖² over the interior curve points, relative to the squared mean edge length.
fn curve_roughness(p: &[DVec3]) -> f64 {
    let mean_edge = p.windows(2).map(|w| w[0].distance(w[1])).sum::<f64>() / (p.len() - 1) as f64;
    p.windows(3)
        .map(|w| (w[1] - 0.5 * (w[0] + w[2])).length_squared())
        .sum::<f64>()
        / (mean_edge * mean_edge)
}

fn bbox_diagonal(mesh: &Mesh) -> f64 {
    let (lo, hi) = mesh.bounding_box().unwrap();
    lo.distance(hi)
}

/// The largest over `a`'s vertices of their distance to the surface `b` along the ray from
/// `b`'s centroid (both shapes are star-shaped about it): a one-sided Hausdorff distance
/// that does not count how differently the two are sampled.
fn max_distance(a: &Mesh, b: &Mesh) -> f64 {
    // Off the centroid a little, so that no ray passes exactly through a vertex of `b`
    // (many vertices of `a` are vertices of `b`), where it might slip between triangles.
    let centre = b.positions().iter().sum::<DVec3>() / b.n_vertices() as f64
        + DVec3::new(1.3e-4, 2.9e-4, 0.7e-4);
    let distances: Vec<f64> = a
        .positions()
        .iter()
        .filter_map(|&p| {
            let offset = p - centre;
            let hit = raycast(b, centre, offset.normalize())?;
            Some((hit.distance - offset.length()).abs())
        })
        .collect();
    // Rays grazing the outline, where front and back meet, can slip between triangles.
    assert!(
        distances.len() * 10 >= 9 * a.n_vertices(),
        "rays missed the surface: {} of {} hit",
        distances.len(),
        a.n_vertices()
    );
    distances.iter().copied().fold(0.0, f64::max)
}

//! Feature sketching (Nealen's dissertation §4.4): ridges and ravines along a sketch, bumps,
//! flattening and suggestive contours over a region, on generated shapes and scans.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use glam::{DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::polyline::distance_to_polyline;
use sketchmesh_core::feature::{FeatureEdit, FeatureError, FeatureKind, Sketch};
use sketchmesh_core::geometry::vertex_normals;
use sketchmesh_core::mesh::{Mesh, TriSoup, VertexId, primitives};

use crate::common::{circle, screen, testdata};

const VIEWPORT: DVec2 = DVec2::new(800.0, 800.0);

fn front_camera() -> Camera {
    Camera {
        eye: DVec3::new(0.0, 0.0, 3.0),
        ..Camera::default()
    }
}

fn sketch(camera: Camera, points: Vec<DVec2>, region: Option<Vec<DVec2>>) -> Sketch {
    Sketch {
        camera,
        viewport: VIEWPORT,
        points,
        region,
    }
}

/// A straight sketch from `a` to `b`, sampled every 2 px.
fn line(a: DVec2, b: DVec2) -> Vec<DVec2> {
    let n = (a.distance(b) / 2.0).ceil() as usize;
    (0..=n).map(|i| a.lerp(b, i as f64 / n as f64)).collect()
}

/// The screen point of a world point seen by `camera`.
fn px(camera: &Camera, p: DVec3) -> DVec2 {
    screen(camera, VIEWPORT, p).unwrap()
}

/// A flat square grid in the xy plane, `n` cells a side, whose diagonals mirror across the
/// x axis, so the mesh is symmetric about it.
fn mirrored_grid(n: usize, size: f64) -> Mesh {
    let cell = size / n as f64;
    let at = |i: usize, j: usize| (j * (n + 1) + i) as u32;
    let positions = (0..=n)
        .flat_map(|j| (0..=n).map(move |i| (i, j)))
        .map(|(i, j)| {
            DVec3::new(
                i as f64 * cell - 0.5 * size,
                j as f64 * cell - 0.5 * size,
                0.0,
            )
        })
        .collect();
    let mut triangles = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            if j >= n / 2 {
                triangles.extend([[a, b, c], [a, c, d]]);
            } else {
                triangles.extend([[a, b, d], [b, c, d]]);
            }
        }
    }
    Mesh::from_soup(&TriSoup {
        positions,
        triangles,
    })
    .unwrap()
}

/// Mean curvature normals' components along the normal, the normalised cotangent
/// Laplacians `δ·n` at `vertices` of `positions` on `mesh`'s connectivity.
fn normal_laplacians(mesh: &Mesh, positions: &[DVec3], vertices: &[VertexId]) -> Vec<f64> {
    let mut shaped = mesh.clone();
    shaped.positions_mut().copy_from_slice(positions);
    let normals = vertex_normals(&shaped);
    vertices
        .iter()
        .map(|&v| {
            let p = positions[v.index()];
            let mut weights = Vec::new();
            for h in shaped.outgoing_halfedges(v) {
                let j = shaped.head(h);
                let k = shaped.tail(shaped.prev(h));
                let (pj, pk) = (positions[j.index()], positions[k.index()]);
                let cot = |u: DVec3, w: DVec3| u.dot(w) / u.cross(w).length();
                weights.push((j, 0.5 * cot(p - pk, pj - pk)));
                weights.push((k, 0.5 * cot(p - pj, pk - pj)));
            }
            let total: f64 = weights.iter().map(|w| w.1).sum();
            let mean: DVec3 = weights.iter().map(|&(u, w)| w * positions[u.index()]).sum();
            (p - mean / total).dot(normals[v.index()])
        })
        .collect()
}

fn sphere_sketch() -> (Mesh, Sketch) {
    let mesh = primitives::icosphere(1.0, 4);
    let camera = front_camera();
    let points = line(
        px(&camera, DVec3::new(-0.5, 0.1, 0.8)),
        px(&camera, DVec3::new(0.5, 0.1, 0.8)),
    );
    (mesh, sketch(camera, points, None))
}

#[test]
fn the_embedded_path_follows_the_sketch() {
    let (mesh, sketch) = sphere_sketch();
    let edit = FeatureEdit::new(&mesh, &sketch, FeatureKind::Ridge).unwrap();
    assert!(
        edit.path().len() > 10,
        "{} path vertices",
        edit.path().len()
    );
    for &v in edit.path() {
        let s = px(&sketch.camera, edit.embedded()[v.index()]);
        let off = distance_to_polyline(s, &sketch.points);
        assert!(off < 0.5, "path vertex {v:?} is {off} px off the sketch");
    }
    // Only the region moved, and the shape at the neutral amount is the embedded one.
    let roi: std::collections::HashSet<VertexId> = edit.roi().iter().copied().collect();
    for v in mesh.vertices().filter(|v| !roi.contains(v)) {
        assert_eq!(edit.embedded()[v.index()], mesh.position(v));
    }
    assert_eq!(edit.shape(1.0).unwrap().positions, edit.embedded());
}

#[test]
fn ridge_height_grows_with_the_amount_and_its_curvature_flips_with_its_sign() {
    let (mesh, sketch) = sphere_sketch();
    let edit = FeatureEdit::new(&mesh, &sketch, FeatureKind::Ridge).unwrap();
    let inner = &edit.path()[2..edit.path().len() - 2];
    let height = |amount: f64| {
        let shaped = edit.shape(amount).unwrap();
        assert_eq!(shaped.limited_to, None, "amount {amount} was cut back");
        let total: f64 = inner
            .iter()
            .map(|&v| {
                let (before, after) = (edit.embedded()[v.index()], shaped.positions[v.index()]);
                (after - before).dot(before.normalize())
            })
            .sum();
        (total / inner.len() as f64, shaped.positions)
    };
    let amounts = [-4.0, -2.0, 0.0, 1.0, 2.0, 4.0, 8.0];
    let heights: Vec<f64> = amounts.iter().map(|&a| height(a).0).collect();
    eprintln!("ridge heights {heights:?}");
    assert!(heights.windows(2).all(|h| h[0] < h[1]), "{heights:?}");
    assert!(
        heights[6] > 0.02,
        "a ridge of amount 8 rises {}",
        heights[6]
    );
    let curvature = |amount: f64| {
        let values = normal_laplacians(&mesh, &height(amount).1, inner);
        values.iter().sum::<f64>() / values.len() as f64
    };
    let (ridge, ravine, neutral) = (curvature(4.0), curvature(-4.0), curvature(1.0));
    eprintln!("mean δ·n along the path: ravine {ravine}, neutral {neutral}, ridge {ridge}");
    assert!(neutral > 0.0 && ridge > 2.0 * neutral && ravine < 0.0);
}

#[test]
fn a_ridge_on_a_flat_grid_is_symmetric_about_the_sketch() {
    let mesh = mirrored_grid(60, 2.0);
    let camera = front_camera();
    let points = line(
        px(&camera, DVec3::new(-0.6, 0.0, 0.0)),
        px(&camera, DVec3::new(0.6, 0.0, 0.0)),
    );
    let edit = FeatureEdit::new(&mesh, &sketch(camera, points, None), FeatureKind::Ridge).unwrap();
    let shaped = edit.shape(10.0).unwrap().positions;
    let peak = edit
        .path()
        .iter()
        .map(|v| shaped[v.index()].z)
        .fold(0.0, f64::max);
    // A third of a cell at amount 3 (see `feature::targets` on flat parts).
    assert!(peak > 0.5 / 30.0, "the ridge rises {peak}");
    let mirror_of = |v: VertexId| {
        let n = 61;
        let (i, j) = (v.0 as usize % n, v.0 as usize / n);
        VertexId((((n - 1 - j) * n) + i) as u32)
    };
    let mut worst: f64 = 0.0;
    for v in mesh.vertices() {
        let (p, q) = (shaped[v.index()], shaped[mirror_of(v).index()]);
        worst = worst.max((p - DVec3::new(q.x, -q.y, q.z)).length());
    }
    assert!(worst < 1e-9, "asymmetric by {worst}");
}

/// A bumpy sheet: a Gaussian hill in the middle of a flat grid.
fn hill() -> Mesh {
    let mut mesh = mirrored_grid(50, 2.0);
    for p in mesh.positions_mut() {
        p.z = 0.25 * (-(p.x * p.x + p.y * p.y) / 0.08).exp();
    }
    mesh
}

#[test]
fn flatten_drives_the_region_s_curvature_to_zero() {
    let mesh = hill();
    let camera = front_camera();
    let region = circle(px(&camera, DVec3::ZERO), 0.6 * 322.0);
    let points = line(
        px(&camera, DVec3::new(-0.3, 0.0, 0.0)),
        px(&camera, DVec3::new(0.3, 0.0, 0.0)),
    );
    let edit = FeatureEdit::new(
        &mesh,
        &sketch(camera, points, Some(region)),
        FeatureKind::Flatten,
    )
    .unwrap();
    let shaped = edit.shape(1.0).unwrap().positions;
    // Inside the region, away from its border (where the anchors' curvature meets it).
    let inner: Vec<VertexId> = edit
        .roi()
        .iter()
        .copied()
        .filter(|&v| mesh.position(v).truncate().length() < 0.4)
        .collect();
    let before = normal_laplacians(&mesh, mesh.positions(), &inner);
    let after = normal_laplacians(&mesh, &shaped, &inner);
    let max = |values: &[f64]| values.iter().fold(0.0, |m: f64, x| m.max(x.abs()));
    eprintln!("max |δ·n| before {}, after {}", max(&before), max(&after));
    assert!(max(&after) < 0.02 * max(&before));
}

#[test]
fn turning_by_pi_equals_scaling_by_minus_one() {
    let (mesh, base) = sphere_sketch();
    let region = circle(px(&base.camera, DVec3::new(0.0, 0.1, 0.99)), 220.0);
    let sketch = Sketch {
        region: Some(region),
        ..base
    };
    let turned = FeatureEdit::new(&mesh, &sketch, FeatureKind::Suggestive).unwrap();
    let a = turned.shape(180.0).unwrap();
    assert_eq!(a.limited_to, None);
    // Scaling by −1: the same region system with every region Laplacian negated.
    let mut system = turned.region_system(&mesh).unwrap();
    let in_region: std::collections::HashSet<VertexId> = turned.roi().iter().copied().collect();
    let change: Vec<DVec3> = (system.laplacian_rows())
        .map(|(v, delta)| {
            if in_region.contains(&v) {
                -2.0 * delta
            } else {
                DVec3::ZERO
            }
        })
        .collect();
    let mut scaled = turned.embedded().to_vec();
    let displacement = system.prescribed_displacement(&change).unwrap();
    for (v, d) in system.roi_vertices().iter().zip(displacement) {
        scaled[v.index()] += d;
    }
    let worst = (a.positions.iter().zip(&scaled))
        .map(|(p, q)| p.distance(*q))
        .fold(0.0, f64::max);
    let moved = (a.positions.iter().zip(turned.embedded()))
        .map(|(p, q)| p.distance(*q))
        .fold(0.0, f64::max);
    eprintln!("turn by π vs scale by −1: {worst} apart; moved up to {moved}");
    assert!(moved > 0.01);
    assert!(worst < 1e-9 * 2.0 * 3f64.sqrt());
    // Other angles turn the region's Laplacians part way: the surface moves, and by less
    // than the half turn moves it.
    let quarter = turned.shape(90.0).unwrap().positions;
    let moved_quarter = (quarter.iter().zip(turned.embedded()))
        .map(|(p, q)| p.distance(*q))
        .fold(0.0, f64::max);
    assert!(moved_quarter > 0.001 && moved_quarter < moved);
}

#[test]
fn an_amount_that_would_fold_triangles_is_cut_back() {
    let (mesh, sketch) = sphere_sketch();
    let edit = FeatureEdit::new(&mesh, &sketch, FeatureKind::Ridge).unwrap();
    for amount in [1.0e4, -1.0e4] {
        let shaped = edit.shape(amount).unwrap();
        let limit = shaped
            .limited_to
            .expect("an amount of 10000 folds triangles");
        eprintln!("amount {amount} limited to {limit}");
        assert!(
            limit.abs() > 2.0 && limit.abs() < 1.0e4,
            "limited to {limit}"
        );
        let normals_before = face_normals(&mesh, edit.embedded());
        let normals_after = face_normals(&mesh, &shaped.positions);
        let worst = (normals_before.iter().zip(&normals_after))
            .map(|(a, b)| a.normalize().dot(b.normalize()))
            .fold(1.0, f64::min);
        assert!(worst > 0.17, "a face turned to cos {worst}");
        // Just short of the limit is allowed as it is, just past it is cut back.
        let neutral = 1.0;
        assert_eq!(
            edit.shape(neutral + 0.99 * (limit - neutral))
                .unwrap()
                .limited_to,
            None
        );
        assert!(
            edit.shape(neutral + 1.05 * (limit - neutral))
                .unwrap()
                .limited_to
                .is_some()
        );
    }
}

fn face_normals(mesh: &Mesh, positions: &[DVec3]) -> Vec<DVec3> {
    mesh.triangles()
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|v| positions[v as usize]);
            (b - a).cross(c - a)
        })
        .collect()
}

#[test]
fn bad_sketches_are_refused_with_a_sentence() {
    let (mesh, good) = sphere_sketch();
    let camera = good.camera;
    let centre = px(&camera, DVec3::ZERO);
    let refused = |points: Vec<DVec2>, region: Option<Vec<DVec2>>| {
        FeatureEdit::new(&mesh, &sketch(camera, points, region), FeatureKind::Ridge).unwrap_err()
    };
    let off = line(DVec2::new(10.0, 10.0), centre);
    assert_eq!(refused(off, None), FeatureError::MissesMesh);
    let leaving = line(centre, DVec2::new(790.0, 400.0));
    assert_eq!(refused(leaving, None), FeatureError::LeavesMesh);
    let mut back = line(centre, centre + DVec2::new(120.0, 0.0));
    back.extend(line(
        centre + DVec2::new(120.0, 0.0),
        centre + DVec2::new(20.0, 5.0),
    ));
    assert_eq!(refused(back, None), FeatureError::FoldsBack);
    let bow = vec![
        centre + DVec2::new(-100.0, -100.0),
        centre + DVec2::new(100.0, 100.0),
        centre + DVec2::new(100.0, -100.0),
        centre + DVec2::new(-100.0, 100.0),
    ];
    assert_eq!(
        refused(good.points.clone(), Some(bow)),
        FeatureError::RegionCrosses
    );
    let elsewhere = circle(centre + DVec2::new(0.0, 200.0), 30.0);
    assert_eq!(
        refused(good.points.clone(), Some(elsewhere)),
        FeatureError::RegionMissesSketch
    );
    let edit = FeatureEdit::new(&mesh, &good, FeatureKind::Ridge).unwrap();
    assert_eq!(
        edit.shape(f64::NAN).unwrap_err(),
        FeatureError::AmountNotFinite
    );
}

#[test]
fn a_ridge_on_scans_follows_the_sketch_and_keeps_the_rest() {
    let Some(dir) = testdata() else { return };
    for name in [
        "spot.glb",
        "stanford_bunny.glb",
        "nefertiti.glb",
        "igea.glb",
    ] {
        let bytes = std::fs::read(dir.join("meshes").join(name)).unwrap();
        let file = sketchmesh_core::io::ImportFile {
            name,
            bytes: &bytes,
        };
        let imported = sketchmesh_core::io::import_gltf(&file, &[], &Default::default()).unwrap();
        let mesh = &imported.models[0].mesh;
        let (lo, hi) = mesh.bounding_box().unwrap();
        let centre = 0.5 * (lo + hi);
        let radius = 0.5 * (hi - lo).length();
        let camera = Camera {
            eye: centre + DVec3::new(0.0, 0.0, 2.5 * radius),
            target: centre,
            ..Camera::default()
        };
        // A stroke across the middle of the model as seen, over its front.
        let middle = px(&camera, centre);
        let points = line(
            middle - DVec2::new(60.0, 10.0),
            middle + DVec2::new(60.0, 10.0),
        );
        let edit = FeatureEdit::new(
            mesh,
            &sketch(camera, points.clone(), None),
            FeatureKind::Ridge,
        )
        .unwrap_or_else(|e| panic!("{name}: {e}"));
        let worst = edit
            .path()
            .iter()
            .map(|&v| distance_to_polyline(px(&camera, edit.embedded()[v.index()]), &points))
            .fold(0.0, f64::max);
        let shaped = edit.shape(3.0).unwrap();
        eprintln!(
            "{name}: {} region vertices, path {} vertices at most {worst:.3} px off, limited {:?}",
            edit.roi().len(),
            edit.path().len(),
            shaped.limited_to
        );
        assert!(worst < 0.5, "{name}: the path is {worst} px off the sketch");
        let roi: std::collections::HashSet<VertexId> = edit.roi().iter().copied().collect();
        for v in mesh.vertices().filter(|v| !roi.contains(v)) {
            assert_eq!(shaped.positions[v.index()], mesh.position(v), "{name}");
        }
        let moved = edit
            .path()
            .iter()
            .map(|&v| (shaped.positions[v.index()] - edit.embedded()[v.index()]).length());
        assert!(
            moved.fold(0.0, f64::max) > 1e-3 * radius,
            "{name}: the ridge does not rise"
        );
    }
}

//! Silhouette scenarios with known answers: a sphere's outline against the exact tangent
//! cone, a torus seen down its axis (two circles, both visible) and at a grazing angle
//! (hidden parts removed, checked against a linear-scan visibility reference), and a rough
//! sphere whose zig-zag outline smoothing straightens.

use std::f64::consts::TAU;

use glam::{DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::polyline;
use sketchmesh_core::geometry::{Bvh, raycast, vertex_normals};
use sketchmesh_core::mesh::Mesh;
use sketchmesh_core::mesh::primitives::{icosphere, torus};
use sketchmesh_core::silhouette::{Silhouette, silhouettes};

const VIEWPORT: DVec2 = DVec2::new(800.0, 600.0);

/// Focal length in px of a perspective camera for [`VIEWPORT`].
fn focal_px(camera: &Camera) -> f64 {
    0.5 * VIEWPORT.y / (0.5 * camera.fov_y_deg.to_radians()).tan()
}

/// The exact outline of a sphere on screen, densely sampled: the circle where the cone from
/// the eye touches the sphere, projected.
fn exact_sphere_outline(center: DVec3, radius: f64, camera: &Camera) -> Vec<DVec2> {
    let to_center = center - camera.eye;
    let d = to_center.length();
    let axis = to_center / d;
    let circle_center = camera.eye + to_center * (1.0 - radius * radius / (d * d));
    let circle_radius = radius * (d * d - radius * radius).sqrt() / d;
    let (u, v) = axis.any_orthonormal_pair();
    (0..20_000)
        .map(|k| {
            let angle = TAU * k as f64 / 20_000.0;
            let p = circle_center + circle_radius * (angle.cos() * u + angle.sin() * v);
            camera
                .screen_from_world(p, VIEWPORT)
                .expect("in front")
                .truncate()
        })
        .collect()
}

fn distance_to_samples(p: DVec2, samples: &[DVec2]) -> f64 {
    samples
        .iter()
        .map(|q| q.distance(p))
        .fold(f64::INFINITY, f64::min)
}

/// Checks that every point lies on its edge and `g` changes sign across it.
fn assert_points_on_sign_changes(mesh: &Mesh, camera: &Camera, curves: &[Silhouette]) {
    let normals = vertex_normals(mesh);
    let g = |v: usize| match camera.ortho_height {
        Some(_) => normals[v].dot(camera.forward()),
        None => normals[v].dot(mesh.positions()[v] - camera.eye),
    };
    for point in curves.iter().flat_map(|c| &c.points) {
        let [a, b] = point.edge.map(|v| v.index());
        assert!((0.0..=1.0).contains(&point.t), "{point:?}");
        let on_edge = mesh.positions()[a].lerp(mesh.positions()[b], point.t);
        assert!((on_edge - point.world).length() < 1e-12, "{point:?}");
        assert!(g(a) * g(b) <= 0.0 && g(a) != g(b), "{point:?}");
        let interpolated = (1.0 - point.t) * g(a) + point.t * g(b);
        assert!(interpolated.abs() < 1e-12, "{point:?}");
        let projected = camera
            .screen_from_world(point.world, VIEWPORT)
            .expect("in front");
        assert!((projected.z - point.depth).abs() < 1e-12);
    }
}

/// Shoelace area in screen coordinates (y down).
fn signed_area(curve: &Silhouette) -> f64 {
    let screen: Vec<DVec2> = curve.points.iter().map(|p| p.screen).collect();
    polyline::signed_area(&screen)
}

fn spacing_range(curve: &Silhouette) -> (f64, f64) {
    curve
        .points
        .windows(2)
        .fold((f64::INFINITY, 0.0), |(lo, hi), pair| {
            let gap = pair[0].screen.distance(pair[1].screen);
            (lo.min(gap), hi.max(gap))
        })
}

#[test]
fn sphere_outline_in_perspective_is_the_tangent_cone() {
    let sphere = icosphere(1.0, 5);
    let bvh = Bvh::new(&sphere);
    let cameras = [
        Camera::default(),
        // Off-centre and tilted: the outline is an ellipse.
        Camera {
            eye: DVec3::new(1.5, 2.0, 3.5),
            target: DVec3::new(0.6, 0.4, 0.0),
            up: DVec3::new(0.2, 1.0, 0.0),
            ..Camera::default()
        },
    ];
    for camera in cameras {
        let curves = silhouettes(&sphere, &bvh, &camera, VIEWPORT);
        assert_eq!(curves.len(), 1, "{camera:?}");
        let outline = &curves[0];
        assert!(outline.closed);
        assert_points_on_sign_changes(&sphere, &camera, &curves);
        let exact = exact_sphere_outline(DVec3::ZERO, 1.0, &camera);
        let worst = outline
            .points
            .iter()
            .map(|p| distance_to_samples(p.screen, &exact))
            .fold(0.0, f64::max);
        assert!(worst < 0.1, "worst distance {worst} px");
        // Counter-clockwise as the viewer sees it: negative area with y down.
        assert!(signed_area(outline) < 0.0);
        let (lo, hi) = spacing_range(outline);
        // Gaps of 1.25 to 3.75 px where crossings are denser; the mesh sets wider ones.
        assert!(lo >= 1.25 && hi < 8.0, "spacing {lo}..{hi}");
    }
    // On the default camera the outline is the circle of radius f·tan(asin(1/5)).
    let camera = Camera::default();
    let expected = focal_px(&camera) * (0.2f64).asin().tan();
    let curves = silhouettes(&sphere, &bvh, &camera, VIEWPORT);
    for p in &curves[0].points {
        let r = p.screen.distance(0.5 * VIEWPORT);
        assert!((r - expected).abs() < 0.25, "{r} vs {expected}");
    }
}

#[test]
fn sphere_outline_in_orthographic_view_has_the_sphere_radius() {
    let sphere = icosphere(0.8, 4);
    let bvh = Bvh::new(&sphere);
    let camera = Camera {
        eye: DVec3::new(2.0, 1.0, 4.0),
        ortho_height: Some(3.0),
        ..Camera::default()
    };
    let curves = silhouettes(&sphere, &bvh, &camera, VIEWPORT);
    assert_eq!(curves.len(), 1);
    assert!(curves[0].closed);
    assert_points_on_sign_changes(&sphere, &camera, &curves);
    // 0.8 world units at 600 px per 3 units.
    let expected = 0.8 * VIEWPORT.y / 3.0;
    for p in &curves[0].points {
        let r = p.screen.distance(0.5 * VIEWPORT);
        assert!((r - expected).abs() < 0.2, "{r} vs {expected}");
    }
}

#[test]
fn torus_seen_down_its_axis_shows_both_circles() {
    let (major, minor) = (1.0, 0.35);
    let mesh = torus(major, minor, 128, 64);
    let bvh = Bvh::new(&mesh);
    let height = 4.0;
    let camera = Camera {
        eye: DVec3::new(0.0, 0.0, height),
        ..Camera::default()
    };
    let mut curves = silhouettes(&mesh, &bvh, &camera, VIEWPORT);
    assert_eq!(curves.len(), 2);
    assert!(curves.iter().all(|c| c.closed));
    assert_points_on_sign_changes(&mesh, &camera, &curves);
    // In a meridian plane the two lines from the eye tangent to the tube make angles α ± β
    // with the axis: tan α = R / h, sin β = r / √(R² + h²).
    let alpha = (major / height).atan();
    let beta = (minor / major.hypot(height)).asin();
    let f = focal_px(&camera);
    let mut expected = [f * (alpha - beta).tan(), f * (alpha + beta).tan()];
    curves.sort_by(|a, b| a.screen_length().total_cmp(&b.screen_length()));
    for (curve, expected) in curves.iter().zip(&mut expected) {
        for p in &curve.points {
            let r = p.screen.distance(0.5 * VIEWPORT);
            assert!((r - *expected).abs() < 0.25, "{r} vs {expected}");
        }
    }
}

/// Whether a linear scan sees `p` from the eye, forgiving hits within `margin` of it.
fn is_visible_by_scan(mesh: &Mesh, camera: &Camera, p: DVec3, margin: f64) -> bool {
    let distance = p.distance(camera.eye);
    let dir = (p - camera.eye) / distance;
    raycast(mesh, camera.eye, dir).is_none_or(|hit| hit.distance >= distance - margin)
}

#[test]
fn torus_at_a_grazing_angle_loses_its_hidden_parts() {
    let mesh = torus(1.0, 0.35, 96, 48);
    let bvh = Bvh::new(&mesh);
    let camera = Camera {
        eye: DVec3::new(0.0, -5.0, 1.0),
        ..Camera::default()
    };
    let curves = silhouettes(&mesh, &bvh, &camera, VIEWPORT);
    assert_points_on_sign_changes(&mesh, &camera, &curves);
    // The outline stays whole; of the inner contour only the far rim of the hole shows, the
    // rest is behind the near tube.
    let closed = curves.iter().filter(|c| c.closed).count();
    let open = curves.len() - closed;
    assert_eq!(closed, 1, "{curves:#?}");
    assert_eq!(open, 1, "the far rim of the hole");

    // Every point passes an independent visibility test with a generous margin, except at
    // the two ends of an open piece, where the piece meets its occluder (the test aims at the
    // point itself; `silhouettes` aims a quarter edge outside the surface) ...
    let edge = |p: &sketchmesh_core::silhouette::SilhouettePoint| {
        mesh.position(p.edge[0]).distance(mesh.position(p.edge[1]))
    };
    let is_end = |c: &Silhouette, i: usize| !c.closed && (i < 2 || i + 2 >= c.points.len());
    let mut n_disagree = 0;
    for c in &curves {
        for (i, p) in c.points.iter().enumerate() {
            if !is_visible_by_scan(&mesh, &camera, p.world, 3.0 * edge(p)) {
                assert!(is_end(c, i), "{i} of {}: {p:?}", c.points.len());
                n_disagree += 1;
            }
        }
    }
    assert!(n_disagree <= 4, "{n_disagree}");
    // ... and the raw zero crossings that are clearly hidden (a hit more than three edge
    // lengths in front) show up nowhere on the result, while every clearly visible one (no hit
    // but within half an edge length) has a result point within 4 px or lies within 8 px of
    // the end of a piece.
    let normals = vertex_normals(&mesh);
    let g: Vec<f64> = (0..mesh.n_vertices())
        .map(|v| normals[v].dot(mesh.positions()[v] - camera.eye))
        .collect();
    let shown: Vec<(DVec2, DVec3)> = curves
        .iter()
        .flat_map(|c| c.points.iter().map(|p| (p.screen, p.world)))
        .collect();
    let shown_inside: Vec<(DVec2, DVec3)> = curves
        .iter()
        .flat_map(|c| {
            let ends = c
                .points
                .iter()
                .enumerate()
                .filter(move |&(i, _)| !is_end(c, i));
            ends.map(|(_, p)| (p.screen, p.world))
        })
        .collect();
    let (mut n_hidden, mut n_visible, mut n_visible_covered) = (0, 0, 0);
    for tri in mesh.triangles() {
        for k in 0..3 {
            let (a, b) = (tri[k] as usize, tri[(k + 1) % 3] as usize);
            if a > b || (g[a] > 0.0) == (g[b] > 0.0) {
                continue;
            }
            let t = g[a] / (g[a] - g[b]);
            let (pa, pb) = (mesh.positions()[a], mesh.positions()[b]);
            let p = pa.lerp(pb, t);
            let screen = camera
                .screen_from_world(p, VIEWPORT)
                .expect("in front")
                .truncate();
            let length = pa.distance(pb);
            if !is_visible_by_scan(&mesh, &camera, p, 3.0 * length) {
                n_hidden += 1;
                // Near a T-junction a hidden crossing lies next to the occluding curve on
                // screen, but not in space.
                let nearest = shown_inside
                    .iter()
                    .filter(|(_, world)| world.distance(p) < 0.1)
                    .map(|(q, _)| q.distance(screen))
                    .fold(f64::INFINITY, f64::min);
                assert!(nearest > 1.0, "hidden crossing {p} shown ({nearest} px)");
            } else if is_visible_by_scan(&mesh, &camera, p, 0.5 * length) {
                n_visible += 1;
                let nearest = shown
                    .iter()
                    .map(|(q, _)| q.distance(screen))
                    .fold(f64::INFINITY, f64::min);
                // Pieces may stop a few px short of where they meet their occluder.
                let near_an_end = curves
                    .iter()
                    .filter(|c| !c.closed)
                    .flat_map(|c| [c.points[0].screen, c.points[c.points.len() - 1].screen])
                    .any(|end| end.distance(screen) < 8.0);
                n_visible_covered += usize::from(nearest < 4.0 || near_an_end);
            }
        }
    }
    assert!(n_hidden > 20, "{n_hidden}");
    assert!(
        n_visible_covered == n_visible,
        "{n_visible_covered} of {n_visible}"
    );
}

/// Total absolute turning angle of a closed screen polyline.
fn total_turning(points: &[DVec2]) -> f64 {
    let n = points.len();
    (0..n)
        .map(|i| {
            let a = points[i] - points[(i + n - 1) % n];
            let b = points[(i + 1) % n] - points[i];
            a.angle_to(b).abs()
        })
        .sum()
}

#[test]
fn smoothing_removes_the_zig_zag_of_a_rough_sphere() {
    // Radial noise of ±0.5% at every vertex.
    let mut sphere = icosphere(1.0, 5);
    for (k, p) in sphere.positions_mut().iter_mut().enumerate() {
        let noise = ((k as f64 * 12.9898).sin() * 43_758.545).fract();
        *p *= 1.0 + 0.002 * (noise - 0.5);
    }
    let bvh = Bvh::new(&sphere);
    let camera = Camera::default();
    let curves = silhouettes(&sphere, &bvh, &camera, VIEWPORT);
    // The outline, plus perhaps a few tiny loops around bumps.
    let (outline, bumps): (Vec<&Silhouette>, Vec<&Silhouette>) =
        curves.iter().partition(|c| c.screen_length() > 100.0);
    assert_eq!(outline.len(), 1);
    assert!(outline[0].closed);
    assert!(bumps.iter().all(|c| c.screen_length() < 30.0));
    assert_points_on_sign_changes(&sphere, &camera, &curves);
    let raw: Vec<DVec2> = outline[0]
        .points
        .iter()
        .map(|p| {
            camera
                .screen_from_world(p.world, VIEWPORT)
                .expect("in front")
                .truncate()
        })
        .collect();
    let smoothed: Vec<DVec2> = outline[0].points.iter().map(|p| p.screen).collect();
    // A smooth closed curve turns by 2π in all; the raw one zig-zags far more.
    let (before, after) = (total_turning(&raw), total_turning(&smoothed));
    assert!(
        before > 2.0 * TAU && after < 0.7 * before,
        "{before} -> {after}"
    );
    let shift = raw
        .iter()
        .zip(&smoothed)
        .map(|(a, b)| a.distance(*b))
        .fold(0.0, f64::max);
    assert!(shift < 0.5, "{shift}");
}

#[test]
fn nothing_behind_the_eye_or_through_an_invalid_camera() {
    let sphere = icosphere(1.0, 3);
    let bvh = Bvh::new(&sphere);
    let looking_away = Camera {
        eye: DVec3::new(0.0, 0.0, 5.0),
        target: DVec3::new(0.0, 0.0, 10.0),
        ..Camera::default()
    };
    assert!(silhouettes(&sphere, &bvh, &looking_away, VIEWPORT).is_empty());
    let invalid = Camera {
        eye: DVec3::ZERO,
        target: DVec3::ZERO,
        ..Camera::default()
    };
    assert!(silhouettes(&sphere, &bvh, &invalid, VIEWPORT).is_empty());
}

#![allow(clippy::unwrap_used)]

use glam::{DVec2, DVec3};

use super::*;
use crate::camera::Camera;
use crate::mesh::primitives::icosphere;

const VIEWPORT: DVec2 = DVec2::new(800.0, 600.0);

fn screen(camera: &Camera, p: DVec3) -> DVec2 {
    camera.screen_from_world(p, VIEWPORT).unwrap().truncate()
}

/// A base loop of `radius` px around the screen point of `centre`, and a silhouette from
/// its top out `reach` px to the right and back to its bottom.
fn strokes(camera: &Camera, centre: DVec3, radius: f64, reach: f64) -> (Vec<DVec2>, Vec<DVec2>) {
    let c = screen(camera, centre);
    let base = (0..48)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / 48.0;
            c + radius * DVec2::new(a.cos(), a.sin())
        })
        .collect();
    let silhouette = (0..=40)
        .map(|k| {
            let a = std::f64::consts::PI * (k as f64 / 40.0 - 0.5);
            c + DVec2::new(reach * a.cos(), radius * a.sin())
        })
        .collect();
    (base, silhouette)
}

fn viewed<'a>(camera: &'a Camera, points: &'a [DVec2]) -> ViewedStroke<'a> {
    ViewedStroke {
        camera,
        viewport: VIEWPORT,
        stroke: points,
    }
}

#[test]
fn a_loop_and_a_silhouette_grow_a_limb_out_of_a_sphere() {
    let sphere = icosphere(1.0, 4);
    let front = Camera::default();
    let (base, silhouette) = strokes(&front, DVec3::new(0.6, 0.0, 0.8), 25.0, 150.0);
    let e = extrude(&sphere, viewed(&front, &base), viewed(&front, &silhouette)).unwrap();
    let mesh = &e.mesh;
    mesh.validate().unwrap();
    assert!(mesh.is_closed());
    assert_eq!(mesh.genus(), Some(0));
    assert!(Bvh::new(mesh).crossing_faces(mesh, |_| true).is_empty());
    let n = e.base.len();
    for k in 0..n {
        assert!(mesh.find_edge(e.base[k], e.base[(k + 1) % n]).is_some());
    }
    for w in e.silhouette.windows(2) {
        assert!(mesh.find_edge(w[0], w[1]).is_some());
    }
    assert_eq!(
        e.silhouette[0],
        e.base[e.base.iter().position(|&v| v == e.silhouette[0]).unwrap()]
    );
    assert!(e.base.contains(e.silhouette.last().unwrap()));
    // The limb reaches out to the right, and its tip sits under the stroke's far point.
    let tip = mesh.position(e.silhouette[e.silhouette.len() / 2]);
    assert!(tip.x > 1.3, "tip at {tip}");
    let far = silhouette[silhouette.len() / 2];
    assert!(screen(&front, tip).distance(far) < 1.0);
    // Every silhouette vertex lies under the stroke (the ends within the base's reach).
    for &v in &e.silhouette {
        let s = screen(&front, mesh.position(v));
        let d = silhouette
            .iter()
            .map(|p| p.distance(s))
            .fold(f64::INFINITY, f64::min);
        assert!(d < NEAR_BASE_PX, "silhouette vertex {d} px off the stroke");
    }
    assert!(e.is_limb.iter().filter(|&&x| x).count() > 30);
}

#[test]
fn a_silhouette_far_from_the_loop_is_refused() {
    let sphere = icosphere(1.0, 3);
    let front = Camera::default();
    let (base, _) = strokes(&front, DVec3::new(0.6, 0.0, 0.8), 25.0, 150.0);
    let (_, elsewhere) = strokes(&front, DVec3::new(-0.6, 0.0, 0.8), 25.0, 150.0);
    let result = extrude(&sphere, viewed(&front, &base), viewed(&front, &elsewhere));
    assert_eq!(result.unwrap_err(), ExtrudeError::NotNearBase);
}

#[test]
fn a_silhouette_into_the_shape_is_refused() {
    let sphere = icosphere(1.0, 3);
    let front = Camera::default();
    let (base, silhouette) = strokes(&front, DVec3::new(0.6, 0.0, 0.8), 25.0, -120.0);
    let result = extrude(&sphere, viewed(&front, &base), viewed(&front, &silhouette));
    assert_eq!(result.unwrap_err(), ExtrudeError::Inward);
}

#[test]
fn a_base_off_the_shape_says_so() {
    let sphere = icosphere(1.0, 3);
    let front = Camera::default();
    let (base, silhouette) = strokes(&front, DVec3::new(2.5, 0.0, 0.0), 30.0, 150.0);
    let result = extrude(&sphere, viewed(&front, &base), viewed(&front, &silhouette));
    assert!(matches!(result.unwrap_err(), ExtrudeError::Base(_)));
}

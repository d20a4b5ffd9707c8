#![allow(clippy::unwrap_used)]

use glam::{DVec2, DVec3};

use super::*;
use crate::geometry::enclosed_volume;
use crate::mesh::primitives::{icosphere, torus};

const VIEWPORT: DVec2 = DVec2::new(800.0, 600.0);

fn screen(camera: &Camera, p: DVec3) -> DVec2 {
    camera.screen_from_world(p, VIEWPORT).unwrap().truncate()
}

/// A straight stroke between the screen images of two world points, 40 samples.
fn stroke(camera: &Camera, from: DVec3, to: DVec3) -> Vec<DVec2> {
    (0..=40)
        .map(|i| screen(camera, from.lerp(to, i as f64 / 40.0)))
        .collect()
}

/// The plane through the eye and the world points `from` and `to`: unit normal and offset.
fn cutting_plane(camera: &Camera, from: DVec3, to: DVec3) -> (DVec3, f64) {
    let normal = (from - camera.eye).cross(to - camera.eye).normalize();
    (normal, normal.dot(camera.eye))
}

/// How far the farthest vertex of `mesh` lies on the normal's side of the plane.
fn beyond(mesh: &Mesh, (normal, offset): (DVec3, f64)) -> f64 {
    mesh.positions()
        .iter()
        .map(|&p| normal.dot(p) - offset)
        .fold(f64::MIN, f64::max)
}

/// The checks every cut passes: valid, closed, genus 0 for these inputs, every rim an edge
/// loop, positive volume.
fn assert_closed_shape(cut: &Cut) {
    let mesh = &cut.mesh;
    mesh.validate().unwrap();
    assert!(mesh.is_closed());
    assert_eq!(mesh.genus(), Some(0));
    for rim in &cut.rims {
        for k in 0..rim.len() {
            assert!(mesh.find_edge(rim[k], rim[(k + 1) % rim.len()]).is_some());
        }
    }
    assert!(enclosed_volume(mesh) > 0.0);
}

#[test]
fn a_stroke_across_a_sphere_cuts_off_the_smaller_part_with_a_flat_cap() {
    let sphere = icosphere(1.0, 4);
    let camera = Camera::default();
    let (from, to) = (DVec3::new(0.4, -1.4, 0.0), DVec3::new(0.4, 1.4, 0.0));
    let cut = cut(&sphere, &camera, VIEWPORT, &stroke(&camera, from, to)).unwrap();
    assert_closed_shape(&cut);
    assert_eq!(cut.rims.len(), 1);
    let (normal, offset) = cutting_plane(&camera, from, to);
    // The removed part is on the +x side, where the normal points.
    assert!(normal.x > 0.9);
    let side = |p: DVec3| normal.dot(p) - offset;
    let beyond = beyond(&cut.mesh, (normal, offset));
    assert!(beyond < 1e-9, "a vertex lies {beyond} beyond the cut");
    let cap: Vec<VertexId> = cut
        .mesh
        .vertices()
        .filter(|v| cut.is_cap[v.index()])
        .collect();
    assert!(cap.len() > 20, "{} cap vertices", cap.len());
    for &v in cap.iter().chain(&cut.rims[0]) {
        assert!(
            side(cut.mesh.position(v)).abs() < 1e-9,
            "cap vertex off the plane"
        );
    }
    // Volume: the sphere less the segment beyond the plane at distance h from the centre,
    // π (1 − h)² (2 + h) / 3, on the polyhedron's slightly smaller sphere.
    let h = offset.abs();
    let expected = 4.0 / 3.0 * std::f64::consts::PI
        - std::f64::consts::PI * (1.0 - h).powi(2) * (2.0 + h) / 3.0;
    let volume = enclosed_volume(&cut.mesh);
    assert!(
        (volume / expected - 1.0).abs() < 0.02,
        "{volume} against {expected}"
    );
    // Every kept vertex of the input off the rim is where it was; the rim moved onto the cut
    // by at most the snapping distance, 5% of an edge.
    let edge = sphere.mean_edge_length();
    for (old, new) in cut.remap.iter().enumerate().take(sphere.n_vertices()) {
        if let Some(new) = new {
            let moved = cut.mesh.position(*new).distance(sphere.positions()[old]);
            let limit = if cut.rims[0].contains(new) {
                0.06 * edge
            } else {
                0.0
            };
            assert!(moved <= limit, "vertex {old} moved {moved}");
        }
    }
}

#[test]
fn the_removed_side_is_the_smaller_one_on_screen_whichever_way_the_stroke_runs() {
    let sphere = icosphere(1.0, 3);
    let camera = Camera::default();
    let (from, to) = (DVec3::new(-1.4, -0.3, 0.0), DVec3::new(1.4, -0.3, 0.0));
    // The plane's normal points down, to the smaller part.
    let (normal, offset) = cutting_plane(&camera, from, to);
    assert!(normal.y < -0.9);
    for stroke in [stroke(&camera, from, to), stroke(&camera, to, from)] {
        let cut = cut(&sphere, &camera, VIEWPORT, &stroke).unwrap();
        assert_closed_shape(&cut);
        let beyond = beyond(&cut.mesh, (normal, offset));
        assert!(beyond < 1e-9, "a vertex lies {beyond} below the cut");
    }
}

#[test]
fn a_stroke_across_both_sides_of_a_ring_caps_two_openings() {
    let ring = torus(1.0, 0.4, 48, 16);
    let camera = Camera::default();
    let (from, to) = (DVec3::new(0.3, -1.8, 0.0), DVec3::new(0.3, 1.8, 0.0));
    let cut = cut(&ring, &camera, VIEWPORT, &stroke(&camera, from, to)).unwrap();
    assert_closed_shape(&cut);
    assert_eq!(cut.rims.len(), 2);
    let beyond = beyond(&cut.mesh, cutting_plane(&camera, from, to));
    assert!(beyond < 1e-9, "a vertex lies {beyond} beyond the cut");
}

#[test]
fn a_ring_shaped_section_is_refused() {
    let ring = torus(1.0, 0.4, 48, 16);
    let camera = Camera {
        eye: DVec3::new(0.0, -6.0, 0.0),
        target: DVec3::ZERO,
        up: DVec3::Z,
        ..Camera::default()
    };
    let (from, to) = (DVec3::new(-2.0, 0.0, 0.0), DVec3::new(2.0, 0.0, 0.0));
    let result = cut(&ring, &camera, VIEWPORT, &stroke(&camera, from, to));
    assert_eq!(result.unwrap_err(), CutError::RingSection);
}

#[test]
fn strokes_that_do_not_cross_are_refused() {
    let sphere = icosphere(1.0, 3);
    let camera = Camera::default();
    let starts_on = stroke(
        &camera,
        DVec3::new(0.0, 0.0, 1.0),
        DVec3::new(0.0, 1.5, 0.0),
    );
    let misses = stroke(
        &camera,
        DVec3::new(1.5, -1.5, 0.0),
        DVec3::new(1.5, 1.5, 0.0),
    );
    for stroke in [starts_on, misses, Vec::new()] {
        let result = cut(&sphere, &camera, VIEWPORT, &stroke);
        assert_eq!(result.unwrap_err(), CutError::DoesNotCross);
    }
}

#[test]
fn an_open_mesh_is_refused() {
    let mut open = icosphere(1.0, 2);
    open.delete_faces(&[crate::mesh::FaceId(0)]).unwrap();
    open.compact();
    let camera = Camera::default();
    let stroke = stroke(
        &camera,
        DVec3::new(0.4, -1.4, 0.0),
        DVec3::new(0.4, 1.4, 0.0),
    );
    assert_eq!(
        cut(&open, &camera, VIEWPORT, &stroke).unwrap_err(),
        CutError::NotClosed
    );
}

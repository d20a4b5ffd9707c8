//! The feature sketches shared by `benches/feature.rs` and `examples/feature_export.rs`: on a
//! 40,962-vertex icosphere seen from the front (orthographic), a sketch across its middle, alone (a ridge in
//! a 40 px band) and inside a lasso around the whole front half (about 20k vertices, the
//! issue's region size).

use glam::{DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::feature::Sketch;
use sketchmesh_core::mesh::{Mesh, primitives};

/// The icosphere the sketches are drawn on (6 subdivisions, 40,962 vertices).
pub fn sphere() -> Mesh {
    primitives::icosphere(1.0, 6)
}

const VIEWPORT: DVec2 = DVec2::new(1000.0, 1000.0);

/// An orthographic view, so that the lasso around the outline holds the whole front half.
fn camera() -> Camera {
    Camera {
        eye: DVec3::new(0.0, 0.0, 3.0),
        ortho_height: Some(2.4),
        ..Camera::default()
    }
}

fn on_screen(p: DVec3) -> DVec2 {
    camera()
        .screen_from_world(p, VIEWPORT)
        .expect("in front of the eye")
        .truncate()
}

/// The sketch across the sphere's front, from `x = -0.6` to `0.6`, gently curved; with the
/// lasso around the whole front half when `with_region`.
pub fn sketch(with_region: bool) -> Sketch {
    let points = (0..=120)
        .map(|i| {
            let x = -0.6 + 1.2 * f64::from(i) / 120.0;
            on_screen(DVec3::new(x, 0.1 * (3.0 * x).sin(), (1.0 - x * x).sqrt()))
        })
        .collect();
    let centre = on_screen(DVec3::Z);
    let rim = on_screen(DVec3::X).x - centre.x;
    let region = with_region.then(|| {
        (0..96)
            .map(|i| {
                centre + 1.05 * rim * DVec2::from_angle(std::f64::consts::TAU * f64::from(i) / 96.0)
            })
            .collect()
    });
    Sketch {
        camera: camera(),
        viewport: VIEWPORT,
        points,
        region,
    }
}

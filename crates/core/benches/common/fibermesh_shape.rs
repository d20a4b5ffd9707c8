//! A FiberMesh shape of a chosen size with its outline as control curve: the fixture the
//! curve-editing bench and the page bench (through `examples/fixture_glb.rs`) pull, since
//! the app creates shapes at its default resolution only.

use std::sync::Arc;

use glam::DVec2;
use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::StrokePoint;
use sketchmesh_core::document::{Document, Editor, FileInput, ImportInput, Model, Op};
use sketchmesh_core::fibermesh::{CreateParams, create_converged_from_stroke};
use sketchmesh_core::io::write_glb;

/// The viewport the ellipse is drawn in (the page's canvas below its toolbar).
pub const VIEWPORT: DVec2 = DVec2::new(1280.0, 680.0);

/// Half-axes of the ellipse, in px, centred in [`VIEWPORT`] under the default camera.
pub const HALF_AXES: DVec2 = DVec2::new(260.0, 170.0);

/// A document holding one created ellipse of about `target_vertices` vertices.
pub fn ellipse_document(target_vertices: usize) -> Result<Document, Box<dyn std::error::Error>> {
    let centre = VIEWPORT / 2.0;
    let stroke: Vec<StrokePoint> = (0..=120)
        .map(|i| {
            let a = std::f64::consts::TAU * f64::from(i) / 120.0;
            StrokePoint::new(centre + HALF_AXES * DVec2::new(a.cos(), a.sin()), 0.5)
        })
        .collect();
    let params = CreateParams {
        target_vertices,
        ..CreateParams::default()
    };
    let (creation, _) =
        create_converged_from_stroke(&stroke, &Camera::default(), VIEWPORT, &params)?;
    let model = Model {
        curves: vec![creation.control_curve()],
        mesh: creation.mesh,
        ..Model::default()
    };
    let mut document = Document::default();
    document.models.push(Arc::new(model));
    Ok(document)
}

/// An editor holding [`ellipse_document`], imported from its .glb as the page bench does.
#[allow(dead_code)] // The .glb example needs the document only.
pub fn ellipse_editor(target_vertices: usize) -> Result<Editor, Box<dyn std::error::Error>> {
    let document = ellipse_document(target_vertices)?;
    let mut editor = Editor::new();
    editor.apply(Op::Import(ImportInput {
        files: vec![FileInput {
            name: "ellipse.glb".to_owned(),
            data: Some(Arc::new(write_glb(&document))),
        }],
        beside: false,
    }))?;
    Ok(editor)
}

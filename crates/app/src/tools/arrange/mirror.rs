//! Arrange's symmetry buttons (issue 50), all about the document's symmetry plane (the
//! default one, `x = 0`, until a mirrored op or a file sets another): Mirror flips the
//! selected model to the other side, Mirrored duplicate adds its mirror twin, Symmetrize
//! makes it symmetric keeping the half the user picks. Left and right are the view's, so the
//! buttons say which half stays as the user sees it.

use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{Document, DuplicateInput, Op, SymmetrizeInput};
use sketchmesh_core::model::{MirrorPlane, Side};

use crate::tools::context::ToolOutput;

/// What a symmetry button asks for: the op, and the model selected after it.
pub struct Picked {
    /// What the tool gives the runner.
    pub output: ToolOutput,
    /// The model to select once it lands.
    pub select: usize,
}

/// The buttons for the `selected` model, `size` each, seen through `camera`; what was pressed.
pub fn symmetry_ui(
    ui: &mut egui::Ui,
    doc: &Document,
    selected: Option<usize>,
    camera: &Camera,
    size: egui::Vec2,
) -> Option<Picked> {
    let plane = doc.symmetry.unwrap_or_default();
    let mut picked = None;
    let mut button =
        |ui: &mut egui::Ui, label: &str, hint: &str, made: &dyn Fn(usize) -> Picked| {
            let response =
                ui.add_enabled(selected.is_some(), egui::Button::new(label).min_size(size));
            let response = response
                .on_hover_text(hint)
                .on_disabled_hover_text("Tap a model first");
            if response.clicked()
                && let Some(model) = selected
            {
                picked = Some(made(model));
            }
        };
    button(
        ui,
        "Mirror",
        "Flip the selected model across the symmetry plane, to the other side",
        &|model| Picked {
            output: ToolOutput::CommitAsMade(flip(model, &plane)),
            select: model,
        },
    );
    button(
        ui,
        "Mirrored duplicate",
        "Add the selected model's mirror image across the symmetry plane: with Symmetry on, \
         an edit of either changes both",
        &|model| Picked {
            output: ToolOutput::Commit(mirrored_duplicate(model, plane)),
            select: doc.models.len(),
        },
    );
    ui.label("Symmetrize:");
    for (label, right) in [("Keep left half", false), ("Keep right half", true)] {
        let half = if right { "right" } else { "left" };
        let hint = format!(
            "Make the selected model symmetric: its {half} half, as you see it, is kept and \
             mirrored onto the other side of the plane"
        );
        button(ui, label, &hint, &|model| Picked {
            output: ToolOutput::Commit(symmetrize(
                model,
                plane,
                side_on_screen(&plane, camera, right),
            )),
            select: model,
        });
    }
    picked
}

/// A `transform` op flipping `model` across `plane`.
fn flip(model: usize, plane: &MirrorPlane) -> Op {
    Op::Transform(sketchmesh_core::document::TransformInput {
        model,
        matrix: plane.matrix().to_cols_array(),
    })
}

/// A `duplicate` of `model` made with symmetry on about `plane`: its mirror twin.
fn mirrored_duplicate(model: usize, plane: MirrorPlane) -> Op {
    Op::Duplicate(DuplicateInput {
        model,
        beside: None,
    })
    .mirrored(plane)
}

/// A `symmetrize` op of `model` about `plane`, keeping `keep`.
fn symmetrize(model: usize, plane: MirrorPlane, keep: Side) -> Op {
    Op::Symmetrize(SymmetrizeInput { model, plane, keep })
}

/// The side of `plane` on the screen's right (`right`) or left through `camera`: where the
/// plane's normal points, against the screen's right. A plane seen face on has no left and
/// right; its near side then counts as the right.
fn side_on_screen(plane: &MirrorPlane, camera: &Camera, right: bool) -> Side {
    let frame = camera.frame();
    let across = plane.normal().dot(frame.right);
    let towards_right = if across.abs() > 1e-6 {
        across > 0.0
    } else {
        plane.normal().dot(-frame.forward) > 0.0
    };
    match towards_right == right {
        true => Side::Positive,
        false => Side::Negative,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DMat4, DVec3};

    #[test]
    fn mirror_flips_across_the_plane_and_the_duplicate_is_made_with_symmetry_on() {
        let plane = MirrorPlane::new(DVec3::X, 0.5).unwrap();
        let Op::Transform(input) = flip(0, &plane) else {
            panic!("Mirror is a transform");
        };
        let m = DMat4::from_cols_array(&input.matrix);
        let moved = m.transform_point3(DVec3::new(2.0, 1.0, -3.0));
        assert!(
            (moved - DVec3::new(-1.0, 1.0, -3.0)).length() < 1e-12,
            "{moved}"
        );
        let (op, mirror) = mirrored_duplicate(3, plane).into_parts();
        assert_eq!(mirror, Some(plane));
        assert!(matches!(op, Op::Duplicate(DuplicateInput { model: 3, .. })));
    }

    #[test]
    fn left_and_right_are_the_views() {
        let plane = MirrorPlane::default();
        let front = Camera::default();
        assert_eq!(
            front.frame().right.x.signum(),
            1.0,
            "the first view looks along -z"
        );
        assert_eq!(side_on_screen(&plane, &front, true), Side::Positive);
        assert_eq!(side_on_screen(&plane, &front, false), Side::Negative);
        // From behind, the model's +x is on the screen's left.
        let mut behind = front;
        behind.eye = DVec3::new(-behind.eye.x, behind.eye.y, -behind.eye.z);
        assert_eq!(side_on_screen(&plane, &behind, true), Side::Negative);
    }
}

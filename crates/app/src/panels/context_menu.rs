//! A model's context actions, opened by a long press on it (touch screens' right click):
//! frame it, duplicate it, delete it, or over-sketch it.

use egui::Pos2;
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{DuplicateInput, ModelInput, Op};

/// Touch-sized rows.
const ROW: egui::Vec2 = egui::vec2(160.0, 44.0);

/// The open menu: where the finger held, and the model under it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContextMenu {
    /// Where it opens, in screen points.
    pub at: Pos2,
    /// The model's index.
    pub model: usize,
}

/// What the user chose.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ContextAction {
    /// Frame the model.
    Frame,
    /// Duplicate it (the `duplicate` op), beside it toward the screen's right.
    Duplicate,
    /// Delete it (the `delete` op).
    Delete,
    /// Switch to the over-sketch tool to redraw its outline.
    Oversketch,
}

impl ContextAction {
    /// The op it makes for model `model` seen through `camera`, if it makes one.
    pub fn op(self, model: usize, camera: &Camera) -> Option<Op> {
        match self {
            ContextAction::Duplicate => Some(Op::Duplicate(DuplicateInput {
                model,
                beside: Some(camera.frame().right.to_array()),
            })),
            ContextAction::Delete => Some(Op::Delete(ModelInput { model })),
            ContextAction::Frame | ContextAction::Oversketch => None,
        }
    }
}

/// Draws the open menu; a choice, a press outside or Escape closes it.
pub fn context_menu_ui(
    ctx: &egui::Context,
    menu: &mut Option<ContextMenu>,
) -> Option<(usize, ContextAction)> {
    let open = (*menu)?;
    let mut chosen = None;
    let area = egui::Area::new(egui::Id::unique("model context menu"))
        .order(egui::Order::Foreground)
        .fixed_pos(open.at)
        .constrain(true)
        .show(ctx, |ui| {
            egui::Frame::popup(ui.style()).show(ui, |ui| {
                for (action, label) in [
                    (ContextAction::Frame, "Frame"),
                    (ContextAction::Duplicate, "Duplicate"),
                    (ContextAction::Delete, "Delete"),
                    (ContextAction::Oversketch, "Over-sketch"),
                ] {
                    if ui.add(egui::Button::new(label).min_size(ROW)).clicked() {
                        chosen = Some((open.model, action));
                    }
                }
            })
        });
    let pressed_outside = ctx.input(|i| {
        i.pointer.any_pressed()
            && i.pointer
                .interact_pos()
                .is_some_and(|p| !area.response.rect.contains(p))
    });
    let escape = ctx.input(|i| i.key_pressed(egui::Key::Escape));
    if chosen.is_some() || pressed_outside || escape {
        *menu = None;
    }
    chosen
}

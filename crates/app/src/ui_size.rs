//! The size of a touch target, which the toolbar sets and every tool's options follow.

/// The smallest size of a target in the toolbar's `ui`: square, the layout's target, which
/// the toolbar puts in `interact_size.y`, so that every tool's options follow the layout.
pub fn target_size(ui: &egui::Ui) -> egui::Vec2 {
    egui::Vec2::splat(ui.spacing().interact_size.y)
}

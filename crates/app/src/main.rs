//! Native shell: runs the app in a desktop window.

#[cfg(not(target_arch = "wasm32"))]
fn main() -> eframe::Result {
    env_logger::init();
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("Sketchmesh")
            .with_inner_size([1280.0, 800.0]),
        ..Default::default()
    };
    eframe::run_native(
        "Sketchmesh",
        options,
        Box::new(|cc| Ok(Box::new(sketchmesh_app::SketchApp::new(cc)))),
    )
}

#[cfg(target_arch = "wasm32")]
fn main() {}

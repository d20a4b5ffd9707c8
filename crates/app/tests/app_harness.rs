//! Drives the real app headlessly through egui_kittest with a wgpu renderer (lavapipe or
//! any adapter the machine has): a mouse stroke leaves ink on the rendered image and one
//! curve in the document; Ctrl+Z takes both away; right-drag orbits.

use egui::{Event, Modifiers, PointerButton, Pos2, pos2, vec2};
use egui_kittest::Harness;
use sketchmesh_app::SketchApp;

fn harness() -> Harness<'static, SketchApp> {
    Harness::builder()
        .with_size(vec2(900.0, 600.0))
        .wgpu()
        .build_eframe(|cc| SketchApp::new(cc))
}

fn press(h: &Harness<'_, SketchApp>, pos: Pos2, button: PointerButton, pressed: bool) {
    h.event(Event::PointerButton {
        pos,
        button,
        pressed,
        modifiers: Modifiers::NONE,
    });
}

fn drag(h: &mut Harness<'_, SketchApp>, from: Pos2, to: Pos2, button: PointerButton) {
    h.event(Event::PointerMoved(from));
    press(h, from, button, true);
    h.step();
    for i in 1..=20 {
        let t = i as f32 / 20.0;
        let p = from + (to - from) * t + vec2(0.0, 40.0 * (t * std::f32::consts::PI).sin());
        h.event(Event::PointerMoved(p));
        h.step();
    }
    press(h, to, button, false);
    h.run();
}

fn curves(h: &Harness<'_, SketchApp>) -> usize {
    h.state().shared().borrow().editor.document().stats().curves
}

/// Pixels whose colour differs noticeably between two renders.
fn changed_pixels(a: &image::RgbaImage, b: &image::RgbaImage) -> usize {
    a.pixels()
        .zip(b.pixels())
        .filter(|(p, q)| p.0.iter().zip(q.0.iter()).any(|(x, y)| x.abs_diff(*y) > 24))
        .count()
}

#[test]
fn stroke_leaves_ink_and_undo_takes_it_away() {
    let mut h = harness();
    h.run();
    let before = h.render().expect("render");
    drag(&mut h, pos2(250.0, 300.0), pos2(650.0, 320.0), PointerButton::Primary);
    assert_eq!(curves(&h), 1, "one stroke, one curve");
    let with_stroke = h.render().expect("render");
    let inked = changed_pixels(&before, &with_stroke);
    // A 400-point stroke at 3–5 points wide, plus the toolbar's counters changing.
    assert!(inked > 1000, "only {inked} pixels changed");
    // The ink is the sketch colour: warm yellow, somewhere along the drawn path.
    let mid = with_stroke.get_pixel(450, (310.0 + 40.0) as u32);
    let ink_near_mid = (340..370).any(|y| {
        let p = with_stroke.get_pixel(450, y).0;
        p[0] > 180 && p[1] > 140 && p[2] < 140
    });
    assert!(ink_near_mid, "no ink near the stroke's middle (pixel there: {mid:?})");

    h.key_press_modifiers(Modifiers::COMMAND, egui::Key::Z);
    h.run();
    assert_eq!(curves(&h), 0);
    let undone = h.render().expect("render");
    let left = changed_pixels(&before, &undone);
    assert!(left < inked / 20, "{left} pixels still differ after undo");

    h.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, egui::Key::Z);
    h.run();
    assert_eq!(curves(&h), 1, "redo brings the stroke back");
}

#[test]
fn right_drag_orbits_without_drawing() {
    let mut h = harness();
    h.run();
    let yaw_before = h.state().shared().borrow().camera.yaw;
    drag(&mut h, pos2(300.0, 300.0), pos2(500.0, 300.0), PointerButton::Secondary);
    let yaw_after = h.state().shared().borrow().camera.yaw;
    assert!((yaw_after - yaw_before).abs() > 0.5, "yaw {yaw_before} -> {yaw_after}");
    assert_eq!(curves(&h), 0);
}

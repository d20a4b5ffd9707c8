//! Drives the real app headlessly through egui_kittest with a wgpu renderer (lavapipe or
//! any adapter the machine has): a mouse stroke leaves ink on the rendered image and one
//! curve in the document; Ctrl+Z takes both away; right-drag orbits; a shape created and
//! pulled in the app, previewed over frames, is bit for bit the replay of its session.

use egui::{Event, Modifiers, PointerButton, Pos2, pos2, vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use sketchmesh_app::SketchApp;
use sketchmesh_app::panels::falloff::{falloff_gray, panel_rect};

fn harness() -> Harness<'static, SketchApp> {
    let mut h = Harness::builder()
        .with_size(vec2(900.0, 600.0))
        // A creation refines over about ten frames before it settles.
        .with_max_steps(40)
        // The status line's ℹ: the page's browser draws it, egui's bundled font lacks it.
        .allow_missing_glyphs()
        .wgpu()
        .build_eframe(|cc| {
            // These cases were written for edits that change one side; those with symmetry
            // turn it on.
            let app = SketchApp::new(cc);
            app.shared().borrow_mut().symmetry.choose(false);
            app
        });
    // The pointer's own cursor would differ between before and after.
    h.set_render_cursor(false);
    h
}

/// The app on a touch screen of `size` points, with a finger as the pointer.
fn touch_harness(size: egui::Vec2) -> Harness<'static, SketchApp> {
    Harness::builder()
        .with_size(size)
        .with_max_steps(40)
        // The page's browser draws what egui's bundled font lacks (☰, ▶, ⋯); here only that
        // font is installed, and the sizes are what is checked.
        .allow_missing_glyphs()
        .wgpu()
        .build_eframe(|cc| {
            let mut app = SketchApp::new(cc);
            app.set_coarse_pointer(true);
            app
        })
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

/// Rows taken by the toolbar, whose button states and counters change with the document.
const TOOLBAR_ROWS: u32 = 80;

/// Pixels of the 3D view whose colour differs noticeably between two renders.
fn changed_pixels(a: &image::RgbaImage, b: &image::RgbaImage) -> usize {
    a.enumerate_pixels()
        .filter(|(_, y, _)| *y >= TOOLBAR_ROWS)
        .filter(|(x, y, p)| {
            p.0.iter()
                .zip(b.get_pixel(*x, *y).0.iter())
                .any(|(u, v)| u.abs_diff(*v) > 24)
        })
        .count()
}

/// Pixels in columns `xs` and rows `ys` whose colour differs strongly between two renders.
fn changed_in(
    a: &image::RgbaImage,
    b: &image::RgbaImage,
    xs: std::ops::Range<u32>,
    ys: std::ops::Range<u32>,
) -> usize {
    let differs = |x, y| {
        let (p, q) = (a.get_pixel(x, y).0, b.get_pixel(x, y).0);
        (0..3).any(|c| p[c].abs_diff(q[c]) > 40)
    };
    ys.flat_map(|y| xs.clone().map(move |x| (x, y)))
        .filter(|&(x, y)| differs(x, y))
        .count()
}

#[test]
fn stroke_leaves_ink_and_undo_takes_it_away() {
    let mut h = harness();
    h.run();
    let before = h.render().expect("render");
    drag(
        &mut h,
        pos2(250.0, 300.0),
        pos2(650.0, 320.0),
        PointerButton::Primary,
    );
    assert_eq!(curves(&h), 1, "one stroke, one curve");
    let with_stroke = h.render().expect("render");
    let inked = changed_pixels(&before, &with_stroke);
    // A 400-point stroke, 3–5 points wide.
    assert!(inked > 1000, "only {inked} pixels changed");
    // The ink is the sketch colour: warm yellow, somewhere along the drawn path.
    let mid = with_stroke.get_pixel(450, (310.0 + 40.0) as u32);
    let ink_near_mid = (340..370).any(|y| {
        let p = with_stroke.get_pixel(450, y).0;
        p[0] > 180 && p[1] > 140 && p[2] < 140
    });
    assert!(
        ink_near_mid,
        "no ink near the stroke's middle (pixel there: {mid:?})"
    );

    h.key_press_modifiers(Modifiers::COMMAND, egui::Key::Z);
    h.run();
    assert_eq!(curves(&h), 0);
    let undone = h.render().expect("render");
    let left = changed_pixels(&before, &undone);
    assert!(left == 0, "{left} pixels still differ after undo");

    h.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, egui::Key::Z);
    h.run();
    assert_eq!(curves(&h), 1, "redo brings the stroke back");
}

/// Saves a render where a person can look at it (`target/tmp/*.png`).
fn save(image: &image::RgbaImage, name: &str) {
    let path = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("{name}.png"));
    image.save(&path).expect("save render");
}

/// Draws a closed ellipse of half-axes 150 × 110 about `center`, one sample per frame.
fn draw_ellipse(h: &mut Harness<'_, SketchApp>, center: Pos2) {
    draw_loop(h, center, vec2(150.0, 110.0));
}

/// Draws a closed ellipse of half-axes `radii` about `center`, one sample per frame.
fn draw_loop(h: &mut Harness<'_, SketchApp>, center: Pos2, radii: egui::Vec2) {
    trace(h, ellipse(center, radii));
    h.run();
}

/// The 61 points of a closed ellipse, back at its start.
fn ellipse(center: Pos2, radii: egui::Vec2) -> Vec<Pos2> {
    (0..=60)
        .map(|i| {
            let a = std::f32::consts::TAU * i as f32 / 60.0;
            center + vec2(radii.x * a.cos(), radii.y * a.sin())
        })
        .collect()
}

/// Presses at the first of `points`, moves through the rest one per frame, releases.
fn trace(h: &mut Harness<'_, SketchApp>, points: Vec<Pos2>) {
    h.event(Event::PointerMoved(points[0]));
    press(h, points[0], PointerButton::Primary, true);
    h.step();
    for &p in &points[1..] {
        h.event(Event::PointerMoved(p));
        h.step();
    }
    press(h, points[points.len() - 1], PointerButton::Primary, false);
}

/// Whether the app's document is exactly what replaying its session gives.
fn replays_bit_for_bit(h: &Harness<'_, SketchApp>) -> bool {
    let shared = h.state().shared();
    let editor = &shared.borrow().editor;
    let replayed = sketchmesh_core::document::Editor::replay_json(&editor.session_json())
        .expect("the session replays");
    replayed.document() == editor.document()
}

/// The Symmetry switch (X) on, an outline beside the plane (x = 0, the view's middle) makes
/// the shape and its mirror twin in one op logged with its plane; one undo takes both.
#[test]
fn with_symmetry_on_an_outline_beside_the_plane_makes_two_mirror_twins() {
    let mut h = harness();
    h.run();
    h.key_press(egui::Key::X);
    h.run();
    assert!(h.state().shared().borrow().symmetry.is_on);
    let before = h.render().expect("render");
    trace(&mut h, ellipse(pos2(640.0, 340.0), vec2(90.0, 70.0)));
    h.step();
    h.step();
    // While the shape inflates, before it is committed, its twin inflates too.
    let shared = h.state().shared();
    assert!(
        shared.borrow().editor.document().models.is_empty(),
        "still inflating"
    );
    let inflating = h.render().expect("render");
    save(&inflating, "symmetric-create-preview");
    let changed_around = |x: u32| changed_in(&before, &inflating, x - 20..x + 20, 320..360);
    assert!(
        changed_around(640) > 800,
        "the shape: {}",
        changed_around(640)
    );
    assert!(
        changed_around(260) > 800,
        "its twin: {}",
        changed_around(260)
    );
    h.run();
    let boxes: Vec<_> = (shared.borrow().editor.document().models.iter())
        .map(|m| m.mesh.bounding_box().expect("a model has vertices"))
        .collect();
    assert_eq!(boxes.len(), 2, "the shape and its twin");
    let ((lo, hi), (twin_lo, twin_hi)) = (boxes[0], boxes[1]);
    assert!(lo.x > 0.0, "drawn right of the plane: {lo}");
    let mirrored = glam::DVec3::new(-hi.x, lo.y, lo.z);
    assert!(
        (twin_lo - mirrored).length() < 1e-9,
        "{twin_lo} vs {mirrored}"
    );
    assert!((twin_hi - glam::DVec3::new(-lo.x, hi.y, hi.z)).length() < 1e-9);
    let session = shared.borrow().editor.session_json();
    assert!(
        session.contains("\"mirror\":[1.0,0.0,0.0,0.0]"),
        "{session}"
    );
    assert!(replays_bit_for_bit(&h));
    h.key_press_modifiers(Modifiers::COMMAND, egui::Key::Z);
    h.run();
    assert!(shared.borrow().editor.document().models.is_empty());
}

/// With Symmetry on, a pull on the right end of a shape drawn across the plane previews on
/// both sides while the pointer is down (the left end moves out as the right one does), and
/// commits one pull that keeps the shape symmetric.
#[test]
fn with_symmetry_on_a_pull_previews_on_both_sides() {
    let (mut h, center) = symmetric_shape_with(egui::Key::P);
    let before = h.render().expect("render");
    let held = drag_right_end(&mut h, center);
    let dragging = h.render().expect("render");
    save(&dragging, "symmetric-pull-preview");
    // Just beyond each end of the outline: background before, the shape while dragging.
    let (cx, ends) = (center.x as u32, 150 + 8..150 + 28);
    let right = changed_in(&before, &dragging, cx + ends.start..cx + ends.end, 325..355);
    let left = changed_in(
        &before,
        &dragging,
        cx - ends.end + 1..cx - ends.start + 1,
        325..355,
    );
    assert!(right > 150, "the pulled end moved out: {right} pixels");
    assert!(left > 150, "the other end moved out with it: {left} pixels");
    press(&h, held, PointerButton::Primary, false);
    h.run();
    let shared = h.state().shared();
    let (lo, hi) = (shared.borrow().editor.document().models[0].mesh)
        .bounding_box()
        .expect("a model");
    assert!(
        (lo.x + hi.x).abs() < 1e-9 * (hi - lo).length(),
        "symmetric: {lo} {hi}"
    );
    let last = shared.borrow().editor.ops().last().map(|op| op.name());
    assert_eq!(last, Some("pull"));
}

/// With Symmetry on, Arrange's Plane shows the plane's handles on a shape drawn across it:
/// a drag of its dot moves the plane, one along its ring turns it, each one undoable
/// `symmetry_plane` op that replays.
#[test]
fn the_symmetry_plane_moves_and_turns_with_the_arrange_handles() {
    let (mut h, center) = symmetric_shape_with(egui::Key::V);
    h.get_by_label("Plane").click();
    h.run();
    let line = |from: Pos2, to: Pos2| (0..=12).map(move |i| from + (to - from) * (i as f32 / 12.0));
    // The dot sits where the plane meets the middle of the shape, the middle of the view.
    trace(&mut h, line(center, center + vec2(60.0, 0.0)).collect());
    h.run();
    let shared = h.state().shared();
    let plane = |h: &Harness<'_, SketchApp>| {
        let shared = h.state().shared();
        let plane = shared.borrow().editor.document().symmetry;
        plane.expect("a plane")
    };
    let moved = plane(&h);
    assert_eq!(moved.normal(), glam::DVec3::X, "moved, not turned");
    assert!(moved.offset() > 0.1, "moved right: {moved:?}");
    // Along the ring (70 points about the dot, now 60 points right), from its bottom to
    // its bottom-left: the plane turns about the dot by the angle swept.
    let dot = center + vec2(60.0, 0.0);
    let on_ring = |a: f32| dot + 70.0 * vec2(a.cos(), a.sin());
    let sweep = (0..=12).map(|i| on_ring(std::f32::consts::FRAC_PI_2 + 0.04 * i as f32));
    trace(&mut h, sweep.collect());
    h.run();
    let turned = plane(&h);
    // The ring's middle is the dot as projected, a few points off where this case aims.
    let angle = turned.normal().angle_between(glam::DVec3::X);
    assert!((angle - 0.48).abs() < 0.1, "turned by {angle}: {turned:?}");
    let forward = shared.borrow().camera.camera().forward();
    let across = turned.normal().dot(forward);
    assert!(across.abs() < 1e-12, "about the view's axis: {across}");
    // The ring stays where the turn left it: swept back along it, the plane turns back.
    let back = (0..=12).map(|i| on_ring(std::f32::consts::FRAC_PI_2 + 0.04 * (12 - i) as f32));
    trace(&mut h, back.collect());
    h.run();
    let back = plane(&h).normal().angle_between(glam::DVec3::X);
    assert!(back < 0.02, "turned back to within {back} rad");
    let ops: Vec<&str> = (shared.borrow().editor.ops().iter())
        .map(|op| op.name())
        .collect();
    assert_eq!(
        ops,
        [
            "create",
            "symmetry_plane",
            "symmetry_plane",
            "symmetry_plane"
        ]
    );
    assert!(replays_bit_for_bit(&h));
    h.key_press_modifiers(Modifiers::COMMAND, egui::Key::Z);
    h.run();
    assert_eq!(plane(&h), turned, "one undo gives the turned plane back");
}

#[test]
fn closed_stroke_becomes_a_lit_shape_with_its_curve() {
    let mut h = harness();
    h.run();
    let center = pos2(450.0, 340.0);
    draw_ellipse(&mut h, center);
    let stats = h.state().shared().borrow().editor.document().stats();
    assert_eq!((stats.models, stats.curves), (1, 1), "{stats:?}");
    assert!(stats.vertices > 500, "{stats:?}");
    let image = h.render().expect("render");
    save(&image, "created-shape");
    // The middle of the shape is lit clay: bright, warm, opaque (the background is dark blue-grey).
    let p = image.get_pixel(center.x as u32, center.y as u32).0;
    assert!(p[0] > 120 && p[0] >= p[2], "centre pixel {p:?}");
    // The outline is drawn as a blue control curve on the silhouette.
    let blue_on_rim = (-6..=6).any(|dx: i32| {
        let q = image
            .get_pixel((center.x as i32 + 150 + dx) as u32, center.y as u32)
            .0;
        q[2] > 180 && q[2] > q[0] + 60
    });
    assert!(
        blue_on_rim,
        "no blue curve near the right end of the outline"
    );
}

#[test]
fn right_drag_orbits_without_drawing() {
    let mut h = harness();
    h.run();
    let yaw_before = h.state().shared().borrow().camera.yaw;
    drag(
        &mut h,
        pos2(300.0, 300.0),
        pos2(500.0, 300.0),
        PointerButton::Secondary,
    );
    let yaw_after = h.state().shared().borrow().camera.yaw;
    assert!(
        (yaw_after - yaw_before).abs() > 0.5,
        "yaw {yaw_before} -> {yaw_after}"
    );
    assert_eq!(curves(&h), 0);
}

#[test]
fn a_shape_created_and_pulled_in_the_app_is_its_session_replayed() {
    let mut h = harness();
    h.run();
    let center = pos2(450.0, 340.0);
    draw_ellipse(&mut h, center);
    let ops = |h: &Harness<'_, SketchApp>| h.state().shared().borrow().editor.ops().len();
    assert_eq!(ops(&h), 1, "one create op");
    assert!(
        replays_bit_for_bit(&h),
        "the creation refined over frames differs from apply"
    );
    let before = h.render().expect("render");

    // Pull the outline's right end outwards: the shape follows while the pointer is down,
    // and nothing is committed until it is released.
    h.key_press(egui::Key::P);
    h.run();
    let held = drag_right_end(&mut h, center);
    let dragging = h.render().expect("render");
    save(&dragging, "pull-preview");
    assert_eq!(ops(&h), 1, "nothing committed while dragging");
    let moved = changed_pixels(&before, &dragging);
    assert!(moved > 200, "the preview moved only {moved} pixels");
    press(&h, held, PointerButton::Primary, false);
    h.run();
    let shared = h.state().shared();
    let last = shared.borrow().editor.ops().last().map(|op| op.name());
    assert_eq!((ops(&h), last), (2, Some("pull")));
    assert!(
        replays_bit_for_bit(&h),
        "the pull committed in the app differs from apply"
    );
}

#[test]
fn an_oversketch_stroke_shows_its_outline_piece_then_commits_what_replay_gives() {
    let mut h = harness();
    h.run();
    let center = pos2(450.0, 340.0);
    draw_ellipse(&mut h, center);
    h.key_press(egui::Key::O);
    h.run();
    // Beside the right end of the outline, 15% out, from -30° to +30°.
    let at = |k: usize| {
        let a = (-30.0 + 60.0 * k as f32 / 30.0).to_radians();
        center + vec2(172.0 * a.cos(), 126.0 * a.sin())
    };
    h.event(Event::PointerMoved(at(0)));
    press(&h, at(0), PointerButton::Primary, true);
    h.step();
    for k in 1..30 {
        h.event(Event::PointerMoved(at(k)));
        h.step();
    }
    let drawing = h.render().expect("render");
    save(&drawing, "oversketch-preview");
    let green = drawing
        .pixels()
        .filter(|p| p.0[1] > 200 && p.0[0] < 130 && p.0[2] < 160)
        .count();
    assert!(green > 100, "no outline piece shown green ({green} pixels)");
    press(&h, at(30), PointerButton::Primary, false);
    h.run();
    let shared = h.state().shared();
    let names: Vec<&str> = shared
        .borrow()
        .editor
        .ops()
        .iter()
        .map(|op| op.name())
        .collect();
    assert_eq!(names, ["create", "oversketch"]);
    assert!(
        replays_bit_for_bit(&h),
        "the over-sketch committed in the app differs from apply"
    );
}

#[test]
fn a_ridge_sketched_and_dragged_in_the_app_is_its_session_replayed() {
    let mut h = harness();
    h.run();
    let center = pos2(450.0, 340.0);
    draw_ellipse(&mut h, center);
    h.key_press(egui::Key::D);
    h.run();
    // The sketch, across the middle of the shape: nothing changes yet.
    let before = h.render().expect("render");
    h.event(Event::PointerMoved(center - vec2(90.0, 0.0)));
    press(&h, center - vec2(90.0, 0.0), PointerButton::Primary, true);
    h.step();
    for i in 1..=30 {
        h.event(Event::PointerMoved(
            center + vec2(-90.0 + 6.0 * i as f32, 0.0),
        ));
        h.step();
    }
    press(&h, center + vec2(90.0, 0.0), PointerButton::Primary, false);
    h.run();
    let ops = |h: &Harness<'_, SketchApp>| h.state().shared().borrow().editor.ops().len();
    assert_eq!(ops(&h), 1, "a sketch alone commits nothing");
    // The drag upwards raises the ridge while the pointer is down.
    let grab = center + vec2(0.0, 80.0);
    h.event(Event::PointerMoved(grab));
    press(&h, grab, PointerButton::Primary, true);
    h.step();
    for i in 1..=10 {
        h.event(Event::PointerMoved(grab - vec2(0.0, 9.0 * i as f32)));
        h.step();
    }
    let dragging = h.render().expect("render");
    save(&dragging, "feature-ridge-preview");
    assert_eq!(ops(&h), 1, "nothing committed while dragging");
    let moved = changed_pixels(&before, &dragging);
    assert!(moved > 200, "the ridge preview changed only {moved} pixels");
    press(&h, grab - vec2(0.0, 90.0), PointerButton::Primary, false);
    h.run();
    let shared = h.state().shared();
    let last = shared.borrow().editor.ops().last().cloned();
    let Some(sketchmesh_core::document::Op::SketchFeature(input)) = last else {
        panic!("the last op is {last:?}");
    };
    assert_eq!(input.amount, Some(7.0), "a 90 px drag up is a factor of 7");
    assert!(
        replays_bit_for_bit(&h),
        "the feature committed in the app differs from apply"
    );
}

/// Another editor at the same revision (a session opened, a restore, the page's `replay`) is
/// another document: the view shows it. The editor's revision alone did not tell them apart,
/// and the view kept showing the old one.
#[test]
fn an_opened_session_at_the_same_revision_is_shown() {
    let mut h = harness();
    h.run();
    drag(
        &mut h,
        pos2(250.0, 300.0),
        pos2(650.0, 320.0),
        PointerButton::Primary,
    );
    let first = h.render().expect("render");
    let session = h.state().shared().borrow().editor.session_json();
    let moved = session.replace("[250", "[150").replace("[650", "[750");
    assert_ne!(moved, session, "the session names the stroke's ends");
    let other = sketchmesh_core::document::Editor::replay_json(&moved).expect("replays");
    assert_eq!(
        other.revision(),
        h.state().shared().borrow().editor.revision()
    );
    h.state().shared().borrow_mut().open(other);
    h.run();
    let opened = h.render().expect("render");
    let changed = changed_pixels(&first, &opened);
    assert!(
        changed > 500,
        "the opened document is not shown ({changed} pixels changed)"
    );
}

#[test]
fn a_region_shows_its_falloff_as_gray_levels_equal_to_the_weights() {
    let mut h = harness();
    h.run();
    draw_ellipse(&mut h, pos2(450.0, 340.0));
    // No grid: its axis lines cross the model's front.
    h.key_press(egui::Key::G);
    h.key_press(egui::Key::L);
    h.run();
    // The region tool's rows move the view: find the model's middle and right edge on
    // screen as it is now.
    let (center, right) = {
        let app = h.state();
        let (_, view) = app.edit_in_view();
        let shared = app.shared();
        let shared = shared.borrow();
        let camera = shared.camera.camera();
        let mesh = &shared.editor.document().models[0].mesh;
        let size = glam::DVec2::new(view.width().into(), view.height().into());
        let seen: Vec<glam::DVec2> = mesh
            .positions()
            .iter()
            .filter_map(|&p| camera.screen_from_world(p, size).map(|s| s.truncate()))
            .collect();
        let (lo, hi) = seen.iter().fold(
            (
                glam::DVec2::splat(f64::INFINITY),
                glam::DVec2::splat(f64::NEG_INFINITY),
            ),
            |(lo, hi), &p| (lo.min(p), hi.max(p)),
        );
        let middle = 0.5 * (lo + hi);
        (
            view.min + vec2(middle.x as f32, middle.y as f32),
            view.min.x + hi.x as f32,
        )
    };
    let half_width = right - center.x;
    let (a, b) = (
        center - vec2(0.5 * half_width, 0.0),
        center + vec2(0.5 * half_width, 0.0),
    );
    trace(
        &mut h,
        (0..=30).map(|i| a + (b - a) * (i as f32 / 30.0)).collect(),
    );
    h.run();
    // The loop opens the edit, which keeps the app drawing: steps, not a settled run.
    let boundary = ellipse(center, vec2(0.85 * half_width, 0.55 * half_width));
    trace(&mut h, boundary.clone());
    h.run_steps(8);
    // The two curves are drawn over the model: pixels near them are not the fall-off's.
    let as_dvec = |p: &Pos2| glam::DVec2::new(p.x.into(), p.y.into());
    let drawn = [
        boundary.iter().map(as_dvec).collect::<Vec<_>>(),
        vec![as_dvec(&a), as_dvec(&b)],
    ];
    let near_curves = |p: glam::DVec2| {
        drawn
            .iter()
            .any(|c| sketchmesh_core::curve::polyline::distance_to_polyline(p, c) < 7.0)
    };
    let image = h.render().expect("render");
    save(&image, "region-falloff");
    let app = h.state();
    let (Some(edit), view) = app.edit_in_view() else {
        panic!("the loop opens the region edit, unmoved")
    };
    let (model, vertices, weights) = edit.region_falloff().expect("the region is found");
    let shared = app.shared();
    let shared = shared.borrow();
    let camera = shared.camera.camera();
    let mesh = &edit.document().models[model].mesh;
    let size = glam::DVec2::new(view.width().into(), view.height().into());
    // Inside a triangle whose corners all fall on one level, every weight the pixels
    // interpolate rounds to that level too: the pixel at its centre is that level's gray.
    let steps = 4.0;
    let level = |w: f64| (w * steps).round() / steps;
    let by_vertex: std::collections::HashMap<_, _> = vertices
        .iter()
        .copied()
        .zip(weights.iter().copied())
        .collect();
    let (mut checked, mut levels_seen) = (0, std::collections::BTreeSet::new());
    for f in mesh.faces() {
        let corners = mesh.face_vertices(f);
        let Some(ws) = corners
            .iter()
            .map(|v| by_vertex.get(v).copied())
            .collect::<Option<Vec<f64>>>()
        else {
            continue;
        };
        if ws.iter().any(|&w| level(w) != level(ws[0])) {
            continue;
        }
        let Some(seen) = corners
            .iter()
            .map(|&v| camera.screen_from_world(mesh.position(v), size))
            .collect::<Option<Vec<_>>>()
        else {
            continue;
        };
        let [a, b, c] = [seen[0], seen[1], seen[2]].map(|p| p.truncate());
        if (b - a).perp_dot(c - a).abs() < 40.0 {
            continue;
        }
        let at = (a + b + c) / 3.0;
        let (x, y) = (view.min.x + at.x as f32, view.min.y + at.y as f32);
        if near_curves(glam::DVec2::new(x.into(), y.into())) {
            continue;
        }
        let p = image.get_pixel(x.round() as u32, y.round() as u32).0;
        let expected = falloff_gray(level(ws[0]));
        assert!(
            p[..3].iter().all(|&c| c.abs_diff(expected) <= 2),
            "weights {ws:?} (level {}) drawn {p:?} at ({x}, {y}), expected gray {expected}",
            level(ws[0])
        );
        checked += 1;
        levels_seen.insert((level(ws[0]) * steps) as u32);
    }
    // (The curves embedded in the mesh split the triangles they cross into smaller ones,
    // which the 40 px² filter passes over: about 100 remain.)
    assert!(
        checked > 80,
        "only {checked} triangles checked of a region of {} vertices",
        vertices.len()
    );
    // Levels 0 and 4 meet the two curves, whose strokes cover them in part.
    assert!(levels_seen.len() >= 3, "levels shown: {levels_seen:?}");
    // The panel in the view's lower left corner shows the region flat, in the same grays.
    let panel = panel_rect(view);
    let mut grays = std::collections::BTreeSet::new();
    for y in (panel.top() as u32..panel.bottom() as u32).step_by(2) {
        for x in (panel.left() as u32..panel.right() as u32).step_by(2) {
            let p = image.get_pixel(x, y).0;
            if let Some(k) = (0..=4).find(|&k| {
                p[..3]
                    .iter()
                    .all(|&c| c == falloff_gray(f64::from(k) / steps))
            }) {
                grays.insert(k);
            }
        }
    }
    assert!(grays.len() >= 3, "the panel's levels: {grays:?}");
    // Between the loop and the outline, the model keeps its lit clay colour.
    let (from, to) = ((0.86 * half_width) as u32, (0.99 * half_width) as u32);
    let clay: Vec<_> = (from..to)
        .map(|dx| image.get_pixel(center.x as u32 + dx, center.y as u32).0)
        .collect();
    let warm = |p: &[u8; 4]| i32::from(p[0]) - i32::from(p[2]) > 10 && p[0] > 120;
    assert!(clay.iter().any(warm), "outside the region: {clay:?}");
}

/// Blanco's handles in the app: a stroke across a shape makes a handle (drawn as a curve
/// with dots), a drag on its last dot bends the shape while the pointer is down, and the
/// release commits what replaying the session gives.
#[test]
fn a_curve_handle_drawn_and_dragged_in_the_app_is_its_session_replayed() {
    let mut h = harness();
    h.run();
    let center = pos2(450.0, 340.0);
    draw_ellipse(&mut h, center);
    h.key_press(egui::Key::J);
    h.run();
    let bare = h.render().expect("render");
    let (from, to) = (center - vec2(120.0, 0.0), center + vec2(120.0, 0.0));
    trace(
        &mut h,
        (0..=40)
            .map(|i| from + (to - from) * (i as f32 / 40.0))
            .collect(),
    );
    h.run();
    let handles =
        |h: &Harness<'_, SketchApp>| h.state().shared().borrow().editor.document().handles.len();
    assert_eq!(handles(&h), 1, "the stroke made no handle");
    let with_handle = h.render().expect("render");
    assert!(
        changed_pixels(&bare, &with_handle) > 300,
        "the handle is not drawn"
    );
    // Grab the last dot (the stroke's end) and drag it up.
    h.event(Event::PointerMoved(to));
    press(&h, to, PointerButton::Primary, true);
    h.step();
    for i in 1..=10 {
        h.event(Event::PointerMoved(to - vec2(0.0, 8.0 * i as f32)));
        h.step();
    }
    let dragging = h.render().expect("render");
    save(&dragging, "curve-handle-drag");
    let ops = |h: &Harness<'_, SketchApp>| h.state().shared().borrow().editor.ops().len();
    assert_eq!(ops(&h), 2, "nothing committed while dragging");
    assert!(
        changed_pixels(&with_handle, &dragging) > 500,
        "the drag's preview did not bend the shape"
    );
    press(&h, to - vec2(0.0, 80.0), PointerButton::Primary, false);
    h.run();
    let last = h.state().shared().borrow().editor.ops().last().cloned();
    let Some(sketchmesh_core::document::Op::HandleEdit(input)) = last else {
        panic!("the last op is {last:?}");
    };
    assert!(input.translate.is_some_and(|t| t[1] > 0.0), "{input:?}");
    assert!(
        replays_bit_for_bit(&h),
        "the handle edit committed in the app differs from apply"
    );
}

/// An imported model is drawn in its material's colour (Khronos' BoxInterleaved: a base
/// colour factor of dark red), and as clay once **Clay** is on.
#[test]
fn an_imported_model_shows_its_base_colour_and_clay_on_request() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/testdata/gltf/real/BoxInterleaved.glb");
    let bytes = std::fs::read(&path).unwrap_or_else(|e| {
        panic!(
            "TEST DATA MISSING: {} ({e}); the app's colour test needs ../shared/testdata",
            path.display()
        )
    });
    let mut editor = sketchmesh_core::document::Editor::new();
    let import = sketchmesh_core::document::ImportInput {
        files: vec![sketchmesh_core::document::FileInput {
            name: "BoxInterleaved.glb".to_owned(),
            data: Some(std::sync::Arc::new(bytes)),
        }],
        beside: false,
    };
    editor
        .apply(sketchmesh_core::document::Op::Import(import))
        .expect("imports");
    let mut h = harness();
    h.run();
    h.state().shared().borrow_mut().open(editor);
    h.key_press(egui::Key::G);
    h.key_press(egui::Key::F);
    h.run();
    let centre = h.state().edit_in_view().1.center();
    let pixel = |image: &image::RgbaImage| {
        let ppp = image.width() as f32 / 900.0;
        *image.get_pixel((centre.x * ppp) as u32, (centre.y * ppp) as u32)
    };
    let coloured = h.render().expect("render");
    save(&coloured, "imported-colour");
    let [r, g, b, _] = pixel(&coloured).0;
    assert!(
        r > 90 && u32::from(g) * 3 < u32::from(r) && u32::from(b) * 3 < u32::from(r),
        "the box is not red: {:?}",
        [r, g, b]
    );
    // The view switches sit in the View menu.
    h.get_by_label("View").click();
    h.run();
    h.get_by_label("Clay").click();
    h.run();
    let clay = h.render().expect("render");
    let [r, g, b, _] = pixel(&clay).0;
    assert!(
        g > 60 && u32::from(r) < u32::from(g) * 3 / 2,
        "clay is not clay: {:?}",
        [r, g, b]
    );
}

/// Issue 17: with a finger as the pointer, on a phone (390×844) and an upright tablet
/// (820×1180) the toolbar is docked at the bottom, on a tablet on its side (1180×820) at the
/// top, and every target in it, in every tool's options too, measures at least 44 points
/// (CSS px) each way, as egui laid it out; the 3D view keeps at least 80% of the phone's
/// screen.
#[test]
fn the_touch_layout_gives_every_toolbar_target_44_points() {
    use egui::accesskit::Role;
    use sketchmesh_app::tools::Mode;
    let interactive = [
        Role::Button,
        Role::CheckBox,
        Role::ComboBox,
        Role::Slider,
        Role::SpinButton,
        Role::RadioButton,
        Role::TextInput,
    ];
    for (name, size) in [
        ("phone", vec2(390.0, 844.0)),
        ("tablet", vec2(820.0, 1180.0)),
        ("tablet on its side", vec2(1180.0, 820.0)),
    ] {
        let mut h = touch_harness(size);
        h.run();
        let view = h.state().edit_in_view().1;
        let upright = size.y > size.x;
        assert!(
            !upright || view.min.y < 1.0,
            "{name}: the view starts at the top, the tools in reach of a thumb: {view:?}"
        );
        if name == "phone" {
            let share = view.area() / (size.x * size.y);
            assert!(
                share >= 0.8,
                "{name}: the view covers {share} of the screen"
            );
        }
        let mut checked = 0;
        for mode in Mode::ALL {
            h.key_press(mode.key());
            h.run();
            let view = h.state().edit_in_view().1;
            for node in h.query_all_by(|node| interactive.contains(&node.role())) {
                let rect = node.rect();
                if rect.min.y < view.max.y - 1.0 && rect.max.y > view.min.y + 1.0 {
                    continue; // Over the view, not in the toolbar.
                }
                checked += 1;
                assert!(
                    rect.width() >= 44.0 - 0.5 && rect.height() >= 44.0 - 0.5,
                    "{name}, {mode:?}: {node:?} measures {} × {}",
                    rect.width(),
                    rect.height()
                );
            }
        }
        assert!(checked > 100, "{name}: only {checked} targets found");
    }
}

/// Issue 17: on a phone the tools that do not fit beside the ☰ menu, Undo and Redo sit
/// behind ⋯ (the row no longer scrolls them out of sight); each one picked there becomes the
/// tool in use, the menu closes, and the tool takes a place in the row, within the screen.
#[test]
fn on_a_phone_the_tools_that_do_not_fit_are_behind_more() {
    use sketchmesh_app::tools::Mode;
    let mut h = touch_harness(vec2(390.0, 844.0));
    h.run();
    // The row shows the tools' icons (their buttons named by the tools' names), the menu
    // their icons and names.
    let in_row: Vec<Mode> = (Mode::ALL.into_iter())
        .filter(|&m| h.query_by_label(m.label()).is_some())
        .collect();
    assert!(
        in_row.len() >= 3 && in_row.len() < Mode::ALL.len(),
        "in the row: {in_row:?}"
    );
    for mode in Mode::ALL.into_iter().filter(|m| !in_row.contains(m)) {
        // The tools row's ⋯, the lowest (a tool's options may have one of their own).
        let more = (h.query_all_by_label("⋯"))
            .max_by(|a, b| a.rect().min.y.total_cmp(&b.rect().min.y))
            .expect("a More button");
        more.click();
        h.run();
        h.get_by_label(mode.label()).click();
        h.run();
        assert_eq!(h.state().mode(), mode, "picked from the menu");
        let button = h.get_by_label(mode.label()).rect();
        assert!(
            button.min.x >= 0.0 && button.max.x <= 390.5 && button.min.y > 844.0 - 100.0,
            "{mode:?} in the row at the bottom, within the screen: {button:?}"
        );
    }
}

/// Issue 17: a session replayed through the page API's path runs over frames behind a
/// progress line; its Cancel (a touch-sized button on a phone's screen) stops it and
/// leaves the document as it was, telling whoever waits; a shape drawn while it runs is not
/// made (it would be lost under the replayed document); replayed to the end, the document is
/// the session's.
#[test]
fn a_replay_runs_over_frames_and_its_cancel_changes_nothing() {
    use sketchmesh_app::files::{Incoming, Reply};
    use std::cell::RefCell;
    use std::rc::Rc;
    let mut source = sketchmesh_core::document::Editor::new();
    // Enough work that it takes many frames of the app's 12 ms budget.
    for k in 0..24 {
        let centre = pos2(
            120.0 + 130.0 * (k % 6) as f32,
            120.0 + 110.0 * (k / 6) as f32,
        );
        let stroke = ellipse(centre, vec2(50.0, 40.0))
            .iter()
            .map(|p| [f64::from(p.x), f64::from(p.y), 0.5])
            .collect();
        let op = sketchmesh_core::document::Op::Create(
            sketchmesh_core::document::StrokeInput {
                viewport: [900.0, 600.0],
                camera: sketchmesh_core::camera::Camera::default(),
                stroke,
            }
            .into(),
        );
        source.apply(op).expect("creates");
    }
    let session = source.session_json();
    let heard: Rc<RefCell<Vec<Result<(), String>>>> = Rc::default();
    let replay = |h: &Harness<'_, SketchApp>| {
        let heard = heard.clone();
        let reply = Reply::to(move |landed| heard.borrow_mut().push(landed));
        let shared = h.state().shared();
        let imports = shared.borrow().imports.clone();
        imports
            .borrow_mut()
            .push_back(Incoming::Replay(session.clone(), reply));
    };
    let mut h = touch_harness(vec2(390.0, 844.0));
    h.run();
    replay(&h);
    let mut frames = 0;
    while h.query_by_label("Cancel").is_none() && frames < 20 {
        h.step();
        frames += 1;
    }
    let progress = h.state().shared().borrow().progress.clone();
    assert!(
        progress.is_some_and(|p| p.starts_with("Replaying the session")),
        "a progress line while it runs"
    );
    let cancel = h.get_by_label("Cancel").rect();
    let screen = egui::Rect::from_min_size(Pos2::ZERO, vec2(390.0, 844.0));
    assert!(
        cancel.width() >= 44.0 && cancel.height() >= 44.0 && screen.contains_rect(cancel),
        "a touch-sized Cancel on the phone's screen: {cancel:?}"
    );
    save(&h.render().expect("render"), "replay-progress-phone");
    h.get_by_label("Cancel").click();
    h.run();
    assert_eq!(
        *heard.borrow(),
        [Err(String::from("The replay was cancelled."))]
    );
    assert!(
        h.state().shared().borrow().editor.ops().is_empty(),
        "nothing changed"
    );

    replay(&h);
    h.step();
    h.step();
    assert!(h.state().shared().borrow().progress.is_some(), "replaying");
    // A shape drawn meanwhile would be lost under the replayed document: it is not made.
    trace(
        &mut h,
        ellipse(pos2(195.0, 300.0), vec2(90.0, 70.0))
            .into_iter()
            .step_by(10)
            .collect(),
    );
    for _ in 0..200 {
        h.step();
        if heard.borrow().len() == 2 {
            break;
        }
        let shared = h.state().shared();
        assert!(
            shared.borrow().editor.ops().is_empty(),
            "nothing made meanwhile"
        );
    }
    assert_eq!(heard.borrow()[1], Ok(()));
    let shared = h.state().shared();
    assert_eq!(shared.borrow().editor.document(), source.document());
    assert_eq!(shared.borrow().editor.ops(), source.ops());
    assert_eq!(shared.borrow().progress, None);

    // A replay the page starts the moment the last one's Promise resolves is not taken for
    // one of the old document, and cancelled (the page bench's merge met this).
    let imports = shared.borrow().imports.clone();
    let (again, heard_again) = (session.clone(), heard.clone());
    let reply = Reply::to(move |landed| {
        heard_again.borrow_mut().push(landed);
        let heard = heard_again.clone();
        let reply = Reply::to(move |landed| heard.borrow_mut().push(landed));
        imports
            .borrow_mut()
            .push_back(Incoming::Replay(again.clone(), reply));
    });
    let imports = shared.borrow().imports.clone();
    imports
        .borrow_mut()
        .push_back(Incoming::Replay(session.clone(), reply));
    for _ in 0..400 {
        h.step();
        if heard.borrow().len() == 4 {
            break;
        }
    }
    assert_eq!(heard.borrow()[2..], [Ok(()), Ok(())]);
    assert_eq!(shared.borrow().editor.ops(), source.ops());
}

/// The app with Symmetry on, an ellipse drawn across the plane (the view's middle, returned)
/// and the tool of `key` picked.
fn symmetric_shape_with(key: egui::Key) -> (Harness<'static, SketchApp>, Pos2) {
    let mut h = harness();
    h.run();
    h.state().shared().borrow_mut().symmetry.choose(true);
    let center = pos2(450.0, 340.0);
    draw_ellipse(&mut h, center);
    h.key_press(key);
    h.run();
    (h, center)
}

/// Grabs the outline's right end (150 px right of `center`) and drags it 40 px further out,
/// a frame per 4 px, the pointer still down there (returned).
fn drag_right_end(h: &mut Harness<'_, SketchApp>, center: Pos2) -> Pos2 {
    let grab = center + vec2(150.0, 0.0);
    h.event(Event::PointerMoved(grab));
    press(h, grab, PointerButton::Primary, true);
    h.step();
    for i in 1..=10 {
        h.event(Event::PointerMoved(grab + vec2(4.0 * i as f32, 0.0)));
        h.step();
    }
    grab + vec2(40.0, 0.0)
}

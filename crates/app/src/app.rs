//! The eframe app: wires input, the tools, the edit runner and the 3D view together.
//!
//! Data flows one way: pointer samples go through the [`InputRouter`] to the tool in use
//! ([`ToolSet`]) or the camera; what a tool makes goes to the [`EditRunner`], which runs it
//! as an edit of the document; the [`SceneView`] draws the document shown, and
//! [`view_overlay`] what the tool and the edit show over it. The toolbar and the keys ask
//! for [`Command`]s; [`FileActions`] opens and saves files. Nothing here names an op; the
//! only tools named are Erase (the pen's eraser end) and Over-sketch (the context menu).

use std::cell::RefCell;
use std::rc::Rc;

use eframe::egui_wgpu;
use sketchmesh_core::document::{Document, Edit};

#[cfg(target_arch = "wasm32")]
use crate::autosave_writer::AutosaveWriter;
use crate::backdrop::Backdrop;
use crate::camera::OrbitCamera;
use crate::clock;
use crate::command::Command;
use crate::edit_runner::{Cx, EditRunner};
use crate::file_actions::FileActions;
use crate::input::router::{Hands, Routed};
use crate::input::sample_clock;
use crate::input::taps::TapCommand;
use crate::making;
use crate::panels;
use crate::panels::PanelState;
use crate::panels::context_menu::{ContextAction, ContextMenu, context_menu_ui};
use crate::playback::Playback;
use crate::pointer::Pointer;
use crate::render::SceneRenderer;
use crate::scene_view::{SceneView, model_at};
pub use crate::shared::Shared;
use crate::shortcuts;
use crate::status::{Status, Tone, status_ui};
use crate::tools::{Device, Mode, ToolEvent, ToolOutput, ToolSet, ViewCtx};
use crate::view_overlay;

/// The Sketchmesh app.
pub struct SketchApp {
    shared: Rc<RefCell<Shared>>,
    /// The pointer samples and where they go.
    pub(crate) pointer: Pointer,
    /// The panels' state between frames.
    panels: PanelState,
    /// The tools and the active mode.
    tools: ToolSet,
    /// The reference image over the view, to trace a motion's frames.
    backdrop: Backdrop,
    /// Writes the autosave in the page.
    #[cfg(target_arch = "wasm32")]
    autosave: AutosaveWriter,
    /// The 3D scene as drawn.
    scene: SceneView,
    /// The status line.
    status: Status,
    /// The edit in progress and the work around it.
    runner: EditRunner,
    has_renderer: bool,
    /// The files the user opens and saves.
    files: FileActions,
    /// How a document was made, being played (an example's session).
    making: making::Player,
    /// The document the tools work on (see [`crate::autosave::Revision::opened`]): when the page
    /// replaces it, the edit in progress belongs to the old one and is dropped.
    opened: u64,
    /// The 3D view's rectangle last frame, in points (thumbnails are cut to it).
    view_rect: egui::Rect,
    /// Whether the screen's main pointer is a finger (the page's `(pointer: coarse)`): the
    /// toolbar then takes the touch layout where it is narrow enough.
    coarse_pointer: bool,
}

impl SketchApp {
    /// Creates the app and installs the 3D renderer when wgpu is available.
    pub fn new(cc: &eframe::CreationContext<'_>) -> Self {
        let backend = cc
            .wgpu_render_state
            .as_ref()
            .map_or_else(|| "none".to_owned(), backend_name);
        if let Some(rs) = cc.wgpu_render_state.as_ref() {
            SceneRenderer::install(rs);
        }
        // The 3D view is dark; a light toolbar beside it would glare.
        cc.egui_ctx.set_theme(egui::Theme::Dark);
        cc.egui_ctx.set_fonts(crate::fonts::definitions());
        let mut app = Self::with_backend(backend, cc.wgpu_render_state.is_some());
        app.runner = EditRunner::new(&cc.egui_ctx);
        app
    }

    /// Creates the app without graphics, for tests that drive input and tools.
    pub fn with_backend(backend: String, has_renderer: bool) -> Self {
        Self {
            shared: Rc::new(RefCell::new(Shared::new(backend))),
            pointer: Pointer::default(),
            panels: PanelState::default(),
            tools: ToolSet::default(),
            // Nothing built yet: no document has this revision.
            backdrop: Backdrop::default(),
            #[cfg(target_arch = "wasm32")]
            autosave: AutosaveWriter::default(),
            scene: SceneView::default(),
            status: Status::default(),
            runner: EditRunner::default(),
            has_renderer,
            files: FileActions::default(),
            making: making::Player::default(),
            opened: 0,
            view_rect: egui::Rect::NOTHING,
            coarse_pointer: false,
        }
    }

    /// Shows the first visit's introduction unless it was `seen` (the page's store keeps it).
    pub fn start_intro(&mut self, seen: bool) {
        self.panels.intro = panels::intro::Intro::new(seen);
    }

    /// Says whether the screen's main pointer is a finger (see [`panels::toolbar::Layout`]).
    pub fn set_coarse_pointer(&mut self, coarse: bool) {
        self.coarse_pointer = coarse;
    }

    /// The tool in use.
    pub fn mode(&self) -> Mode {
        self.tools.mode()
    }

    /// The edit in progress, if any, and the 3D view's rectangle last frame in points: what
    /// a headless test reads the shown preview from.
    pub fn edit_in_view(&self) -> (Option<&Edit>, egui::Rect) {
        (self.runner.edit(), self.view_rect)
    }

    /// The state the page API shares.
    pub fn shared(&self) -> Rc<RefCell<Shared>> {
        self.shared.clone()
    }

    /// Undo: drops a gesture in progress (a drag, an open preview) if there is one, else
    /// undoes the last op.
    fn undo(&mut self, now: f64) {
        if self.making.is_playing() {
            // The example's next op would apply to the wrong document; Esc stops it.
        } else if self.runner.edit().is_some_and(Edit::is_gesture) {
            self.drop_gesture(now);
        } else if self.runner.is_busy() || self.runner.is_computing() {
            // Undoing an import, a replay or an op still running is not making it.
            self.run(now, |r, cx| r.cancel_offloaded(cx));
            self.run(now, |r, cx| r.cancel_replay(cx));
        } else {
            self.run(now, |r, cx| r.undo(cx));
        }
    }

    /// Drops the gesture in progress and the tool's part of it: nothing changes.
    fn drop_gesture(&mut self, now: f64) {
        self.runner.cancel_gesture();
        let dropped = self.tools.cancel();
        self.take_output(dropped, now);
    }

    /// Switches the tool mode (toolbar, keys); a gesture in progress is dropped.
    fn set_mode(&mut self, mode: Mode, now: f64) {
        if mode != self.tools.mode() {
            self.runner.cancel_gesture();
        }
        let dropped = self.tools.set_mode(mode);
        self.shared.borrow_mut().mode = mode;
        self.take_output(dropped, now);
    }

    /// Follows what the page changed from outside: another document (the edit in progress
    /// and the tool's gesture were the old one's, and go), the tool a restore chose, a
    /// sentence.
    fn follow_page(&mut self, now: f64) {
        let (opened, mode, notice) = {
            let mut shared = self.shared.borrow_mut();
            (shared.revision().opened, shared.mode, shared.notice.take())
        };
        if opened != self.opened {
            self.opened = opened;
            self.making.drop_for_another(&self.shared);
            self.run(now, |r, cx| r.drop_all(cx));
            let dropped = self.tools.cancel();
            self.take_output(dropped, now);
        }
        if mode != self.tools.mode() {
            self.set_mode(mode, now);
        }
        if let Some(notice) = notice {
            self.status.say(Tone::Info, notice, now);
        }
    }

    fn refuse(&mut self, message: String, now: f64) {
        self.status.refuse(message, now);
    }

    /// The file actions and the edit runner, and what they work with.
    fn parts(&mut self, now: f64) -> (&mut FileActions, &mut EditRunner, Cx<'_>) {
        let cx = Cx {
            shared: &self.shared,
            tools: &mut self.tools,
            status: &mut self.status,
            frame_all: &mut self.scene.frame_after_rebuild,
            now,
        };
        (&mut self.files, &mut self.runner, cx)
    }

    /// Runs `f` on the edit runner, lending it what it works with.
    fn run<R>(&mut self, now: f64, f: impl FnOnce(&mut EditRunner, &mut Cx<'_>) -> R) -> R {
        let (_, runner, mut cx) = self.parts(now);
        f(runner, &mut cx)
    }

    /// Applies what a tool produced: to the edit, or to the view, the backdrop, playing.
    fn take_output(&mut self, output: ToolOutput, now: f64) {
        match self.run(now, |r, cx| r.take_output(output, cx)) {
            Some(ToolOutput::Face { point, normal }) => {
                self.shared.borrow_mut().camera.face(point, normal);
            }
            Some(ToolOutput::Backdrop(load)) => {
                if !load {
                    self.backdrop.remove();
                } else if let Err(message) = self.backdrop.pick() {
                    self.refuse(message, now);
                }
            }
            Some(ToolOutput::Play(true)) => {
                let played =
                    Playback::start(self.shared.borrow().editor.document(), clock::now_ms());
                match played {
                    Ok(playback) => self.scene.playback = Some(playback),
                    Err(message) => self.refuse(message, now),
                }
            }
            Some(ToolOutput::Play(false)) => self.scene.stop_playing(),
            _ => {}
        }
    }

    /// Does what the user asked for from the toolbar or the keyboard.
    fn command(&mut self, command: Command, ctx: &egui::Context, now: f64) {
        match command {
            Command::Undo => self.undo(now),
            Command::Redo => self.run(now, |r, cx| r.redo(cx)),
            Command::FrameAll => self.scene.frame_all(&self.shared),
            Command::ResetView => self.shared.borrow_mut().camera = OrbitCamera::default(),
            Command::NewDocument | Command::Documents => {
                let method = match command {
                    Command::NewDocument => "newDocument",
                    _ => "show",
                };
                let (files, runner, mut cx) = self.parts(now);
                files.page_documents(method, runner, &mut cx);
            }
            Command::Import => {
                let (files, _, mut cx) = self.parts(now);
                files.import_files(ctx, &mut cx);
            }
            Command::Export => {
                let (files, runner, mut cx) = self.parts(now);
                files.export(runner, &mut cx);
            }
            Command::SaveSession => {
                let (files, runner, mut cx) = self.parts(now);
                files.save_session(runner, &mut cx);
            }
            Command::Mode(mode) => self.set_mode(mode, now),
            Command::Tool(output) => self.take_output(*output, now),
            // Esc closes an open menu first, and only that.
            Command::Stop if egui::Popup::is_any_open(ctx) => egui::Popup::close_all(ctx),
            Command::Stop => {
                self.scene.stop_playing();
                let stopped = Some(String::from("Stopped playing the example."));
                if let Some(said) = self.making.end(stopped, &self.shared) {
                    self.status.say(Tone::Info, said, now);
                }
                self.run(now, |r, cx| r.cancel_offloaded(cx));
                self.run(now, |r, cx| r.cancel_replay(cx));
                self.drop_gesture(now);
            }
            Command::ToolKey(mode, key) => {
                self.set_mode(mode, now);
                let output = self
                    .tools
                    .on_key(key, self.shared.borrow().editor.document());
                self.take_output(output, now);
            }
            Command::ToggleWireframe => self.scene.options.wireframe ^= true,
            Command::ToggleGrid => self.scene.options.grid ^= true,
            Command::ToggleSymmetry => {
                let on = !self.shared.borrow().symmetry.is_on;
                let said = self.shared.borrow_mut().choose_symmetry(on);
                self.status.say(Tone::Info, said.to_owned(), now);
            }
            Command::ToggleHelp => self.panels.show_help ^= true,
        }
    }

    /// What the active tool makes of an input (`feed`), in the current view of the document.
    fn feed_tool(
        &mut self,
        viewport: egui::Rect,
        feed: impl FnOnce(&mut ToolSet, &ViewCtx, &Document) -> ToolOutput,
    ) -> ToolOutput {
        let view = ViewCtx {
            camera: self.shared.borrow().camera.camera(),
            viewport,
        };
        let shared = self.shared.borrow();
        feed(&mut self.tools, &view, shared.editor.document())
    }

    /// Two fingers for the tool: offered when they come down (the tool takes them by
    /// beginning a gesture, and the router then sends their moves to it), then followed.
    fn handle_hands(&mut self, hands: &Hands, viewport: egui::Rect, now: f64) {
        if matches!(hands, Hands::Down(_)) {
            self.runner.cancel_gesture();
            self.run(now, |r, cx| r.finish_edit_unless_offloaded(cx));
        }
        let output = self.feed_tool(viewport, |tools, view, doc| {
            tools.on_hands(hands, view, doc)
        });
        if matches!(hands, Hands::Down(_)) && matches!(output, ToolOutput::Begin(_)) {
            self.pointer.router.give_hands_to_tool();
        }
        self.take_output(output, now);
    }

    /// Routes this frame's pointer samples to the tool and the camera.
    fn handle_pointer(&mut self, ctx: &egui::Context, viewport: egui::Rect) {
        let now = ctx.input(|i| i.time);
        let mut routed = Vec::new();
        let samples = self.pointer.take_samples(ctx);
        let polled = samples.len();
        for k in 0..=polled {
            routed.clear();
            match samples.get(k) {
                Some(sample) => {
                    let on_view = viewport.contains(sample.pos_in_screen)
                        && ctx
                            .layer_id_at(sample.pos_in_screen)
                            .is_none_or(|l| l.order == egui::Order::Background);
                    self.pointer.router.route(sample, on_view, &mut routed);
                }
                // Between samples: a finger held still becomes a long press.
                None => self.pointer.router.poll(sample_clock(ctx), &mut routed),
            }
            for r in &routed {
                if matches!(
                    r,
                    Routed::Tool(ToolEvent::Begin(_)) | Routed::Hands(Hands::Down(_))
                ) {
                    // A stroke or two fingers on the view close an open menu, as a mouse
                    // click outside it does.
                    egui::Popup::close_all(ctx);
                }
                match r {
                    Routed::Hands(hands) => self.handle_hands(hands, viewport, now),
                    Routed::Nav(action) => self
                        .shared
                        .borrow_mut()
                        .camera
                        .apply(*action, viewport.height().into()),
                    Routed::Tap(TapCommand::Undo) => self.undo(now),
                    Routed::Tap(TapCommand::Redo) => self.run(now, |r, cx| r.redo(cx)),
                    Routed::Tap(TapCommand::DoubleTap(at)) => {
                        self.scene.double_tap(&self.shared, *at, viewport)
                    }
                    Routed::Tap(TapCommand::LongPress(at)) => self.long_press(*at, viewport, now),
                    Routed::Tool(event) if self.pointer.holds_stroke(event, self.is_busy()) => {}
                    Routed::Tool(event) => {
                        // The pen's eraser erases whatever the tool, for one stroke.
                        if let ToolEvent::Begin(sample) = event
                            && sample.is_eraser()
                            && self.tools.mode() != Mode::Erase
                        {
                            self.pointer.erasing_from = Some(self.tools.mode());
                            self.set_mode(Mode::Erase, now);
                        }
                        if matches!(event, ToolEvent::Begin(_)) {
                            self.runner.cancel_gesture();
                            self.run(now, |r, cx| r.finish_edit_unless_offloaded(cx));
                        }
                        let output = self.feed_tool(viewport, |tools, view, doc| {
                            tools.on_event(event, view, doc)
                        });
                        self.take_output(output, now);
                        if matches!(event, ToolEvent::End(_) | ToolEvent::Cancel)
                            && let Some(mode) = self.pointer.erasing_from.take()
                        {
                            self.set_mode(mode, now);
                        }
                    }
                }
            }
        }
        // A finger down may become a long press without another sample.
        if self.pointer.router.is_touching() {
            ctx.request_repaint_after(std::time::Duration::from_millis(50));
        }
        // A stroke across a shape cuts it when no tap follows in time.
        let (output, wait) = self.tools.poll(now);
        self.take_output(output, now);
        if let Some(seconds) = wait {
            ctx.request_repaint_after(std::time::Duration::from_secs_f64(seconds));
        }
    }

    /// A long press at `at`: on a model, its context actions (the finger's stroke is
    /// cancelled); elsewhere nothing, and the stroke goes on.
    fn long_press(&mut self, at: egui::Pos2, viewport: egui::Rect, now: f64) {
        let Some(model) = model_at(&self.shared.borrow(), at, viewport) else {
            return;
        };
        let mut cancelled = Vec::new();
        self.pointer.router.take_touch(&mut cancelled);
        for routed in &cancelled {
            if let Routed::Tool(event) = routed {
                let output = self.feed_tool(viewport, |tools, view, doc| {
                    tools.on_event(event, view, doc)
                });
                self.take_output(output, now);
            }
        }
        self.panels.context_menu = Some(ContextMenu { at, model });
    }

    /// Carries out a context menu's choice for model `model`.
    fn context_action(&mut self, model: usize, action: ContextAction, now: f64) {
        match action {
            ContextAction::Frame => self.scene.frame_model(&self.shared, model),
            ContextAction::Duplicate | ContextAction::Delete => {
                let camera = self.shared.borrow().camera.camera();
                if let Some(op) = action.op(model, &camera) {
                    self.run(now, |r, cx| r.begin_made(op, false, cx));
                }
            }
            ContextAction::Oversketch => self.set_mode(Mode::Oversketch, now),
        }
    }

    /// Whether a stroke drawn now must reach no tool: an import or a replay runs, or an
    /// example's making plays (its ops would mix with the user's).
    fn is_busy(&self) -> bool {
        self.runner.is_busy() || self.making.is_playing()
    }

    /// Plays this frame's part of an example's making (see [`making::Player`]).
    fn run_making(&mut self, ctx: &egui::Context, viewport: egui::Rect, now: f64) {
        let mut player = std::mem::take(&mut self.making);
        let over = self.run(now, |r, cx| player.run(ctx, r, cx, viewport));
        self.making = player;
        if let Some(said) = over {
            self.making_over(said, now);
        }
    }

    /// Says how the making ended; a document with key frames then plays its animation.
    fn making_over(&mut self, said: String, now: f64) {
        self.status.done(said, now);
        let document = self.shared.borrow().editor.document().clone();
        if let Ok(playback) = Playback::start(&document, clock::now_ms()) {
            self.scene.playback = Some(playback);
        }
    }

    fn viewport_ui(&mut self, ui: &mut egui::Ui) {
        let viewport = ui.max_rect();
        let response = ui.allocate_rect(viewport, egui::Sense::hover());
        self.handle_pointer(ui.ctx(), viewport);
        if response.hovered() {
            let (scroll, zoom) = ui.input(|i| (i.smooth_scroll_delta.y, i.zoom_delta()));
            let mut shared = self.shared.borrow_mut();
            if scroll != 0.0 {
                shared.camera.wheel(scroll.into());
            }
            // egui also derives a zoom from touch pinches, which the router already handles.
            if zoom != 1.0 && !self.pointer.router.is_touching() {
                shared.camera.dolly(1.0 / f64::from(zoom));
            }
        }
        let started = clock::now_ms();
        let (ctx, now) = (ui.ctx().clone(), ui.input(|i| i.time));
        self.run(now, |r, cx| r.step_edit(&ctx, cx));
        if self.run(now, |r, cx| r.step_replay(&ctx, cx)) {
            self.follow_page(now);
        }
        self.run_making(&ctx, viewport, now);
        self.scene.frame_work_ms += clock::now_ms() - started;
        let shared = self.shared.borrow();
        let shown = (self.runner.edit()).map_or(shared.editor.document(), Edit::document);
        self.scene.textures.poll(shown, ui.ctx());
        drop(shared);
        let (edit, begun) = (self.runner.edit(), self.runner.edits_begun());
        let mirror = self.runner.edit_mirror();
        self.scene
            .update(ui.ctx(), &self.shared, edit.map(|e| (e, mirror)), begun);
        if self.has_renderer {
            let camera = self.shared.borrow().camera.camera();
            self.scene.paint(ui, viewport, &camera);
        }
        self.backdrop.paint(ui, viewport);
        let shared = self.shared.borrow();
        let played = self.scene.played();
        let mut scene = self.runner.scene(&shared, viewport);
        scene.played = &played;
        scene.symmetry = (shared.symmetry.is_on && !shared.thumbnails.is_capturing())
            .then(|| scene.shown.symmetry.unwrap_or_default());
        let device = Device::of(self.pointer.router.device(), self.coarse_pointer);
        let line = view_overlay::line(&scene, &self.tools, device);
        if let Some(plane) = &scene.symmetry {
            view_overlay::symmetry_plane_ui(ui, &scene, plane, self.scene.bounds());
        }
        let below = view_overlay::draw(ui, &scene, &self.tools, &line, self.runner.waiting());
        let intro = &mut self.panels.intro;
        intro.follow(&shared.editor, shared.exports);
        drop(shared);
        intro.ui(ui.ctx(), viewport, below, device);
        let mut shared = self.shared.borrow_mut();
        shared.hint = line.into_owned();
        shared.intro = intro.step().map(|step| (step.number(), intro.skip_at()));
        drop(shared);
        if let Some(edit) = self.runner.edit() {
            let camera = self.shared.borrow().camera.camera();
            (self.panels.falloff).ui(ui, viewport, &camera, edit, self.runner.edits_begun());
        }
        if let Some(at) = self
            .pointer
            .router
            .pen_hover()
            .filter(|at| viewport.contains(*at))
        {
            view_overlay::pen_ring(ui, at);
        }
        self.view_rect = viewport;
        panels::readout::update(ui.ctx(), |r| r.view = panels::readout::corners(viewport));
        self.scene.view_aspect = f64::from(viewport.aspect_ratio());
        let progress = self.runner.progress(ui.input(|i| i.time));
        self.shared.borrow_mut().progress.clone_from(&progress);
        if self.shared.borrow().thumbnails.is_capturing() {
            // A thumbnail is being taken: the shapes only.
        } else if self.making.ui(ui, viewport, &self.shared) {
            // An example's making plays: its caption and buttons stand for the status.
        } else if let Some(what) = progress {
            if panels::progress::progress_ui(ui.ctx(), viewport, &what) {
                let now = ui.input(|i| i.time);
                self.run(now, |r, cx| r.cancel_offloaded(cx));
                self.run(now, |r, cx| r.cancel_replay(cx));
            }
        } else if let Some((said, tone)) = self.status.said() {
            status_ui(ui, viewport, said, tone);
        }
        let said = self
            .status
            .said()
            .map(|(said, tone)| (said.to_owned(), tone));
        self.shared.borrow_mut().status = said;
    }
}

impl eframe::App for SketchApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        let ctx = ui.ctx().clone();
        self.shared.borrow_mut().notes.take_escape(&ctx);
        for command in shortcuts::read(&ctx, &self.tools) {
            let now = ctx.input(|i| i.time);
            self.command(command, &ctx, now);
        }
        let now = ctx.input(|i| i.time);
        if let Some(message) = self.backdrop.poll(&ctx) {
            self.refuse(message, now);
        }
        // The page's document first: a replay or a making it asked for after opening a new
        // one is for the new one, not dropped with the old one's edits.
        self.follow_page(now);
        let (files, runner, mut cx) = self.parts(now);
        files.run_imports(&ctx, runner, &mut cx);
        self.scene.frame_work_ms = 0.0;
        self.status.expire(now);
        if self.scene.is_playing() {
            ctx.request_repaint();
        }
        self.tools.playing(self.scene.is_playing());
        let layout =
            panels::toolbar::Layout::for_screen(ctx.content_rect().size(), self.coarse_pointer);
        let panel = match layout.bottom {
            true => egui::Panel::bottom("toolbar"),
            false => egui::Panel::top("toolbar"),
        };
        let action = panel
            .show(ui, |ui| {
                let shared = self.shared.borrow();
                panels::toolbar::toolbar_ui(
                    ui,
                    layout,
                    &shared.editor,
                    shared.symmetry.is_on,
                    &mut self.scene.options,
                    &mut self.tools,
                    &mut self.panels.show_help,
                )
            })
            .inner;
        if let Some(action) = action {
            self.command(action, &ctx, now);
        }
        egui::CentralPanel::no_frame().show(ui, |ui| self.viewport_ui(ui));
        self.shared
            .borrow_mut()
            .thumbnails
            .run(&ctx, self.view_rect);
        if let Some((model, action)) = context_menu_ui(&ctx, &mut self.panels.context_menu) {
            self.context_action(model, action, now);
        }
        // After the frame's edits land, and left to a later frame if their work filled this
        // one.
        #[cfg(target_arch = "wasm32")]
        self.autosave
            .run(&ctx, &self.shared, &self.scene, &mut self.status, now);
        let backend = self.shared.borrow().backend.clone();
        let show_intro = panels::help::help_ui(
            &ctx,
            &mut self.panels.show_help,
            &backend,
            self.pointer.router.pen_seen(),
            self.coarse_pointer,
        );
        if show_intro {
            self.panels.show_help = false;
            self.panels.intro.reopen();
        }
        #[cfg(target_arch = "wasm32")]
        if self.panels.intro.take_ended() {
            crate::page_store::keep_intro_seen();
        }
        let mut shared = self.shared.borrow_mut();
        let revision = shared.revision();
        let Shared { editor, notes, .. } = &mut *shared;
        notes.follow((revision.opened, revision.edits), editor.notes());
        panels::notes::notes_ui(&ctx, notes);
    }
}

fn backend_name(rs: &egui_wgpu::RenderState) -> String {
    match rs.adapter.get_info().backend {
        eframe::wgpu::Backend::BrowserWebGpu => "WebGPU".to_owned(),
        eframe::wgpu::Backend::Gl => "WebGL2".to_owned(),
        other => format!("{other:?}"),
    }
}

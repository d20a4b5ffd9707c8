//! The 3D scene as drawn: the GPU arrays built from the document shown, rebuilt when it
//! changes (spread over frames when a frame's work is spent), a moved model's vertices moved
//! in place, and the key-framed animation played over it.

use std::cell::RefCell;
use std::sync::Arc;

use eframe::egui_wgpu;
use glam::DVec3;
use sketchmesh_core::document::{Edit, Op, StrokeInput, model_under};
use sketchmesh_core::mesh::VertexId;
use sketchmesh_core::model::MirrorPlane;
use sketchmesh_core::symmetry::{are_twins, mirror_positions, moved_side, partners};

use crate::autosave;
use crate::camera::OrbitCamera;
use crate::clock;
use crate::edit_runner::FRAME_BUDGET_MS;
use crate::playback::Playback;
use crate::render::geometry::NormalsAhead;
use crate::render::{SceneCallback, SceneGeometry, Uniforms, ViewOptions};
use crate::shared::Shared;
use crate::textures::Textures;

/// A frame whose own work has taken this long (ms) leaves the scene's rebuild, then its
/// upload, then the autosave, to the next frames, one each: a large result's landing (a
/// million triangles decoded; their arrays built; uploaded; the session with the file
/// written) is then four frames of at most about 100 ms in the page rather than one of
/// 250 ms and one of 190.
pub const SPREAD_AFTER_MS: f64 = 50.0;

/// What the drawn scene was built from: the editor's revision, the edit's number and
/// revision when it shows another document than the editor's, the textures' version, and
/// whether the wireframe is shown (its edges are built only then).
type GeometrySource = (autosave::Revision, Option<(u64, u64)>, u64, bool);

/// The scene drawn in the view and what it was built from.
pub struct SceneView {
    geometry: Arc<SceneGeometry>,
    /// What `geometry` was built from: the editor's revision, and the edit's number and
    /// revision when it shows another document than the editor's.
    geometry_source: GeometrySource,
    /// A scene built in a frame its work had filled, with what it was built from: the next
    /// frame shows (and uploads) it.
    stashed_geometry: Option<(GeometrySource, Arc<SceneGeometry>)>,
    /// Imported models' textures, decoded for the view.
    pub textures: Textures,
    /// The edit generation whose moved model `geometry` shows, if it shows one (it is rebuilt
    /// when the edit stops moving it).
    shown_motion: Option<u64>,
    /// Normals of a moved model, reused between frames.
    moved_normals: Vec<glam::DVec3>,
    /// How the other side of a mirrored edit's moved model follows it in the view.
    mirrored_motion: MirroredMotion,
    /// The key-framed animation being played, if any.
    pub playback: Option<Playback>,
    /// What this frame's own work (the edit's steps and landing, the scene's rebuild) has
    /// taken so far, in ms (see [`SPREAD_AFTER_MS`]).
    pub frame_work_ms: f64,
    /// Whether the last frame left the scene's rebuild to this one, which then does it
    /// whatever its own work took.
    rebuild_waited: bool,
    /// The normals of large new models, computed a frame before their arrays.
    normals_ahead: NormalsAhead,
    /// Frame everything once the geometry has been rebuilt (after an import, or opening a
    /// session).
    pub frame_after_rebuild: bool,
    /// The wireframe, grid and clay switches.
    pub options: ViewOptions,
    /// The 3D view's width over its height, last frame: framing fits both.
    pub view_aspect: f64,
}

impl Default for SceneView {
    fn default() -> Self {
        SceneView {
            geometry: Arc::new(SceneGeometry::default()),
            // Nothing built yet: no document has this revision.
            geometry_source: (
                autosave::Revision {
                    opened: u64::MAX,
                    edits: u64::MAX,
                },
                None,
                0,
                false,
            ),
            stashed_geometry: None,
            textures: Textures::default(),
            shown_motion: None,
            moved_normals: Vec::new(),
            mirrored_motion: MirroredMotion::default(),
            playback: None,
            frame_work_ms: 0.0,
            rebuild_waited: false,
            normals_ahead: NormalsAhead::default(),
            frame_after_rebuild: false,
            view_aspect: 1.0,
            options: ViewOptions {
                wireframe: false,
                grid: true,
                clay: false,
            },
        }
    }
}

impl SceneView {
    /// Paints the scene into `viewport` through `camera`.
    pub fn paint(
        &self,
        ui: &egui::Ui,
        viewport: egui::Rect,
        camera: &sketchmesh_core::camera::Camera,
    ) {
        let aspect = f64::from(viewport.width() / viewport.height().max(1.0));
        let callback = SceneCallback {
            rect: viewport,
            uniforms: Uniforms {
                clip_from_world: camera.clip_from_world(aspect).as_mat4().to_cols_array_2d(),
                eye: camera.eye.as_vec3().extend(1.0).to_array(),
                viewport: [0.0; 4],
            },
            geometry: self.geometry.clone(),
            options: self.options,
            repaint: ui.ctx().clone(),
        };
        ui.painter()
            .add(egui_wgpu::Callback::new_paint_callback(viewport, callback));
    }

    /// The box around everything drawn, if anything is.
    pub fn bounds(&self) -> Option<(DVec3, DVec3)> {
        self.geometry.bounds
    }

    /// Frames everything in the document, or resets the view when it is empty.
    pub fn frame_all(&self, shared: &RefCell<Shared>) {
        let mut shared = shared.borrow_mut();
        match self.geometry.bounds {
            Some((min, max)) => shared.camera.frame(min, max, self.view_aspect),
            None => shared.camera = OrbitCamera::default(),
        }
    }

    /// A one-finger double tap at `at`: on empty canvas it frames everything, as in 3D apps
    /// on tablets; on a model it does nothing more than its taps did.
    pub fn double_tap(&self, shared: &RefCell<Shared>, at: egui::Pos2, viewport: egui::Rect) {
        if model_at(&shared.borrow(), at, viewport).is_none() {
            self.frame_all(shared);
        }
    }

    /// Frames model `model` (a context menu's choice).
    pub fn frame_model(&self, shared: &RefCell<Shared>, model: usize) {
        let mut shared = shared.borrow_mut();
        let bounds =
            (shared.editor.document().models.get(model)).and_then(|m| m.mesh.bounding_box());
        if let Some((min, max)) = bounds {
            shared.camera.frame(min, max, self.view_aspect);
        }
    }

    /// Rebuilds the GPU arrays when the document drawn changed (the editor's, or the one the
    /// edit in progress shows, such as a shape being created), and moves a model's vertices
    /// in place while the edit moves them (a pull's preview).
    pub fn update(
        &mut self,
        ctx: &egui::Context,
        shared: &RefCell<Shared>,
        edit: Option<(&Edit, Option<MirrorPlane>)>,
        edits_begun: u64,
    ) {
        let (edit, mirror) = (edit.map(|(edit, _)| edit), edit.and_then(|(_, m)| m));
        let source = (
            shared.borrow().revision(),
            edit.map(Edit::revision)
                .filter(|&revision| revision != 0)
                .map(|revision| (edits_begun, revision)),
            self.textures.version,
            self.options.wireframe,
        );
        let moved = edit.and_then(Edit::moved_model);
        let motion_ended = self.shown_motion.is_some() && moved.is_none();
        let rebuilt = source != self.geometry_source || motion_ended;
        let stashed = self.stashed_geometry.take();
        let had_stash = stashed.is_some();
        if rebuilt && let Some((built_for, built)) = stashed.filter(|(s, _)| *s == source) {
            // Built in the last frame, which its work had filled: shown from this one, which
            // uploads it (that upload is this frame's work).
            self.geometry = built;
            self.geometry_source = built_for;
            self.shown_motion = None;
            self.frame_work_ms += SPREAD_AFTER_MS;
        } else if rebuilt {
            let waited = std::mem::take(&mut self.rebuild_waited);
            if !waited && self.is_frame_spent(ctx) {
                // The next frame rebuilds; this one draws what it drew (a moved model's
                // positions belong to the document to be built).
                self.rebuild_waited = true;
                return;
            }
            let borrowed = shared.borrow();
            // A shape created with symmetry on beside the plane shows its twin as it inflates.
            let with_twin = edit.and_then(Edit::mirrored_creation);
            let document = (with_twin.as_ref())
                .unwrap_or_else(|| edit.map_or(borrowed.editor.document(), Edit::document));
            let generation = self.geometry.generation + 1;
            let started = clock::now_ms();
            // The arrays of unchanged models are copied, unless textures were decoded since
            // or the wireframe was turned on or off.
            let (built_with, wanted) = (self.geometry_source, source);
            let previous =
                (built_with.2 == wanted.2 && built_with.3 == wanted.3).then_some(&*self.geometry);
            // A large new model's normals take a frame of their own (one with little else to
            // do, unless it waited already: not the one that landed it), its arrays the next.
            let ahead = self.normals_ahead.is_wanted(document, previous);
            if ahead && !waited && self.frame_work_ms > FRAME_BUDGET_MS {
                self.rebuild_waited = true;
                ctx.request_repaint();
                return;
            }
            if ahead {
                self.normals_ahead.compute(document, previous);
            }
            let large = !self.normals_ahead.is_empty();
            let built = (!ahead).then(|| {
                Arc::new(SceneGeometry::build(
                    document,
                    generation,
                    &self.textures,
                    previous,
                    self.options.wireframe,
                    &std::mem::take(&mut self.normals_ahead),
                ))
            });
            // What a new document costs the frame before the GPU sees it (the page bench).
            let ms = clock::now_ms() - started;
            self.frame_work_ms += ms;
            drop(borrowed);
            clock::record(&mut shared.borrow_mut().timings.of("scene").frame_ms, ms);
            let Some(built) = built else {
                self.rebuild_waited = true;
                ctx.request_repaint();
                return;
            };
            if !had_stash && source != self.geometry_source && (large || self.is_frame_spent(ctx)) {
                // Its upload waits for the next frame, which shows it (unless the document
                // moves on meanwhile: then that frame builds and shows the next one); so
                // does a large model's, whatever this frame took.
                self.stashed_geometry = Some((source, built));
                ctx.request_repaint();
                return;
            }
            self.geometry = built;
            self.geometry_source = source;
            self.shown_motion = None;
        }
        if let (Some(edit), Some((index, positions))) = (edit, moved)
            && self.shown_motion != Some(edit.generation())
            && let Some(model) = edit.document().models.get(index)
        {
            let geometry = Arc::make_mut(&mut self.geometry);
            let followed = mirror.and_then(|plane| {
                let motion = &mut self.mirrored_motion;
                motion.follow(edit, edits_begun, index, positions, &plane)
            });
            let positions = match followed {
                Some(Followed::Itself(mirrored)) => mirrored,
                Some(Followed::Twin(twin, mirrored)) => {
                    if let Some(model) = edit.document().models.get(twin) {
                        geometry.move_model(twin, model, mirrored, &mut self.moved_normals);
                    }
                    positions
                }
                None => positions,
            };
            geometry.move_model(index, model, positions, &mut self.moved_normals);
            if let Some((shaded, vertices, weights)) = edit.region_falloff()
                && let Some(levels) = edit.region_levels()
                && shaded == index
            {
                // The gray levels until the region moves; then the lit surface, as committed.
                let (vertices, weights) = match edit.region_shade_levels() {
                    Some(_) => (vertices, weights),
                    None => (&[][..], &[][..]),
                };
                geometry.shade_model(index, vertices, weights, levels);
            }
            self.shown_motion = Some(edit.generation());
        }
        self.play_frame(shared, edit.is_none());
        if rebuilt && std::mem::take(&mut self.frame_after_rebuild) {
            self.frame_all(shared);
        }
    }

    /// Whether the scene's rebuild is under way over frames (its normals, its arrays or their
    /// upload still to come): the autosave waits for it rather than share its frames.
    #[cfg(target_arch = "wasm32")]
    pub fn is_pending(&self) -> bool {
        self.rebuild_waited || self.stashed_geometry.is_some() || !self.normals_ahead.is_empty()
    }

    /// Whether this frame's own work has reached [`SPREAD_AFTER_MS`], so that what is left waits
    /// for the next frame (which is asked for).
    pub fn is_frame_spent(&self, ctx: &egui::Context) -> bool {
        let spent = self.frame_work_ms >= SPREAD_AFTER_MS;
        if spent {
            ctx.request_repaint();
        }
        spent
    }

    /// Shows the animation's pose of each model while it plays; when it has played
    /// through (or an edit began), the document's pose again.
    fn play_frame(&mut self, shared: &RefCell<Shared>, no_edit: bool) {
        let Some(playback) = &mut self.playback else {
            return;
        };
        let time = playback.advance(clock::now_ms()).filter(|_| no_edit);
        let Some(time) = time else {
            return self.stop_playing();
        };
        let shared = shared.borrow();
        let models = &shared.editor.document().models;
        let geometry = Arc::make_mut(&mut self.geometry);
        for (index, positions) in playback.poses(time) {
            if let Some(model) = models.get(index) {
                geometry.move_model(index, model, positions, &mut self.moved_normals);
            }
        }
    }

    /// Stops the animation, if one plays: the document's pose is shown again.
    pub fn stop_playing(&mut self) {
        if self.playback.take().is_some() {
            // Rebuilt from the document at the next frame.
            self.geometry_source.1 = Some((u64::MAX, u64::MAX));
        }
    }

    /// The models the animation playing shows posed, and their vertices in that pose.
    pub fn played(&self) -> Vec<(usize, &[DVec3])> {
        (self.playback.iter()).flat_map(Playback::shown).collect()
    }

    /// Whether an animation is playing (the page then draws every frame).
    pub fn is_playing(&self) -> bool {
        self.playback.is_some()
    }
}

/// The index of the model seen at screen point `at` of `viewport`.
pub fn model_at(shared: &Shared, at: egui::Pos2, viewport: egui::Rect) -> Option<usize> {
    let relative = at - viewport.min;
    let size = viewport.size();
    let tap = StrokeInput {
        viewport: [size.x.into(), size.y.into()],
        camera: shared.camera.camera(),
        stroke: vec![[relative.x.into(), relative.y.into(), 0.5]],
    };
    model_under(shared.editor.document(), &tap)
}

/// The other side of a mirrored edit's moved model, shown while it moves (a pull's preview
/// on a symmetric model or a twin pair): the edit commits both sides, so the view previews
/// both. Which model or vertices follow is found once per edit (an O(n) search), then each
/// frame mirrors the moved positions onto them.
#[derive(Default)]
struct MirroredMotion {
    /// The edit (by number) and moved model this was found for, and what follows it.
    found: Option<(u64, usize, Follower)>,
    /// The mirrored positions, reused between frames.
    mirrored: Vec<DVec3>,
}

/// What follows a moved model across the plane.
enum Follower {
    /// Its mirror twin, vertex for vertex.
    Twin(usize),
    /// Its own other side: each vertex's partner.
    Partners(Vec<VertexId>),
    /// Nothing: neither symmetric nor a twin (the edit will be refused), or a symmetric
    /// model being moved whole (it stays as moved).
    Nothing,
}

/// What a moved model's mirrored positions are for.
enum Followed<'a> {
    /// The model itself, made symmetric: draw these instead.
    Itself(&'a [DVec3]),
    /// Its twin (this model index): draw these there.
    Twin(usize, &'a [DVec3]),
}

impl MirroredMotion {
    /// The mirrored positions for model `index` of `edit` (edit number `edit_number`) moved
    /// to `positions`, about `plane`.
    fn follow<'a>(
        &'a mut self,
        edit: &Edit,
        edit_number: u64,
        index: usize,
        positions: &[DVec3],
        plane: &MirrorPlane,
    ) -> Option<Followed<'a>> {
        let models = &edit.document().models;
        let base = models.get(index)?.mesh.positions();
        let is_current =
            |(number, model, _): &(u64, usize, Follower)| *number == edit_number && *model == index;
        if !self.found.as_ref().is_some_and(is_current) {
            let mesh = &models[index].mesh;
            let twin =
                (0..models.len()).find(|&j| j != index && are_twins(mesh, &models[j].mesh, plane));
            let follower = match (twin, edit.op()) {
                (Some(twin), _) => Follower::Twin(twin),
                (None, Op::Transform(_)) => Follower::Nothing,
                (None, _) => partners(mesh, plane).map_or(Follower::Nothing, Follower::Partners),
            };
            self.found = Some((edit_number, index, follower));
        }
        let (_, _, follower) = self.found.as_ref()?;
        self.mirrored.clear();
        match follower {
            Follower::Twin(twin) => {
                self.mirrored
                    .extend(positions.iter().map(|&p| plane.reflect(p)));
                Some(Followed::Twin(*twin, &self.mirrored))
            }
            Follower::Partners(partners) if partners.len() == positions.len() => {
                self.mirrored.extend_from_slice(positions);
                let keep = moved_side(base, positions, plane);
                mirror_positions(base, &mut self.mirrored, partners, plane, keep);
                Some(Followed::Itself(&self.mirrored))
            }
            _ => None,
        }
    }
}

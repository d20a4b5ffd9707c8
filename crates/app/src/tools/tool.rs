//! The tool protocol: what every tool is given and what it gives back. The app, the toolbar,
//! the help and the shortcuts know a tool only through [`Tool`]; [`super::registry`] lists
//! them, one line each.

use egui::Key;
use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::StrokePoint;
use sketchmesh_core::document::{Document, Edit, Op};

use super::context::{ToolOutput, ViewCtx};
use super::hint::{Device, Hint};
use super::icon::Icon;
use crate::input::router::{Hands, ToolEvent};

/// What the toolbar, the help and the shortcuts show of a tool.
#[derive(Clone, Copy, Debug)]
pub struct ToolInfo {
    /// The toolbar label.
    pub label: &'static str,
    /// Draws the tool's icon (see [`crate::tools::icon`]), drawn for this app in its folder.
    pub icon: Icon,
    /// The key that selects it (without modifiers).
    pub key: Key,
    /// What it is for: the toolbar groups the tools by it, in [`Group::ALL`]'s order.
    pub group: Group,
    /// What it does, for tooltips and the help window.
    pub about: &'static str,
    /// How to use it with each pointer, for the help window.
    pub gestures: Gestures,
    /// For a tool that deforms a model: when to choose it rather than another that does.
    pub when: Option<&'static str>,
}

/// How to use a tool with a pen, a finger and a mouse: a few words each.
#[derive(Clone, Copy, Debug)]
pub struct Gestures {
    /// With a pen.
    pub pen: &'static str,
    /// With a finger (fingers draw until a pen is seen).
    pub finger: &'static str,
    /// With a mouse.
    pub mouse: &'static str,
}

/// What a tool is for; the toolbar and the help show the tools in these groups, in this
/// order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Group {
    /// Make shapes and curves.
    Make,
    /// Change the control curves.
    Curves,
    /// Change a model's shape.
    Reshape,
    /// Bend a model into poses and animate them.
    Animate,
    /// Clean up a model's triangles.
    Tidy,
    /// Colour models.
    Colour,
    /// Place, copy and delete models.
    Arrange,
}

impl Group {
    /// Every group, in toolbar order.
    pub const ALL: [Group; 7] = [
        Group::Make,
        Group::Curves,
        Group::Reshape,
        Group::Animate,
        Group::Tidy,
        Group::Colour,
        Group::Arrange,
    ];

    /// Its name, as the help and the toolbar's menus show it.
    pub fn label(self) -> &'static str {
        match self {
            Group::Make => "Make",
            Group::Curves => "Curves",
            Group::Reshape => "Reshape",
            Group::Animate => "Pose and animate",
            Group::Tidy => "Tidy",
            Group::Colour => "Colour",
            Group::Arrange => "Arrange",
        }
    }

    /// Whether its tools deform a model (each then says when to choose it).
    pub fn deforms(self) -> bool {
        matches!(self, Group::Reshape | Group::Animate)
    }
}

/// What a tool draws over from: the document shown (the edit's while one runs), the edit in
/// progress, and the view.
#[derive(Clone, Copy)]
pub struct Scene<'a> {
    /// The document as shown: the edit in progress's, else the editor's.
    pub shown: &'a Document,
    /// The editor's document (what the edit in progress began from).
    pub doc: &'a Document,
    /// The edit in progress, if any.
    pub edit: Option<&'a Edit>,
    /// Whether the page's worker computes the edit in progress's op.
    pub computing: bool,
    /// The camera the user sees through.
    pub camera: Camera,
    /// The 3D viewport's rectangle in screen points.
    pub viewport: egui::Rect,
    /// The models the animation being played shows posed, and their vertices' positions in
    /// that pose (empty when nothing plays).
    pub played: &'a [(usize, &'a [glam::DVec3])],
    /// The symmetry plane as the shown document has it, while the Symmetry switch is on.
    pub symmetry: Option<sketchmesh_core::model::MirrorPlane>,
}

impl Scene<'_> {
    /// The viewport's size, as strokes and cameras measure it.
    pub fn size(&self) -> glam::DVec2 {
        glam::DVec2::new(self.viewport.width().into(), self.viewport.height().into())
    }

    /// The models drawn elsewhere than the document has them, and where their vertices are
    /// drawn: the one the edit in progress moves, then those the animation playing poses.
    pub fn moved_models(&self) -> Vec<(usize, &[glam::DVec3])> {
        (self.edit.and_then(Edit::moved_model).into_iter())
            .chain(self.played.iter().copied())
            .collect()
    }

    /// A point relative to the viewport, in screen points.
    pub fn at(&self, p: glam::DVec2) -> egui::Pos2 {
        self.viewport.min + egui::vec2(p.x as f32, p.y as f32)
    }
}

/// A lasso or brush stroke of a tool's open preview, as shown on screen.
#[derive(Debug)]
pub struct Mark {
    /// The samples, in the view they were drawn in.
    pub points: Vec<StrokePoint>,
    /// The brush's radius in CSS px; `None` for the lasso.
    pub radius: Option<f64>,
    /// Whether it marks features that hold (else what moves).
    pub features: bool,
}

/// A tool: a state machine (an enum of its stages) that turns pointer events into
/// [`ToolOutput`]s, with its options panel and what it draws over the view. Everything but
/// [`Tool::info`], [`Tool::on_event`], [`Tool::cancel`] and [`Tool::hint`] has a default
/// that does nothing.
pub trait Tool: std::fmt::Debug {
    /// Its name, icon, key and one-line description.
    fn info(&self) -> &'static ToolInfo;

    /// One pointer event, in `view` of `doc`.
    fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput;

    /// Two fingers; a tool takes them by answering [`Hands::Down`] with
    /// [`ToolOutput::Begin`] (the router then sends their moves to it).
    fn on_hands(&mut self, _hands: &Hands, _view: &ViewCtx, _doc: &Document) -> ToolOutput {
        ToolOutput::None
    }

    /// Drops any gesture in progress; what is left of it (a stroke kept as ink, the edit to
    /// drop).
    fn cancel(&mut self) -> ToolOutput;

    /// Its options in the toolbar's second row; what the user did there (`None`: it has
    /// no options).
    fn panel(&mut self, _ui: &mut egui::Ui, _doc: &Document) -> Option<ToolOutput> {
        None
    }

    /// Draws what it shows over the view (handles, picked curves, its panels in the view).
    fn overlay(&self, _ui: &egui::Ui, _scene: &Scene<'_>) {}

    /// Draws what an edit of an op it makes shows over the view, whichever tool is in use
    /// (a feature's amount, a fine shape's outline while the worker computes it).
    fn edit_overlay(&self, _ui: &egui::Ui, _scene: &Scene<'_>) {}

    /// What the edit in progress says, if it is of an op this tool makes (a feature's
    /// amount): shown in place of the hint, whichever tool is in use.
    fn edit_line(&self, _edit: &Edit) -> Option<String> {
        None
    }

    /// What to tell the user once an edit of an op it makes has landed (`before` is the
    /// document it began from).
    fn report(&self, _op: &Op, _before: &Document, _after: &Document) -> Option<String> {
        None
    }

    /// What it asks the user to do next, in `device`'s words ([`Device::say`]): one short
    /// line in every stage, naming the conditions its op will check (a loop near the
    /// outline, a half-turn of the view) before a refusal has to. Asked only while the
    /// document has something to work on, unless it [`Tool::makes_shapes`].
    fn hint(&self, doc: &Document, device: Device) -> Hint;

    /// Whether it works on an empty document, making shapes. The others, while there is
    /// nothing to work on, say which tool makes shapes instead of their hint, and refuse a
    /// stroke with that sentence (see `ToolSet::on_event`).
    fn makes_shapes(&self) -> bool {
        false
    }

    /// The stroke in progress, for live display.
    fn preview(&self) -> Option<&[StrokePoint]> {
        None
    }

    /// Its lasso and brush strokes, while the view is the one each was drawn in.
    fn marks(&self, _camera: &Camera) -> Vec<Mark> {
        Vec::new()
    }

    /// The keys it takes while it is the tool in use (see [`Tool::on_key`]).
    fn keys(&self) -> &'static [Key] {
        &[]
    }

    /// The keys it takes whatever the tool in use: pressing one makes it the tool in use,
    /// then [`Tool::on_key`] runs.
    fn keys_anywhere(&self) -> &'static [Key] {
        &[]
    }

    /// One of its [`Tool::keys`] or [`Tool::keys_anywhere`] was pressed.
    fn on_key(&mut self, _key: Key, _doc: &Document) -> ToolOutput {
        ToolOutput::None
    }

    /// Called every frame while it is in use, with the frame's clock (s): what a waiting
    /// stroke becomes when its tap is late, and how long until the next such moment.
    fn poll(&mut self, _now: f64) -> (ToolOutput, Option<f64>) {
        (ToolOutput::None, None)
    }

    /// The edit in progress stepped (whichever tool is in use): a tool waiting on what its
    /// edit finds takes it.
    fn edit_stepped(&mut self, _edit: &Edit) {}

    /// The edit a gesture began was refused (whichever tool is in use): the tool starts
    /// over.
    fn gesture_refused(&mut self) {}

    /// Whether the key-framed animation is playing, told every frame (whichever tool is in
    /// use): a tool that plays it offers to stop it meanwhile.
    fn playing(&mut self, _is_playing: bool) {}
}

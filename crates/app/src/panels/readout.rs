//! Where the last frame put the 3D view and the help's scrolled list, for the page API's
//! `layout` read-out: the browser suite measures the toolbar's height for every tool and
//! scrolls the help to its end through it.

/// Where the view and the help are, in CSS px.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct Readout {
    /// The 3D view's rectangle: left, top, right, bottom.
    pub view: [f32; 4],
    /// The help's scrolled list, while the help is open.
    pub help: Option<HelpScroll>,
}

/// The help's scrolled list.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct HelpScroll {
    /// The visible part's rectangle: left, top, right, bottom.
    pub rect: [f32; 4],
    /// How far it is scrolled down, in points.
    pub offset: f32,
    /// How far it scrolls at most (0: all of it shows).
    pub max_offset: f32,
}

fn id() -> egui::Id {
    egui::Id::unique("sketchmesh-readout")
}

/// The corners of `rect`.
pub fn corners(rect: egui::Rect) -> [f32; 4] {
    [rect.min.x, rect.min.y, rect.max.x, rect.max.y]
}

/// The last frame's read-out.
pub fn read(ctx: &egui::Context) -> Readout {
    ctx.data(|d| d.get_temp(id())).unwrap_or_default()
}

/// Changes the read-out.
pub fn update(ctx: &egui::Context, change: impl FnOnce(&mut Readout)) {
    ctx.data_mut(|d| change(d.get_temp_mut_or_default(id())));
}

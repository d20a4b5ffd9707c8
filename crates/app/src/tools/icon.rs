//! The pen the tools' icons are drawn with: lines, arcs, dots and fills on a 24-unit square,
//! scaled to the icon's rectangle, so an icon is sharp at any size and pixel density (a font
//! glyph meant something else: ✋ read as "pan", ✖ as "close"). Each tool draws its own
//! icon in its folder ([`super::ToolInfo::icon`]).

use egui::{Color32, Painter, Pos2, Rect, Shape, Stroke};

/// The icons' design grid: an icon draws in `0..GRID` on both axes, y down.
pub const GRID: f32 = 24.0;

/// The width of an icon's lines, in grid units: about 2 px at 24 px, which reads on a dark
/// toolbar at 20 px as well.
const LINE: f32 = 2.0;

/// Draws in one icon's square: the main colour for what the tool acts with, the dim one
/// for what it acts on.
pub struct Pen<'a> {
    painter: &'a Painter,
    rect: Rect,
    ink: Color32,
    dim: Color32,
}

impl<'a> Pen<'a> {
    /// A pen that draws in `rect` (the icon's square) with `ink`, the dim parts in `ink` at
    /// half its opacity.
    pub fn new(painter: &'a Painter, rect: Rect, ink: Color32) -> Self {
        Pen {
            painter,
            rect,
            ink,
            dim: ink.gamma_multiply(0.45),
        }
    }

    /// A grid point on the screen.
    fn at(&self, (x, y): (f32, f32)) -> Pos2 {
        let scale = self.rect.width().min(self.rect.height()) / GRID;
        let origin = self.rect.center() - egui::vec2(GRID, GRID) * scale / 2.0;
        origin + egui::vec2(x, y) * scale
    }

    /// Grid units in screen points.
    fn len(&self, units: f32) -> f32 {
        units * self.rect.width().min(self.rect.height()) / GRID
    }

    fn stroke(&self, dim: bool) -> Stroke {
        Stroke::new(self.len(LINE), if dim { self.dim } else { self.ink })
    }

    fn line_points(&self, points: &[(f32, f32)]) -> Vec<Pos2> {
        points.iter().map(|&p| self.at(p)).collect()
    }

    /// An open line through `points`.
    pub fn line(&self, points: &[(f32, f32)]) {
        let line = Shape::line(self.line_points(points), self.stroke(false));
        self.painter.add(line);
    }

    /// An open line in the dim colour.
    pub fn dim_line(&self, points: &[(f32, f32)]) {
        let line = Shape::line(self.line_points(points), self.stroke(true));
        self.painter.add(line);
    }

    /// A closed outline through `points`.
    pub fn outline(&self, points: &[(f32, f32)]) {
        let line = Shape::closed_line(self.line_points(points), self.stroke(false));
        self.painter.add(line);
    }

    /// A convex polygon filled with the main colour.
    pub fn fill(&self, points: &[(f32, f32)]) {
        let polygon = Shape::convex_polygon(self.line_points(points), self.ink, Stroke::NONE);
        self.painter.add(polygon);
    }

    /// A smooth curve from `a` to `d` pulled toward `b` and `c` (a cubic Bézier), in the
    /// dim colour or not.
    pub fn curve(&self, [a, b, c, d]: [(f32, f32); 4], dim: bool) {
        let points = (0..=16).map(|i| {
            let t = i as f32 / 16.0;
            let u = 1.0 - t;
            let w = [u * u * u, 3.0 * u * u * t, 3.0 * u * t * t, t * t * t];
            (
                w[0] * a.0 + w[1] * b.0 + w[2] * c.0 + w[3] * d.0,
                w[0] * a.1 + w[1] * b.1 + w[2] * c.1 + w[3] * d.1,
            )
        });
        let points: Vec<(f32, f32)> = points.collect();
        if dim {
            self.dim_line(&points);
        } else {
            self.line(&points);
        }
    }

    /// An arc about `centre` of `radius` from angle `from` to `to` (radians, y down), in
    /// the dim colour or not.
    pub fn arc(&self, centre: (f32, f32), radius: (f32, f32), from: f32, to: f32, dim: bool) {
        let points: Vec<(f32, f32)> = (0..=24)
            .map(|i| {
                let a = from + (to - from) * i as f32 / 24.0;
                (centre.0 + radius.0 * a.cos(), centre.1 + radius.1 * a.sin())
            })
            .collect();
        if dim {
            self.dim_line(&points);
        } else {
            self.line(&points);
        }
    }

    /// A filled dot of `radius` grid units.
    pub fn dot(&self, centre: (f32, f32), radius: f32) {
        let dot = Shape::circle_filled(self.at(centre), self.len(radius), self.ink);
        self.painter.add(dot);
    }

    /// An arrow's head at `tip`, pointing from `from`.
    pub fn arrow_head(&self, from: (f32, f32), tip: (f32, f32)) {
        let (dx, dy) = (tip.0 - from.0, tip.1 - from.1);
        let n = (dx * dx + dy * dy).sqrt().max(1e-3);
        let (ux, uy) = (dx / n * 4.5, dy / n * 4.5);
        let back = (tip.0 - ux, tip.1 - uy);
        let side = (-uy * 0.8, ux * 0.8);
        self.fill(&[
            tip,
            (back.0 + side.0, back.1 + side.1),
            (back.0 - side.0, back.1 - side.1),
        ]);
    }

    /// A straight arrow from `from` to `tip`.
    pub fn arrow(&self, from: (f32, f32), tip: (f32, f32)) {
        let (dx, dy) = (tip.0 - from.0, tip.1 - from.1);
        let n = (dx * dx + dy * dy).sqrt().max(1e-3);
        // The shaft stops inside the head, so its end does not poke through the point.
        let end = (tip.0 - dx / n * 3.0, tip.1 - dy / n * 3.0);
        self.line(&[from, end]);
        self.arrow_head(from, tip);
    }
}

/// Draws a tool's icon with the pen it is given.
pub type Icon = fn(&Pen<'_>);

/// Draws `icon` in `rect` with `ink`.
pub fn paint(painter: &Painter, rect: Rect, ink: Color32, icon: Icon) {
    icon(&Pen::new(painter, rect, ink));
}

//! The over-sketch tool's icon: a shape's outline and the new stroke drawn beside it.

use crate::tools::icon::Pen;

use std::f32::consts::PI;

/// Draws the icon.
pub fn draw(pen: &Pen<'_>) {
    pen.arc((12.0, 19.0), (9.5, 9.5), PI, 2.0 * PI, true);
    pen.arc((12.0, 19.0), (10.0, 15.5), 1.2 * PI, 1.72 * PI, false);
    let tip = |a: f32| (12.0 + 10.0 * a.cos(), 19.0 + 15.5 * a.sin());
    pen.arrow_head(tip(1.62 * PI), tip(1.8 * PI));
}

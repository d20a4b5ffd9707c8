//! The paint tool's icon: a round brush laying a stroke of colour over a surface.

use crate::tools::icon::Pen;

/// Draws the icon.
pub fn draw(pen: &Pen<'_>) {
    pen.dim_line(&[(2.0, 21.0), (22.0, 21.0)]);
    pen.curve(
        [(3.0, 17.0), (8.0, 13.0), (12.0, 19.0), (16.0, 15.0)],
        false,
    );
    pen.line(&[(16.0, 15.0), (21.0, 4.0)]);
    pen.dot((16.0, 15.0), 2.6);
}

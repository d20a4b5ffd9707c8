//! The pull tool's icon: a curve pulled up by its middle, the surface under it following.

use crate::tools::icon::Pen;

/// Draws the icon.
pub fn draw(pen: &Pen<'_>) {
    pen.dim_line(&[(2.0, 20.0), (22.0, 20.0)]);
    pen.curve([(2.0, 20.0), (8.0, 20.0), (8.0, 12.0), (12.0, 12.0)], false);
    pen.curve(
        [(12.0, 12.0), (16.0, 12.0), (16.0, 20.0), (22.0, 20.0)],
        false,
    );
    pen.dot((12.0, 12.0), 2.4);
    pen.arrow((12.0, 10.0), (12.0, 1.5));
}

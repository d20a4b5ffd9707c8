//! The region tool's icon: a loop around a curve, and the way the region moves.

use crate::tools::icon::Pen;

/// Draws the icon.
pub fn draw(pen: &Pen<'_>) {
    pen.arc((10.5, 14.0), (8.5, 7.5), 0.0, std::f32::consts::TAU, true);
    pen.curve(
        [(5.5, 16.0), (8.0, 10.5), (11.0, 17.0), (14.0, 11.0)],
        false,
    );
    pen.arrow((14.0, 11.0), (22.0, 2.5));
}

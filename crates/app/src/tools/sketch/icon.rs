//! The sketch tool's icon: a pencil drawing a round shape.

use crate::tools::icon::Pen;

/// Draws the icon.
pub fn draw(pen: &Pen<'_>) {
    pen.arc((9.0, 15.5), (6.5, 5.5), 0.0, std::f32::consts::TAU, true);
    pen.outline(&[(21.7, 4.7), (19.3, 2.3), (12.8, 8.8), (15.2, 11.2)]);
    pen.fill(&[(12.8, 8.8), (15.2, 11.2), (11.0, 13.0)]);
}

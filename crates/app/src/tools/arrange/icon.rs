//! The arrange tool's icon: arrows four ways, as moving a model anywhere.

use crate::tools::icon::Pen;

/// Draws the icon.
pub fn draw(pen: &Pen<'_>) {
    pen.line(&[(12.0, 4.0), (12.0, 20.0)]);
    pen.line(&[(4.0, 12.0), (20.0, 12.0)]);
    for (from, tip) in [
        ((12.0, 12.0), (12.0, 1.5)),
        ((12.0, 12.0), (12.0, 22.5)),
        ((12.0, 12.0), (1.5, 12.0)),
        ((12.0, 12.0), (22.5, 12.0)),
    ] {
        pen.arrow_head(from, tip);
    }
}

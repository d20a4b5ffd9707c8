//! The bend tool's icon: a straight limb's handle (dim) bent at its dots.

use crate::tools::icon::Pen;

/// Draws the icon.
pub fn draw(pen: &Pen<'_>) {
    pen.dim_line(&[(3.0, 20.0), (10.0, 16.0), (16.5, 14.0), (22.5, 13.0)]);
    let bent = [(3.0, 20.0), (10.0, 16.0), (14.0, 9.0), (20.0, 4.0)];
    pen.line(&bent);
    for p in bent {
        pen.dot(p, 2.3);
    }
}

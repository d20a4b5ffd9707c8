//! The feature tool's icon: a ridge raised along a line across a surface seen in perspective.

use crate::tools::icon::Pen;

/// Draws the icon.
pub fn draw(pen: &Pen<'_>) {
    pen.dim_line(&[
        (1.5, 21.0),
        (7.5, 12.0),
        (22.5, 12.0),
        (16.5, 21.0),
        (1.5, 21.0),
    ]);
    pen.curve([(4.5, 16.5), (8.0, 16.5), (9.0, 4.0), (12.0, 4.0)], false);
    pen.curve(
        [(12.0, 4.0), (15.0, 4.0), (16.0, 16.5), (19.5, 16.5)],
        false,
    );
}

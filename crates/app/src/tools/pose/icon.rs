//! The pose tool's icon: a figure in a running pose.

use crate::tools::icon::Pen;

/// Draws the icon.
pub fn draw(pen: &Pen<'_>) {
    pen.dot((13.5, 3.5), 2.6);
    pen.line(&[(13.0, 7.5), (11.0, 14.0)]);
    pen.line(&[
        (5.5, 10.0),
        (9.0, 8.0),
        (13.0, 7.5),
        (16.0, 11.0),
        (20.0, 10.0),
    ]);
    pen.line(&[
        (4.0, 19.0),
        (7.5, 20.0),
        (11.0, 14.0),
        (15.0, 17.0),
        (14.5, 22.5),
    ]);
}

//! The three curve tools' icons: an eraser on a curve, a curve turning sharp, a curve rubbed smooth.

use crate::tools::icon::Pen;

/// Erase: an eraser whose rubber end has taken away the curve to its right.
pub fn erase(pen: &Pen<'_>) {
    pen.dim_line(&[(2.0, 21.0), (8.0, 21.0)]);
    pen.outline(&[(21.4, 7.5), (16.5, 2.6), (6.6, 12.5), (11.5, 17.4)]);
    pen.fill(&[(10.8, 8.2), (15.8, 13.2), (11.5, 17.4), (6.6, 12.5)]);
}

/// Sharp: a round bump, then a sharp peak with its corner marked.
pub fn sharp(pen: &Pen<'_>) {
    pen.curve([(1.5, 19.0), (2.5, 8.0), (10.0, 8.0), (11.0, 19.0)], true);
    pen.line(&[(11.0, 19.0), (16.5, 5.0), (22.5, 19.0)]);
    pen.dot((16.5, 5.0), 2.2);
}

/// Rub: a smooth curve over the scribble that smoothed it.
pub fn rub(pen: &Pen<'_>) {
    pen.curve([(2.0, 9.0), (8.0, 2.0), (16.0, 14.0), (22.0, 7.0)], false);
    pen.dim_line(&[
        (4.0, 20.0),
        (7.0, 14.5),
        (10.0, 20.0),
        (13.0, 14.5),
        (16.0, 20.0),
        (19.0, 14.5),
    ]);
}

//! The optimize tool's icon: a patch of even triangles.

use crate::tools::icon::Pen;

/// Draws the icon.
pub fn draw(pen: &Pen<'_>) {
    let corner = |k: f32| {
        let a = k * std::f32::consts::PI / 3.0;
        (12.0 + 10.0 * a.cos(), 12.0 + 10.0 * a.sin())
    };
    let ring: Vec<(f32, f32)> = (0..6).map(|k| corner(k as f32)).collect();
    pen.outline(&ring);
    for k in 0..3 {
        pen.dim_line(&[ring[k], ring[k + 3]]);
    }
    pen.dot((12.0, 12.0), 2.0);
}

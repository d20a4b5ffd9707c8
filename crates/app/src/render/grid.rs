//! The ground grid on the y = 0 plane, fading towards its rim.

use bytemuck::{Pod, Zeroable};

/// A coloured line vertex.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Pod, Zeroable)]
pub struct GridVertex {
    /// Position in world space.
    pub pos: [f32; 3],
    /// Straight RGBA.
    pub color: [f32; 4],
}

/// Half the grid's extent in world units.
const HALF_EXTENT: i32 = 10;

/// Line-list vertices of the grid: unit cells, brighter every fifth line, red X and blue Z axes.
pub fn grid_lines() -> Vec<GridVertex> {
    let mut out = Vec::new();
    let e = HALF_EXTENT as f32;
    for i in -HALF_EXTENT..=HALF_EXTENT {
        let t = i as f32;
        let fade = 1.0 - (t.abs() / e) * 0.7;
        let (x_axis, z_axis) = if i == 0 {
            ([0.85, 0.3, 0.3, 0.8], [0.3, 0.5, 0.9, 0.8])
        } else {
            let a = if i % 5 == 0 { 0.35 } else { 0.18 } * fade;
            ([0.7, 0.72, 0.78, a], [0.7, 0.72, 0.78, a])
        };
        // Lines parallel to X at z = t (the z = 0 one is the X axis), then parallel to Z.
        out.push(GridVertex {
            pos: [-e, 0.0, t],
            color: x_axis,
        });
        out.push(GridVertex {
            pos: [e, 0.0, t],
            color: x_axis,
        });
        out.push(GridVertex {
            pos: [t, 0.0, -e],
            color: z_axis,
        });
        out.push(GridVertex {
            pos: [t, 0.0, e],
            color: z_axis,
        });
    }
    out
}

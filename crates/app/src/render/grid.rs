//! The ground grid on the y = 0 plane: one large quad whose fragment shader draws the lines.
//!
//! Line primitives would be simpler, but grid lines run behind the eye, and SwiftShader
//! (headless Chromium's GPU) drops lines that cross the eye plane instead of clipping them;
//! triangles are clipped correctly everywhere. A procedural grid is also antialiased and
//! fades out with distance, instead of ending at a hard edge.

use bytemuck::{Pod, Zeroable};

/// A vertex of the grid quad.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Pod, Zeroable)]
pub struct GridVertex {
    /// Position in world space.
    pub pos: [f32; 3],
}

/// Half the grid's extent in world units: where `fs_grid`'s fade reaches zero (22 units
/// from the origin), so that no fragment beyond it is shaded for nothing (the grid costs
/// about a quarter of an empty scene's frame on a software adapter).
const HALF_EXTENT: f32 = 22.0;

/// The quad as two triangles.
pub fn grid_quad() -> Vec<GridVertex> {
    let e = HALF_EXTENT;
    let corners = [[-e, 0.0, -e], [e, 0.0, -e], [e, 0.0, e], [-e, 0.0, e]];
    [0, 1, 2, 0, 2, 3]
        .iter()
        .map(|&i| GridVertex { pos: corners[i] })
        .collect()
}

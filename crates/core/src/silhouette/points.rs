//! What a silhouette is: screen points with the mesh position each comes from.

use glam::{DVec2, DVec3};

use crate::curve::polyline;
use crate::mesh::VertexId;

/// One point of a silhouette curve: where it is drawn and where it lies on the mesh.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SilhouettePoint {
    /// Screen position in CSS px (origin top-left, y down), after smoothing.
    pub screen: DVec2,
    /// Distance in front of the eye along the view direction, of [`Self::world`].
    pub depth: f64,
    /// The zero crossing on the mesh: `lerp(p[edge[0]], p[edge[1]], t)` (before smoothing).
    pub world: DVec3,
    /// The edge the point lies on; `g` changes sign between its ends.
    pub edge: [VertexId; 2],
    /// Parameter of [`Self::world`] along [`Self::edge`], in `[0, 1]`.
    pub t: f64,
}

/// One visible silhouette curve.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Silhouette {
    /// Points in order, about [`SPACING_PX`](super::SPACING_PX) apart on screen. Along a curve the surface facing
    /// the viewer is on the left as seen from outside the surface, so an outline runs
    /// counter-clockwise as the viewer sees it (clockwise in y-down screen coordinates).
    pub points: Vec<SilhouettePoint>,
    /// Whether the last point connects back to the first.
    pub closed: bool,
}

impl Silhouette {
    /// Length on screen in CSS px, including the closing segment of a closed curve.
    pub fn screen_length(&self) -> f64 {
        let screen = self.points.iter().map(|p| p.screen);
        if self.closed {
            polyline::perimeter(screen)
        } else {
            polyline::length(screen)
        }
    }
}

//! A curve handle as a document keeps it: what it is on, its curve and its links (Blanco
//! §4, §5.3). The skeleton technique ([`crate::skeleton`]) places, edits and deforms with it.

use glam::DVec3;

/// On the surface, or inside along the part's middle (Blanco §4.1–4.2).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum HandleKind {
    /// Control points on the surface under the stroke: stays visible while it deforms.
    #[default]
    Surface,
    /// Control points at the centroids of the part's slices: its middle line.
    Skeleton,
}

/// A handle's curve: control points with a twist (radians) and scales (`v`, `w`) each.
#[derive(Clone, Debug, PartialEq)]
pub struct HandleCurve {
    /// The control points, in world space.
    pub points: Vec<DVec3>,
    /// Twist about the tangent at each control point, in radians.
    pub twist: Vec<f64>,
    /// Scale across the curve at each control point, along the frame's two axes.
    pub scale: Vec<[f64; 2]>,
    /// Rigid limbs (§7): straight spans bent only at the control points.
    pub is_rigid: bool,
}

/// What a handle deforms.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum HandleTarget {
    /// A model, by its index in the document.
    Model(usize),
    /// A point cloud, by its index in the document.
    Cloud(usize),
}

/// One handle: its number (creation order in the document), target, kind, curve and links.
#[derive(Clone, Debug, PartialEq)]
pub struct CurveHandle {
    /// Its number: handles are numbered in creation order within a document.
    pub id: u32,
    /// What it deforms.
    pub target: HandleTarget,
    /// On the surface or a skeleton.
    pub kind: HandleKind,
    /// Its control points, twist and scale.
    pub curve: HandleCurve,
    /// Its control points linked to other handles' (`(point, handle, their point)`).
    pub links: Vec<(usize, u32, usize)>,
}

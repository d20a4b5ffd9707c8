//! A curve handle as a document keeps it: what it is on, its curve and its links.

use super::handle::{HandleCurve, HandleKind};

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

//! Imported point sets.

use glam::DVec3;

/// Points imported from a file (a scan, say): shown, kept and exported as they are.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PointCloud {
    /// Positions in world space.
    pub positions: Vec<DVec3>,
    /// RGBA colour per point, if the file had colours.
    pub colors: Option<Vec<[f32; 4]>>,
}

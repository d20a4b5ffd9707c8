//! What a document holds: models (a mesh and its control curves) and free sketch curves.

use std::sync::Arc;

use glam::DVec3;
use serde::Serialize;

use super::Appearance;
use crate::mesh::{Mesh, VertexId};

/// An ink stroke placed in 3D: the processed screen stroke projected onto a plane.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SketchCurve {
    /// Points in world space, in drawing order.
    pub points: Vec<DVec3>,
    /// Pen pressure (0..=1) at each point; same length as `points`.
    pub pressures: Vec<f64>,
}

/// A curve on a model's surface that defines or deforms its shape (FiberMesh).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ControlCurve {
    /// Points in world space, in order.
    pub points: Vec<DVec3>,
    /// The mesh vertices the curve runs through (a chain of mesh edges), in the order of
    /// `points`; empty when the curve is not embedded in the mesh (for example imported).
    pub vertices: Vec<VertexId>,
    /// Whether the last point connects back to the first.
    pub closed: bool,
    /// Whether the surface has a crease along the curve (instead of being smooth across it).
    pub sharp: bool,
}

/// A surface model: a triangle mesh and the control curves that shape it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Model {
    /// The surface, in world space.
    pub mesh: Mesh,
    /// Control curves on the surface.
    pub curves: Vec<ControlCurve>,
    /// The name it had in an imported file.
    pub name: Option<String>,
    /// How it looked in an imported file; `None` for models made here.
    pub appearance: Option<Arc<Appearance>>,
}

/// Points imported from a file (a scan, say): shown, kept and exported as they are.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PointCloud {
    /// Positions in world space.
    pub positions: Vec<DVec3>,
    /// RGBA colour per point, if the file had colours.
    pub colors: Option<Vec<[f32; 4]>>,
}

/// Everything the user has made. Cheap to clone: a clone shares every model and sketch.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Document {
    /// Surface models, in creation order.
    pub models: Vec<Arc<Model>>,
    /// Free sketch curves, in creation order.
    pub sketches: Vec<Arc<SketchCurve>>,
    /// Imported point sets.
    pub point_clouds: Vec<Arc<PointCloud>>,
}

/// Counts shown in the app's status line and printed by the CLI.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Stats {
    /// Number of models.
    pub models: usize,
    /// Vertices over all models.
    pub vertices: usize,
    /// Triangles over all models.
    pub triangles: usize,
    /// Control curves over all models plus sketch curves.
    pub curves: usize,
}

impl Document {
    /// Counts of models, vertices, triangles and curves.
    pub fn stats(&self) -> Stats {
        let mut stats = Stats {
            models: self.models.len(),
            curves: self.sketches.len(),
            ..Stats::default()
        };
        for model in &self.models {
            stats.vertices += model.mesh.n_vertices();
            stats.triangles += model.mesh.n_faces();
            stats.curves += model.curves.len();
        }
        stats
    }

    /// Whether there are no models, sketches or points.
    pub fn is_empty(&self) -> bool {
        self.models.is_empty() && self.sketches.is_empty() && self.point_clouds.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;

    #[test]
    fn stats_count_everything() {
        let model = Model {
            mesh: primitives::icosphere(1.0, 1),
            curves: vec![ControlCurve::default(), ControlCurve::default()],
            ..Model::default()
        };
        let document = Document {
            models: vec![Arc::new(model.clone()), Arc::new(model)],
            sketches: vec![Arc::new(SketchCurve::default())],
            ..Document::default()
        };
        let stats = document.stats();
        assert_eq!(
            stats,
            Stats {
                models: 2,
                vertices: 84,
                triangles: 160,
                curves: 5
            }
        );
        assert!(!document.is_empty());
        assert!(Document::default().is_empty());
        assert_eq!(
            serde_json::to_string(&stats).unwrap(),
            r#"{"models":2,"vertices":84,"triangles":160,"curves":5}"#
        );
    }
}

//! Everything the user has made, and its counts.

use std::sync::Arc;

use serde::Serialize;

use super::curve_handle::CurveHandle;
use super::mirror_plane::MirrorPlane;
use super::point_cloud::PointCloud;
use super::sketch::SketchCurve;
use super::surface::Model;

/// Everything the user has made. Cheap to clone: a clone shares every model and sketch.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Document {
    /// Surface models, in creation order.
    pub models: Vec<Arc<Model>>,
    /// Free sketch curves, in creation order.
    pub sketches: Vec<Arc<SketchCurve>>,
    /// Imported point sets.
    pub point_clouds: Vec<Arc<PointCloud>>,
    /// Curve handles on models and point clouds (Blanco), in creation order.
    pub handles: Vec<Arc<CurveHandle>>,
    /// How many handles were ever made: the number of the next one.
    pub handles_made: u32,
    /// The plane the last op made with symmetry on mirrored about (or a file's): the
    /// plane its symmetric models and mirror twins pair up across.
    pub symmetry: Option<MirrorPlane>,
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
    use crate::model::ControlCurve;

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

//! Surface models: a triangle mesh and the control curves that shape it.

use std::sync::Arc;

use super::appearance::Appearance;
use super::as_imported::AsImported;
use super::control_curve::ControlCurve;
use super::finish::Finish;
use super::keyframe::Keyframe;
use crate::mesh::Mesh;

/// A surface model: a triangle mesh and the control curves that shape it (FiberMesh).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Model {
    /// The surface, in world space.
    pub mesh: Mesh,
    /// Control curves on the surface: chains of `mesh`'s vertices, so they move with it.
    pub curves: Vec<ControlCurve>,
    /// The name it had in an imported file.
    pub name: Option<String>,
    /// How it looked in an imported file; `None` for models made here.
    pub appearance: Option<Arc<Appearance>>,
    /// The triangles of an imported soup as they came, when `mesh` had to be repaired
    /// from them (see [`AsImported`]); `None` otherwise.
    pub as_imported: Option<Arc<AsImported>>,
    /// Its animation's key frames, by increasing time; a key whose pose no longer has one
    /// position per vertex (the surface was remeshed since) is ignored.
    pub keyframes: Vec<Keyframe>,
    /// Linear RGB per vertex of `mesh`, painted here or read from a file's `COLOR_0`;
    /// `None` while unpainted. Shared, as the colours of a large scan are many megabytes and
    /// most ops leave them as they are.
    pub colors: Option<Arc<Vec<[f32; 3]>>>,
    /// Its material; `None`: [`Finish::CLAY`].
    pub finish: Option<Finish>,
}

impl Model {
    /// The input as it came, while `mesh` still fits it.
    pub fn as_imported(&self) -> Option<&AsImported> {
        self.as_imported.as_deref().filter(|a| a.fits(&self.mesh))
    }

    /// The painted colour of each vertex, while there is one per vertex.
    pub fn vertex_colors(&self) -> Option<&[[f32; 3]]> {
        let colors = self.colors.as_deref()?;
        (colors.len() == self.mesh.n_vertices()).then_some(colors.as_slice())
    }

    /// Its material: the one set, or clay.
    pub fn finish(&self) -> Finish {
        self.finish.unwrap_or_default()
    }

    /// The key frames that fit the mesh as it is, by increasing time.
    pub fn keyframes(&self) -> impl Iterator<Item = &Keyframe> {
        let n = self.mesh.n_vertices();
        self.keyframes
            .iter()
            .filter(move |k| k.positions.len() == n)
    }
}

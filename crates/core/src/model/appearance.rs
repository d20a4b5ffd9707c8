//! How an imported model looked: per-corner normals, UVs and colours and its materials.
//!
//! Sketchmesh renders every model as clay, but a model that came from a file should leave
//! with the look it came with. Attributes are stored per triangle corner (a welded vertex may
//! have several UVs across a seam) together with the triangles they belong to, so the export
//! can tell whether they still apply: edits that keep the connectivity (deformations) keep
//! UVs, colours and materials; imported normals are kept only while the positions are
//! unchanged too.

use std::hash::{Hash as _, Hasher as _};
use std::sync::Arc;

use crate::mesh::Mesh;

/// The imported look of a model (see the module docs).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Appearance {
    /// The mesh triangles the corner attributes belong to.
    pub triangles: Vec<[u32; 3]>,
    /// [`positions_hash`] of the mesh the normals belong to.
    pub positions_hash: u64,
    /// Unit normals per corner (`3 * face + k`).
    pub normals: Option<Vec<[f32; 3]>>,
    /// TEXCOORD_0 per corner.
    pub uvs: Option<Vec<[f32; 2]>>,
    /// RGBA colour per corner.
    pub colors: Option<Vec<[f32; 4]>>,
    /// Index into `materials` per face; `None` for the glTF default material.
    pub face_materials: Vec<Option<u32>>,
    /// The materials used.
    pub materials: Vec<Material>,
}

impl Appearance {
    /// Whether the corner attributes and materials still apply to `mesh`.
    pub fn fits(&self, mesh: &Mesh) -> bool {
        self.triangles == mesh.triangles()
    }

    /// Whether the imported normals still apply (same triangles and same positions).
    pub fn normals_fit(&self, mesh: &Mesh) -> bool {
        self.normals.is_some() && self.fits(mesh) && self.positions_hash == positions_hash(mesh)
    }
}

/// A hash of the exact position bits, to tell whether a mesh has been deformed.
pub fn positions_hash(mesh: &Mesh) -> u64 {
    positions_hash_of(mesh.positions())
}

/// [`positions_hash`] of positions that are not a mesh's (an imported soup's).
pub fn positions_hash_of(positions: &[glam::DVec3]) -> u64 {
    let mut hasher = std::collections::hash_map::DefaultHasher::new();
    for p in positions {
        p.to_array().map(f64::to_bits).hash(&mut hasher);
    }
    hasher.finish()
}

/// A metallic-roughness material as glTF describes it.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// Its name.
    pub name: Option<String>,
    /// Linear RGBA base colour factor.
    pub base_color: [f32; 4],
    /// The base colour texture, if any.
    pub base_color_texture: Option<Texture>,
    /// Metalness 0..1.
    pub metallic: f32,
    /// Roughness 0..1.
    pub roughness: f32,
    /// Emissive RGB factor.
    pub emissive: [f32; 3],
    /// Whether back faces are drawn.
    pub double_sided: bool,
    /// How alpha is used.
    pub alpha_mode: AlphaMode,
}

/// glTF alpha modes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AlphaMode {
    /// Alpha ignored.
    Opaque,
    /// Alpha tested against the cutoff.
    Mask(f32),
    /// Alpha blended.
    Blend,
}

/// A texture: an encoded image and how it is sampled.
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    /// The encoded image (PNG or JPEG).
    pub image: Arc<Image>,
    /// glTF magnification filter code, if given.
    pub mag_filter: Option<u32>,
    /// glTF minification filter code, if given.
    pub min_filter: Option<u32>,
    /// glTF wrap mode codes (s, t).
    pub wrap: [u32; 2],
}

/// An encoded image file.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    /// `image/png` or `image/jpeg`.
    pub mime_type: String,
    /// The file's bytes.
    pub bytes: Vec<u8>,
}

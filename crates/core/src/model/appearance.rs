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

    /// The linear RGBA colour each triangle corner (`3 * face + k`) is drawn with: its
    /// material's base colour factor times its vertex colour (glTF's base colour, which the
    /// texture, if any, then multiplies). `None` when the file gave no coloured or textured
    /// material and no vertex colours: such a model is drawn as clay rather than in glTF's
    /// default white.
    pub fn corner_colors(&self) -> Option<Vec<[f32; 4]>> {
        if !self.is_coloured() {
            return None;
        }
        let corners = 3 * self.triangles.len();
        let factor = |face: usize| {
            (self.face_materials.get(face).copied().flatten())
                .and_then(|m| self.materials.get(m as usize))
                .map_or([1.0; 4], |m| m.base_color)
        };
        Some(
            (0..corners)
                .map(|c| {
                    let vertex = self.colors.as_ref().and_then(|v| v.get(c).copied());
                    let [r, g, b, a] = vertex.unwrap_or([1.0; 4]);
                    let [fr, fg, fb, fa] = factor(c / 3);
                    [r * fr, g * fg, b * fb, a * fa]
                })
                .collect(),
        )
    }

    /// Whether the file gave vertex colours or a coloured or textured material.
    fn is_coloured(&self) -> bool {
        let coloured = |m: &Material| m.base_color != [1.0; 4] || m.base_color_texture.is_some();
        self.colors.is_some() || self.materials.iter().any(coloured)
    }

    /// Whether the look changes how the model is drawn (colours, textures or the file's
    /// normals): a plain scan's is drawn as clay, so its fit (a comparison of every
    /// triangle) need not be asked when its arrays are built.
    pub fn is_drawn(&self) -> bool {
        self.is_coloured() || self.normals.is_some() || self.uvs.is_some()
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

#[cfg(test)]
mod tests {
    use super::*;

    fn material(base_color: [f32; 4]) -> Material {
        Material {
            name: None,
            base_color,
            base_color_texture: None,
            metallic: 0.0,
            roughness: 1.0,
            emissive: [0.0; 3],
            double_sided: false,
            alpha_mode: AlphaMode::Opaque,
        }
    }

    #[test]
    fn corners_take_their_material_times_their_vertex_colour() {
        let mut look = Appearance {
            triangles: vec![[0, 1, 2], [0, 2, 3]],
            face_materials: vec![Some(0), None],
            materials: vec![material([0.5, 0.25, 1.0, 1.0])],
            ..Appearance::default()
        };
        let colors = look.corner_colors().unwrap();
        assert_eq!(colors.len(), 6);
        assert_eq!(colors[2], [0.5, 0.25, 1.0, 1.0]);
        assert_eq!(colors[3], [1.0; 4], "the default material is white");
        look.colors = Some(vec![[0.5, 0.5, 0.5, 1.0]; 6]);
        assert_eq!(look.corner_colors().unwrap()[0], [0.25, 0.125, 0.5, 1.0]);
        // White materials and no vertex colours: clay.
        look.colors = None;
        look.materials = vec![material([1.0; 4])];
        assert_eq!(look.corner_colors(), None);
    }
}

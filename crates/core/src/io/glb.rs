//! A binary glTF 2.0 file being written: the JSON root and the BIN chunk, with accessors
//! and buffer views laid out as [`super::write_glb`] describes (one tightly packed view per
//! accessor on a 4-byte boundary, `min`/`max` of the `f32` values written, `u16` indices when
//! they fit). It knows glTF, not documents: `gltf_write.rs` and `appearance_write.rs` fill it.

use std::collections::{BTreeMap, HashMap};

use glam::{DVec3, Vec3};
use gltf::json;
use json::validation::{Checked::Valid, USize64};

use super::extras::{CLAY_MATERIAL_NAME, FINISH_MATERIAL_NAME};
use crate::geometry::vertex_normals_of;
use crate::model::{Finish, Image};

/// A .glb being written: [`Writer::finish`] packs it.
#[derive(Default)]
pub(super) struct Writer {
    /// The glTF JSON.
    pub(super) root: json::Root,
    /// The BIN chunk.
    bin: Vec<u8>,
    /// The materials of models made here, by their finish's bits, each written once.
    materials: HashMap<[u32; 6], json::Index<json::Material>>,
    /// Images already written, by the address of their shared bytes.
    pub(super) images: HashMap<*const Image, json::Index<json::Image>>,
}

impl Writer {
    /// A triangle primitive over the given attributes.
    pub(super) fn triangle_primitive(
        &mut self,
        attributes: BTreeMap<
            json::validation::Checked<json::mesh::Semantic>,
            json::Index<json::Accessor>,
        >,
        indices: &[u32],
        n_vertices: usize,
        material: Option<json::Index<json::Material>>,
    ) -> json::mesh::Primitive {
        json::mesh::Primitive {
            attributes,
            extensions: None,
            extras: None,
            indices: Some(self.indices(indices, n_vertices)),
            material,
            mode: Valid(json::mesh::Mode::Triangles),
            targets: None,
        }
    }

    /// A mesh of `primitives`, whose `n_targets` morph targets (if any) rest at weight 0.
    pub(super) fn mesh(
        &mut self,
        name: String,
        primitives: Vec<json::mesh::Primitive>,
        n_targets: usize,
    ) -> json::Index<json::Mesh> {
        self.root.push(json::Mesh {
            extensions: None,
            extras: None,
            name: Some(name),
            primitives,
            weights: (n_targets > 0).then(|| vec![0.0; n_targets]),
        })
    }

    /// The material of a model made here with `finish` (`None`: clay), written once per
    /// finish, when first used.
    pub(super) fn material(&mut self, finish: Option<Finish>) -> json::Index<json::Material> {
        let shown = finish.unwrap_or_default();
        let [r, g, b, a] = shown.base_color;
        let key = [r, g, b, a, shown.roughness, shown.metalness].map(f32::to_bits);
        if let Some(&material) = self.materials.get(&key) {
            return material;
        }
        let name = if finish.is_some() {
            FINISH_MATERIAL_NAME
        } else {
            CLAY_MATERIAL_NAME
        };
        let material = self.root.push(json::Material {
            name: Some(String::from(name)),
            // Open surfaces are common while modeling; show their back faces too.
            double_sided: true,
            alpha_mode: Valid(if a < 1.0 {
                json::material::AlphaMode::Blend
            } else {
                json::material::AlphaMode::Opaque
            }),
            pbr_metallic_roughness: json::material::PbrMetallicRoughness {
                base_color_factor: json::material::PbrBaseColorFactor(shown.base_color),
                metallic_factor: json::material::StrengthFactor(shown.metalness),
                roughness_factor: json::material::StrengthFactor(shown.roughness),
                ..Default::default()
            },
            ..Default::default()
        });
        self.materials.insert(key, material);
        material
    }

    /// A POSITION accessor, with `min` and `max` of the written `f32` values.
    pub(super) fn positions(&mut self, values: &[Vec3]) -> json::Index<json::Accessor> {
        let min = values.iter().fold(Vec3::INFINITY, |lo, &p| lo.min(p));
        let max = values.iter().fold(Vec3::NEG_INFINITY, |hi, &p| hi.max(p));
        self.vec3s(values, Some((min, max)))
    }

    pub(super) fn vec3s(
        &mut self,
        values: &[Vec3],
        bounds: Option<(Vec3, Vec3)>,
    ) -> json::Index<json::Accessor> {
        let mut bytes = Vec::with_capacity(values.len() * 12);
        for value in values {
            for component in value.to_array() {
                bytes.extend_from_slice(&component.to_le_bytes());
            }
        }
        let view = self.view(&bytes, Some(json::buffer::Target::ArrayBuffer));
        let (min, max) = match bounds {
            Some((min, max)) => (Some(f32_array(min)), Some(f32_array(max))),
            None => (None, None),
        };
        self.accessor(
            view,
            values.len(),
            json::accessor::ComponentType::F32,
            json::accessor::Type::Vec3,
            min,
            max,
        )
    }

    fn indices(&mut self, indices: &[u32], n_vertices: usize) -> json::Index<json::Accessor> {
        // 65535 is the u16 primitive-restart value, which glTF forbids as an index.
        let (bytes, component_type) = if n_vertices <= usize::from(u16::MAX) {
            let bytes: Vec<u8> = indices
                .iter()
                .flat_map(|&i| (i as u16).to_le_bytes())
                .collect();
            (bytes, json::accessor::ComponentType::U16)
        } else {
            let bytes: Vec<u8> = indices.iter().flat_map(|&i| i.to_le_bytes()).collect();
            (bytes, json::accessor::ComponentType::U32)
        };
        let view = self.view(&bytes, Some(json::buffer::Target::ElementArrayBuffer));
        self.accessor(
            view,
            indices.len(),
            component_type,
            json::accessor::Type::Scalar,
            None,
            None,
        )
    }

    fn accessor(
        &mut self,
        view: json::Index<json::buffer::View>,
        count: usize,
        component_type: json::accessor::ComponentType,
        type_: json::accessor::Type,
        min: Option<serde_json::Value>,
        max: Option<serde_json::Value>,
    ) -> json::Index<json::Accessor> {
        self.root.push(json::Accessor {
            buffer_view: Some(view),
            byte_offset: None,
            count: USize64::from(count),
            component_type: Valid(json::accessor::GenericComponentType(component_type)),
            extensions: None,
            extras: None,
            type_: Valid(type_),
            min,
            max,
            name: None,
            normalized: false,
            sparse: None,
        })
    }

    /// VEC2 or VEC4 float attributes (UVs, colours), without bounds.
    pub(super) fn floats<const N: usize>(
        &mut self,
        values: &[[f32; N]],
    ) -> json::Index<json::Accessor> {
        let bytes: Vec<u8> = values
            .iter()
            .flatten()
            .flat_map(|c| c.to_le_bytes())
            .collect();
        let view = self.view(&bytes, Some(json::buffer::Target::ArrayBuffer));
        let type_ = if N == 2 {
            json::accessor::Type::Vec2
        } else {
            json::accessor::Type::Vec4
        };
        self.accessor(
            view,
            values.len(),
            json::accessor::ComponentType::F32,
            type_,
            None,
            None,
        )
    }

    /// SCALAR floats (animation times and weights), with `min` and `max` when `bounded`
    /// (animation inputs must have them); their view has no target, as animation data must.
    pub(super) fn scalars(&mut self, values: &[f32], bounded: bool) -> json::Index<json::Accessor> {
        let bytes: Vec<u8> = values.iter().flat_map(|c| c.to_le_bytes()).collect();
        let view = self.view(&bytes, None);
        let bound = |fold: fn(f32, f32) -> f32, start: f32| {
            bounded.then(|| {
                serde_json::Value::from(vec![f64::from(values.iter().copied().fold(start, fold))])
            })
        };
        let (min, max) = (
            bound(f32::min, f32::INFINITY),
            bound(f32::max, f32::NEG_INFINITY),
        );
        self.accessor(
            view,
            values.len(),
            json::accessor::ComponentType::F32,
            json::accessor::Type::Scalar,
            min,
            max,
        )
    }

    /// Appends `bytes` to the BIN chunk as a new buffer view, padded to 4 bytes (images have
    /// no target).
    pub(super) fn view(
        &mut self,
        bytes: &[u8],
        target: Option<json::buffer::Target>,
    ) -> json::Index<json::buffer::View> {
        let offset = self.bin.len();
        self.bin.extend_from_slice(bytes);
        pad(&mut self.bin, 0);
        self.root.push(json::buffer::View {
            buffer: json::Index::new(0),
            byte_length: USize64::from(bytes.len()),
            byte_offset: Some(USize64::from(offset)),
            byte_stride: None,
            name: None,
            target: target.map(Valid),
            extensions: None,
            extras: None,
        })
    }

    pub(super) fn finish(mut self, nodes: Vec<json::Index<json::Node>>) -> Vec<u8> {
        if !self.bin.is_empty() {
            self.root.push(json::Buffer {
                byte_length: USize64::from(self.bin.len()),
                name: None,
                uri: None,
                extensions: None,
                extras: None,
            });
        }
        let scene = self.root.push(json::Scene {
            extensions: None,
            extras: None,
            name: None,
            nodes,
        });
        self.root.scene = Some(scene);
        self.root.asset.generator = Some(format!("Sketchmesh {}", env!("CARGO_PKG_VERSION")));
        let json = serde_json::to_vec(&self.root).unwrap_or_else(|error| {
            // Unreachable: every value is `Valid` and every map key a string.
            debug_assert!(false, "glTF JSON serialization failed: {error}");
            br#"{"asset":{"version":"2.0"}}"#.to_vec()
        });
        pack_glb(json, self.bin)
    }
}

/// Packs a GLB: 12-byte header, JSON chunk padded with spaces, BIN chunk (if any) padded
/// with zeros.
fn pack_glb(mut json: Vec<u8>, mut bin: Vec<u8>) -> Vec<u8> {
    pad(&mut json, b' ');
    pad(&mut bin, 0);
    let bin_chunk_length = if bin.is_empty() { 0 } else { 8 + bin.len() };
    let total = 12 + 8 + json.len() + bin_chunk_length;
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&(total as u32).to_le_bytes());
    out.extend_from_slice(&(json.len() as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&json);
    if !bin.is_empty() {
        out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
        out.extend_from_slice(b"BIN\0");
        out.extend_from_slice(&bin);
    }
    out
}

fn pad(bytes: &mut Vec<u8>, with: u8) {
    while !bytes.len().is_multiple_of(4) {
        bytes.push(with);
    }
}

/// `[x, y, z]` as JSON numbers that read back as exactly these `f32` values.
fn f32_array(v: Vec3) -> serde_json::Value {
    serde_json::Value::from(v.to_array().map(f64::from).to_vec())
}

/// The triangles a model is written as: its mesh's, or an imported soup's as it came.
pub(super) struct Written<'a> {
    /// Positions, indexed by `triangles`.
    pub positions: std::borrow::Cow<'a, [DVec3]>,
    /// The triangles.
    pub triangles: &'a [[u32; 3]],
}

/// Positions as written (`f32`) and unit normals computed from exactly those positions, so a
/// file imported and exported again gets the same normals, bit for bit.
pub(super) fn f32_positions_and_normals(
    positions: &[DVec3],
    triangles: &[[u32; 3]],
) -> (Vec<Vec3>, Vec<Vec3>) {
    let positions: Vec<Vec3> = positions.iter().map(|p| p.as_vec3()).collect();
    let rounded: Vec<DVec3> = positions.iter().map(|q| q.as_dvec3()).collect();
    let mut normals = Vec::new();
    vertex_normals_of(triangles, &rounded, &mut normals);
    (positions, normals.into_iter().map(unit_f32).collect())
}

/// A normal as a unit `f32` vector; a degenerate normal (a vertex whose faces have no area)
/// becomes +Z, because glTF requires unit length.
fn unit_f32(normal: DVec3) -> Vec3 {
    match normal.try_normalize() {
        Some(unit) => unit.as_vec3(),
        None => Vec3::Z,
    }
}

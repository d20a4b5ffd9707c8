//! Writing an imported model with the look it came with: vertices split again where corners
//! differ in normal, UV or colour, one primitive per material, materials with their
//! base-colour textures embedded in the BIN chunk.

use std::collections::{BTreeMap, HashMap};
use std::sync::Arc;

use glam::Vec3;
use gltf::json;
use json::validation::Checked::Valid;

use super::animation_write::{Baked, morph_targets};
use super::glb::{Writer, Written, f32_positions_and_normals};
use crate::model::{AlphaMode, Appearance, Material, Texture, positions_hash_of};

/// The vertex arrays of an imported model after splitting corners that differ.
struct SplitVertices {
    positions: Vec<Vec3>,
    normals: Vec<Vec3>,
    uvs: Option<Vec<[f32; 2]>>,
    colors: Option<Vec<[f32; 4]>>,
    /// The split vertex of each corner.
    corner_vertex: Vec<u32>,
    /// The written vertex each split vertex was made from.
    source: Vec<u32>,
}

/// One primitive per material (faces without one last), sharing the vertex accessors, and
/// the animation's poses as morph targets of positions (the file's own normals are kept
/// as they came, so they are not morphed).
pub(super) fn imported_primitives(
    writer: &mut Writer,
    surface: &Written,
    appearance: &Appearance,
    baked: Option<&Baked>,
) -> Vec<json::mesh::Primitive> {
    let split = split_vertices(surface, appearance);
    let targets = baked.map(|baked| {
        let poses = baked.poses.iter().map(|pose| {
            let positions = split
                .source
                .iter()
                .map(|&v| pose[v as usize].as_vec3())
                .collect();
            (positions, None)
        });
        morph_targets(writer, &split.positions, poses, None)
    });
    let mut attributes = BTreeMap::new();
    attributes.insert(
        Valid(json::mesh::Semantic::Positions),
        writer.positions(&split.positions),
    );
    attributes.insert(
        Valid(json::mesh::Semantic::Normals),
        writer.vec3s(&split.normals, None),
    );
    if let Some(uvs) = &split.uvs {
        attributes.insert(
            Valid(json::mesh::Semantic::TexCoords(0)),
            writer.floats(uvs),
        );
    }
    if let Some(colors) = &split.colors {
        attributes.insert(
            Valid(json::mesh::Semantic::Colors(0)),
            writer.floats(colors),
        );
    }
    let mut groups: BTreeMap<Option<u32>, Vec<u32>> = BTreeMap::new();
    for (f, &material) in appearance.face_materials.iter().enumerate() {
        // `None` sorts first in a BTreeMap; write it last by keying it past every index.
        groups
            .entry(material.or(Some(u32::MAX)))
            .or_default()
            .extend_from_slice(&split.corner_vertex[3 * f..3 * f + 3]);
    }
    let n_vertices = split.positions.len();
    groups
        .into_iter()
        .map(|(material, indices)| {
            let material = material
                .and_then(|m| appearance.materials.get(m as usize))
                .map(|m| imported_material(writer, m));
            let mut primitive =
                writer.triangle_primitive(attributes.clone(), &indices, n_vertices, material);
            primitive.targets = targets.clone();
            primitive
        })
        .collect()
}

fn imported_material(writer: &mut Writer, material: &Material) -> json::Index<json::Material> {
    let base_color_texture =
        material
            .base_color_texture
            .as_ref()
            .map(|texture| json::texture::Info {
                index: write_texture(writer, texture),
                tex_coord: 0,
                extensions: None,
                extras: None,
            });
    let (alpha_mode, alpha_cutoff) = match material.alpha_mode {
        AlphaMode::Opaque => (json::material::AlphaMode::Opaque, None),
        AlphaMode::Mask(cutoff) => (
            json::material::AlphaMode::Mask,
            Some(json::material::AlphaCutoff(cutoff)),
        ),
        AlphaMode::Blend => (json::material::AlphaMode::Blend, None),
    };
    writer.root.push(json::Material {
        name: material.name.clone(),
        alpha_mode: Valid(alpha_mode),
        alpha_cutoff,
        double_sided: material.double_sided,
        emissive_factor: json::material::EmissiveFactor(material.emissive),
        pbr_metallic_roughness: json::material::PbrMetallicRoughness {
            base_color_factor: json::material::PbrBaseColorFactor(material.base_color),
            base_color_texture,
            metallic_factor: json::material::StrengthFactor(material.metallic),
            roughness_factor: json::material::StrengthFactor(material.roughness),
            ..Default::default()
        },
        ..Default::default()
    })
}

fn write_texture(writer: &mut Writer, texture: &Texture) -> json::Index<json::Texture> {
    let key = Arc::as_ptr(&texture.image);
    let source = match writer.images.get(&key) {
        Some(&image) => image,
        None => {
            let view = writer.view(&texture.image.bytes, None);
            let image = writer.root.push(json::Image {
                buffer_view: Some(view),
                mime_type: Some(json::image::MimeType(texture.image.mime_type.clone())),
                name: None,
                uri: None,
                extensions: None,
                extras: None,
            });
            writer.images.insert(key, image);
            image
        }
    };
    let sampler = writer.root.push(json::texture::Sampler {
        mag_filter: texture.mag_filter.and_then(mag_filter).map(Valid),
        min_filter: texture.min_filter.and_then(min_filter).map(Valid),
        wrap_s: Valid(wrapping(texture.wrap[0])),
        wrap_t: Valid(wrapping(texture.wrap[1])),
        ..Default::default()
    });
    writer.root.push(json::Texture {
        name: None,
        sampler: Some(sampler),
        source,
        extensions: None,
        extras: None,
    })
}

/// Splits mesh vertices whose corners carry different attributes, in corner order.
fn split_vertices(surface: &Written, appearance: &Appearance) -> SplitVertices {
    let (positions, vertex_normals) =
        f32_positions_and_normals(&surface.positions, surface.triangles);
    let corner_normals = appearance
        .normals
        .as_ref()
        .filter(|_| appearance.positions_hash == positions_hash_of(&surface.positions));
    let mut split = SplitVertices {
        positions: Vec::new(),
        normals: Vec::new(),
        uvs: appearance.uvs.as_ref().map(|_| Vec::new()),
        colors: appearance.colors.as_ref().map(|_| Vec::new()),
        corner_vertex: Vec::with_capacity(3 * surface.triangles.len()),
        source: Vec::new(),
    };
    let mut index_of: HashMap<(u32, [u32; 9]), u32> = HashMap::new();
    for (corner, &v) in surface.triangles.as_flattened().iter().enumerate() {
        let normal = match corner_normals {
            Some(normals) => unit_or_vertex(normals[corner], vertex_normals[v as usize]),
            None => vertex_normals[v as usize],
        };
        let uv = appearance.uvs.as_ref().map_or([0.0; 2], |uvs| uvs[corner]);
        let color = appearance.colors.as_ref().map_or([0.0; 4], |c| c[corner]);
        let mut key = [0u32; 9];
        for (slot, value) in key
            .iter_mut()
            .zip(normal.to_array().into_iter().chain(uv).chain(color))
        {
            *slot = value.to_bits();
        }
        let index = *index_of.entry((v, key)).or_insert_with(|| {
            split.positions.push(positions[v as usize]);
            split.source.push(v);
            split.normals.push(normal);
            if let Some(uvs) = &mut split.uvs {
                uvs.push(uv);
            }
            if let Some(colors) = &mut split.colors {
                colors.push(color);
            }
            (split.positions.len() - 1) as u32
        });
        split.corner_vertex.push(index);
    }
    split
}

/// An imported normal if it has unit length (to the validator's tolerance), else the
/// computed one.
fn unit_or_vertex(normal: [f32; 3], fallback: Vec3) -> Vec3 {
    let n = Vec3::from(normal);
    if (n.length() - 1.0).abs() < 5e-4 {
        n
    } else {
        fallback
    }
}

fn mag_filter(code: u32) -> Option<json::texture::MagFilter> {
    match code {
        9728 => Some(json::texture::MagFilter::Nearest),
        9729 => Some(json::texture::MagFilter::Linear),
        _ => None,
    }
}

fn min_filter(code: u32) -> Option<json::texture::MinFilter> {
    use json::texture::MinFilter;
    [
        MinFilter::Nearest,
        MinFilter::Linear,
        MinFilter::NearestMipmapNearest,
        MinFilter::LinearMipmapNearest,
        MinFilter::NearestMipmapLinear,
        MinFilter::LinearMipmapLinear,
    ]
    .into_iter()
    .find(|filter| filter.as_gl_enum() == code)
}

fn wrapping(code: u32) -> json::texture::WrappingMode {
    use json::texture::WrappingMode;
    [
        WrappingMode::ClampToEdge,
        WrappingMode::MirroredRepeat,
        WrappingMode::Repeat,
    ]
    .into_iter()
    .find(|mode| mode.as_gl_enum() == code)
    .unwrap_or(WrappingMode::Repeat)
}

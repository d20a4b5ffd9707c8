//! Parsing a .glb or .gltf file into a checked `gltf::Document`, leniently where it is safe.
//!
//! The `gltf` crate's own validation is all-or-nothing and its wrappers index arrays without
//! checks, so this module runs the validation itself: every broken reference or invalid
//! enum is refused (they would make the wrappers panic), but a missing or malformed
//! `min`/`max` on POSITION, which common exporters omit and which this reader never uses, is
//! tolerated. Required extensions are checked against what the importer really implements.

use std::borrow::Cow;

use gltf::json::validation::{Error as ValidationError, Validate as _};

use super::error::GltfError;
use super::input::ImportLimits;

/// Required extensions the importer honours: mesh quantization is read by the accessor
/// reader; the others only change shading, which a modeller may ignore.
const SUPPORTED_REQUIRED_EXTENSIONS: &[&str] = &[
    "KHR_mesh_quantization",
    "KHR_materials_unlit",
    "KHR_materials_emissive_strength",
    "KHR_materials_ior",
    "KHR_materials_specular",
    "KHR_materials_transmission",
    "KHR_materials_volume",
    "KHR_materials_clearcoat",
    "KHR_materials_sheen",
    "KHR_materials_pbrSpecularGlossiness",
    "KHR_texture_transform",
    "KHR_lights_punctual",
];

/// A parsed file: the checked document and the GLB BIN chunk, if any.
pub(crate) struct Parsed<'a> {
    pub(crate) document: gltf::Document,
    pub(crate) blob: Option<Cow<'a, [u8]>>,
}

/// Parses and checks a .glb or .gltf file (see the module docs for what is tolerated).
pub(crate) fn parse<'a>(bytes: &'a [u8], limits: &ImportLimits) -> Result<Parsed<'a>, GltfError> {
    if bytes.len() > limits.max_file_bytes {
        return Err(GltfError::FileTooLarge {
            bytes: bytes.len(),
            limit: limits.max_file_bytes,
        });
    }
    let (json, blob) = if bytes.starts_with(b"glTF") {
        split_glb(bytes)?
    } else {
        (bytes, None)
    };
    let mut value: serde_json::Value = serde_json::from_slice(json).map_err(parse_error)?;
    check_version(&value)?;
    check_required_extensions(&mut value)?;
    supply_scene_nodes(&mut value);
    integral_floats_to_integers(&mut value);
    // gltf-json refuses valid animations (a channel target without a node), so they are
    // read apart, after the rest has passed (see `with_animations`).
    let animations = value.as_object_mut().and_then(|o| o.remove("animations"));
    let mut root: gltf::json::Root = serde_json::from_value(value).map_err(parse_error)?;
    check_position_references(&root)?;
    validate(&root)?;
    if let Some(animations) = animations {
        root = with_animations(root, animations);
    }
    Ok(Parsed {
        document: gltf::Document::from_json_without_validation(root),
        blob,
    })
}

/// `root` with the file's animations (the only thing a modeller reads from them is the
/// morph-target weights that become key frames): channels without a node dropped, then
/// animations without channels. Animations that still do not deserialize or validate are
/// left out whole: the models import as they are, without key frames.
fn with_animations(root: gltf::json::Root, mut animations: serde_json::Value) -> gltf::json::Root {
    if let Some(list) = animations.as_array_mut() {
        for animation in list.iter_mut() {
            if let Some(channels) = animation.get_mut("channels").and_then(|c| c.as_array_mut()) {
                channels.retain(|channel| channel.pointer("/target/node").is_some());
            }
        }
        list.retain(|a| {
            a.get("channels")
                .and_then(|c| c.as_array())
                .is_some_and(|c| !c.is_empty())
        });
    }
    let Ok(parsed) = serde_json::from_value(animations) else {
        return root;
    };
    let mut animated = root.clone();
    animated.animations = parsed;
    if validate(&animated).is_ok() {
        animated
    } else {
        root
    }
}

fn parse_error(error: impl std::fmt::Display) -> GltfError {
    GltfError::Parse(error.to_string())
}

/// A GLB's JSON chunk and its BIN chunk, if any.
type GlbChunks<'a> = (&'a [u8], Option<Cow<'a, [u8]>>);

/// Splits a GLB into its JSON chunk and BIN chunk (if any), checking every length; unknown
/// chunks and trailing bytes after the declared length are ignored, as the spec allows.
fn split_glb(bytes: &[u8]) -> Result<GlbChunks<'_>, GltfError> {
    let word = |at: usize| {
        bytes
            .get(at..at + 4)
            .map(|w| u32::from_le_bytes([w[0], w[1], w[2], w[3]]) as usize)
    };
    let (Some(version), Some(length)) = (word(4), word(8)) else {
        return Err(parse_error("the GLB header is truncated"));
    };
    if version != 2 {
        return Err(GltfError::UnsupportedVersion(format!("{version} (GLB)")));
    }
    if length < 12 + 8 || length > bytes.len() {
        return Err(parse_error(format_args!(
            "the GLB header declares {length} bytes, but the file has {}",
            bytes.len()
        )));
    }
    let mut chunks = Vec::new();
    let mut at = 12;
    while at + 8 <= length {
        let (Some(chunk_length), Some(kind)) = (word(at), bytes.get(at + 4..at + 8)) else {
            break;
        };
        let start = at + 8;
        let Some(data) = start
            .checked_add(chunk_length)
            .filter(|&end| end <= length)
            .map(|end| &bytes[start..end])
        else {
            return Err(parse_error("a GLB chunk reaches past the end of the file"));
        };
        chunks.push((kind, data));
        at = start + chunk_length.next_multiple_of(4);
    }
    let json = match chunks.first() {
        Some((kind, data)) if *kind == b"JSON" => *data,
        _ => return Err(parse_error("the GLB file does not start with a JSON chunk")),
    };
    let bin = chunks
        .get(1)
        .filter(|(kind, _)| *kind == b"BIN\0")
        .map(|(_, data)| Cow::Borrowed(*data));
    Ok((json, bin))
}

fn check_version(value: &serde_json::Value) -> Result<(), GltfError> {
    let version = value
        .get("asset")
        .and_then(|asset| asset.get("version"))
        .and_then(serde_json::Value::as_str);
    match version {
        Some(version) if version.split('.').next() == Some("2") => Ok(()),
        Some(version) => Err(GltfError::UnsupportedVersion(version.to_owned())),
        None => Err(parse_error("it has no asset.version")),
    }
}

/// Refuses unknown required extensions by name, then removes the list so that the `gltf`
/// crate (which knows fewer extensions than this importer) does not refuse known ones.
fn check_required_extensions(value: &mut serde_json::Value) -> Result<(), GltfError> {
    let Some(object) = value.as_object_mut() else {
        return Err(parse_error("the top level is not a JSON object"));
    };
    let Some(required) = object.remove("extensionsRequired") else {
        return Ok(());
    };
    let unknown: Vec<String> = required
        .as_array()
        .into_iter()
        .flatten()
        .map(|name| name.as_str().unwrap_or("(not a string)"))
        .filter(|name| !SUPPORTED_REQUIRED_EXTENSIONS.contains(name))
        .map(String::from)
        .collect();
    if unknown.is_empty() {
        Ok(())
    } else {
        Err(GltfError::UnsupportedExtensions(unknown.join(", ")))
    }
}

/// gltf-json requires `scene.nodes`, which the spec makes optional (an empty scene has none,
/// and `"nodes": []` is not allowed), so supply it before deserializing.
fn supply_scene_nodes(value: &mut serde_json::Value) {
    let Some(scenes) = value
        .get_mut("scenes")
        .and_then(serde_json::Value::as_array_mut)
    else {
        return;
    };
    for scene in scenes
        .iter_mut()
        .filter_map(serde_json::Value::as_object_mut)
    {
        scene
            .entry("nodes")
            .or_insert_with(|| serde_json::Value::Array(Vec::new()));
    }
}

/// gltf-json's validation indexes the accessor of every POSITION attribute without a check,
/// so dangling ones must be refused before it runs.
fn check_position_references(root: &gltf::json::Root) -> Result<(), GltfError> {
    let position = gltf::json::validation::Checked::Valid(gltf::json::mesh::Semantic::Positions);
    for (m, mesh) in root.meshes.iter().enumerate() {
        for (p, primitive) in mesh.primitives.iter().enumerate() {
            if let Some(index) = primitive.attributes.get(&position)
                && index.value() >= root.accessors.len()
            {
                return Err(parse_error(format_args!(
                    "meshes[{m}].primitives[{p}] takes POSITION from accessor {}, which does not exist",
                    index.value()
                )));
            }
        }
    }
    Ok(())
}

/// JSON writers that print `1.0` where glTF wants an integer are common; serde refuses them,
/// so whole-number floats become integers (float fields read integers just as well).
fn integral_floats_to_integers(value: &mut serde_json::Value) {
    match value {
        serde_json::Value::Number(number) => {
            if let Some(float) = number.as_f64()
                && !number.is_i64()
                && !number.is_u64()
                && float.fract() == 0.0
                && float.abs() < 9.0e15
            {
                *number = serde_json::Number::from(float as i64);
            }
        }
        serde_json::Value::Array(items) => items.iter_mut().for_each(integral_floats_to_integers),
        serde_json::Value::Object(map) => map.values_mut().for_each(integral_floats_to_integers),
        _ => {}
    }
}

/// Runs the schema validation and refuses on the first error that matters.
fn validate(root: &gltf::json::Root) -> Result<(), GltfError> {
    let used_accessors = accessors_used_by_meshes(root);
    let mut first_error = None;
    root.validate(root, gltf::json::Path::new, &mut |path, error| {
        let path = path();
        if first_error.is_none() && !is_tolerated(path.as_str(), &error, &used_accessors) {
            first_error = Some(format!("{} is {error}", path.as_str()));
        }
    });
    match first_error {
        Some(message) => Err(parse_error(message)),
        None => Ok(()),
    }
}

/// Errors the importer can live with, because the wrappers it calls never touch them:
/// missing or malformed POSITION bounds (the reader computes its own), accessors without a
/// buffer view (all zeros, as the spec says), textures whose image comes from an extension
/// (the texture is skipped), primitives without POSITION (skipped), and unknown types on accessors no mesh reads.
fn is_tolerated(path: &str, error: &ValidationError, used_accessors: &[bool]) -> bool {
    let is_missing_or_invalid =
        matches!(error, ValidationError::Missing | ValidationError::Invalid);
    let unused_accessor = path
        .strip_prefix("accessors[")
        .and_then(|rest| rest.split_once(']'))
        .and_then(|(index, _)| index.parse::<usize>().ok())
        .is_some_and(|index| !used_accessors.get(index).copied().unwrap_or(true));
    is_missing_or_invalid
        && (path.ends_with("POSITION\"].min")
            || path.ends_with("POSITION\"].max")
            || (path.starts_with("accessors[") && path.ends_with("].bufferView"))
            || (path.starts_with("textures[") && path.ends_with("].source"))
            || path.ends_with("attributes[\"POSITION\"]")
            || unused_accessor)
}

/// Which accessors mesh primitives refer to (attributes, indices, morph targets).
fn accessors_used_by_meshes(root: &gltf::json::Root) -> Vec<bool> {
    let mut used = vec![false; root.accessors.len()];
    let mut mark = |index: usize| {
        if let Some(slot) = used.get_mut(index) {
            *slot = true;
        }
    };
    for primitive in root.meshes.iter().flat_map(|mesh| &mesh.primitives) {
        primitive.attributes.values().for_each(|a| mark(a.value()));
        primitive.indices.iter().for_each(|a| mark(a.value()));
        for target in primitive.targets.iter().flatten() {
            [&target.positions, &target.normals, &target.tangents]
                .into_iter()
                .flatten()
                .for_each(|a| mark(a.value()));
        }
    }
    used
}

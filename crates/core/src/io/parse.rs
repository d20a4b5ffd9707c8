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
use super::import::ImportLimits;

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
        check_glb_header(bytes)?;
        let glb = gltf::binary::Glb::from_slice(bytes).map_err(parse_error)?;
        (glb.json, glb.bin)
    } else {
        (Cow::Borrowed(bytes), None)
    };
    let mut value: serde_json::Value = serde_json::from_slice(&json).map_err(parse_error)?;
    check_version(&value)?;
    check_required_extensions(&mut value)?;
    supply_scene_nodes(&mut value);
    let root: gltf::json::Root = serde_json::from_value(value).map_err(parse_error)?;
    check_position_references(&root)?;
    validate(&root)?;
    Ok(Parsed {
        document: gltf::Document::from_json_without_validation(root),
        blob,
    })
}

fn parse_error(error: impl std::fmt::Display) -> GltfError {
    GltfError::Parse(error.to_string())
}

/// Refuses GLB headers that would make the `gltf` crate subtract past zero, and versions
/// other than 2 with a sentence of their own.
fn check_glb_header(bytes: &[u8]) -> Result<(), GltfError> {
    let word = |k: usize| {
        bytes
            .get(4 * k..4 * k + 4)
            .map(|w| u32::from_le_bytes([w[0], w[1], w[2], w[3]]) as usize)
    };
    let (Some(version), Some(length)) = (word(1), word(2)) else {
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
    Ok(())
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

/// Runs the schema validation and refuses on the first error that matters.
fn validate(root: &gltf::json::Root) -> Result<(), GltfError> {
    let mut first_error = None;
    root.validate(root, gltf::json::Path::new, &mut |path, error| {
        let path = path();
        if first_error.is_none() && !is_tolerated(path.as_str(), &error) {
            first_error = Some(format!("{} is {error}", path.as_str()));
        }
    });
    match first_error {
        Some(message) => Err(parse_error(message)),
        None => Ok(()),
    }
}

/// Missing or malformed POSITION bounds: the reader computes its own.
fn is_tolerated(path: &str, error: &ValidationError) -> bool {
    matches!(error, ValidationError::Missing | ValidationError::Invalid)
        && (path.ends_with("POSITION\"].min") || path.ends_with("POSITION\"].max"))
}

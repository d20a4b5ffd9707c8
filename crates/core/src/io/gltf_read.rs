//! Reading the triangles and Sketchmesh extras of a glTF scene, defensively.
//!
//! Input may be anything a user drops on the app, so every offset, length and index is
//! checked before use and every problem becomes a [`GltfError`]; nothing here panics. The
//! `gltf` crate parses and validates the JSON; buffer data is read by hand (GLB BIN chunk or
//! base64 `data:` URIs; external files are refused), because its `import` feature pulls in
//! file I/O and image decoding.

use glam::{DMat4, DVec3};
use gltf::accessor::{DataType, Dimensions};
use gltf::mesh::Mode;

use super::extras::NodeExtras;
use crate::mesh::TriSoup;
use base64::Engine as _;

/// Why a glTF file could not be read.
#[derive(Debug, thiserror::Error)]
pub enum GltfError {
    /// The bytes are neither a GLB container nor glTF JSON, or the JSON breaks the schema.
    #[error("The file is not valid glTF: {0}.")]
    Parse(String),
    /// A buffer points at a separate file.
    #[error(
        "Buffer {index} refers to the external file \"{uri}\"; only .glb files and .gltf files with embedded data can be read."
    )]
    ExternalBuffer {
        /// The buffer.
        index: usize,
        /// Its URI.
        uri: String,
    },
    /// A `data:` URI is not base64 data.
    #[error("Buffer {index} has a data URI that is not valid base64.")]
    BadDataUri {
        /// The buffer.
        index: usize,
    },
    /// A buffer holds fewer bytes than its `byteLength` (or the GLB has no BIN chunk).
    #[error("Buffer {index} is shorter than its declared length of {length} bytes.")]
    BufferTooShort {
        /// The buffer.
        index: usize,
        /// Its declared `byteLength`.
        length: usize,
    },
    /// An accessor or its buffer view reaches past the end of the data.
    #[error("Accessor {index} reads past the end of its buffer.")]
    AccessorOutOfBounds {
        /// The accessor.
        index: usize,
    },
    /// An accessor has a form this reader does not handle.
    #[error("Accessor {index} is not supported: {reason}.")]
    UnsupportedAccessor {
        /// The accessor.
        index: usize,
        /// What is unsupported.
        reason: &'static str,
    },
    /// A vertex index is not below the number of vertices.
    #[error("Mesh {mesh} uses vertex index {index}, but the primitive has only {count} vertices.")]
    IndexOutOfRange {
        /// The mesh.
        mesh: usize,
        /// The bad index.
        index: u32,
        /// The number of vertices in the primitive.
        count: usize,
    },
    /// The node hierarchy is not a tree (a node is reached twice).
    #[error("Node {node} appears more than once in the scene's node tree.")]
    NodeReachedTwice {
        /// The node.
        node: usize,
    },
    /// Node extras under `"sketchmesh"` do not follow `docs/gltf-extras.md`.
    #[error("The Sketchmesh data on node {node} is malformed: {message}.")]
    BadExtras {
        /// The node.
        node: usize,
        /// What serde reported.
        message: String,
    },
}

/// What [`read_scene`] found in the default scene.
#[derive(Clone, Debug, Default)]
pub(crate) struct SceneContents {
    /// All triangles of the scene in world space, one soup per triangle primitive, unwelded.
    pub(crate) soup: TriSoup,
    /// Sketchmesh extras of the scene's nodes.
    pub(crate) extras: Vec<NodeExtras>,
}

/// Reads the default scene (or the first scene) of a .glb or .gltf file: triangles of every
/// triangle primitive with node transforms applied (winding kept outward under mirroring
/// transforms), and the Sketchmesh extras of every node. Lines and points are skipped.
pub(crate) fn read_scene(bytes: &[u8]) -> Result<SceneContents, GltfError> {
    let gltf = parse(bytes)?;
    let buffers = load_buffers(&gltf)?;
    let mut contents = SceneContents::default();
    let Some(scene) = gltf.default_scene().or_else(|| gltf.scenes().next()) else {
        return Ok(contents);
    };
    let mut is_visited = vec![false; gltf.nodes().len()];
    let mut stack: Vec<(gltf::Node, DMat4)> =
        scene.nodes().map(|node| (node, DMat4::IDENTITY)).collect();
    while let Some((node, world_from_parent)) = stack.pop() {
        let Some(visited) = is_visited.get_mut(node.index()) else {
            return Err(GltfError::NodeReachedTwice { node: node.index() });
        };
        if std::mem::replace(visited, true) {
            return Err(GltfError::NodeReachedTwice { node: node.index() });
        }
        let parent_from_node = glam::Mat4::from_cols_array_2d(&node.transform().matrix());
        let world_from_node = world_from_parent * parent_from_node.as_dmat4();
        if let Some(raw) = node.extras()
            && let Some(extras) = parse_extras(node.index(), raw.get())?
        {
            contents.extras.push(extras);
        }
        if let Some(mesh) = node.mesh() {
            for primitive in mesh.primitives() {
                read_triangles(
                    &primitive,
                    mesh.index(),
                    &buffers,
                    world_from_node,
                    &mut contents.soup,
                )?;
            }
        }
        stack.extend(node.children().map(|child| (child, world_from_node)));
    }
    Ok(contents)
}

/// Parses and validates a .glb or .gltf file.
fn parse(bytes: &[u8]) -> Result<gltf::Gltf, GltfError> {
    let parse_error = |error: &dyn std::fmt::Display| GltfError::Parse(error.to_string());
    let (json, blob) = if bytes.starts_with(b"glTF") {
        check_glb_header(bytes)?;
        let glb = gltf::binary::Glb::from_slice(bytes).map_err(|e| parse_error(&e))?;
        (glb.json.into_owned(), glb.bin.map(|bin| bin.into_owned()))
    } else {
        (bytes.to_vec(), None)
    };
    let mut value: serde_json::Value =
        serde_json::from_slice(&json).map_err(|e| parse_error(&e))?;
    // gltf-json requires `scene.nodes`, which the spec makes optional (an empty scene has
    // none, and `"nodes": []` is not allowed), so supply it before deserializing.
    if let Some(scenes) = value
        .get_mut("scenes")
        .and_then(serde_json::Value::as_array_mut)
    {
        for scene in scenes
            .iter_mut()
            .filter_map(serde_json::Value::as_object_mut)
        {
            scene
                .entry("nodes")
                .or_insert_with(|| serde_json::Value::Array(Vec::new()));
        }
    }
    let root: gltf::json::Root = serde_json::from_value(value).map_err(|e| parse_error(&e))?;
    let document = gltf::Document::from_json(root).map_err(|e| parse_error(&e))?;
    Ok(gltf::Gltf { document, blob })
}

/// Refuses GLB headers that would make the `gltf` crate subtract past zero.
fn check_glb_header(bytes: &[u8]) -> Result<(), GltfError> {
    let Some(length) = bytes.get(8..12) else {
        return Err(GltfError::Parse(String::from(
            "the GLB header is truncated",
        )));
    };
    let length = u32::from_le_bytes([length[0], length[1], length[2], length[3]]) as usize;
    if length < 12 + 8 || length > bytes.len() {
        return Err(GltfError::Parse(format!(
            "the GLB header declares {length} bytes, but the file has {}",
            bytes.len()
        )));
    }
    Ok(())
}

/// `Some` for extras with a `"sketchmesh"` key, `None` for anyone else's extras.
fn parse_extras(node: usize, raw: &str) -> Result<Option<NodeExtras>, GltfError> {
    let value: serde_json::Value =
        serde_json::from_str(raw).map_err(|error| GltfError::Parse(error.to_string()))?;
    if value.get("sketchmesh").is_none() {
        return Ok(None);
    }
    serde_json::from_value(value)
        .map(Some)
        .map_err(|error| GltfError::BadExtras {
            node,
            message: error.to_string(),
        })
}

fn load_buffers(gltf: &gltf::Gltf) -> Result<Vec<Vec<u8>>, GltfError> {
    gltf.buffers()
        .map(|buffer| {
            let index = buffer.index();
            let data = match buffer.source() {
                gltf::buffer::Source::Bin => gltf.blob.clone().unwrap_or_default(),
                gltf::buffer::Source::Uri(uri) => {
                    let Some(rest) = uri.strip_prefix("data:") else {
                        return Err(GltfError::ExternalBuffer {
                            index,
                            uri: uri.to_owned(),
                        });
                    };
                    let Some((_, payload)) = rest.split_once(";base64,") else {
                        return Err(GltfError::BadDataUri { index });
                    };
                    base64::engine::general_purpose::STANDARD
                        .decode(payload)
                        .map_err(|_| GltfError::BadDataUri { index })?
                }
            };
            if data.len() < buffer.length() {
                return Err(GltfError::BufferTooShort {
                    index,
                    length: buffer.length(),
                });
            }
            Ok(data)
        })
        .collect()
}

/// Appends a primitive's triangles to `soup`, transformed to world space.
fn read_triangles(
    primitive: &gltf::Primitive,
    mesh: usize,
    buffers: &[Vec<u8>],
    world_from_node: DMat4,
    soup: &mut TriSoup,
) -> Result<(), GltfError> {
    let mode = primitive.mode();
    if !matches!(
        mode,
        Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan
    ) {
        return Ok(());
    }
    let Some(positions) = primitive.get(&gltf::Semantic::Positions) else {
        return Ok(());
    };
    let positions = read_vec3s(&positions, buffers)?;
    let indices = match primitive.indices() {
        Some(indices) => read_indices(&indices, buffers)?,
        None => (0..positions.len() as u32).collect(),
    };
    if let Some(&index) = indices.iter().find(|&&i| i as usize >= positions.len()) {
        return Err(GltfError::IndexOutOfRange {
            mesh,
            index,
            count: positions.len(),
        });
    }
    let is_mirrored = world_from_node.determinant() < 0.0;
    let offset = soup.positions.len() as u32;
    soup.positions.extend(
        positions
            .iter()
            .map(|&p| world_from_node.transform_point3(p)),
    );
    let mut push = |a: u32, b: u32, c: u32| {
        let triangle = if is_mirrored { [a, c, b] } else { [a, b, c] };
        soup.triangles.push(triangle.map(|i| i + offset));
    };
    match mode {
        Mode::TriangleStrip => {
            for (k, w) in indices.windows(3).enumerate() {
                // Every other strip triangle is wound the other way.
                if k % 2 == 0 {
                    push(w[0], w[1], w[2])
                } else {
                    push(w[1], w[0], w[2])
                }
            }
        }
        Mode::TriangleFan => {
            if let Some((&centre, rest)) = indices.split_first() {
                for w in rest.windows(2) {
                    push(centre, w[0], w[1]);
                }
            }
        }
        _ => {
            for t in indices.chunks_exact(3) {
                push(t[0], t[1], t[2]);
            }
        }
    }
    Ok(())
}

fn read_vec3s(accessor: &gltf::Accessor, buffers: &[Vec<u8>]) -> Result<Vec<DVec3>, GltfError> {
    let index = accessor.index();
    if accessor.data_type() != DataType::F32 || accessor.dimensions() != Dimensions::Vec3 {
        return Err(GltfError::UnsupportedAccessor {
            index,
            reason: "positions must be float VEC3",
        });
    }
    let elements = accessor_elements(accessor, buffers, 12)?;
    Ok(elements
        .map(|bytes| {
            let component = |k: usize| {
                f32::from_le_bytes([
                    bytes[4 * k],
                    bytes[4 * k + 1],
                    bytes[4 * k + 2],
                    bytes[4 * k + 3],
                ])
            };
            DVec3::new(
                component(0).into(),
                component(1).into(),
                component(2).into(),
            )
        })
        .collect())
}

fn read_indices(accessor: &gltf::Accessor, buffers: &[Vec<u8>]) -> Result<Vec<u32>, GltfError> {
    let index = accessor.index();
    if accessor.dimensions() != Dimensions::Scalar {
        return Err(GltfError::UnsupportedAccessor {
            index,
            reason: "indices must be SCALAR",
        });
    }
    match accessor.data_type() {
        DataType::U8 => Ok(accessor_elements(accessor, buffers, 1)?
            .map(|b| u32::from(b[0]))
            .collect()),
        DataType::U16 => Ok(accessor_elements(accessor, buffers, 2)?
            .map(|b| u32::from(u16::from_le_bytes([b[0], b[1]])))
            .collect()),
        DataType::U32 => Ok(accessor_elements(accessor, buffers, 4)?
            .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
            .collect()),
        _ => Err(GltfError::UnsupportedAccessor {
            index,
            reason: "indices must be unsigned bytes, shorts or ints",
        }),
    }
}

/// The bytes of each element (`element_size` bytes each) of a non-sparse accessor, after
/// checking that all of them lie inside the buffer view and the buffer.
fn accessor_elements<'a>(
    accessor: &gltf::Accessor,
    buffers: &'a [Vec<u8>],
    element_size: usize,
) -> Result<impl Iterator<Item = &'a [u8]> + use<'a>, GltfError> {
    let index = accessor.index();
    let out_of_bounds = GltfError::AccessorOutOfBounds { index };
    if accessor.sparse().is_some() {
        return Err(GltfError::UnsupportedAccessor {
            index,
            reason: "sparse accessors",
        });
    }
    let Some(view) = accessor.view() else {
        return Err(GltfError::UnsupportedAccessor {
            index,
            reason: "no buffer view",
        });
    };
    let stride = view.stride().unwrap_or(element_size).max(element_size);
    let count = accessor.count();
    let Some(buffer) = buffers.get(view.buffer().index()) else {
        return Err(out_of_bounds);
    };
    let view_end = view.offset().checked_add(view.length());
    let Some(view_bytes) = view_end.and_then(|end| buffer.get(view.offset()..end)) else {
        return Err(out_of_bounds);
    };
    let Some(bytes) = view_bytes.get(accessor.offset()..) else {
        return Err(out_of_bounds);
    };
    let needed = match count {
        0 => Some(0),
        _ => (count - 1)
            .checked_mul(stride)
            .and_then(|n| n.checked_add(element_size)),
    };
    match needed {
        Some(needed) if needed <= bytes.len() => {}
        _ => return Err(out_of_bounds),
    }
    Ok((0..count).map(move |k| &bytes[k * stride..k * stride + element_size]))
}

//! Walking the default scene: node transforms applied, primitives read per node instance.
//!
//! The walk first lists node instances and adds up how many vertices and triangles they
//! would produce (instancing can make a small file describe a huge scene), refuses scenes
//! over the limits, and only then reads data.

use glam::{DMat3, DMat4, DVec3};
use gltf::mesh::Mode;

use super::accessor::{read_f64, read_u32};
use super::animation_read::{NodeAnimation, node_animations, posed};
use super::error::GltfError;
use super::extras::NodeExtras;
use super::input::ImportLimits;
use super::resources::Buffers;

/// The triangles of one node instance with their per-vertex attributes (before welding).
#[derive(Clone, Debug, Default)]
pub(crate) struct Surface {
    /// World-space positions.
    pub(crate) positions: Vec<DVec3>,
    /// Triangles, wound so that mirroring transforms keep them facing out.
    pub(crate) triangles: Vec<[u32; 3]>,
    /// World-space unit normals, one per vertex while `has_normals`; empty otherwise.
    pub(crate) normals: Vec<[f32; 3]>,
    /// Whether every triangle primitive had normals.
    pub(crate) has_normals: bool,
    /// TEXCOORD_0 per vertex (zeros where a primitive had none) once any primitive has it.
    pub(crate) uvs: Vec<[f32; 2]>,
    /// Whether any primitive had TEXCOORD_0.
    pub(crate) has_uvs: bool,
    /// COLOR_0 per vertex as RGBA (white where a primitive had none) once any has it.
    pub(crate) colors: Vec<[f32; 4]>,
    /// Whether any primitive had COLOR_0.
    pub(crate) has_colors: bool,
    /// The glTF material of each triangle.
    pub(crate) face_materials: Vec<Option<usize>>,
    /// The times of the node's key poses (its morph-target animation), if any.
    pub(crate) key_times: Vec<f64>,
    /// World-space positions at each key time, one per vertex like `positions`.
    pub(crate) poses: Vec<Vec<DVec3>>,
    /// Sampled times of the animation left out (over `animation_read::MAX_KEYS`).
    pub(crate) skipped_keys: usize,
}

/// A point primitive: positions and optional RGBA colours.
#[derive(Clone, Debug, Default)]
pub(crate) struct Points {
    pub(crate) positions: Vec<DVec3>,
    pub(crate) colors: Option<Vec<[f32; 4]>>,
}

/// Everything one node instance contributes.
#[derive(Clone, Debug, Default)]
pub(crate) struct NodeGeometry {
    /// The node's name, if any.
    pub(crate) name: Option<String>,
    /// Its Sketchmesh extras, if any.
    pub(crate) extras: Option<NodeExtras>,
    /// All triangle primitives of its mesh.
    pub(crate) surface: Surface,
    /// Line primitives as polylines (strips and loops kept whole; loops repeat their start).
    pub(crate) lines: Vec<Vec<DVec3>>,
    /// Point primitives.
    pub(crate) points: Vec<Points>,
}

/// Reads every node instance of the default scene (or the first scene).
pub(crate) fn read_nodes(
    document: &gltf::Document,
    buffers: &Buffers,
    limits: &ImportLimits,
) -> Result<Vec<NodeGeometry>, GltfError> {
    let instances = node_instances(document)?;
    check_limits(&instances, limits)?;
    let animations = node_animations(document, buffers)?;
    instances
        .iter()
        .map(|(node, world_from_node)| {
            let animation = animations.get(&node.index());
            read_node(node, *world_from_node, buffers, limits, animation)
        })
        .collect()
}

/// Nodes of the scene in depth-first order with their world transforms.
fn node_instances(document: &gltf::Document) -> Result<Vec<(gltf::Node<'_>, DMat4)>, GltfError> {
    let Some(scene) = document
        .default_scene()
        .or_else(|| document.scenes().next())
    else {
        return Ok(Vec::new());
    };
    let mut is_visited = vec![false; document.nodes().len()];
    let mut instances = Vec::new();
    let mut stack: Vec<(gltf::Node, DMat4)> =
        scene.nodes().map(|node| (node, DMat4::IDENTITY)).collect();
    stack.reverse();
    while let Some((node, world_from_parent)) = stack.pop() {
        let visited = is_visited.get_mut(node.index());
        if visited.is_none_or(|visited| std::mem::replace(visited, true)) {
            return Err(GltfError::NodeReachedTwice { node: node.index() });
        }
        let parent_from_node = glam::Mat4::from_cols_array_2d(&node.transform().matrix());
        let world_from_node = world_from_parent * parent_from_node.as_dmat4();
        let first_child = stack.len();
        stack.extend(node.children().map(|child| (child, world_from_node)));
        stack[first_child..].reverse();
        instances.push((node, world_from_node));
    }
    Ok(instances)
}

/// Refuses scenes whose instances add up to more vertices or triangles than allowed.
fn check_limits(instances: &[(gltf::Node, DMat4)], limits: &ImportLimits) -> Result<(), GltfError> {
    let (mut vertices, mut triangles) = (0u64, 0u64);
    for primitive in instances
        .iter()
        .filter_map(|(node, _)| node.mesh())
        .flat_map(|mesh| mesh.primitives())
    {
        let count = |a: Option<gltf::Accessor>| a.map_or(0, |a| a.count() as u64);
        let n_vertices = count(primitive.get(&gltf::Semantic::Positions));
        let n_indices = primitive.indices().map_or(n_vertices, |a| a.count() as u64);
        vertices += n_vertices;
        triangles += match primitive.mode() {
            Mode::Triangles => n_indices / 3,
            Mode::TriangleStrip | Mode::TriangleFan => n_indices.saturating_sub(2),
            _ => 0,
        };
    }
    let check = |what, count: u64, limit: usize| {
        if count > limit as u64 {
            Err(GltfError::TooMuchGeometry { what, count, limit })
        } else {
            Ok(())
        }
    };
    check("vertices", vertices, limits.max_vertices)?;
    check("triangles", triangles, limits.max_triangles)
}

fn read_node(
    node: &gltf::Node,
    world_from_node: DMat4,
    buffers: &Buffers,
    limits: &ImportLimits,
    animation: Option<&NodeAnimation>,
) -> Result<NodeGeometry, GltfError> {
    let mut geometry = NodeGeometry {
        name: node.name().map(String::from),
        extras: match node.extras() {
            Some(raw) => parse_extras(node.index(), raw.get())?,
            None => None,
        },
        ..NodeGeometry::default()
    };
    geometry.surface.has_normals = true;
    let Some(mesh) = node.mesh() else {
        geometry.surface.has_normals = false;
        return Ok(geometry);
    };
    let transform = Transform::new(world_from_node);
    for primitive in mesh.primitives() {
        let Some(positions) = primitive.get(&gltf::Semantic::Positions) else {
            continue;
        };
        let position_index = positions.index();
        let in_node: Vec<DVec3> = read_f64::<3>(&positions, buffers, limits.max_vertices)?
            .into_iter()
            .map(DVec3::from)
            .collect();
        let to_world = |p: DVec3| transform.world_from_node.transform_point3(p);
        let positions: Vec<DVec3> = in_node.iter().map(|&p| to_world(p)).collect();
        // World positions must also fit in f32, the precision of the GPU and of exports.
        if positions.iter().any(|p| !p.as_vec3().is_finite()) {
            return Err(GltfError::NonFinitePosition {
                index: position_index,
            });
        }
        let indices = match primitive.indices() {
            Some(indices) => read_u32(&indices, buffers, 3 * limits.max_triangles)?,
            None => (0..positions.len() as u32).collect(),
        };
        if let Some(&index) = indices.iter().find(|&&i| i as usize >= positions.len()) {
            return Err(GltfError::IndexOutOfRange {
                mesh: mesh.index(),
                index,
                count: positions.len(),
            });
        }
        match primitive.mode() {
            Mode::Points => geometry.points.push(Points {
                colors: read_colors(&primitive, buffers, positions.len())?,
                positions: indices.iter().map(|&i| positions[i as usize]).collect(),
            }),
            Mode::Lines => geometry.lines.extend(
                indices
                    .chunks_exact(2)
                    .map(|pair| pair.iter().map(|&i| positions[i as usize]).collect()),
            ),
            Mode::LineStrip | Mode::LineLoop => {
                let mut line: Vec<DVec3> = indices.iter().map(|&i| positions[i as usize]).collect();
                if primitive.mode() == Mode::LineLoop
                    && let Some(&first) = line.first()
                {
                    line.push(first);
                }
                geometry.lines.push(line);
            }
            mode => {
                if let Some(animation) = animation {
                    let surface = &mut geometry.surface;
                    let poses = posed(&primitive, buffers, animation, &in_node)?;
                    surface.poses.resize(poses.len(), Vec::new());
                    for (all, pose) in surface.poses.iter_mut().zip(poses) {
                        all.extend(pose.into_iter().map(to_world));
                    }
                    surface.key_times.clone_from(&animation.times);
                    surface.skipped_keys = animation.skipped;
                }
                let triangles = assemble_triangles(mode, &indices, transform.is_mirrored);
                append_surface(
                    &mut geometry.surface,
                    &primitive,
                    buffers,
                    &transform,
                    positions,
                    triangles,
                )?;
            }
        }
    }
    if geometry.surface.positions.is_empty() {
        geometry.surface.has_normals = false;
    }
    Ok(geometry)
}

/// A node's world transform and what follows from it for normals and winding.
struct Transform {
    world_from_node: DMat4,
    normal_matrix: DMat3,
    is_mirrored: bool,
}

impl Transform {
    fn new(world_from_node: DMat4) -> Self {
        let linear = DMat3::from_mat4(world_from_node);
        Self {
            world_from_node,
            normal_matrix: linear.inverse().transpose(),
            is_mirrored: linear.determinant() < 0.0,
        }
    }
}

/// Triangles of a triangle-list, strip or fan index sequence, wound outward.
fn assemble_triangles(mode: Mode, indices: &[u32], is_mirrored: bool) -> Vec<[u32; 3]> {
    let orient = |[a, b, c]: [u32; 3]| if is_mirrored { [a, c, b] } else { [a, b, c] };
    match mode {
        // Every other strip triangle is wound the other way.
        Mode::TriangleStrip => indices
            .windows(3)
            .enumerate()
            .map(|(k, w)| {
                orient(if k % 2 == 0 {
                    [w[0], w[1], w[2]]
                } else {
                    [w[1], w[0], w[2]]
                })
            })
            .collect(),
        Mode::TriangleFan => match indices.split_first() {
            Some((&centre, rest)) => rest
                .windows(2)
                .map(|w| orient([centre, w[0], w[1]]))
                .collect(),
            None => Vec::new(),
        },
        _ => indices
            .chunks_exact(3)
            .map(|t| orient([t[0], t[1], t[2]]))
            .collect(),
    }
}

/// Appends one triangle primitive, with its attributes, to the node's surface.
fn append_surface(
    surface: &mut Surface,
    primitive: &gltf::Primitive,
    buffers: &Buffers,
    transform: &Transform,
    positions: Vec<DVec3>,
    triangles: Vec<[u32; 3]>,
) -> Result<(), GltfError> {
    let n = positions.len();
    let before = surface.positions.len();
    let offset = before as u32;
    let attribute = |semantic: gltf::Semantic| primitive.get(&semantic);
    // Normals count only if every primitive has them; drop them at the first that has none.
    match attribute(gltf::Semantic::Normals) {
        Some(normals) if surface.has_normals => {
            let normals = read_f64::<3>(&normals, buffers, n)?;
            check_count(normals.len(), n, "NORMAL")?;
            surface.normals.extend(normals.into_iter().map(|n| {
                let n = transform.normal_matrix * DVec3::from(n);
                n.normalize_or_zero().as_vec3().to_array()
            }));
        }
        Some(_) => {}
        None => {
            surface.has_normals = false;
            surface.normals = Vec::new();
        }
    }
    let uvs = match attribute(gltf::Semantic::TexCoords(0)) {
        Some(uvs) => Some(
            read_f64::<2>(&uvs, buffers, n)?
                .into_iter()
                .map(|uv| uv.map(|c| c as f32))
                .collect(),
        ),
        None => None,
    };
    append_optional(
        &mut surface.uvs,
        &mut surface.has_uvs,
        uvs,
        before,
        n,
        [0.0; 2],
        "TEXCOORD_0",
    )?;
    let colors = read_colors(primitive, buffers, n)?;
    append_optional(
        &mut surface.colors,
        &mut surface.has_colors,
        colors,
        before,
        n,
        [1.0; 4],
        "COLOR_0",
    )?;
    surface.positions.extend(positions);
    let material = primitive.material().index();
    surface
        .face_materials
        .extend(std::iter::repeat_n(material, triangles.len()));
    surface
        .triangles
        .extend(triangles.into_iter().map(|t| t.map(|i| i + offset)));
    Ok(())
}

/// Appends a primitive's values of an attribute that some primitives may lack: nothing is
/// stored until one has it, then earlier and later vertices without it get `default`.
fn append_optional<T: Copy>(
    values: &mut Vec<T>,
    has: &mut bool,
    read: Option<Vec<T>>,
    before: usize,
    n: usize,
    default: T,
    name: &str,
) -> Result<(), GltfError> {
    match read {
        Some(read) => {
            check_count(read.len(), n, name)?;
            values.resize(before, default);
            values.extend(read);
            *has = true;
        }
        None if *has => values.resize(before + n, default),
        None => {}
    }
    Ok(())
}

/// Attribute accessors may differ from POSITION in length only in broken files.
fn check_count(count: usize, n: usize, name: &str) -> Result<(), GltfError> {
    if count == n {
        Ok(())
    } else {
        Err(GltfError::Parse(format!(
            "a primitive's {name} count differs from its POSITION count"
        )))
    }
}

/// COLOR_0 as RGBA, if present (RGB gets alpha 1).
fn read_colors(
    primitive: &gltf::Primitive,
    buffers: &Buffers,
    n: usize,
) -> Result<Option<Vec<[f32; 4]>>, GltfError> {
    let Some(colors) = primitive.get(&gltf::Semantic::Colors(0)) else {
        return Ok(None);
    };
    let rgba: Vec<[f32; 4]> = if colors.dimensions().multiplicity() == 3 {
        read_f64::<3>(&colors, buffers, n)?
            .into_iter()
            .map(|[r, g, b]| [r as f32, g as f32, b as f32, 1.0])
            .collect()
    } else {
        read_f64::<4>(&colors, buffers, n)?
            .into_iter()
            .map(|c| c.map(|v| v as f32))
            .collect()
    };
    Ok(Some(rgba))
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strips_and_fans_keep_one_winding() {
        assert_eq!(
            assemble_triangles(Mode::TriangleStrip, &[0, 1, 2, 3], false),
            vec![[0, 1, 2], [2, 1, 3]]
        );
        assert_eq!(
            assemble_triangles(Mode::TriangleFan, &[0, 1, 2, 3], false),
            vec![[0, 1, 2], [0, 2, 3]]
        );
        assert_eq!(
            assemble_triangles(Mode::Triangles, &[0, 1, 2, 3], true),
            vec![[0, 2, 1]]
        );
    }
}

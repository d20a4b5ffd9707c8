//! Writing a [`Document`] as binary glTF 2.0.
//!
//! Layout, chosen to pass the Khronos glTF validator without errors or warnings: one buffer
//! (the GLB BIN chunk); one tightly packed buffer view per accessor, each starting on a
//! 4-byte boundary and carrying its `target`; `min`/`max` on every POSITION accessor computed
//! from the `f32` values actually written; unit-length normals; `u16` indices when no index
//! reaches the primitive-restart value 65535, else `u32`; the material is written only if a
//! triangle primitive uses it. An empty document gives a valid file with one empty scene.

use std::borrow::Cow;
use std::collections::BTreeMap;

use glam::Vec3;
use gltf::json;
use json::validation::Checked::Valid;
use serde_json::value::RawValue;

use super::animation_write::{Baked, bake, morph_targets, weights_animation};
use super::appearance_write::imported_primitives;
use super::extras::{
    CurveExtras, EXTRAS_VERSION, MirrorExtras, NodeExtras, SketchExtras, SketchmeshExtras,
};
use super::glb::{Writer, Written, f32_positions_and_normals};
use crate::model::{Document, MirrorPlane, Model, PointCloud, SketchCurve};
use crate::symmetry::{are_twins, partners};

/// Encodes the document as a .glb file; see the module docs for the layout.
pub fn write_glb(doc: &Document) -> Vec<u8> {
    let mut writer = Writer::default();
    let mut nodes = Vec::new();
    for (index, model) in doc.models.iter().enumerate() {
        let mirror = doc
            .symmetry
            .and_then(|plane| mirror_extras(doc, index, plane));
        nodes.push(model_node(&mut writer, index, model, mirror));
    }
    if !doc.sketches.is_empty() {
        nodes.push(sketch_node(&mut writer, &doc.sketches));
    }
    for (index, points) in doc.point_clouds.iter().enumerate() {
        nodes.push(point_cloud_node(&mut writer, index, points));
    }
    writer.finish(nodes)
}

/// How model `index` pairs up across `plane`: a twin, symmetric, or (`None`) neither.
fn mirror_extras(doc: &Document, index: usize, plane: MirrorPlane) -> Option<MirrorExtras> {
    let mesh = &doc.models[index].mesh;
    let twin =
        (0..doc.models.len()).find(|&j| j != index && are_twins(mesh, &doc.models[j].mesh, &plane));
    (twin.is_some() || partners(mesh, &plane).is_some()).then_some(MirrorExtras { plane, twin })
}

fn model_node(
    writer: &mut Writer,
    index: usize,
    model: &Model,
    mirror: Option<MirrorExtras>,
) -> json::Index<json::Node> {
    let mesh = &model.mesh;
    let name = model
        .name
        .clone()
        .unwrap_or_else(|| format!("model {index}"));
    // A model coloured here is written as made here, in its colours and finish; an imported
    // soup is written as it came while the mesh repaired from it still fits.
    let is_coloured_here = model.vertex_colors().is_some() || model.finish.is_some();
    let (written, appearance) = match model.as_imported().filter(|_| !is_coloured_here) {
        Some(input) => (
            Written {
                positions: Cow::Owned(input.positions_of(mesh)),
                triangles: &input.soup.triangles,
            },
            input.appearance.as_deref(),
        ),
        None => (
            Written {
                positions: Cow::Borrowed(mesh.positions()),
                triangles: mesh.triangles(),
            },
            (model.appearance.as_deref()).filter(|a| a.fits(mesh) && !is_coloured_here),
        ),
    };
    let baked = bake(model).filter(|_| !written.triangles.is_empty());
    let mesh_index = (!written.triangles.is_empty()).then(|| {
        let primitives = match appearance {
            Some(appearance) => imported_primitives(writer, &written, appearance, baked.as_ref()),
            None => vec![clay_primitive(writer, &written, model, baked.as_ref())],
        };
        let n_targets = baked.as_ref().map_or(0, |b| b.poses.len());
        writer.mesh(name.clone(), primitives, n_targets)
    });
    // Imported models without curves stay foreign files' models: no Sketchmesh extras,
    // so importing the export again keeps their look.
    let extras =
        (appearance.is_none() || !model.curves.is_empty() || mirror.is_some()).then(|| {
            let curves = model
                .curves
                .iter()
                .map(|curve| CurveExtras {
                    closed: curve.is_closed,
                    sharp: curve.is_sharp(),
                    points: curve.points(mesh).iter().map(|p| p.to_array()).collect(),
                })
                .collect();
            extras(SketchmeshExtras {
                version: EXTRAS_VERSION,
                curves,
                sketches: Vec::new(),
                mirror,
            })
        });
    let node = writer.root.push(json::Node {
        mesh: mesh_index,
        name: Some(name.clone()),
        extras: extras.flatten(),
        ..Default::default()
    });
    if let Some(baked) = &baked {
        weights_animation(writer, node, baked, name);
    }
    node
}

/// A model made here: welded vertices, smooth normals, its painted colours as `COLOR_0`,
/// its finish (or clay) as the material; its animation's poses as morph targets of positions
/// and normals.
fn clay_primitive(
    writer: &mut Writer,
    surface: &Written,
    model: &Model,
    baked: Option<&Baked>,
) -> json::mesh::Primitive {
    let (positions, normals) = f32_positions_and_normals(&surface.positions, surface.triangles);
    let targets = baked.map(|baked| {
        let poses = baked.poses.iter().map(|pose| {
            let (p, n) = f32_positions_and_normals(pose, surface.triangles);
            (p, Some(n))
        });
        morph_targets(writer, &positions, poses, Some(&normals))
    });
    let mut attributes = BTreeMap::new();
    attributes.insert(
        Valid(json::mesh::Semantic::Positions),
        writer.positions(&positions),
    );
    attributes.insert(
        Valid(json::mesh::Semantic::Normals),
        writer.vec3s(&normals, None),
    );
    if let Some(colors) = model.vertex_colors() {
        let colors: Vec<Vec3> = colors.iter().map(|&c| Vec3::from(c)).collect();
        attributes.insert(
            Valid(json::mesh::Semantic::Colors(0)),
            writer.vec3s(&colors, None),
        );
    }
    let material = writer.material(model.finish);
    let mut primitive = writer.triangle_primitive(
        attributes,
        surface.triangles.as_flattened(),
        positions.len(),
        Some(material),
    );
    primitive.targets = targets;
    primitive
}

fn point_cloud_node(
    writer: &mut Writer,
    index: usize,
    points: &PointCloud,
) -> json::Index<json::Node> {
    let positions: Vec<Vec3> = points.positions.iter().map(|p| p.as_vec3()).collect();
    let mut attributes = BTreeMap::new();
    attributes.insert(
        Valid(json::mesh::Semantic::Positions),
        writer.positions(&positions),
    );
    if let Some(colors) = &points.colors {
        attributes.insert(
            Valid(json::mesh::Semantic::Colors(0)),
            writer.floats(colors),
        );
    }
    let primitive = json::mesh::Primitive {
        attributes,
        extensions: None,
        extras: None,
        indices: None,
        material: None,
        mode: Valid(json::mesh::Mode::Points),
        targets: None,
    };
    let name = format!("points {index}");
    let mesh = (!positions.is_empty()).then(|| writer.mesh(name.clone(), vec![primitive], 0));
    writer.root.push(json::Node {
        mesh,
        name: Some(name),
        ..Default::default()
    })
}

fn sketch_node(
    writer: &mut Writer,
    sketches: &[std::sync::Arc<SketchCurve>],
) -> json::Index<json::Node> {
    let primitives: Vec<json::mesh::Primitive> = sketches
        .iter()
        .filter(|sketch| sketch.points.len() >= 2)
        .map(|sketch| {
            let positions: Vec<Vec3> = sketch.points.iter().map(|p| p.as_vec3()).collect();
            let mut attributes = BTreeMap::new();
            attributes.insert(
                Valid(json::mesh::Semantic::Positions),
                writer.positions(&positions),
            );
            json::mesh::Primitive {
                attributes,
                extensions: None,
                extras: None,
                indices: None,
                material: None,
                mode: Valid(json::mesh::Mode::LineStrip),
                targets: None,
            }
        })
        .collect();
    let mesh =
        (!primitives.is_empty()).then(|| writer.mesh(String::from("sketches"), primitives, 0));
    let sketches = sketches
        .iter()
        .map(|sketch| SketchExtras {
            points: sketch.points.iter().map(|p| p.to_array()).collect(),
            pressures: sketch.pressures.clone(),
        })
        .collect();
    let extras = extras(SketchmeshExtras {
        version: EXTRAS_VERSION,
        curves: Vec::new(),
        sketches,
        mirror: None,
    });
    writer.root.push(json::Node {
        mesh,
        name: Some(String::from("sketches")),
        extras,
        ..Default::default()
    })
}

fn extras(sketchmesh: SketchmeshExtras) -> Option<Box<RawValue>> {
    // Unreachable failure: plain numbers and booleans (non-finite numbers become null).
    serde_json::value::to_raw_value(&NodeExtras { sketchmesh }).ok()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{VertexId, primitives};
    use crate::model::{ControlCurve, CurveKind};
    use glam::DVec3;
    use serde_json::Value;
    use std::sync::Arc;

    /// Splits a GLB into its JSON value and BIN chunk, checking the container layout.
    fn unpack(glb: &[u8]) -> (Value, Vec<u8>) {
        let word = |at: usize| u32::from_le_bytes(glb[at..at + 4].try_into().unwrap()) as usize;
        assert_eq!(&glb[0..4], b"glTF");
        assert_eq!(word(4), 2);
        assert_eq!(word(8), glb.len());
        assert_eq!(glb.len() % 4, 0);
        let json_length = word(12);
        assert_eq!(&glb[16..20], b"JSON");
        assert_eq!(json_length % 4, 0);
        let json: Value = serde_json::from_slice(&glb[20..20 + json_length]).unwrap();
        let rest = &glb[20 + json_length..];
        let bin = if rest.is_empty() {
            Vec::new()
        } else {
            let bin_length = u32::from_le_bytes(rest[0..4].try_into().unwrap()) as usize;
            assert_eq!(&rest[4..8], b"BIN\0");
            assert_eq!(rest.len(), 8 + bin_length);
            rest[8..].to_vec()
        };
        (json, bin)
    }

    fn sample_document() -> Document {
        let mesh = primitives::icosphere(1.0, 1);
        let a = VertexId(0);
        let neighbors: Vec<VertexId> = mesh.vertex_neighbors(a).collect();
        let (b, c) = (neighbors[0], neighbors[1]);
        let curve = ControlCurve {
            vertices: vec![a, b, c],
            is_closed: true,
            kind: CurveKind::Smooth,
        };
        Document {
            models: vec![Arc::new(Model {
                mesh,
                curves: vec![curve],
                ..Model::default()
            })],
            sketches: vec![Arc::new(SketchCurve {
                points: vec![DVec3::new(0.1, 0.2, 0.3), DVec3::new(0.4, 0.5, 0.6)],
                pressures: vec![0.25, 0.75],
            })],
            ..Document::default()
        }
    }

    #[test]
    fn layout_follows_the_spec() {
        let document = sample_document();
        let glb = write_glb(&document);
        let (json, bin) = unpack(&glb);
        assert!(gltf::Gltf::from_slice(&glb).is_ok());
        assert_eq!(json["asset"]["version"], "2.0");
        assert_eq!(
            json["asset"]["generator"],
            format!("Sketchmesh {}", env!("CARGO_PKG_VERSION"))
        );
        assert_eq!(json["buffers"][0]["byteLength"], bin.len());
        assert_eq!(json["scene"], 0);
        assert_eq!(json["scenes"][0]["nodes"], serde_json::json!([0, 1]));
        assert_eq!(json["materials"].as_array().unwrap().len(), 1);
        for view in json["bufferViews"].as_array().unwrap() {
            assert_eq!(view["byteOffset"].as_u64().unwrap() % 4, 0);
            assert!(view.get("byteStride").is_none());
            assert!(view["target"] == 34962 || view["target"] == 34963);
        }
        let model = &json["meshes"][0]["primitives"][0];
        assert_eq!(model["material"], 0);
        let indices = &json["accessors"][model["indices"].as_u64().unwrap() as usize];
        assert_eq!(indices["componentType"], 5123); // UNSIGNED_SHORT
        assert_eq!(indices["count"], 240);
        // min/max are exactly the f32 extremes of the data.
        let mesh = &document.models[0].mesh;
        let position =
            &json["accessors"][model["attributes"]["POSITION"].as_u64().unwrap() as usize];
        let max_x = mesh
            .positions()
            .iter()
            .map(|p| p.x as f32)
            .fold(f32::NEG_INFINITY, f32::max);
        assert_eq!(position["max"][0].as_f64().unwrap() as f32, max_x);
        assert_eq!(position["max"][0].as_f64().unwrap(), f64::from(max_x));
        // Normals are unit length.
        let normal = &json["accessors"][model["attributes"]["NORMAL"].as_u64().unwrap() as usize];
        let view = &json["bufferViews"][normal["bufferView"].as_u64().unwrap() as usize];
        let start = view["byteOffset"].as_u64().unwrap() as usize;
        for chunk in bin[start..start + view["byteLength"].as_u64().unwrap() as usize].chunks(12) {
            let n: Vec<f32> = chunk
                .chunks(4)
                .map(|c| f32::from_le_bytes(c.try_into().unwrap()))
                .collect();
            let length = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            assert!((length - 1.0).abs() < 1e-6);
        }
        // Sketches are line strips without a material; extras carry full precision.
        let sketch = &json["meshes"][1]["primitives"][0];
        assert_eq!(sketch["mode"], 3);
        assert!(sketch.get("material").is_none());
        let extras = &json["nodes"][1]["extras"]["sketchmesh"];
        assert_eq!(extras["version"], 1);
        assert_eq!(
            extras["sketches"][0]["points"][0],
            serde_json::json!([0.1, 0.2, 0.3])
        );
        assert_eq!(
            extras["sketches"][0]["pressures"],
            serde_json::json!([0.25, 0.75])
        );
        let curves = &json["nodes"][0]["extras"]["sketchmesh"]["curves"];
        assert_eq!(curves[0]["closed"], true);
        assert_eq!(curves[0]["sharp"], false);
        let curve = &document.models[0].curves[0];
        let points: Vec<[f64; 3]> = curve.points(mesh).iter().map(|p| p.to_array()).collect();
        assert_eq!(curves[0]["points"], serde_json::json!(points));
    }

    #[test]
    fn empty_document_is_an_empty_scene() {
        let glb = write_glb(&Document::default());
        let (json, bin) = unpack(&glb);
        assert!(bin.is_empty());
        assert_eq!(json["scenes"], serde_json::json!([{}]));
        assert!(json.get("buffers").is_none() && json.get("materials").is_none());
    }

    #[test]
    fn large_meshes_use_u32_indices() {
        let mesh = primitives::grid(256, 256, 1.0);
        assert!(mesh.n_vertices() > 65535);
        let document = Document {
            models: vec![Arc::new(Model {
                mesh,
                ..Model::default()
            })],
            ..Document::default()
        };
        let (json, _) = unpack(&write_glb(&document));
        let primitive = &json["meshes"][0]["primitives"][0];
        let indices = &json["accessors"][primitive["indices"].as_u64().unwrap() as usize];
        assert_eq!(indices["componentType"], 5125); // UNSIGNED_INT
        // Models without sketches have no curves extras to carry but still say what they are.
        assert_eq!(json["nodes"][0]["extras"]["sketchmesh"]["version"], 1);
    }
}

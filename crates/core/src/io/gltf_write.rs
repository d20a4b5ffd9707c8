//! Writing a [`Document`] as binary glTF 2.0.
//!
//! Layout, chosen to pass the Khronos glTF validator without errors or warnings: one buffer
//! (the GLB BIN chunk); one tightly packed buffer view per accessor, each starting on a
//! 4-byte boundary and carrying its `target`; `min`/`max` on every POSITION accessor computed
//! from the `f32` values actually written; unit-length normals; `u16` indices when no index
//! reaches the primitive-restart value 65535, else `u32`; the material is written only if a
//! triangle primitive uses it. An empty document gives a valid file with one empty scene.

use std::collections::{BTreeMap, HashMap};

use glam::{DVec3, Vec3};
use gltf::json;
use json::validation::{Checked::Valid, USize64};
use serde_json::value::RawValue;

use super::EXTRAS_VERSION;
use super::extras::{CurveExtras, NodeExtras, SketchExtras, SketchmeshExtras};
use crate::document::{Document, Image, Model, PointCloud, SketchCurve};
use crate::geometry::vertex_normals;
use crate::mesh::Mesh;

/// The name of the material of models made here, by which import recognizes them.
pub(super) const CLAY_MATERIAL_NAME: &str = "Sketchmesh clay";

/// Encodes the document as a .glb file; see the module docs for the layout.
pub fn write_glb(doc: &Document) -> Vec<u8> {
    let mut writer = Writer::default();
    let mut nodes = Vec::new();
    for (index, model) in doc.models.iter().enumerate() {
        nodes.push(writer.model_node(index, model));
    }
    if !doc.sketches.is_empty() {
        nodes.push(writer.sketch_node(&doc.sketches));
    }
    for (index, points) in doc.point_clouds.iter().enumerate() {
        nodes.push(writer.point_cloud_node(index, points));
    }
    writer.finish(nodes)
}

#[derive(Default)]
pub(super) struct Writer {
    pub(super) root: json::Root,
    bin: Vec<u8>,
    material: Option<json::Index<json::Material>>,
    /// Images already written, by the address of their shared bytes.
    pub(super) images: HashMap<*const Image, json::Index<json::Image>>,
}

impl Writer {
    fn model_node(&mut self, index: usize, model: &Model) -> json::Index<json::Node> {
        let mesh = &model.mesh;
        let name = model
            .name
            .clone()
            .unwrap_or_else(|| format!("model {index}"));
        let appearance = model.appearance.as_deref().filter(|a| a.fits(mesh));
        let mesh_index = (mesh.n_faces() > 0).then(|| {
            let primitives = match appearance {
                Some(appearance) => self.imported_primitives(mesh, appearance),
                None => vec![self.clay_primitive(mesh)],
            };
            self.mesh(name.clone(), primitives)
        });
        // Imported models without curves stay foreign files' models: no Sketchmesh extras,
        // so importing the export again keeps their look.
        let extras = (appearance.is_none() || !model.curves.is_empty()).then(|| {
            let curves = model
                .curves
                .iter()
                .map(|curve| CurveExtras {
                    closed: curve.closed,
                    sharp: curve.sharp,
                    points: curve.points.iter().map(|p| p.to_array()).collect(),
                })
                .collect();
            extras(SketchmeshExtras {
                version: EXTRAS_VERSION,
                curves,
                sketches: Vec::new(),
            })
        });
        self.root.push(json::Node {
            mesh: mesh_index,
            name: Some(name),
            extras: extras.flatten(),
            ..Default::default()
        })
    }

    /// A model made here: welded vertices, smooth normals, the clay material.
    fn clay_primitive(&mut self, mesh: &Mesh) -> json::mesh::Primitive {
        let (positions, normals) = f32_positions_and_normals(mesh);
        let mut attributes = BTreeMap::new();
        attributes.insert(
            Valid(json::mesh::Semantic::Positions),
            self.positions(&positions),
        );
        attributes.insert(
            Valid(json::mesh::Semantic::Normals),
            self.vec3s(&normals, None),
        );
        let material = self.material();
        self.triangle_primitive(
            attributes,
            mesh.triangle_indices(),
            positions.len(),
            Some(material),
        )
    }

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

    fn point_cloud_node(&mut self, index: usize, points: &PointCloud) -> json::Index<json::Node> {
        let positions: Vec<Vec3> = points.positions.iter().map(|p| p.as_vec3()).collect();
        let mut attributes = BTreeMap::new();
        attributes.insert(
            Valid(json::mesh::Semantic::Positions),
            self.positions(&positions),
        );
        if let Some(colors) = &points.colors {
            attributes.insert(Valid(json::mesh::Semantic::Colors(0)), self.floats(colors));
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
        let mesh = (!positions.is_empty()).then(|| self.mesh(name.clone(), vec![primitive]));
        self.root.push(json::Node {
            mesh,
            name: Some(name),
            ..Default::default()
        })
    }

    fn sketch_node(&mut self, sketches: &[std::sync::Arc<SketchCurve>]) -> json::Index<json::Node> {
        let primitives: Vec<json::mesh::Primitive> = sketches
            .iter()
            .filter(|sketch| sketch.points.len() >= 2)
            .map(|sketch| {
                let positions: Vec<Vec3> = sketch.points.iter().map(|p| p.as_vec3()).collect();
                let mut attributes = BTreeMap::new();
                attributes.insert(
                    Valid(json::mesh::Semantic::Positions),
                    self.positions(&positions),
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
            (!primitives.is_empty()).then(|| self.mesh(String::from("sketches"), primitives));
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
        });
        self.root.push(json::Node {
            mesh,
            name: Some(String::from("sketches")),
            extras,
            ..Default::default()
        })
    }

    pub(super) fn mesh(
        &mut self,
        name: String,
        primitives: Vec<json::mesh::Primitive>,
    ) -> json::Index<json::Mesh> {
        self.root.push(json::Mesh {
            extensions: None,
            extras: None,
            name: Some(name),
            primitives,
            weights: None,
        })
    }

    pub(super) fn material(&mut self) -> json::Index<json::Material> {
        if let Some(material) = self.material {
            return material;
        }
        let material = self.root.push(json::Material {
            name: Some(String::from(CLAY_MATERIAL_NAME)),
            // Open surfaces are common while modeling; show their back faces too.
            double_sided: true,
            pbr_metallic_roughness: json::material::PbrMetallicRoughness {
                base_color_factor: json::material::PbrBaseColorFactor([0.8, 0.8, 0.8, 1.0]),
                metallic_factor: json::material::StrengthFactor(0.0),
                roughness_factor: json::material::StrengthFactor(0.6),
                ..Default::default()
            },
            ..Default::default()
        });
        self.material = Some(material);
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

    fn finish(mut self, nodes: Vec<json::Index<json::Node>>) -> Vec<u8> {
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

/// Positions as written (`f32`) and unit normals computed from exactly those positions, so a
/// file imported and exported again gets the same normals, bit for bit.
pub(super) fn f32_positions_and_normals(mesh: &Mesh) -> (Vec<Vec3>, Vec<Vec3>) {
    let positions: Vec<Vec3> = mesh.positions().iter().map(|p| p.as_vec3()).collect();
    let mut rounded = mesh.clone();
    for (p, q) in rounded.positions_mut().iter_mut().zip(&positions) {
        *p = q.as_dvec3();
    }
    let normals = vertex_normals(&rounded).into_iter().map(unit_f32).collect();
    (positions, normals)
}

/// A normal as a unit `f32` vector; a degenerate normal (a vertex whose faces have no area)
/// becomes +Z, because glTF requires unit length.
fn unit_f32(normal: DVec3) -> Vec3 {
    match normal.try_normalize() {
        Some(unit) => unit.as_vec3(),
        None => Vec3::Z,
    }
}

fn extras(sketchmesh: SketchmeshExtras) -> Option<Box<RawValue>> {
    // Unreachable failure: plain numbers and booleans (non-finite numbers become null).
    serde_json::value::to_raw_value(&NodeExtras { sketchmesh }).ok()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::document::{ControlCurve, Model};
    use crate::mesh::primitives;
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
        let curve = ControlCurve {
            points: vec![
                DVec3::new(1.0, 0.0, 0.0),
                DVec3::new(0.0, 1.0, 0.0),
                DVec3::new(0.0, 0.0, 1.0),
            ],
            vertices: Vec::new(),
            closed: true,
            sharp: false,
        };
        Document {
            models: vec![Arc::new(Model {
                mesh: primitives::icosphere(1.0, 1),
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
        assert_eq!(curves[0]["points"].as_array().unwrap().len(), 3);
    }

    #[test]
    fn empty_document_is_an_empty_scene() {
        let glb = write_glb(&Document::default());
        let (json, bin) = unpack(&glb);
        assert!(bin.is_empty());
        assert_eq!(json["scenes"], serde_json::json!([{}]));
        assert!(json.get("buffers").is_none() && json.get("materials").is_none());
        // (gltf-json itself cannot read a scene without "nodes"; our reader can.)
        let file = crate::io::ImportFile {
            name: "empty.glb",
            bytes: &glb,
        };
        assert!(crate::io::inspect_gltf(&file, &[]).is_ok());
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

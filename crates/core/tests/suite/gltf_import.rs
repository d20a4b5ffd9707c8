//! glTF import over a generated fixture corpus: every feature the importer promises, every
//! kind of bad input it must refuse (with a sentence, without touching the document), and
//! the export → import → export round trip.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::sync::Arc;

use glam::{DMat4, DQuat, DVec3};
use serde_json::{Value, json};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{Editor, FileInput, ImportInput, Op, StrokeInput};
use sketchmesh_core::io::{
    GltfError, ImportFile, ImportLimits, Imported, import_gltf, inspect_gltf, write_glb,
};

const FLOAT: u32 = 5126;
const BYTE: u32 = 5120;
const UNSIGNED_BYTE: u32 = 5121;
const SHORT: u32 = 5122;
const UNSIGNED_SHORT: u32 = 5123;
const UNSIGNED_INT: u32 = 5125;

/// A unit tetrahedron, wound outward.
const TETRA_POSITIONS: [[f32; 3]; 4] = [
    [0.0, 0.0, 0.0],
    [1.0, 0.0, 0.0],
    [0.0, 1.0, 0.0],
    [0.0, 0.0, 1.0],
];
const TETRA_TRIANGLES: [[u32; 3]; 4] = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];

/// Builds small glTF assets by hand: JSON plus one binary buffer.
#[derive(Clone)]
struct Asset {
    json: Value,
    bin: Vec<u8>,
}

impl Asset {
    fn new() -> Self {
        Self {
            json: json!({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": []}],
                "nodes": [], "meshes": [], "accessors": [], "bufferViews": []}),
            bin: Vec::new(),
        }
    }

    fn push(&mut self, array: &str, value: Value) -> usize {
        let list = self.json[array].as_array_mut().unwrap();
        list.push(value);
        list.len() - 1
    }

    fn view(&mut self, bytes: &[u8], stride: Option<usize>) -> usize {
        while !self.bin.len().is_multiple_of(4) {
            self.bin.push(0);
        }
        let mut view =
            json!({"buffer": 0, "byteOffset": self.bin.len(), "byteLength": bytes.len()});
        if let Some(stride) = stride {
            view["byteStride"] = json!(stride);
        }
        self.bin.extend_from_slice(bytes);
        self.push("bufferViews", view)
    }

    fn accessor(
        &mut self,
        view: Option<usize>,
        component: u32,
        count: usize,
        ty: &str,
        extra: Value,
    ) -> usize {
        let mut accessor = json!({"componentType": component, "count": count, "type": ty});
        if let Some(view) = view {
            accessor["bufferView"] = json!(view);
        }
        for (key, value) in extra.as_object().into_iter().flatten() {
            accessor[key] = value.clone();
        }
        self.push("accessors", accessor)
    }

    fn positions(&mut self, positions: &[[f32; 3]]) -> usize {
        let bytes: Vec<u8> = positions
            .iter()
            .flatten()
            .flat_map(|c| c.to_le_bytes())
            .collect();
        let view = self.view(&bytes, None);
        let min: Vec<f32> = (0..3)
            .map(|k| positions.iter().map(|p| p[k]).fold(f32::INFINITY, f32::min))
            .collect();
        let max: Vec<f32> = (0..3)
            .map(|k| {
                positions
                    .iter()
                    .map(|p| p[k])
                    .fold(f32::NEG_INFINITY, f32::max)
            })
            .collect();
        self.accessor(
            Some(view),
            FLOAT,
            positions.len(),
            "VEC3",
            json!({"min": min, "max": max}),
        )
    }

    fn floats(&mut self, values: &[f32], ty: &str, n: usize) -> usize {
        let bytes: Vec<u8> = values.iter().flat_map(|c| c.to_le_bytes()).collect();
        let view = self.view(&bytes, None);
        self.accessor(Some(view), FLOAT, values.len() / n, ty, json!({}))
    }

    fn indices(&mut self, indices: &[u32], component: u32) -> usize {
        let bytes: Vec<u8> = match component {
            UNSIGNED_BYTE => indices.iter().map(|&i| i as u8).collect(),
            UNSIGNED_SHORT => indices
                .iter()
                .flat_map(|&i| (i as u16).to_le_bytes())
                .collect(),
            _ => indices.iter().flat_map(|&i| i.to_le_bytes()).collect(),
        };
        let view = self.view(&bytes, None);
        self.accessor(Some(view), component, indices.len(), "SCALAR", json!({}))
    }

    /// A mesh with one primitive; returns the mesh index.
    fn mesh(&mut self, primitive: Value) -> usize {
        self.push("meshes", json!({"primitives": [primitive]}))
    }

    /// A node placed in the scene's root list.
    fn root_node(&mut self, node: Value) -> usize {
        let index = self.push("nodes", node);
        self.json["scenes"][0]["nodes"]
            .as_array_mut()
            .unwrap()
            .push(json!(index));
        index
    }

    /// The tetrahedron as an indexed primitive with `component` indices.
    fn tetra_mesh(&mut self, component: u32) -> usize {
        let position = self.positions(&TETRA_POSITIONS);
        let indices = self.indices(TETRA_TRIANGLES.as_flattened(), component);
        self.mesh(json!({"attributes": {"POSITION": position}, "indices": indices}))
    }

    fn finish_json(&self, uri: Option<&str>) -> Value {
        let mut json = self.json.clone();
        let mut buffer = json!({"byteLength": self.bin.len()});
        if let Some(uri) = uri {
            buffer["uri"] = json!(uri);
        }
        if !self.bin.is_empty() {
            json["buffers"] = json!([buffer]);
        }
        json
    }

    fn glb(&self) -> Vec<u8> {
        let mut json = serde_json::to_vec(&self.finish_json(None)).unwrap();
        while !json.len().is_multiple_of(4) {
            json.push(b' ');
        }
        let mut bin = self.bin.clone();
        while !bin.len().is_multiple_of(4) {
            bin.push(0);
        }
        let total = 12 + 8 + json.len() + if bin.is_empty() { 0 } else { 8 + bin.len() };
        let mut out = Vec::new();
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

    fn gltf_embedded(&self) -> Vec<u8> {
        use base64::Engine as _;
        let uri = format!(
            "data:application/octet-stream;base64,{}",
            base64::engine::general_purpose::STANDARD.encode(&self.bin)
        );
        serde_json::to_vec(&self.finish_json(Some(&uri))).unwrap()
    }
}

fn import(bytes: &[u8]) -> Result<Imported, GltfError> {
    import_gltf(
        &ImportFile {
            name: "test.glb",
            bytes,
        },
        &[],
        &ImportLimits::default(),
    )
}

fn signed_volume(imported: &Imported) -> f64 {
    imported
        .models
        .iter()
        .map(|m| sketchmesh_core::geometry::enclosed_volume(&m.mesh))
        .sum()
}

#[test]
fn index_widths_and_containers_all_give_the_tetrahedron() {
    for component in [UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT] {
        let mut asset = Asset::new();
        let mesh = asset.tetra_mesh(component);
        asset.root_node(json!({"mesh": mesh}));
        for bytes in [asset.glb(), asset.gltf_embedded()] {
            let imported = import(&bytes).unwrap();
            assert_eq!(imported.models.len(), 1);
            let mesh = &imported.models[0].mesh;
            assert_eq!((mesh.n_vertices(), mesh.n_faces()), (4, 4));
            assert!(mesh.is_closed());
            assert!((signed_volume(&imported) - 1.0 / 6.0).abs() < 1e-9);
        }
    }
}

#[test]
fn gltf_with_separate_bin_needs_the_bin() {
    let mut asset = Asset::new();
    let mesh = asset.tetra_mesh(UNSIGNED_SHORT);
    asset.root_node(json!({"mesh": mesh}));
    let json = serde_json::to_vec(&asset.finish_json(Some("tetra%20data.bin"))).unwrap();
    let main = ImportFile {
        name: "tetra.gltf",
        bytes: &json,
    };
    let bin = ImportFile {
        name: "tetra data.bin",
        bytes: &asset.bin,
    };
    let imported = import_gltf(&main, &[bin], &ImportLimits::default()).unwrap();
    assert_eq!(imported.models[0].mesh.n_faces(), 4);
    let error = import_gltf(&main, &[], &ImportLimits::default()).unwrap_err();
    assert_eq!(
        error.to_string(),
        "Buffer 0 refers to the file \"tetra%20data.bin\", which was not given; open or drop it together with the .gltf file."
    );
    let remote = serde_json::to_vec(&asset.finish_json(Some("https://example.com/t.bin"))).unwrap();
    let error = import(&remote).unwrap_err();
    assert!(error.to_string().contains("never downloads"), "{error}");
}

#[test]
fn node_transforms_nest_and_mirroring_keeps_volumes_positive() {
    let mut asset = Asset::new();
    let mesh = asset.tetra_mesh(UNSIGNED_SHORT);
    // Parent: TRS (translate, rotate 90° about z, scale 2); child: a matrix translating by x=1.
    let rotation = DQuat::from_rotation_z(std::f64::consts::FRAC_PI_2);
    let child = asset.push(
        "nodes",
        json!({"mesh": mesh, "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 1,0,0,1]}),
    );
    asset.root_node(json!({"children": [child], "translation": [0, 0, 5],
        "rotation": rotation.to_array(), "scale": [2, 2, 2]}));
    // A mirrored instance (negative determinant).
    asset.root_node(json!({"mesh": mesh, "scale": [-1, 1, 1], "translation": [10, 0, 0]}));
    let imported = import(&asset.glb()).unwrap();
    assert_eq!(imported.models.len(), 2);
    let world = DMat4::from_scale_rotation_translation(
        DVec3::splat(2.0),
        rotation,
        DVec3::new(0.0, 0.0, 5.0),
    ) * DMat4::from_translation(DVec3::X);
    let expected: Vec<DVec3> = TETRA_POSITIONS
        .iter()
        .map(|p| world.transform_point3(DVec3::from(p.map(f64::from))))
        .collect();
    for (got, want) in imported.models[0].mesh.positions().iter().zip(&expected) {
        assert!(got.distance(*want) < 1e-6, "{got} vs {want}");
    }
    for model in &imported.models {
        assert!(sketchmesh_core::geometry::enclosed_volume(&model.mesh) > 0.0);
    }
    assert!(
        (sketchmesh_core::geometry::enclosed_volume(&imported.models[0].mesh) - 8.0 / 6.0).abs()
            < 1e-6
    );
    assert!(
        imported.models[1]
            .mesh
            .positions()
            .iter()
            .all(|p| p.x <= 10.0 && p.x >= 9.0)
    );
}

#[test]
fn non_indexed_strips_and_fans() {
    let mut asset = Asset::new();
    // Non-indexed list: the tetrahedron with 12 vertices, welded back to 4.
    let corners: Vec<[f32; 3]> = TETRA_TRIANGLES
        .iter()
        .flatten()
        .map(|&i| TETRA_POSITIONS[i as usize])
        .collect();
    let position = asset.positions(&corners);
    let list = asset.mesh(json!({"attributes": {"POSITION": position}}));
    asset.root_node(json!({"mesh": list}));
    // A strip of 4 vertices (a quad) and a fan of 5 (a square split into 3).
    let strip_positions = asset.positions(&[
        [0.0, 0.0, 2.0],
        [1.0, 0.0, 2.0],
        [0.0, 1.0, 2.0],
        [1.0, 1.0, 2.0],
    ]);
    let strip = asset.mesh(json!({"attributes": {"POSITION": strip_positions}, "mode": 5}));
    asset.root_node(json!({"mesh": strip}));
    let fan_positions = asset.positions(&[
        [0.0, 0.0, 3.0],
        [1.0, 0.0, 3.0],
        [1.0, 1.0, 3.0],
        [0.0, 1.0, 3.0],
        [-1.0, 0.5, 3.0],
    ]);
    let fan = asset.mesh(json!({"attributes": {"POSITION": fan_positions}, "mode": 6}));
    asset.root_node(json!({"mesh": fan}));
    let imported = import(&asset.glb()).unwrap();
    let counts: Vec<(usize, usize)> = imported
        .models
        .iter()
        .map(|m| (m.mesh.n_vertices(), m.mesh.n_faces()))
        .collect();
    assert_eq!(counts, vec![(4, 4), (4, 2), (5, 3)]);
    assert!(imported.models[0].mesh.is_closed());
    // Strip and fan triangles all face +z (consistent winding).
    for model in &imported.models[1..] {
        for f in model.mesh.faces() {
            assert!(sketchmesh_core::geometry::face_normal(&model.mesh, f).z > 0.99);
        }
    }
}

#[test]
fn quantized_and_sparse_positions() {
    let mut asset = Asset::new();
    asset.json["extensionsUsed"] = json!(["KHR_mesh_quantization"]);
    asset.json["extensionsRequired"] = json!(["KHR_mesh_quantization"]);
    // Normalized signed bytes, 4-byte stride: 127 means 1.0.
    let bytes: Vec<u8> = TETRA_POSITIONS
        .iter()
        .flat_map(|p| {
            [
                (p[0] * 127.0) as i8 as u8,
                (p[1] * 127.0) as i8 as u8,
                (p[2] * 127.0) as i8 as u8,
                0,
            ]
        })
        .collect();
    let view = asset.view(&bytes, Some(4));
    let position = asset.accessor(
        Some(view),
        BYTE,
        4,
        "VEC3",
        json!({"normalized": true, "min": [0, 0, 0], "max": [127, 127, 127]}),
    );
    let indices = asset.indices(TETRA_TRIANGLES.as_flattened(), UNSIGNED_SHORT);
    let mesh = asset.mesh(json!({"attributes": {"POSITION": position}, "indices": indices}));
    asset.root_node(json!({"mesh": mesh, "translation": [5, 0, 0]}));
    // Unnormalized shorts scaled by the node, as quantizing exporters write them.
    let shorts: Vec<u8> = TETRA_POSITIONS
        .iter()
        .flat_map(|p| {
            p.iter()
                .map(|c| (c * 1000.0) as i16)
                .chain([0])
                .flat_map(i16::to_le_bytes)
                .collect::<Vec<u8>>()
        })
        .collect();
    let view = asset.view(&shorts, Some(8));
    let position = asset.accessor(
        Some(view),
        SHORT,
        4,
        "VEC3",
        json!({"min": [0, 0, 0], "max": [1000, 1000, 1000]}),
    );
    let indices = asset.indices(TETRA_TRIANGLES.as_flattened(), UNSIGNED_BYTE);
    let mesh = asset.mesh(json!({"attributes": {"POSITION": position}, "indices": indices}));
    asset.root_node(
        json!({"mesh": mesh, "scale": [0.001, 0.001, 0.001], "translation": [10, 0, 0]}),
    );
    // Sparse: all-zero positions (no buffer view) with 3 of 4 substituted.
    let sparse_indices = asset.view(
        &[1u16, 2, 3]
            .iter()
            .flat_map(|i| i.to_le_bytes())
            .collect::<Vec<u8>>(),
        None,
    );
    let sparse_values: Vec<u8> = TETRA_POSITIONS[1..]
        .iter()
        .flatten()
        .map(|c| c + 20.0)
        .flat_map(f32::to_le_bytes)
        .collect();
    let sparse_values_view = asset.view(&sparse_values, None);
    let position = asset.accessor(None, FLOAT, 4, "VEC3", json!({"min": [0, 0, 0], "max": [21, 21, 21],
        "sparse": {"count": 3, "indices": {"bufferView": sparse_indices, "componentType": UNSIGNED_SHORT},
                   "values": {"bufferView": sparse_values_view}}}));
    let indices = asset.indices(TETRA_TRIANGLES.as_flattened(), UNSIGNED_INT);
    let mesh = asset.mesh(json!({"attributes": {"POSITION": position}, "indices": indices}));
    asset.root_node(json!({"mesh": mesh}));
    let imported = import(&asset.glb()).unwrap();
    assert_eq!(imported.models.len(), 3);
    let expected = |offset: DVec3| -> Vec<DVec3> {
        TETRA_POSITIONS
            .iter()
            .map(|p| DVec3::from(p.map(f64::from)) + offset)
            .collect()
    };
    let close = |a: &[DVec3], b: &[DVec3]| a.iter().zip(b).all(|(p, q)| p.distance(*q) < 1e-6);
    assert!(close(
        imported.models[0].mesh.positions(),
        &expected(DVec3::X * 5.0)
    ));
    assert!(close(
        imported.models[1].mesh.positions(),
        &expected(DVec3::X * 10.0)
    ));
    let sparse = imported.models[2].mesh.positions();
    assert_eq!(sparse[0], DVec3::ZERO);
    assert!(close(&sparse[1..], &expected(DVec3::splat(20.0))[1..]));
}

#[test]
fn seams_are_welded_and_uvs_survive_export() {
    // A cube-like tetrahedron split at every corner (as exporters do for flat normals/UVs).
    let mut asset = Asset::new();
    let corners: Vec<[f32; 3]> = TETRA_TRIANGLES
        .iter()
        .flatten()
        .map(|&i| TETRA_POSITIONS[i as usize])
        .collect();
    let position = asset.positions(&corners);
    let uvs: Vec<f32> = (0..12)
        .flat_map(|k| [k as f32 / 12.0, 1.0 - k as f32 / 12.0])
        .collect();
    let uv = asset.floats(&uvs, "VEC2", 2);
    let colors: Vec<f32> = (0..12)
        .flat_map(|k| [1.0, k as f32 / 11.0, 0.0, 1.0])
        .collect();
    let color = asset.floats(&colors, "VEC4", 4);
    let indices = asset.indices(&(0..12).collect::<Vec<u32>>(), UNSIGNED_SHORT);
    asset.json["materials"] = json!([{"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1], "metallicFactor": 0.5}}]);
    let mesh = asset.mesh(json!({"attributes": {"POSITION": position, "TEXCOORD_0": uv, "COLOR_0": color}, "indices": indices, "material": 0}));
    asset.root_node(json!({"mesh": mesh, "name": "painted"}));
    let imported = import(&asset.glb()).unwrap();
    let model = &imported.models[0];
    assert_eq!((model.mesh.n_vertices(), model.mesh.n_faces()), (4, 4));
    assert_eq!(model.name.as_deref(), Some("painted"));
    let appearance = model.appearance.as_ref().unwrap();
    assert_eq!(appearance.uvs.as_ref().unwrap().len(), 12);
    assert_eq!(appearance.materials[0].base_color, [1.0, 0.0, 0.0, 1.0]);
    // Export writes the 12 split vertices with their UVs and colours and the material.
    let mut editor = Editor::new();
    editor.apply(import_op("painted.glb", asset.glb())).unwrap();
    let exported = write_glb(editor.document());
    let again = import(&exported).unwrap();
    let appearance_again = again.models[0].appearance.as_ref().unwrap();
    assert_eq!(appearance_again.uvs, appearance.uvs);
    assert_eq!(appearance_again.colors, appearance.colors);
    assert_eq!(appearance_again.materials[0].name.as_deref(), Some("red"));
    assert_eq!(appearance_again.materials[0].metallic, 0.5);
    // And a second round gives the same bytes.
    let mut second = Editor::new();
    second
        .apply(import_op("again.glb", exported.clone()))
        .unwrap();
    assert_eq!(write_glb(second.document()), exported);
}

#[test]
fn points_and_lines_are_kept() {
    let mut asset = Asset::new();
    let position = asset.positions(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]]);
    let points = asset.mesh(json!({"attributes": {"POSITION": position}, "mode": 0}));
    asset.root_node(json!({"mesh": points}));
    let strip = asset.mesh(json!({"attributes": {"POSITION": position}, "mode": 3}));
    asset.root_node(json!({"mesh": strip}));
    let imported = import(&asset.glb()).unwrap();
    assert!(imported.models.is_empty());
    assert_eq!(imported.point_clouds.len(), 1);
    assert_eq!(imported.point_clouds[0].positions.len(), 3);
    assert_eq!(imported.sketches.len(), 1);
    assert_eq!(imported.sketches[0].points.len(), 3);
}

/// A tetrahedron with three hand-written curves: one near its vertices, one on them, one far
/// off its surface.
fn tetra_with_curve_extras() -> Asset {
    let mut asset = Asset::new();
    let mesh = asset.tetra_mesh(UNSIGNED_SHORT);
    let curves = json!([
        // Near vertices 1 and 2 (not on them): snapped, and joined by their edge.
        {"closed": false, "sharp": true, "points": [[0.98, 0.01, 0.0], [0.02, 0.97, 0.01]]},
        // Exactly on vertices 0, 1 and 3: found as they are.
        {"closed": true, "sharp": false, "points": [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]},
        // Far off the surface.
        {"closed": false, "sharp": false, "points": [[0.0, 0.0, 0.0], [5.0, 5.0, 5.0]]},
    ]);
    asset.root_node(json!({
        "mesh": mesh,
        "extras": {"sketchmesh": {"version": 1, "curves": curves}},
    }));
    asset
}

#[test]
fn hand_written_curve_extras_become_edge_chains_or_are_left_out() {
    let imported = import(&tetra_with_curve_extras().glb()).unwrap();
    let model = &imported.models[0];
    assert_eq!(model.curves.len(), 2);
    let (snapped, exact) = (&model.curves[0], &model.curves[1]);
    let position = |v: sketchmesh_core::mesh::VertexId| model.mesh.position(v).to_array();
    assert!(snapped.is_sharp() && !snapped.is_closed);
    assert_eq!(
        snapped
            .vertices
            .iter()
            .map(|&v| position(v))
            .collect::<Vec<_>>(),
        [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
    );
    assert!(!exact.is_sharp() && exact.is_closed);
    assert_eq!(exact.points(&model.mesh), [DVec3::ZERO, DVec3::X, DVec3::Z]);
    assert_eq!(imported.notes.len(), 2, "{:?}", imported.notes);
    assert!(imported.notes[0].contains("1 control curve of"));
    assert!(imported.notes[1].contains("was left out"));
}

#[test]
fn unknown_required_extensions_are_named() {
    let mut asset = Asset::new();
    let mesh = asset.tetra_mesh(UNSIGNED_SHORT);
    asset.root_node(json!({"mesh": mesh}));
    asset.json["extensionsUsed"] = json!(["KHR_draco_mesh_compression", "EXT_foo"]);
    asset.json["extensionsRequired"] = json!(["KHR_draco_mesh_compression", "EXT_foo"]);
    assert_eq!(
        import(&asset.glb()).unwrap_err().to_string(),
        "The file requires the glTF extension(s) KHR_draco_mesh_compression, EXT_foo, which Sketchmesh cannot read."
    );
}

fn import_op(name: &str, bytes: Vec<u8>) -> Op {
    Op::Import(ImportInput {
        files: vec![FileInput {
            name: name.to_owned(),
            data: Some(Arc::new(bytes)),
        }],
        beside: false,
    })
}

#[test]
fn the_editor_keeps_an_imports_notes_until_the_next_op() {
    let mut editor = Editor::new();
    editor
        .apply(import_op("curves.glb", tetra_with_curve_extras().glb()))
        .unwrap();
    let expected = import(&tetra_with_curve_extras().glb()).unwrap().notes;
    assert_eq!(editor.notes(), expected.as_slice());
    assert_eq!(editor.notes().len(), 2);
    editor.undo().unwrap();
    assert!(editor.notes().is_empty(), "an undo says nothing");
    editor.redo().unwrap();
    assert!(
        editor.notes().is_empty(),
        "nor does a redo: the notes were said once"
    );
}

/// An editor with one sketch, to check that refused imports change nothing.
fn editor_with_a_sketch() -> Editor {
    let mut editor = Editor::new();
    editor
        .apply(Op::Stroke(StrokeInput {
            viewport: [800.0, 600.0],
            camera: Camera::default(),
            stroke: vec![
                [100.0, 100.0, 0.5],
                [200.0, 150.0, 0.5],
                [300.0, 100.0, 0.5],
            ],
        }))
        .unwrap();
    editor
}

/// Applies a bad file: the error message must contain `expected` and nothing may change.
fn assert_refused(bytes: Vec<u8>, expected: &str) {
    let mut editor = editor_with_a_sketch();
    let (document, ops, revision) = (
        editor.document().clone(),
        editor.ops().to_vec(),
        editor.revision(),
    );
    let error = editor
        .apply(import_op("bad.glb", bytes))
        .expect_err(expected);
    assert!(
        error.to_string().contains(expected),
        "\"{error}\" lacks \"{expected}\""
    );
    assert!(error.to_string().ends_with('.'), "not a sentence: {error}");
    assert_eq!(editor.document(), &document);
    assert_eq!(editor.ops(), &ops[..]);
    assert_eq!(editor.revision(), revision);
    editor.undo().unwrap();
    assert!(editor.document().sketches.is_empty());
}

#[test]
fn bad_files_are_refused_with_a_sentence_and_change_nothing() {
    let mut asset = Asset::new();
    let mesh = asset.tetra_mesh(UNSIGNED_SHORT);
    asset.root_node(json!({"mesh": mesh}));
    let good = asset.glb();
    assert_refused(good[..good.len() - 10].to_vec(), "not valid glTF");
    assert_refused(good[..30].to_vec(), "not valid glTF");
    let mut magic = good.clone();
    magic[0] = b'X';
    assert_refused(magic, "not valid glTF");
    let mut version = good.clone();
    version[4] = 1;
    assert_refused(version, "glTF version 1 (GLB)");
    let mut json_v1 = asset.clone();
    json_v1.json["asset"]["version"] = json!("1.0");
    assert_refused(json_v1.gltf_embedded(), "glTF version 1.0");
    // An accessor reaching past its view.
    let mut long = asset.clone();
    long.json["accessors"][0]["count"] = json!(5);
    assert_refused(long.glb(), "Accessor 0 reads past the end of its buffer.");
    // An index past the vertices.
    let mut wild = Asset::new();
    let position = wild.positions(&TETRA_POSITIONS);
    let indices = wild.indices(&[0, 1, 9], UNSIGNED_SHORT);
    let mesh = wild.mesh(json!({"attributes": {"POSITION": position}, "indices": indices}));
    wild.root_node(json!({"mesh": mesh}));
    assert_refused(
        wild.glb(),
        "uses vertex index 9, but the primitive has only 4 vertices",
    );
    // NaN and infinite positions.
    let mut nan = Asset::new();
    let mut positions = TETRA_POSITIONS;
    positions[2][1] = f32::NAN;
    let position = nan.positions(&positions);
    let indices = nan.indices(TETRA_TRIANGLES.as_flattened(), UNSIGNED_SHORT);
    let mesh = nan.mesh(json!({"attributes": {"POSITION": position}, "indices": indices}));
    nan.root_node(json!({"mesh": mesh}));
    nan.json["accessors"][0]["min"] = json!([0, 0, 0]);
    nan.json["accessors"][0]["max"] = json!([1, 1, 1]);
    assert_refused(nan.glb(), "holds a position that is not a finite number");
    let mut huge_scale = asset.clone();
    huge_scale.json["nodes"][0]["scale"] = json!([1e38, 1e38, 1e38]);
    huge_scale.json["nodes"][0]["translation"] = json!([3e38, 0, 0]);
    assert_refused(huge_scale.glb(), "not a finite number");
    // An accessor claiming 2^31 elements, with and without data behind it.
    let mut absurd = asset.clone();
    absurd.json["accessors"][0]["count"] = json!(1u64 << 31);
    assert_refused(absurd.glb(), "more than the import limit of 10000000");
    let mut absurd_sparse = asset.clone();
    absurd_sparse.json["accessors"][1]["count"] = json!(1u64 << 31);
    assert_refused(absurd_sparse.glb(), "more than the import limit");
    // Instancing a mesh past the limits is refused before anything is read.
    let mut many = asset.clone();
    let children: Vec<usize> = (0..64)
        .map(|_| many.push("nodes", json!({"mesh": 0})))
        .collect();
    many.root_node(json!({"children": children}));
    let limits = ImportLimits {
        max_vertices: 100,
        ..ImportLimits::default()
    };
    let error = import_gltf(
        &ImportFile {
            name: "many.glb",
            bytes: &many.glb(),
        },
        &[],
        &limits,
    )
    .unwrap_err();
    assert_eq!(
        error.to_string(),
        "The scene has 260 vertices, more than the import limit of 100."
    );
    let limits = ImportLimits {
        max_file_bytes: 100,
        ..ImportLimits::default()
    };
    let error = import_gltf(
        &ImportFile {
            name: "big.glb",
            bytes: &good,
        },
        &[],
        &limits,
    )
    .unwrap_err();
    assert!(error.to_string().starts_with("The file is "), "{error}");
    // A broken reference and a scene without geometry.
    let mut dangling = asset.clone();
    dangling.json["meshes"][0]["primitives"][0]["indices"] = json!(7);
    assert_refused(dangling.glb(), "not valid glTF");
    assert_refused(Asset::new().glb(), "no triangles, lines or points");
    assert_refused(b"{\"asset\": 3}".to_vec(), "asset.version");
    assert_refused(Vec::new(), "not valid glTF");
}

#[test]
fn mutated_files_never_panic() {
    let mut asset = Asset::new();
    let mesh = asset.tetra_mesh(UNSIGNED_SHORT);
    asset.root_node(json!({"mesh": mesh}));
    for good in [asset.glb(), asset.gltf_embedded()] {
        let mut corrupted = good.clone();
        for at in 0..good.len() {
            for flip in [0x01, 0x80, 0xff] {
                corrupted[at] ^= flip;
                let _ = import(&corrupted);
                corrupted[at] = good[at];
            }
        }
        for length in 0..good.len() {
            let _ = import(&good[..length]);
        }
    }
}

/// A closed stroke (a circle) that creates a FiberMesh model.
fn create_op(centre_x: f64) -> Op {
    let stroke = (0..=64)
        .map(|k| {
            let angle = std::f64::consts::TAU * f64::from(k) / 64.0;
            [
                centre_x + 120.0 * angle.cos(),
                300.0 + 120.0 * angle.sin(),
                0.5,
            ]
        })
        .collect();
    Op::Create(
        StrokeInput {
            viewport: [800.0, 600.0],
            camera: Camera::default(),
            stroke,
        }
        .into(),
    )
}

#[test]
fn created_models_round_trip_with_their_curves() {
    let mut editor = editor_with_a_sketch();
    editor.apply(create_op(400.0)).unwrap();
    let original = editor.document().clone();
    let exported = write_glb(&original);
    let mut reimported = Editor::new();
    reimported
        .apply(import_op("round.glb", exported.clone()))
        .unwrap();
    let document = &reimported.document().clone();
    assert_eq!(document.models.len(), 1);
    let (before, after) = (&original.models[0], &document.models[0]);
    assert!(after.appearance.is_none() && after.name.is_none());
    assert_eq!(after.mesh.triangles(), before.mesh.triangles());
    assert_eq!(after.curves.len(), 1);
    assert_eq!(after.curves[0].vertices, before.curves[0].vertices);
    assert_eq!(
        (after.curves[0].is_closed, after.curves[0].is_sharp()),
        (true, false)
    );
    // The mesh comes back at f32 precision, except the curve vertices: the extras keep
    // their exact positions.
    let on_curve = &before.curves[0].vertices;
    for v in before.mesh.vertices() {
        let (p, q) = (after.mesh.position(v), before.mesh.position(v));
        if on_curve.contains(&v) {
            assert_eq!(p, q);
        } else {
            assert_eq!(p, q.as_vec3().as_dvec3());
        }
    }
    assert_eq!(document.sketches, original.sketches);
    assert_eq!(
        write_glb(document),
        exported,
        "a second export must be byte-identical"
    );
    let info = inspect_gltf(
        &ImportFile {
            name: "round.glb",
            bytes: &exported,
        },
        &[],
    )
    .unwrap();
    assert_eq!((info.control_curves, info.sketches), (1, 1));
    // The import is one undoable step.
    reimported.undo().unwrap();
    assert!(reimported.document().is_empty());
    reimported.redo().unwrap();
    assert_eq!(reimported.document(), document);
}

//! `inspect_glb`: what a glTF file contains, as topology a modeler cares about.

use glam::DVec3;
use serde::Serialize;

use super::error::GltfError;
use super::input::{ImportFile, ImportLimits};
use super::parse::parse;
use super::resources::load_buffers;
use super::scene::read_nodes;
use super::weld::weld;
use crate::mesh::{Mesh, TriSoup, count_components};

/// Summary of a glTF file's default scene (printed as JSON by `sketchmesh info`).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Info {
    /// Distinct vertex positions used by triangles, after welding equal positions.
    pub vertices: usize,
    /// Triangles over all triangle primitives.
    pub triangles: usize,
    /// Connected pieces (triangles sharing a welded vertex are connected).
    pub components: usize,
    /// Whether the welded triangles form a manifold mesh without boundary.
    pub closed: bool,
    /// Whether the welded triangles form an oriented manifold mesh (see `Mesh::from_soup`);
    /// false when there are no triangles.
    pub manifold: bool,
    /// Total genus of a manifold mesh (with or without boundary); `null` otherwise.
    pub genus: Option<u32>,
    /// Lower corner of the world-space bounds of the triangles; `null` if there are none.
    pub bbox_min: Option<[f64; 3]>,
    /// Upper corner of the world-space bounds of the triangles; `null` if there are none.
    pub bbox_max: Option<[f64; 3]>,
    /// Control curves stored in Sketchmesh node extras.
    pub control_curves: usize,
    /// Sketch curves stored in Sketchmesh node extras.
    pub sketches: usize,
}

/// Reads a .glb or .gltf (with the files given alongside) and summarizes its default scene:
/// all triangle primitives with node transforms applied, vertices welded by exact position.
///
/// Errors on anything that is not readable glTF, and never panics on bad input.
pub fn inspect_gltf(main: &ImportFile, others: &[ImportFile]) -> Result<Info, GltfError> {
    let limits = ImportLimits::default();
    let parsed = parse(main.bytes, &limits)?;
    let buffers = load_buffers(&parsed.document, parsed.blob, others);
    let nodes = read_nodes(&parsed.document, &buffers, &limits)?;
    let mut soup = TriSoup::default();
    for node in &nodes {
        soup.append(&TriSoup {
            positions: node.surface.positions.clone(),
            triangles: node.surface.triangles.clone(),
        });
    }
    let (positions, welded_of) = weld(&soup.positions);
    soup.positions = positions;
    for i in soup.triangles.iter_mut().flatten() {
        *i = welded_of[*i as usize];
    }
    soup.remove_unreferenced_vertices();
    let mesh = (!soup.triangles.is_empty())
        .then(|| Mesh::from_soup(&soup).ok())
        .flatten();
    let bounds = bounding_box(&soup.positions);
    let extras = nodes
        .iter()
        .filter_map(|node| node.extras.as_ref())
        .map(|extras| &extras.sketchmesh);
    Ok(Info {
        vertices: soup.positions.len(),
        triangles: soup.triangles.len(),
        components: count_components(soup.positions.len(), &soup.triangles),
        closed: mesh.as_ref().is_some_and(Mesh::is_closed),
        manifold: mesh.is_some(),
        genus: mesh.as_ref().and_then(Mesh::genus),
        bbox_min: bounds.map(|(lo, _)| lo.to_array()),
        bbox_max: bounds.map(|(_, hi)| hi.to_array()),
        control_curves: extras.clone().map(|e| e.curves.len()).sum(),
        sketches: extras.map(|e| e.sketches.len()).sum(),
    })
}

fn bounding_box(positions: &[DVec3]) -> Option<(DVec3, DVec3)> {
    let first = *positions.first()?;
    Some(
        positions
            .iter()
            .fold((first, first), |(lo, hi), &p| (lo.min(p), hi.max(p))),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::write_glb;
    use crate::mesh::{VertexId, primitives};
    use crate::model::{ControlCurve, CurveKind, Document, Model, SketchCurve};
    use std::sync::Arc;

    fn inspect(bytes: &[u8]) -> Result<Info, GltfError> {
        inspect_gltf(
            &ImportFile {
                name: "test.glb",
                bytes,
            },
            &[],
        )
    }

    fn document_with(mesh: Mesh) -> Document {
        let neighbor = mesh.vertex_neighbors(VertexId(0)).next().unwrap();
        Document {
            models: vec![Arc::new(Model {
                mesh,
                curves: vec![ControlCurve {
                    vertices: vec![VertexId(0), neighbor],
                    is_closed: false,
                    kind: CurveKind::Sharp,
                }],
                ..Model::default()
            })],
            sketches: vec![Arc::new(SketchCurve {
                points: vec![DVec3::ZERO, DVec3::ONE, DVec3::Z],
                pressures: vec![0.5; 3],
            })],
            ..Document::default()
        }
    }

    #[test]
    fn icosphere_round_trip() {
        let glb = write_glb(&document_with(primitives::icosphere(2.0, 2)));
        let info = inspect(&glb).unwrap();
        assert_eq!(info.vertices, 162);
        assert_eq!(info.triangles, 320);
        assert_eq!(info.components, 1);
        assert!(info.closed && info.manifold);
        assert_eq!(info.genus, Some(0));
        assert_eq!(info.control_curves, 1);
        assert_eq!(info.sketches, 1);
        let (lo, hi) = (info.bbox_min.unwrap(), info.bbox_max.unwrap());
        for k in 0..3 {
            assert!((lo[k] + 2.0).abs() < 1e-6 && (hi[k] - 2.0).abs() < 1e-6);
        }
    }

    #[test]
    fn torus_has_genus_one() {
        let info = inspect(&write_glb(&document_with(primitives::torus(
            2.0, 0.5, 24, 12,
        ))))
        .unwrap();
        assert_eq!((info.vertices, info.triangles), (24 * 12, 2 * 24 * 12));
        assert!(info.closed);
        assert_eq!(info.genus, Some(1));
    }

    #[test]
    fn empty_document() {
        // (gltf-json itself cannot read a scene without "nodes"; our reader can.)
        let info = inspect(&write_glb(&Document::default())).unwrap();
        let json = serde_json::to_string(&info).unwrap();
        assert_eq!(
            json,
            r#"{"vertices":0,"triangles":0,"components":0,"closed":false,"manifold":false,"genus":null,"bbox_min":null,"bbox_max":null,"control_curves":0,"sketches":0}"#
        );
    }

    /// One triangle as .gltf JSON with a base64 buffer, placed by a node transform.
    fn triangle_gltf(node: &str) -> String {
        format!(
            r#"{{"asset":{{"version":"2.0"}},"scene":0,"scenes":[{{"nodes":[0]}}],
            "nodes":[{node}],
            "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}}}}]}}],
            "accessors":[{{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}}],
            "bufferViews":[{{"buffer":0,"byteLength":36}}],
            "buffers":[{{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}}]}}"#
        )
    }

    #[test]
    fn gltf_json_with_data_uri_and_transform() {
        let info =
            inspect(triangle_gltf(r#"{"mesh":0,"translation":[0,0,5]}"#).as_bytes()).unwrap();
        assert_eq!((info.vertices, info.triangles, info.components), (3, 1, 1));
        assert!(info.manifold && !info.closed);
        assert_eq!(info.genus, Some(0));
        assert_eq!(info.bbox_min, Some([0.0, 0.0, 5.0]));
        assert_eq!(info.bbox_max, Some([1.0, 1.0, 5.0]));
        // Two instances of the mesh under one parent weld into nothing new.
        let twice = triangle_gltf(r#"{"children":[1,2]},{"mesh":0},{"mesh":0}"#);
        let info = inspect(twice.as_bytes()).unwrap();
        assert_eq!((info.vertices, info.triangles), (3, 2));
        assert!(!info.manifold);
        assert_eq!(info.genus, None);
        // A cycle in the node graph is refused, not followed forever.
        let cycle = triangle_gltf(r#"{"children":[1]},{"children":[0]}"#);
        assert!(matches!(
            inspect(cycle.as_bytes()),
            Err(GltfError::NodeReachedTwice { .. })
        ));
        let external = triangle_gltf(r#"{"mesh":0}"#).replace(
            "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA",
            "triangle.bin",
        );
        let error = inspect(external.as_bytes()).unwrap_err();
        assert!(
            error
                .to_string()
                .contains("\"triangle.bin\", which was not given"),
            "{error}"
        );
    }

    #[test]
    fn bad_input_is_an_error_not_a_panic() {
        let glb = write_glb(&document_with(primitives::icosphere(1.0, 1)));
        for length in (0..glb.len()).step_by(7) {
            let _ = inspect(&glb[..length]);
        }
        assert!(inspect(&glb[..glb.len() - 4]).is_err());
        // Flip bytes all over the file, one at a time.
        let mut corrupted = glb.clone();
        for at in (0..glb.len()).step_by(5) {
            corrupted[at] ^= 0xA5;
            let _ = inspect(&corrupted);
            corrupted[at] = glb[at];
        }
        // Headers claiming lengths that do not fit.
        let mut header = glb[..12].to_vec();
        header[8..12].copy_from_slice(&4u32.to_le_bytes());
        assert!(inspect(&header).is_err());
        assert!(inspect(b"glTF").is_err());
        assert!(inspect(b"").is_err());
        assert!(inspect(b"{}").is_err());
        // An accessor past the end of its buffer.
        let short = triangle_gltf(r#"{"mesh":0}"#).replace(r#""count":3"#, r#""count":4"#);
        assert!(inspect(short.as_bytes()).is_err());
    }
}

//! `inspect_glb`: what a glTF file contains, as topology a modeler cares about.

use std::collections::HashMap;

use glam::DVec3;
use serde::Serialize;

use super::gltf_read::{GltfError, read_scene};
use crate::mesh::{Mesh, TriSoup};

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

/// Reads a .glb (or .gltf JSON with embedded data) and summarizes its default scene: all
/// triangle primitives with node transforms applied, vertices welded by exact position.
///
/// Errors on anything that is not readable glTF, and never panics on bad input.
pub fn inspect_glb(bytes: &[u8]) -> Result<Info, GltfError> {
    let contents = read_scene(bytes)?;
    let soup = weld(&contents.soup);
    let mesh = (!soup.triangles.is_empty())
        .then(|| Mesh::from_soup(&soup).ok())
        .flatten();
    let bounds = bounding_box(&soup.positions);
    let extras = contents.extras.iter().map(|extras| &extras.sketchmesh);
    Ok(Info {
        vertices: soup.positions.len(),
        triangles: soup.triangles.len(),
        components: count_components(&soup),
        closed: mesh.as_ref().is_some_and(Mesh::is_closed),
        manifold: mesh.is_some(),
        genus: mesh.as_ref().and_then(Mesh::genus),
        bbox_min: bounds.map(|(lo, _)| lo.to_array()),
        bbox_max: bounds.map(|(_, hi)| hi.to_array()),
        control_curves: extras.clone().map(|e| e.curves.len()).sum(),
        sketches: extras.map(|e| e.sketches.len()).sum(),
    })
}

/// Merges vertices with bit-identical positions (−0 equals +0) and drops vertices no
/// triangle uses. Triangle order and count are kept.
fn weld(soup: &TriSoup) -> TriSoup {
    let mut welded = TriSoup::default();
    let mut index_of: HashMap<[u64; 3], u32> = HashMap::new();
    let mut new_index = |p: DVec3, welded: &mut TriSoup| {
        // Adding +0.0 turns −0.0 into +0.0 and leaves everything else alone.
        let key = (p + DVec3::ZERO).to_array().map(f64::to_bits);
        *index_of.entry(key).or_insert_with(|| {
            welded.positions.push(p);
            (welded.positions.len() - 1) as u32
        })
    };
    for triangle in &soup.triangles {
        let mut out = [0; 3];
        for (slot, &i) in out.iter_mut().zip(triangle) {
            let p = soup.positions[i as usize];
            *slot = new_index(p, &mut welded);
        }
        welded.triangles.push(out);
    }
    welded
}

fn bounding_box(positions: &[DVec3]) -> Option<(DVec3, DVec3)> {
    let first = *positions.first()?;
    Some(
        positions
            .iter()
            .fold((first, first), |(lo, hi), &p| (lo.min(p), hi.max(p))),
    )
}

/// Connected components of triangles sharing vertices (union-find with path halving).
fn count_components(soup: &TriSoup) -> usize {
    let mut parent: Vec<usize> = (0..soup.positions.len()).collect();
    fn find(parent: &mut [usize], mut v: usize) -> usize {
        while parent[v] != v {
            parent[v] = parent[parent[v]];
            v = parent[v];
        }
        v
    }
    for triangle in &soup.triangles {
        let a = find(&mut parent, triangle[0] as usize);
        for &other in &triangle[1..] {
            let b = find(&mut parent, other as usize);
            parent[b] = a;
        }
    }
    (0..parent.len())
        .filter(|&v| find(&mut parent, v) == v)
        .count()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::document::{ControlCurve, Document, Model, SketchCurve};
    use crate::io::write_glb;
    use crate::mesh::primitives;
    use std::sync::Arc;

    fn document_with(mesh: Mesh) -> Document {
        Document {
            models: vec![Arc::new(Model {
                mesh,
                curves: vec![ControlCurve {
                    points: vec![DVec3::X, DVec3::Y],
                    vertices: Vec::new(),
                    closed: false,
                    sharp: true,
                }],
            })],
            sketches: vec![Arc::new(SketchCurve {
                points: vec![DVec3::ZERO, DVec3::ONE, DVec3::Z],
                pressures: vec![0.5; 3],
            })],
        }
    }

    #[test]
    fn icosphere_round_trip() {
        let glb = write_glb(&document_with(primitives::icosphere(2.0, 2)));
        let info = inspect_glb(&glb).unwrap();
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
        let info = inspect_glb(&write_glb(&document_with(primitives::torus(
            2.0, 0.5, 24, 12,
        ))))
        .unwrap();
        assert_eq!((info.vertices, info.triangles), (24 * 12, 2 * 24 * 12));
        assert!(info.closed);
        assert_eq!(info.genus, Some(1));
    }

    #[test]
    fn empty_document() {
        let info = inspect_glb(&write_glb(&Document::default())).unwrap();
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
            inspect_glb(triangle_gltf(r#"{"mesh":0,"translation":[0,0,5]}"#).as_bytes()).unwrap();
        assert_eq!((info.vertices, info.triangles, info.components), (3, 1, 1));
        assert!(info.manifold && !info.closed);
        assert_eq!(info.genus, Some(0));
        assert_eq!(info.bbox_min, Some([0.0, 0.0, 5.0]));
        assert_eq!(info.bbox_max, Some([1.0, 1.0, 5.0]));
        // Two instances of the mesh under one parent weld into nothing new.
        let twice = triangle_gltf(r#"{"children":[1,2]},{"mesh":0},{"mesh":0}"#);
        let info = inspect_glb(twice.as_bytes()).unwrap();
        assert_eq!((info.vertices, info.triangles), (3, 2));
        assert!(!info.manifold);
        assert_eq!(info.genus, None);
        // A cycle in the node graph is refused, not followed forever.
        let cycle = triangle_gltf(r#"{"children":[1]},{"children":[0]}"#);
        assert!(matches!(
            inspect_glb(cycle.as_bytes()),
            Err(GltfError::NodeReachedTwice { .. })
        ));
        let external = triangle_gltf(r#"{"mesh":0}"#).replace(
            "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA",
            "triangle.bin",
        );
        let error = inspect_glb(external.as_bytes()).unwrap_err();
        assert!(
            error.to_string().contains("external file \"triangle.bin\""),
            "{error}"
        );
    }

    #[test]
    fn weld_merges_exact_positions_only() {
        let soup = TriSoup {
            positions: vec![
                DVec3::ZERO,
                DVec3::X,
                DVec3::Y,
                DVec3::new(-0.0, 0.0, 0.0),
                DVec3::Y,
                DVec3::new(1.0, 1.0, 1e-300),
            ],
            triangles: vec![[0, 1, 2], [3, 4, 5]],
        };
        let welded = weld(&soup);
        assert_eq!(welded.positions.len(), 4);
        assert_eq!(welded.triangles, vec![[0, 1, 2], [0, 2, 3]]);
        assert_eq!(count_components(&welded), 1);
    }

    #[test]
    fn bad_input_is_an_error_not_a_panic() {
        let glb = write_glb(&document_with(primitives::icosphere(1.0, 1)));
        for length in (0..glb.len()).step_by(7) {
            let _ = inspect_glb(&glb[..length]);
        }
        assert!(inspect_glb(&glb[..glb.len() - 4]).is_err());
        // Flip bytes all over the file, one at a time.
        let mut corrupted = glb.clone();
        for at in (0..glb.len()).step_by(5) {
            corrupted[at] ^= 0xA5;
            let _ = inspect_glb(&corrupted);
            corrupted[at] = glb[at];
        }
        // Headers claiming lengths that do not fit.
        let mut header = glb[..12].to_vec();
        header[8..12].copy_from_slice(&4u32.to_le_bytes());
        assert!(inspect_glb(&header).is_err());
        assert!(inspect_glb(b"glTF").is_err());
        assert!(inspect_glb(b"").is_err());
        assert!(inspect_glb(b"{}").is_err());
        // An accessor past the end of its buffer.
        let short = triangle_gltf(r#"{"mesh":0}"#).replace(r#""count":3"#, r#""count":4"#);
        assert!(inspect_glb(short.as_bytes()).is_err());
    }
}

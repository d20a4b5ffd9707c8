//! Writing models as binary STL, the file slicers (PrusaSlicer, Cura) read.
//!
//! Layout (there is no formal standard; this is what every slicer reads): an 80-byte header,
//! here text that does not begin with "solid" (readers take a file that does for ASCII STL),
//! the triangle count as a little-endian `u32`, then 50 bytes per triangle: the facet's unit
//! normal, its three corners counter-clockwise seen from outside, all as little-endian `f32`,
//! and a `u16` attribute of 0. STL has no unit: the numbers are in the unit asked for (slicers
//! assume millimetres), scaled from the document's metres in `f64` and rounded to `f32` last.
//!
//! The file holds each model's mesh, the welded manifold surface the tools edit, and not an
//! imported soup as its file had it (which the glTF export keeps, see
//! [`crate::model::AsImported`]): a printer needs a closed, consistently wound surface whose
//! triangles share their corners, and what the soup keeps beyond the mesh (its per-corner
//! colours and texture coordinates, its duplicate and flipped triangles) STL cannot carry or
//! a slicer would stumble on. The print check looks at the same mesh.

use glam::DVec3;

use super::export::{ExportScope, exported_models};
use super::export_error::ExportError;
use crate::model::Document;
use crate::unit::Unit;

/// Bytes before the first triangle: the header and the count.
const PREAMBLE: usize = 84;
/// Bytes per triangle: normal, three corners, attribute.
const FACET: usize = 50;

/// Encodes the models `scope` names as a binary STL in `unit`; see the module docs.
///
/// Errors: [`ExportError::EmptyDocument`] or [`ExportError::EmptyModel`] when there is no
/// triangle to write, [`ExportError::NoSuchModel`] for a model index out of range.
pub fn write_stl(doc: &Document, scope: ExportScope, unit: Unit) -> Result<Vec<u8>, ExportError> {
    let models = exported_models(doc, scope, "STL")?;
    let n_triangles: usize = models.iter().map(|m| m.model.mesh.n_faces()).sum();
    let mut bytes = Vec::with_capacity(PREAMBLE + FACET * n_triangles);
    bytes.extend_from_slice(&header(unit));
    // Far below u32::MAX: a document's meshes index their vertices with u32.
    bytes.extend_from_slice(&(n_triangles as u32).to_le_bytes());
    let scale = unit.per_metre();
    for exported in &models {
        let mesh = &exported.model.mesh;
        for f in mesh.faces() {
            let corners = mesh.face_positions(f);
            let [a, b, c] = corners;
            // The normal of the f64 triangle, so that rounding the corners cannot turn it.
            push_vec3(&mut bytes, (b - a).cross(c - a).normalize_or_zero());
            for corner in corners {
                push_vec3(&mut bytes, corner * scale);
            }
            bytes.extend_from_slice(&0u16.to_le_bytes());
        }
    }
    debug_assert_eq!(bytes.len(), PREAMBLE + FACET * n_triangles);
    Ok(bytes)
}

/// 80 bytes of text naming the writer and the unit, padded with spaces.
fn header(unit: Unit) -> [u8; 80] {
    let text = format!(
        "Binary STL written by Sketchmesh {}; units: {}",
        env!("CARGO_PKG_VERSION"),
        unit.symbol()
    );
    let mut header = [b' '; 80];
    let n = text.len().min(80);
    header[..n].copy_from_slice(&text.as_bytes()[..n]);
    header
}

fn push_vec3(bytes: &mut Vec<u8>, v: DVec3) {
    for x in v.as_vec3().to_array() {
        bytes.extend_from_slice(&x.to_le_bytes());
    }
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use super::*;
    use crate::mesh::{Mesh, primitives};
    use crate::model::Model;

    /// A parsed STL: header, and per facet the normal and corners.
    struct Stl {
        header: Vec<u8>,
        facets: Vec<[DVec3; 4]>,
    }

    fn read(bytes: &[u8]) -> Stl {
        let f32_at = |at: usize| f32::from_le_bytes(bytes[at..at + 4].try_into().unwrap());
        let count = u32::from_le_bytes(bytes[80..84].try_into().unwrap()) as usize;
        assert_eq!(
            bytes.len(),
            PREAMBLE + FACET * count,
            "size for {count} facets"
        );
        let facets = (0..count)
            .map(|k| {
                let at = PREAMBLE + FACET * k;
                assert_eq!(&bytes[at + 48..at + 50], &[0, 0], "attribute");
                std::array::from_fn(|i| {
                    let v = at + 12 * i;
                    DVec3::new(
                        f64::from(f32_at(v)),
                        f64::from(f32_at(v + 4)),
                        f64::from(f32_at(v + 8)),
                    )
                })
            })
            .collect();
        Stl {
            header: bytes[..80].to_vec(),
            facets,
        }
    }

    fn document(meshes: Vec<Mesh>) -> Document {
        Document {
            models: meshes
                .into_iter()
                .map(|mesh| {
                    Arc::new(Model {
                        mesh,
                        ..Model::default()
                    })
                })
                .collect(),
            ..Document::default()
        }
    }

    #[test]
    fn a_cube_in_millimetres_has_its_facets_bounds_and_outward_normals() {
        // A 40 mm cube, in metres as documents are.
        let doc = document(vec![primitives::cube(0.04)]);
        let stl = read(&write_stl(&doc, ExportScope::Document, Unit::Millimetre).unwrap());
        assert!(!stl.header.starts_with(b"solid"));
        assert!(String::from_utf8_lossy(&stl.header).contains("units: mm"));
        assert_eq!(stl.facets.len(), 12);
        let mut lo = DVec3::INFINITY;
        let mut hi = DVec3::NEG_INFINITY;
        for [normal, a, b, c] in &stl.facets {
            for p in [a, b, c] {
                lo = lo.min(*p);
                hi = hi.max(*p);
            }
            assert!((normal.length() - 1.0).abs() < 1e-6);
            // Outward: the normal points away from the centre, and agrees with the winding.
            let centre = (*a + *b + *c) / 3.0;
            assert!(normal.dot(centre) > 0.0, "{normal} at {centre}");
            assert!(normal.dot((*b - *a).cross(*c - *a)) > 0.0);
            // Axis-aligned faces: the normal is a unit axis.
            assert!((normal.abs().max_element() - 1.0).abs() < 1e-6);
        }
        assert!(
            (lo - DVec3::splat(-20.0)).abs().max_element() < 1e-4,
            "{lo}"
        );
        assert!((hi - DVec3::splat(20.0)).abs().max_element() < 1e-4, "{hi}");
    }

    #[test]
    fn an_icosphere_in_each_unit_is_scaled_and_closed() {
        let sphere = primitives::icosphere(0.05, 2);
        let doc = document(vec![sphere.clone()]);
        for unit in Unit::ALL {
            let stl = read(&write_stl(&doc, ExportScope::Model(0), unit).unwrap());
            assert_eq!(stl.facets.len(), sphere.n_faces());
            let radius = unit.from_metres(0.05);
            for [normal, a, b, c] in &stl.facets {
                for p in [a, b, c] {
                    assert!((p.length() / radius - 1.0).abs() < 1e-6, "{unit}: {p}");
                }
                assert!(normal.dot(*a + *b + *c) > 0.0, "outward in {unit}");
            }
            // Closed: every edge, as the f32 corners written, has its reverse in another facet.
            let key = |p: DVec3| p.to_array().map(f64::to_bits);
            let mut directed = std::collections::HashSet::new();
            for [_, a, b, c] in &stl.facets {
                for (p, q) in [(a, b), (b, c), (c, a)] {
                    assert!(directed.insert((key(*p), key(*q))), "an edge twice");
                }
            }
            for &(p, q) in &directed {
                assert!(directed.contains(&(q, p)), "an open edge in {unit}");
            }
        }
    }

    #[test]
    fn one_model_or_all_and_refusals_are_sentences() {
        let doc = document(vec![
            primitives::icosphere(1.0, 1),
            Mesh::default(),
            primitives::cube(1.0),
        ]);
        let count = |scope| {
            read(&write_stl(&doc, scope, Unit::Metre).unwrap())
                .facets
                .len()
        };
        assert_eq!(count(ExportScope::Document), 80 + 12);
        assert_eq!(count(ExportScope::Model(2)), 12);
        let refusal = |doc: &Document, scope| {
            write_stl(doc, scope, Unit::Millimetre)
                .unwrap_err()
                .to_string()
        };
        assert_eq!(
            refusal(&doc, ExportScope::Model(1)),
            "The model \"model 1\" has no triangles to write to STL."
        );
        assert_eq!(
            refusal(&doc, ExportScope::Model(3)),
            "There is no model 3: the document has 3 models."
        );
        assert_eq!(
            refusal(&Document::default(), ExportScope::Document),
            "The document has no triangles to write to STL."
        );
    }
}

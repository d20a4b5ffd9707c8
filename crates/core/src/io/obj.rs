//! Writing models as Wavefront OBJ with its MTL, the text format every modeller reads.
//!
//! Per model: `o` (its name), `usemtl` (its own material), `v x y z` (with `r g b` after the
//! position when the model has vertex colours: the extension Blender, MeshLab and three.js
//! read), `vn` (area-weighted smooth normals, one per vertex) and `f a//a b//b c//c`, 1-based
//! and counted on across models. Numbers are printed with six decimals, so equal documents
//! give equal text. Like the STL export, it writes each model's welded, repaired mesh (see
//! `stl.rs`): vertex colours are per mesh vertex, and OBJ cannot carry an imported file's
//! textures anyway.
//!
//! Colours: documents keep them linear; files are read as sRGB (readers show `Kd` and vertex
//! colours as they are), so both go through the sRGB transfer function (IEC 61966-2-1). The
//! MTL gives each model `Kd` (base colour), `d` (its alpha), `Ns` (a Phong exponent from the
//! roughness, as Blender's OBJ exporter maps it: `(30 (1 - roughness))²`) and the PBR
//! extension's `Pr` and `Pm` (roughness and metalness), which Blender and three.js's
//! loaders understand.

use std::collections::HashSet;
use std::fmt::Write as _;

use super::export::{ExportScope, exported_models};
use super::export_error::ExportError;
use crate::geometry::vertex_normals;
use crate::mesh::Mesh;
use crate::model::{Document, Finish, Model};
use crate::unit::Unit;

/// An OBJ file and the MTL file it names.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ObjFiles {
    /// The geometry: `mtllib`, then per model `o`, `usemtl`, `v`, `vn` and `f` lines.
    pub obj: String,
    /// The materials, one per model.
    pub mtl: String,
}

/// How a model looks in the files: its linear vertex colours and its finish.
struct Look<'a> {
    /// One linear RGB colour per mesh vertex, when the model is painted.
    vertex_colors: Option<&'a [[f32; 3]]>,
    finish: Finish,
}

impl<'a> Look<'a> {
    fn of(model: &'a Model) -> Self {
        Self {
            vertex_colors: model.vertex_colors(),
            finish: model.finish(),
        }
    }
}

/// Encodes the models `scope` names as OBJ text in `unit`, and their materials as MTL text
/// that the OBJ refers to as `mtl_name` (the MTL file's name beside the OBJ, without spaces,
/// which OBJ readers split at); see the module docs.
///
/// Errors: [`ExportError::EmptyDocument`] or [`ExportError::EmptyModel`] when there is no
/// triangle to write, [`ExportError::NoSuchModel`] for a model index out of range.
pub fn write_obj(
    doc: &Document,
    scope: ExportScope,
    unit: Unit,
    mtl_name: &str,
) -> Result<ObjFiles, ExportError> {
    let models = exported_models(doc, scope, "OBJ")?;
    let generator = format!("# Written by Sketchmesh {}\n", env!("CARGO_PKG_VERSION"));
    let mut obj = format!("{generator}# Units: {}\nmtllib {mtl_name}\n", unit.symbol());
    let mut mtl = generator;
    let mut used = HashSet::new();
    // OBJ indices are 1-based and global: each model's count on from the last.
    let mut first_vertex = 1;
    let scale = unit.per_metre();
    for (k, exported) in models.iter().enumerate() {
        let mut name = token(&exported.name);
        if !used.insert(name.clone()) {
            name = format!("{name}_{k}");
            used.insert(name.clone());
        }
        let mesh = &exported.model.mesh;
        let look = Look::of(exported.model);
        write_material(&mut mtl, &name, &look);
        write_model(&mut obj, &name, mesh, &look, first_vertex, scale);
        first_vertex += mesh.n_vertices();
    }
    Ok(ObjFiles { obj, mtl })
}

/// One model's lines; its vertices are numbered from `first_vertex`, positions scaled by
/// `scale`.
fn write_model(
    obj: &mut String,
    name: &str,
    mesh: &Mesh,
    look: &Look,
    first_vertex: usize,
    scale: f64,
) {
    // Writing to a String cannot fail.
    let _ = writeln!(obj, "o {name}\nusemtl {name}");
    debug_assert!(
        look.vertex_colors
            .is_none_or(|colors| colors.len() == mesh.n_vertices())
    );
    for (v, p) in mesh.positions().iter().enumerate() {
        let p = *p * scale;
        let _ = write!(obj, "v {:.6} {:.6} {:.6}", p.x, p.y, p.z);
        if let Some(colors) = look.vertex_colors {
            let [r, g, b] = colors[v].map(srgb_from_linear);
            let _ = write!(obj, " {r:.6} {g:.6} {b:.6}");
        }
        obj.push('\n');
    }
    for n in vertex_normals(mesh) {
        let _ = writeln!(obj, "vn {:.6} {:.6} {:.6}", n.x, n.y, n.z);
    }
    for t in mesh.triangles() {
        let [a, b, c] = t.map(|v| first_vertex + v as usize);
        let _ = writeln!(obj, "f {a}//{a} {b}//{b} {c}//{c}");
    }
}

/// One `newmtl` block.
fn write_material(mtl: &mut String, name: &str, look: &Look) {
    let Finish {
        base_color: [r, g, b, alpha],
        roughness,
        metalness,
    } = look.finish;
    let [r, g, b] = [r, g, b].map(srgb_from_linear);
    let roughness = f64::from(roughness).clamp(0.0, 1.0);
    let shininess = (30.0 * (1.0 - roughness)).powi(2);
    let _ = write!(
        mtl,
        "\nnewmtl {name}\nKd {r:.6} {g:.6} {b:.6}\nd {:.6}\nNs {shininess:.6}\nPr {roughness:.6}\nPm {:.6}\nillum 2\n",
        f64::from(alpha).clamp(0.0, 1.0),
        f64::from(metalness).clamp(0.0, 1.0),
    );
}

/// A name as one OBJ token: whitespace (which readers split at) becomes `_`; an empty name
/// becomes "model".
fn token(name: &str) -> String {
    let token: String = name
        .chars()
        .map(|c| if c.is_whitespace() { '_' } else { c })
        .collect();
    if token.is_empty() {
        String::from("model")
    } else {
        token
    }
}

/// A linear colour channel as sRGB, both in 0..1 (clamped): the exact piecewise transfer
/// function of IEC 61966-2-1, computed in f64.
fn srgb_from_linear(linear: f32) -> f64 {
    let c = f64::from(linear).clamp(0.0, 1.0);
    if c <= 0.003_130_8 {
        12.92 * c
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    }
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use glam::DVec3;

    use super::*;
    use crate::mesh::primitives;

    fn document(meshes: Vec<(Option<&str>, Mesh)>) -> Document {
        Document {
            models: meshes
                .into_iter()
                .map(|(name, mesh)| {
                    Arc::new(Model {
                        mesh,
                        name: name.map(String::from),
                        ..Model::default()
                    })
                })
                .collect(),
            ..Document::default()
        }
    }

    /// The lines of `text` that start with `keyword` and a space, split into their fields.
    fn lines<'a>(text: &'a str, keyword: &str) -> Vec<Vec<&'a str>> {
        text.lines()
            .filter_map(|line| line.strip_prefix(keyword)?.strip_prefix(' '))
            .map(|rest| rest.split(' ').collect())
            .collect()
    }

    #[test]
    fn two_models_read_back_with_their_counts_offsets_and_positions() {
        let sphere = primitives::icosphere(0.5, 2);
        let cube = primitives::cube(0.2);
        let doc = document(vec![
            (Some("the ball"), sphere.clone()),
            (None, cube.clone()),
        ]);
        let files = write_obj(&doc, ExportScope::Document, Unit::Centimetre, "out.mtl").unwrap();
        let obj = &files.obj;
        assert!(obj.contains("\nmtllib out.mtl\n"));
        assert_eq!(lines(obj, "o"), vec![vec!["the_ball"], vec!["model_1"]]);
        assert_eq!(lines(obj, "usemtl"), lines(obj, "o"));
        let vertices = lines(obj, "v");
        let normals = lines(obj, "vn");
        let faces = lines(obj, "f");
        let n_vertices = sphere.n_vertices() + cube.n_vertices();
        assert_eq!(vertices.len(), n_vertices);
        assert_eq!(normals.len(), n_vertices);
        assert_eq!(faces.len(), sphere.n_faces() + cube.n_faces());
        assert!(
            vertices.iter().all(|v| v.len() == 3),
            "no colours unpainted"
        );
        // Read back: positions in centimetres, faces indexing the right model's vertices.
        let read: Vec<DVec3> = vertices
            .iter()
            .map(|v| {
                DVec3::new(
                    v[0].parse().unwrap(),
                    v[1].parse().unwrap(),
                    v[2].parse().unwrap(),
                )
            })
            .collect();
        for (p, q) in sphere.positions().iter().chain(cube.positions()).zip(&read) {
            assert!((*p * 100.0 - *q).length() < 1e-5, "{p} against {q}");
        }
        let corners: Vec<Vec<usize>> = faces
            .iter()
            .map(|f| {
                f.iter()
                    .map(|corner| {
                        let (v, n) = corner.split_once("//").unwrap();
                        assert_eq!(v, n, "the vertex's own normal");
                        v.parse().unwrap()
                    })
                    .collect()
            })
            .collect();
        let expected: Vec<Vec<usize>> = sphere
            .triangles()
            .iter()
            .map(|t| t.map(|v| v as usize + 1))
            .chain(
                cube.triangles()
                    .iter()
                    .map(|t| t.map(|v| v as usize + 1 + sphere.n_vertices())),
            )
            .map(|t| t.to_vec())
            .collect();
        assert_eq!(corners, expected);
        // Normals are unit and outward on the sphere.
        for (n, p) in normals.iter().zip(&read).take(sphere.n_vertices()) {
            let n = DVec3::new(
                n[0].parse().unwrap(),
                n[1].parse().unwrap(),
                n[2].parse().unwrap(),
            );
            assert!((n.length() - 1.0).abs() < 1e-5 && n.dot(*p) > 0.0);
        }
    }

    #[test]
    fn a_painted_model_has_its_colours_after_the_positions_in_srgb() {
        let mut doc = document(vec![
            (None, primitives::cube(1.0)),
            (None, primitives::cube(1.0)),
        ]);
        let colors: Vec<[f32; 3]> = (0..8).map(|v| [v as f32 / 7.0, 0.0, 1.0]).collect();
        Arc::make_mut(&mut doc.models[1]).colors = Some(Arc::new(colors));
        let files = write_obj(&doc, ExportScope::Document, Unit::Metre, "a.mtl").unwrap();
        let vertices = lines(&files.obj, "v");
        assert_eq!(vertices.len(), 16);
        assert!(
            vertices[..8].iter().all(|v| v.len() == 3),
            "the unpainted cube"
        );
        for (v, fields) in vertices[8..].iter().enumerate() {
            assert_eq!(fields.len(), 6, "{fields:?}");
            let red: f64 = fields[3].parse().unwrap();
            assert!((red - srgb_from_linear(v as f32 / 7.0)).abs() < 1e-6);
            assert_eq!(&fields[4..], ["0.000000", "1.000000"]);
        }
        // The second cube's faces count on from the first's eight vertices.
        assert_eq!(lines(&files.obj, "f")[12], vec!["9//9", "11//11", "10//10"]);
    }

    #[test]
    fn the_mtl_has_each_models_finish_in_srgb() {
        let mut doc = document(vec![
            (Some("a"), primitives::cube(1.0)),
            (Some("a"), primitives::cube(1.0)),
        ]);
        Arc::make_mut(&mut doc.models[1]).finish = Some(Finish {
            base_color: [0.214_041_14, 1.0, 0.0, 0.5],
            roughness: 0.25,
            metalness: 1.0,
        });
        let files = write_obj(&doc, ExportScope::Document, Unit::Metre, "a.mtl").unwrap();
        assert_eq!(lines(&files.mtl, "newmtl"), vec![vec!["a"], vec!["a_1"]]);
        assert_eq!(lines(&files.obj, "usemtl"), vec![vec!["a"], vec!["a_1"]]);
        // Clay, the finish of a model that has none set.
        let clay = Finish::CLAY
            .rgb()
            .map(|c| format!("{:.6}", srgb_from_linear(c)));
        assert_eq!(lines(&files.mtl, "Kd")[0], clay);
        assert_eq!(lines(&files.mtl, "Pr")[0], vec!["0.600000"]);
        // Linear 0.214 is sRGB 0.5.
        assert_eq!(
            lines(&files.mtl, "Kd")[1],
            vec!["0.500000", "1.000000", "0.000000"]
        );
        assert_eq!(lines(&files.mtl, "d")[1], vec!["0.500000"]);
        assert_eq!(lines(&files.mtl, "Pr")[1], vec!["0.250000"]);
        assert_eq!(lines(&files.mtl, "Pm")[1], vec!["1.000000"]);
        // (30 (1 - 0.25))², as Blender's exporter maps roughness.
        assert_eq!(lines(&files.mtl, "Ns")[1], vec!["506.250000"]);
        // Deterministic: the same document gives the same text.
        assert_eq!(
            write_obj(&doc, ExportScope::Document, Unit::Metre, "a.mtl").unwrap(),
            files
        );
    }

    #[test]
    fn the_srgb_transfer_function_meets_its_known_values() {
        assert_eq!(srgb_from_linear(0.0), 0.0);
        assert!((srgb_from_linear(1.0) - 1.0).abs() < 1e-12);
        // The linear segment and the curve meet at 0.0031308 (sRGB 0.04045).
        assert!((srgb_from_linear(0.003_130_8) - 0.040_449_936).abs() < 1e-6);
        assert!((srgb_from_linear(0.214_041_14) - 0.5).abs() < 1e-6);
        assert_eq!(srgb_from_linear(2.0), srgb_from_linear(1.0), "clamped");
    }

    #[test]
    fn a_missing_or_empty_model_is_refused() {
        let doc = document(vec![(Some("empty"), Mesh::default())]);
        let refusal = |scope| {
            write_obj(&doc, scope, Unit::Metre, "x.mtl")
                .unwrap_err()
                .to_string()
        };
        assert_eq!(
            refusal(ExportScope::Document),
            "The document has no triangles to write to OBJ."
        );
        assert_eq!(
            refusal(ExportScope::Model(0)),
            "The model \"empty\" has no triangles to write to OBJ."
        );
    }
}

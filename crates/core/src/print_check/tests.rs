//! The print check on known shapes: a closed sphere, a hole, crossing spheres, a thin wall,
//! a repaired file and a size.

use std::sync::Arc;

use glam::DVec3;

use super::*;
use crate::mesh::{Mesh, make_manifold, primitives};
use crate::model::AsImported;
use crate::unit::Unit;

fn model(mesh: Mesh) -> Model {
    Model {
        mesh,
        ..Model::default()
    }
}

/// A closed plate `size` wide and `thickness` thick, centred on the origin: a grid of
/// `n × n` cells on top, its mirror below, and a strip of triangles around the rim.
fn plate(n: usize, size: f64, thickness: f64) -> Mesh {
    let top = primitives::grid(n, n, size);
    let rim = top.boundary_loops().remove(0);
    let mut soup = top.to_soup();
    let offset = soup.positions.len() as u32;
    let bottom: Vec<DVec3> = soup
        .positions
        .iter()
        .map(|p| *p - DVec3::Z * 0.5 * thickness)
        .collect();
    for p in &mut soup.positions {
        p.z += 0.5 * thickness;
    }
    soup.positions.extend(bottom);
    let turned: Vec<[u32; 3]> = soup
        .triangles
        .iter()
        .map(|&[a, b, c]| [a + offset, c + offset, b + offset])
        .collect();
    soup.triangles.extend(turned);
    // The rim runs with the top on its left: each boundary edge a→b needs a face with b→a.
    for k in 0..rim.len() {
        let (a, b) = (rim[k].0, rim[(k + 1) % rim.len()].0);
        soup.triangles
            .extend([[b, a, a + offset], [b, a + offset, b + offset]]);
    }
    let mesh = Mesh::from_soup(&soup).unwrap();
    assert!(mesh.is_closed());
    mesh
}

#[test]
fn a_closed_sphere_is_printable() {
    // 40 mm across.
    let check = PrintCheck::of_model(&model(primitives::icosphere(0.02, 3)), DEFAULT_MIN_WALL);
    assert!(
        check.is_printable(),
        "{:?}",
        check.sentences(Unit::Millimetre)
    );
    let sentences = check.sentences(Unit::Millimetre);
    assert_eq!(sentences[0], "Closed and manifold.");
    assert_eq!(sentences[1], "The surface does not cross itself.");
    assert!(
        sentences[2].starts_with("Thinnest wall 3")
            && sentences[2].ends_with("above the 1 mm minimum."),
        "{}",
        sentences[2]
    );
    assert_eq!(sentences.len(), 4);
    let model_check = &check.models[0];
    assert!(model_check.holes.is_empty() && !model_check.is_repaired);
    assert_eq!(model_check.thickness.per_vertex.len(), 642);
}

#[test]
fn a_hole_is_reported_with_its_edges() {
    let mut soup = primitives::icosphere(0.02, 2).to_soup();
    let removed = soup.triangles.remove(7);
    let check = PrintCheck::of_model(&model(Mesh::from_soup(&soup).unwrap()), DEFAULT_MIN_WALL);
    assert!(!check.is_printable());
    assert_eq!(check.n_holes(), 1);
    let mut hole: Vec<u32> = check.models[0].holes[0].iter().map(|v| v.0).collect();
    hole.sort_unstable();
    let mut corners = removed.to_vec();
    corners.sort_unstable();
    assert_eq!(hole, corners, "the hole runs around the removed triangle");
    assert_eq!(
        check.sentences(Unit::Millimetre)[0],
        "Not closed: 1 hole (its edges are shown)."
    );
}

#[test]
fn two_spheres_in_one_mesh_cross_in_one_place() {
    let mut soup = primitives::icosphere(0.01, 3).to_soup();
    let mut other = soup.clone();
    for p in &mut other.positions {
        p.x += 0.012;
    }
    soup.append(&other);
    let mesh = Mesh::from_soup(&soup).unwrap();
    let check = PrintCheck::of_model(&model(mesh), DEFAULT_MIN_WALL);
    let crossings = &check.models[0].crossings;
    assert_eq!(crossings.n_places, 1);
    assert!(crossings.pairs.len() > 50, "{}", crossings.pairs.len());
    // Both spheres' faces are marked.
    let n = primitives::icosphere(0.01, 3).n_faces() as u32;
    assert!(crossings.faces.iter().any(|f| f.0 < n) && crossings.faces.iter().any(|f| f.0 >= n));
    assert!(!check.is_printable());
    assert_eq!(check.n_holes(), 0);
    assert_eq!(
        check.sentences(Unit::Millimetre)[1],
        "1 place where the surface crosses itself (shown)."
    );
}

#[test]
fn a_half_millimetre_plate_is_too_thin_for_a_millimetre() {
    // 20 mm square, 0.5 mm thick.
    let check = PrintCheck::of_model(&model(plate(20, 0.02, 0.0005)), DEFAULT_MIN_WALL);
    let thinnest = check.thinnest().unwrap();
    assert!((0.000_45..0.000_6).contains(&thinnest), "{thinnest}");
    assert!(!check.is_printable());
    let thin = check.models[0].thickness.thin_vertices.len();
    assert!(thin > 800, "most of the {} vertices: {thin}", 2 * 21 * 21);
    let sentences = check.sentences(Unit::Millimetre);
    assert_eq!(sentences[0], "Closed and manifold.");
    let wall = &sentences[2];
    assert!(
        wall.starts_with("Thinnest wall 0.5") && wall.contains("mm, under the 1 mm minimum, at "),
        "{wall}"
    );
    // Against a 0.4 mm minimum the same plate passes.
    let check = PrintCheck::of_model(&model(plate(20, 0.02, 0.0005)), 0.0004);
    assert!(
        check.is_printable(),
        "{:?}",
        check.sentences(Unit::Millimetre)
    );
    assert!(check.sentences(Unit::Millimetre)[2].contains("above the 0.4 mm minimum"));
}

#[test]
fn the_size_is_said_in_the_unit_asked_for() {
    let mut mesh = primitives::cube(1.0);
    for p in mesh.positions_mut() {
        *p *= DVec3::new(0.0821, 0.04, 0.0513);
    }
    let doc = Document {
        models: vec![Arc::new(model(mesh)), Arc::new(model(Mesh::default()))],
        ..Document::default()
    };
    let check = PrintCheck::of_document(&doc, DEFAULT_MIN_WALL);
    assert_eq!(check.models.len(), 1, "the empty model is left out");
    let size = |unit| check.sentences(unit).last().cloned().unwrap();
    assert_eq!(size(Unit::Millimetre), "Size 82.1 × 40.0 × 51.3 mm.");
    assert_eq!(size(Unit::Centimetre), "Size 8.21 × 4.00 × 5.13 cm.");
    assert_eq!(size(Unit::Metre), "Size 0.0821 × 0.0400 × 0.0513 m.");
    assert_eq!(size(Unit::Inch), "Size 3.23 × 1.57 × 2.02 in.");
    assert!(check.is_printable());
    let (lo, hi) = check.bounds().unwrap();
    assert!((hi - lo - DVec3::new(0.0821, 0.04, 0.0513)).length() < 1e-12);
}

#[test]
fn nothing_to_print_is_not_printable() {
    let check = PrintCheck::of_document(&Document::default(), DEFAULT_MIN_WALL);
    assert!(!check.is_printable());
    assert_eq!(
        check.sentences(Unit::Millimetre),
        ["There is nothing to print: no model has triangles."]
    );
}

#[test]
fn a_repaired_file_says_so_and_shows_where_it_was_split() {
    // A cube with a fin: a third triangle on one of its edges.
    let mut soup = primitives::cube(0.03).to_soup();
    soup.positions.push(DVec3::new(0.0, -0.05, -0.05));
    let fin_tip = soup.positions.len() as u32 - 1;
    soup.triangles.push([0, 1, fin_tip]);
    assert!(Mesh::from_soup(&soup).is_err());
    let repaired = make_manifold(&soup).unwrap();
    let imported = AsImported {
        soup: soup.clone(),
        vertex_source: repaired.vertex_source.iter().map(|v| v.0).collect(),
        mesh_triangles: repaired.mesh.triangles().to_vec(),
        appearance: None,
    };
    let model = Model {
        mesh: repaired.mesh,
        as_imported: Some(Arc::new(imported)),
        ..Model::default()
    };
    let check = PrintCheck::of_model(&model, DEFAULT_MIN_WALL);
    let model_check = &check.models[0];
    assert!(model_check.is_repaired);
    assert_eq!(model_check.file_non_manifold_edges, 1);
    assert!(!check.is_printable(), "the split fin is open");
    let sentences = check.sentences(Unit::Millimetre);
    assert!(sentences[0].starts_with("Not closed"), "{sentences:?}");
    assert_eq!(
        sentences[1],
        "The imported file was not manifold (1 edge with more than two triangles or a turned one); the check and the STL use the surface it was repaired into."
    );
}

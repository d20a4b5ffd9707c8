#![allow(clippy::unwrap_used)]

use glam::{DVec2, DVec3};

use super::*;
use crate::curve::polyline::distance_to_polyline;
use crate::mesh::VertexId;
use crate::mesh::primitives::icosphere;

const VIEWPORT: DVec2 = DVec2::new(800.0, 600.0);

fn sphere() -> Mesh {
    icosphere(1.0, 4)
}

fn screen(p: DVec3) -> DVec2 {
    Camera::default()
        .screen_from_world(p, VIEWPORT)
        .unwrap()
        .truncate()
}

/// The point of the unit sphere's front (facing the default camera) above `(x, y)`.
fn front(x: f64, y: f64) -> DVec3 {
    DVec3::new(x, y, (1.0 - x * x - y * y).sqrt())
}

fn embed(mesh: &Mesh, stroke: &[DVec2], shape: CurveShape) -> Result<Embedded, AddCurveError> {
    add_curve(mesh, &Camera::default(), VIEWPORT, stroke, shape)
}

/// A wavy stroke across the front of the unit sphere.
fn wavy_stroke() -> Vec<DVec2> {
    (0..=30)
        .map(|i| {
            let x = -0.7 + 1.4 * i as f64 / 30.0;
            screen(front(x, 0.15 + 0.2 * (4.0 * x).sin()))
        })
        .collect()
}

/// The largest gap between a triangle's centroid and the unit sphere: how far inside the
/// sphere a point of the polyhedron can lie.
fn chord_sag(mesh: &Mesh) -> f64 {
    mesh.faces()
        .map(|f| {
            let [a, b, c] = mesh.face_positions(f);
            1.0 - ((a + b + c) / 3.0).length()
        })
        .fold(0.0, f64::max)
}

fn assert_edge_chain(mesh: &Mesh, chain: &[VertexId], closed: bool) {
    for w in chain.windows(2) {
        assert!(
            mesh.find_edge(w[0], w[1]).is_some(),
            "{:?} – {:?} is no edge",
            w[0],
            w[1]
        );
    }
    if closed {
        let (first, last) = (chain[0], chain[chain.len() - 1]);
        assert!(
            mesh.find_edge(last, first).is_some(),
            "closing {last:?} – {first:?} is no edge"
        );
    }
}

/// The checks every embedding passes: a valid mesh that keeps the input vertices and is
/// closed if the input was, no degenerate faces, an edge chain, and splits that name
/// edges and vertices that existed.
fn assert_valid(input: &Mesh, embedded: &Embedded) {
    let mesh = &embedded.mesh;
    mesh.validate().unwrap();
    assert_eq!(mesh.is_closed(), input.is_closed());
    let n = input.n_vertices();
    assert_eq!(&mesh.positions()[..n], input.positions());
    assert_edge_chain(mesh, &embedded.chain, embedded.closed);
    for (k, &(a, b, new)) in embedded.split_edges.iter().enumerate() {
        assert!(a < new && b < new && new.index() >= n, "split {k}");
    }
    for f in mesh.faces() {
        let [a, b, c] = mesh.face_positions(f);
        assert!(
            (b - a).cross(c - a).length() > 1e-10,
            "degenerate face {f:?}"
        );
    }
}

/// [`assert_valid`], and for the unit sphere: new vertices lie on the input surface,
/// inside the sphere by at most the chord sag.
fn assert_embedding(input: &Mesh, embedded: &Embedded) {
    assert_valid(input, embedded);
    let sag = chord_sag(input);
    for p in &embedded.mesh.positions()[input.n_vertices()..] {
        let r = p.length();
        assert!(
            r <= 1.0 + 1e-12 && r >= 1.0 - sag,
            "new vertex at radius {r}"
        );
    }
}

#[test]
fn open_stroke_across_the_front_follows_it() {
    let input = sphere();
    let stroke = wavy_stroke();
    let embedded = embed(&input, &stroke, CurveShape::Open).unwrap();
    assert_embedding(&input, &embedded);
    assert!(!embedded.closed);
    let chain = &embedded.chain;
    assert!(chain.len() > 20, "{} vertices", chain.len());
    let positions = embedded.mesh.positions();
    let on_screen: Vec<DVec2> = chain
        .iter()
        .map(|&v| screen(positions[v.index()]))
        .collect();
    // The ends snap within a tenth of an edge (about 1.2 px here); the rest lie on the
    // swept planes, up to the snapping of crossings.
    for (k, &s) in on_screen.iter().enumerate() {
        let tolerance = if k == 0 || k + 1 == chain.len() {
            2.0
        } else {
            0.5
        };
        let gap = distance_to_polyline(s, &stroke);
        assert!(gap < tolerance, "vertex {k} is {gap} px off the stroke");
        assert!(
            positions[chain[k].index()].z > 0.0,
            "vertex {k} is on the back"
        );
    }
    assert!(on_screen[0].distance(stroke[0]) < 2.0);
    assert!(on_screen[chain.len() - 1].distance(stroke[stroke.len() - 1]) < 2.0);
}

#[test]
fn open_stroke_leaving_the_shape_is_clipped() {
    let input = sphere();
    let start = screen(front(-0.3, 0.1));
    // Far to the right of the silhouette, which lies about 148 px from the centre.
    let end = DVec2::new(700.0, start.y);
    let stroke: Vec<DVec2> = (0..=20).map(|i| start.lerp(end, i as f64 / 20.0)).collect();
    let embedded = embed(&input, &stroke, CurveShape::Open).unwrap();
    assert_embedding(&input, &embedded);
    let positions = embedded.mesh.positions();
    let last = positions[(*embedded.chain.last().unwrap()).index()];
    // It ends near the silhouette, where the visible surface ends.
    assert!(last.x > 0.9, "ends at {last}");
    assert!(screen(last).x < 560.0);
    for &v in &embedded.chain {
        let s = screen(positions[v.index()]);
        assert!(distance_to_polyline(s, &stroke) < 2.0);
    }
    // Drawn the other way, the curve starts at the silhouette.
    let reversed: Vec<DVec2> = stroke.iter().rev().copied().collect();
    let embedded = embed(&input, &reversed, CurveShape::Open).unwrap();
    assert_embedding(&input, &embedded);
    let first = embedded.mesh.positions()[embedded.chain[0].index()];
    assert!(first.x > 0.9, "starts at {first}");
}

#[test]
fn closed_loop_on_the_front() {
    let input = sphere();
    let stroke: Vec<DVec2> = (0..48)
        .map(|i| {
            let angle = std::f64::consts::TAU * i as f64 / 48.0;
            screen(front(0.1 + 0.45 * angle.cos(), 0.4 * angle.sin()))
        })
        .collect();
    let embedded = embed(&input, &stroke, CurveShape::Closed).unwrap();
    assert_embedding(&input, &embedded);
    assert!(embedded.closed);
    let mut looped = stroke.clone();
    looped.push(stroke[0]);
    let positions = embedded.mesh.positions();
    for (k, &v) in embedded.chain.iter().enumerate() {
        let tolerance = if k == 0 { 2.0 } else { 0.5 };
        let gap = distance_to_polyline(screen(positions[v.index()]), &looped);
        assert!(gap < tolerance, "vertex {k} is {gap} px off the stroke");
    }
    assert!(embedded.chain.len() > 30);
}

#[test]
fn cross_section_goes_around_the_back() {
    let input = sphere();
    let camera = Camera::default();
    let centre = screen(DVec3::ZERO);
    let stroke = [DVec2::new(150.0, centre.y), DVec2::new(650.0, centre.y)];
    let embedded = embed(&input, &stroke, CurveShape::CrossSection).unwrap();
    assert_embedding(&input, &embedded);
    assert!(embedded.closed);
    let positions = embedded.mesh.positions();
    // The rays through a horizontal line through the centre sweep the plane y = 0.
    let mut behind = 0;
    for &v in &embedded.chain {
        let p = positions[v.index()];
        assert!(p.y.abs() < 0.01, "{p} is off the plane");
        let depth = camera.screen_from_world(p, VIEWPORT).unwrap().z;
        behind += usize::from(depth > camera.distance());
    }
    assert!(
        behind > embedded.chain.len() / 3,
        "{behind} behind the centre"
    );
    // Around the whole equator: its length is close to 2π.
    let n = embedded.chain.len();
    let length: f64 = (0..n)
        .map(|i| {
            let (a, b) = (embedded.chain[i], embedded.chain[(i + 1) % n]);
            positions[a.index()].distance(positions[b.index()])
        })
        .sum();
    assert!(
        (length - std::f64::consts::TAU).abs() < 0.05,
        "length {length}"
    );
}

#[test]
fn slanted_cross_section_lies_under_its_stroke() {
    let input = sphere();
    let (a, b) = (DVec2::new(250.0, 120.0), DVec2::new(560.0, 470.0));
    let embedded = embed(&input, &[a, b], CurveShape::CrossSection).unwrap();
    assert_embedding(&input, &embedded);
    let positions = embedded.mesh.positions();
    let normal = (b - a).perp().normalize();
    for &v in &embedded.chain {
        // About 12 px edges, snapped within 5%.
        let off = normal.dot(screen(positions[v.index()]) - a).abs();
        assert!(off < 1.0, "{off} px off the stroke's line");
    }
}

#[test]
fn strokes_that_miss_or_do_not_cross_are_refused() {
    let input = sphere();
    let beside = [DVec2::new(20.0, 20.0), DVec2::new(200.0, 40.0)];
    assert_eq!(
        embed(&input, &beside, CurveShape::Open).unwrap_err(),
        AddCurveError::Misses
    );
    assert_eq!(
        embed(&input, &beside, CurveShape::CrossSection).unwrap_err(),
        AddCurveError::DoesNotCross
    );
    let centre = screen(DVec3::ZERO);
    let into = [DVec2::new(100.0, centre.y), centre];
    assert_eq!(
        embed(&input, &into, CurveShape::CrossSection).unwrap_err(),
        AddCurveError::DoesNotCross
    );
    let partly_off: Vec<DVec2> = (0..24)
        .map(|i| {
            let angle = std::f64::consts::TAU * i as f64 / 24.0;
            centre + DVec2::new(100.0, 0.0) + 100.0 * DVec2::new(angle.cos(), angle.sin())
        })
        .collect();
    assert_eq!(
        embed(&input, &partly_off, CurveShape::Closed).unwrap_err(),
        AddCurveError::ClosedOffSurface
    );
    assert_eq!(
        embed(&input, &[centre], CurveShape::Open).unwrap_err(),
        AddCurveError::Misses
    );
}

/// A path of input edges over the front from near `from` to near `to`, chosen greedily.
fn edge_path(mesh: &Mesh, from: DVec3, to: DVec3) -> Vec<VertexId> {
    let nearest = |p: DVec3| {
        mesh.vertices()
            .min_by(|a, b| {
                let (da, db) = (mesh.position(*a).distance(p), mesh.position(*b).distance(p));
                da.total_cmp(&db)
            })
            .unwrap()
    };
    let (mut at, goal) = (nearest(from), nearest(to));
    let mut path = vec![at];
    while at != goal {
        at = mesh
            .vertex_neighbors(at)
            .min_by(|a, b| {
                let (da, db) = (
                    mesh.position(*a).distance(to),
                    mesh.position(*b).distance(to),
                );
                da.total_cmp(&db)
            })
            .unwrap();
        path.push(at);
    }
    path
}

/// What callers do with `split_edges`: insert each new vertex into a curve edge it split.
fn replay(curve: &mut Vec<VertexId>, splits: &[(VertexId, VertexId, VertexId)]) {
    for &(a, b, new) in splits {
        let is_split = |w: &[VertexId]| (w[0], w[1]) == (a, b) || (w[0], w[1]) == (b, a);
        if let Some(k) = curve.windows(2).position(is_split) {
            curve.insert(k + 1, new);
        }
    }
}

#[test]
fn split_edges_keep_other_curves_edge_chains() {
    let input = sphere();
    let meridian = edge_path(&input, front(0.05, 0.8), front(0.05, -0.8));
    let strokes = [
        (wavy_stroke(), CurveShape::Open),
        (
            vec![DVec2::new(150.0, 310.0), DVec2::new(650.0, 290.0)],
            CurveShape::CrossSection,
        ),
    ];
    for (stroke, shape) in strokes {
        let embedded = embed(&input, &stroke, shape).unwrap();
        let mut curve = meridian.clone();
        replay(&mut curve, &embedded.split_edges);
        assert_edge_chain(&embedded.mesh, &curve, false);
        // The curves meet in a vertex: a junction.
        assert!(
            curve.iter().any(|v| embedded.chain.contains(v)),
            "{shape:?} does not meet the meridian"
        );
    }
}

/// A deterministic pseudo-random number in [0, 1).
fn random(state: &mut u64) -> f64 {
    *state = state
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    (*state >> 11) as f64 / (1u64 << 53) as f64
}

#[test]
fn random_strokes_embed_validly() {
    let input = sphere();
    let mut state = 7;
    for case in 0..12 {
        let mut r = || random(&mut state);
        // Open: curly strokes over the front, some crossing themselves.
        let (x0, y0, curl, turns) = (
            0.4 * (r() - 0.5),
            0.4 * (r() - 0.5),
            0.2 * r(),
            1.0 + 3.0 * r(),
        );
        let open: Vec<DVec2> = (0..=80)
            .map(|i| {
                let t = i as f64 / 80.0;
                let angle = std::f64::consts::TAU * turns * t;
                let (x, y) = (x0 + 1.0 * t - 0.5, y0 * (1.0 - t) + 0.3 * t);
                screen(front(x + curl * angle.cos(), y + curl * angle.sin()))
            })
            .collect();
        let embedded = embed(&input, &open, CurveShape::Open).unwrap();
        assert_embedding(&input, &embedded);
        // Closed: ellipses on the front.
        let (cx, cy, a, b) = (
            0.3 * (r() - 0.5),
            0.3 * (r() - 0.5),
            0.1 + 0.4 * r(),
            0.1 + 0.4 * r(),
        );
        let closed: Vec<DVec2> = (0..40)
            .map(|i| {
                let angle = std::f64::consts::TAU * i as f64 / 40.0;
                screen(front(cx + a * angle.cos(), cy + b * angle.sin()))
            })
            .collect();
        let embedded = embed(&input, &closed, CurveShape::Closed)
            .unwrap_or_else(|e| panic!("closed case {case}: {e}"));
        assert_embedding(&input, &embedded);
        // Cross sections at any angle and offset.
        let (angle, offset) = (std::f64::consts::PI * r(), 100.0 * (r() - 0.5));
        let dir = DVec2::from_angle(angle);
        let through = screen(DVec3::ZERO) + dir.perp() * offset;
        let across = [through - 300.0 * dir, through + 300.0 * dir];
        let embedded = embed(&input, &across, CurveShape::CrossSection).unwrap();
        assert_embedding(&input, &embedded);
    }
}

/// A camera looking at a mesh's bounding box from a little above and to the side.
fn framing(mesh: &Mesh) -> Camera {
    let (lo, hi) = mesh.bounding_box().unwrap();
    let (centre, size) = (0.5 * (lo + hi), (hi - lo).length());
    Camera {
        eye: centre + size * DVec3::new(0.3, 0.4, 2.0),
        target: centre,
        ..Camera::default()
    }
}

#[test]
fn fixtures_take_curves() {
    for fixture in crate::mesh::fixtures::closed_meshes() {
        let mesh = &fixture.mesh;
        let camera = framing(mesh);
        let y = 0.5 * VIEWPORT.y + 0.37;
        let open = [DVec2::new(150.0, y), DVec2::new(650.0, y + 11.0)];
        let across = [DVec2::new(0.0, y), DVec2::new(VIEWPORT.x, y - 9.0)];
        for (stroke, shape) in [(open, CurveShape::Open), (across, CurveShape::CrossSection)] {
            let embedded = add_curve(mesh, &camera, VIEWPORT, &stroke, shape)
                .unwrap_or_else(|e| panic!("{} {shape:?}: {e}", fixture.name));
            assert_valid(mesh, &embedded);
        }
    }
}

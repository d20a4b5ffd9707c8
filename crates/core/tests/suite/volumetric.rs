//! The volumetric graph Laplacian (issue 20): large bends and twists keep volume and detail
//! and do not fold; an unmoved handle moves nothing.

use std::collections::HashMap;
use std::f64::consts::PI;

use crate::common::{
    commit_elsewhere, digest, import_mesh, preview_elsewhere, quarter_bend, screen_line,
    supply_elsewhere,
};

use glam::{DMat4, DVec2, DVec3};
use sketchmesh_core::curve::bspline::uniform_knots;
use sketchmesh_core::document::{
    CoarseInput, CurveDeformInput, DeformHandleInput, DeformInput, DeformMethod, Editor, Op,
    Progress,
};
use sketchmesh_core::feature::Sketch;
use sketchmesh_core::geometry::{Bvh, enclosed_volume};
use sketchmesh_core::mesh::{Mesh, TriSoup, primitives};
use sketchmesh_core::volumetric::{
    COARSE_CONTROLS, GraphTerm, Method, Sphere, SphereHandle, VolumetricError, VolumetricGraph,
    VolumetricParams, deform_with_spheres, pick_curve,
};

/// Bumps on the capsule: centre (x, angle around) of each.
const BUMPS: [(f64, f64); 6] = [
    (-1.0, 0.0),
    (0.0, 0.5 * PI),
    (1.0, PI),
    (-0.5, 1.5 * PI),
    (0.5, 0.0),
    (0.0, 1.5 * PI),
];
const BUMP_HEIGHT: f64 = 0.08;
const BUMP_SIGMA: f64 = 0.12;

/// The capsule the bumps sit on.
fn smooth_capsule() -> Mesh {
    primitives::capsule(0.5, 3.0, 40, 120)
}

/// A capsule along x (radius 0.5, straight part 6 long) with six Gaussian bumps on its
/// middle, and the vertex at each bump's top.
fn bumpy_capsule() -> (Mesh, Vec<usize>) {
    let mut mesh = smooth_capsule();
    let centres: Vec<DVec3> = BUMPS
        .iter()
        .map(|&(x, a)| DVec3::new(x, 0.5 * a.cos(), 0.5 * a.sin()))
        .collect();
    for p in mesh.positions_mut() {
        let radial = DVec3::new(0.0, p.y, p.z).normalize_or_zero();
        let lift: f64 = centres
            .iter()
            .map(|c| {
                let d2 = p.distance_squared(*c);
                BUMP_HEIGHT * (-d2 / (2.0 * BUMP_SIGMA * BUMP_SIGMA)).exp()
            })
            .sum();
        *p += radial * lift;
    }
    let tops = centres
        .iter()
        .map(|c| nearest_vertex(&mesh, *c + (*c - DVec3::new(c.x, 0.0, 0.0)) * 0.2))
        .collect();
    (mesh, tops)
}

fn nearest_vertex(mesh: &Mesh, p: DVec3) -> usize {
    (0..mesh.n_vertices())
        .min_by(|&a, &b| {
            let da = mesh.positions()[a].distance_squared(p);
            let db = mesh.positions()[b].distance_squared(p);
            da.total_cmp(&db)
        })
        .expect("the mesh has vertices")
}

/// A bump's height: how far its top stands off the same capsule without bumps, deformed
/// the same way (so the base's own bending does not count as detail).
fn bump_height(top: DVec3, base: &Mesh) -> f64 {
    let bvh = Bvh::new(base);
    let (nearest, _) = bvh.nearest(base, top).expect("the base has faces");
    top.distance(nearest)
}

fn crossing_pairs(rest: &Mesh, positions: &[DVec3]) -> usize {
    let mut moved = rest.clone();
    moved.positions_mut().copy_from_slice(positions);
    Bvh::new(&moved).crossing_faces(&moved, |_| true).len()
}

fn volume(rest: &Mesh, positions: &[DVec3]) -> f64 {
    let mut moved = rest.clone();
    moved.positions_mut().copy_from_slice(positions);
    enclosed_volume(&moved)
}

/// Half a turn about the z axis through `(x, y)`.
fn half_turn_about(x: f64, y: f64) -> DMat4 {
    let pivot = DVec3::new(x, y, 0.0);
    DMat4::from_translation(pivot) * DMat4::from_rotation_z(PI) * DMat4::from_translation(-pivot)
}

#[test]
fn a_capsule_bent_by_half_a_turn_keeps_its_volume_bumps_and_does_not_fold() {
    let (mesh, tops) = bumpy_capsule();
    let base = smooth_capsule();
    let graph = VolumetricGraph::build(&mesh).unwrap();
    let base_graph = VolumetricGraph::build(&base).unwrap();
    // The fixed end and the handle each hold about 1.4 of the capsule's ends; the free
    // length between them is about 4.26, a half circle of radius 1.36 about (−2.13, 1.36),
    // which the half turn about (0, 1.36) asks for.
    let fixed = [Sphere {
        centre: DVec3::new(-3.0, 0.0, 0.0),
        radius: 1.0,
    }];
    let bend = 4.26 / PI;
    let handles = [SphereHandle {
        sphere: Sphere {
            centre: DVec3::new(3.0, 0.0, 0.0),
            radius: 1.0,
        },
        matrix: half_turn_about(0.0, bend),
    }];
    let rest_volume = enclosed_volume(&mesh);
    let mut report = Vec::new();
    let printed = VolumetricParams {
        graph_term: GraphTerm::Laplacian,
        ..VolumetricParams::default()
    };
    let methods = [
        Method::Volumetric(VolumetricParams::default()),
        Method::Volumetric(printed),
        Method::Surface,
    ];
    for method in methods {
        let moved = deform_with_spheres(&mesh, Some(&graph), &handles, &fixed, method).unwrap();
        let change = volume(&mesh, &moved) / rest_volume - 1.0;
        let crossings = crossing_pairs(&mesh, &moved);
        let mut bent_base = base.clone();
        let base_moved =
            deform_with_spheres(&base, Some(&base_graph), &handles, &fixed, method).unwrap();
        bent_base.positions_mut().copy_from_slice(&base_moved);
        let heights: Vec<f64> = tops
            .iter()
            .map(|&t| bump_height(moved[t], &bent_base) / bump_height(mesh.positions()[t], &base))
            .collect();
        report.push(format!(
            "{method:?}: volume {:+.2}%, {crossings} crossing pairs, bump heights {:?}",
            100.0 * change,
            heights
                .iter()
                .map(|h| format!("{h:.3}"))
                .collect::<Vec<_>>()
        ));
        if method == methods[0] {
            println!("{}", report.join("\n"));
            assert!(change.abs() < 0.05, "{}", report.join("\n"));
            assert_eq!(crossings, 0, "{}", report.join("\n"));
            for h in &heights {
                assert!((h - 1.0).abs() < 0.10, "{}", report.join("\n"));
            }
            // The handle went where its matrix says.
            let tip = nearest_vertex(&mesh, DVec3::new(3.5, 0.0, 0.0));
            let expected = handles[0].matrix.transform_point3(mesh.positions()[tip]);
            assert!(moved[tip].distance(expected) < 1e-9);
        }
    }
    println!("{}", report.join("\n"));
    println!(
        "graph: {} points for {} vertices",
        graph.n_points(),
        graph.n_mesh()
    );
}

/// A box `size` centred on the origin, with `cells` quads along each axis split into
/// triangles, faces outward.
pub fn box_mesh(size: DVec3, cells: [usize; 3]) -> Mesh {
    let mut index: HashMap<[usize; 3], u32> = HashMap::new();
    let mut positions = Vec::new();
    let mut vertex = |c: [usize; 3]| -> u32 {
        *index.entry(c).or_insert_with(|| {
            let t = DVec3::new(
                c[0] as f64 / cells[0] as f64,
                c[1] as f64 / cells[1] as f64,
                c[2] as f64 / cells[2] as f64,
            );
            positions.push((t - 0.5) * size);
            positions.len() as u32 - 1
        })
    };
    let mut triangles = Vec::new();
    for a in 0..3 {
        let (b, c) = ((a + 1) % 3, (a + 2) % 3);
        for side in [0, cells[a]] {
            for i in 0..cells[b] {
                for j in 0..cells[c] {
                    let corner = |di: usize, dj: usize| {
                        let mut p = [0; 3];
                        p[a] = side;
                        p[b] = i + di;
                        p[c] = j + dj;
                        p
                    };
                    let quad =
                        [corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)].map(&mut vertex);
                    let [q0, q1, q2, q3] = if side == 0 {
                        [quad[0], quad[3], quad[2], quad[1]]
                    } else {
                        quad
                    };
                    triangles.extend([[q0, q1, q2], [q0, q2, q3]]);
                }
            }
        }
    }
    Mesh::from_soup(&TriSoup {
        positions,
        triangles,
    })
    .expect("the box is a manifold")
}

/// The largest distance of a point inside the convex hull of `points` from the hull's
/// boundary, relative to the hull's size: 0 when every point is on the hull.
fn concavity(points: &[DVec2]) -> f64 {
    let mut sorted = points.to_vec();
    sorted.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    let cross = |o: DVec2, a: DVec2, b: DVec2| (a - o).perp_dot(b - o);
    let mut hull: Vec<DVec2> = Vec::new();
    for pass in 0..2 {
        let start = hull.len();
        let iter: Box<dyn Iterator<Item = &DVec2>> = if pass == 0 {
            Box::new(sorted.iter())
        } else {
            Box::new(sorted.iter().rev())
        };
        for &p in iter {
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0
            {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
    }
    let size = sorted[sorted.len() - 1].distance(sorted[0]);
    let to_hull = |p: DVec2| {
        (0..hull.len())
            .map(|k| {
                let (a, b) = (hull[k], hull[(k + 1) % hull.len()]);
                let t = ((p - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
                p.distance(a + (b - a) * t)
            })
            .fold(f64::INFINITY, f64::min)
    };
    points.iter().map(|&p| to_hull(p)).fold(0.0, f64::max) / size
}

#[test]
fn a_bar_twisted_by_a_quarter_turn_keeps_its_volume_and_convex_sections() {
    let mesh = box_mesh(DVec3::new(2.4, 0.4, 0.4), [60, 10, 10]);
    assert!(enclosed_volume(&mesh) > 0.0);
    let graph = VolumetricGraph::build(&mesh).unwrap();
    let fixed = [Sphere {
        centre: DVec3::new(-1.4, 0.0, 0.0),
        radius: 0.45,
    }];
    let handles = [SphereHandle {
        sphere: Sphere {
            centre: DVec3::new(1.4, 0.0, 0.0),
            radius: 0.45,
        },
        matrix: DMat4::from_rotation_x(0.5 * PI),
    }];
    let run = |params| {
        deform_with_spheres(
            &mesh,
            Some(&graph),
            &handles,
            &fixed,
            Method::Volumetric(params),
        )
        .unwrap()
    };
    let printed = run(VolumetricParams {
        graph_term: GraphTerm::Laplacian,
        ..VolumetricParams::default()
    });
    let moved = run(VolumetricParams::default());
    let change = volume(&mesh, &moved) / enclosed_volume(&mesh) - 1.0;
    let printed_change = volume(&mesh, &printed) / enclosed_volume(&mesh) - 1.0;
    println!(
        "twist: volume {:+.2}% (Eq. 3's Laplacian term: {:+.2}%)",
        100.0 * change,
        100.0 * printed_change
    );
    assert!(
        change.abs() < 0.03,
        "volume changed by {:.2}%",
        100.0 * change
    );
    assert_eq!(crossing_pairs(&mesh, &moved), 0);
    // Sections across the free part: the ring of vertices at each x stays convex.
    for k in 0..9 {
        let x = -0.8 + 0.2 * k as f64;
        let ring: Vec<DVec2> = (0..mesh.n_vertices())
            .filter(|&v| (mesh.positions()[v].x - x).abs() < 1e-9)
            .map(|v| DVec2::new(moved[v].y, moved[v].z))
            .collect();
        assert!(ring.len() >= 40);
        let c = concavity(&ring);
        assert!(
            c < 0.01,
            "section at x = {x}: a point {c:.4} of its size inside the hull"
        );
    }
}

#[test]
fn unmoved_handles_move_nothing_bit_for_bit() {
    let (mesh, _) = bumpy_capsule();
    let graph = VolumetricGraph::build(&mesh).unwrap();
    let fixed = [Sphere {
        centre: DVec3::new(-3.0, 0.0, 0.0),
        radius: 1.0,
    }];
    let handles = [SphereHandle {
        sphere: Sphere {
            centre: DVec3::new(3.0, 0.0, 0.0),
            radius: 1.0,
        },
        matrix: DMat4::IDENTITY,
    }];
    let moved = deform_with_spheres(
        &mesh,
        Some(&graph),
        &handles,
        &fixed,
        Method::Volumetric(VolumetricParams::default()),
    )
    .unwrap();
    let worst = moved
        .iter()
        .zip(mesh.positions())
        .map(|(a, b)| a.distance(*b))
        .fold(0.0, f64::max);
    assert!(moved == mesh.positions(), "a vertex moved by {worst}");
}

#[test]
fn bad_input_gets_a_sentence() {
    let (mesh, _) = bumpy_capsule();
    let ball = |x: f64| Sphere {
        centre: DVec3::new(x, 0.0, 0.0),
        radius: 1.0,
    };
    let handle = |x: f64, matrix: DMat4| SphereHandle {
        sphere: ball(x),
        matrix,
    };
    let refuse = |handles: &[SphereHandle], fixed: &[Sphere]| {
        deform_with_spheres(
            &mesh,
            None,
            handles,
            fixed,
            Method::Volumetric(VolumetricParams::default()),
        )
        .unwrap_err()
    };
    assert_eq!(
        refuse(&[handle(10.0, DMat4::IDENTITY)], &[]),
        VolumetricError::EmptyHandle { index: 0 }
    );
    assert_eq!(
        refuse(&[handle(3.0, DMat4::IDENTITY)], &[ball(2.5)]),
        VolumetricError::FixedOverlapsHandle { index: 0 }
    );
    let flat = DMat4::from_scale(DVec3::new(1.0, 0.0, 1.0));
    assert_eq!(
        refuse(&[handle(3.0, flat)], &[]),
        VolumetricError::BadMatrix { index: 0 }
    );
    let nan = DMat4::from_translation(DVec3::new(f64::NAN, 0.0, 0.0));
    assert_eq!(
        refuse(&[handle(3.0, nan)], &[]),
        VolumetricError::BadMatrix { index: 0 }
    );
    let open = primitives::grid(5, 5, 1.0);
    let err = deform_with_spheres(
        &open,
        None,
        &[SphereHandle {
            sphere: Sphere {
                centre: DVec3::ZERO,
                radius: 0.3,
            },
            matrix: DMat4::IDENTITY,
        }],
        &[],
        Method::Volumetric(VolumetricParams::default()),
    )
    .unwrap_err();
    assert_eq!(err, VolumetricError::NotClosed);
    assert!(err.to_string().contains("closed surface"), "{err}");
    let large = primitives::capsule(0.5, 3.0, 300, 201);
    let err = VolumetricGraph::build(&large).unwrap_err();
    assert_eq!(err, VolumetricError::TooLarge { vertices: 60_002 });
    assert!(err.to_string().contains("up to 60,000 vertices"), "{err}");
}

fn deform_op(method: DeformMethod, handle_sphere: [f64; 4], matrix: DMat4) -> Op {
    Op::Deform(DeformInput {
        method,
        model: 0,
        handles: vec![DeformHandleInput {
            sphere: handle_sphere,
            matrix: matrix.to_cols_array(),
        }],
        fixed: vec![[-3.0, 0.0, 0.0, 1.0]],
    })
}

#[test]
fn the_deform_op_replays_bit_for_bit_and_a_refusal_changes_nothing() {
    let (mesh, _) = bumpy_capsule();
    let mut editor = Editor::new();
    editor.apply(import_mesh("capsule.glb", &mesh)).unwrap();
    let imported = editor.document().models[0].mesh.clone();
    let bend = deform_op(
        DeformMethod::Volumetric,
        [3.0, 0.0, 0.0, 1.0],
        half_turn_about(0.0, 4.26 / PI),
    );
    editor.apply(bend).unwrap();
    let expected = deform_with_spheres(
        &imported,
        None,
        &[SphereHandle {
            sphere: Sphere {
                centre: DVec3::new(3.0, 0.0, 0.0),
                radius: 1.0,
            },
            matrix: half_turn_about(0.0, 4.26 / PI),
        }],
        &[Sphere {
            centre: DVec3::new(-3.0, 0.0, 0.0),
            radius: 1.0,
        }],
        Method::Volumetric(VolumetricParams::default()),
    )
    .unwrap();
    assert!(editor.document().models[0].mesh.positions() == expected.as_slice());
    let json = editor.session_json();
    assert!(
        json.contains(r#""op":"deform","method":"volumetric""#),
        "{json}"
    );
    let replayed = Editor::replay_json(&json).unwrap();
    assert_eq!(digest(replayed.document()), digest(editor.document()));
    // As the page replays it: computed in its worker, the same.
    let mut elsewhere = Editor::new();
    let ops = replayed.session().ops;
    for op in ops {
        let mut edit = elsewhere.begin(op).unwrap();
        if edit.op().name() == "deform" {
            supply_elsewhere(&mut edit);
        }
        edit.finish(&mut elsewhere).unwrap();
    }
    assert_eq!(digest(elsewhere.document()), digest(editor.document()));

    // The surface editor on the same constraints, then undone.
    let before = digest(editor.document());
    let surface = deform_op(
        DeformMethod::Surface,
        [-3.0, 2.712, 0.0, 1.0],
        DMat4::from_translation(DVec3::Z * 0.3),
    );
    editor.apply(surface).unwrap();
    assert_ne!(digest(editor.document()), before);
    editor.apply(Op::Undo).unwrap();
    assert_eq!(digest(editor.document()), before);

    // Refused: a handle over the fixed sphere; the document and history stay.
    let session = editor.session_json();
    let err = editor
        .apply(deform_op(
            DeformMethod::Volumetric,
            [-2.5, 0.0, 0.0, 1.0],
            DMat4::IDENTITY,
        ))
        .unwrap_err();
    assert!(err.to_string().contains("overlaps a fixed sphere"), "{err}");
    assert_eq!(digest(editor.document()), before);
    assert_eq!(editor.session_json(), session);
}

#[test]
fn a_control_curve_redrawn_in_its_plane_bends_the_capsule_and_keeps_its_volume() {
    let mesh = smooth_capsule();
    let mut editor = Editor::new();
    editor.apply(import_mesh("capsule.glb", &mesh)).unwrap();
    let imported = editor.document().models[0].mesh.clone();
    let op = Op::CurveDeform(quarter_bend());
    // The same op drawn as a gesture: the preview follows the stroke, and the commit is
    // the op applied at once, bit for bit.
    let mut drawn = Editor::new();
    drawn.apply(import_mesh("capsule.glb", &mesh)).unwrap();
    let Op::CurveDeform(whole) = &op else {
        unreachable!()
    };
    let mut begun = whole.clone();
    begun.stroke.truncate(1);
    let mut gesture = drawn.begin_gesture(Op::CurveDeform(begun)).unwrap();
    for &sample in &whole.stroke[1..] {
        gesture.extend(sample);
        while gesture.step().unwrap() == Progress::Working {}
    }
    assert!(gesture.moved_model().is_some(), "no preview");
    gesture.finish(&mut drawn).unwrap();
    // And as the page draws it with its worker: each preview computed elsewhere by the
    // worker's own edit of the drag, the commit computed whole elsewhere.
    let mut offloaded = Editor::new();
    offloaded.apply(import_mesh("capsule.glb", &mesh)).unwrap();
    let mut begun = whole.clone();
    begun.stroke.truncate(1);
    let mut gesture = offloaded.begin_gesture(Op::CurveDeform(begun)).unwrap();
    let mut worker = None;
    for &sample in &whole.stroke[1..] {
        gesture.extend(sample);
        preview_elsewhere(&mut gesture, &mut worker);
        assert_eq!(
            gesture.step().unwrap(),
            Progress::Waiting,
            "nothing to step here"
        );
    }
    assert!(gesture.moved_model().is_some(), "no preview from elsewhere");
    commit_elsewhere(gesture, worker, &mut offloaded);
    // Drawn in the front view the plane is seen edge-on: refused, nothing changes.
    let mut edge_on = whole.clone();
    edge_on.stroke_camera = None;
    let before = digest(editor.document());
    let err = editor.apply(Op::CurveDeform(edge_on)).unwrap_err();
    assert!(err.to_string().contains("edge-on"), "{err}");
    assert_eq!(digest(editor.document()), before);
    editor.apply(op).unwrap();
    assert_eq!(digest(drawn.document()), digest(editor.document()));
    assert_eq!(digest(offloaded.document()), digest(editor.document()));
    let moved = editor.document().models[0].mesh.positions().to_vec();
    let change = volume(&imported, &moved) / enclosed_volume(&imported) - 1.0;
    let tip = nearest_vertex(&imported, DVec3::new(3.5, 0.0, 0.0));
    println!(
        "curve deform: volume {:+.2}%, tip {} -> {}",
        100.0 * change,
        imported.positions()[tip],
        moved[tip]
    );
    assert!(
        change.abs() < 0.05,
        "volume changed by {:.2}%",
        100.0 * change
    );
    assert_eq!(crossing_pairs(&imported, &moved), 0);
    // The right end swung out toward +z and round toward -x; the left end held.
    assert!(
        moved[tip].z > 1.5 && moved[tip].x < 2.5,
        "tip at {}",
        moved[tip]
    );
    let left = nearest_vertex(&imported, DVec3::new(-3.5, 0.0, 0.0));
    assert!(moved[left] == imported.positions()[left]);
    let replayed = Editor::replay_json(&editor.session_json()).unwrap();
    assert_eq!(digest(replayed.document()), digest(editor.document()));
}

/// Spot turns its head by 40° about a vertical axis through its neck, its rump held: the
/// volume stays within 3%, no new self-intersection appears, and an unmoved head moves
/// nothing. (The other closed scans in the test data are 50k and 134k vertices: see
/// `VolumetricGraph::build`'s limit.)
#[test]
fn spot_turns_its_head_keeping_its_volume() {
    let Some(meshes) = crate::common::testdata_meshes("spot.glb") else {
        return;
    };
    let spot = &meshes[0];
    let graph = VolumetricGraph::build(spot).unwrap();
    let neck = DVec3::new(0.0, 0.3, 0.45);
    let turn = DMat4::from_translation(neck)
        * DMat4::from_rotation_y(40f64.to_radians())
        * DMat4::from_translation(-neck);
    let head = |matrix| SphereHandle {
        sphere: Sphere {
            centre: DVec3::new(0.0, 0.35, 0.85),
            radius: 0.3,
        },
        matrix,
    };
    let rump = [Sphere {
        centre: DVec3::new(0.0, 0.0, -0.6),
        radius: 0.45,
    }];
    let run =
        |matrix, method| deform_with_spheres(spot, Some(&graph), &[head(matrix)], &rump, method);
    let params = Method::Volumetric(VolumetricParams::default());
    let still = run(DMat4::IDENTITY, params).unwrap();
    assert!(still == spot.positions(), "an unmoved head moved something");
    let turned = run(turn, params).unwrap();
    let surface = run(turn, Method::Surface).unwrap();
    let rest = enclosed_volume(spot);
    let change = volume(spot, &turned) / rest - 1.0;
    let surface_change = volume(spot, &surface) / rest - 1.0;
    let (before, after) = (
        crossing_pairs(spot, spot.positions()),
        crossing_pairs(spot, &turned),
    );
    println!(
        "spot: {} vertices, {} graph points; head turned 40°: volume {:+.2}% (surface editor {:+.2}%), crossing pairs {before} -> {after}",
        spot.n_vertices(),
        graph.n_points(),
        100.0 * change,
        100.0 * surface_change
    );
    assert!(
        change.abs() < 0.03,
        "volume changed by {:.2}%",
        100.0 * change
    );
    assert!(after <= before, "the turn made the surface cross itself");
    // The nose went where the matrix takes it.
    let nose = nearest_vertex(spot, DVec3::new(0.0, 0.35, 1.05));
    let expected = turn.transform_point3(spot.positions()[nose]);
    assert!(turned[nose].distance(expected) < 1e-9);
}

/// The edge path `input`'s curve stroke picks on `mesh`.
fn picked_path(mesh: &Mesh, input: &CurveDeformInput) -> Vec<u32> {
    let sketch = Sketch {
        camera: input.camera,
        viewport: DVec2::from(input.viewport),
        points: input
            .curve
            .iter()
            .map(|&[x, y, _]| DVec2::new(x, y))
            .collect(),
        region: None,
    };
    pick_curve(mesh, &sketch)
        .expect("the curve stroke lies on the capsule")
        .iter()
        .map(|v| v.0)
        .collect()
}

/// Several curves: a curve named by its vertex chain bends exactly as the stroke that picks
/// it; a second curve held (no lasso) keeps its part in place where, without it, the bend
/// spreads over it; a chain with a gap is refused with a sentence and nothing changes.
#[test]
fn a_held_curve_keeps_its_part_while_another_curve_bends() {
    let mesh = smooth_capsule();
    let start = || {
        let mut editor = Editor::new();
        editor.apply(import_mesh("capsule.glb", &mesh)).unwrap();
        editor
    };
    let imported = start().document().models[0].mesh.clone();
    let mut stroked = quarter_bend();
    stroked.fixed = None;
    let path = picked_path(&imported, &stroked);
    let mut by_path = stroked.clone();
    by_path.curve.clear();
    by_path.path = Some(path.clone());
    let (mut a, mut b) = (start(), start());
    a.apply(Op::CurveDeform(stroked.clone())).unwrap();
    b.apply(Op::CurveDeform(by_path.clone())).unwrap();
    assert_eq!(digest(a.document()), digest(b.document()));
    // The held curve runs along the capsule's top over its left end.
    let mut left = stroked.clone();
    left.curve = screen_line(
        &left.camera,
        DVec2::from(left.viewport),
        DVec3::new(-3.2, 0.25, 0.4),
        DVec3::new(-2.0, 0.25, 0.4),
    );
    let held = picked_path(&imported, &left);
    assert!(held.len() >= 3, "held curve of {} vertices", held.len());
    let mut holding = by_path.clone();
    holding.held = vec![held.clone()];
    let mut c = start();
    c.apply(Op::CurveDeform(holding.clone())).unwrap();
    let drift = |editor: &Editor| {
        let moved = editor.document().models[0].mesh.positions();
        held.iter()
            .map(|&v| moved[v as usize].distance(imported.positions()[v as usize]))
            .fold(0.0, f64::max)
    };
    let (free, kept) = (drift(&a), drift(&c));
    println!("held curve: its vertices move {kept:.4} at most, {free:.4} when not held");
    assert!(free > 0.05, "the bend did not reach the left end ({free})");
    assert!(kept < 0.2 * free, "held {kept} against {free}");
    let moved = c.document().models[0].mesh.positions();
    let change = volume(&imported, moved) / enclosed_volume(&imported) - 1.0;
    assert!(change.abs() < 0.05, "volume {:+.2}%", 100.0 * change);
    let replayed = Editor::replay_json(&c.session_json()).unwrap();
    assert_eq!(digest(replayed.document()), digest(c.document()));
    // A chain whose neighbours are not joined by an edge, or a curve given both ways.
    let mut gap = by_path.clone();
    gap.path = Some(vec![path[0], path[path.len() - 1]]);
    let mut both = by_path;
    both.curve = stroked.curve;
    for bad in [gap, both] {
        let before = digest(c.document());
        let err = c.apply(Op::CurveDeform(bad)).unwrap_err();
        assert!(
            err.to_string().contains("chain of the model's vertices"),
            "{err}"
        );
        assert_eq!(digest(c.document()), before);
    }
}

/// Coarse editing: the curve's last spline control point dragged 1.5 toward +z (seen from
/// above, face on to the plane) swings the capsule's right end out with it; the curve gets
/// longer and the tube keeps its cross-section (the volume grows by the radius' disc times
/// the curve's new length, within 2% of the volume); a drag that goes nowhere moves nothing measurable; bad knots or a control point
/// the spline lacks are refused with a sentence, nothing changed.
#[test]
fn dragging_a_spline_control_point_bends_the_capsule() {
    let mesh = smooth_capsule();
    let mut editor = Editor::new();
    editor.apply(import_mesh("capsule.glb", &mesh)).unwrap();
    let imported = editor.document().models[0].mesh.clone();
    let mut input = quarter_bend();
    let above = input.stroke_camera.expect("drawn from above");
    let viewport = DVec2::from(input.viewport);
    let knots = uniform_knots(COARSE_CONTROLS);
    let last = COARSE_CONTROLS - 1;
    let tip = DVec3::new(2.5, 0.0, 0.5);
    input.stroke = screen_line(&above, viewport, tip, tip + DVec3::new(0.0, 0.0, 1.5));
    input.coarse = Some(CoarseInput {
        knots: knots.clone(),
        control: last,
    });
    let path = picked_path(&imported, &input);
    let end = path[path.len() - 1] as usize;
    let middle = path[path.len() / 2] as usize;
    // Refused: knots out of order, a control point past the last.
    for coarse in [
        CoarseInput {
            knots: vec![0.6, 0.3],
            control: 0,
        },
        CoarseInput {
            knots: knots.clone(),
            control: COARSE_CONTROLS,
        },
    ] {
        let bad = CurveDeformInput {
            coarse: Some(coarse),
            ..input.clone()
        };
        let before = digest(editor.document());
        let err = editor.apply(Op::CurveDeform(bad)).unwrap_err();
        assert!(
            err.to_string().contains("spline needs increasing knots"),
            "{err}"
        );
        assert_eq!(digest(editor.document()), before);
    }
    // A drag back to where it began.
    let mut nowhere = input.clone();
    let first = nowhere.stroke[0];
    nowhere.stroke = vec![first, nowhere.stroke[10], first];
    let mut still = Editor::new();
    still.apply(import_mesh("capsule.glb", &mesh)).unwrap();
    still.apply(Op::CurveDeform(nowhere)).unwrap();
    let drift = (still.document().models[0].mesh.positions().iter())
        .zip(imported.positions())
        .map(|(a, b)| a.distance(*b))
        .fold(0.0, f64::max);
    assert!(drift < 1e-6, "an unmoved spline moved a vertex by {drift}");
    editor.apply(Op::CurveDeform(input)).unwrap();
    let moved = editor.document().models[0].mesh.positions().to_vec();
    let rise = |v: usize| moved[v].z - imported.positions()[v].z;
    let rest_volume = enclosed_volume(&imported);
    let change = volume(&imported, &moved) / rest_volume - 1.0;
    let length = |x: &[DVec3]| {
        (path.windows(2))
            .map(|w| x[w[0] as usize].distance(x[w[1] as usize]))
            .sum::<f64>()
    };
    let longer = length(&moved) - length(imported.positions());
    let tube = PI * 0.5 * 0.5 * longer / rest_volume;
    println!(
        "coarse drag: the curve's end rises {:.3}, its middle {:.3}; the curve {longer:+.3} \
         longer; volume {:+.2}% ({:+.2}% for a tube that long)",
        rise(end),
        rise(middle),
        100.0 * change,
        100.0 * tube
    );
    assert!(rise(end) > 0.75, "the end rose {}", rise(end));
    assert!(
        rise(middle) < 0.5 * rise(end),
        "the middle rose {}",
        rise(middle)
    );
    assert!(
        (change - tube).abs() < 0.02,
        "volume {:+.2}% against {:+.2}%",
        100.0 * change,
        100.0 * tube
    );
    assert_eq!(crossing_pairs(&imported, &moved), 0);
    let replayed = Editor::replay_json(&editor.session_json()).unwrap();
    assert_eq!(digest(replayed.document()), digest(editor.document()));
}

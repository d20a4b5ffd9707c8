//! Key-framed animation (issue 20): in-betweens by Laplacian-coordinate interpolation, the
//! key ops, and the morph-target export that comes back as key frames.

use std::f64::consts::FRAC_PI_2;

use glam::{DMat4, DVec3};
use sketchmesh_core::animation::{KeyBlend, SAMPLES_PER_SECOND, Timeline};
use sketchmesh_core::document::{
    DeformHandleInput, DeformInput, DeformMethod, Editor, KeyframeInput, Op,
};
use sketchmesh_core::io::{ImportFile, import_gltf, write_glb};
use sketchmesh_core::mesh::Mesh;
use sketchmesh_core::volumetric::{
    Method, Sphere, SphereHandle, VolumetricParams, deform_with_spheres,
};

use crate::common::{digest, import_mesh};
use crate::volumetric::box_mesh;

/// A bar along x (2.4 long) and the same bar bent up by a quarter turn: its free middle
/// (1.7 long between the held ends) follows a quarter circle of radius 1.7 / (π/2), which
/// the quarter turn about (0, 1.082 − 0.85) asks of the right end.
fn bar_and_bent() -> (Mesh, Vec<DVec3>) {
    let bar = box_mesh(DVec3::new(2.4, 0.3, 0.3), [48, 6, 6]);
    let pivot = DVec3::new(0.0, 1.7 / FRAC_PI_2 - 0.85, 0.0);
    let turn = DMat4::from_translation(pivot)
        * DMat4::from_rotation_z(FRAC_PI_2)
        * DMat4::from_translation(-pivot);
    let bent = deform_with_spheres(
        &bar,
        None,
        &[SphereHandle {
            sphere: Sphere {
                centre: DVec3::new(1.2, 0.0, 0.0),
                radius: 0.35,
            },
            matrix: turn,
        }],
        &[Sphere {
            centre: DVec3::new(-1.2, 0.0, 0.0),
            radius: 0.35,
        }],
        Method::Volumetric(VolumetricParams::default()),
    )
    .expect("the bar bends");
    (bar, bent)
}

/// The centroid of the bar's far end face (x = 1.2 at rest).
fn tip(bar: &Mesh, pose: &[DVec3]) -> DVec3 {
    let end: Vec<usize> = (0..bar.n_vertices())
        .filter(|&v| (bar.positions()[v].x - 1.2).abs() < 1e-9)
        .collect();
    end.iter().map(|&v| pose[v]).sum::<DVec3>() / end.len() as f64
}

#[test]
fn half_way_between_keys_a_bend_is_half_turned_and_keeps_its_length() {
    let (bar, bent) = bar_and_bent();
    let mut blend = KeyBlend::new(&bar, bar.positions(), &bent).expect("factors");
    let mut pose = vec![DVec3::ZERO; bar.n_vertices()];
    blend.at(0.0, &mut pose).expect("solves");
    assert!(pose == bar.positions());
    blend.at(1.0, &mut pose).expect("solves");
    assert!(pose == bent);
    blend.at(0.5, &mut pose).expect("solves");
    // The bar's length along its middle (through the centroids of its cross-sections)
    // stays within 3% of the keys' (2.8% here); a linear blend's falls 11.5% short.
    let length = |pose: &[DVec3]| {
        let centres: Vec<DVec3> = (0..=48)
            .map(|k| {
                let x = -1.2 + 0.05 * k as f64;
                let ring: Vec<usize> = (0..bar.n_vertices())
                    .filter(|&v| (bar.positions()[v].x - x).abs() < 1e-9)
                    .collect();
                ring.iter().map(|&v| pose[v]).sum::<DVec3>() / ring.len() as f64
            })
            .collect();
        centres.windows(2).map(|w| w[0].distance(w[1])).sum::<f64>()
    };
    let linear: Vec<DVec3> = bar
        .positions()
        .iter()
        .zip(&bent)
        .map(|(a, b)| a.lerp(*b, 0.5))
        .collect();
    let (rest, bent_length, half, blended) = (
        length(bar.positions()),
        length(&bent),
        length(&pose),
        length(&linear),
    );
    println!(
        "length: rest {rest:.3}, bent {bent_length:.3}, Laplacian half way {half:.3}, linear half way {blended:.3}"
    );
    let mean = 0.5 * (rest + bent_length);
    assert!((half - mean).abs() < 0.03 * rest, "half way length {half}");
    assert!(
        blended < mean - 0.08 * rest,
        "the linear blend should fall short"
    );
    // The far end's axis is turned about half of the quarter turn.
    let end_axis = |pose: &[DVec3]| {
        let near: Vec<usize> = (0..bar.n_vertices())
            .filter(|&v| (bar.positions()[v].x - 0.95).abs() < 1e-9)
            .collect();
        let inner = near.iter().map(|&v| pose[v]).sum::<DVec3>() / near.len() as f64;
        (tip(&bar, pose) - inner).normalize()
    };
    let angle = end_axis(&pose).angle_between(DVec3::X).to_degrees();
    assert!((angle - 45.0).abs() < 8.0, "the end turned by {angle:.1}°");
}

fn keyframe(time: f64) -> Op {
    Op::Keyframe(KeyframeInput { time })
}

fn lift(height: f64) -> Op {
    Op::Deform(DeformInput {
        method: DeformMethod::Volumetric,
        model: 0,
        handles: vec![DeformHandleInput {
            sphere: [1.2, 0.0, 0.0, 0.35],
            matrix: DMat4::from_translation(DVec3::Y * height).to_cols_array(),
        }],
        fixed: vec![[-1.2, 0.0, 0.0, 0.35]],
    })
}

#[test]
fn three_keys_interpolate_export_and_come_back() {
    let (bar, _) = bar_and_bent();
    let mut editor = Editor::new();
    editor.apply(import_mesh("bar.glb", &bar)).unwrap();
    for (time, height) in [(0.0, None), (1.0, Some(0.4)), (2.0, Some(-0.3))] {
        if let Some(height) = height {
            editor.apply(lift(height)).unwrap();
        }
        editor.apply(keyframe(time)).unwrap();
    }
    let model = editor.document().models[0].clone();
    assert_eq!(model.keyframes().count(), 3);
    // The in-between at 0.5 is the Laplacian interpolation of the first two keys.
    let mut timeline = Timeline::new(&model).unwrap().expect("three keys");
    let mut at_half = vec![DVec3::ZERO; model.mesh.n_vertices()];
    timeline.pose(0.5, &mut at_half).unwrap();
    let keys: Vec<_> = model.keyframes().collect();
    let mut blend = KeyBlend::new(&model.mesh, &keys[0].positions, &keys[1].positions).unwrap();
    let mut expected = vec![DVec3::ZERO; model.mesh.n_vertices()];
    blend.at(0.5, &mut expected).unwrap();
    assert!(at_half == expected);
    assert_eq!(
        timeline.sample_times().len(),
        1 + 2 * SAMPLES_PER_SECOND as usize
    );

    // Exported and imported again: the three keys, at f32 precision.
    let glb = write_glb(editor.document());
    let file = ImportFile {
        name: "animated.glb",
        bytes: &glb,
    };
    let imported = import_gltf(&file, &[], &Default::default()).unwrap();
    let back = &imported.models[0];
    let back_keys: Vec<_> = back.keyframes().collect();
    assert_eq!(back_keys.len(), 3);
    for (a, b) in keys.iter().zip(&back_keys) {
        assert_eq!(a.time, b.time);
        let worst = a
            .positions
            .iter()
            .zip(b.positions.iter())
            .map(|(p, q)| p.distance(*q))
            .fold(0.0, f64::max);
        assert!(worst < 1e-5, "key at {} moved by {worst}", a.time);
    }

    // Deleting a key, undoing, replaying.
    let before = digest(editor.document());
    editor
        .apply(Op::DeleteKeyframe(KeyframeInput { time: 1.0 }))
        .unwrap();
    assert_eq!(editor.document().models[0].keyframes().count(), 2);
    editor.apply(Op::Undo).unwrap();
    assert_eq!(digest(editor.document()), before);
    let replayed = Editor::replay_json(&editor.session_json()).unwrap();
    assert_eq!(
        replayed.document().models[0].keyframes,
        editor.document().models[0].keyframes
    );

    // Posing at a time between keys puts the model in that in-between; the keys stay.
    editor
        .apply(Op::PoseAt(KeyframeInput { time: 0.5 }))
        .unwrap();
    assert!(editor.document().models[0].mesh.positions() == expected.as_slice());
    assert_eq!(editor.document().models[0].keyframes().count(), 3);
    editor.apply(Op::Undo).unwrap();
    assert_eq!(digest(editor.document()), before);

    // Refusals change nothing.
    let err = editor.apply(keyframe(-1.0)).unwrap_err();
    assert!(err.to_string().contains("zero or more"), "{err}");
    let err = editor
        .apply(Op::DeleteKeyframe(KeyframeInput { time: 7.0 }))
        .unwrap_err();
    assert_eq!(err.to_string(), "There is no key frame at 7 s.");
    assert_eq!(digest(editor.document()), before);
}

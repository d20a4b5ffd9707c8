//! A model's mirror image: its twin across the plane.

use crate::model::{Keyframe, MirrorPlane, Model};

/// `model` reflected about `plane`, vertex for vertex: the same vertex ids, faces turned
/// over so the outside stays outside, the same control curves, and key frames reflected.
/// Its imported look goes with it only while nothing depends on the positions (a soup as
/// imported no longer fits the reflected mesh, so it is left behind).
pub fn mirrored_model(model: &Model, plane: &MirrorPlane) -> Model {
    Model {
        mesh: model.mesh.mirrored(|p| plane.reflect(p)),
        curves: model.curves.clone(),
        name: model.name.clone(),
        appearance: model.appearance.clone(),
        as_imported: None,
        // Vertex for vertex, so each vertex keeps its colour.
        colors: model.colors.clone(),
        finish: model.finish,
        keyframes: (model.keyframes.iter())
            .map(|key| Keyframe {
                positions: std::sync::Arc::new(
                    key.positions.iter().map(|&p| plane.reflect(p)).collect(),
                ),
                ..key.clone()
            })
            .collect(),
    }
}

//! Colour on models: a round brush that paints vertex colours under the pen ([`brush`]), and
//! colours carried onto the new mesh of an op that changes a painted model's triangles
//! ([`carry`]).
//!
//! Colours are linear RGB, one per vertex, and are what the model shows: a painted model's
//! finish keeps a white base colour, and its colours are what clay, an imported look or an
//! earlier base colour showed before the first stroke (see [`shown_colors`]). So the colour
//! picked is the colour seen, and glTF's `COLOR_0` times its base colour factor gives the
//! same picture.

mod brush;
mod carry;

pub use brush::{Brush, Dab, PaintStroke, dabs_between, mirrored_dab};
pub use carry::carried_colors;

use crate::model::{Finish, Model};

/// The colour each vertex of `model` shows: its paint times its base colour; unpainted, the
/// base colour, or an imported model's vertex colours and materials averaged over each
/// vertex's corners.
pub fn shown_colors(model: &Model) -> Vec<[f32; 3]> {
    let tint = model.finish().rgb();
    let times = |[r, g, b]: [f32; 3]| [r * tint[0], g * tint[1], b * tint[2]];
    if let Some(colors) = model.vertex_colors() {
        return colors.iter().map(|&c| times(c)).collect();
    }
    let imported = (model.appearance.as_deref())
        .filter(|a| a.fits(&model.mesh))
        .and_then(|a| a.corner_colors());
    let Some(corners) = imported else {
        return vec![tint; model.mesh.n_vertices()];
    };
    let mut sums = vec![([0.0f32; 3], 0u32); model.mesh.n_vertices()];
    for (&v, [r, g, b, _]) in model.mesh.triangle_indices().iter().zip(corners) {
        let (sum, count) = &mut sums[v as usize];
        *sum = [sum[0] + r, sum[1] + g, sum[2] + b];
        *count += 1;
    }
    sums.into_iter()
        .map(|(sum, count)| times(sum.map(|s| s / count.max(1) as f32)))
        .collect()
}

/// `model` with `colors` as its paint (one per vertex, what it shows): its finish keeps its
/// roughness, metalness and alpha, with a white base colour so that nothing tints the paint.
pub fn with_colors(model: &Model, colors: Vec<[f32; 3]>) -> Model {
    let finish = model.finish();
    let [_, _, _, alpha] = finish.base_color;
    Model {
        colors: Some(std::sync::Arc::new(colors)),
        finish: Some(Finish {
            base_color: [1.0, 1.0, 1.0, alpha],
            ..finish
        }),
        ..model.clone()
    }
}

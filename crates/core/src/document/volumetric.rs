//! The `deform` op: a scripted large deformation of one model by sphere handles, through the
//! volumetric graph Laplacian or, for comparison, the surface editor
//! ([`crate::volumetric::deform_with_spheres`]).

use glam::{DMat4, DVec3};
use serde::{Deserialize, Serialize};

use super::outcome::{target, with_positions};
use super::{CommandError, Document, Model};
use crate::volumetric::{Method, Sphere, SphereHandle, VolumetricParams, deform_with_spheres};

/// `{"op":"deform","method":…,"model":i,"handles":[…],"fixed":[…]}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DeformInput {
    /// How the points that follow are solved for.
    pub method: DeformMethod,
    /// The model's index.
    pub model: usize,
    /// What moves: the points inside each sphere, exactly by its matrix.
    pub handles: Vec<DeformHandleInput>,
    /// What stays: the points inside these spheres `[x, y, z, r]`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub fixed: Vec<[f64; 4]>,
}

/// The `"method"` of a `deform` op.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum DeformMethod {
    /// The volumetric graph Laplacian.
    #[default]
    Volumetric,
    /// The surface Laplacian editor with rotations.
    Surface,
}

/// One handle of a `deform` op.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DeformHandleInput {
    /// The sphere `[x, y, z, r]` whose points it moves.
    pub sphere: [f64; 4],
    /// The 4×4 affine matrix, column by column, that moves them.
    pub matrix: [f64; 16],
}

/// The index of the model and the model with its vertices moved; its triangles, curves and
/// appearance stay.
///
/// Errors: [`CommandError::NoSuchModel`], and the deformation's refusal (an open model,
/// a handle that holds nothing, a fixed sphere over a handle, a bad matrix).
pub(super) fn deform_op(
    doc: &Document,
    input: &DeformInput,
) -> Result<(usize, Model), CommandError> {
    let mesh = &target(doc, input.model)?.mesh;
    let handles: Vec<SphereHandle> = input
        .handles
        .iter()
        .map(|h| SphereHandle {
            sphere: sphere(h.sphere),
            matrix: DMat4::from_cols_array(&h.matrix),
        })
        .collect();
    let fixed: Vec<Sphere> = input.fixed.iter().map(|&s| sphere(s)).collect();
    let method = match input.method {
        DeformMethod::Volumetric => Method::Volumetric(VolumetricParams::default()),
        DeformMethod::Surface => Method::Surface,
    };
    let positions = deform_with_spheres(mesh, None, &handles, &fixed, method)?;
    Ok((input.model, with_positions(doc, input.model, &positions)))
}

fn sphere([x, y, z, radius]: [f64; 4]) -> Sphere {
    Sphere {
        centre: DVec3::new(x, y, z),
        radius,
    }
}

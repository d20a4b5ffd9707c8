//! Scripted large deformations (the `deform` op): the points inside each handle sphere move
//! exactly by the handle's affine matrix, those inside the fixed spheres stay, and the rest
//! follow, through the volumetric graph (`Method::Volumetric`) or, for comparison, through
//! the surface Laplacian editor with rotations (`Method::Surface`, `crate::deform`).
//!
//! A handle's similarity (the part of its matrix that is propagated) is the polar rotation
//! and the cube root of the determinant. A turn by about half a turn is ambiguous: the same
//! matrix is reached turning either way round, and the in-between points would turn the
//! other way. The way chosen is the one whose spread of turns best carries the rest chord
//! from the fixed part to the handle onto the moved chord (16 samples of the linear field
//! along it); for small turns that is always the short way.

use glam::{DMat3, DMat4, DVec3};

use super::{
    Constraints, Falloff, Similarity, VolumetricEdit, VolumetricError, VolumetricGraph,
    VolumetricParams, spread,
};
use crate::deform::{EditParams, HandlePoint, LaplacianEdit};
use crate::mesh::{Mesh, VertexId};

/// Samples of the chord test that picks a half turn's direction.
const CHORD_SAMPLES: usize = 16;

/// A ball in model space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    /// Its centre.
    pub centre: DVec3,
    /// Its radius, positive.
    pub radius: f64,
}

impl Sphere {
    fn holds(&self, p: DVec3) -> bool {
        p.distance_squared(self.centre) <= self.radius * self.radius
    }

    fn is_usable(&self) -> bool {
        self.centre.is_finite() && self.radius.is_finite() && self.radius > 0.0
    }
}

/// A handle of a scripted deformation: what lies inside `sphere` moves by `matrix`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereHandle {
    /// Which points it holds.
    pub sphere: Sphere,
    /// Where it takes them.
    pub matrix: DMat4,
}

/// How a scripted deformation solves for the points that follow.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Method {
    /// Zhou et al.'s volumetric graph Laplacian.
    Volumetric(VolumetricParams),
    /// The surface Laplacian editor with per-vertex rotations (for comparison).
    Surface,
}

/// The mesh's new vertex positions after moving `handles` with `fixed` held still.
///
/// Errors: [`VolumetricError::BadSphere`], [`VolumetricError::BadMatrix`],
/// [`VolumetricError::EmptyHandle`], [`VolumetricError::FixedOverlapsHandle`],
/// [`VolumetricError::HandlesOverlap`], those of [`VolumetricGraph::build`] and the solve's.
pub fn deform_with_spheres(
    mesh: &Mesh,
    graph: Option<&VolumetricGraph>,
    handles: &[SphereHandle],
    fixed: &[Sphere],
    method: Method,
) -> Result<Vec<DVec3>, VolumetricError> {
    let similarities = check(mesh, handles, fixed)?;
    match method {
        Method::Surface => surface(mesh, handles, fixed),
        Method::Volumetric(params) => {
            let built;
            let graph = match graph {
                Some(graph) => graph,
                None => {
                    built = VolumetricGraph::build(mesh)?;
                    &built
                }
            };
            volumetric(mesh, graph, handles, &similarities, fixed, params)
        }
    }
}

/// The handles' similarities, after checking the input.
fn check(
    mesh: &Mesh,
    handles: &[SphereHandle],
    fixed: &[Sphere],
) -> Result<Vec<Similarity>, VolumetricError> {
    if let Some(index) = fixed.iter().position(|s| !s.is_usable()) {
        return Err(VolumetricError::BadSphere {
            what: "fixed",
            index,
        });
    }
    let mut owner = vec![usize::MAX; mesh.n_vertices()];
    let mut similarities = Vec::with_capacity(handles.len());
    for (index, handle) in handles.iter().enumerate() {
        if !handle.sphere.is_usable() {
            return Err(VolumetricError::BadSphere {
                what: "handle",
                index,
            });
        }
        let linear = DMat3::from_mat4(handle.matrix);
        // The identity exactly, so that an unmoved handle changes nothing bit for bit.
        if handle.matrix == DMat4::IDENTITY {
            similarities.push(Similarity::IDENTITY);
        }
        let affine_row = handle.matrix.row(3);
        let similarity = (affine_row == glam::DVec4::W && handle.matrix.is_finite())
            .then(|| Similarity::nearest(linear))
            .flatten()
            .ok_or(VolumetricError::BadMatrix { index })?;
        if handle.matrix != DMat4::IDENTITY {
            similarities.push(similarity);
        }
        let mut selected = false;
        for (v, &p) in mesh.positions().iter().enumerate() {
            if !handle.sphere.holds(p) {
                continue;
            }
            selected = true;
            if fixed.iter().any(|s| s.holds(p)) {
                return Err(VolumetricError::FixedOverlapsHandle { index });
            }
            if owner[v] != usize::MAX {
                return Err(VolumetricError::HandlesOverlap { index });
            }
            owner[v] = index;
        }
        if !selected {
            return Err(VolumetricError::EmptyHandle { index });
        }
    }
    Ok(similarities)
}

fn volumetric(
    mesh: &Mesh,
    graph: &VolumetricGraph,
    handles: &[SphereHandle],
    similarities: &[Similarity],
    fixed: &[Sphere],
    params: VolumetricParams,
) -> Result<Vec<DVec3>, VolumetricError> {
    let points = graph.points();
    let member = |p: DVec3| -> Option<usize> {
        if fixed.iter().any(|s| s.holds(p)) {
            return Some(handles.len());
        }
        handles.iter().position(|h| h.sphere.holds(p))
    };
    let membership: Vec<Option<usize>> = points.iter().map(|&p| member(p)).collect();
    let sources = |group: usize| -> Vec<u32> {
        (0..points.len() as u32)
            .filter(|&i| membership[i as usize] == Some(group))
            .collect()
    };
    let handle_distances: Vec<Vec<f64>> = (0..handles.len())
        .map(|h| graph.distances(mesh, &sources(h)))
        .collect();
    let fixed_sources = sources(handles.len());
    let fixed_distances = if fixed_sources.is_empty() {
        vec![f64::INFINITY; points.len()]
    } else {
        graph.distances(mesh, &fixed_sources)
    };
    let similarities: Vec<Similarity> = similarities
        .iter()
        .zip(handles)
        .enumerate()
        .map(|(h, (&s, handle))| turn_way(mesh, s, handle, &handle_distances[h], &fixed_distances))
        .collect();
    let mut transforms = vec![Similarity::IDENTITY; points.len()];
    spread(
        &similarities,
        &handle_distances,
        &fixed_distances,
        Falloff::Linear,
        &mut transforms,
    );
    let constraints = Constraints {
        hard: membership.iter().map(Option::is_some).collect(),
        soft: Vec::new(),
    };
    let mut edit = VolumetricEdit::new(mesh, graph, &constraints, params)?;
    let mut out = vec![DVec3::ZERO; points.len()];
    let place = |i: usize, rest: DVec3| match membership[i] {
        Some(h) if h < handles.len() => handles[h].matrix.transform_point3(rest),
        _ => rest,
    };
    edit.deform(&transforms, place, &[], &mut out)?;
    out.truncate(graph.n_mesh());
    Ok(out)
}

/// `s`, or `s` the long way round when that carries the rest chord from the fixed part to
/// the handle better onto the moved one (see the module docs).
fn turn_way(
    mesh: &Mesh,
    s: Similarity,
    handle: &SphereHandle,
    handle_distances: &[f64],
    fixed_distances: &[f64],
) -> Similarity {
    let n = mesh.n_vertices();
    let centroid = |pick: &dyn Fn(usize) -> bool| {
        let (sum, count) = (0..n)
            .filter(|&v| pick(v))
            .fold((DVec3::ZERO, 0usize), |(s, c), v| {
                (s + mesh.positions()[v], c + 1)
            });
        (count > 0).then(|| sum / count as f64)
    };
    let Some(anchor) = centroid(&|v| fixed_distances[v] == 0.0) else {
        return s;
    };
    let Some(start) = centroid(&|v| handle_distances[v] == 0.0) else {
        return s;
    };
    let chord = start - anchor;
    let moved = handle.matrix.transform_point3(start) - anchor;
    let carried = |s: Similarity| -> DVec3 {
        (0..CHORD_SAMPLES)
            .map(|k| s.part((k as f64 + 0.5) / CHORD_SAMPLES as f64).apply(chord))
            .sum::<DVec3>()
            / CHORD_SAMPLES as f64
    };
    // The short way unless the long one is clearly better: for a turn about the chord
    // itself (a twist) both carry it equally.
    let long = s.the_long_way();
    let margin = 0.05 * chord.length();
    if carried(long).distance(moved) + margin < carried(s).distance(moved) {
        long
    } else {
        s
    }
}

/// The surface editor on the same constraints: the vertices outside the fixed spheres move,
/// the handle vertices exactly.
fn surface(
    mesh: &Mesh,
    handles: &[SphereHandle],
    fixed: &[Sphere],
) -> Result<Vec<DVec3>, VolumetricError> {
    let positions = mesh.positions();
    let roi: Vec<bool> = positions
        .iter()
        .map(|&p| !fixed.iter().any(|s| s.holds(p)))
        .collect();
    let mut points = Vec::new();
    let mut targets = Vec::new();
    for handle in handles {
        for (v, &p) in positions.iter().enumerate() {
            if handle.sphere.holds(p) {
                points.push(HandlePoint::vertex(VertexId(v as u32)));
                targets.push(handle.matrix.transform_point3(p));
            }
        }
    }
    let mut edit = LaplacianEdit::new(mesh, &roi, &points, EditParams::default())?;
    let mut out = positions.to_vec();
    edit.deform(&targets, &mut out)?;
    Ok(out)
}

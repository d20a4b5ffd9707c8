//! Adding a control curve (FiberMesh, Nealen's thesis §3.2.1, Fig. 3.4): a stroke drawn
//! over a shape becomes a chain of mesh edges, the new control curve.
//!
//! The curve is the intersection of the surface with the surface swept by the view rays
//! through the stroke, so it looks, from where it was drawn, exactly like the stroke.
//! Two methods compute it:
//! - **Open and closed curves** (`walk.rs`) lie on the visible surface. The stroke is
//!   resampled at about the edge length on screen and each sample cast onto the
//!   front-most triangle ([`Bvh`]); between consecutive samples the walk follows the plane
//!   through both that contains the view ray, splitting each crossed edge. It is local
//!   (it touches only the triangles under the stroke) and exact (its vertices lie on the
//!   swept planes, up to snapping, and on the input surface), and since it moves across
//!   shared edges it cannot jump to another part of the shape the way projecting every
//!   point separately can.
//! - **Cross sections** (`level_set.rs`) also run around the back, which no ray reaches,
//!   so they are the zero set of the signed screen distance to the stroke, cut into the
//!   mesh edge by edge and traced into loops; the loop nearest the stroke's visible hits
//!   is the curve.
//!
//! Both split edges rather than remeshing, so every input vertex keeps its index and
//! position and other control curves can follow the splits ([`Embedded::split_edges`]).
//! Crossings near a vertex snap onto it, so the result has no slivers thinner than a few
//! percent of an edge; callers remesh around the new curve anyway.
//!
//! Limits: a stroke that runs off the shape ends the open curve there (the first run of
//! hits is kept, also when it jumps over a silhouette onto a part behind); a cross section
//! through a part of the shape behind the eye is not on the swept surface there; of several
//! loops a cross section cuts (two legs), only the nearest to the stroke becomes the curve,
//! though the others are split into the mesh too. Runs in O(stroke samples · edge crossings)
//! for open and closed curves and O(vertices · stroke segments) for cross sections, plus
//! building the BVH and the output mesh.

mod embedding;
mod error;
mod level_set;
mod project;
mod walk;

pub use error::AddCurveError;

use glam::{DVec2, DVec3};

use crate::camera::Camera;
use crate::curve::polyline::simplify;
use crate::geometry::Bvh;
use crate::mesh::{Mesh, VertexId};
use embedding::Embedding;
use level_set::ZeroSet;
use project::{Projector, SurfacePoint};

/// A cross-section stroke is resampled every this many px, then simplified by
/// Douglas–Peucker at [`CROSS_SECTION_TOLERANCE_PX`], before the signed screen distance to
/// it is taken; the values of the over-sketch's stroke simplification
/// ([`crate::oversketch::simplify_stroke`]).
const CROSS_SECTION_SPACING_PX: f64 = 2.0;
/// Douglas–Peucker tolerance (px) for a cross-section stroke; see
/// [`CROSS_SECTION_SPACING_PX`].
const CROSS_SECTION_TOLERANCE_PX: f64 = 1.0;

/// What kind of curve a stroke makes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CurveShape {
    /// An open curve on the visible surface, where the stroke first runs over the shape.
    Open,
    /// A closed loop on the visible surface; the whole stroke must lie over the shape.
    Closed,
    /// A closed loop around the shape, front and back, cut by a stroke drawn across it
    /// from beside it to beside it.
    CrossSection,
}

/// A curve embedded in a mesh.
#[derive(Clone, Debug)]
pub struct Embedded {
    /// The mesh with the curve embedded: every vertex of the input keeps its index and
    /// position; new vertices are appended.
    pub mesh: Mesh,
    /// The new curve's vertices in stroke order, consecutive ones joined by mesh edges (and
    /// last→first when `closed`).
    pub chain: Vec<VertexId>,
    /// Whether the curve is a closed loop.
    pub closed: bool,
    /// Every edge split, in order: (a, b, new) means the edge a–b (of the mesh at that
    /// moment) got vertex `new` between a and b. Callers replay this list to insert `new`
    /// into other curves that ran along a–b.
    pub split_edges: Vec<(VertexId, VertexId, VertexId)>,
}

/// Embeds the curve that `stroke` (screen points in CSS px, y down, in a `viewport` of
/// `[width, height]` px seen through `camera`) draws on `mesh`. See the module docs.
///
/// Errors: [`AddCurveError`], as sentences for the user.
pub fn add_curve(
    mesh: &Mesh,
    camera: &Camera,
    viewport: DVec2,
    stroke: &[DVec2],
    shape: CurveShape,
) -> Result<Embedded, AddCurveError> {
    let projector = Projector {
        mesh,
        bvh: Bvh::new(mesh),
        camera,
        viewport,
    };
    let mut embedding = Embedding::new(mesh);
    let chain = match shape {
        CurveShape::Open => {
            let run = first_run(&projector, stroke)?;
            walk::walk(&mut embedding, &run, false)
        }
        CurveShape::Closed => {
            let samples = closed_samples(&projector, stroke)?;
            walk::walk(&mut embedding, &samples, true)
        }
        CurveShape::CrossSection => cross_section(&projector, &mut embedding, stroke)?,
    };
    let chain = chain.ok_or(AddCurveError::NotPlaced)?;
    let closed = shape != CurveShape::Open;
    if chain.len() < if closed { 3 } else { 2 } {
        return Err(AddCurveError::NotPlaced);
    }
    let Embedding {
        mut mesh,
        splits: split_edges,
    } = embedding;
    // Splits append only, so this keeps every id; it only picks the vertices' half-edges
    // as a mesh built from these triangles would have them.
    mesh.compact();
    debug_assert_eq!(mesh.validate(), Ok(()));
    Ok(Embedded {
        mesh,
        chain,
        closed,
        split_edges,
    })
}

/// The first run of consecutive samples on one sheet of the surface (at least two),
/// reaching out to the edge of the visible surface where the stroke runs off it.
fn first_run(projector: &Projector, stroke: &[DVec2]) -> Result<Vec<SurfacePoint>, AddCurveError> {
    let samples = projector.samples(stroke).ok_or(AddCurveError::Misses)?;
    let begin = samples
        .iter()
        .position(|(_, hit)| hit.is_some())
        .ok_or(AddCurveError::Misses)?;
    let mut run: Vec<SurfacePoint> = Vec::new();
    let mut end = samples.len();
    for (i, &(_, hit)) in samples.iter().enumerate().skip(begin) {
        match (hit, run.last()) {
            (Some(s), Some(last)) if !projector.is_continuous(last, &s) => break,
            (Some(s), _) => run.push(s),
            (None, _) => {
                end = i;
                break;
            }
        }
    }
    let edge = |inside: usize, outside: usize| {
        projector.edge_of_surface(samples[inside].0, samples[outside].0)
    };
    if begin > 0 {
        run.splice(0..0, edge(begin, begin - 1));
    }
    if end < samples.len() {
        run.extend(edge(end - 1, end));
    }
    if run.len() < 2 {
        return Err(AddCurveError::Misses);
    }
    Ok(run)
}

/// The samples of a closed stroke, as a loop (the last is not the first again); every one
/// must hit, on one sheet.
fn closed_samples(
    projector: &Projector,
    stroke: &[DVec2],
) -> Result<Vec<SurfacePoint>, AddCurveError> {
    let mut looped = stroke.to_vec();
    looped.extend(stroke.first());
    let samples = projector.samples(&looped).ok_or(AddCurveError::Misses)?;
    let mut samples: Vec<SurfacePoint> = samples
        .into_iter()
        .map(|(_, hit)| hit)
        .collect::<Option<_>>()
        .ok_or(AddCurveError::ClosedOffSurface)?;
    samples.pop();
    let n = samples.len();
    let is_continuous = (0..n).all(|i| projector.is_continuous(&samples[i], &samples[(i + 1) % n]));
    if n < 3 || !is_continuous {
        return Err(AddCurveError::ClosedOffSurface);
    }
    Ok(samples)
}

/// A cross section: checks that the stroke runs from beside the shape across it, then
/// embeds the loop of the cut nearest to its hits.
fn cross_section(
    projector: &Projector,
    embedding: &mut Embedding,
    stroke: &[DVec2],
) -> Result<Option<Vec<VertexId>>, AddCurveError> {
    let (hits, polyline) = crossing(projector, stroke)?;
    let distances = screen_distances(projector, &embedding.mesh, &polyline);
    let curve = level_set::cross_section(embedding, &distances, &hits);
    curve.map(Some).ok_or(AddCurveError::DoesNotCross)
}

/// The stroke's hits on the visible surface and its simplified polyline, once it is known
/// to run from beside the shape across it to beside it.
fn crossing(
    projector: &Projector,
    stroke: &[DVec2],
) -> Result<(Vec<DVec3>, Vec<DVec2>), AddCurveError> {
    let (Some(&first), Some(&last)) = (stroke.first(), stroke.last()) else {
        return Err(AddCurveError::DoesNotCross);
    };
    let samples = projector
        .samples(stroke)
        .ok_or(AddCurveError::DoesNotCross)?;
    let hits: Vec<DVec3> = samples
        .iter()
        .filter_map(|(_, hit)| hit.map(|s| s.point))
        .collect();
    let ends_miss = projector.cast(first).is_none() && projector.cast(last).is_none();
    let polyline = simplify(stroke, CROSS_SECTION_SPACING_PX, CROSS_SECTION_TOLERANCE_PX);
    if hits.is_empty() || !ends_miss || polyline.len() < 2 {
        return Err(AddCurveError::DoesNotCross);
    }
    Ok((hits, polyline))
}

/// The signed screen distance of every vertex of `mesh` to the stroke's polyline.
fn screen_distances(projector: &Projector, mesh: &Mesh, polyline: &[DVec2]) -> Vec<f64> {
    level_set::screen_distances(
        mesh.positions(),
        projector.camera,
        projector.viewport,
        polyline,
    )
}

/// A mesh split along the zero set of a per-vertex value, with the side of every face.
pub(crate) struct Split {
    /// The split mesh: every input vertex keeps its index and position.
    pub mesh: Mesh,
    /// Every edge split, as in [`Embedded::split_edges`].
    pub split_edges: Vec<(VertexId, VertexId, VertexId)>,
    /// The faces' sides and the loops between them.
    pub zero_set: ZeroSet,
}

/// Splits `mesh` along the zero set of `values` (one per vertex): every edge whose ends have
/// opposite signs is split at its linear zero. `None` when a split fails or the zero set
/// holds no loop.
pub(crate) fn split_at_zero(mesh: &Mesh, values: &[f64]) -> Option<Split> {
    let mut embedding = Embedding::new(mesh);
    let zero_set = level_set::split_zero_set(&mut embedding, values)
        .filter(|zero_set| !zero_set.loops.is_empty())?;
    Some(Split {
        mesh: embedding.mesh,
        split_edges: embedding.splits,
        zero_set,
    })
}

/// A mesh split along the whole surface swept by the view rays through a stroke drawn
/// across it: what [`CurveShape::CrossSection`] embeds, with every loop of the cut and the
/// side of every face, for cutting the shape in two.
pub(crate) struct Slice {
    /// The split mesh and the sides of its faces.
    pub split: Split,
    /// The stroke as it was cut with (simplified), in screen px.
    pub polyline: Vec<DVec2>,
}

/// Splits `mesh` along the surface swept by `stroke`, which must run from beside the shape
/// across it to beside it.
///
/// Errors: [`AddCurveError::DoesNotCross`] when it does not, or the cut holds no loop.
pub(crate) fn slice(
    mesh: &Mesh,
    camera: &Camera,
    viewport: DVec2,
    stroke: &[DVec2],
) -> Result<Slice, AddCurveError> {
    let projector = Projector {
        mesh,
        bvh: Bvh::new(mesh),
        camera,
        viewport,
    };
    let (_, polyline) = crossing(&projector, stroke)?;
    let distances = screen_distances(&projector, mesh, &polyline);
    let split = split_at_zero(mesh, &distances).ok_or(AddCurveError::DoesNotCross)?;
    Ok(Slice { split, polyline })
}

#[cfg(test)]
mod tests;

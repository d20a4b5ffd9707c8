//! Merging two shapes into one (FiberMesh's users asked for joining separately made parts;
//! the thesis has no such operation): two closed meshes that overlap become one closed
//! manifold along their intersection.
//!
//! Each mesh is split along a level set of its vertices' signed distances to the other
//! (negative inside it; the distance from the other's nearest point, the sign from a parity
//! ray), as a cut splits along its cutting surface, and its faces inside the other, or
//! within a gap of a fraction of an edge length of it, are removed. Each rim of the first is
//! zipped to the rim of the second that traces the same stretch of the intersection by a
//! strip (`rings.rs`), a narrow chamfer along the intersection that the caller remeshes and
//! re-optimizes into a blend.
//!
//! Why the gap: split exactly at the intersection, each rim is off the other surface by
//! the linear interpolation's error, to either side, and the parts' last rows of triangles
//! cross each other near the seam (put exactly on it, the rims' triangles touch the other
//! part's). A gap of a fraction of an edge keeps them apart, and costs a wedge along the
//! seam whose volume is of the order of the gap squared times the seam's length.
//!
//! Where real shapes meet (a scan and a turned copy of it, say), the surfaces graze in
//! places: one part pokes out of the other by less than the gap, or runs just under its
//! surface. Then a rim can lose its partner (its hole is closed with a fan) and a nub of a
//! part can be cut off on its own (it is dropped when tiny); and when a gap still leaves
//! crossing triangles, the next of [`SEAM_GAPS`] is tried, since grazing contacts change
//! with it.
//!
//! The result must be closed, manifold, connected and free of crossing triangles; anything
//! else is refused.

mod error;

pub use error::MergeError;

use glam::DVec3;

use super::add_curve::{Split, split_at_zero};
use super::rings::tube;
use crate::geometry::Bvh;
use crate::mesh::{FaceId, Mesh, Remap, TriSoup, VertexId};

/// Two shapes joined into one.
#[derive(Clone, Debug)]
pub struct Merged {
    /// The joined shape, with the seam's strip in place (the caller remeshes it).
    pub mesh: Mesh,
    /// Where the parts meet: the first part's rims, closed chains of `mesh` vertices.
    pub seams: Vec<Vec<VertexId>>,
    /// Whether each vertex of `mesh` lies on a rim of either part.
    pub is_seam: Vec<bool>,
    /// What happened to each part's vertices.
    pub parts: [PartMap; 2],
}

/// What a merge did to one part's vertices, for carrying its curves over.
#[derive(Clone, Debug)]
pub struct PartMap {
    /// Every edge of the part split along the intersection, in the numbering of the part
    /// with the split vertices appended.
    pub split_edges: Vec<(VertexId, VertexId, VertexId)>,
    /// Where each vertex of that numbering went in the merged mesh, `None` for removed ones.
    pub remap: Vec<Option<VertexId>>,
}

/// Joins the closed meshes `first` and `second` along their intersection. See the module
/// docs.
///
/// Errors: [`MergeError`], as sentences for the user.
pub fn merge(first: &Mesh, second: &Mesh) -> Result<Merged, MergeError> {
    if !first.is_closed() || !second.is_closed() {
        return Err(MergeError::NotClosed);
    }
    let edge = first.mean_edge_length().min(second.mean_edge_length());
    let mut result = Err(MergeError::Broken(None));
    for gap in SEAM_GAPS.map(|g| g * edge) {
        result = merge_with_gap(first, second, gap);
        if !matches!(result, Err(MergeError::Broken(_))) {
            break;
        }
    }
    result
}

/// [`merge`] with the parts cut back by `gap`.
fn merge_with_gap(first: &Mesh, second: &Mesh, gap: f64) -> Result<Merged, MergeError> {
    let split_first = split_outside(first, second, gap)?;
    let split_second = split_outside(second, first, gap)?;
    let (rims_first, rims_second) = (&split_first.zero_set.loops, &split_second.zero_set.loops);
    let tolerance = 2.0 * (first.mean_edge_length().max(second.mean_edge_length()) + gap);
    let pairs = paired(&split_first, &split_second, tolerance);
    let n_first = split_first.mesh.n_vertices();
    let mut soup = joined(&split_first, &split_second, &pairs);
    let kept_vertices = soup.remove_unreferenced_vertices();
    let mut mesh = Mesh::from_soup(&soup).map_err(|e| MergeError::Broken(Some(e)))?;
    let mut remap: Vec<Option<VertexId>> = kept_vertices.iter().map(|k| k.map(VertexId)).collect();
    let mapped = |v: &VertexId| remap[v.index()];
    let mut seams: Vec<Vec<VertexId>> = (pairs.iter())
        .map(|&(i, _)| rims_first[i].iter().filter_map(mapped).collect())
        .collect();
    let mut is_seam = vec![false; mesh.n_vertices()];
    let second_rims = (rims_second.iter().flatten()).map(|v| VertexId(v.0 + n_first as u32));
    for v in rims_first.iter().flatten().copied().chain(second_rims) {
        if let Some(w) = mapped(&v) {
            is_seam[w.index()] = true;
        }
    }
    close_unpaired_rims(&mut mesh, &mut is_seam);
    if let Some(kept) = without_stray_pieces(&mut mesh)? {
        follow(&kept, &mut remap, &mut seams, &mut is_seam);
    }
    check(&mesh, &is_seam)?;
    let parts = [
        PartMap {
            split_edges: split_first.split_edges,
            remap: remap[..n_first].to_vec(),
        },
        PartMap {
            split_edges: split_second.split_edges,
            remap: remap[n_first..].to_vec(),
        },
    ];
    Ok(Merged {
        mesh,
        seams,
        is_seam,
        parts,
    })
}

/// How far outside the other part (in edge lengths, of the finer part) each part is cut
/// back, in the order tried; see the module docs. Of forty random placements of Spot against
/// a turned copy of itself, 35 merge with these three.
pub const SEAM_GAPS: [f64; 3] = [0.3, 0.1, 0.6];

/// `mesh` split where its signed distance to `other` (negative inside it) is `gap`.
/// Distances are clamped to an edge length and the gap on either side of `other`'s surface,
/// which keeps the nearest-point searches short (one from deep inside visits much of the
/// surface) and changes no split: an edge that reaches the level `gap` has both ends nearer
/// than that. Vertices outside `other`'s bounding box by more than that are outside.
///
/// Errors: [`MergeError::NotTouching`] when no vertex lies inside `other`,
/// [`MergeError::Inside`] when every vertex does.
fn split_outside(mesh: &Mesh, other: &Mesh, gap: f64) -> Result<Split, MergeError> {
    let (lo, hi) = other.bounding_box().ok_or(MergeError::NotTouching)?;
    let bvh = Bvh::new(other);
    let reach = max_edge_length(mesh) + gap;
    let distances: Vec<f64> = (mesh.positions().iter())
        .map(|&p| {
            if (lo - p).max(p - hi).max_element() > reach {
                return reach;
            }
            let distance =
                (bvh.nearest_within(other, p, reach)).map_or(reach, |(q, _)| q.distance(p));
            if bvh.contains(other, p) {
                -distance
            } else {
                distance
            }
        })
        .collect();
    if distances.iter().all(|&d| d > 0.0) {
        return Err(MergeError::NotTouching);
    }
    if distances.iter().all(|&d| d <= 0.0) {
        return Err(MergeError::Inside);
    }
    let values: Vec<f64> = distances.iter().map(|d| d - gap).collect();
    split_at_zero(mesh, &values).ok_or(MergeError::Broken(None))
}

/// Both parts' outside faces in one soup (the second's vertices after the first's), with
/// a strip zipping each pair of rims.
fn joined(split_first: &Split, split_second: &Split, pairs: &[(usize, usize)]) -> TriSoup {
    let (rims_first, rims_second) = (&split_first.zero_set.loops, &split_second.zero_set.loops);
    let n_first = split_first.mesh.n_vertices();
    let mut positions = split_first.mesh.positions().to_vec();
    positions.extend_from_slice(split_second.mesh.positions());
    let mut triangles = outside_faces(split_first, 0);
    triangles.extend(outside_faces(split_second, n_first as u32));
    for &(i, j) in pairs {
        // Both rims run with their kept faces on the left; seen from the strip, the second
        // runs the other way round.
        let other: Vec<u32> = (rims_second[j].iter().rev())
            .map(|v| v.0 + n_first as u32)
            .collect();
        let rim: Vec<u32> = rims_first[i].iter().map(|v| v.0).collect();
        let ring = |vertices: &[u32]| {
            (vertices.iter())
                .map(|&v| positions[v as usize])
                .collect::<Vec<DVec3>>()
        };
        let (_, strip) = tube(&ring(&rim), &ring(&other), 0);
        let corner = |i: u32| match rim.get(i as usize) {
            Some(&v) => v,
            None => other[i as usize - rim.len()],
        };
        triangles.extend(strip.iter().map(|t| t.map(corner)));
    }
    TriSoup {
        positions,
        triangles,
    }
}

/// Carries the merge's vertex maps over a compaction that dropped stray pieces.
fn follow(
    kept: &Remap,
    remap: &mut [Option<VertexId>],
    seams: &mut Vec<Vec<VertexId>>,
    is_seam: &mut Vec<bool>,
) {
    let moved = |v: &VertexId| kept.vertex(*v);
    for v in remap.iter_mut() {
        *v = v.as_ref().and_then(moved);
    }
    for seam in seams.iter_mut() {
        *seam = seam.iter().filter_map(moved).collect();
    }
    seams.retain(|seam| !seam.is_empty());
    let mut kept_seam = vec![false; kept.vertices().iter().flatten().count()];
    for (v, &on_seam) in is_seam.iter().enumerate() {
        if let Some(w) = moved(&VertexId(v as u32)) {
            kept_seam[w.index()] = on_seam;
        }
    }
    *is_seam = kept_seam;
}

/// The faces of a split part outside the other, their corners shifted by `offset`.
fn outside_faces(split: &Split, offset: u32) -> Vec<[u32; 3]> {
    (split.mesh.triangles().iter())
        .zip(&split.zero_set.is_positive)
        .filter(|&(_, &outside)| outside)
        .map(|(t, _)| t.map(|v| v + offset))
        .collect()
}

/// The rims of the two parts that trace the same stretch of the intersection: pairs
/// `(first, second)` of rims each of whose points lies, on average, within `tolerance` of
/// the other, matched nearest first, each rim in one pair at most; in the first's order.
///
/// A rim can be left without a partner: where one part pokes out of the other by less than
/// the gap, that part's cap is cut away whole while the other part's rim remains (see
/// [`close_unpaired_rims`]).
fn paired(first: &Split, second: &Split, tolerance: f64) -> Vec<(usize, usize)> {
    let points = |split: &Split| -> Vec<Vec<DVec3>> {
        (split.zero_set.loops.iter())
            .map(|rim| rim.iter().map(|&v| split.mesh.position(v)).collect())
            .collect()
    };
    let (a, b) = (points(first), points(second));
    let mean_distance = |from: &[DVec3], to: &[DVec3]| {
        let nearest = |p: &DVec3| {
            to.iter()
                .map(|q| p.distance(*q))
                .fold(f64::INFINITY, f64::min)
        };
        from.iter().map(nearest).sum::<f64>() / from.len().max(1) as f64
    };
    let mut candidates: Vec<(f64, usize, usize)> = (0..a.len())
        .flat_map(|i| (0..b.len()).map(move |j| (i, j)))
        .map(|(i, j)| {
            (
                mean_distance(&a[i], &b[j]).max(mean_distance(&b[j], &a[i])),
                i,
                j,
            )
        })
        .filter(|&(distance, _, _)| distance < tolerance)
        .collect();
    candidates.sort_by(|x, y| x.0.total_cmp(&y.0));
    let (mut taken_a, mut taken_b) = (vec![false; a.len()], vec![false; b.len()]);
    let mut pairs = Vec::new();
    for (_, i, j) in candidates {
        if !taken_a[i] && !taken_b[j] {
            (taken_a[i], taken_b[j]) = (true, true);
            pairs.push((i, j));
        }
    }
    pairs.sort_unstable();
    pairs
}

/// Closes each hole left by a rim without a partner with a fan (the caller remeshes and
/// re-optimizes the band around the seams, the fan included). Such a hole is where the other
/// part's cap, thinner than the gap, was cut away, so the fan stands in for that cap.
fn close_unpaired_rims(mesh: &mut Mesh, is_seam: &mut Vec<bool>) {
    // A boundary vertex's own half-edge is its outgoing boundary half-edge.
    for rim in mesh.boundary_loops() {
        mesh.fill_boundary_loop(mesh.vertex_halfedge(rim[0]));
    }
    is_seam.resize(mesh.n_vertices(), true);
}

/// Drops what the join leaves beside the main shape: a cavity (where the parts enclose a
/// pocket that neither fills, the union's boundary has an inner component facing into it,
/// with a negative enclosed volume) and a crumb (a nub of one part that pokes out of the
/// other by little more than the gap, closed off on its own when the other part's thin cap
/// around it was cut away; under [`CRUMB_VOLUME`] of the main shape). Returns where the
/// vertices went, or `None` when the mesh is one piece.
///
/// Errors: [`MergeError::Broken`] when a second piece is too large to be either.
fn without_stray_pieces(mesh: &mut Mesh) -> Result<Option<Remap>, MergeError> {
    let (label, n_components) = mesh.face_components();
    if n_components < 2 {
        return Ok(None);
    }
    let mut volume = vec![0.0; n_components];
    for f in mesh.faces() {
        let [a, b, c] = mesh.face_positions(f);
        volume[label[f.index()] as usize] += a.dot(b.cross(c)) / 6.0;
    }
    let main = (0..n_components)
        .max_by(|&i, &j| volume[i].total_cmp(&volume[j]))
        .unwrap_or_default();
    let is_stray = |c: usize| c != main && volume[c] < CRUMB_VOLUME * volume[main];
    if (0..n_components).any(|c| c != main && !is_stray(c)) {
        return Err(MergeError::Broken(None));
    }
    let stray: Vec<FaceId> = (mesh.faces())
        .filter(|f| label[f.index()] as usize != main)
        .collect();
    mesh.delete_faces(&stray)
        .map_err(|e| MergeError::Broken(Some(e)))?;
    Ok(Some(mesh.compact()))
}

/// The largest volume, as a fraction of the main shape's, of a piece dropped as a crumb.
const CRUMB_VOLUME: f64 = 0.01;

/// Refuses a merged mesh that is not closed and connected, or has a triangle through
/// another near the seam. (Its genus follows from the parts' and how they meet: a ball
/// around a ring's tube meets it in two loops and leaves a genus-one shape.)
fn check(mesh: &Mesh, is_seam: &[bool]) -> Result<(), MergeError> {
    let near_seam = |f: FaceId| {
        mesh.face_vertices(f)
            .iter()
            .any(|v: &VertexId| is_seam[v.index()])
    };
    let crossing = !Bvh::new(mesh).crossing_faces(mesh, near_seam).is_empty();
    if !mesh.is_closed() || mesh.n_components() != 1 || crossing {
        return Err(MergeError::Broken(None));
    }
    Ok(())
}

/// The longest edge of `mesh`.
fn max_edge_length(mesh: &Mesh) -> f64 {
    (mesh.faces())
        .flat_map(|f| {
            let [a, b, c] = mesh.face_positions(f);
            [a.distance(b), b.distance(c), c.distance(a)]
        })
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests;

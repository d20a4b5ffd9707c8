//! Merging two shapes into one (FiberMesh's users asked for joining separately made parts;
//! the thesis has no such operation): two closed meshes that overlap become one closed
//! manifold along their intersection.
//!
//! Each mesh is split along a level set of its vertices' signed distances to the other
//! (negative inside it; the distance from the other's nearest point, the sign from a parity
//! ray), as a cut splits along its cutting surface, and its faces inside the other, or
//! within [`SEAM_GAP`] edge lengths of it, are removed. Each rim of the first is zipped to
//! the nearest rim of the second by a strip (`rings.rs`), a narrow chamfer along the
//! intersection that the caller remeshes and re-optimizes into a blend.
//!
//! Why the gap: split exactly at the intersection, each rim is off the other surface by
//! the linear interpolation's error, to either side, and the parts' last rows of triangles
//! cross each other near the seam (put exactly on it, the rims' triangles touch the other
//! part's). A gap of a fraction of an edge keeps them apart, and costs a wedge along the
//! seam whose volume is of the order of the gap squared times the seam's length.
//!
//! The result must be closed, manifold, connected and free of crossing triangles; anything
//! else is refused.

mod error;

pub use error::MergeError;

use glam::DVec3;

use super::add_curve::{Split, split_at_zero};
use super::opening::middle;
use super::rings::tube;
use crate::geometry::Bvh;
use crate::mesh::{FaceId, Mesh, TriSoup, VertexId};

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
    let gap = SEAM_GAP * first.mean_edge_length().min(second.mean_edge_length());
    let split_first = split_outside(first, second, gap)?;
    let split_second = split_outside(second, first, gap)?;
    let (rims_first, rims_second) = (&split_first.zero_set.loops, &split_second.zero_set.loops);
    let pairs = paired(&split_first, &split_second)?;
    let n_first = split_first.mesh.n_vertices();
    let mut positions = split_first.mesh.positions().to_vec();
    positions.extend_from_slice(split_second.mesh.positions());
    let mut triangles = outside_faces(&split_first, 0);
    triangles.extend(outside_faces(&split_second, n_first as u32));
    for (rim, other) in rims_first.iter().zip(&pairs) {
        // Both rims run with their kept faces on the left; seen from the strip, the second
        // runs the other way round.
        let other: Vec<u32> = (rims_second[*other].iter().rev())
            .map(|v| v.0 + n_first as u32)
            .collect();
        let rim: Vec<u32> = rim.iter().map(|v| v.0).collect();
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
    let mut soup = TriSoup {
        positions,
        triangles,
    };
    let kept_vertices = soup.remove_unreferenced_vertices();
    let mesh = Mesh::from_soup(&soup).map_err(|e| MergeError::Broken(Some(e)))?;
    let remap: Vec<Option<VertexId>> = kept_vertices.iter().map(|k| k.map(VertexId)).collect();
    let mapped = |v: &VertexId| remap[v.index()];
    let seams: Vec<Vec<VertexId>> = (rims_first.iter())
        .map(|rim| rim.iter().filter_map(mapped).collect())
        .collect();
    let mut is_seam = vec![false; mesh.n_vertices()];
    let second_rims = (rims_second.iter().flatten()).map(|v| VertexId(v.0 + n_first as u32));
    for v in rims_first.iter().flatten().copied().chain(second_rims) {
        if let Some(w) = mapped(&v) {
            is_seam[w.index()] = true;
        }
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
/// back; see the module docs.
pub const SEAM_GAP: f64 = 0.3;

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

/// The faces of a split part outside the other, their corners shifted by `offset`.
fn outside_faces(split: &Split, offset: u32) -> Vec<[u32; 3]> {
    (split.mesh.triangles().iter())
        .zip(&split.zero_set.is_positive)
        .filter(|&(_, &outside)| outside)
        .map(|(t, _)| t.map(|v| v + offset))
        .collect()
}

/// For each rim of the first part, the index of the rim of the second whose middle is
/// nearest to its middle; every rim of the second must be taken once.
///
/// Errors: [`MergeError::Broken`] when the rims do not pair up.
fn paired(first: &Split, second: &Split) -> Result<Vec<usize>, MergeError> {
    let middles = |split: &Split| -> Vec<DVec3> {
        (split.zero_set.loops.iter())
            .map(|rim| {
                let points: Vec<DVec3> = rim.iter().map(|&v| split.mesh.position(v)).collect();
                middle(&points)
            })
            .collect()
    };
    let (a, b) = (middles(first), middles(second));
    let pairs: Vec<usize> = (a.iter())
        .filter_map(|p| (0..b.len()).min_by(|&i, &j| p.distance(b[i]).total_cmp(&p.distance(b[j]))))
        .collect();
    let mut taken = vec![false; b.len()];
    for &j in &pairs {
        taken[j] = true;
    }
    if pairs.len() != a.len() || a.len() != b.len() || taken.contains(&false) {
        return Err(MergeError::Broken(None));
    }
    Ok(pairs)
}

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

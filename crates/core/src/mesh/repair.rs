//! Turning any triangle soup into an oriented manifold [`Mesh`], losing as little as possible.
//!
//! Real files hold repeated triangles, flipped triangles, fins (three or more triangles on
//! one edge) and bowties (fans touching at a vertex). Editing needs a manifold mesh, so:
//! 1. degenerate triangles (a repeated corner) and exact duplicates are dropped;
//! 2. triangles are oriented consistently by a breadth-first walk over edges shared by
//!    exactly two triangles; an edge that cannot agree (a Möbius band) or that has more than
//!    two triangles becomes a cut; each connected piece keeps the winding of most of its
//!    triangles, so correct files are never turned inside out;
//! 3. every vertex gets one copy per fan of triangles around it (cuts separate fans);
//! 4. whatever [`Mesh::from_soup`] still refuses (rare: a cut whose triangles stay in one fan
//!    at both ends) is fixed by detaching the named triangles, a bounded number of times.
//!
//! Only the mapping back to the soup is returned with the mesh, so callers can carry
//! per-corner data (UVs, colours) across.

use std::collections::{HashSet, VecDeque};

use super::build::for_each_edge;
use super::{FaceId, Mesh, MeshError, TriSoup, VertexId};

const NONE: u32 = u32::MAX;

/// How many times step 4 may detach triangles before giving up.
const MAX_DETACH_ROUNDS: usize = 200;

/// A manifold mesh made from a soup, with where each part came from.
#[derive(Clone, Debug)]
pub struct Repaired {
    /// The manifold mesh.
    pub mesh: Mesh,
    /// For each mesh vertex, the soup vertex whose position it has.
    pub vertex_source: Vec<VertexId>,
    /// For each mesh face, the soup triangle it came from and whether its winding was
    /// reversed (corners 1 and 2 swapped).
    pub face_source: Vec<(FaceId, bool)>,
    /// What was changed.
    pub report: RepairReport,
}

/// Counts of what [`make_manifold`] changed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RepairReport {
    /// Triangles dropped for repeating a corner.
    pub degenerate: usize,
    /// Triangles dropped for repeating another triangle's corners.
    pub duplicates: usize,
    /// Triangles whose winding was reversed to agree with their neighbours.
    pub flipped: usize,
    /// Vertex copies made to separate fans.
    pub split_vertices: usize,
    /// Triangles detached from their neighbours in the last step.
    pub detached: usize,
}

/// Makes an oriented manifold mesh of `soup` (see the module docs). Unused vertices are
/// dropped.
///
/// Errors: an index out of range or a non-finite position (nothing to repair there), or a soup
/// the bounded last step could not fix.
pub fn make_manifold(soup: &TriSoup) -> Result<Repaired, MeshError> {
    let mut report = RepairReport::default();
    let faces = clean_faces(soup, &mut report)?;
    let triangles: Vec<[u32; 3]> = faces.iter().map(|&f| soup.triangles[f as usize]).collect();
    let mut partner = pair_edges(&triangles);
    let flipped = orient(&triangles, &mut partner);
    report.flipped = flipped.iter().filter(|&&f| f).count();
    let (mut corner_vertex, mut vertex_source) =
        split_fans(&triangles, &partner, soup.positions.len());
    report.split_vertices = vertex_source.len() - soup.positions.len();
    for (f, &is_flipped) in flipped.iter().enumerate() {
        if is_flipped {
            corner_vertex.swap(3 * f + 1, 3 * f + 2);
        }
    }
    for _ in 0..MAX_DETACH_ROUNDS {
        let mut out = TriSoup {
            positions: vertex_source
                .iter()
                .map(|&v| soup.positions[v as usize])
                .collect(),
            triangles: corner_vertex
                .chunks_exact(3)
                .map(|c| [c[0], c[1], c[2]])
                .collect(),
        };
        let new_from_old = out.remove_unreferenced_vertices();
        let error = match Mesh::from_soup(&out) {
            Ok(mesh) => {
                let mut kept_source = vec![VertexId(0); mesh.n_vertices()];
                for (old, new) in new_from_old.iter().enumerate() {
                    if let Some(new) = new {
                        kept_source[*new as usize] = VertexId(vertex_source[old]);
                    }
                }
                return Ok(Repaired {
                    mesh,
                    vertex_source: kept_source,
                    face_source: faces.into_iter().map(FaceId).zip(flipped).collect(),
                    report,
                });
            }
            Err(error) => error,
        };
        let old_from_new: Vec<u32> = new_from_old
            .iter()
            .enumerate()
            .filter_map(|(old, new)| new.map(|_| old as u32))
            .collect();
        let named: Vec<u32> = match error {
            MeshError::NonManifoldEdge { a, b } | MeshError::InconsistentOrientation { a, b } => {
                vec![a, b]
            }
            MeshError::NonManifoldVertex { vertex } => vec![vertex],
            other => return Err(other),
        };
        let named: Vec<u32> = named.iter().map(|&v| old_from_new[v as usize]).collect();
        report.detached += detach(&mut corner_vertex, &mut vertex_source, &named);
    }
    Err(MeshError::InvalidConnectivity(String::from(
        "the triangles could not be made into a manifold surface",
    )))
}

/// Indices of the soup triangles to keep; checks indices and positions first.
fn clean_faces(soup: &TriSoup, report: &mut RepairReport) -> Result<Vec<u32>, MeshError> {
    let n = soup.positions.len();
    if let Some(vertex) = soup.positions.iter().position(|p| !p.is_finite()) {
        return Err(MeshError::NonFinitePosition {
            vertex: vertex as u32,
        });
    }
    let mut seen = HashSet::with_capacity(soup.triangles.len());
    let mut kept = Vec::with_capacity(soup.triangles.len());
    for (face, t) in soup.triangles.iter().enumerate() {
        if let Some(&index) = t.iter().find(|&&i| i as usize >= n) {
            return Err(MeshError::IndexOutOfRange {
                face: face as u32,
                index,
                n_vertices: n,
            });
        }
        if t[0] == t[1] || t[1] == t[2] || t[2] == t[0] {
            report.degenerate += 1;
            continue;
        }
        let mut key = *t;
        key.sort_unstable();
        if !seen.insert(key) {
            report.duplicates += 1;
            continue;
        }
        kept.push(face as u32);
    }
    Ok(kept)
}

/// For each corner (half-edge `3 f + k`, from corner `k` to `k + 1`), the other half-edge on
/// its edge when exactly two share the edge, else [`NONE`].
fn pair_edges(triangles: &[[u32; 3]]) -> Vec<u32> {
    let mut partner = vec![NONE; 3 * triangles.len()];
    for_each_edge(triangles, |group| {
        if let [g, h] = *group {
            partner[g as usize] = h;
            partner[h as usize] = g;
        }
    });
    partner
}

/// Decides which triangles to flip so that paired edges run opposite ways; pairs that cannot
/// agree are cut (set to [`NONE`]).
fn orient(triangles: &[[u32; 3]], partner: &mut [u32]) -> Vec<bool> {
    let corners = triangles.as_flattened();
    let tail = |h: usize| corners[h];
    let mut flip: Vec<Option<bool>> = vec![None; triangles.len()];
    let mut queue = VecDeque::new();
    for start in 0..triangles.len() {
        if flip[start].is_some() {
            continue;
        }
        flip[start] = Some(false);
        queue.push_back(start);
        let mut component = vec![start];
        while let Some(f) = queue.pop_front() {
            let flip_f = flip[f].unwrap_or(false);
            for h in 3 * f..3 * f + 3 {
                let g = partner[h];
                if g == NONE {
                    continue;
                }
                let other = g as usize / 3;
                // Half-edges starting at the same vertex run the same way.
                let same_direction = tail(h) == tail(g as usize);
                let wanted = flip_f ^ same_direction;
                match flip[other] {
                    None => {
                        flip[other] = Some(wanted);
                        component.push(other);
                        queue.push_back(other);
                    }
                    Some(actual) if actual != wanted => {
                        partner[h] = NONE;
                        partner[g as usize] = NONE;
                    }
                    Some(_) => {}
                }
            }
        }
        let n_flipped = component.iter().filter(|&&f| flip[f] == Some(true)).count();
        if 2 * n_flipped > component.len() {
            for &f in &component {
                flip[f] = flip[f].map(|x| !x);
            }
        }
    }
    flip.into_iter().map(|f| f.unwrap_or(false)).collect()
}

/// Gives every fan of corners around a vertex its own vertex. Returns the new vertex of each
/// corner and the soup vertex of each new vertex (the first fan keeps the original index).
fn split_fans(triangles: &[[u32; 3]], partner: &[u32], n_vertices: usize) -> (Vec<u32>, Vec<u32>) {
    let corners = triangles.as_flattened();
    let mut parent: Vec<u32> = (0..corners.len() as u32).collect();
    fn find(parent: &mut [u32], mut c: u32) -> u32 {
        while parent[c as usize] != c {
            parent[c as usize] = parent[parent[c as usize] as usize];
            c = parent[c as usize];
        }
        c
    }
    let corner_of = |face: usize, vertex: u32| {
        (3 * face..3 * face + 3)
            .find(|&c| corners[c] == vertex)
            .unwrap_or(3 * face) as u32
    };
    for h in 0..corners.len() {
        let g = partner[h] as usize;
        if partner[h] == NONE || g < h {
            continue;
        }
        let next = if h % 3 == 2 { h - 2 } else { h + 1 };
        for vertex in [corners[h], corners[next]] {
            let a = find(&mut parent, corner_of(h / 3, vertex));
            let b = find(&mut parent, corner_of(g / 3, vertex));
            parent[a.max(b) as usize] = a.min(b);
        }
    }
    // The root of a fan is its smallest corner; the first fan met keeps the soup vertex.
    let mut vertex_of_root = vec![NONE; corners.len()];
    let mut is_vertex_taken = vec![false; n_vertices];
    let mut vertex_source: Vec<u32> = (0..n_vertices as u32).collect();
    let mut corner_vertex = Vec::with_capacity(corners.len());
    for c in 0..corners.len() as u32 {
        let root = find(&mut parent, c) as usize;
        if vertex_of_root[root] == NONE {
            let v = corners[c as usize];
            vertex_of_root[root] = if std::mem::replace(&mut is_vertex_taken[v as usize], true) {
                vertex_source.push(v);
                (vertex_source.len() - 1) as u32
            } else {
                v
            };
        }
        corner_vertex.push(vertex_of_root[root]);
    }
    (corner_vertex, vertex_source)
}

/// Gives every face touching the named vertices, except the first, its own copies of them.
/// Returns how many faces were detached.
fn detach(corner_vertex: &mut [u32], vertex_source: &mut Vec<u32>, named: &[u32]) -> usize {
    let touches = |face: &[u32]| named.iter().filter(|v| face.contains(v)).count();
    // An edge names two vertices: faces holding both; a vertex: faces holding it.
    let needed = named.len();
    let faces: Vec<usize> = (0..corner_vertex.len() / 3)
        .filter(|&f| touches(&corner_vertex[3 * f..3 * f + 3]) == needed)
        .skip(1)
        .collect();
    let mut n_detached = 0;
    for f in faces {
        for c in &mut corner_vertex[3 * f..3 * f + 3] {
            if named.contains(c) {
                vertex_source.push(vertex_source[*c as usize]);
                *c = (vertex_source.len() - 1) as u32;
            }
        }
        n_detached += 1;
    }
    n_detached
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;
    use glam::DVec3;

    fn soup(positions: usize, triangles: &[[u32; 3]]) -> TriSoup {
        TriSoup {
            positions: (0..positions)
                .map(|i| DVec3::new(i as f64, (i * i) as f64, 0.0))
                .collect(),
            triangles: triangles.to_vec(),
        }
    }

    #[test]
    fn a_manifold_soup_comes_back_unchanged() {
        let sphere = primitives::icosphere(1.0, 2);
        let repaired = make_manifold(&sphere.to_soup()).unwrap();
        assert_eq!(repaired.mesh, sphere);
        assert_eq!(repaired.report, RepairReport::default());
        assert!(
            repaired
                .face_source
                .iter()
                .enumerate()
                .all(|(f, &(s, flipped))| s.index() == f && !flipped)
        );
    }

    #[test]
    fn flipped_triangles_are_turned_to_agree_with_most() {
        let sphere = primitives::icosphere(1.0, 1);
        let mut broken = sphere.to_soup();
        for t in broken.triangles.iter_mut().step_by(7) {
            t.swap(1, 2);
        }
        let repaired = make_manifold(&broken).unwrap();
        assert_eq!(repaired.mesh, sphere);
        assert_eq!(repaired.report.flipped, broken.triangles.len().div_ceil(7));
    }

    #[test]
    fn fins_bowties_and_duplicates_become_manifold() {
        // A fin: three triangles on edge 0-1. A bowtie at vertex 5. A duplicate and a
        // degenerate triangle.
        let broken = soup(
            9,
            &[
                [0, 1, 2],
                [1, 0, 3],
                [0, 1, 4],
                [5, 6, 7],
                [5, 8, 2],
                [6, 5, 7],
                [0, 0, 4],
                [1, 2, 0],
            ],
        );
        let repaired = make_manifold(&broken).unwrap();
        repaired.mesh.validate().unwrap();
        assert_eq!(repaired.report.degenerate, 1);
        assert_eq!(repaired.report.duplicates, 2);
        assert_eq!(repaired.mesh.n_faces(), 5);
        for (v, &source) in repaired.vertex_source.iter().enumerate() {
            assert_eq!(
                repaired.mesh.positions()[v],
                broken.positions[source.index()]
            );
        }
        for (f, &(source, flipped)) in repaired.face_source.iter().enumerate() {
            let mut original = broken.triangles[source.index()];
            if flipped {
                original.swap(1, 2);
            }
            let now = repaired.mesh.triangles()[f].map(|v| repaired.vertex_source[v as usize].0);
            assert_eq!(now, original);
        }
    }

    #[test]
    fn a_moebius_band_is_cut_open() {
        // A strip of 8 quads whose ends join with a half twist.
        let n = 8u32;
        let mut triangles = Vec::new();
        for i in 0..n {
            let (a, b) = (2 * i, 2 * i + 1);
            let (c, d) = if i + 1 == n {
                (1, 0)
            } else {
                (2 * i + 2, 2 * i + 3)
            };
            triangles.push([a, c, b]);
            triangles.push([b, c, d]);
        }
        let repaired = make_manifold(&soup(2 * n as usize, &triangles)).unwrap();
        repaired.mesh.validate().unwrap();
        assert_eq!(repaired.mesh.n_faces(), triangles.len());
    }

    #[test]
    fn bad_indices_are_errors() {
        assert!(matches!(
            make_manifold(&soup(3, &[[0, 1, 3]])),
            Err(MeshError::IndexOutOfRange { .. })
        ));
    }
}

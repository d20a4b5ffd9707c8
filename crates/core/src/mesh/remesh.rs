//! Explicit isotropic remeshing that keeps control curves as edge chains.
//!
//! FiberMesh remeshes after each sketch op and when a curve pull is released (Nealen's thesis
//! §3.3.3, "modified explicit remeshing \[SG03\]"), so that stretched regions get new vertices
//! and the later optimization sees well-shaped triangles. The method is Botsch & Kobbelt's
//! ("A remeshing approach to multiresolution modeling", SGP 2004): with a target edge length
//! `L`, each iteration
//! 1. splits edges longer than `4/3 L`, longest first (Rivara's longest-edge bisection, so the
//!    pass ends), until none is;
//! 2. collapses edges shorter than `4/5 L`, unless that would create an edge longer than
//!    `4/3 L`; these bounds are the ones for which a split never needs an undoing collapse;
//! 3. flips edges where that brings valences closer to 6 (4 on the boundary);
//! 4. relaxes: each free vertex moves to the uniform centroid of its one-ring, projected
//!    into its tangent plane (one Gauss–Seidel sweep; the next iteration continues it).
//!
//! Choices:
//! - The uniform centroid, not the area-weighted one: for a single target length it is the
//!   one that equalizes edge lengths (as B&K use it), and it is cheaper. Area weights pay off
//!   for adaptive sizing, which FiberMesh does not use.
//! - Moves happen within the tangent plane and are not projected back onto the input: the
//!   surface is re-optimized right after (`document::curve_edit::settle`), which moves every
//!   free vertex anyway. A relaxation move that would fold or degrade a triangle is skipped.
//! - Chain vertices are positional constraints of that optimization, so they never move; new
//!   chain vertices split chain edges on the input polyline (halfway along its arc, the edge
//!   midpoint unless a collapse made the edge a chord). Chain edges never flip. A chain
//!   vertex disappears only by collapsing along its own chain when it is an interior vertex
//!   of exactly one chain; chain ends and junctions stay, since other curves and the user's
//!   handles refer to them.
//! - Boundary vertices stay in place except for collapses along the boundary away from
//!   corners, so boundary loops keep their shape.
//! - Every edit is checked locally (link condition, valences of at least 3, no normal turning
//!   by more than 60°, no new sliver), so genus, components and boundary loops are unchanged.
//! - The work happens on a copy of the [`Mesh`] through its edits ([`crate::mesh::edit`]);
//!   collapses leave tombstones, which one [`Mesh::compact`] drops at the end.
//!
//! A current limitation: split and collapse keep the flat input surface (midpoints, kept
//! vertex positions); nothing smooths the new vertices into the curved shape but the
//! optimization that follows.

mod chains;
mod error;
mod passes;

pub use chains::Chain;
pub use error::RemeshError;

use super::Mesh;
use chains::ChainNetwork;
use passes::Remesher;

/// Above this many vertices expected at the target edge length, remeshing refuses, since
/// the result would not fit in memory or time.
const MAX_EXPECTED_VERTICES: f64 = 4_000_000.0;

/// How finely and how thoroughly to remesh.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RemeshParams {
    /// The edge length `L` to aim for.
    pub target_edge: f64,
    /// Split–collapse–flip–relax rounds; 3–5 settle a mesh at its own resolution.
    pub iterations: usize,
}

impl RemeshParams {
    /// Target = the mesh's mean edge length, a few (3–5) iterations.
    pub fn keep_resolution(mesh: &Mesh) -> RemeshParams {
        RemeshParams {
            target_edge: mesh.mean_edge_length(),
            iterations: 4,
        }
    }
}

/// The remeshed surface and its chains, in the order given, over the new vertex indices.
#[derive(Clone, Debug)]
pub struct Remeshed {
    /// The new mesh.
    pub mesh: Mesh,
    /// The input chains over the new mesh's vertices.
    pub chains: Vec<Chain>,
    /// Per new vertex, whether it lies in the region that was remeshed (see
    /// [`remesh_within`]): every vertex for [`remesh`].
    pub is_remeshed: Vec<bool>,
    /// Per new vertex, whether remeshing made it (by a split), rather than kept one of the
    /// input's vertices.
    pub is_new: Vec<bool>,
}

/// Remeshes `mesh` isotropically at `params.target_edge`, keeping every chain as an edge
/// chain (see the module docs for what moves and what stays).
///
/// # Errors
/// [`RemeshError::InvalidTargetEdge`] or [`RemeshError::TargetTooSmall`] for a bad target;
/// [`RemeshError::VertexOutOfRange`], [`RemeshError::NotAnEdgeChain`] or
/// [`RemeshError::ClosedChainTooShort`] for a chain that is not a chain of mesh edges;
/// [`RemeshError::InvalidResult`] if the result fails [`Mesh::validate`].
pub fn remesh(
    mesh: &Mesh,
    chains: &[Chain],
    params: &RemeshParams,
) -> Result<Remeshed, RemeshError> {
    remesh_within(mesh, chains, params, &vec![true; mesh.n_vertices()])
}

/// [`remesh`] restricted to the vertices with `region[v]`: only edges between them split,
/// collapse or flip, and only they relax, so every other vertex keeps its position and its
/// neighbours. For a local edit: the cost follows the region, and the rest of the surface
/// stays exactly as it was (the tangential moves of a remesh do not stay on the surface).
///
/// # Errors
/// Those of [`remesh`], and [`RemeshError::RegionMismatch`] when `region` does not have one
/// entry per vertex.
pub fn remesh_within(
    mesh: &Mesh,
    chains: &[Chain],
    params: &RemeshParams,
    region: &[bool],
) -> Result<Remeshed, RemeshError> {
    if region.len() != mesh.n_vertices() {
        return Err(RemeshError::RegionMismatch {
            expected: mesh.n_vertices(),
            found: region.len(),
        });
    }
    check_target(mesh, params.target_edge)?;
    check_chains(mesh, chains)?;
    let network = ChainNetwork::new(chains, mesh.positions());
    let mut remesher = Remesher::new(mesh.clone(), network, params.target_edge, region.to_vec());
    for _ in 0..params.iterations {
        remesher.iterate();
    }
    let remap = remesher.mesh.compact();
    let n_new = remesher.mesh.n_vertices();
    let (mut is_remeshed, mut is_new) = (vec![false; n_new], vec![false; n_new]);
    for (old, (&new, &edited)) in remap
        .vertices()
        .iter()
        .zip(&remesher.is_editable)
        .enumerate()
    {
        if let Some(new) = new {
            is_remeshed[new.index()] = edited;
            is_new[new.index()] = old >= mesh.n_vertices();
        }
    }
    remesher
        .mesh
        .validate()
        .map_err(RemeshError::InvalidResult)?;
    Ok(Remeshed {
        chains: remesher.chains.to_chains(&remap),
        mesh: remesher.mesh,
        is_remeshed,
        is_new,
    })
}

fn check_target(mesh: &Mesh, target_edge: f64) -> Result<(), RemeshError> {
    if !(target_edge.is_finite() && target_edge > 0.0) {
        return Err(RemeshError::InvalidTargetEdge);
    }
    let area: f64 = mesh
        .faces()
        .map(|f| {
            let [a, b, c] = mesh.face_positions(f);
            0.5 * (b - a).cross(c - a).length()
        })
        .sum();
    // An equilateral triangle of side L has area √3/4 L², and there are about two per vertex.
    let expected_vertices = area / (3f64.sqrt() / 4.0 * target_edge * target_edge) / 2.0;
    if expected_vertices > MAX_EXPECTED_VERTICES {
        return Err(RemeshError::TargetTooSmall {
            expected_vertices: expected_vertices as u64,
        });
    }
    Ok(())
}

fn check_chains(mesh: &Mesh, chains: &[Chain]) -> Result<(), RemeshError> {
    for (chain, c) in chains.iter().enumerate() {
        if let Some(&vertex) = c.vertices.iter().find(|&&v| v.index() >= mesh.n_vertices()) {
            return Err(RemeshError::VertexOutOfRange {
                chain,
                vertex: vertex.0,
            });
        }
        if c.closed && c.vertices.len() < 3 {
            return Err(RemeshError::ClosedChainTooShort { chain });
        }
        let closing = c
            .closed
            .then(|| (c.vertices[c.vertices.len() - 1], c.vertices[0]));
        let edges = c.vertices.windows(2).map(|w| (w[0], w[1])).chain(closing);
        for (a, b) in edges {
            if !mesh.vertex_neighbors(a).any(|w| w == b) {
                return Err(RemeshError::NotAnEdgeChain {
                    chain,
                    a: a.0,
                    b: b.0,
                });
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use glam::DVec3;
    use rustc_hash::FxHashMap;

    use super::*;
    use crate::mesh::{HalfedgeId, VertexId, fixtures, primitives};

    /// The closed edge loop between the faces whose centroids lie above the plane
    /// `normal · p = offset` and the others.
    fn plane_cut_loop(mesh: &Mesh, normal: DVec3, offset: f64) -> Chain {
        let is_above = |f: crate::mesh::FaceId| {
            let [a, b, c] = mesh.face_positions(f);
            normal.dot((a + b + c) / 3.0) > offset
        };
        let mut head_from_tail = FxHashMap::default();
        for h in (0..mesh.n_halfedges() as u32).map(HalfedgeId) {
            let t = mesh.twin(h).unwrap();
            if is_above(mesh.face(h)) && !is_above(mesh.face(t)) {
                let previous = head_from_tail.insert(mesh.tail(h), mesh.head(h));
                assert!(previous.is_none(), "the cut loop touches itself");
            }
        }
        let start = *head_from_tail.keys().min().unwrap();
        let mut vertices = vec![start];
        while let Some(&v) = head_from_tail.get(vertices.last().unwrap()) {
            if v == start {
                break;
            }
            vertices.push(v);
        }
        assert_eq!(
            vertices.len(),
            head_from_tail.len(),
            "the cut is not one loop"
        );
        Chain {
            vertices,
            closed: true,
        }
    }

    fn equator(mesh: &Mesh) -> Chain {
        plane_cut_loop(mesh, DVec3::new(0.01, 0.02, 1.0).normalize(), 0.003)
    }

    fn chain_edges(chain: &Chain) -> Vec<(VertexId, VertexId)> {
        let n = chain.vertices.len();
        let n_edges = if chain.closed { n } else { n.saturating_sub(1) };
        (0..n_edges)
            .map(|i| (chain.vertices[i], chain.vertices[(i + 1) % n]))
            .collect()
    }

    fn assert_edge_chain(mesh: &Mesh, chain: &Chain) {
        for (a, b) in chain_edges(chain) {
            assert!(mesh.find_edge(a, b).is_some(), "{a:?}-{b:?} is not an edge");
        }
    }

    fn distance_to_segment(p: DVec3, a: DVec3, b: DVec3) -> f64 {
        let ab = b - a;
        let t = ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0);
        p.distance(a + t * ab)
    }

    /// Every vertex of `chain` on `remeshed` lies on the polyline of `input` on `mesh`.
    fn assert_on_polyline(mesh: &Mesh, input: &Chain, remeshed: &Mesh, chain: &Chain) {
        let p = mesh.positions();
        for &v in &chain.vertices {
            let q = remeshed.positions()[v.index()];
            let distance = chain_edges(input)
                .iter()
                .map(|&(a, b)| distance_to_segment(q, p[a.index()], p[b.index()]))
                .fold(f64::INFINITY, f64::min);
            assert!(
                distance < 1e-9,
                "chain vertex {v:?} is {distance} off the curve"
            );
        }
    }

    fn edge_lengths(mesh: &Mesh) -> Vec<f64> {
        (0..mesh.n_halfedges() as u32)
            .map(HalfedgeId)
            .filter(|&h| mesh.twin(h).is_none_or(|t| h < t))
            .map(|h| {
                mesh.position(mesh.tail(h))
                    .distance(mesh.position(mesh.head(h)))
            })
            .collect()
    }

    fn assert_same_topology(before: &Mesh, after: &Mesh, name: &str) {
        assert_eq!(after.validate(), Ok(()), "{name}");
        assert_eq!(after.genus(), before.genus(), "{name}");
        assert_eq!(after.n_components(), before.n_components(), "{name}");
        assert_eq!(
            after.n_boundary_loops(),
            before.n_boundary_loops(),
            "{name}"
        );
        assert!(after.positions().iter().all(|p| p.is_finite()), "{name}");
    }

    #[test]
    fn sphere_with_equator_remeshes_isotropically_at_half_and_double_length() {
        let mesh = primitives::icosphere(1.0, 3);
        let chain = equator(&mesh);
        let mean = mesh.mean_edge_length();
        for scale in [0.5, 2.0] {
            let params = RemeshParams {
                target_edge: scale * mean,
                iterations: 5,
            };
            let out = remesh(&mesh, std::slice::from_ref(&chain), &params).unwrap();
            assert_same_topology(&mesh, &out.mesh, "icosphere");
            assert!(out.mesh.is_closed());
            let [new_chain] = &out.chains[..] else {
                panic!("one chain in, one out")
            };
            assert!(new_chain.closed && new_chain.vertices.len() >= 3);
            assert_edge_chain(&out.mesh, new_chain);
            assert_on_polyline(&mesh, &chain, &out.mesh, new_chain);

            let lengths = edge_lengths(&out.mesh);
            let l = params.target_edge;
            let n_good = lengths
                .iter()
                .filter(|&&e| (0.5 * l..=1.5 * l).contains(&e))
                .count();
            let good = n_good as f64 / lengths.len() as f64;
            let valences: Vec<usize> = out.mesh.vertices().map(|v| out.mesh.valence(v)).collect();
            let mean_valence = valences.iter().sum::<usize>() as f64 / valences.len() as f64;
            let regular = valences.iter().filter(|&&k| (5..=7).contains(&k)).count() as f64
                / valences.len() as f64;
            let expected_vertices = mesh.n_vertices() as f64 / (scale * scale);
            let vertex_ratio = out.mesh.n_vertices() as f64 / expected_vertices;
            assert!(
                good >= 0.9,
                "scale {scale}: only {good} of edges near the target"
            );
            assert!(
                (mean_valence - 6.0).abs() < 0.2,
                "scale {scale}: {mean_valence}"
            );
            assert!(
                regular >= 0.85,
                "scale {scale}: only {regular} of valences 5 to 7"
            );
            assert!(
                (0.6..1.6).contains(&vertex_ratio),
                "scale {scale}: {vertex_ratio}"
            );
        }
    }

    #[test]
    fn stretched_chain_is_split_to_the_target_length() {
        // Stretched 13 target lengths at 4 subdivisions: a split order other than longest
        // first cascades there.
        let mut mesh = primitives::icosphere(1.0, 4);
        let target_edge = mesh.mean_edge_length();
        let chain = equator(&mesh);
        for &v in &chain.vertices {
            let p = &mut mesh.positions_mut()[v.index()];
            if p.x > 0.0 {
                *p *= 1.5;
            }
        }
        let params = RemeshParams {
            target_edge,
            iterations: 4,
        };
        let out = remesh(&mesh, std::slice::from_ref(&chain), &params).unwrap();
        assert_same_topology(&mesh, &out.mesh, "stretched sphere");
        let new_chain = &out.chains[0];
        assert!(new_chain.vertices.len() > chain.vertices.len());
        assert_edge_chain(&out.mesh, new_chain);
        assert_on_polyline(&mesh, &chain, &out.mesh, new_chain);
        let p = out.mesh.positions();
        for (a, b) in chain_edges(new_chain) {
            let length = p[a.index()].distance(p[b.index()]);
            assert!(length <= 4.0 / 3.0 * target_edge, "chain edge of {length}");
        }
    }

    #[test]
    fn crossing_chains_keep_their_junction_and_ends() {
        let n = 12;
        let mesh = primitives::grid(n, n, 1.0);
        let index = |i: usize, j: usize| VertexId((i + j * (n + 1)) as u32);
        let row = Chain {
            vertices: (0..=n).map(|i| index(i, n / 2)).collect(),
            closed: false,
        };
        let column = Chain {
            vertices: (0..=n).map(|j| index(n / 2, j)).collect(),
            closed: false,
        };
        let chains = [row, column];
        let mean = mesh.mean_edge_length();
        for scale in [0.5, 1.0, 2.0] {
            let params = RemeshParams {
                target_edge: scale * mean,
                iterations: 4,
            };
            let out = remesh(&mesh, &chains, &params).unwrap();
            assert_same_topology(&mesh, &out.mesh, "grid");
            let p = |v: VertexId| out.mesh.position(v);
            let centre = mesh.positions()[index(n / 2, n / 2).index()];
            let at_centre = |c: &Chain| c.vertices.iter().filter(|&&v| p(v) == centre).count();
            for (input, chain) in chains.iter().zip(&out.chains) {
                assert!(!chain.closed);
                assert_edge_chain(&out.mesh, chain);
                assert_on_polyline(&mesh, input, &out.mesh, chain);
                assert_eq!(at_centre(chain), 1, "scale {scale}: junction lost");
                let ends =
                    [input.vertices[0], input.vertices[n]].map(|v| mesh.positions()[v.index()]);
                let new_ends = [chain.vertices[0], *chain.vertices.last().unwrap()].map(p);
                assert_eq!(ends, new_ends, "scale {scale}: an end moved");
            }
            let junction = |c: &Chain| *c.vertices.iter().find(|&&v| p(v) == centre).unwrap();
            assert_eq!(junction(&out.chains[0]), junction(&out.chains[1]));
        }
    }

    #[test]
    fn every_fixture_keeps_its_topology() {
        for fixture in fixtures::all() {
            let mean = fixture.mesh.mean_edge_length();
            for scale in [0.5, 1.0, 2.0] {
                let params = RemeshParams {
                    target_edge: scale * mean,
                    iterations: 4,
                };
                let out = remesh(&fixture.mesh, &[], &params).unwrap();
                let name = format!("{} at {scale}", fixture.name);
                assert_same_topology(&fixture.mesh, &out.mesh, &name);
                assert_eq!(out.mesh.is_closed(), fixture.is_closed, "{name}");
            }
        }
    }

    #[test]
    fn a_regional_remesh_changes_nothing_outside_its_region() {
        // A sphere with one side stretched, so that remeshing has work to do there.
        let mut mesh = primitives::icosphere(1.0, 3);
        for p in mesh.positions_mut() {
            if p.x > 0.0 {
                p.x *= 2.0;
            }
        }
        let region: Vec<bool> = mesh.positions().iter().map(|p| p.x > 0.3).collect();
        let params = RemeshParams::keep_resolution(&mesh);
        let out = remesh_within(&mesh, &[], &params, &region).unwrap();
        assert_same_topology(&mesh, &out.mesh, "stretched sphere");
        let kept: Vec<DVec3> = mesh
            .vertices()
            .filter(|v| !region[v.index()])
            .map(|v| mesh.position(v))
            .collect();
        let outside: Vec<DVec3> = out
            .mesh
            .vertices()
            .filter(|v| !out.is_remeshed[v.index()])
            .map(|v| out.mesh.position(v))
            .collect();
        assert_eq!(outside, kept, "a vertex outside the region moved or went");
        let n_inside = region.iter().filter(|&&r| r).count();
        let n_remeshed = out.is_remeshed.iter().filter(|&&r| r).count();
        assert!(
            n_remeshed > n_inside,
            "the stretched side got no new vertices"
        );
        // New vertices are all in the region, and every other one is an input vertex.
        let n_new = out.is_new.iter().filter(|&&r| r).count();
        assert!(n_new > 0);
        let is_inside_new = |(&new, &remeshed): (&bool, &bool)| !new || remeshed;
        assert!(out.is_new.iter().zip(&out.is_remeshed).all(is_inside_new));
        assert!(out.mesh.n_vertices() - n_new <= mesh.n_vertices());
        // Remeshing everything changes the outside too: the restriction is what kept it.
        let everywhere = remesh(&mesh, &[], &params).unwrap();
        assert_ne!(everywhere.mesh.n_vertices(), out.mesh.n_vertices());
        assert_eq!(
            remesh_within(&mesh, &[], &params, &region[1..]).unwrap_err(),
            RemeshError::RegionMismatch {
                expected: mesh.n_vertices(),
                found: mesh.n_vertices() - 1
            }
        );
    }

    #[test]
    fn open_grid_keeps_its_boundary() {
        let mesh = primitives::grid(10, 10, 1.0);
        let params = RemeshParams::keep_resolution(&mesh);
        let out = remesh(&mesh, &[], &params).unwrap();
        assert_same_topology(&mesh, &out.mesh, "grid");
        let (lo, hi) = out.mesh.bounding_box().unwrap();
        assert_eq!((lo, hi), mesh.bounding_box().unwrap());
        for v in out
            .mesh
            .vertices()
            .filter(|&v| out.mesh.is_boundary_vertex(v))
        {
            let q = out.mesh.position(v);
            let on_rim = (q.x.abs() - 0.5).abs() < 1e-12 || (q.y.abs() - 0.5).abs() < 1e-12;
            assert!(on_rim && q.z == 0.0, "boundary vertex left the rim: {q}");
        }
    }

    #[test]
    fn chains_that_are_not_edge_chains_are_refused() {
        let mesh = primitives::icosphere(1.0, 1);
        let params = RemeshParams::keep_resolution(&mesh);
        let far = (1..mesh.n_vertices() as u32)
            .map(VertexId)
            .find(|&v| mesh.find_edge(VertexId(0), v).is_none())
            .unwrap();
        let jump = Chain {
            vertices: vec![VertexId(0), far],
            closed: false,
        };
        assert_eq!(
            remesh(&mesh, &[jump], &params).unwrap_err(),
            RemeshError::NotAnEdgeChain {
                chain: 0,
                a: 0,
                b: far.0
            }
        );
        let missing = Chain {
            vertices: vec![VertexId(0), VertexId(1000)],
            closed: false,
        };
        assert!(matches!(
            remesh(&mesh, &[missing], &params),
            Err(RemeshError::VertexOutOfRange { vertex: 1000, .. })
        ));
        let short = Chain {
            vertices: vec![
                VertexId(0),
                mesh.vertex_neighbors(VertexId(0)).next().unwrap(),
            ],
            closed: true,
        };
        let error = remesh(&mesh, &[short], &params).unwrap_err();
        assert_eq!(error, RemeshError::ClosedChainTooShort { chain: 0 });
        assert!(
            error
                .to_string()
                .starts_with("The surface could not be remeshed: ")
        );
        let bad_target = RemeshParams {
            target_edge: 0.0,
            ..params
        };
        assert_eq!(
            remesh(&mesh, &[], &bad_target).unwrap_err(),
            RemeshError::InvalidTargetEdge
        );
    }
}

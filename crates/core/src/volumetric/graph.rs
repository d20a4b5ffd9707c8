//! The volumetric graph (Zhou et al. 2005, §3.2, Figs. 4–6): the mesh, its inner and outer
//! shells and a BCC lattice inside the inner shell, joined by edges that "simply connect
//! nearby points in the volume".
//!
//! Built in the paper's order: the shells (`shell.rs`), the lattice (`lattice.rs`), the
//! edges (each mesh vertex to its two shell copies, the shorter diagonal of each prism
//! face between a mesh edge and its shell copy, the shells' own edges, the lattice's body
//! diagonals, lattice to inner shell), then the edges shorter than half the mean edge
//! length collapsed to their midpoints (shortest first) and three smoothing passes that move
//! each point to its neighbours' mean; neither touches a mesh vertex. The graph's points
//! are the mesh's vertices first, in order, then the rest. Its edges never join two mesh
//! vertices: they are `G'` of Eq. 3, and the mesh's own edges are read from the mesh where
//! a path needs them.

use glam::DVec3;

use super::VolumetricError;
use super::lattice::bcc_lattice;
use super::shell::{Side, offset_shell};
use super::weights::WeightSolver;
use crate::geometry::{Bvh, enclosed_volume, vertex_normals};
use crate::mesh::{Mesh, VertexId, distances_within};

/// The most lattice nodes per mesh vertex, and in all (see [`lattice_spacing`]).
const LATTICE_PER_VERTEX: f64 = 4.0;
const MAX_LATTICE_NODES: f64 = 40_000.0;

/// The most mesh vertices a graph is built for. Nefertiti (49,971 vertices, 167k graph
/// points) takes 2.6 s to build and 3.1 s to factor natively, about four times that in the
/// page; Igea (134,345) would have 430k points. The paper deforms a simplified mesh and
/// adds the detail back for such models (multiresolution editing, not built yet).
pub const MAX_VERTICES: usize = 60_000;

/// Edges shorter than this share of the mean edge length are collapsed (the paper's half).
const COLLAPSE_SHARE: f64 = 0.5;
/// Smoothing passes over the points that are not mesh vertices (the paper's three).
const SMOOTHING_PASSES: usize = 3;

/// A closed mesh's volumetric graph with its Laplacian weights; see the module docs.
#[derive(Clone, Debug)]
pub struct VolumetricGraph {
    points: Vec<DVec3>,
    n_mesh: usize,
    /// Row `i`'s neighbours are `neighbours[offsets[i]..offsets[i + 1]]`.
    offsets: Vec<u32>,
    neighbours: Vec<u32>,
    /// The Laplacian weight of each neighbour entry: positive, summing to one per row.
    weights: Vec<f64>,
}

impl VolumetricGraph {
    /// The graph of `mesh`, which must be closed and oriented with its faces outward.
    ///
    /// Errors: [`VolumetricError::NotClosed`], [`VolumetricError::InsideOut`],
    /// [`VolumetricError::TooLarge`].
    pub fn build(mesh: &Mesh) -> Result<VolumetricGraph, VolumetricError> {
        if mesh.n_faces() == 0 || !mesh.is_closed() {
            return Err(VolumetricError::NotClosed);
        }
        if mesh.n_vertices() > MAX_VERTICES {
            return Err(VolumetricError::TooLarge {
                vertices: mesh.n_vertices(),
            });
        }
        if enclosed_volume(mesh).is_nan() || enclosed_volume(mesh) <= 0.0 {
            return Err(VolumetricError::InsideOut);
        }
        let spacing = mesh.mean_edge_length();
        let normals = vertex_normals(mesh);
        let bvh = Bvh::new(mesh);
        let inner = offset_shell(mesh, &bvh, &normals, spacing, Side::Inner);
        let outer = offset_shell(mesh, &bvh, &normals, spacing, Side::Outer);
        let lattice = bcc_lattice(&inner, &Bvh::new(&inner), lattice_spacing(mesh, spacing));

        let n = mesh.n_vertices() as u32;
        let (inner_at, outer_at, lattice_at) = (n, 2 * n, 3 * n);
        let mut points = mesh.positions().to_vec();
        points.extend_from_slice(inner.positions());
        points.extend_from_slice(outer.positions());
        points.extend_from_slice(&lattice.nodes);
        let mut edges = Vec::new();
        for v in 0..n {
            edges.extend([[v, inner_at + v], [v, outer_at + v]]);
        }
        for &[a, b, c] in mesh.triangles() {
            for (a, b) in [(a, b), (b, c), (c, a)].into_iter().filter(|(a, b)| a < b) {
                for shell in [inner_at, outer_at] {
                    edges.push([shell + a, shell + b]);
                    let (ab, ba) = ([a, shell + b], [b, shell + a]);
                    let length = |[p, q]: [u32; 2]| points[p as usize].distance(points[q as usize]);
                    edges.push(if length(ab) <= length(ba) { ab } else { ba });
                }
            }
        }
        edges.extend(
            lattice
                .edges
                .iter()
                .map(|[a, b]| [lattice_at + a, lattice_at + b]),
        );
        edges.extend(
            lattice
                .to_shell
                .iter()
                .map(|[node, v]| [lattice_at + node, inner_at + v]),
        );

        let (points, edges) = collapse_short_edges(points, edges, n, COLLAPSE_SHARE * spacing);
        let (offsets, neighbours) = adjacency(points.len(), &edges);
        let mut graph = VolumetricGraph {
            points,
            n_mesh: n as usize,
            offsets,
            neighbours,
            weights: Vec::new(),
        };
        graph.smooth();
        graph.weights = graph.laplacian_weights();
        Ok(graph)
    }

    /// All points: the mesh's vertices first, then the shells' and the lattice's.
    pub fn points(&self) -> &[DVec3] {
        &self.points
    }

    /// How many points there are.
    pub fn n_points(&self) -> usize {
        self.points.len()
    }

    /// How many of the points are the mesh's vertices (the first ones).
    pub fn n_mesh(&self) -> usize {
        self.n_mesh
    }

    /// Point `i`'s neighbours in `G'` (no mesh edge) and their Laplacian weights.
    pub fn row(&self, i: usize) -> impl ExactSizeIterator<Item = (usize, f64)> + '_ {
        let range = self.offsets[i] as usize..self.offsets[i + 1] as usize;
        self.neighbours[range.clone()]
            .iter()
            .zip(&self.weights[range])
            .map(|(&j, &w)| (j as usize, w))
    }

    /// The shortest-path distance from the nearest of `sources` to every point, over the
    /// graph and the mesh's edges (the paper's discrete geodesic distance).
    pub fn distances(&self, mesh: &Mesh, sources: &[u32]) -> Vec<f64> {
        distances_within(self.n_points(), sources, f64::INFINITY, |i| {
            self.edges_from(mesh, i)
        })
    }

    /// Point `i`'s neighbours over the graph and, for a mesh vertex, the mesh's edges, with
    /// the edges' lengths.
    pub(super) fn edges_from(
        &self,
        mesh: &Mesh,
        i: u32,
    ) -> impl Iterator<Item = (u32, f64)> + use<'_> {
        let p = self.points[i as usize];
        let range = self.offsets[i as usize] as usize..self.offsets[i as usize + 1] as usize;
        let on_mesh: Vec<u32> = if (i as usize) < self.n_mesh {
            mesh.vertex_neighbors(VertexId(i)).map(|v| v.0).collect()
        } else {
            Vec::new()
        };
        self.neighbours[range]
            .iter()
            .copied()
            .chain(on_mesh)
            .map(move |j| (j, p.distance(self.points[j as usize])))
    }

    /// The paper's smoothing: each point that is not a mesh vertex to its neighbours' mean.
    fn smooth(&mut self) {
        for _ in 0..SMOOTHING_PASSES {
            let next: Vec<DVec3> = (self.n_mesh..self.points.len())
                .map(|i| {
                    let range = self.offsets[i] as usize..self.offsets[i + 1] as usize;
                    let count = range.len();
                    if count == 0 {
                        return self.points[i];
                    }
                    let sum: DVec3 = self.neighbours[range]
                        .iter()
                        .map(|&j| self.points[j as usize])
                        .sum();
                    sum / count as f64
                })
                .collect();
            self.points[self.n_mesh..].copy_from_slice(&next);
        }
    }

    fn laplacian_weights(&self) -> Vec<f64> {
        let mut weights = Vec::with_capacity(self.neighbours.len());
        let max_k = self
            .offsets
            .windows(2)
            .map(|w| (w[1] - w[0]) as usize)
            .max();
        let mut solver = WeightSolver::new(max_k.unwrap_or(0));
        let mut around = Vec::new();
        for i in 0..self.points.len() {
            let range = self.offsets[i] as usize..self.offsets[i + 1] as usize;
            around.clear();
            around.extend(
                self.neighbours[range]
                    .iter()
                    .map(|&j| self.points[j as usize]),
            );
            solver.weights(self.points[i], &around, &mut weights);
        }
        weights
    }
}

/// The lattice's spacing: the mean edge length, as the paper sets it, unless that would put
/// more than [`LATTICE_PER_VERTEX`] nodes per mesh vertex, or [`MAX_LATTICE_NODES`] in all,
/// inside (a BCC lattice of spacing `s` has `2 V / s³` nodes in a volume `V`). The paper's
/// graphs have 1.6 to 2 points per vertex all told, on limbs a few edges thick; a finely
/// sampled thick body (a 134k-vertex scan) would otherwise fill with millions of nodes
/// (5.2 M for Igea, built in 20 s). Fewer nodes keep less volume: a quarter as many as the
/// mean edge length gives on the test capsule lets its half-turn bend lose 5.1% instead of
/// 4.4%.
fn lattice_spacing(mesh: &Mesh, edge: f64) -> f64 {
    let volume = enclosed_volume(mesh);
    let nodes = (LATTICE_PER_VERTEX * mesh.n_vertices() as f64).min(MAX_LATTICE_NODES);
    edge.max((2.0 * volume / nodes).cbrt())
}

/// The paper's simplification: edges between points that are not mesh vertices (index at
/// least `n_mesh`), shortest first, collapse to their midpoint while shorter than
/// `threshold`. Returns the surviving points, the mesh's first and in order, and the edges
/// between them, each once.
fn collapse_short_edges(
    mut points: Vec<DVec3>,
    edges: Vec<[u32; 2]>,
    n_mesh: u32,
    threshold: f64,
) -> (Vec<DVec3>, Vec<[u32; 2]>) {
    let mut parent: Vec<u32> = (0..points.len() as u32).collect();
    fn root(parent: &mut [u32], mut i: u32) -> u32 {
        while parent[i as usize] != i {
            parent[i as usize] = parent[parent[i as usize] as usize];
            i = parent[i as usize];
        }
        i
    }
    let length =
        |points: &[DVec3], [a, b]: [u32; 2]| points[a as usize].distance(points[b as usize]);
    let mut short: Vec<[u32; 2]> = edges
        .iter()
        .copied()
        .filter(|&[a, b]| a >= n_mesh && b >= n_mesh && length(&points, [a, b]) < threshold)
        .collect();
    short.sort_by(|&e, &f| length(&points, e).total_cmp(&length(&points, f)));
    for [a, b] in short {
        let (a, b) = (root(&mut parent, a), root(&mut parent, b));
        if a == b || length(&points, [a, b]) >= threshold {
            continue;
        }
        let (keep, gone) = (a.min(b), a.max(b));
        points[keep as usize] = 0.5 * (points[a as usize] + points[b as usize]);
        parent[gone as usize] = keep;
    }
    let mut index = vec![u32::MAX; points.len()];
    let mut kept = Vec::new();
    for i in 0..points.len() as u32 {
        if root(&mut parent, i) == i {
            index[i as usize] = kept.len() as u32;
            kept.push(points[i as usize]);
        }
    }
    let mut edges: Vec<[u32; 2]> = edges
        .into_iter()
        .map(|[a, b]| {
            let (a, b) = (root(&mut parent, a), root(&mut parent, b));
            let (a, b) = (index[a as usize], index[b as usize]);
            [a.min(b), a.max(b)]
        })
        .filter(|[a, b]| a != b)
        .collect();
    edges.sort_unstable();
    edges.dedup();
    (kept, edges)
}

/// Both directions of every edge, as rows: offsets and neighbour indices.
fn adjacency(n: usize, edges: &[[u32; 2]]) -> (Vec<u32>, Vec<u32>) {
    let mut degree = vec![0u32; n + 1];
    for &[a, b] in edges {
        degree[a as usize + 1] += 1;
        degree[b as usize + 1] += 1;
    }
    for i in 0..n {
        degree[i + 1] += degree[i];
    }
    let offsets = degree;
    let mut fill = offsets.clone();
    let mut neighbours = vec![0u32; edges.len() * 2];
    for &[a, b] in edges {
        neighbours[fill[a as usize] as usize] = b;
        fill[a as usize] += 1;
        neighbours[fill[b as usize] as usize] = a;
        fill[b as usize] += 1;
    }
    (offsets, neighbours)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;

    #[test]
    fn a_sphere_graph_fills_the_ball_and_keeps_the_mesh_first() {
        let sphere = primitives::icosphere(1.0, 3);
        let graph = VolumetricGraph::build(&sphere).unwrap();
        assert_eq!(graph.n_mesh(), sphere.n_vertices());
        assert_eq!(&graph.points()[..graph.n_mesh()], sphere.positions());
        // Points fill the ball: its centre is within a lattice spacing of one.
        let spacing = sphere.mean_edge_length();
        let nearest = graph
            .points()
            .iter()
            .map(|p| p.length())
            .fold(f64::INFINITY, f64::min);
        assert!(nearest < spacing, "nearest to the centre {nearest}");
        assert!(graph.n_points() > 3 * sphere.n_vertices());
        for i in 0..graph.n_points() {
            let row: Vec<_> = graph.row(i).collect();
            assert!(!row.is_empty(), "point {i} has no neighbour");
            let sum: f64 = row.iter().map(|(_, w)| w).sum();
            assert!((sum - 1.0).abs() < 1e-9 && row.iter().all(|(_, w)| *w > 0.0));
            if i < graph.n_mesh() {
                assert!(
                    row.iter().all(|&(j, _)| j >= graph.n_mesh()),
                    "a mesh edge in G'"
                );
            }
        }
        // After collapsing, no edge between two inner points is much shorter than half a spacing.
        let shortest = (graph.n_mesh()..graph.n_points())
            .flat_map(|i| graph.row(i).map(move |(j, _)| (i, j)))
            .filter(|&(_, j)| j >= graph.n_mesh())
            .map(|(i, j)| graph.points()[i].distance(graph.points()[j]))
            .fold(f64::INFINITY, f64::min);
        assert!(shortest > 0.05 * spacing, "shortest {shortest}");
    }

    #[test]
    fn open_and_inside_out_meshes_are_refused() {
        let grid = primitives::grid(4, 4, 1.0);
        assert_eq!(
            VolumetricGraph::build(&grid).unwrap_err(),
            VolumetricError::NotClosed
        );
        let sphere = primitives::icosphere(1.0, 2);
        let mut soup = sphere.to_soup();
        for t in &mut soup.triangles {
            t.swap(1, 2);
        }
        let flipped = Mesh::from_soup(&soup).unwrap();
        assert_eq!(
            VolumetricGraph::build(&flipped).unwrap_err(),
            VolumetricError::InsideOut
        );
    }
}

//! Pulling a control curve (FiberMesh deform tool, Nealen's thesis §3.2.2 and §3.3.1): one
//! point of the curve network is dragged, a *peeled* segment around it deforms while
//! keeping its detail, and every other curve point stays exactly.
//!
//! **Peeling.** The deformed segment is every node within a distance `r` of the grabbed
//! one along the curves (through junctions, so the peel crosses into connected curves),
//! with `r` proportional to how far the point has been pulled ([`PullParams`]): it grows
//! as the user pulls and shrinks back when they return. It never covers a whole connected
//! network: `r` stays below the distance to the farthest node, which keeps something to
//! deform against.
//!
//! **Deformation** (Eqs. 3.1–3.2). Each deformed node `i` has an explicit rotation `R_i`
//! (nearly collinear curve neighbours cannot determine rotations implicitly). The nodes
//! just outside the segment are the positional and rotational constraints (`R = I`), the
//! grabbed node the third positional one. Rotations are estimated with first-order
//! differentials, the edge vectors, because the second-order ones vanish on straight
//! curves: per iteration, with `r_i = I + [ω_i]×` linearized around the current `R_i`,
//!
//! `min Σ_E ‖v_i − v_j − ½(r_i R_i + r_j R_j) e_ij‖² + w² Σ_E ‖r_i R_i − r_j R_j‖²_F`
//!
//! over the positions and the `ω`, one sparse solve; then `R_i ← polar(r_i R_i)`. The polar
//! factor of `I + [ω]×` is the rotation by `atan ‖ω‖` about `ω`, so this is exact and
//! needs no SVD. The thesis shows three iterations (Fig. 3.9). The final positions solve
//! the second-order system `v_i − mean_j v_j = R_i δ_i` (uniform curve Laplacian, `δ` of
//! the rest curve), whose C¹ blend at the segment ends the edge-vector solve lacks; its
//! matrix depends only on the segment, so it is factored once per segment and a drag frame
//! that keeps the segment only back-substitutes.
//!
//! Each pull starts from the rest curve with `R = I`, so the result depends on the target
//! only, not on the drag path: a committed pull replays from its release point exactly.
//! With zero rotation iterations the deformation is the plain linear Laplacian one (`δ`
//! not rotated), kept for comparison.

mod error;

use glam::{DMat3, DVec3};
use rustc_hash::FxHashMap;

pub use error::PullError;

use super::measure::Rings;
use crate::mesh::{VertexId, distances_within};
use crate::solve::{Prefactored, Triplets};

/// How a pull peels and deforms.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PullParams {
    /// Radius of the peeled segment (along the curves) per unit of pull distance. The
    /// thesis gives no constant. 1.5 makes a pull of `d` a lobe `3d` wide at its base,
    /// local enough to shape one part of an outline (pull farther for a broader change);
    /// 2.5 bent a third of an ellipse's outline for a pull of a fifth of its width. The
    /// surface region a pull moves, and so its cost, grows with the square of this.
    pub peel_per_distance: f64,
    /// Smallest peel radius, in mean curve edge lengths.
    pub min_peel_edges: f64,
    /// Rotation-estimation iterations (the thesis shows three); zero deforms with the plain
    /// linear Laplacian.
    pub rotation_iterations: usize,
    /// Weight of rotation smoothness against the edge-vector rows (per unit of mean edge
    /// length, so that both terms have the same units).
    pub rotation_weight: f64,
}

impl Default for PullParams {
    fn default() -> Self {
        PullParams {
            peel_per_distance: 1.5,
            min_peel_edges: 3.0,
            rotation_iterations: 3,
            rotation_weight: 1.0,
        }
    }
}

/// The control curves of a model as one graph: every curve vertex once (curves that share
/// a vertex meet there), joined along the curves.
#[derive(Clone, Debug)]
pub struct CurveNetwork {
    /// The mesh vertex of each node.
    mesh_vertex: Vec<VertexId>,
    node_of: FxHashMap<VertexId, u32>,
    rest: Vec<DVec3>,
    adjacency: Rings,
    mean_edge: f64,
}

impl CurveNetwork {
    /// The network of `chains` (mesh vertex indices, and whether each is closed) on a mesh
    /// with `positions`.
    pub fn new(positions: &[DVec3], chains: &[(&[VertexId], bool)]) -> CurveNetwork {
        let mut mesh_vertex = Vec::new();
        let mut node_of = FxHashMap::default();
        let mut node = |v: VertexId| {
            *node_of.entry(v).or_insert_with(|| {
                mesh_vertex.push(v);
                mesh_vertex.len() as u32 - 1
            })
        };
        let mut edges = Vec::new();
        for &(chain, is_closed) in chains {
            let nodes: Vec<u32> = chain.iter().map(|&v| node(v)).collect();
            edges.extend(nodes.windows(2).map(|w| [w[0], w[1]]));
            if let (true, Some(&first), Some(&last)) = (is_closed, nodes.first(), nodes.last()) {
                edges.push([last, first]);
            }
        }
        edges.retain(|&[a, b]| a != b);
        let rest: Vec<DVec3> = mesh_vertex.iter().map(|&v| positions[v.index()]).collect();
        let total: f64 = edges
            .iter()
            .map(|&[a, b]| rest[a as usize].distance(rest[b as usize]))
            .sum();
        let mean_edge = if edges.is_empty() {
            1.0
        } else {
            total / edges.len() as f64
        };
        CurveNetwork {
            adjacency: Rings::from_edges(mesh_vertex.len(), edges),
            mesh_vertex,
            node_of,
            rest,
            mean_edge,
        }
    }

    /// The node at mesh vertex `v`, if a curve passes through it.
    pub fn node_of(&self, v: VertexId) -> Option<usize> {
        self.node_of.get(&v).map(|&k| k as usize)
    }

    /// Number of nodes.
    pub fn n_nodes(&self) -> usize {
        self.mesh_vertex.len()
    }

    /// The mesh vertex of `node`.
    pub fn mesh_vertex(&self, node: usize) -> VertexId {
        self.mesh_vertex[node]
    }

    /// The rest position of every node.
    pub fn rest(&self) -> &[DVec3] {
        &self.rest
    }

    /// The network neighbours of `node`.
    pub fn neighbours(&self, node: usize) -> &[u32] {
        self.adjacency.ring(node)
    }

    /// Distances along the curves from `node` to every node (infinite in other parts).
    fn distances_from(&self, node: usize) -> Vec<f64> {
        distances_within(self.n_nodes(), &[node as u32], f64::INFINITY, |i| {
            let p = self.rest[i as usize];
            self.adjacency
                .ring(i as usize)
                .iter()
                .map(move |&j| (j, p.distance(self.rest[j as usize])))
        })
    }
}

/// What a pull deformed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Peel {
    /// Radius of the peeled segment along the curves (world units).
    pub radius: f64,
    /// Number of nodes that moved (the grabbed one included).
    pub n_deformed: usize,
}

/// A pull of one node of a [`CurveNetwork`]: call [`CurvePull::pull_to`] for each target.
#[derive(Debug)]
pub struct CurvePull {
    network: CurveNetwork,
    grabbed: usize,
    params: PullParams,
    /// Distance along the curves from the grabbed node.
    distance: Vec<f64>,
    /// The largest radius that leaves a node outside the peel.
    max_radius: f64,
    /// The second-order system of the current segment, kept while the segment stays.
    placement: Option<Placement>,
}

impl CurvePull {
    /// Grabs `node` of `network`.
    pub fn new(network: CurveNetwork, node: usize, params: PullParams) -> CurvePull {
        let distance = network.distances_from(node);
        let farthest = distance
            .iter()
            .copied()
            .filter(|d| d.is_finite())
            .fold(0.0, f64::max);
        CurvePull {
            network,
            grabbed: node,
            params,
            distance,
            max_radius: farthest,
            placement: None,
        }
    }

    /// The network being pulled.
    pub fn network(&self) -> &CurveNetwork {
        &self.network
    }

    /// Deforms the network so that the grabbed node lands on `target`; writes every node's
    /// position into `nodes` (the rest position outside the peel).
    ///
    /// Errors: [`PullError::BadTarget`] for a non-finite target, [`PullError::WrongLength`]
    /// when `nodes` does not have one entry per node, and failed solves.
    pub fn pull_to(&mut self, target: DVec3, nodes: &mut [DVec3]) -> Result<Peel, PullError> {
        if !target.is_finite() {
            return Err(PullError::BadTarget);
        }
        let n = self.network.n_nodes();
        if nodes.len() != n {
            return Err(PullError::WrongLength {
                expected: n,
                found: nodes.len(),
            });
        }
        nodes.copy_from_slice(&self.network.rest);
        let pulled = target.distance(self.network.rest[self.grabbed]);
        let radius = (self.params.peel_per_distance * pulled)
            .max(self.params.min_peel_edges * self.network.mean_edge);
        // Strictly below the farthest node's distance, so one node at least stays.
        let radius = radius.min(self.max_radius * (1.0 - 1e-9));
        let segment = Segment::within(&self.network, &self.distance, radius, self.grabbed);
        if segment.n_free() <= 1 || pulled == 0.0 {
            nodes[self.grabbed] = target;
            return Ok(Peel {
                radius,
                n_deformed: 1,
            });
        }
        let rotations = self.estimate_rotations(&segment, target)?;

        if self
            .placement
            .as_ref()
            .is_none_or(|p| p.segment.nodes != segment.nodes)
        {
            self.placement = Some(Placement::new(&self.network, segment)?);
        }
        let placement = self.placement.as_mut().ok_or(PullError::BadTarget)?;
        placement.solve(&rotations, target, nodes)?;
        Ok(Peel {
            radius,
            n_deformed: placement.segment.n_free(),
        })
    }

    /// The rotations of the segment's nodes (local order), from `rotation_iterations`
    /// linearized edge-vector solves; identity on the frame.
    fn estimate_rotations(
        &self,
        segment: &Segment,
        target: DVec3,
    ) -> Result<Vec<DMat3>, PullError> {
        let m = segment.nodes.len();
        let mut rotations = vec![DMat3::IDENTITY; m];
        let rest = &self.network.rest;
        let w = self.params.rotation_weight * self.network.mean_edge;
        // Unknowns: positions (3 per node), then ω (3 per node).
        let mut fixed = vec![false; 6 * m];
        let mut fixed_values = vec![0.0; 6 * m];
        for k in 0..m {
            let is_frame = k >= segment.n_free();
            let is_handle = k == segment.handle;
            let p = if is_handle {
                target
            } else {
                rest[segment.nodes[k] as usize]
            };
            for c in 0..3 {
                fixed[3 * k + c] = is_frame || is_handle;
                fixed_values[3 * k + c] = p[c];
                fixed[3 * (m + k) + c] = is_frame;
            }
        }
        let edges = segment.edges(&self.network);
        for _ in 0..self.params.rotation_iterations {
            let mut triplets = Triplets::with_capacity(12 * edges.len(), 6 * m, 60 * edges.len());
            let mut rhs = Vec::with_capacity(12 * edges.len());
            for &(i, j) in &edges {
                let e = rest[segment.nodes[i] as usize] - rest[segment.nodes[j] as usize];
                let (a_i, a_j) = (rotations[i] * e, rotations[j] * e);
                let target_edge = 0.5 * (a_i + a_j);
                for c in 0..3 {
                    let row = rhs.len();
                    triplets.push(row, 3 * i + c, 1.0);
                    triplets.push(row, 3 * j + c, -1.0);
                    push_cross_row(&mut triplets, row, 3 * (m + i), a_i, c, 0.5);
                    push_cross_row(&mut triplets, row, 3 * (m + j), a_j, c, 0.5);
                    rhs.push(target_edge[c]);
                }
                for column in 0..3 {
                    let (r_i, r_j) = (rotations[i].col(column), rotations[j].col(column));
                    for c in 0..3 {
                        let row = rhs.len();
                        push_cross_row(&mut triplets, row, 3 * (m + i), r_i, c, -w);
                        push_cross_row(&mut triplets, row, 3 * (m + j), r_j, c, w);
                        rhs.push(w * (r_j[c] - r_i[c]));
                    }
                }
            }
            let mut solver = Prefactored::new(&triplets.build(), &fixed)?;
            let mut x = vec![0.0; 6 * m];
            solver.solve_scalar(&rhs, &fixed_values, &mut x)?;
            for (k, rotation) in rotations.iter_mut().enumerate().take(segment.n_free()) {
                let omega = DVec3::new(x[3 * (m + k)], x[3 * (m + k) + 1], x[3 * (m + k) + 2]);
                *rotation = polar_of_linearized(omega) * *rotation;
            }
        }
        Ok(rotations)
    }
}

/// Adds `scale · ([a]× ω)[c]` to `row`, with `ω` at columns `omega..omega + 3`.
fn push_cross_row(
    triplets: &mut Triplets,
    row: usize,
    omega: usize,
    a: DVec3,
    c: usize,
    scale: f64,
) {
    // [a]× = [[0, -a_z, a_y], [a_z, 0, -a_x], [-a_y, a_x, 0]].
    let entries = match c {
        0 => [(1, -a.z), (2, a.y)],
        1 => [(0, a.z), (2, -a.x)],
        _ => [(0, -a.y), (1, a.x)],
    };
    for (k, value) in entries {
        triplets.push(row, omega + k, scale * value);
    }
}

/// The polar (orthogonal) factor of `I + [ω]×`: the rotation by `atan ‖ω‖` about `ω`.
fn polar_of_linearized(omega: DVec3) -> DMat3 {
    let angle = omega.length();
    if angle < 1e-15 {
        return DMat3::IDENTITY;
    }
    DMat3::from_axis_angle(omega / angle, angle.atan())
}

/// The peeled nodes in a local order: the deformed ones first (the grabbed one among them),
/// then the frame that holds them: the nodes just outside, then their neighbours further
/// out. The inner frame ring has second-order rows too, which makes the segment meet the
/// rest of the curve without a kink; the outer ring completes those rows.
#[derive(Clone, Debug, PartialEq)]
struct Segment {
    /// Network node of each local node.
    nodes: Vec<u32>,
    /// Local index of the grabbed node.
    handle: usize,
    n_free: usize,
    /// Number of deformed and inner frame nodes.
    n_rows: usize,
}

impl Segment {
    /// The nodes closer than `radius` to `grabbed` (by `distance`) and their frame.
    fn within(network: &CurveNetwork, distance: &[f64], radius: f64, grabbed: usize) -> Segment {
        let mut nodes: Vec<u32> = (0..network.n_nodes() as u32)
            .filter(|&i| distance[i as usize] < radius)
            .collect();
        let n_free = nodes.len();
        let mut is_inside = vec![false; network.n_nodes()];
        for &i in &nodes {
            is_inside[i as usize] = true;
        }
        let mut ring = 0..n_free;
        for _ in 0..2 {
            let start = nodes.len();
            for k in ring {
                for &j in network.neighbours(nodes[k] as usize) {
                    if !is_inside[j as usize] {
                        is_inside[j as usize] = true;
                        nodes.push(j);
                    }
                }
            }
            ring = start..nodes.len();
        }
        let n_rows = ring.start;
        let handle = nodes
            .iter()
            .position(|&i| i as usize == grabbed)
            .unwrap_or(0);
        Segment {
            nodes,
            handle,
            n_free,
            n_rows,
        }
    }

    /// Number of deformed nodes, the grabbed one included.
    fn n_free(&self) -> usize {
        self.n_free
    }

    /// The network edges with a deformed end, in local indices.
    fn edges(&self, network: &CurveNetwork) -> Vec<(usize, usize)> {
        let local: FxHashMap<u32, usize> = self
            .nodes
            .iter()
            .enumerate()
            .map(|(k, &i)| (i, k))
            .collect();
        let mut edges = Vec::new();
        for k in 0..self.n_free {
            for &j in network.neighbours(self.nodes[k] as usize) {
                let l = local[&j];
                if l >= self.n_free || k < l {
                    edges.push((k, l));
                }
            }
        }
        edges
    }
}

/// The second-order system of one segment, factored: `v_i − mean_j v_j = R_i δ_i` for the
/// deformed nodes and the inner frame (where `R = I`), with the grabbed node and the frame
/// fixed.
#[derive(Debug)]
struct Placement {
    segment: Segment,
    solver: Prefactored,
    /// `δ_i` of the rest curve, per deformed and inner frame node.
    deltas: Vec<DVec3>,
    rhs: Vec<DVec3>,
    fixed_values: Vec<DVec3>,
    solved: Vec<DVec3>,
}

impl Placement {
    fn new(network: &CurveNetwork, segment: Segment) -> Result<Placement, PullError> {
        let m = segment.nodes.len();
        let local: FxHashMap<u32, usize> = segment
            .nodes
            .iter()
            .enumerate()
            .map(|(k, &i)| (i, k))
            .collect();
        let rest = network.rest();
        let n_rows = segment.n_rows;
        let mut triplets = Triplets::with_capacity(n_rows, m, 4 * n_rows);
        let mut deltas = Vec::with_capacity(n_rows);
        for k in 0..n_rows {
            let node = segment.nodes[k] as usize;
            let ring = network.neighbours(node);
            let weight = 1.0 / ring.len() as f64;
            triplets.push(k, k, 1.0);
            let mut mean = DVec3::ZERO;
            for &j in ring {
                triplets.push(k, local[&j], -weight);
                mean += weight * rest[j as usize];
            }
            deltas.push(rest[node] - mean);
        }
        let fixed: Vec<bool> = (0..m)
            .map(|k| k >= segment.n_free() || k == segment.handle)
            .collect();
        let solver = Prefactored::new(&triplets.build(), &fixed)?;
        Ok(Placement {
            fixed_values: segment.nodes.iter().map(|&i| rest[i as usize]).collect(),
            rhs: vec![DVec3::ZERO; n_rows],
            solved: vec![DVec3::ZERO; m],
            segment,
            solver,
            deltas,
        })
    }

    /// Places the deformed nodes for `rotations` (local order) and the grabbed node at
    /// `target`, into the network-wide `nodes`.
    fn solve(
        &mut self,
        rotations: &[DMat3],
        target: DVec3,
        nodes: &mut [DVec3],
    ) -> Result<(), PullError> {
        for (k, row) in self.rhs.iter_mut().enumerate() {
            *row = rotations[k] * self.deltas[k];
        }
        self.fixed_values[self.segment.handle] = target;
        self.solver
            .solve(&self.rhs, &self.fixed_values, &mut self.solved)?;
        for (k, &node) in self
            .segment
            .nodes
            .iter()
            .enumerate()
            .take(self.segment.n_free())
        {
            nodes[node as usize] = self.solved[k];
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A wavy open curve along x (one node every 0.1), waves of amplitude 0.05 in y.
    fn wavy(n: usize) -> Vec<DVec3> {
        (0..n)
            .map(|i| {
                let x = 0.1 * i as f64;
                DVec3::new(x, 0.05 * (x * 9.0).sin(), 0.0)
            })
            .collect()
    }

    fn network(points: &[DVec3]) -> CurveNetwork {
        let chain: Vec<VertexId> = (0..points.len() as u32).map(VertexId).collect();
        CurveNetwork::new(points, &[(&chain, false)])
    }

    #[test]
    fn the_grabbed_point_reaches_the_target_and_the_rest_stays() {
        let points = wavy(101);
        let mut pull = CurvePull::new(network(&points), 50, PullParams::default());
        let mut nodes = vec![DVec3::ZERO; points.len()];
        let target = points[50] + DVec3::new(0.0, 0.8, 0.3);
        let peel = pull.pull_to(target, &mut nodes).unwrap();
        assert!(nodes[50].distance(target) <= 1e-6 * target.length());
        let mut moved = 0;
        for (i, (p, q)) in points.iter().zip(&nodes).enumerate() {
            let along = (i as f64 - 50.0).abs() * 0.1;
            if p != q {
                moved += 1;
                assert!(along < peel.radius * 1.2, "node {i} moved outside the peel");
            }
        }
        assert_eq!(moved, peel.n_deformed);
        assert!(moved > 3 && moved < points.len() / 2);
    }

    #[test]
    fn the_peel_grows_with_the_pull_and_shrinks_back() {
        let points = wavy(201);
        let mut pull = CurvePull::new(network(&points), 100, PullParams::default());
        let mut nodes = vec![DVec3::ZERO; points.len()];
        let mut sizes = Vec::new();
        for step in [0.1, 0.3, 0.6, 1.0, 1.5] {
            let peel = pull
                .pull_to(points[100] + DVec3::Y * step, &mut nodes)
                .unwrap();
            sizes.push(peel.n_deformed);
        }
        assert!(sizes.windows(2).all(|w| w[0] <= w[1]), "{sizes:?}");
        assert!(sizes[4] > sizes[0]);
        let back = pull
            .pull_to(points[100] + DVec3::Y * 0.1, &mut nodes)
            .unwrap();
        assert_eq!(back.n_deformed, sizes[0]);
    }

    #[test]
    fn the_peel_crosses_junctions_into_connected_curves() {
        // A horizontal and a vertical line crossing at node (50, 50).
        let mut points = wavy(101);
        points.extend((0..101).map(|i| DVec3::new(5.0, 0.1 * i as f64 - 5.0, 0.0)));
        let horizontal: Vec<VertexId> = (0..101).map(VertexId).collect();
        let mut vertical: Vec<VertexId> = (101..202).map(VertexId).collect();
        vertical[50] = VertexId(50);
        let network = CurveNetwork::new(&points, &[(&horizontal, false), (&vertical, false)]);
        let mut pull = CurvePull::new(network, 50, PullParams::default());
        let mut nodes = vec![DVec3::ZERO; pull.network().n_nodes()];
        pull.pull_to(points[50] + DVec3::Z * 1.0, &mut nodes)
            .unwrap();
        let node = pull.network().node_of(VertexId(101 + 45)).unwrap();
        assert!(nodes[node].z > 0.1, "the crossing curve did not follow");
    }

    /// Signed turning angles of a polyline in the xy plane.
    fn turning(points: &[DVec3]) -> Vec<f64> {
        points
            .windows(3)
            .map(|w| {
                let (a, b) = ((w[1] - w[0]).truncate(), (w[2] - w[1]).truncate());
                a.angle_to(b)
            })
            .collect()
    }

    #[test]
    fn rotations_keep_the_detail_that_a_linear_laplacian_shears() {
        let points = wavy(121);
        let before = turning(&points);
        let error = |params: PullParams| {
            let mut pull = CurvePull::new(network(&points), 60, params);
            let mut nodes = vec![DVec3::ZERO; points.len()];
            pull.pull_to(points[60] + DVec3::Y * 2.0, &mut nodes)
                .unwrap();
            let after = turning(&nodes);
            // Away from the handle's immediate neighbourhood (5 nodes each side).
            before
                .iter()
                .zip(&after)
                .enumerate()
                .filter(|(k, _)| (*k as i64 + 1 - 60).abs() > 5)
                .map(|(_, (a, b))| (a - b).abs())
                .fold(0.0, f64::max)
        };
        // A broad peel, so that the bend spreads over several waves and their turning can
        // keep or lose their shape (with a short one the segment is mostly the handle's own
        // neighbourhood).
        let broad = PullParams {
            peel_per_distance: 2.5,
            ..PullParams::default()
        };
        let rotated = error(broad);
        let linear = error(PullParams {
            rotation_iterations: 0,
            ..broad
        });
        eprintln!("largest turning-angle change: rotations {rotated:.4}, linear {linear:.4} rad");
        assert!(rotated < TURNING_TOLERANCE, "{rotated}");
        assert!(
            linear > 1.5 * rotated,
            "linear {linear}, rotations {rotated}"
        );
    }

    /// Largest change of a turning angle (radians) outside the handle's neighbourhood when a
    /// wavy curve of 12 waves is pulled by its own length's sixth, peeled 2.5 per distance.
    const TURNING_TOLERANCE: f64 = 0.12;

    #[test]
    fn rotations_are_orthonormal_and_bad_targets_are_refused() {
        let omega = DVec3::new(0.3, -0.2, 0.5);
        let r = polar_of_linearized(omega);
        assert!((r.transpose() * r - DMat3::IDENTITY).abs_diff_eq(DMat3::ZERO, 1e-12));
        assert!((r.determinant() - 1.0).abs() < 1e-12);
        let points = wavy(20);
        let mut pull = CurvePull::new(network(&points), 10, PullParams::default());
        let mut nodes = vec![DVec3::ZERO; points.len()];
        assert_eq!(
            pull.pull_to(DVec3::NAN, &mut nodes),
            Err(PullError::BadTarget)
        );
        assert!(matches!(
            pull.pull_to(DVec3::ZERO, &mut nodes[1..]),
            Err(PullError::WrongLength { .. })
        ));
    }
}

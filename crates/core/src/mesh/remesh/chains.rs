//! The control curves during remeshing: each chain is a doubly linked list of nodes, one per
//! visit of a vertex, and each vertex lists its nodes (several at a junction).
//!
//! Nodes remember their arc length along the input polyline, so a split of a chain edge puts
//! the new vertex on the input curve halfway along the arc between its ends. Where no
//! collapse has shortcut the chain this is the edge midpoint; where one has, the edge is a
//! chord and its midpoint would leave the curve.

use glam::DVec3;

use crate::mesh::{INVALID, Remap, VertexId};

/// A chain of mesh vertices joined by mesh edges (a control curve); `closed` adds the edge last→first.
#[derive(Clone, Debug, PartialEq)]
pub struct Chain {
    /// The vertices in curve order.
    pub vertices: Vec<VertexId>,
    /// Whether the last vertex joins the first.
    pub closed: bool,
}

/// What a vertex is to the chains, which decides how it may move or disappear.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Role {
    /// On no chain.
    Free,
    /// Visited once by one chain and not its end: may be collapsed along the chain. Holds
    /// its node.
    Interior(u32),
    /// A chain end, a junction or a vertex a chain visits twice: never moves nor goes.
    Pinned,
}

#[derive(Clone, Debug)]
struct Node {
    vertex: u32,
    prev: u32,
    next: u32,
    chain: u32,
    /// Arc length from the chain's first input vertex along the input polyline.
    arc: f64,
    /// The next node at the same vertex, or [`INVALID`].
    next_at_vertex: u32,
}

/// One chain: its input polyline, for placing split vertices on it, and its current nodes.
#[derive(Clone, Debug)]
struct ChainState {
    points: Vec<DVec3>,
    /// Arc length at each point.
    arc: Vec<f64>,
    /// Total length, with the closing edge for a closed chain.
    length: f64,
    is_closed: bool,
    /// Some live node, the first one unless a collapse removed it.
    head: u32,
    n_nodes: usize,
}

impl ChainState {
    /// The point at arc length `s` along the input polyline.
    fn point_at(&self, s: f64) -> DVec3 {
        let i = self.arc.partition_point(|&a| a <= s).saturating_sub(1);
        if i + 1 == self.points.len() && !self.is_closed {
            return self.points[i];
        }
        let j = (i + 1) % self.points.len();
        let end = if j == 0 { self.length } else { self.arc[j] };
        let span = end - self.arc[i];
        let t = if span > 0.0 {
            ((s - self.arc[i]) / span).clamp(0.0, 1.0)
        } else {
            0.0
        };
        self.points[i].lerp(self.points[j], t)
    }
}

/// All chains, linked through their nodes; see the module docs.
#[derive(Clone, Debug)]
pub(super) struct ChainNetwork {
    nodes: Vec<Node>,
    /// First node at each vertex, or [`INVALID`].
    first_at_vertex: Vec<u32>,
    chains: Vec<ChainState>,
    /// Scratch for [`ChainNetwork::insert_split`].
    split_edges: Vec<(u32, u32)>,
}

impl ChainNetwork {
    /// Links the (already validated) chains over vertices with `positions`.
    pub(super) fn new(chains: &[Chain], positions: &[DVec3]) -> ChainNetwork {
        let mut network = ChainNetwork {
            nodes: Vec::new(),
            first_at_vertex: vec![INVALID; positions.len()],
            chains: Vec::with_capacity(chains.len()),
            split_edges: Vec::new(),
        };
        for (c, chain) in chains.iter().enumerate() {
            let points: Vec<DVec3> = chain
                .vertices
                .iter()
                .map(|&v| positions[v.index()])
                .collect();
            let mut arc = Vec::with_capacity(points.len());
            let mut length = 0.0;
            for (i, p) in points.iter().enumerate() {
                if i > 0 {
                    length += p.distance(points[i - 1]);
                }
                arc.push(length);
            }
            if chain.closed && points.len() > 1 {
                length += points[points.len() - 1].distance(points[0]);
            }
            let first = network.nodes.len() as u32;
            for (i, &v) in chain.vertices.iter().enumerate() {
                network.push_node(v.0, c as u32, arc[i]);
                if i > 0 {
                    network.link(first + i as u32 - 1, first + i as u32);
                }
            }
            if chain.closed && !points.is_empty() {
                network.link(network.nodes.len() as u32 - 1, first);
            }
            network.chains.push(ChainState {
                points,
                arc,
                length,
                is_closed: chain.closed,
                head: if chain.vertices.is_empty() {
                    INVALID
                } else {
                    first
                },
                n_nodes: chain.vertices.len(),
            });
        }
        network
    }

    fn push_node(&mut self, vertex: u32, chain: u32, arc: f64) -> u32 {
        let node = self.nodes.len() as u32;
        let v = vertex as usize;
        if v >= self.first_at_vertex.len() {
            self.first_at_vertex.resize(v + 1, INVALID);
        }
        self.nodes.push(Node {
            vertex,
            prev: INVALID,
            next: INVALID,
            chain,
            arc,
            next_at_vertex: self.first_at_vertex[v],
        });
        self.first_at_vertex[v] = node;
        node
    }

    fn link(&mut self, from: u32, to: u32) {
        self.nodes[from as usize].next = to;
        self.nodes[to as usize].prev = from;
    }

    /// The nodes at `v`.
    fn nodes_at(&self, v: u32) -> impl Iterator<Item = u32> + '_ {
        let first = self
            .first_at_vertex
            .get(v as usize)
            .copied()
            .unwrap_or(INVALID);
        std::iter::successors((first != INVALID).then_some(first), |&n| {
            let next = self.nodes[n as usize].next_at_vertex;
            (next != INVALID).then_some(next)
        })
    }

    fn vertex_of(&self, node: u32) -> u32 {
        self.nodes.get(node as usize).map_or(INVALID, |n| n.vertex)
    }

    pub(super) fn role(&self, v: u32) -> Role {
        let mut nodes = self.nodes_at(v);
        match (nodes.next(), nodes.next()) {
            (None, _) => Role::Free,
            (Some(n), None) => {
                let node = &self.nodes[n as usize];
                if node.prev != INVALID && node.next != INVALID {
                    Role::Interior(n)
                } else {
                    Role::Pinned
                }
            }
            (Some(_), Some(_)) => Role::Pinned,
        }
    }

    pub(super) fn is_on_chain(&self, v: u32) -> bool {
        self.role(v) != Role::Free
    }

    /// Every chain edge `a–b` as consecutive nodes `(from, to)` in chain order.
    fn chain_edges(&self, a: u32, b: u32) -> impl Iterator<Item = (u32, u32)> + '_ {
        self.nodes_at(a).flat_map(move |n| {
            let node = &self.nodes[n as usize];
            let forward = (self.vertex_of(node.next) == b).then_some((n, node.next));
            let backward = (self.vertex_of(node.prev) == b).then_some((node.prev, n));
            forward.into_iter().chain(backward)
        })
    }

    pub(super) fn is_chain_edge(&self, a: u32, b: u32) -> bool {
        self.chain_edges(a, b).next().is_some()
    }

    /// Arc length halfway from node `from` to the next node `to` of its chain.
    fn mid_arc(&self, from: u32, to: u32) -> f64 {
        let (from, to) = (&self.nodes[from as usize], &self.nodes[to as usize]);
        let length = self.chains[from.chain as usize].length;
        // Only the closing edge of a closed chain runs past the end of the arc.
        let end = if to.arc <= from.arc {
            to.arc + length
        } else {
            to.arc
        };
        let mid = 0.5 * (from.arc + end);
        if mid >= length { mid - length } else { mid }
    }

    /// Where a split of the edge `a–b` puts its vertex when the edge is on a chain.
    pub(super) fn split_point(&self, a: u32, b: u32) -> Option<DVec3> {
        let (from, to) = self.chain_edges(a, b).next()?;
        let chain = self.nodes[from as usize].chain as usize;
        Some(self.chains[chain].point_at(self.mid_arc(from, to)))
    }

    /// Inserts `m`, the vertex that split the edge `a–b`, into every chain along that edge.
    pub(super) fn insert_split(&mut self, a: u32, b: u32, m: u32) {
        let mut edges = std::mem::take(&mut self.split_edges);
        edges.clear();
        edges.extend(self.chain_edges(a, b));
        for &(from, to) in &edges {
            let chain = self.nodes[from as usize].chain;
            let node = self.push_node(m, chain, self.mid_arc(from, to));
            self.link(from, node);
            self.link(node, to);
            self.chains[chain as usize].n_nodes += 1;
        }
        self.split_edges = edges;
    }

    /// Whether the interior chain vertex at `node` may collapse onto vertex `k`: only along
    /// its chain, and never shrinking a closed chain below three vertices.
    pub(super) fn can_collapse_onto(&self, node: u32, k: u32) -> bool {
        let n = &self.nodes[node as usize];
        let chain_state = &self.chains[n.chain as usize];
        let is_along = self.vertex_of(n.prev) == k || self.vertex_of(n.next) == k;
        is_along && (!chain_state.is_closed || chain_state.n_nodes > 3)
    }

    /// Drops the interior chain vertex at `node`, which collapsed onto a chain neighbour.
    pub(super) fn remove(&mut self, node: u32) {
        let Node {
            vertex,
            prev,
            next,
            chain,
            ..
        } = self.nodes[node as usize];
        self.link(prev, next);
        self.first_at_vertex[vertex as usize] = INVALID;
        let chain_state = &mut self.chains[chain as usize];
        chain_state.n_nodes -= 1;
        if chain_state.head == node {
            chain_state.head = next;
        }
    }

    /// The chains over the compacted vertex ids of `remap` (a chain never keeps a vertex
    /// that a collapse removed).
    pub(super) fn to_chains(&self, remap: &Remap) -> Vec<Chain> {
        self.chains
            .iter()
            .map(|chain_state| {
                let mut vertices = Vec::with_capacity(chain_state.n_nodes);
                let mut n = chain_state.head;
                while n != INVALID && vertices.len() < chain_state.n_nodes {
                    let node = &self.nodes[n as usize];
                    vertices.extend(remap.vertex(VertexId(node.vertex)));
                    n = node.next;
                }
                Chain {
                    vertices,
                    closed: chain_state.is_closed,
                }
            })
            .collect()
    }
}

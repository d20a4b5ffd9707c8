//! Shortest edge paths between two vertices, for any edge cost; shortest-path distances from
//! a set of seeds over any graph.
//!
//! Dijkstra's algorithm with its distances in hash maps rather than arrays, so a short path
//! on a large mesh costs what it explores, not the mesh's size. Used to join the vertices of
//! an imported curve (cost: edge length) and to embed a sketch as the edge path under it
//! (cost: how far the edge's ends lie from the sketch on screen).

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use rustc_hash::FxHashMap;

use super::{Mesh, VertexId};

impl Mesh {
    /// The vertices of a cheapest edge path from `from` to `to`, both included, through
    /// vertices that `allowed` accepts (the ends need not be), where walking edge `(a, b)`
    /// costs `cost(a, b)` (finite, not negative); `None` when no such path exists.
    pub fn shortest_path(
        &self,
        from: VertexId,
        to: VertexId,
        allowed: impl Fn(VertexId) -> bool,
        cost: impl Fn(VertexId, VertexId) -> f64,
    ) -> Option<Vec<VertexId>> {
        let mut distance: FxHashMap<VertexId, f64> = FxHashMap::default();
        let mut previous: FxHashMap<VertexId, VertexId> = FxHashMap::default();
        // Costs are not negative, so their bit patterns order like the numbers.
        let mut queue = BinaryHeap::new();
        distance.insert(from, 0.0);
        queue.push(Reverse((0f64.to_bits(), from.0)));
        while let Some(Reverse((bits, v))) = queue.pop() {
            let (v, d) = (VertexId(v), f64::from_bits(bits));
            if v == to {
                let mut path = vec![to];
                while let Some(&p) = previous.get(path.last()?) {
                    path.push(p);
                }
                path.reverse();
                return Some(path);
            }
            if distance.get(&v).is_some_and(|&best| d > best) {
                continue;
            }
            for w in self.vertex_neighbors(v) {
                if w != to && !allowed(w) {
                    continue;
                }
                let dw = d + cost(v, w).max(0.0);
                if distance.get(&w).is_none_or(|&best| dw < best) {
                    distance.insert(w, dw);
                    previous.insert(w, v);
                    queue.push(Reverse((dw.to_bits(), w.0)));
                }
            }
        }
        None
    }
}

/// Shortest-path distances from `seeds` over a graph on `n` nodes whose edges from a node
/// `neighbours` lists with their lengths, up to `radius`; infinite beyond it.
pub(crate) fn distances_within<I: Iterator<Item = (u32, f64)>>(
    n: usize,
    seeds: &[u32],
    radius: f64,
    neighbours: impl Fn(u32) -> I,
) -> Vec<f64> {
    shortest_paths(n, seeds, radius, neighbours, |_, _| false).distance
}

/// What a Dijkstra pass reached: per node, its distance (infinite where not reached) and
/// the index in the seeds of the seed nearest to it (`u32::MAX` where not reached).
#[derive(Clone, Debug)]
pub(crate) struct Reached {
    pub distance: Vec<f64>,
    pub seed: Vec<u32>,
}

/// Dijkstra from `seeds` up to `radius`, calling `settled` with each node and its distance
/// as it becomes final, in increasing order, and stopping when it returns true (nodes
/// reached but not yet settled then keep tentative distances).
pub(crate) fn shortest_paths<I: Iterator<Item = (u32, f64)>>(
    n: usize,
    seeds: &[u32],
    radius: f64,
    neighbours: impl Fn(u32) -> I,
    mut settled: impl FnMut(u32, f64) -> bool,
) -> Reached {
    let mut distance = vec![f64::INFINITY; n];
    let mut seed = vec![u32::MAX; n];
    let mut queue = BinaryHeap::new();
    for (i, &s) in seeds.iter().enumerate().filter(|(_, s)| (**s as usize) < n) {
        if distance[s as usize] == 0.0 {
            continue;
        }
        distance[s as usize] = 0.0;
        seed[s as usize] = i as u32;
        queue.push(Reverse((Ordered(0.0), s)));
    }
    while let Some(Reverse((Ordered(d), v))) = queue.pop() {
        if d > distance[v as usize] {
            continue;
        }
        if settled(v, d) {
            break;
        }
        for (w, length) in neighbours(v) {
            let through = d + length;
            if through <= radius && through < distance[w as usize] {
                distance[w as usize] = through;
                seed[w as usize] = seed[v as usize];
                queue.push(Reverse((Ordered(through), w)));
            }
        }
    }
    Reached { distance, seed }
}

/// A finite distance with the total order the heap needs.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Ordered(f64);

impl Eq for Ordered {}

impl PartialOrd for Ordered {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Ordered {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.0.total_cmp(&other.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;

    #[test]
    fn the_path_follows_the_cost() {
        // A unit 6 x 6 grid split along its diagonals: by length, corner to corner is the
        // diagonal; allowing only the border makes it go round.
        let mesh = primitives::grid(6, 6, 1.0);
        let at = |i: u32, j: u32| VertexId(j * 7 + i);
        let length = |a: VertexId, b: VertexId| mesh.position(a).distance(mesh.position(b));
        let path = mesh
            .shortest_path(at(0, 0), at(6, 6), |_| true, length)
            .unwrap();
        assert_eq!((path[0], *path.last().unwrap()), (at(0, 0), at(6, 6)));
        for pair in path.windows(2) {
            assert!(mesh.vertex_neighbors(pair[0]).any(|w| w == pair[1]));
        }
        let total: f64 = path.windows(2).map(|p| length(p[0], p[1])).sum();
        assert_eq!(path.len(), 7);
        assert!((total - 2f64.sqrt()).abs() < 1e-12);
        // Only the bottom row and right column allowed: the path is that L, cutting its
        // corner along the one diagonal between them.
        let on_edge = |v: VertexId| v.0 / 7 == 0 || v.0 % 7 == 6;
        let round = mesh
            .shortest_path(at(0, 0), at(6, 6), on_edge, length)
            .unwrap();
        assert_eq!(round.len(), 12);
        assert!(round.iter().all(|&v| on_edge(v)));
        let total: f64 = round.windows(2).map(|p| length(p[0], p[1])).sum();
        assert!((total - (10.0 + 2f64.sqrt()) / 6.0).abs() < 1e-12);
        // Nothing allowed between two far vertices: no path.
        assert!(
            mesh.shortest_path(at(0, 0), at(6, 6), |_| false, length)
                .is_none()
        );
    }
}

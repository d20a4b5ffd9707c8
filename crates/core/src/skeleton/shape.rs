//! What a handle deforms, as it is: positions, and triangles when there are any (a soup:
//! non-manifold, non-orientable, in pieces, or none at all for a point cloud).
//!
//! Blanco's method needs no surface structure to deform, only to find the region under a
//! stroke (§3.1.2): it grows over shared vertices, and where the input is in pieces or has
//! no triangles it also joins points closer than [`Shape::reach`] (the thesis tests every
//! vertex of a multi-part mesh; joining by distance keeps its topological growth's point,
//! that a leg behind the stroked one is left out, wherever the parts are apart).

use std::collections::HashMap;

use glam::DVec3;

use crate::mesh::count_components;

/// Positions and (possibly no) triangles, borrowed.
#[derive(Clone, Copy, Debug)]
pub struct Shape<'a> {
    /// Every point.
    pub positions: &'a [DVec3],
    /// Triangles as indices into `positions`; empty for a point cloud.
    pub triangles: &'a [[u32; 3]],
}

/// Who is next to whom: the vertices sharing a triangle, as compressed rows.
#[derive(Clone, Debug, Default)]
pub struct Neighbours {
    offsets: Vec<u32>,
    list: Vec<u32>,
    /// Whether the triangles join every vertex into one piece.
    pub is_one_piece: bool,
}

impl Neighbours {
    /// The vertices sharing a triangle with `v`.
    pub fn of(&self, v: usize) -> &[u32] {
        match self.offsets.get(v..v + 2) {
            Some(&[from, to]) => &self.list[from as usize..to as usize],
            _ => &[],
        }
    }
}

impl Shape<'_> {
    /// The vertices sharing a triangle, in compressed rows (each pair once per triangle it
    /// shares, which growth does not mind).
    pub fn neighbours(&self) -> Neighbours {
        let n = self.positions.len();
        let mut counts = vec![0u32; n + 1];
        for t in self.triangles {
            for &i in t {
                counts[i as usize + 1] += 2;
            }
        }
        for i in 0..n {
            counts[i + 1] += counts[i];
        }
        let mut fill = counts.clone();
        let mut list = vec![0u32; counts[n] as usize];
        for t in self.triangles {
            for k in 0..3 {
                let (a, b, c) = (t[k], t[(k + 1) % 3], t[(k + 2) % 3]);
                let slot = &mut fill[a as usize];
                list[*slot as usize] = b;
                list[*slot as usize + 1] = c;
                *slot += 2;
            }
        }
        let mut neighbours = Neighbours {
            offsets: counts,
            list,
            is_one_piece: false,
        };
        neighbours.is_one_piece = count_components(n, self.triangles) == 1;
        neighbours
    }

    /// How far apart two points may be to count as next to each other when the shape is in
    /// pieces or has no triangles: twice the typical spacing (the mean edge length, or for
    /// a cloud the median distance to the nearest point of a sample).
    pub fn reach(&self) -> f64 {
        if !self.triangles.is_empty() {
            let total: f64 = self
                .triangles
                .iter()
                .map(|t| {
                    let p = t.map(|i| self.positions[i as usize]);
                    p[0].distance(p[1]) + p[1].distance(p[2]) + p[2].distance(p[0])
                })
                .sum();
            return 2.0 * total / (3 * self.triangles.len()) as f64;
        }
        2.0 * median_spacing(self.positions)
    }
}

/// The median distance to the nearest other point, over a sample of at most 512 points,
/// found in a grid whose cells hold a few points each.
fn median_spacing(points: &[DVec3]) -> f64 {
    if points.len() < 2 {
        return 0.0;
    }
    let (lo, hi) = points
        .iter()
        .fold((DVec3::MAX, DVec3::MIN), |(lo, hi), &p| {
            (lo.min(p), hi.max(p))
        });
    // Points on a surface: about n over the bounding box's largest face.
    let extent = hi - lo;
    let area = (extent.x * extent.y)
        .max(extent.y * extent.z)
        .max(extent.z * extent.x);
    let cell = (4.0 * area / points.len() as f64).sqrt().max(1e-12);
    let grid = PointGrid::new(points, cell, |_| true);
    let step = (points.len() / 512).max(1);
    let mut nearest: Vec<f64> = (0..points.len())
        .step_by(step)
        .filter_map(|i| grid.nearest_other(points, i))
        .collect();
    if nearest.is_empty() {
        return cell;
    }
    let middle = nearest.len() / 2;
    *nearest.select_nth_unstable_by(middle, f64::total_cmp).1
}

/// Points bucketed in cubic cells, to find those near a point.
pub struct PointGrid {
    cell: f64,
    cells: HashMap<[i64; 3], Vec<u32>>,
}

impl PointGrid {
    /// The points `keep` accepts, in cells of side `cell`.
    pub fn new(points: &[DVec3], cell: f64, keep: impl Fn(usize) -> bool) -> Self {
        let mut cells: HashMap<[i64; 3], Vec<u32>> = HashMap::new();
        for (i, &p) in points.iter().enumerate() {
            if keep(i) {
                cells.entry(cell_of(p, cell)).or_default().push(i as u32);
            }
        }
        PointGrid { cell, cells }
    }

    /// Calls `visit` with every point of the cells around `p` (within one cell).
    pub fn around(&self, p: DVec3, mut visit: impl FnMut(u32)) {
        let [x, y, z] = cell_of(p, self.cell);
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    if let Some(bucket) = self.cells.get(&[x + dx, y + dy, z + dz]) {
                        bucket.iter().copied().for_each(&mut visit);
                    }
                }
            }
        }
    }

    /// The distance from point `i` to the nearest other point within one cell of it.
    fn nearest_other(&self, points: &[DVec3], i: usize) -> Option<f64> {
        let mut best: Option<f64> = None;
        self.around(points[i], |j| {
            let d = points[i].distance(points[j as usize]);
            if j as usize != i && d > 0.0 && best.is_none_or(|b| d < b) {
                best = Some(d);
            }
        });
        best
    }
}

fn cell_of(p: DVec3, cell: f64) -> [i64; 3] {
    (p / cell).floor().as_i64vec3().to_array()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn neighbours_share_triangles_and_pieces_are_told_apart() {
        let positions: Vec<DVec3> = (0..6).map(|i| DVec3::splat(f64::from(i))).collect();
        let one = Shape {
            positions: &positions[..4],
            triangles: &[[0, 1, 2], [2, 1, 3]],
        };
        let neighbours = one.neighbours();
        assert!(neighbours.is_one_piece);
        let mut of_1 = neighbours.of(1).to_vec();
        of_1.sort_unstable();
        assert_eq!(of_1, vec![0, 2, 2, 3]);
        let two = Shape {
            positions: &positions,
            triangles: &[[0, 1, 2], [3, 4, 5]],
        };
        assert!(!two.neighbours().is_one_piece);
    }

    #[test]
    fn a_cloud_on_a_grid_reaches_twice_its_spacing() {
        let positions: Vec<DVec3> = (0..50)
            .flat_map(|i| {
                (0..50).map(move |j| DVec3::new(f64::from(i) * 0.1, f64::from(j) * 0.1, 0.0))
            })
            .collect();
        let cloud = Shape {
            positions: &positions,
            triangles: &[],
        };
        assert!((cloud.reach() - 0.2).abs() < 1e-9, "{}", cloud.reach());
    }
}

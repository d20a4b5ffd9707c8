//! A hash grid of points for finding the one within a small distance of a query.

use std::collections::HashMap;

use glam::DVec3;

/// Points bucketed by cells of side `cell`: a query looks in the 27 cells around it.
pub(super) struct PointGrid<'a> {
    points: &'a [DVec3],
    cell: f64,
    cells: HashMap<[i64; 3], Vec<u32>>,
}

impl<'a> PointGrid<'a> {
    /// Buckets `points`; queries then find points within `cell` of them.
    pub(super) fn new(points: &'a [DVec3], cell: f64) -> Self {
        let mut cells: HashMap<[i64; 3], Vec<u32>> = HashMap::with_capacity(points.len());
        for (index, &p) in points.iter().enumerate() {
            cells.entry(key(p, cell)).or_default().push(index as u32);
        }
        Self {
            points,
            cell,
            cells,
        }
    }

    /// The index of the point nearest `q` if it is within `tolerance` (at most the cell).
    pub(super) fn nearest_within(&self, q: DVec3, tolerance: f64) -> Option<u32> {
        let [x, y, z] = key(q, self.cell);
        let mut best: Option<(f64, u32)> = None;
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    let Some(bucket) = self.cells.get(&[x + dx, y + dy, z + dz]) else {
                        continue;
                    };
                    for &index in bucket {
                        let distance = self.points[index as usize].distance(q);
                        if distance <= tolerance && best.is_none_or(|(d, _)| distance < d) {
                            best = Some((distance, index));
                        }
                    }
                }
            }
        }
        best.map(|(_, index)| index)
    }
}

fn key(p: DVec3, cell: f64) -> [i64; 3] {
    (p / cell).floor().to_array().map(|c| c as i64)
}

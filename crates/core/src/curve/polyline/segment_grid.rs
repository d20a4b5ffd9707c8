//! Segments bucketed in a uniform grid, for nearest-distance and crossing queries.
//!
//! The grid keeps every query local, so checking an outline of `m` segments for
//! self-crossings ([`super::self_crossings`]) costs about `O(m)` instead of `O(m²)`, and a
//! clearance test of many points against an outline (FiberMesh's lattice) stays linear in
//! the number of points.

use glam::DVec2;

use super::{distance_to_segment, segment_crossing};

/// Segments bucketed in a uniform grid (compressed rows: `cell_start`, `items`).
pub(crate) struct SegmentGrid {
    segments: Vec<[DVec2; 2]>,
    origin: DVec2,
    cell: f64,
    nx: usize,
    ny: usize,
    cell_start: Vec<u32>,
    items: Vec<u32>,
}

impl SegmentGrid {
    /// Buckets the segments into cells of about `cell` (enlarged when that would make more
    /// than four cells per segment).
    pub(crate) fn new(segments: Vec<[DVec2; 2]>, cell: f64) -> SegmentGrid {
        let (lo, hi) = segments.iter().flatten().fold(
            (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
            |(lo, hi), &p| (lo.min(p), hi.max(p)),
        );
        let extent = (hi - lo).max(DVec2::splat(1e-12));
        let min_cell = (extent.x * extent.y / (4.0 * segments.len().max(1) as f64)).sqrt();
        let cell = cell.max(min_cell).max(1e-12);
        let nx = (extent.x / cell).floor() as usize + 1;
        let ny = (extent.y / cell).floor() as usize + 1;
        let mut grid = SegmentGrid {
            segments,
            origin: lo,
            cell,
            nx,
            ny,
            cell_start: vec![0; nx * ny + 1],
            items: Vec::new(),
        };
        // Two passes, count then fill, so the buckets live in one array.
        let ranges: Vec<[usize; 4]> = (0..grid.segments.len())
            .map(|s| grid.cell_range(s))
            .collect();
        for &[x0, y0, x1, y1] in &ranges {
            for y in y0..=y1 {
                for x in x0..=x1 {
                    grid.cell_start[y * nx + x + 1] += 1;
                }
            }
        }
        for k in 0..nx * ny {
            grid.cell_start[k + 1] += grid.cell_start[k];
        }
        let mut fill = grid.cell_start.clone();
        grid.items = vec![0; grid.cell_start[nx * ny] as usize];
        for (s, &[x0, y0, x1, y1]) in ranges.iter().enumerate() {
            for y in y0..=y1 {
                for x in x0..=x1 {
                    let k = y * nx + x;
                    grid.items[fill[k] as usize] = s as u32;
                    fill[k] += 1;
                }
            }
        }
        grid
    }

    /// The segments of a closed polygon, `i -> i + 1`.
    pub(crate) fn closed(points: &[DVec2], cell: f64) -> SegmentGrid {
        let n = points.len();
        SegmentGrid::new(
            (0..n).map(|i| [points[i], points[(i + 1) % n]]).collect(),
            cell,
        )
    }

    fn cell_of(&self, p: DVec2) -> (usize, usize) {
        let q = ((p - self.origin) / self.cell).floor();
        (
            (q.x.max(0.0) as usize).min(self.nx - 1),
            (q.y.max(0.0) as usize).min(self.ny - 1),
        )
    }

    /// The cells `[x0, y0, x1, y1]` (inclusive) the bounding box of segment `s` touches.
    fn cell_range(&self, s: usize) -> [usize; 4] {
        let [a, b] = self.segments[s];
        let (x0, y0) = self.cell_of(a.min(b));
        let (x1, y1) = self.cell_of(a.max(b));
        [x0, y0, x1, y1]
    }

    /// Calls `f` with every segment in a cell the box `lo..hi` touches (a segment may come
    /// more than once).
    fn for_each_near(&self, lo: DVec2, hi: DVec2, mut f: impl FnMut(usize)) {
        let (x0, y0) = self.cell_of(lo);
        let (x1, y1) = self.cell_of(hi);
        for y in y0..=y1 {
            for x in x0..=x1 {
                let k = y * self.nx + x;
                for &s in &self.items[self.cell_start[k] as usize..self.cell_start[k + 1] as usize]
                {
                    f(s as usize);
                }
            }
        }
    }

    /// Whether some segment lies closer than `radius` to `p`.
    pub(crate) fn is_within(&self, p: DVec2, radius: f64) -> bool {
        let mut found = false;
        self.for_each_near(p - radius, p + radius, |s| {
            let [a, b] = self.segments[s];
            found |= distance_to_segment(p, a, b) < radius;
        });
        found
    }

    /// Proper crossings between segments that are not neighbours in a chain, as sorted,
    /// unique pairs `(i, j)` with `i < j`. `is_closed` makes the first and last segments
    /// neighbours too.
    pub(crate) fn chain_crossings(&self, is_closed: bool) -> Vec<(usize, usize)> {
        let m = self.segments.len();
        let mut pairs = Vec::new();
        for i in 0..m {
            let [a0, a1] = self.segments[i];
            self.for_each_near(a0.min(a1), a0.max(a1), |j| {
                let is_neighbour = j <= i + 1 || (is_closed && i == 0 && j == m - 1);
                if !is_neighbour
                    && segment_crossing(a0, a1, self.segments[j][0], self.segments[j][1]).is_some()
                {
                    pairs.push((i, j));
                }
            });
        }
        pairs.sort_unstable();
        pairs.dedup();
        pairs
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crossings_do_not_depend_on_the_cell_size_and_distances() {
        let square =
            [(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)].map(|(x, y)| DVec2::new(x, y));
        // A bow tie: the edges 0 -> 1 and 2 -> 3 cross at (1, 1).
        let bow = vec![
            DVec2::new(0.0, 0.0),
            DVec2::new(2.0, 2.0),
            DVec2::new(2.0, 0.0),
            DVec2::new(0.0, 2.0),
        ];
        for cell in [0.3, 1.0, 5.0] {
            let grid = SegmentGrid::closed(&bow, cell);
            assert_eq!(grid.chain_crossings(true), vec![(0, 2)]);
        }
        let grid = SegmentGrid::closed(&square, 0.3);
        assert!(grid.chain_crossings(true).is_empty());
        assert!(grid.is_within(DVec2::new(1.0, 0.2), 0.25));
        assert!(!grid.is_within(DVec2::new(1.0, 1.0), 0.9));
    }
}

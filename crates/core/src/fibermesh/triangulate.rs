//! The planar mesh inside an outline: a regular triangular lattice, clipped with a
//! clearance from the outline, joined to the outline by a constrained Delaunay
//! triangulation (spade), then relaxed.
//!
//! Why lattice points plus CDT, rather than clipping the lattice and zipping its rim to the
//! outline as FiberMesh does (§3.3.3): the lattice keeps the interior exactly equilateral
//! with valence 6, which is where the uniform Laplacian of the fair-surface optimization is
//! a good mean-curvature estimator; the CDT handles the band along the outline, narrow necks
//! and concave corners without case analysis, and its Delaunay property maximises the
//! smallest angle there.
//!
//! Two fixes make the result usable for stitching front and back copies:
//! - a *chord*, an interior edge between two outline vertices, would be shared by four
//!   triangles after stitching (and pin the surface flat), so each chord gets its midpoint
//!   as a new interior vertex and the triangulation is rebuilt;
//! - [`RELAX_ROUNDS`] round(s) of Laplacian relaxation of the interior vertices (a vertex
//!   moves only if it stays clear of the outline), each followed by a new Delaunay
//!   triangulation, even out the band along the outline.

use glam::DVec2;
use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};

use super::CreateError;
use crate::curve::polyline::{SegmentGrid, centroid, contains};

/// Lattice points closer than this many spacings to the outline are dropped.
const CLEARANCE: f64 = 0.6;
/// Relaxed vertices must stay this many spacings away from the outline.
const MIN_RELAXED_CLEARANCE: f64 = 0.35;
/// Rounds of relaxation followed by re-triangulation (a second round changed the smallest
/// angles of the optimized meshes by under a degree and cost another triangulation).
const RELAX_ROUNDS: usize = 1;
/// Fraction of the step to the neighbours' centroid taken per round.
const RELAX_STEP: f64 = 0.6;
/// Chord splitting gives up after this many rounds.
const MAX_CHORD_ROUNDS: usize = 6;

/// A triangulated planar region: the outline's vertices first, in order, then the interior.
#[derive(Clone, Debug)]
pub(crate) struct PlanarMesh {
    /// Vertex positions in plane coordinates.
    pub points: Vec<DVec2>,
    /// The first `n_boundary` points are the outline.
    pub n_boundary: usize,
    /// Counter-clockwise triangles.
    pub triangles: Vec<[u32; 3]>,
}

/// Triangulates the inside of a simple closed outline sampled at about `spacing`.
///
/// Errors: [`CreateError::TooThin`] when the triangulation cannot be made free of chords
/// (or spade reports overlapping outline edges).
pub(crate) fn triangulate(outline: &[DVec2], spacing: f64) -> Result<PlanarMesh, CreateError> {
    let grid = SegmentGrid::closed(outline, spacing);
    let mut interior = lattice_points(outline, spacing, &grid);
    let mut triangles = triangulate_without_chords(outline, &mut interior)?;
    for _ in 0..RELAX_ROUNDS {
        relax(
            outline.len(),
            outline,
            &mut interior,
            &triangles,
            spacing,
            &grid,
        );
        triangles = triangulate_without_chords(outline, &mut interior)?;
    }
    let mut points = outline.to_vec();
    points.extend_from_slice(&interior);
    Ok(PlanarMesh {
        points,
        n_boundary: outline.len(),
        triangles,
    })
}

/// Points of the triangular lattice with the given spacing, centred on the outline's
/// centroid, inside the outline and at least [`CLEARANCE`] spacings away from it.
fn lattice_points(outline: &[DVec2], spacing: f64, grid: &SegmentGrid) -> Vec<DVec2> {
    let centre = centroid(outline);
    let (lo, hi) = outline
        .iter()
        .fold((centre, centre), |(lo, hi), &p| (lo.min(p), hi.max(p)));
    let row_step = spacing * 3f64.sqrt() / 2.0;
    let rows = ((lo.y - centre.y) / row_step).floor() as i64
        ..=((hi.y - centre.y) / row_step).ceil() as i64;
    let mut points = Vec::new();
    let mut xs = Vec::new();
    let n = outline.len();
    for row in rows {
        let y = centre.y + row as f64 * row_step;
        // Scanline: the outline's crossings with this row, paired into inside spans.
        xs.clear();
        for i in 0..n {
            let (a, b) = (outline[i], outline[(i + 1) % n]);
            if (a.y > y) != (b.y > y) {
                xs.push(a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x));
            }
        }
        xs.sort_by(f64::total_cmp);
        let shift = if row.rem_euclid(2) == 1 {
            0.5 * spacing
        } else {
            0.0
        };
        for span in xs.chunks_exact(2) {
            let first = ((span[0] - centre.x - shift) / spacing).ceil() as i64;
            let last = ((span[1] - centre.x - shift) / spacing).floor() as i64;
            for k in first..=last {
                let p = DVec2::new(centre.x + shift + k as f64 * spacing, y);
                if !grid.is_within(p, CLEARANCE * spacing) {
                    points.push(p);
                }
            }
        }
    }
    points
}

type Cdt = ConstrainedDelaunayTriangulation<Point2<f64>>;

/// Constrained Delaunay triangulation of the outline and interior points, keeping the
/// triangles inside; splits chords (inserting their midpoints as interior points, which
/// spade does incrementally) until there are none.
fn triangulate_without_chords(
    outline: &[DVec2],
    interior: &mut Vec<DVec2>,
) -> Result<Vec<[u32; 3]>, CreateError> {
    let n = outline.len();
    let vertices: Vec<Point2<f64>> = outline
        .iter()
        .chain(interior.iter())
        .map(|p| Point2::new(p.x, p.y))
        .collect();
    let n_vertices = vertices.len();
    let edges: Vec<[usize; 2]> = (0..n).map(|i| [i, (i + 1) % n]).collect();
    let mut has_conflict = false;
    let mut cdt = Cdt::try_bulk_load_cdt(vertices, edges, |_| has_conflict = true)
        .map_err(|_| CreateError::TooThin)?;
    if has_conflict || cdt.num_vertices() != n_vertices {
        return Err(CreateError::TooThin);
    }
    for _ in 0..MAX_CHORD_ROUNDS {
        let triangles = inside_triangles(&cdt, outline, interior);
        let mut chords: Vec<(u32, u32)> = Vec::new();
        for t in &triangles {
            for k in 0..3 {
                let (a, b) = (t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3]));
                let is_outline_edge = b - a == 1 || (a == 0 && b as usize == n - 1);
                if (b as usize) < n && !is_outline_edge {
                    chords.push((a, b));
                }
            }
        }
        if chords.is_empty() {
            return Ok(triangles);
        }
        chords.sort_unstable();
        chords.dedup();
        for (a, b) in chords {
            let midpoint = 0.5 * (outline[a as usize] + outline[b as usize]);
            let handle = cdt
                .insert(Point2::new(midpoint.x, midpoint.y))
                .map_err(|_| CreateError::TooThin)?;
            // A new vertex gets the next index; anything else means spade merged it.
            if handle.index() != n + interior.len() {
                return Err(CreateError::TooThin);
            }
            interior.push(midpoint);
        }
    }
    Err(CreateError::TooThin)
}

/// The CDT's triangles inside the outline, counter-clockwise, indexed outline first.
fn inside_triangles(cdt: &Cdt, outline: &[DVec2], interior: &[DVec2]) -> Vec<[u32; 3]> {
    let n = outline.len();
    let point = |i: u32| {
        if (i as usize) < n {
            outline[i as usize]
        } else {
            interior[i as usize - n]
        }
    };
    let mut triangles = Vec::with_capacity(cdt.num_inner_faces());
    for face in cdt.inner_faces() {
        let [a, b, c] = face.vertices().map(|v| v.fix().index() as u32);
        let is_inside = a.max(b).max(c) as usize >= n
            || contains(outline, (point(a) + point(b) + point(c)) / 3.0);
        if !is_inside {
            continue;
        }
        let is_ccw = (point(b) - point(a)).perp_dot(point(c) - point(a)) > 0.0;
        triangles.push(if is_ccw { [a, b, c] } else { [a, c, b] });
    }
    triangles
}

/// One Jacobi round of damped Laplacian relaxation of the interior points; a point moves
/// only if the move cannot cross the outline and ends clear of it.
fn relax(
    n: usize,
    outline: &[DVec2],
    interior: &mut [DVec2],
    triangles: &[[u32; 3]],
    spacing: f64,
    grid: &SegmentGrid,
) {
    let point = |i: usize, interior: &[DVec2]| if i < n { outline[i] } else { interior[i - n] };
    let mut sum = vec![DVec2::ZERO; interior.len()];
    let mut count = vec![0u32; interior.len()];
    for t in triangles {
        for k in 0..3 {
            let (i, j) = (t[k] as usize, t[(k + 1) % 3] as usize);
            // Every edge at an interior point lies in two triangles, so each neighbour is
            // counted twice: evenly.
            for (a, b) in [(i, j), (j, i)] {
                if a >= n {
                    sum[a - n] += point(b, interior);
                    count[a - n] += 1;
                }
            }
        }
    }
    let moved: Vec<DVec2> = interior
        .iter()
        .enumerate()
        .map(|(k, &p)| {
            if count[k] == 0 {
                return p;
            }
            let target = p + RELAX_STEP * (sum[k] / count[k] as f64 - p);
            let step = p.distance(target);
            let is_safe = !grid.is_within(p, step + 1e-12 * spacing)
                && !grid.is_within(target, MIN_RELAXED_CLEARANCE * spacing);
            if is_safe { target } else { p }
        })
        .collect();
    interior.copy_from_slice(&moved);
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::TAU;

    fn circle(n: usize, radius: f64) -> Vec<DVec2> {
        (0..n)
            .map(|k| radius * DVec2::from_angle(TAU * k as f64 / n as f64))
            .collect()
    }

    fn min_angle_deg(mesh: &PlanarMesh) -> f64 {
        let mut worst = 180.0f64;
        for t in &mesh.triangles {
            let p = t.map(|i| mesh.points[i as usize]);
            for k in 0..3 {
                let (a, b) = (p[(k + 1) % 3] - p[k], p[(k + 2) % 3] - p[k]);
                worst = worst.min(a.angle_to(b).abs().to_degrees());
            }
        }
        worst
    }

    #[test]
    fn a_disk_is_a_disk_of_good_triangles() {
        let outline = circle(64, 1.0);
        let spacing = TAU / 64.0;
        let mesh = triangulate(&outline, spacing).unwrap();
        assert_eq!(mesh.n_boundary, 64);
        // Euler characteristic of a disk: V - E + F = 1, with E = (3 F + boundary) / 2.
        let (v, f) = (mesh.points.len() as i64, mesh.triangles.len() as i64);
        assert_eq!(v - (3 * f + 64) / 2 + f, 1);
        // Every triangle is counter-clockwise and the areas add up to the polygon's.
        let area: f64 = mesh
            .triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| mesh.points[i as usize]);
                0.5 * (b - a).perp_dot(c - a)
            })
            .inspect(|&a| assert!(a > 0.0))
            .sum();
        assert!((area - crate::curve::polyline::signed_area(&outline)).abs() < 1e-9);
        assert!(min_angle_deg(&mesh) > 25.0, "{}", min_angle_deg(&mesh));
    }

    #[test]
    fn a_neck_thinner_than_the_spacing_gets_no_chords() {
        // A dumbbell whose waist is 0.4 spacings wide.
        let spacing = 0.1;
        let mut outline = Vec::new();
        let n = 160;
        for k in 0..n {
            let t = TAU * k as f64 / n as f64;
            let waist = 0.02 + 0.5 * (2.0 * t).sin().powi(2);
            outline.push(DVec2::new(1.5 * t.cos(), waist * t.sin()));
        }
        let outline = crate::curve::polyline::resample_closed(&outline, spacing);
        let mesh = triangulate(&outline, spacing).unwrap();
        let n = mesh.n_boundary as u32;
        for t in &mesh.triangles {
            assert!(
                t.iter().any(|&i| i >= n),
                "triangle {t:?} has only outline vertices"
            );
        }
    }
}

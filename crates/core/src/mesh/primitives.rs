//! Generated meshes: the closed-form fixtures the test suite runs on, and simple shapes for
//! the app.
//!
//! All are consistently oriented with outward (or +z) normals. Sizes whose closed forms the
//! tests use: an icosphere with `s` subdivisions has `10 * 4^s + 2` vertices and `20 * 4^s`
//! faces; a grid has `(nx + 1)(ny + 1)` vertices and `2 nx ny` faces; a torus has
//! `n_major * n_minor` vertices and twice as many faces; a capsule `n_around (n_profile - 1) + 2`
//! vertices.

use std::collections::HashMap;
use std::f64::consts::TAU;

use glam::DVec3;

use super::{Mesh, TriSoup};

/// Builds a mesh from a soup the generator knows is manifold.
fn mesh_from_valid_soup(soup: &TriSoup) -> Mesh {
    let result = Mesh::from_soup(soup);
    debug_assert!(
        result.is_ok(),
        "generated soup is not a manifold: {result:?}"
    );
    result.unwrap_or_default()
}

/// The 12 vertices and 20 faces of a regular icosahedron on the unit sphere.
fn icosahedron() -> TriSoup {
    let phi = (1.0 + 5f64.sqrt()) / 2.0;
    #[rustfmt::skip]
    let corners = [
        (-1.0, phi, 0.0), (1.0, phi, 0.0), (-1.0, -phi, 0.0), (1.0, -phi, 0.0),
        (0.0, -1.0, phi), (0.0, 1.0, phi), (0.0, -1.0, -phi), (0.0, 1.0, -phi),
        (phi, 0.0, -1.0), (phi, 0.0, 1.0), (-phi, 0.0, -1.0), (-phi, 0.0, 1.0),
    ];
    let positions = corners
        .iter()
        .map(|&(x, y, z)| DVec3::new(x, y, z).normalize())
        .collect();
    #[rustfmt::skip]
    let triangles = vec![
        [0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11],
        [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6], [7, 1, 8],
        [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9],
        [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1],
    ];
    TriSoup {
        positions,
        triangles,
    }
}

/// Splits every triangle of a unit-sphere soup into four and pushes the new vertices onto
/// the unit sphere.
fn subdivide_on_sphere(soup: &TriSoup) -> TriSoup {
    let mut positions = soup.positions.clone();
    let mut midpoint_of_edge: HashMap<(u32, u32), u32> = HashMap::new();
    let mut midpoint = |a: u32, b: u32| -> u32 {
        *midpoint_of_edge
            .entry((a.min(b), a.max(b)))
            .or_insert_with(|| {
                let p = (positions[a as usize] + positions[b as usize]).normalize();
                positions.push(p);
                positions.len() as u32 - 1
            })
    };
    let mut triangles = Vec::with_capacity(4 * soup.triangles.len());
    for &[a, b, c] in &soup.triangles {
        let (ab, bc, ca) = (midpoint(a, b), midpoint(b, c), midpoint(c, a));
        triangles.extend([[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
    }
    TriSoup {
        positions,
        triangles,
    }
}

/// A sphere of `radius` at the origin: an icosahedron split `subdivisions` times.
///
/// Its triangles are nearly equilateral, but valence-5 and valence-6 vertices differ, which
/// makes it a fair test of discrete curvature.
pub fn icosphere(radius: f64, subdivisions: u32) -> Mesh {
    let mut soup = icosahedron();
    for _ in 0..subdivisions {
        soup = subdivide_on_sphere(&soup);
    }
    soup.positions.iter_mut().for_each(|p| *p *= radius);
    mesh_from_valid_soup(&soup)
}

/// A flat open grid in the plane `z = 0`, centred on the origin, with `nx` by `ny` square
/// cells (each at least 1) spanning `size` along x and `size * ny / nx` along y.
///
/// Vertex `(i, j)` has index `i + j * (nx + 1)`. Each cell is split along the same diagonal,
/// so interior vertices have valence 6 and a symmetric one-ring (linear functions are
/// harmonic under the uniform Laplacian too).
pub fn grid(nx: usize, ny: usize, size: f64) -> Mesh {
    let (nx, ny) = (nx.max(1), ny.max(1));
    let cell = size / nx as f64;
    let origin = DVec3::new(-0.5 * size, -0.5 * cell * ny as f64, 0.0);
    let mut positions = Vec::with_capacity((nx + 1) * (ny + 1));
    for j in 0..=ny {
        for i in 0..=nx {
            positions.push(origin + DVec3::new(i as f64 * cell, j as f64 * cell, 0.0));
        }
    }
    let triangles = quads(nx, ny, |i, j| (i + j * (nx + 1)) as u32);
    mesh_from_valid_soup(&TriSoup {
        positions,
        triangles,
    })
}

/// Two triangles for each cell `(i, j)` of an `ni × nj` grid of quads, corners taken
/// counter-clockwise from `index(i, j)` through `index(i + 1, j)`; `index` names the grid
/// point's vertex (wrapping, for closed surfaces).
fn quads(ni: usize, nj: usize, index: impl Fn(usize, usize) -> u32) -> Vec<[u32; 3]> {
    let mut triangles = Vec::with_capacity(2 * ni * nj);
    for i in 0..ni {
        for j in 0..nj {
            let (a, b, c, d) = (
                index(i, j),
                index(i + 1, j),
                index(i + 1, j + 1),
                index(i, j + 1),
            );
            triangles.extend([[a, b, c], [a, c, d]]);
        }
    }
    triangles
}

/// A torus around the z axis: tube centre at distance `major`, tube radius `minor`, with
/// `n_major` segments around the axis and `n_minor` around the tube (each at least 3).
pub fn torus(major: f64, minor: f64, n_major: usize, n_minor: usize) -> Mesh {
    let (n_major, n_minor) = (n_major.max(3), n_minor.max(3));
    let mut positions = Vec::with_capacity(n_major * n_minor);
    for i in 0..n_major {
        let u = TAU * i as f64 / n_major as f64;
        for j in 0..n_minor {
            let v = TAU * j as f64 / n_minor as f64;
            let ring = major + minor * v.cos();
            positions.push(DVec3::new(ring * u.cos(), ring * u.sin(), minor * v.sin()));
        }
    }
    // d(position)/du x d(position)/dv points out of the tube, so the quads' order is outward.
    let triangles = quads(n_major, n_minor, |i, j| {
        ((i % n_major) * n_minor + j % n_minor) as u32
    });
    mesh_from_valid_soup(&TriSoup {
        positions,
        triangles,
    })
}

/// A torus about z with radii 1 and 0.4 ([`torus`]) carrying bumps of `height` along the
/// tube's normal, 24 around the axis and 8 around the tube (`max(0, cos 24u · cos 8v)²`):
/// surface detail for over-sketching and editing to keep, with an outline that wiggles.
pub fn bumpy_torus(height: f64, n_major: usize, n_minor: usize) -> Mesh {
    let mut mesh = torus(1.0, 0.4, n_major, n_minor);
    for p in mesh.positions_mut() {
        let u = p.y.atan2(p.x);
        let centre = DVec3::new(u.cos(), u.sin(), 0.0);
        let normal = (*p - centre).normalize();
        let v = normal.z.atan2(normal.truncate().dot(centre.truncate()));
        *p += normal * height * ((24.0 * u).cos() * (8.0 * v).cos()).max(0.0).powi(2);
    }
    mesh
}

/// A unit icosphere ([`icosphere`]) with a horn along +x: each vertex at angle `θ` from
/// the x axis is pushed out radially by `height · exp(-(θ / width)²)`. A thin part on a
/// thick body, as an ear on a head, for the part ROI of over-sketching (SEED).
pub fn horned_sphere(subdivisions: u32, height: f64, width: f64) -> Mesh {
    let mut mesh = icosphere(1.0, subdivisions);
    for p in mesh.positions_mut() {
        let angle = p.angle_between(DVec3::X);
        *p *= 1.0 + height * (-(angle / width).powi(2)).exp();
    }
    mesh
}

/// A capsule along x: a cylinder of `radius` from `x = -half_length` to `half_length`,
/// capped by hemispheres. A surface of revolution with `n_around` vertices per ring and
/// `n_profile` steps of equal arclength from pole to pole: `n_around (n_profile - 1) + 2`
/// vertices. Its silhouette seen from the side has straight parts and round ends, which a
/// sphere's has not.
pub fn capsule(radius: f64, half_length: f64, n_around: usize, n_profile: usize) -> Mesh {
    let (n_around, n_profile) = (n_around.max(3), n_profile.max(2));
    let quarter = 0.25 * TAU * radius;
    let total = 2.0 * quarter + 2.0 * half_length;
    let profile = |s: f64| -> (f64, f64) {
        if s < quarter {
            let angle = s / radius;
            (-half_length - radius * angle.cos(), radius * angle.sin())
        } else if s <= quarter + 2.0 * half_length {
            (-half_length + (s - quarter), radius)
        } else {
            let angle = (total - s) / radius;
            (half_length + radius * angle.cos(), radius * angle.sin())
        }
    };
    let mut positions = vec![DVec3::new(-half_length - radius, 0.0, 0.0)];
    for i in 1..n_profile {
        let (x, rho) = profile(total * i as f64 / n_profile as f64);
        for j in 0..n_around {
            let angle = TAU * j as f64 / n_around as f64;
            positions.push(DVec3::new(x, rho * angle.cos(), rho * angle.sin()));
        }
    }
    positions.push(DVec3::new(half_length + radius, 0.0, 0.0));
    let (first_pole, last_pole) = (0, positions.len() as u32 - 1);
    let ring = |i: usize, j: usize| (1 + i * n_around + j % n_around) as u32;
    let last_ring = n_profile - 2;
    let mut triangles = Vec::with_capacity(2 * n_around * n_profile);
    for j in 0..n_around {
        triangles.push([first_pole, ring(0, j + 1), ring(0, j)]);
        triangles.push([last_pole, ring(last_ring, j), ring(last_ring, j + 1)]);
        for i in 0..last_ring {
            let (a, b, c, d) = (
                ring(i, j),
                ring(i + 1, j),
                ring(i + 1, j + 1),
                ring(i, j + 1),
            );
            triangles.extend([[a, d, c], [a, c, b]]);
        }
    }
    mesh_from_valid_soup(&TriSoup {
        positions,
        triangles,
    })
}

/// An axis-aligned cube with side `size` centred on the origin: 8 vertices, 12 triangles.
///
/// Useful for sharp features and very coarse input; vertex `k` sits at `±size/2` per axis
/// according to bits 0 (x), 1 (y) and 2 (z) of `k`.
pub fn cube(size: f64) -> Mesh {
    let positions = (0..8)
        .map(|k: u32| {
            let bit = |axis: u32| if k >> axis & 1 == 1 { 0.5 } else { -0.5 };
            DVec3::new(bit(0), bit(1), bit(2)) * size
        })
        .collect();
    #[rustfmt::skip]
    let triangles = vec![
        [0, 2, 1], [1, 2, 3], // -z
        [4, 5, 7], [4, 7, 6], // +z
        [0, 1, 5], [0, 5, 4], // -y
        [2, 6, 7], [2, 7, 3], // +y
        [0, 4, 6], [0, 6, 2], // -x
        [1, 3, 7], [1, 7, 5], // +x
    ];
    mesh_from_valid_soup(&TriSoup {
        positions,
        triangles,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_match_closed_forms() {
        for s in 0..4u32 {
            let mesh = icosphere(1.0, s);
            assert_eq!(mesh.n_vertices(), 10 * 4usize.pow(s) + 2);
            assert_eq!(mesh.n_faces(), 20 * 4usize.pow(s));
        }
        let mesh = grid(5, 3, 1.0);
        assert_eq!((mesh.n_vertices(), mesh.n_faces()), (24, 30));
        let mesh = torus(2.0, 0.5, 10, 7);
        assert_eq!((mesh.n_vertices(), mesh.n_faces()), (70, 140));
        let mesh = cube(2.0);
        assert_eq!(
            (mesh.n_vertices(), mesh.n_edges(), mesh.n_faces()),
            (8, 18, 12)
        );
    }

    #[test]
    fn icosphere_vertices_lie_on_the_sphere() {
        let mesh = icosphere(2.5, 3);
        assert!(
            mesh.positions()
                .iter()
                .all(|p| (p.length() - 2.5).abs() < 1e-12)
        );
    }

    #[test]
    fn grid_spans_its_size_and_torus_its_radii() {
        let (lo, hi) = grid(4, 2, 2.0).bounding_box().unwrap();
        assert_eq!(
            (lo, hi),
            (DVec3::new(-1.0, -0.5, 0.0), DVec3::new(1.0, 0.5, 0.0))
        );
        let mesh = torus(3.0, 1.0, 24, 12);
        for p in mesh.positions() {
            let tube_centre = DVec3::new(p.x, p.y, 0.0).normalize() * 3.0;
            assert!(((*p - tube_centre).length() - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn capsule_is_closed_outward_and_round() {
        let mesh = capsule(0.5, 1.0, 32, 40);
        assert_eq!(mesh.validate(), Ok(()));
        assert!(mesh.is_closed());
        assert_eq!(mesh.n_vertices(), 32 * 39 + 2);
        let euler = mesh.n_vertices() + mesh.n_faces() - mesh.n_edges();
        assert_eq!(euler, 2);
        // Every vertex lies at the radius from the axis segment.
        for p in mesh.positions() {
            let on_axis = DVec3::new(p.x.clamp(-1.0, 1.0), 0.0, 0.0);
            assert!(((*p - on_axis).length() - 0.5).abs() < 1e-12, "{p}");
        }
        // Outward: the enclosed volume is positive and near the closed form.
        let volume = crate::geometry::enclosed_volume(&mesh);
        let exact = std::f64::consts::PI * 0.25 * 2.0 + 4.0 / 3.0 * std::f64::consts::PI * 0.125;
        assert!((volume - exact).abs() < 0.02 * exact, "{volume} vs {exact}");
    }

    #[test]
    fn degenerate_parameters_are_clamped() {
        assert_eq!(grid(0, 0, 1.0).n_faces(), 2);
        assert_eq!(torus(2.0, 1.0, 1, 2).n_faces(), 18);
        assert_eq!(torus(2.0, 1.0, 1, 2).validate(), Ok(()));
    }
}

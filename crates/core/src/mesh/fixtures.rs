//! A tagged corpus of small meshes for tests, after geometry-central's `MeshAssetSuite`.
//!
//! Every technique that changes a mesh should loop over a group here and call
//! [`Mesh::validate`](crate::mesh::Mesh::validate) on each result. The meshes are small
//! (at most a few hundred faces) so a loop over all of them stays fast in debug builds.

use glam::DVec3;

use super::{Mesh, TriSoup, primitives};

/// One test mesh with the topology it is known to have.
#[derive(Clone, Debug)]
pub struct Fixture {
    /// Short unique name, for assertion messages.
    pub name: &'static str,
    /// The mesh.
    pub mesh: Mesh,
    /// Whether it has no boundary.
    pub is_closed: bool,
    /// Total genus (see [`Mesh::genus`]).
    pub genus: u32,
}

fn fixture(name: &'static str, mesh: Mesh, is_closed: bool, genus: u32) -> Fixture {
    Fixture {
        name,
        mesh,
        is_closed,
        genus,
    }
}

/// Builds a fixture mesh from a soup known to be manifold.
fn from_soup(soup: TriSoup) -> Mesh {
    let result = Mesh::from_soup(&soup);
    debug_assert!(result.is_ok(), "fixture soup is not a manifold: {result:?}");
    result.unwrap_or_default()
}

/// Removes the listed faces (and vertices left unused) from a mesh.
fn without_faces(mesh: &Mesh, is_removed: impl Fn(usize) -> bool) -> Mesh {
    let mut soup = mesh.to_soup();
    soup.triangles = soup
        .triangles
        .iter()
        .enumerate()
        .filter(|(f, _)| !is_removed(*f))
        .map(|(_, t)| *t)
        .collect();
    soup.remove_unreferenced_vertices();
    from_soup(soup)
}

/// Closed surfaces: spheres, a cube, tori, two disjoint spheres.
pub fn closed_meshes() -> Vec<Fixture> {
    let mut two_spheres = primitives::icosphere(1.0, 1).to_soup();
    let mut second = primitives::icosphere(0.5, 1).to_soup();
    second
        .positions
        .iter_mut()
        .for_each(|p| *p += DVec3::new(3.0, 0.0, 0.0));
    two_spheres.append(&second);
    vec![
        fixture("icosahedron", primitives::icosphere(1.0, 0), true, 0),
        fixture("icosphere_2", primitives::icosphere(1.0, 2), true, 0),
        fixture("cube", primitives::cube(1.0), true, 0),
        fixture("torus", primitives::torus(2.0, 0.6, 16, 8), true, 1),
        fixture("thin_torus", primitives::torus(1.0, 0.1, 9, 3), true, 1),
        fixture("two_spheres", from_soup(two_spheres), true, 0),
    ]
}

/// Surfaces with boundary: grids, a single triangle, a sphere with a hole, an open tube.
pub fn boundary_meshes() -> Vec<Fixture> {
    let triangle = TriSoup {
        positions: vec![DVec3::ZERO, DVec3::X, DVec3::Y],
        triangles: vec![[0, 1, 2]],
    };
    let sphere = primitives::icosphere(1.0, 2);
    // Removing one ring of the torus (faces of segment 0 around the axis) leaves a tube.
    let n_minor = 8;
    let torus = primitives::torus(2.0, 0.6, 16, n_minor);
    vec![
        fixture("triangle", from_soup(triangle), false, 0),
        fixture("grid_square", primitives::grid(6, 6, 1.0), false, 0),
        fixture("grid_strip", primitives::grid(9, 2, 3.0), false, 0),
        fixture(
            "sphere_with_hole",
            without_faces(&sphere, |f| f < 4),
            false,
            0,
        ),
        fixture(
            "open_tube",
            without_faces(&torus, |f| f < 2 * n_minor),
            false,
            0,
        ),
        fixture(
            "torus_with_hole",
            without_faces(&torus, |f| f == 40),
            false,
            1,
        ),
    ]
}

/// Every fixture: [`closed_meshes`] then [`boundary_meshes`].
pub fn all() -> Vec<Fixture> {
    let mut all = closed_meshes();
    all.extend(boundary_meshes());
    all
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_tags_match_groups() {
        let mut names: Vec<&str> = all().iter().map(|f| f.name).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), all().len());
        assert!(closed_meshes().iter().all(|f| f.is_closed));
        assert!(boundary_meshes().iter().all(|f| !f.is_closed));
    }

    #[test]
    fn open_tube_has_two_rims() {
        let tube = boundary_meshes()
            .into_iter()
            .find(|f| f.name == "open_tube")
            .unwrap();
        assert_eq!(tube.mesh.n_boundary_loops(), 2);
        assert_eq!(
            tube.mesh
                .boundary_loops()
                .iter()
                .map(Vec::len)
                .collect::<Vec<_>>(),
            vec![8, 8]
        );
    }
}

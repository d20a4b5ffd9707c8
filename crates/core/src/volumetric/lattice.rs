//! The body-centred cubic lattice inside the inner shell (Zhou et al. 2005, §3.2, Fig. 6b):
//! the nodes of a cubic grid and of its cell centres, two interlaced grids whose spacing is
//! the mesh's mean edge length, kept where they lie inside the inner shell.
//!
//! Each node is joined to its eight nearest nodes of the other grid (the cell's body
//! diagonals; the paper adds no edges along the axes). A diagonal that leaves the inner
//! shell instead joins its inside node to the shell vertex nearest to where it crosses.

use glam::{DVec3, IVec3};

use crate::geometry::Bvh;
use crate::mesh::{FaceId, Mesh};

/// The lattice nodes inside a shell and their edges.
pub(super) struct Lattice {
    /// Node positions.
    pub nodes: Vec<DVec3>,
    /// Node to node edges (indices into `nodes`).
    pub edges: Vec<[u32; 2]>,
    /// Node to shell edges: node index, shell vertex.
    pub to_shell: Vec<[u32; 2]>,
}

/// The eight body diagonals from a cell centre to its corners.
const CORNERS: [IVec3; 8] = [
    IVec3::new(0, 0, 0),
    IVec3::new(1, 0, 0),
    IVec3::new(0, 1, 0),
    IVec3::new(1, 1, 0),
    IVec3::new(0, 0, 1),
    IVec3::new(1, 0, 1),
    IVec3::new(0, 1, 1),
    IVec3::new(1, 1, 1),
];

/// The lattice of spacing `spacing` inside the closed `shell` (`bvh` is the shell's).
pub(super) fn bcc_lattice(shell: &Mesh, bvh: &Bvh, spacing: f64) -> Lattice {
    let Some((low, high)) = shell.bounding_box() else {
        return Lattice {
            nodes: Vec::new(),
            edges: Vec::new(),
            to_shell: Vec::new(),
        };
    };
    // Corners at low + spacing (i, j, k), 0 ≤ i ≤ dims.x; centres half a cell further.
    let dims = ((high - low) / spacing).ceil().as_ivec3().max(IVec3::ONE);
    let corner_at = |c: IVec3| low + c.as_dvec3() * spacing;
    let centre_at = |c: IVec3| low + (c.as_dvec3() + 0.5) * spacing;
    let corner_index = |c: IVec3| (c.x + (dims.x + 1) * (c.y + (dims.y + 1) * c.z)) as usize;
    let mut nodes = Vec::new();
    let mut corner_node = vec![u32::MAX; ((dims.x + 1) * (dims.y + 1) * (dims.z + 1)) as usize];
    for c in cells(dims + IVec3::ONE) {
        let p = corner_at(c);
        if bvh.contains(shell, p) {
            corner_node[corner_index(c)] = nodes.len() as u32;
            nodes.push(p);
        }
    }
    let mut edges = Vec::new();
    let mut to_shell = Vec::new();
    for cell in cells(dims) {
        let centre = centre_at(cell);
        let centre_inside = bvh.contains(shell, centre);
        let centre_node = nodes.len() as u32;
        if centre_inside {
            nodes.push(centre);
        }
        for offset in CORNERS {
            let c = cell + offset;
            let corner = corner_node[corner_index(c)];
            let corner_inside = corner != u32::MAX;
            match (centre_inside, corner_inside) {
                (true, true) => edges.push([centre_node, corner]),
                (true, false) => to_shell.extend(
                    shell_vertex_between(shell, bvh, centre, corner_at(c))
                        .map(|v| [centre_node, v]),
                ),
                (false, true) => to_shell.extend(
                    shell_vertex_between(shell, bvh, corner_at(c), centre).map(|v| [corner, v]),
                ),
                (false, false) => {}
            }
        }
    }
    Lattice {
        nodes,
        edges,
        to_shell,
    }
}

/// Every integer point of the box `[0, dims)`.
fn cells(dims: IVec3) -> impl Iterator<Item = IVec3> {
    (0..dims.z).flat_map(move |z| {
        (0..dims.y).flat_map(move |y| (0..dims.x).map(move |x| IVec3::new(x, y, z)))
    })
}

/// The shell vertex nearest to where the segment from `inside` to `outside` leaves the
/// shell; `None` when the ray misses (the two inside tests and the ray disagree by round-off).
fn shell_vertex_between(shell: &Mesh, bvh: &Bvh, inside: DVec3, outside: DVec3) -> Option<u32> {
    let dir = outside - inside;
    let length = dir.length();
    let hit = bvh.raycast(shell, inside, dir / length)?;
    if hit.distance > length * (1.0 + 1e-9) {
        return None;
    }
    let crossing = inside + dir / length * hit.distance;
    let corners = shell.face_vertices(FaceId(hit.face.0));
    corners
        .into_iter()
        .min_by(|&a, &b| {
            let da = shell.position(a).distance_squared(crossing);
            let db = shell.position(b).distance_squared(crossing);
            da.total_cmp(&db)
        })
        .map(|v| v.index() as u32)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;

    #[test]
    fn a_sphere_holds_the_lattice_points_inside_it_with_eight_neighbours_in_the_middle() {
        let sphere = primitives::icosphere(1.0, 3);
        let bvh = Bvh::new(&sphere);
        let lattice = bcc_lattice(&sphere, &bvh, 0.2);
        assert!(lattice.nodes.iter().all(|p| p.length() <= 1.0 + 1e-12));
        // Volume 4.19, two nodes per 0.008 cell: about 1,050 nodes.
        let expected = 2.0 * 4.0 / 3.0 * std::f64::consts::PI / 0.008;
        let ratio = lattice.nodes.len() as f64 / expected;
        assert!((0.9..1.1).contains(&ratio), "{} nodes", lattice.nodes.len());
        let mut degree = vec![0; lattice.nodes.len()];
        for [a, b] in &lattice.edges {
            degree[*a as usize] += 1;
            degree[*b as usize] += 1;
            let length = lattice.nodes[*a as usize].distance(lattice.nodes[*b as usize]);
            assert!((length - 0.2 * 3f64.sqrt() / 2.0).abs() < 1e-9);
        }
        for (p, d) in lattice.nodes.iter().zip(&degree) {
            if p.length() < 0.6 {
                assert_eq!(*d, 8, "node at {p}");
            }
        }
        // Every node near the surface reaches the shell.
        let reaching: std::collections::HashSet<u32> =
            lattice.to_shell.iter().map(|e| e[0]).collect();
        assert!(
            reaching
                .iter()
                .all(|&n| lattice.nodes[n as usize].length() > 0.8)
        );
        assert!(!reaching.is_empty());
    }
}

//! The region flattened to the unit disc, where the fall-off panel shows it (Bujans §5: "the
//! ROI is flattened into a disc scaled to [-1, 1]²"; the thesis does not say how).
//!
//! Tutte's embedding with uniform weights: the loop around the region's faces is laid on
//! the unit circle by arclength, and every other vertex sits at the average of its
//! neighbours in the region (one sparse symmetric positive definite solve per coordinate,
//! the Laplacian itself factored). Uniform weights, unlike cotangent ones, guarantee that
//! no triangle flips for a disc-shaped region, whatever the mesh's triangles; the price is
//! some distortion of areas, which a picture of levels can bear. Each hole in the region
//! (parts facing away inside the boundary) is closed for the solve by one extra vertex
//! joined to the vertices around it. Where the loop around the region touches itself at a
//! vertex (a pinch), the region is not a disc and the few triangles there may fold; the
//! panel is a picture, so that is borne rather than refused.

use glam::DVec2;

use super::RegionError;
use crate::mesh::{Mesh, VertexId};
use crate::solve::{SpdSystem, Triplets};

/// A region being laid flat: the rim on the circle and the system for the rest, analysed
/// ([`super::RegionEdit::flattening`]); [`Flattening::factor`] factors the system and
/// [`Flattening::finish`] solves it. The region tool's preview puts each of the three in a
/// frame of its own (about 30, 40 and 10 ms for a 50k-vertex region).
#[derive(Debug)]
pub struct Flattening {
    /// Each region vertex's place, final on the rim.
    uv: Vec<DVec2>,
    /// Each region vertex's unknown, `u32::MAX` on the rim.
    free: Vec<u32>,
    system: SpdSystem,
    /// The right-hand sides, u then v.
    rhs: [Vec<f64>; 2],
}

impl Flattening {
    /// Whether [`Flattening::factor`] ran.
    pub fn is_factored(&self) -> bool {
        self.system.is_factored()
    }

    /// Factors the system: the second step.
    ///
    /// Errors: [`RegionError::NotADisc`] when it cannot be factored.
    pub fn factor(&mut self) -> Result<(), RegionError> {
        self.system.factor().map_err(|_| RegionError::NotADisc)
    }

    /// Each region vertex's place in the unit disc, in the order of the `vertices` this
    /// flattening was made for.
    ///
    /// Errors: [`RegionError::NotADisc`] when the system cannot be solved.
    pub fn finish(self) -> Result<Vec<DVec2>, RegionError> {
        let Flattening {
            mut uv,
            free,
            mut system,
            mut rhs,
        } = self;
        system.solve(&mut rhs).map_err(|_| RegionError::NotADisc)?;
        for (i, slot) in free.iter().enumerate() {
            if *slot != u32::MAX {
                uv[i] = DVec2::new(rhs[0][*slot as usize], rhs[1][*slot as usize]);
            }
        }
        Ok(uv)
    }
}

/// The flattening of the region of `mesh` flagged in `region` (one flag per vertex), its
/// vertices in the order of `vertices`: the first of its three steps (the rim placed, the
/// system built and analysed).
///
/// Errors: [`RegionError::NotADisc`] when the region's faces have no loop around them (it
/// reaches the mesh's own boundary, or has no face).
pub(super) fn flattening(
    mesh: &Mesh,
    region: &[bool],
    vertices: &[VertexId],
) -> Result<Flattening, RegionError> {
    let faces: Vec<bool> = mesh
        .faces()
        .map(|f| mesh.face_vertices(f).iter().all(|v| region[v.index()]))
        .collect();
    let mut loops = mesh.face_set_loops(&faces);
    let longest = (0..loops.len())
        .max_by_key(|&k| loops[k].len())
        .ok_or(RegionError::NotADisc)?;
    let rim = loops.swap_remove(longest);
    let holes = loops;
    // Local numbering: region vertex i is `vertices[i]`.
    let mut local = vec![u32::MAX; mesh.n_vertices()];
    for (i, v) in vertices.iter().enumerate() {
        local[v.index()] = i as u32;
    }
    let mut uv = vec![DVec2::ZERO; vertices.len()];
    let mut on_rim = vec![false; vertices.len()];
    for (v, at) in rim.iter().zip(circle_by_arclength(mesh, &rim)) {
        let i = local[v.index()] as usize;
        uv[i] = at;
        on_rim[i] = true;
    }
    // The free vertices, numbered again for the system.
    let mut free = vec![u32::MAX; vertices.len()];
    let mut n_free = 0;
    for (i, slot) in free.iter_mut().enumerate() {
        if !on_rim[i] {
            *slot = n_free;
            n_free += 1;
        }
    }
    // Each hole gets one more free unknown, joined to the vertices around it, so that the
    // region is a disc for the embedding; it is dropped after the solve.
    let n_unknowns = n_free as usize + holes.len();
    let mut system = Triplets::new(n_unknowns, n_unknowns);
    let mut rhs = [vec![0.0; n_unknowns], vec![0.0; n_unknowns]];
    let mut hole_degree = vec![0.0; vertices.len()];
    for (k, hole) in holes.iter().enumerate() {
        let centre = n_free as usize + k;
        for v in hole {
            let i = local[v.index()] as usize;
            hole_degree[i] += 1.0;
            match free[i] {
                u32::MAX => {
                    rhs[0][centre] += uv[i].x;
                    rhs[1][centre] += uv[i].y;
                }
                row => system.push(centre, row as usize, -1.0),
            }
        }
        system.push(centre, centre, hole.len() as f64);
    }
    for (i, &v) in vertices.iter().enumerate() {
        let row = free[i];
        if row == u32::MAX {
            continue;
        }
        let mut degree = 0.0;
        for w in mesh.vertex_neighbors(v) {
            let j = local[w.index()];
            if j == u32::MAX {
                continue;
            }
            degree += 1.0;
            match free[j as usize] {
                u32::MAX => {
                    rhs[0][row as usize] += uv[j as usize].x;
                    rhs[1][row as usize] += uv[j as usize].y;
                }
                col if col < row => system.push(row as usize, col as usize, -1.0),
                _ => {}
            }
        }
        // A vertex with no neighbour in the region stays at the centre.
        let degree = degree + hole_degree[i];
        system.push(row as usize, row as usize, f64::max(degree, 1.0));
    }
    let system = SpdSystem::analyse(system.build()).map_err(|_| RegionError::NotADisc)?;
    Ok(Flattening {
        uv,
        free,
        system,
        rhs,
    })
}

/// The loop's vertices on the unit circle, spaced as their edges are long, starting at angle
/// 0 and turning counter-clockwise.
fn circle_by_arclength(mesh: &Mesh, rim: &[VertexId]) -> Vec<DVec2> {
    let n = rim.len();
    let lengths: Vec<f64> = (0..n)
        .map(|k| {
            mesh.position(rim[k])
                .distance(mesh.position(rim[(k + 1) % n]))
        })
        .collect();
    let total: f64 = lengths.iter().sum();
    let mut along = 0.0;
    lengths
        .iter()
        .map(|length| {
            let angle = std::f64::consts::TAU * along / total.max(f64::MIN_POSITIVE);
            along += length;
            DVec2::from_angle(angle)
        })
        .collect()
}

//! In-betweens of two key poses by interpolating Laplacian coordinates (Zhou et al. 2005,
//! §4.2, after Alexa 2003): each vertex's Laplacian coordinate turns and scales from its
//! value in the first pose toward the second, and the surface is solved from them.
//!
//! Per vertex, the similarity `T` from pose `a` to pose `b` is read from a frame, as the
//! paper's §3.3 reads transforms at curve points: the vertex normal and its first edge made
//! perpendicular to it, in each pose (`R = F_b F_aᵀ`), with the scale the ratio of the
//! one-ring's edge lengths. At `s ∈ [0, 1]` the coordinate is `T^s δ_a + s (δ_b − T δ_a)`:
//! the turn by part of its angle, plus the part of what the frame does not explain, so the
//! ends are exactly `δ_a` and `δ_b`. The Laplacian (normalised, clamped cotangent weights
//! of pose `a`) determines the surface up to a translation; the vertex nearest the first
//! pose's centroid is held on the straight line between its two positions. A linear blend
//! of positions would shorten whatever turns (a limb swinging through 90° shrinks to 71% of
//! its reach half way); this keeps its length.

use glam::{DMat3, DQuat, DVec3};

use crate::geometry::OneRingWeights;
use crate::geometry::vertex_normals_of;
use crate::mesh::{Mesh, VertexId};
use crate::solve::{Prefactored, SolveError, Triplets};
use crate::volumetric::Similarity;

/// The in-betweens of two poses of one mesh, factored once; see the module docs.
#[derive(Debug)]
pub struct KeyBlend {
    a: Vec<DVec3>,
    b: Vec<DVec3>,
    /// `δ_a` of every vertex.
    delta_a: Vec<DVec3>,
    /// `δ_b − T δ_a` of every vertex.
    unexplained: Vec<DVec3>,
    turns: Vec<Similarity>,
    anchor: usize,
    solver: Prefactored,
    rhs: Vec<DVec3>,
    fixed_values: Vec<DVec3>,
}

impl KeyBlend {
    /// The blend from pose `a` to pose `b` of `mesh`'s connectivity (one position per
    /// vertex in each).
    ///
    /// Errors: [`SolveError::DimensionMismatch`] for poses of the wrong length,
    /// [`SolveError::NonFiniteValue`] for a pose that is not finite.
    pub fn new(mesh: &Mesh, a: &[DVec3], b: &[DVec3]) -> Result<KeyBlend, SolveError> {
        let n = mesh.n_vertices();
        crate::solve::check_len("first pose", n, a.len())?;
        crate::solve::check_len("second pose", n, b.len())?;
        if a.iter().chain(b).any(|p| !p.is_finite()) {
            return Err(SolveError::NonFiniteValue);
        }
        let mut posed = mesh.clone();
        posed.positions_mut().copy_from_slice(a);
        let vertices: Vec<VertexId> = mesh.vertices().collect();
        let rings = OneRingWeights::new(&posed, &vertices, |v| v.0);
        let laplacian =
            |x: &[DVec3], i: usize| x[i] - rings.ring(i).map(|(j, w)| w * x[j]).sum::<DVec3>();
        let (mut normals_a, mut normals_b) = (Vec::new(), Vec::new());
        vertex_normals_of(mesh.triangles(), a, &mut normals_a);
        vertex_normals_of(mesh.triangles(), b, &mut normals_b);
        let mut delta_a = Vec::with_capacity(n);
        let mut unexplained = Vec::with_capacity(n);
        let mut turns = Vec::with_capacity(n);
        for (i, v) in vertices.iter().enumerate() {
            let turn = turn_at(mesh, *v, (a, normals_a[i]), (b, normals_b[i]));
            let (da, db) = (laplacian(a, i), laplacian(b, i));
            delta_a.push(da);
            unexplained.push(db - turn.apply(da));
            turns.push(turn);
        }
        let centroid = a.iter().sum::<DVec3>() / n.max(1) as f64;
        let anchor = (0..n)
            .min_by(|&i, &j| {
                a[i].distance_squared(centroid)
                    .total_cmp(&a[j].distance_squared(centroid))
            })
            .unwrap_or(0);
        let mut triplets = Triplets::with_capacity(n, n, 8 * n);
        for i in 0..n {
            triplets.push(i, i, 1.0);
            for (j, w) in rings.ring(i) {
                triplets.push(i, j, -w);
            }
        }
        let mut fixed = vec![false; n];
        if n > 0 {
            fixed[anchor] = true;
        }
        let solver = Prefactored::new(&triplets.build(), &fixed)?;
        Ok(KeyBlend {
            a: a.to_vec(),
            b: b.to_vec(),
            delta_a,
            unexplained,
            turns,
            anchor,
            solver,
            rhs: vec![DVec3::ZERO; n],
            fixed_values: vec![DVec3::ZERO; n],
        })
    }

    /// The pose at `s` (0: the first pose, 1: the second, exactly), into `out`.
    ///
    /// Errors: [`SolveError::DimensionMismatch`] when `out` has the wrong length.
    pub fn at(&mut self, s: f64, out: &mut [DVec3]) -> Result<(), SolveError> {
        crate::solve::check_len("pose", self.a.len(), out.len())?;
        if s <= 0.0 || s >= 1.0 {
            out.copy_from_slice(if s <= 0.0 { &self.a } else { &self.b });
            return Ok(());
        }
        for (((rhs, turn), &delta), &rest) in self
            .rhs
            .iter_mut()
            .zip(&self.turns)
            .zip(&self.delta_a)
            .zip(&self.unexplained)
        {
            *rhs = turn.part(s).apply(delta) + s * rest;
        }
        if let Some(value) = self.fixed_values.get_mut(self.anchor) {
            *value = self.a[self.anchor].lerp(self.b[self.anchor], s);
        }
        self.solver.solve(&self.rhs, &self.fixed_values, out)
    }
}

/// The similarity that takes vertex `v`'s frame in the first pose to its frame in the
/// second: the turn of (normal, first edge made perpendicular to it), and the ratio of the
/// one-ring's edge lengths.
fn turn_at(mesh: &Mesh, v: VertexId, a: (&[DVec3], DVec3), b: (&[DVec3], DVec3)) -> Similarity {
    let Some(first) = mesh.vertex_neighbors(v).next() else {
        return Similarity::IDENTITY;
    };
    let frame = |(x, normal): (&[DVec3], DVec3)| -> Option<DMat3> {
        let edge = x[first.index()] - x[v.index()];
        let tangent = (edge - normal * normal.dot(edge)).try_normalize()?;
        let normal = normal.try_normalize()?;
        Some(DMat3::from_cols(tangent, normal.cross(tangent), normal))
    };
    let spread = |x: &[DVec3]| -> f64 {
        mesh.vertex_neighbors(v)
            .map(|u| x[u.index()].distance(x[v.index()]))
            .sum()
    };
    let (Some(fa), Some(fb)) = (frame(a), frame(b)) else {
        return Similarity::IDENTITY;
    };
    let scale = spread(b.0) / spread(a.0);
    Similarity {
        rotation: DQuat::from_mat3(&(fb * fa.transpose())).normalize(),
        scale: if scale.is_finite() && scale > 0.0 {
            scale
        } else {
            1.0
        },
    }
}

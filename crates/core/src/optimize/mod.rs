//! Laplacian mesh optimization (Nealen's dissertation ch. 6): one sparse least-squares solve
//! that improves the triangles of any mesh without changing its look, or smooths it while
//! keeping its features. Connectivity never changes; only positions move.
//!
//! Every vertex gets two rows per coordinate (Eq. 6.11):
//! `[W_L L; W_p] V' = [W_L f; W_p V]`, solved through the normal equations with one sparse
//! Cholesky factorization ([`crate::solve`]):
//! - **shape** (§6.5): `L` the uniform Laplacian and `f` the input's normalized cotangent
//!   Laplacian coordinates, so each vertex moves toward the centroid of its one-ring within
//!   its tangent plane (the cotangent coordinates are normal on a smooth surface), evening out
//!   the triangles while the positional rows hold the shape;
//! - **smooth** (§6.6): `f = 0` with the uniform, normalized cotangent or unnormalized
//!   cotangent (curvature flow) Laplacian; the scale `s` of the positional weights sets the
//!   amount (Appendix B: with uniform weights the result is `(L² + s² I)⁻¹ s² V`, a low-pass
//!   filter whose cut-off rises with `s`).
//!
//! The positional weights ([`weights`]) come from the mean curvature magnitude `κ̄` (Eq. 6.7):
//! constant, linear over a box-plot-truncated range, or its cumulative distribution. Options:
//! tangent-plane rows (§6.5.1) couple x, y and z into one `7n × 3n` system that keeps each
//! vertex on its tangent plane; quality modulation (§6.5.2) frees vertices of poor triangles;
//! feature preservation (§6.5.3) sets `W_L = (s I − W_linear) / s`, so high-curvature vertices
//! keep their place. [`quality`] measures the radius ratios and the Hausdorff distance.

mod error;
mod optimizer;
pub mod quality;
mod refine;
pub mod region;
mod system;
pub mod weights;

pub use error::OptimizeError;
pub use optimizer::{Optimizer, optimize};
pub use quality::{QualityReport, quality_report};

use glam::DVec3;
use serde::{Deserialize, Serialize};

/// What the solve aims for.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Mode {
    /// Better triangles, the same look (§6.5).
    #[default]
    Shape,
    /// Less noise, features kept (§6.6).
    Smooth,
}

/// How the positional weights follow the mean curvature.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum WeightScheme {
    /// `s` everywhere: the least geometric error, the least improvement.
    Const,
    /// `κ̄` mapped linearly onto `[0, s]` up to the box-plot fence: for CAD-like shapes.
    Linear,
    /// The cumulative distribution of `κ̄`, scaled to `[0, s]`: for smooth and organic shapes.
    #[default]
    Cdf,
}

/// How the Laplacian rows are reduced on features when `features` is on (§6.5.3, §6.6).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FeatureFalloff {
    /// `W_L = (s I − W_linear) / s` with `W_p = W_linear`: the thesis's §6.5.3.
    #[default]
    Linear,
    /// `W_L = (s I − W_cdf) / s` with `W_p = W_cdf`: the cdf-derived variant of §6.6, which
    /// ranks the curvatures instead of scaling them, so a few outliers do not flatten the rest.
    Cdf,
    /// `W_L = exp(−(κ̄ / σ)²)` with `σ` the box-plot fence of `κ̄` (`Q3 + 1.5 IQR`), and the
    /// positional weights of `weights`: a smooth fall-off that leaves flat and gently curved
    /// regions almost fully smoothed.
    Gaussian,
}

/// Which Laplacian smoothing uses (shape optimization always uses the uniform one).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LaplacianKind {
    /// Uniform weights: smooths along and across the surface (inner and outer fairness).
    #[default]
    Uniform,
    /// Normalized cotangent weights: smooths only along the normal, keeping triangle shapes.
    Cotan,
    /// Unnormalized cotangent weights over the Voronoi area (`κ̄ n`): curvature flow.
    CotanCurvature,
}

/// Every setting of one optimization.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct OptimizeParams {
    /// Better triangles or smoothing.
    pub mode: Mode,
    /// How the positional weights follow the curvature.
    pub weights: WeightScheme,
    /// The thesis's `s`: positional weights lie in `[0, s]`, so a smaller `s` moves more.
    pub scale: f64,
    /// The Laplacian of smoothing (shape optimization always uses the uniform one).
    pub laplacian: LaplacianKind,
    /// Keep every vertex on its tangent plane (§6.5.1): lower error, a 3× larger system.
    pub tangent_plane: bool,
    /// Scale each positional weight by its vertex's worst radius ratio (§6.5.2).
    pub quality: bool,
    /// Hold high-curvature vertices in place (§6.5.3).
    pub features: bool,
    /// How `features` reduces the Laplacian rows.
    pub feature_falloff: FeatureFalloff,
}

impl Default for OptimizeParams {
    fn default() -> Self {
        Self {
            mode: Mode::Shape,
            weights: WeightScheme::Cdf,
            scale: 1.0,
            laplacian: LaplacianKind::Uniform,
            tangent_plane: false,
            quality: false,
            features: false,
            feature_falloff: FeatureFalloff::Linear,
        }
    }
}

/// Which vertices the user marked for one optimization (see [`region`]).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Selection {
    /// Per vertex: whether it may move; all may when `None`. The rest keep their place.
    pub movable: Option<Vec<bool>>,
    /// Per vertex: whether the user tagged it as a feature to keep (§6.6: "vertices the user
    /// tags"): its Laplacian row is dropped and its positional weight is the full `s`, as the
    /// most curved vertices get with `features` (§6.5.3), so it holds its place while its
    /// neighbours move around it.
    pub features: Option<Vec<bool>>,
    /// Per vertex: a direction it may only slide along, or `None` (then free, or held by
    /// `movable`). Used with tangent-plane rows: one more row holds the vertex near the line
    /// through it along the direction, and the solution is put exactly on it, so that a
    /// control curve's vertices even out their spacing without leaving the curve (the tidy-up
    /// after a curve op). Ignored without `tangent_plane`.
    pub sliding: Option<Vec<Option<DVec3>>>,
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::geometry::{enclosed_volume, mean_curvature, uniform_laplacian};
    use crate::mesh::Mesh;
    use crate::mesh::primitives;
    use crate::solve::test_support::dense_solve;

    fn smooth_uniform_const(scale: f64) -> OptimizeParams {
        OptimizeParams {
            mode: Mode::Smooth,
            weights: WeightScheme::Const,
            scale,
            ..OptimizeParams::default()
        }
    }

    /// A deterministic jitter in `[-1, 1]` per vertex and coordinate.
    fn jitter(i: usize, d: usize) -> f64 {
        ((i * 7919 + d * 104_729) as f64 * 0.618_033_988_7).fract() * 2.0 - 1.0
    }

    /// Appendix B: with the uniform Laplacian (symmetric on a valence-6 torus) and constant
    /// weights `w`, the result is `(L² + w² I)⁻¹ w² x`.
    #[test]
    fn smoothing_with_constant_weights_is_the_appendix_b_filter() {
        let mesh = primitives::torus(2.0, 0.7, 12, 8);
        assert!(mesh.vertices().all(|v| mesh.valence(v) == 6));
        let w = 0.3;
        let result = optimize(&mesh, &smooth_uniform_const(w)).unwrap();
        let l = uniform_laplacian(&mesh).to_dense();
        let n = mesh.n_vertices();
        let mut m = vec![vec![0.0; n]; n];
        for i in 0..n {
            for j in 0..n {
                m[i][j] = (0..n).map(|k| l[i][k] * l[k][j]).sum::<f64>();
            }
            m[i][i] += w * w;
        }
        for d in 0..3 {
            let rhs = mesh.positions().iter().map(|p| w * w * p[d]).collect();
            let expected = dense_solve(m.clone(), rhs);
            for (i, p) in result.iter().enumerate() {
                assert!(
                    (p[d] - expected[i]).abs() < 1e-9,
                    "vertex {i} coordinate {d}"
                );
            }
        }
    }

    /// Shape optimization evens out a jittered grid's triangles and keeps it flat.
    #[test]
    fn shape_optimization_evens_out_a_jittered_plane() {
        let mut mesh = primitives::grid(12, 12, 1.0);
        for (i, p) in mesh.positions_mut().iter_mut().enumerate() {
            *p += DVec3::new(jitter(i, 0), jitter(i, 1), 0.0) * 0.03;
        }
        for weights in [WeightScheme::Const, WeightScheme::Linear, WeightScheme::Cdf] {
            let params = OptimizeParams {
                weights,
                ..OptimizeParams::default()
            };
            let result = optimize(&mesh, &params).unwrap();
            let report = quality_report(&mesh, &result);
            assert!(
                report.mean_radius_ratio > report.input_mean_radius_ratio,
                "{weights:?}: {report:?}"
            );
            assert!(
                result.iter().all(|p| p.z.abs() < 1e-12),
                "{weights:?} left the plane"
            );
        }
    }

    /// Smoothing a noisy sphere: the mean curvature's variance drops tenfold, the volume
    /// hardly changes.
    #[test]
    fn smoothing_removes_noise_and_keeps_the_volume() {
        let sphere = primitives::icosphere(1.0, 3);
        let mut noisy = sphere.clone();
        for (i, p) in noisy.positions_mut().iter_mut().enumerate() {
            *p *= 1.0 + 0.01 * jitter(i, 0);
        }
        let params = OptimizeParams {
            scale: 0.3,
            ..smooth_uniform_const(0.3)
        };
        let mut smoothed = noisy.clone();
        smoothed
            .positions_mut()
            .copy_from_slice(&optimize(&noisy, &params).unwrap());
        let variance = |mesh: &Mesh| {
            let h = mean_curvature(mesh);
            let mean = h.iter().sum::<f64>() / h.len() as f64;
            h.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / h.len() as f64
        };
        let ratio = variance(&noisy) / variance(&smoothed);
        assert!(ratio > 10.0, "variance fell only {ratio}×");
        let volume_change = (enclosed_volume(&smoothed) / enclosed_volume(&noisy) - 1.0).abs();
        assert!(volume_change < 0.01, "volume changed by {volume_change}");
    }

    #[test]
    fn tangent_plane_rows_lower_the_distance_to_the_input() {
        let sphere = primitives::icosphere(1.0, 2);
        let mut mesh = sphere.clone();
        for (i, p) in mesh.positions_mut().iter_mut().enumerate() {
            let tangent = DVec3::new(jitter(i, 0), jitter(i, 1), jitter(i, 2)).cross(*p);
            *p += tangent * 0.05;
        }
        let plain = optimize(&mesh, &OptimizeParams::default()).unwrap();
        let params = OptimizeParams {
            tangent_plane: true,
            ..OptimizeParams::default()
        };
        let tangent = optimize(&mesh, &params).unwrap();
        let (a, b) = (
            quality_report(&mesh, &plain),
            quality_report(&mesh, &tangent),
        );
        assert!(
            b.hausdorff_relative < a.hausdorff_relative,
            "{a:?} vs {b:?}"
        );
        assert!(b.mean_radius_ratio > b.input_mean_radius_ratio);
    }

    /// Sliding vertices even out along their line and stay on it: a jittered grid whose
    /// middle row may only slide along x keeps that row at its y and in the plane, while the
    /// row's spacing evens out.
    #[test]
    fn sliding_vertices_stay_on_their_lines_and_even_out() {
        let mut mesh = primitives::grid(12, 12, 1.0);
        let row: Vec<usize> = (0..mesh.n_vertices())
            .filter(|&i| mesh.positions()[i].y.abs() < 1e-9)
            .collect();
        assert_eq!(row.len(), 13);
        for (i, p) in mesh.positions_mut().iter_mut().enumerate() {
            let along_row = if row.contains(&i) { 1.0 } else { 0.3 };
            let jitter_y = if row.contains(&i) { 0.0 } else { jitter(i, 1) };
            *p += DVec3::new(jitter(i, 0) * along_row, jitter_y * 0.3, 0.0) * 0.03;
        }
        let mut sliding = vec![None; mesh.n_vertices()];
        for &i in &row {
            sliding[i] = Some(DVec3::X);
        }
        let selection = Selection {
            sliding: Some(sliding),
            ..Selection::default()
        };
        let params = OptimizeParams {
            tangent_plane: true,
            ..OptimizeParams::default()
        };
        let result = Optimizer::new(&mesh, &params, &selection)
            .unwrap()
            .solve(1.0)
            .unwrap();
        let edge = mesh.mean_edge_length();
        for &i in &row {
            assert!(result[i].y.abs() < 1e-12 * edge, "vertex {i} left its line");
        }
        assert!(
            result.iter().all(|p| p.z.abs() < 1e-12),
            "the grid left its plane"
        );
        let spread = |positions: &[DVec3]| {
            let mut xs: Vec<f64> = row.iter().map(|&i| positions[i].x).collect();
            xs.sort_by(f64::total_cmp);
            let gaps: Vec<f64> = xs.windows(2).map(|w| w[1] - w[0]).collect();
            gaps.iter().fold(0.0f64, |m, &g| m.max(g)) - gaps.iter().fold(1.0f64, |m, &g| m.min(g))
        };
        assert!(
            spread(&result) < 0.5 * spread(mesh.positions()),
            "the row's spacing: {} before, {} after",
            spread(mesh.positions()),
            spread(&result)
        );
    }

    /// A cube of side 1 tessellated into `n × n` quads per side, welded.
    #[test]
    fn a_rescaled_optimizer_gives_what_a_fresh_one_gives_bit_for_bit() {
        let mut mesh = primitives::icosphere(1.0, 2);
        for (i, p) in mesh.positions_mut().iter_mut().enumerate() {
            *p *= 1.0 + 0.02 * jitter(i, 0);
        }
        for tangent_plane in [false, true] {
            let params = OptimizeParams {
                tangent_plane,
                features: true,
                ..OptimizeParams::default()
            };
            let mut optimizer = Optimizer::new(&mesh, &params, &Selection::default()).unwrap();
            let first = optimizer.solve(1.0).unwrap();
            for scale in [0.3, 2.5] {
                let fresh = optimize(&mesh, &OptimizeParams { scale, ..params }).unwrap();
                assert_eq!(optimizer.solve(scale).unwrap(), fresh);
                assert!(optimizer.serves(&OptimizeParams {
                    scale: 9.0,
                    ..params
                }));
            }
            assert_ne!(optimizer.solve(0.3).unwrap(), first);
            assert!(!optimizer.serves(&OptimizeParams::default()));
            assert_eq!(
                optimizer.solve(-1.0),
                Err(OptimizeError::InvalidScale(-1.0))
            );
        }
    }

    #[test]
    fn refining_toward_a_new_scale_converges_to_the_exact_solution() {
        let mut mesh = primitives::icosphere(1.0, 3);
        for (i, p) in mesh.positions_mut().iter_mut().enumerate() {
            *p *= 1.0 + 0.02 * jitter(i, 0);
        }
        let params = OptimizeParams {
            mode: Mode::Smooth,
            ..OptimizeParams::default()
        };
        let mut optimizer = Optimizer::new(&mesh, &params, &Selection::default()).unwrap();
        let mut shown = optimizer.solve(1.0).unwrap();
        for scale in [0.5, 0.2, 0.8] {
            let mut calls = 1;
            while !optimizer.refine(scale, &mut shown).unwrap() {
                calls += 1;
            }
            let exact = optimize(&mesh, &OptimizeParams { scale, ..params }).unwrap();
            let error = shown
                .iter()
                .zip(&exact)
                .map(|(a, b)| a.distance(*b))
                .fold(0.0, f64::max);
            assert!(error < 1e-5, "scale {scale}: {error} after {calls} calls");
            assert!(calls < 40, "scale {scale}: {calls} iterations");
        }
        // The factored scale and the coupled system are solved exactly at once.
        assert!(optimizer.refine(1.0, &mut shown).unwrap());
        assert_eq!(shown, optimizer.solve(1.0).unwrap());
        let coupled = OptimizeParams {
            tangent_plane: true,
            ..OptimizeParams::default()
        };
        let mut optimizer = Optimizer::new(&mesh, &coupled, &Selection::default()).unwrap();
        assert!(optimizer.refine(0.5, &mut shown).unwrap());
        assert_eq!(
            shown,
            optimize(
                &mesh,
                &OptimizeParams {
                    scale: 0.5,
                    ..coupled
                }
            )
            .unwrap()
        );
    }

    #[test]
    fn a_region_moves_only_its_vertices_also_while_refining() {
        let mut mesh = primitives::icosphere(1.0, 3);
        for (i, p) in mesh.positions_mut().iter_mut().enumerate() {
            *p *= 1.0 + 0.02 * jitter(i, 0);
        }
        let movable: Vec<bool> = mesh.positions().iter().map(|p| p.z > 0.3).collect();
        for tangent_plane in [false, true] {
            let params = OptimizeParams {
                mode: Mode::Smooth,
                tangent_plane,
                ..OptimizeParams::default()
            };
            let selection = Selection {
                movable: Some(movable.clone()),
                ..Selection::default()
            };
            let mut optimizer = Optimizer::new(&mesh, &params, &selection).unwrap();
            let mut shown = optimizer.solve(1.0).unwrap();
            while !optimizer.refine(0.4, &mut shown).unwrap() {}
            for result in [shown.clone(), optimizer.solve(0.4).unwrap()] {
                for ((p, q), &m) in mesh.positions().iter().zip(&result).zip(&movable) {
                    if !m {
                        assert_eq!(p, q, "a vertex outside the region moved");
                    }
                }
                let moved = mesh.positions().iter().zip(&result).filter(|(p, q)| p != q);
                assert!(moved.count() > movable.iter().filter(|&&m| m).count() / 2);
            }
        }
        let nothing = Selection {
            movable: Some(vec![false; mesh.n_vertices()]),
            ..Selection::default()
        };
        let refused = Optimizer::new(&mesh, &OptimizeParams::default(), &nothing);
        assert_eq!(refused.err(), Some(OptimizeError::EmptyRegion));
    }

    fn fine_cube(n: usize) -> Mesh {
        let mut soup = crate::mesh::TriSoup::default();
        let mut index = std::collections::HashMap::new();
        let mut vertex = |p: DVec3, soup: &mut crate::mesh::TriSoup| {
            let key = (p * 4.0 * n as f64).round().as_ivec3().to_array();
            *index.entry(key).or_insert_with(|| {
                soup.positions.push(p);
                soup.positions.len() as u32 - 1
            })
        };
        for axis in 0..3 {
            for side in [-0.5, 0.5] {
                let (u, v) = (DVec3::AXES[(axis + 1) % 3], DVec3::AXES[(axis + 2) % 3]);
                let normal = DVec3::AXES[axis] * side;
                // Counter-clockwise seen from outside: u × v points along +axis.
                let (u, v) = if side > 0.0 { (u, v) } else { (v, u) };
                let at = |i: usize, j: usize| {
                    normal + u * (i as f64 / n as f64 - 0.5) + v * (j as f64 / n as f64 - 0.5)
                };
                for i in 0..n {
                    for j in 0..n {
                        let [a, b, c, d] = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]
                            .map(|p| vertex(p, &mut soup));
                        soup.triangles.extend([[a, b, c], [a, c, d]]);
                    }
                }
            }
        }
        Mesh::from_soup(&soup).unwrap()
    }

    /// The largest deviation from 90° of the dihedral angles along the cube's edges.
    fn worst_edge_angle_error(mesh: &Mesh, positions: &[DVec3], rest: &Mesh) -> f64 {
        // The axes along which a rest position lies on a face of the cube; an edge of the
        // mesh runs along an edge of the cube when its ends share two of them.
        let faces_of = |p: DVec3| {
            (p.abs() - DVec3::splat(0.5))
                .abs()
                .cmple(DVec3::splat(1e-9))
                .bitmask()
        };
        let normal = |f| {
            let [a, b, c] = mesh.face_vertices(f).map(|v| positions[v.index()]);
            (b - a).cross(c - a).normalize()
        };
        let mut worst = 0.0f64;
        for h in (0..mesh.n_halfedges() as u32).map(crate::mesh::HalfedgeId) {
            let (a, b) = (mesh.tail(h), mesh.head(h));
            if (faces_of(rest.position(a)) & faces_of(rest.position(b))).count_ones() < 2 {
                continue;
            }
            let t = mesh.twin(h).unwrap();
            let angle = normal(mesh.face(h))
                .dot(normal(mesh.face(t)))
                .clamp(-1.0, 1.0)
                .acos();
            worst = worst.max((angle.to_degrees() - 90.0).abs());
        }
        worst
    }

    /// §6.5.3 and §6.6 on a noisy cube: with feature preservation the sharp edges keep their
    /// right angles within 10° (the linear fall-off; the others within half the error of no
    /// preservation) while the faces smooth; without it they round off.
    #[test]
    fn feature_preservation_keeps_the_edges_of_a_noisy_cube() {
        let cube = fine_cube(12);
        let mut noisy = cube.clone();
        let normals = crate::geometry::vertex_normals(&cube);
        for (i, p) in noisy.positions_mut().iter_mut().enumerate() {
            *p += normals[i] * 0.01 * jitter(i, 0);
        }
        let smooth = |features, feature_falloff| OptimizeParams {
            features,
            feature_falloff,
            ..smooth_uniform_const(0.3)
        };
        let rounded = optimize(&noisy, &smooth(false, FeatureFalloff::Linear)).unwrap();
        let rounded_error = worst_edge_angle_error(&noisy, &rounded, &cube);
        for falloff in [
            FeatureFalloff::Linear,
            FeatureFalloff::Cdf,
            FeatureFalloff::Gaussian,
        ] {
            let kept = optimize(&noisy, &smooth(true, falloff)).unwrap();
            let kept_error = worst_edge_angle_error(&noisy, &kept, &cube);
            eprintln!(
                "cube edges: {kept_error:.1}° off with {falloff:?}, {rounded_error:.1}° without"
            );
            // The thesis's linear variant is the one for CAD shapes (§6.7); the others must
            // still keep the edges much better than none.
            let bound = match falloff {
                FeatureFalloff::Linear => 10.0,
                _ => 0.5 * rounded_error,
            };
            assert!(kept_error < bound, "{falloff:?}: {kept_error}° off");
        }
        // The same edges tagged by the user instead (what a brush over them marks).
        let on_edge = |p: DVec3| {
            (p.abs() - DVec3::splat(0.5))
                .abs()
                .cmple(DVec3::splat(1e-9))
        };
        let tagged = Selection {
            movable: None,
            features: Some(
                cube.positions()
                    .iter()
                    .map(|&p| on_edge(p).bitmask().count_ones() >= 2)
                    .collect(),
            ),
            sliding: None,
        };
        let params = smooth(false, FeatureFalloff::Linear);
        let kept = Optimizer::new(&noisy, &params, &tagged)
            .unwrap()
            .solve(0.3)
            .unwrap();
        let kept_error = worst_edge_angle_error(&noisy, &kept, &cube);
        assert!(kept_error < 10.0, "tagged edges: {kept_error}° off");
    }

    #[test]
    fn bad_settings_and_empty_meshes_are_refused() {
        let mesh = primitives::icosphere(1.0, 1);
        for scale in [0.0, -1.0, f64::NAN] {
            let params = OptimizeParams {
                scale,
                ..OptimizeParams::default()
            };
            assert!(matches!(
                optimize(&mesh, &params),
                Err(OptimizeError::InvalidScale(_))
            ));
        }
        assert_eq!(
            optimize(&Mesh::default(), &OptimizeParams::default()),
            Err(OptimizeError::Empty)
        );
    }
}

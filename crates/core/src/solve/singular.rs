//! Detecting an undetermined system after a Cholesky factorization succeeded.
//!
//! A Laplacian with nothing fixed is singular: translations cost nothing. In exact
//! arithmetic its last Cholesky pivot is zero and faer reports a non-positive pivot, but in
//! floating point the pivot often comes out as a tiny positive number and the "solution"
//! drifts by an arbitrary translation. So after factoring we compare each pivot `L_kk²` with
//! its diagonal entry `N_kk`: that ratio is the part of the unknown the other unknowns do not
//! explain, and it is round-off only for an undetermined unknown.
//!
//! Measured (ignored test `pivot_margins` below): a cotan Laplacian with nothing fixed gives
//! ratios of 1e-15 at 100 unknowns to 2e-13 at 41k, 10 to 50 times below `n ε`; with one
//! vertex fixed the smallest ratio is 6e-6 at 62k unknowns and falls like `1 / n`. A threshold
//! of `4 n ε` sits between the two up to millions of unknowns.
//!
//! A current limitation: a well-posed system whose only anchors are very weak soft
//! constraints (weight below about 1e-3 against unit Laplacian rows, nothing fixed) is nearly
//! singular and can be reported as such.

use faer::sparse::linalg::cholesky::supernodal::SupernodalLltRef;
use faer::sparse::linalg::cholesky::{SymbolicCholesky, SymbolicCholeskyRaw};

/// Threshold on `L_kk² / N_kk`, per unknown; see the module docs.
const MIN_RELATIVE_PIVOT_PER_UNKNOWN: f64 = 4.0 * f64::EPSILON;

/// Whether a factor `l_values` of a matrix with diagonal `diagonal(j)` (in the original,
/// unpermuted numbering) has a pivot that is round-off only.
pub(crate) fn is_numerically_singular(
    symbolic: &SymbolicCholesky<u32>,
    l_values: &[f64],
    diagonal: impl Fn(usize) -> f64,
) -> bool {
    let n = symbolic.nrows();
    smallest_relative_pivot(symbolic, l_values, diagonal)
        < n as f64 * MIN_RELATIVE_PIVOT_PER_UNKNOWN
}

/// `min_k L_kk² / N_kk` over the factor.
fn smallest_relative_pivot(
    symbolic: &SymbolicCholesky<u32>,
    l_values: &[f64],
    diagonal: impl Fn(usize) -> f64,
) -> f64 {
    // Pivot k belongs to the original unknown perm_fwd[k].
    let original = |k: usize| {
        symbolic
            .perm()
            .map_or(k, |perm| perm.arrays().0[k] as usize)
    };
    let ratio = |k: usize, l_kk: f64| l_kk * l_kk / diagonal(original(k));
    match symbolic.raw() {
        SymbolicCholeskyRaw::Simplicial(simplicial) => {
            // Each column of the simplicial factor starts with its diagonal entry.
            let col_ptr = simplicial.col_ptr();
            (0..simplicial.nrows())
                .map(|k| ratio(k, l_values[col_ptr[k] as usize]))
                .fold(f64::INFINITY, f64::min)
        }
        SymbolicCholeskyRaw::Supernodal(supernodal) => {
            // Each supernode stores a dense column block whose top square is lower triangular.
            let llt = SupernodalLltRef::new(supernodal, l_values);
            (0..supernodal.n_supernodes())
                .flat_map(|s| {
                    let node = llt.supernode(s);
                    (0..node.val().ncols())
                        .map(move |j| ratio(node.start() + j, node.val()[(j, j)]))
                })
                .fold(f64::INFINITY, f64::min)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{cotan_laplacian, uniform_laplacian};
    use crate::mesh::primitives;
    use crate::solve::SparseMatrix;
    use crate::solve::normal::NormalSystem;
    use faer::Par;
    use faer::Side;
    use faer::dyn_stack::{MemBuffer, MemStack};
    use faer::sparse::linalg::cholesky::factorize_symbolic_cholesky;

    /// Factors `AᵀA` with the given fixed columns and returns whether faer saw a non-positive
    /// pivot, the smallest relative pivot otherwise, and whether the factor was supernodal.
    fn relative_pivot(a: &SparseMatrix, fixed: &[bool]) -> (Option<f64>, bool) {
        let system = NormalSystem::new(a, fixed);
        let symbolic = factorize_symbolic_cholesky(
            system.normal().symbolic(),
            Side::Lower,
            Default::default(),
            Default::default(),
        )
        .unwrap();
        let is_supernodal = matches!(symbolic.raw(), SymbolicCholeskyRaw::Supernodal(_));
        let mut memory = MemBuffer::new(
            symbolic.factorize_numeric_llt_scratch::<f64>(Par::Seq, Default::default()),
        );
        let mut values = vec![0.0; symbolic.len_val()];
        let is_factored = symbolic
            .factorize_numeric_llt::<f64>(
                &mut values,
                system.normal().as_ref(),
                Side::Lower,
                Default::default(),
                Par::Seq,
                MemStack::new(&mut memory),
                Default::default(),
            )
            .is_ok();
        let ratio = is_factored
            .then(|| smallest_relative_pivot(&symbolic, &values, |j| system.diagonal(j)));
        (ratio, is_supernodal)
    }

    #[test]
    fn both_factor_kinds_separate_singular_from_well_posed() {
        for (n, expect_supernodal) in [(8, false), (70, true)] {
            let mesh = primitives::grid(n, n, 1.0);
            let laplacian = cotan_laplacian(&mesh);
            let n_unknowns = mesh.n_vertices();
            let threshold = n_unknowns as f64 * MIN_RELATIVE_PIVOT_PER_UNKNOWN;
            let mut fixed = vec![false; n_unknowns];
            let (singular, is_supernodal) = relative_pivot(&laplacian, &fixed);
            assert_eq!(is_supernodal, expect_supernodal);
            // Either faer already failed (None) or the ratio is round-off.
            assert!(
                singular.is_none_or(|r| r < threshold),
                "{singular:?} at {n_unknowns}"
            );
            fixed[0] = true;
            let (posed, _) = relative_pivot(&laplacian, &fixed);
            assert!(
                posed.is_some_and(|r| r > 1e3 * threshold),
                "{posed:?} at {n_unknowns}"
            );
        }
    }

    /// Prints the margins quoted in the module docs. Run with
    /// `cargo test -p sketchmesh-core --release pivot_margins -- --ignored --nocapture`.
    #[test]
    #[ignore]
    fn pivot_margins() {
        let meshes =
            [10, 40, 100, 250].map(|n| (format!("grid {n}x{n}"), primitives::grid(n, n, 1.0)));
        let spheres = [2, 4, 6].map(|s| (format!("icosphere {s}"), primitives::icosphere(1.0, s)));
        for (name, mesh) in meshes.into_iter().chain(spheres) {
            for (kind, laplacian) in [
                ("uniform", uniform_laplacian(&mesh)),
                ("cotan", cotan_laplacian(&mesh)),
            ] {
                let mut fixed = vec![false; mesh.n_vertices()];
                let (singular, _) = relative_pivot(&laplacian, &fixed);
                fixed[0] = true;
                let (posed, _) = relative_pivot(&laplacian, &fixed);
                eprintln!("{name} {kind}: nothing fixed {singular:?}, one fixed {posed:?}");
            }
        }
    }
}

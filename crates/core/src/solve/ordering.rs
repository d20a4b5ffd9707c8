//! Fill-reducing orderings with some unknowns forced to the end.
//!
//! Hard constraints on a few unknowns are cheapest when those unknowns are eliminated last:
//! the forward substitution of a right-hand side that lives on them then only touches the
//! trailing block of the factor (see `Prefactored::forward_sparse_columns`). We take faer's
//! AMD ordering of the whole matrix and move the chosen unknowns behind the others, keeping
//! both groups in AMD's relative order: a constrained minimum-degree ordering (CAMD) would
//! fill in slightly less, but the moved set is a curve of a few hundred unknowns and its
//! dense trailing block is small next to the rest of the factor (measured in `deform`'s
//! benchmarks).

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::sparse::SymbolicSparseColMatRef;
use faer::sparse::linalg::amd;

use super::SolveError;

/// AMD ordering of the symmetric pattern `pattern` (one triangle suffices) with the unknowns
/// in `last` moved to the end: `(forward, inverse)` with `forward[position] = unknown`.
///
/// Errors: [`SolveError::Factorization`] when faer's AMD fails (out of memory or index
/// overflow).
pub(crate) fn amd_with_last(
    pattern: SymbolicSparseColMatRef<'_, u32>,
    last: &[usize],
) -> Result<(Vec<u32>, Vec<u32>), SolveError> {
    let n = pattern.ncols();
    let (mut forward, mut inverse) = (vec![0u32; n], vec![0u32; n]);
    let mut memory = MemBuffer::try_new(amd::order_scratch::<u32>(n, pattern.compute_nnz()))
        .map_err(|_| SolveError::Factorization("out of memory".to_owned()))?;
    amd::order(
        &mut forward,
        &mut inverse,
        pattern,
        Default::default(),
        MemStack::new(&mut memory),
    )
    .map_err(|err| SolveError::Factorization(format!("{err:?}")))?;
    let mut is_last = vec![false; n];
    for &j in last {
        is_last[j] = true;
    }
    let (mut front, back): (Vec<u32>, Vec<u32>) =
        forward.iter().partition(|&&j| !is_last[j as usize]);
    front.extend(back);
    for (position, &j) in front.iter().enumerate() {
        inverse[j as usize] = position as u32;
    }
    Ok((front, inverse))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::cotan_laplacian;
    use crate::mesh::primitives;
    use crate::solve::normal::NormalSystem;

    #[test]
    fn chosen_unknowns_come_last_and_the_rest_is_a_permutation() {
        let mesh = primitives::grid(9, 9, 1.0);
        let fixed = vec![false; mesh.n_vertices()];
        let system = NormalSystem::new(&cotan_laplacian(&mesh), &fixed);
        let last = [40, 3, 77];
        let (forward, inverse) = amd_with_last(system.normal().symbolic(), &last).unwrap();
        let n = forward.len();
        assert_eq!(n, mesh.n_vertices());
        let tail: Vec<usize> = forward[n - 3..].iter().map(|&j| j as usize).collect();
        let mut sorted_tail = tail.clone();
        sorted_tail.sort_unstable();
        assert_eq!(sorted_tail, vec![3, 40, 77]);
        for (position, &j) in forward.iter().enumerate() {
            assert_eq!(inverse[j as usize] as usize, position);
        }
    }
}

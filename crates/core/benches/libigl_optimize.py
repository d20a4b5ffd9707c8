"""Solves the Laplacian mesh optimization written by `examples/optimize_export.rs` with
libigl and checks that it matches ours.

The same normal equations in libigl's terms: energy `||A x - b||²`, so `Q = 2 AᵀA` and
`B = -2 Aᵀb`, no known values and no equality constraints; `min_quad_with_fixed_precompute`
is the factorization (its sparse Cholesky), `min_quad_with_fixed_solve` the solve.

Usage (libigl from PyPI, for example in a venv):
    cargo run --release -p sketchmesh-core --example optimize_export -- /tmp/optimize_compare
    python3 crates/core/benches/libigl_optimize.py /tmp/optimize_compare
Exits non-zero when the largest difference exceeds 1e-6 of the bounding-box diagonal.
"""

import sys

import igl
import numpy as np
import scipy.sparse as sp

from libigl_common import RUNS, median_ms, precompute, read_system


def main(directory):
    a, b = read_system(directory)
    cols = a.shape[1]
    ours = np.loadtxt(f"{directory}/ours.txt", ndmin=2)

    def build():
        return (2.0 * (a.T @ a)).tocsc(), -2.0 * (a.T @ b)

    (q, linear), build_ms = median_ms(build)
    known = np.zeros(0, dtype=np.int64)
    aeq = sp.csc_matrix((0, cols))

    data, factor_ms = median_ms(lambda: precompute(q, known, aeq))
    y = np.zeros((0, 3))
    beq = np.zeros((0, 3))
    x, solve_ms = median_ms(lambda: igl.min_quad_with_fixed_solve(data, linear, y, beq))

    diagonal = np.linalg.norm(ours.max(axis=0) - ours.min(axis=0))
    difference = np.abs(x - ours).max() / diagonal
    print(
        "optimize, libigl (min_quad_with_fixed): "
        f"build Q = 2AᵀA {build_ms:.1f} ms, precompute {factor_ms:.1f} ms, "
        f"solve {solve_ms:.1f} ms (median of {RUNS}); "
        f"largest difference {difference:.2e} of the diagonal"
    )
    return 0 if difference < 1e-6 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))

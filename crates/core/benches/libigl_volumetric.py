"""Solves the volumetric graph Laplacian frame written by `examples/volumetric_export.rs`
with libigl and checks that it matches ours.

The same least squares in libigl's terms: energy `||A d - b||²` over the displacements
`d`, so `Q = 2 AᵀA` and `B = -2 Aᵀb`, the held and moved graph points as known values;
`min_quad_with_fixed_precompute` is the factorization, `min_quad_with_fixed_solve` one
frame's solve.

Usage (libigl from PyPI, for example in a venv):
    cargo run --release -p sketchmesh-core --example volumetric_export -- /tmp/volumetric_compare
    python3 crates/core/benches/libigl_volumetric.py /tmp/volumetric_compare
Exits non-zero when the largest difference exceeds 1e-6 of the displacements' extent.
"""

import sys

import igl
import numpy as np
import scipy.sparse as sp

from libigl_common import RUNS, median_ms, precompute, read_system


def main(directory):
    a, b = read_system(directory)
    cols = a.shape[1]
    known = np.loadtxt(f"{directory}/known.txt", dtype=np.int64, ndmin=1)
    known_values = np.loadtxt(f"{directory}/known_values.txt", ndmin=2)
    ours = np.loadtxt(f"{directory}/ours.txt", ndmin=2)

    def build():
        return (2.0 * (a.T @ a)).tocsc(), -2.0 * (a.T @ b)

    (q, linear), build_ms = median_ms(build)
    aeq = sp.csc_matrix((0, cols))

    data, factor_ms = median_ms(lambda: precompute(q, known, aeq))
    beq = np.zeros((0, 3))
    x, solve_ms = median_ms(lambda: igl.min_quad_with_fixed_solve(data, linear, known_values, beq))

    extent = np.abs(ours).max()
    difference = np.abs(x - ours).max() / extent
    print(
        "volumetric, libigl (min_quad_with_fixed): "
        f"build Q = 2AᵀA {build_ms:.1f} ms, precompute {factor_ms:.1f} ms, "
        f"solve {solve_ms:.2f} ms (median of {RUNS}); "
        f"largest difference {difference:.2e} of the largest displacement"
    )
    return 0 if difference < 1e-6 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))

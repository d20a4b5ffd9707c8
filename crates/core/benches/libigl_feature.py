"""Solves the feature-sketch region system written by `examples/feature_export.rs` with
libigl and checks that it matches ours (`core::feature`, through `core::deform`'s system).

In libigl's terms: the cotangent weights of `igl.cotmatrix`, clamped at zero and normalised
per row (`L = I - D⁻¹ W`, Nealen Eq. 4.3), rows for the region and its first anchor ring,
energy `||L d - Δδ||²` over the displacements `d` with `Δδ = (a - 1) L x` on the region's rows
(a bump of factor `a`) and 0 on the ring's, so `Q = 2 LᵀL` and `B = -2 Lᵀ Δδ`; `d = 0`
outside the region (`known`). `min_quad_with_fixed_precompute` is the factorization,
`min_quad_with_fixed_solve` one solve.

Usage (libigl from PyPI, for example in a venv):
    cargo run --release -p sketchmesh-core --example feature_export -- /tmp/feature_compare
    python3 crates/core/benches/libigl_feature.py /tmp/feature_compare
Exits non-zero when the largest difference exceeds 1e-6 of the bounding-box diagonal.
"""

import sys

import igl
import numpy as np
import scipy.sparse as sp

from libigl_common import RUNS, median_ms, precompute, region_rows


def main(directory):
    v, f, _ = igl.readOFF(f"{directory}/mesh.off")
    roi = np.loadtxt(f"{directory}/roi.txt", dtype=bool)
    amount = float(np.loadtxt(f"{directory}/amount.txt"))
    ours = np.loadtxt(f"{directory}/ours.txt")
    n = v.shape[0]

    def build():
        rows, row_ids = region_rows(v, f, roi)
        change = (amount - 1.0) * (rows @ v) * roi[row_ids][:, None]
        return (2.0 * (rows.T @ rows)).tocsc(), -2.0 * (rows.T @ change)

    (q, b), build_ms = median_ms(build)
    known = np.flatnonzero(~roi).astype(np.int64)
    y = np.zeros((known.size, 3))
    aeq = sp.csc_matrix((0, n))
    beq = np.zeros((0, 3))

    data, factor_ms = median_ms(lambda: precompute(q, known, aeq))
    d, solve_ms = median_ms(lambda: igl.min_quad_with_fixed_solve(data, b, y, beq))
    x = v + d

    diagonal = np.linalg.norm(v.max(axis=0) - v.min(axis=0))
    difference = np.abs(x - ours).max() / diagonal
    print(
        f"libigl (PyPI): {n} vertices, region {roi.sum()}; "
        f"build Q {build_ms:.1f} ms, precompute {factor_ms:.1f} ms, solve {solve_ms:.2f} ms "
        f"(median of {RUNS})"
    )
    print(f"max |ours - libigl| / bbox diagonal = {difference:.2e}")
    return 0 if difference < 1e-6 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "/tmp/feature_compare"))

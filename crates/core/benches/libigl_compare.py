"""Solves the over-sketch edit written by `examples/deform_export.rs` with libigl and checks
that it matches our linear, exact-handle Laplacian edit (`core::deform`, `Rotations::None`).

The same problem in libigl's terms: the cotangent weights of `igl.cotmatrix`, clamped at zero
and normalised per row (`L = I - D⁻¹ W`, Nealen Eq. 4.3), rows for the ROI and its first
anchor ring, energy `||L d||²` over the displacements `d = x - p` (so `Q = 2 LᵀL`, `B = 0`),
`d = 0` outside the ROI (`known`), and the handles as equality constraints
`Σ w_k d_k = target - Σ w_k p_k` (`Aeq`, `Beq`). `min_quad_with_fixed_precompute` is the
factorization, `min_quad_with_fixed_solve` one solve.

Usage (libigl from PyPI, for example in a venv):
    cargo run --release -p sketchmesh-core --example deform_export -- /tmp/deform_compare
    python3 crates/core/benches/libigl_compare.py /tmp/deform_compare
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
    handles = np.loadtxt(f"{directory}/handles.txt", ndmin=2)
    targets = np.loadtxt(f"{directory}/targets.txt", ndmin=2)
    ours = np.loadtxt(f"{directory}/ours_linear.txt")
    n = v.shape[0]

    def build():
        rows, _ = region_rows(v, f, roi)
        return (2.0 * (rows.T @ rows)).tocsc()

    q, build_ms = median_ms(build)
    known = np.flatnonzero(~roi).astype(np.int64)
    vertices = handles[:, :3].astype(np.int64)
    weights = handles[:, 3:]
    k = handles.shape[0]
    aeq = sp.csc_matrix(
        (weights.ravel(), (np.repeat(np.arange(k), 3), vertices.ravel())), shape=(k, n)
    )
    beq = targets - aeq @ v
    y = np.zeros((known.size, 3))
    b = np.zeros((n, 3))

    data, factor_ms = median_ms(lambda: precompute(q, known, aeq))
    d, solve_ms = median_ms(lambda: igl.min_quad_with_fixed_solve(data, b, y, beq))
    x = v + d

    diagonal = np.linalg.norm(v.max(axis=0) - v.min(axis=0))
    difference = np.abs(x - ours).max() / diagonal
    handle_error = np.abs(aeq @ x - targets).max() / diagonal
    print(
        f"libigl (PyPI): {n} vertices, ROI {roi.sum()}, {k} handles; "
        f"build Q {build_ms:.1f} ms, precompute {factor_ms:.1f} ms, solve {solve_ms:.2f} ms "
        f"(median of {RUNS})"
    )
    print(
        f"max |ours - libigl| / bbox diagonal = {difference:.2e}; "
        f"libigl handle error / diagonal = {handle_error:.2e}"
    )
    return 0 if difference < 1e-6 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "/tmp/deform_compare"))

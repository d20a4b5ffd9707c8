"""What the libigl comparisons share: timing (the median of a few runs), and the Laplacian
editing system of `core::deform` in libigl's terms."""

import time

import igl
import numpy as np
import scipy.sparse as sp

RUNS = 5


def median_ms(f):
    """Runs `f` RUNS times; its last result and the median time in ms."""
    samples = []
    result = None
    for _ in range(RUNS):
        start = time.perf_counter()
        result = f()
        samples.append(time.perf_counter() - start)
    return result, 1e3 * sorted(samples)[len(samples) // 2]


def read_system(directory):
    """The sparse `A` (`a.txt`: `rows cols`, then `row col value` per entry) and `b`
    (`b.txt`, `x y z` per row) an export wrote."""
    with open(f"{directory}/a.txt") as lines:
        rows, cols = map(int, lines.readline().split())
    entries = np.loadtxt(f"{directory}/a.txt", skiprows=1, ndmin=2)
    a = sp.csc_matrix(
        (entries[:, 2], (entries[:, 0].astype(np.int64), entries[:, 1].astype(np.int64))),
        shape=(rows, cols),
    )
    return a, np.loadtxt(f"{directory}/b.txt", ndmin=2)


def region_rows(v, f, roi):
    """The normalised cotangent Laplacian rows (`L = I - D⁻¹ W`, weights of `igl.cotmatrix`
    clamped at zero, Nealen Eq. 4.3) of the region `roi` and its first anchor ring, and which
    vertices those rows belong to."""
    n = v.shape[0]
    cot = igl.cotmatrix(v, f).tocsr()
    w = (cot - sp.diags(cot.diagonal())).tocsr()
    w.data = np.maximum(w.data, 0.0)
    inv_degree = 1.0 / np.asarray(w.sum(axis=1)).ravel()
    laplacian = sp.identity(n, format="csr") - sp.diags(inv_degree) @ w
    adjacency = w.copy()
    adjacency.data[:] = 1.0
    ring1 = (adjacency @ roi.astype(float) > 0) & ~roi
    row_ids = np.flatnonzero(roi | ring1)
    return laplacian[row_ids], row_ids


def precompute(q, known, aeq):
    """libigl's factorization of `min_quad_with_fixed` for `Q`, the known unknowns and the
    equality constraints `aeq`."""
    data = igl.min_quad_with_fixed_data()
    igl.min_quad_with_fixed_precompute(q, known, aeq, True, data)
    return data

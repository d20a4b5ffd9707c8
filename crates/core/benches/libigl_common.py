"""What the libigl comparisons share: timing (the median of a few runs)."""

import time

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

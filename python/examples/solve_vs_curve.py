"""One `solve` against one sample of `curve`, the ratio issue 24 asks to bring within 2:
the median of 200 `ae.solve(arch, mu)` calls (eta*, its pattern and mechanism, every limit
state above eta_s, the extreme rays, the lines of the figure) and of the cost per friction
coefficient of `ae.curve` over 400 coefficients from mu to mu + 0.2 on one thread (eta*
alone, each sample continued from its neighbour), in one process.

    python python/examples/solve_vs_curve.py
"""

import math
import statistics
import time

import numpy as np

import arch_enum as ae

CASES = [(0.0, 0.35), (1.0, 2.0), (0.0, math.inf)]


def median_seconds(fn, repeat):
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return statistics.median(times)


def main():
    print("| alpha | mu | solve [ms] | curve sample [ms] | ratio |")
    print("|---:|---:|---:|---:|---:|")
    for alpha, mu in CASES:
        arch = ae.Arch(alpha=alpha)
        ae.solve(arch, mu)  # warm-up
        solve = median_seconds(lambda: ae.solve(arch, mu), 200)
        # at mu = inf the curve runs from mu = 5 (eta* no longer depends on mu there)
        lo = mu if math.isfinite(mu) else 5.0
        mus = np.linspace(lo, lo + 0.2, 400)
        sample = median_seconds(lambda: ae.curve(arch, mus, threads=1), 5) / len(mus)
        print(f"| {alpha} | {mu} | {solve * 1e3:.3f} | {sample * 1e3:.4f} | {solve / sample:.1f} |")


if __name__ == "__main__":
    main()

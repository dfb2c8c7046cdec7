"""1,000 solves of eta*(mu) for the semicircle, mu geometrically spaced over [0.31, 10]:
from Python (one vectorised `curve` call on every core and on one thread, and a loop of
1,000 calls) beside the command line (one `arch-enum curve --points 1000` process, and
1,000 processes of one point each), in one run. The command line's mu grid is the same
(mu_grid: geometric, both ends included); both compute mu_ms once per call.

    python python/examples/thousand_solves.py [path/to/arch-enum]
"""

import os
import subprocess
import sys
import time

import numpy as np

import arch_enum as ae

N = 1000
LO, HI = 0.31, 10.0


def timed(fn, repeat=3):
    best = float("inf")
    for _ in range(repeat):
        t = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t)
    return best, out


def main():
    binary = sys.argv[1] if len(sys.argv) > 1 else os.environ.get("ARCH_ENUM_BIN", "arch-enum")
    arch = ae.Arch(alpha=0)
    mus = np.geomspace(LO, HI, N)
    rows = []
    t, c = timed(lambda: ae.curve(arch, mus))
    rows.append((f"python: curve(arch, mu[{N}]), {os.cpu_count()} threads", t, c.eta))
    t, c1 = timed(lambda: ae.curve(arch, mus, threads=1))
    rows.append((f"python: curve(arch, mu[{N}], threads=1)", t, c1.eta))
    t, loop = timed(lambda: np.array([ae.curve(arch, m, threads=1).eta[0] for m in mus]), 1)
    rows.append((f"python: {N} calls curve(arch, mu)", t, loop))

    def cli_curve():
        out = subprocess.run([binary, "curve", "--alpha", "0", "--mu-min", str(LO), "--mu-max",
                              str(HI), "--points", str(N), "--json"], capture_output=True,
                             text=True, check=True)
        import json
        return np.array([p["eta"] for p in json.loads(out.stdout)["points"]], dtype=float)

    t, cli = timed(cli_curve)
    rows.append((f"cli: one `curve --points {N}` process", t, cli))

    def cli_processes():
        import json
        etas = []
        for m in mus:
            out = subprocess.run([binary, "curve", "--alpha", "0", "--mu-min", repr(float(m)),
                                  "--mu-max", repr(float(m)), "--points", "1", "--json"],
                                 capture_output=True, text=True, check=True)
            etas.append(json.loads(out.stdout)["points"][0]["eta"])
        return np.array(etas, dtype=float)

    t, procs = timed(cli_processes, 1)
    rows.append((f"cli: {N} `curve --points 1` processes", t, procs))
    print(f"LP solver of the Python build: {ae.LP_SOLVER}; command line: HiGHS")
    for name, t, eta in rows:
        diff = np.nanmax(np.abs(eta - c.eta) / c.eta)
        print(f"{name:45} {t:8.3f} s  {1e3 * t / N:7.3f} ms/solve  max rel diff {diff:.1e}")


if __name__ == "__main__":
    main()

"""curve() releases the GIL while it solves: another Python thread keeps running.

The main thread counts loop iterations while a worker thread is inside one long
`curve` call. Were the GIL held, it could run only until the worker entered the
extension (one switch interval, 5 ms); released, it runs for most of the call."""

import threading
import time

import numpy as np

import arch_enum as ae


def test_curve_releases_the_gil():
    arch = ae.Arch(alpha=0)
    mus = np.geomspace(0.31, 10, 1500)
    ae.curve(arch, mus[:10], threads=1)  # warm up
    state = {"inside": False, "t": 0.0}

    def work():
        state["inside"] = True
        t = time.perf_counter()
        ae.curve(arch, mus, threads=1)
        state["t"] = time.perf_counter() - t
        state["inside"] = False

    worker = threading.Thread(target=work)
    during = 0
    worker.start()
    while worker.is_alive():
        if state["inside"]:
            during += 1
    worker.join()
    # the main thread's own rate, for scale
    n, t0 = 0, time.perf_counter()
    while time.perf_counter() - t0 < 0.1:
        n += 1
    rate = n / 0.1
    assert state["t"] > 0.1, state
    # at least a tenth of the call's duration worth of iterations (a held GIL allows
    # about 5 ms)
    assert during > 0.1 * rate * state["t"], (during, rate, state["t"])

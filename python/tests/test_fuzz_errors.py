"""A seeded fuzz of bad calls: every public function and argument, one bad argument at a
time among good ones, each call a ValueError or TypeError whose message names the Python
argument (never another exception, never a crash, never an answer)."""

import math
import random

import numpy as np
import pytest

import arch_enum as ae

SEMI = ae.Arch(alpha=0)
TEN = ae.Arch(alpha=0, blocks=10)

# values that are no number at all
NOT_NUMBERS = ["x", "", "1.0.0", [], [1.0, 2.0], {}, object(), b"1", complex(1, 2), True,
               np.array([[1.0]]), ae]
NOT_FINITE = [math.nan, -math.inf, math.inf]
NEGATIVE = [-1.0, -1e-300, -math.inf, -(2**64)]
NOT_WHOLE = ["2", 2.5, 3.0, [], None.__class__, True, np.float64(2.0), complex(1, 0)]


def scalar_bad(extra=()):
    return NOT_NUMBERS + list(extra)


# (the argument named, the call with `v` in its place, the bad values)
CASES = [
    ("alpha", lambda v: ae.Arch(alpha=v), scalar_bad([2.0, -2.0, math.nan, math.inf, 1e300])),
    ("blocks", lambda v: ae.Arch(alpha=0, blocks=v), NOT_WHOLE + [0, -3, 100001, 2**64]),
    ("joints", lambda v: ae.Arch(alpha=0, joints=v),
     ["abc", ["a", "b"], [0.5, 4.0], [2.0, 1.0], [[0.1, 0.2]], [math.nan], 3, object()]),
    ("weight", lambda v: ae.Arch(alpha=0, weight=v), ["middle", "", 3, None, b"centroid"]),
    ("fill_ratio", lambda v: ae.Arch(alpha=0, fill_ratio=v, fill_height=0.1),
     scalar_bad(NEGATIVE + [math.nan, math.inf])),
    ("fill_height", lambda v: ae.Arch(alpha=0, fill_ratio=1.0, fill_height=v),
     scalar_bad(NEGATIVE + [math.nan, math.inf])),
    ("span", lambda v: ae.Arch.from_span_rise(v, 5.0), scalar_bad(NEGATIVE + [0.0, math.nan])),
    ("rise", lambda v: ae.Arch.from_span_rise(10.0, v), scalar_bad(NEGATIVE + [0.0, math.nan])),
    ("arch", lambda v: ae.solve(v, 0.4), [None, 0, "semicircle", {"alpha": 0}]),
    ("mu", lambda v: ae.solve(SEMI, v), scalar_bad([0.0, -1.0, math.nan, -math.inf, 1e201, "max"])),
    ("mu", lambda v: ae.curve(SEMI, v), [[0.4, "x"], "x", [[0.4]], object(), {}]),
    ("threads", lambda v: ae.curve(SEMI, [0.4], threads=v), NOT_WHOLE + [0, -1, 2**64]),
    ("arch", lambda v: ae.modes(v), [None, 1.0, "arch"]),
    ("eta", lambda v: ae.assess(SEMI, v, 0.6), scalar_bad([0.0, -0.1, 2.5, math.nan])),
    ("mu", lambda v: ae.assess(SEMI, 0.2, v), scalar_bad([0.0, -1.0, math.nan])),
    ("eta", lambda v: ae.load(SEMI, v, 0.6, horizontal="right"),
     scalar_bad([0.0, -0.1, 2.5, math.nan])),
    ("mu", lambda v: ae.load(SEMI, 0.2, v, horizontal="right"), scalar_bad([0.0, math.nan])),
    ("horizontal", lambda v: ae.load(SEMI, 0.2, 0.6, horizontal=v), ["up", "", 1, "Right"]),
    ("point_load", lambda v: ae.load(SEMI, 0.2, 0.6, point_load=v),
     scalar_bad([-1.0, 4.0, math.nan, math.inf])),
    ("point_load_deg", lambda v: ae.load(SEMI, 0.2, 0.6, point_load_deg=v),
     scalar_bad([-10.0, 200.0, math.nan])),
    ("point_load_joint", lambda v: ae.load(TEN, 0.2, 0.6, point_load_joint=v),
     NOT_WHOLE + [-1, 11, 2**64]),
    ("mu", lambda v: ae.certify(SEMI, v), scalar_bad([0.0, -1.0, math.nan])),
    ("gap", lambda v: ae.certify(SEMI, 0.4, gap=v), scalar_bad([0.0, 1.0, -1e-12, math.nan])),
    ("certificate", lambda v: ae.verify(v),
     ["[1]", "/nonexistent/cert.json", "{", "{}", {"version": 2}, 3, None, b"{}"]),
    ("eta", lambda v: ae.run("assess", SEMI, eta=v, mu=0.6), scalar_bad([0.0, 2.5, math.nan])),
    ("mu_max", lambda v: ae.load_curve(SEMI, eta=0.3, horizontal="right", mu_min=0.5,
                                       mu_max=v), scalar_bad([0.1, -1.0, math.nan])),
    ("axles", lambda v: ae.critical(span=10, rise=5, ring=0.6, width=1, unit_weight=20, mu=0.6,
                                    axles=v), ["x", "", [], [[100]], {}, object(), [-5], b"1"]),
    ("gap", lambda v: ae.certify_load(SEMI, eta=0.3, mu=0.6, horizontal="left", gap=v),
     scalar_bad([0.0, 1.0, math.nan])),
    ("eta", lambda v: ae.report(SEMI, eta=v, mu=0.6), scalar_bad([0.0, 2.5])),
    ("mu", lambda v: ae.plot("arch", SEMI, mu=v), scalar_bad([0.0, -1.0, math.nan])),
    ("figure", lambda v: ae.plot(v, SEMI, mu=0.4), ["", "pie", 3, None]),
    ("command", lambda v: ae.run(v, SEMI), ["serve", "report", "", None, 1]),
    ("span", lambda v: ae.geometry(v, 5.0, 0.6), scalar_bad(NEGATIVE + [0.0, math.nan])),
    ("ring", lambda v: ae.geometry(10.0, 5.0, v), scalar_bad(NEGATIVE + [0.0, math.nan])),
]


def test_five_hundred_bad_calls_name_their_argument():
    rng = random.Random(20261127)
    calls = [(name, call, v) for name, call, values in CASES for v in values]
    # every listed call once, then seeded repeats in a shuffled order up to 600
    picked = calls + [rng.choice(calls) for _ in range(600 - len(calls))]
    rng.shuffle(picked)
    assert len(picked) >= 500
    failures = set()
    for name, call, v in picked:
        try:
            got = call(v)
        except (ValueError, TypeError) as e:
            message = str(e)
            if name not in message:
                failures.add(f"{name}={v!r}: {type(e).__name__}: {message}")
            elif "--" in message:
                failures.add(f"{name}={v!r}: names a CLI flag: {message}")
        except Exception as e:  # noqa: BLE001 - the point of the test
            failures.add(f"{name}={v!r}: {type(e).__name__}: {e}")
        else:
            failures.add(f"{name}={v!r}: no error, got {type(got).__name__}")
    assert not failures, "\n".join(sorted(failures))


def test_the_hundred_block_modes():
    m = ae.modes(ae.Arch(alpha=0.0, blocks=100))
    assert m.corners, "a 100-block semicircle has corners"
    for c in m.corners:
        assert c.residual is None or c.residual >= 0.0

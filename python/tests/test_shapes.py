"""The result types: frozen dataclasses, read-only numpy arrays of the stated shapes,
to_dict() as plain data, to_pandas()."""

import dataclasses
import json
import math

import numpy as np
import pytest

import arch_enum as ae


@pytest.fixture(scope="module")
def res():
    return ae.solve(ae.Arch(alpha=0), mu=0.35)


def test_frozen(res):
    for obj in (res, res.arch, res.pattern[0], res.reactions, res.mechanism, res.checks):
        assert dataclasses.is_dataclass(obj)
        field = dataclasses.fields(obj)[0].name
        with pytest.raises(dataclasses.FrozenInstanceError):
            setattr(obj, field, None)
    with pytest.raises(ValueError):
        res.thrust_line[0, 0] = 1.0  # arrays are read-only


def test_arrays(res):
    n = len(res.pattern)
    assert res.mechanism.beta.shape == (n,) and res.mechanism.rate.shape == (n,)
    assert len(res.mechanism.kind) == n
    assert [c.kind for c in res.pattern] == list(res.mechanism.kind)
    assert res.thrust_line.ndim == 2 and res.thrust_line.shape[1] == 2
    assert res.friction_line.shape == res.thrust_line.shape
    assert res.outline.shape[1] == 2
    np.testing.assert_array_equal(res.outline[0], res.outline[-1])  # closed
    for a in (res.lines.beta, res.lines.n, res.lines.e_m, res.lines.e_t):
        assert a.shape == res.lines.beta.shape and a.dtype == np.float64
    # the line of thrust lies within the arch's thickness (an admissible state) ...
    radius = np.hypot(res.thrust_line[:, 0], res.thrust_line[:, 1])
    eta = res.eta_drawn
    assert np.all(radius <= 1 + eta / 2 + 1e-9) and np.all(radius >= 1 - eta / 2 - 1e-9)
    # ... and touches it at the hinges (to the sampling: 801 angles, tangent there)
    for c in res.pattern:
        if c.kind.startswith("hinge"):
            k = np.argmin(np.abs(res.lines.beta - c.beta))
            edge = 1 + eta / 2 if c.kind == "hinge_extrados" else 1 - eta / 2
            assert abs(radius[k] - edge) < 1e-4
    assert res.arch.springings == (0.0, math.pi)
    assert res.arch.symmetric and res.arch.joint_angles is None
    d = ae.Arch(alpha=0.5, blocks=12)
    assert d.joint_angles.shape == (13,) and d.joint_angles[0] == -0.5
    assert d.joints is None and d.blocks == 12


def test_arch_value_semantics():
    a = ae.Arch(alpha=0)
    assert a == ae.Arch(alpha=0.0) and hash(a) == hash(ae.Arch(alpha=0.0))
    assert dataclasses.replace(a, blocks=8).joint_angles.shape == (9,)
    assert ae.Arch(alpha=0, joints=np.array([0.5, 1.0])).joints == (0.5, 1.0)


def test_to_dict(res):
    # the command's document, key for key (the lines drawn are not part of it)
    d = res.to_dict()
    assert d["eta"] == res.eta and d["status"] == "ok"
    assert d["arch"]["beta_right"] == 0.0 and d["arch"]["joints"] == "continuous"
    assert d["pattern"][0] == {"beta": 0.0, "kind": "slide_plus", "at": "springing"}
    assert "thrust_line" not in d and res.thrust_line.shape[1] == 2
    json.dumps(d)  # plain data
    inf = ae.solve(ae.Arch(alpha=0), mu=math.inf)
    assert inf.to_dict()["mu"] == math.inf and inf.friction_line is None


def test_curve_shapes_and_pandas():
    mus = np.geomspace(0.25, 4.0, 9)
    c = ae.curve(ae.Arch(alpha=0), mus)
    assert len(c) == 9
    for a in (c.mu, c.eta, c.friction_angle_deg):
        assert a.shape == (9,) and a.dtype == np.float64
    np.testing.assert_array_equal(c.mu, mus)
    assert len(c.column("status")) == len(c.mode) == len(c.pattern) == len(c.message) == 9
    assert c.status == "ok" and len(c.points) == 9
    df = c.to_pandas()
    assert set(df.columns) == {"mu", "friction_angle_deg", "status", "eta", "mode", "pattern",
                               "message"}
    assert len(df) == 9 and df["status"].iloc[0] == "no_equilibrium"
    np.testing.assert_array_equal(df["eta"].to_numpy(), c.eta)
    json.dumps(c.to_dict(), allow_nan=True)


def test_svg_figures(res):
    svg = res._repr_svg_()
    assert svg.lstrip().startswith("<svg") or svg.lstrip().startswith("<?xml")
    assert "mixed_sliding_rotational" in svg or "mixed sliding" in svg.replace("_", " ")

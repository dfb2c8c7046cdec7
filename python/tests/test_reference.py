"""Reference values, statuses and the answer's own checks, through the Python API.

Reference values: the semicircle (alpha = 0, centreline weight) at mu = 0.35,
eta* = 0.15291973385 (11 digits), and at mu = inf the Couplet-Heyman value
eta* = 0.107426452755 (12 digits); both computed independently in
tests/it/continuum_reference.rs and quoted in issue 13.
"""

import copy
import math

import numpy as np
import pytest

import arch_enum as ae


def test_semicircle_mu_035_to_11_digits():
    r = ae.solve(ae.Arch(alpha=0), mu=0.35)
    assert r.status == "ok"
    assert f"{r.eta:.11f}" == "0.15291973385"
    assert abs(r.eta - 0.15291973385) < 1e-11
    assert r.mode == "mixed_sliding_rotational"
    assert r.unique is True
    assert r.mu == 0.35


def test_couplet_heyman_mu_inf_to_12_digits():
    r = ae.solve(ae.Arch(alpha=0), mu=float("inf"))
    assert r.status == "ok"
    assert f"{r.eta:.12f}" == "0.107426452755"
    assert abs(r.eta - 0.107426452755) < 1e-12
    assert r.mode == "purely_rotational"
    assert r.mu == math.inf
    assert r.friction_angle_deg == 90.0
    # no line of friction where no joint can slide
    assert r.friction_line is None


def test_limit_state_certificates_hold():
    """The mechanism of the answer is compatible and complementary, rates sum to 1, and
    the virtual-work balance (external power = frictional dissipation) holds."""
    r = ae.solve(ae.Arch(alpha=0), mu=0.35)
    m = r.mechanism
    assert m.compatibility_residual < 1e-12
    assert m.complementarity_residual < 1e-12
    assert abs(float(np.sum(m.rate)) - 1.0) < 1e-12
    assert np.all(m.rate >= 0)
    assert abs(m.power - m.dissipation) < 1e-12
    assert r.checks.newton_residual < 1e-12
    lo, hi = r.checks.eta_bracket
    assert lo <= r.eta * (1 + 1e-9) and r.eta <= hi * (1 + 1e-9)


def test_statuses_are_results_not_exceptions():
    # below mu_ms no thickness stands
    r = ae.solve(ae.Arch(alpha=0), mu=0.2)
    assert r.status == "no_equilibrium"
    assert r.eta is None and r.mode is None and r.pattern is None
    assert r.mu_ms is not None and abs(r.mu_ms - 0.30921544433) < 1e-10
    assert "mu_ms" in r.message
    assert r._repr_svg_() is None
    assert r.thrust_line.shape == (0, 2)
    with pytest.raises(ValueError, match="no limit state"):
        r.compas_json()
    # a horseshoe arch too open to stand at any thickness
    assert ae.solve(ae.Arch(alpha=1.35), mu=math.inf).status == "no_equilibrium"
    # two voussoirs stand at every thickness: no least thickness
    r = ae.solve(ae.Arch(alpha=0, blocks=2), mu=math.inf)
    assert r.status == "no_collapse"
    assert r.message


def test_curve_matches_solve_and_is_thread_independent():
    arch = ae.Arch(alpha=0)
    mus = np.array([0.2, 0.31, 0.35, 0.5, 1.0, 3.0, math.inf])
    c = ae.curve(arch, mus)
    c1 = ae.curve(arch, mus, threads=1)
    assert c.column("status") == c1.column("status")
    np.testing.assert_array_equal(c.eta, c1.eta)
    assert c.column("status")[0] == "no_equilibrium" and math.isnan(c.eta[0])
    assert c.message[0]
    assert c.mu[-1] == math.inf
    for mu, eta, status in zip(c.mu[1:], c.eta[1:], c.column("status")[1:]):
        assert status == "ok"
        assert abs(eta - ae.solve(arch, mu).eta) < 1e-12 * eta
    assert abs(c.eta[2] - 0.15291973385) < 1e-11
    assert abs(c.mu_ms - 0.30921544433) < 1e-10
    # eta*(mu) does not increase with mu
    ok = ~np.isnan(c.eta)
    assert np.all(np.diff(c.eta[ok]) <= 1e-12)
    # a scalar mu is an array of one
    one = ae.curve(arch, 0.35)
    assert one.eta.shape == (1,) and one.eta[0] == c.eta[2]


def test_assess_modes_load():
    arch = ae.Arch(alpha=0)
    a = ae.assess(arch, eta=0.2, mu=0.35)
    assert a.stands and a.status == "ok"
    assert abs(a.eta_min - 0.15291973385) < 1e-11
    assert abs(a.geometric_factor - 0.2 / a.eta_min) < 1e-12
    assert a.mu_min < 0.35 and abs(a.friction_factor - 0.35 / a.mu_min) < 1e-12
    assert "<svg" in a._repr_svg_()

    m = ae.modes(arch)
    assert m.status == "ok"
    assert [b.mode for b in m.branches] == [
        "purely_rotational", "mixed_sliding_rotational", "purely_sliding"]
    assert m.branches[0].mu_max == math.inf
    assert m.branches[-1].eta_max == math.inf
    assert abs(m.branches[0].eta_min - 0.107426452755) < 1e-12
    assert len(m.corners) == 2 and all(c.exact for c in m.corners)
    assert abs(m.mu_ms - 0.30921544433) < 1e-10
    assert "<svg" in m._repr_svg_()

    ld = ae.load(ae.Arch(alpha=0, blocks=20), eta=0.3, mu=0.8, horizontal="right")
    assert ld.status == "ok" and ld.load.kind == "horizontal" and ld.load.towards == "right"
    assert ld.lambda_ is not None and 0 < ld.lambda_ <= ld.lambda_static
    assert ld.limit_states and ld.limit_states[0].lambda_ == ld.lambda_
    assert "<svg" in ld._repr_svg_()
    # a point load by joint index is the same load as by its angle in degrees
    by_joint = ae.load(ae.Arch(alpha=0, blocks=20), eta=0.3, mu=0.8, point_load_joint=7)
    by_deg = ae.load(ae.Arch(alpha=0, blocks=20), eta=0.3, mu=0.8, point_load_deg=63.0)
    assert by_joint.load.beta == by_deg.load.beta and by_deg.load.at_joint
    assert by_joint.lambda_ == by_deg.lambda_


def test_certify_then_verify():
    c = ae.certify(ae.Arch(alpha=0), mu=0.35)
    assert c.status == "ok" and c.claim == "least_thickness"
    assert c.eta_lo <= 0.15291973385 + 1e-11 and 0.15291973385 - 1e-11 <= c.eta_hi
    assert c.gap_relative <= 1e-12
    v = ae.verify(c)
    assert v.status == "ok" and v.statement and v.checks
    assert ae.verify(c.certificate).status == "ok"
    # a tampered certificate is rejected, not raised
    bad = copy.deepcopy(c.certificate)
    bad["safe"]["eta"] = c.eta_lo * 0.9
    rejected = ae.verify(bad)
    assert rejected.status == "rejected" and rejected.reason


def test_mu_ms_is_the_corner_of_the_vertical_branch():
    """mu="ms": the paper's eta_ms (reference-values.md, 8 digits), not unique, with the
    purely sliding limit states of the vertical branch; as `solve --mu ms` says."""
    r = ae.solve(ae.Arch(alpha=0), mu="ms")
    assert r.status == "ok"
    assert abs(r.mu - 0.30921544) < 5e-9
    assert abs(r.eta - 0.20063732) < 5e-9
    assert r.unique is False
    assert r.vertical_branch is not None
    assert r.vertical_branch.mode == "purely_sliding"
    assert r.vertical_branch.eta_min == r.eta
    assert all(c.kind.startswith("slide") for c in r.vertical_branch.pattern)
    with pytest.raises(ValueError, match="mu"):
        ae.solve(ae.Arch(alpha=0, blocks=2), mu="ms")
    with pytest.raises(TypeError, match="mu"):
        ae.solve(ae.Arch(alpha=0), mu="xs")

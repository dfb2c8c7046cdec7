"""Bad input raises ValueError naming the Python argument (never the CLI flag) and its
valid range; wrong types raise TypeError."""

import math

import pytest

import arch_enum as ae

SEMI = ae.Arch(alpha=0)


def raises(fn, *names):
    """fn() raises ValueError whose message names every one of `names` and no flag."""
    with pytest.raises(ValueError) as e:
        fn()
    message = str(e.value)
    for n in names:
        assert n in message, message
    assert "--" not in message, message
    return message


def test_arch_arguments():
    m = raises(lambda: ae.Arch(alpha=2.0), "invalid value for alpha: 2", "(-pi/2, pi/2)")
    raises(lambda: ae.Arch(alpha=math.nan), "alpha")
    raises(lambda: ae.Arch(beta_right=1.0, beta_left=0.5), "beta_right/beta_left")
    raises(lambda: ae.Arch(beta_right=0.0, beta_left=7.0), "beta_right/beta_left", "overlap")
    raises(lambda: ae.Arch(beta_right=0.0), "beta_right/beta_left")
    raises(lambda: ae.Arch(), "alpha")
    raises(lambda: ae.Arch(alpha=0, beta_right=0.0, beta_left=3.0), "alpha/beta_right/beta_left")
    raises(lambda: ae.Arch(alpha=0, blocks=0), "invalid value for blocks: 0", "1 to 100000")
    raises(lambda: ae.Arch(alpha=0, blocks=-3), "invalid value for blocks: -3")
    raises(lambda: ae.Arch(alpha=0, blocks=100001), "blocks")
    raises(lambda: ae.Arch(alpha=0, joints=[0.0, 2.0, 1.0, math.pi]), "joints", "increasing")
    raises(lambda: ae.Arch(alpha=0, joints=[0.5, 4.0]), "invalid value for joints: 4")
    raises(lambda: ae.Arch(alpha=0, blocks=4, joints=[1.0]), "blocks/joints")
    raises(lambda: ae.Arch(alpha=0, weight="middle"), "weight", "centreline", "centroid")
    raises(lambda: ae.Arch(alpha=0, fill_ratio=-1.0, fill_height=0.1), "invalid value for fill_ratio")
    raises(lambda: ae.Arch(alpha=0, fill_ratio=1.0, fill_height=-0.1), "invalid value for fill_height")
    raises(lambda: ae.Arch(alpha=0, fill_ratio=1.0), "fill_ratio/fill_height")
    assert "valid range" in m
    with pytest.raises(TypeError):
        ae.Arch(alpha="wide")
    with pytest.raises(TypeError):
        ae.Arch(alpha=0, blocks=2.5)


def test_solve_arguments():
    for bad in (0.0, -1.0, math.nan, -math.inf, 1e201):
        raises(lambda: ae.solve(SEMI, mu=bad), "invalid value for mu", "inf (no sliding)")
    with pytest.raises(TypeError):
        ae.solve(SEMI, mu="high")
    with pytest.raises(TypeError):
        ae.solve("semicircle", mu=0.35)


def test_curve_arguments():
    raises(lambda: ae.curve(SEMI, [0.35, 0.5, -1.0]), "invalid value for mu[2]: -1")
    raises(lambda: ae.curve(SEMI, [[0.35, 0.5]]), "invalid value for mu", "1-D")
    raises(lambda: ae.curve(SEMI, [0.35], threads=0), "invalid value for threads: 0")


def test_assess_load_certify_arguments():
    raises(lambda: ae.assess(SEMI, eta=2.5, mu=0.35), "invalid value for eta: 2.5", "0 < eta < 2")
    raises(lambda: ae.assess(SEMI, eta=0.2, mu=-0.35), "invalid value for mu")
    d20 = ae.Arch(alpha=0, blocks=20)
    raises(lambda: ae.load(d20, 0.3, 0.8), "give exactly one live load")
    raises(lambda: ae.load(d20, 0.3, 0.8, horizontal="right", point_load=1.0), "exactly one")
    raises(lambda: ae.load(d20, 0.3, 0.8, horizontal="up"), "horizontal", "right", "left")
    raises(lambda: ae.load(d20, 0.3, 0.8, point_load=4.0), "invalid value for point_load: 4")
    raises(lambda: ae.load(d20, 0.3, 0.8, point_load_deg=200.0), "point_load_deg")
    raises(lambda: ae.load(d20, 0.3, 0.8, point_load_joint=21), "point_load_joint", "<= 20")
    raises(lambda: ae.load(SEMI, 0.3, 0.8, point_load_joint=1), "point_load_joint",
           "discrete arch")
    raises(lambda: ae.load(d20, 2.0, 0.8, horizontal="left"), "invalid value for eta")
    raises(lambda: ae.certify(SEMI, mu=0.35, gap=0.1), "invalid value for gap: 0.1",
           "1e-15 <= gap <= 1e-4")
    raises(lambda: ae.certify(SEMI, mu=0.0), "invalid value for mu")
    with pytest.raises(ValueError, match="not a certificate"):
        ae.verify('{"format": "something else"}')


def test_compas_radius():
    r = ae.solve(SEMI, mu=0.35)
    raises(lambda: r.compas_json(radius=-1.0), "invalid value for radius: -1")
    raises(lambda: r.compas_json(radius=math.inf), "radius")

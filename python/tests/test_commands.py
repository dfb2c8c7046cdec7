"""Every command from Python (`ae.run`, `load_curve`, `critical`, `certify_load`, `report`,
`plot`): the same JSON document as the binary prints (the wheel solves its LPs with
microlp, the binary with HiGHS: numbers agree to 1e-12 relative, as in
test_cli_agreement), and errors that name the Python argument."""

import math

import pytest

import arch_enum as ae
from test_cli_agreement import agree

SEMI = ae.Arch(alpha=0)
BRIDGE = dict(span=10, rise=5, ring=0.6, width=1, unit_weight=20, mu=0.6)


def test_run_is_the_command_line(cli):
    for args, kwargs in [
        (["solve", "--alpha", "0", "--mu", "0.35"], dict(mu=0.35)),
        (["assess", "--alpha", "0", "--eta", "0.2", "--mu", "0.6"], dict(eta=0.2, mu=0.6)),
        (["load", "--alpha", "0", "--eta", "0.3", "--mu", "0.6", "--horizontal-left"],
         dict(eta=0.3, mu=0.6, horizontal="left")),
    ]:
        code, doc = cli(*args, "--json")
        assert code == 0
        agree(ae.run(args[0], SEMI, **kwargs), doc, args[0])
    # the Python answer of solve is the same number
    assert ae.run("solve", SEMI, mu=0.35)["eta"] == ae.solve(SEMI, 0.35).eta


def test_modes_with_fill_is_traced_in_eta(cli):
    filled = ae.Arch(alpha=0, fill_ratio=0.9, fill_height=0.0566)
    code, doc = cli("modes", "--alpha", "0", "--fill-ratio", "0.9", "--fill-height", "0.0566",
                    "--json")
    assert code == 0
    mine = ae.run("modes", filled)
    assert mine["traced_in"] == "eta" and mine["status"] == "ok"
    agree(mine, doc, "modes")
    with pytest.raises(ValueError) as e:
        ae.modes(filled)
    assert "fill_ratio" in str(e.value) and "--" not in str(e.value)


def test_load_curve_and_critical_match_the_cli(cli):
    # twelve voussoirs: the corners are exact in a few seconds (the continuous arch's
    # corner bisection takes about a minute here)
    args = ["--alpha", "0", "--blocks", "12", "--eta", "0.2", "--point-load-joint", "4",
            "--mu-min", "0.4", "--mu-max", "1", "--points", "4"]
    code, doc = cli("load-curve", *args, "--json")
    assert code == 0
    twelve = ae.Arch(alpha=0, blocks=12)
    got = ae.load_curve(twelve, eta=0.2, point_load_joint=4, mu_min=0.4, mu_max=1, points=4)
    # how often the bisection saw the answer change inside a corner's bracket depends on
    # the LP back end's vertices; the corner itself (exact) does not
    skip = tuple(f"doc.corners[{i}].changes" for i in range(len(doc["corners"])))
    agree(got, doc, skip=skip)
    assert len(got["corners"]) >= 3 and all(c["exact"] for c in got["corners"])
    flags = ["--span", "10", "--rise", "5", "--ring", "0.6", "--width", "1", "--unit-weight",
             "20", "--mu", "0.6", "--axles", "100,100", "--spacing", "1.2", "--samples", "11"]
    code, doc = cli("load", *flags, "--critical", "--json")
    assert code == 0
    got = ae.critical(**BRIDGE, axles=[100, 100], spacing=1.2, samples=11)
    agree(got, doc, skip=("doc.search.events",))
    assert got["critical"]["at_m"] > 0 and got["units"]["lambda_kn"] > 0
    assert len(got["influence"]) >= 11


def test_load_certificate_is_verified():
    doc = ae.certify_load(SEMI, eta=0.3, mu=0.6, point_load_deg=60)
    assert doc["claim"] == "largest_multiplier" and doc["status"] == "ok"
    v = ae.verify(doc["certificate"])
    assert v.status == "ok", v
    assert v.claim == "largest_multiplier"


def test_report_and_plot():
    html = ae.report(SEMI, eta=0.2, mu=0.6, title="Python report")
    assert html.lstrip().lower().startswith("<!doctype html") and "Python report" in html
    assert "<script" not in html.lower()
    svg = ae.plot("arch", SEMI, mu=0.35)
    assert svg.lstrip().startswith("<svg") and "mixed_sliding_rotational" in svg
    curves = ae.plot("curve", alpha=[0, 1.15])  # a repeated flag: --alpha 0 --alpha 1.15
    assert "α = 1.15" in curves and "α = 0" in curves
    influence = ae.plot("influence", **BRIDGE, axles=[100], critical=True, samples=9)
    assert influence.lstrip().startswith("<svg")
    load_map = ae.plot("atlas", horizontal="right", mu=[0.6, 1], blocks=5, alpha_min=-0.2,
                       alpha_max=0.6, columns=3, factors=3, factor_max=2.5)
    assert "μ = 0.6:" in load_map and "μ = 1:" in load_map  # one panel per mu


@pytest.mark.parametrize(
    "call, name, kind",
    [
        (lambda: ae.run("load", SEMI, eta=3, mu=0.6, horizontal="right"), "eta", ValueError),
        (lambda: ae.run("solve", SEMI, mu=-1), "mu", ValueError),
        (lambda: ae.run("solve", SEMI, mu=0.4, colour=3), "colour", TypeError),
        (lambda: ae.run("serve"), "command", ValueError),
        (lambda: ae.run("solve", "semicircle", mu=0.4), "arch", TypeError),
        (lambda: ae.load_curve(SEMI, eta=0.3, point_load_deg=60, mu_min=2, mu_max=1),
         "mu_max", ValueError),
        (lambda: ae.critical(**BRIDGE, axles=[100, "x"]), "axles[1]", TypeError),
        (lambda: ae.critical(**BRIDGE, axles=[]), "axles", ValueError),
        (lambda: ae.load_curve(SEMI, eta=0.3, horizontal="up"), "horizontal", ValueError),
        (lambda: ae.report(SEMI, eta=5, mu=0.6), "eta", ValueError),
        (lambda: ae.plot("nothing", SEMI, mu=0.4), "figure", ValueError),
        (lambda: ae.plot("arch", SEMI, mu=0.4, png=True), "png", ValueError),
        (lambda: ae.plot("arch", SEMI, mu=math.nan), "mu", ValueError),
        (lambda: ae.certify_load(SEMI, eta=0.3, mu=0.6, point_load_deg=60, gap={}), "gap",
         TypeError),
    ],
)
def test_errors_name_the_python_argument(call, name, kind):
    with pytest.raises(kind) as e:
        call()
    message = str(e.value)
    assert name in message, message
    assert "--" not in message, message

"""The Python answers agree with the command line's JSON (`arch-enum ... --json`) on a
set of cases. The wheel's library solves its LPs with microlp, the command line with
HiGHS: strings, flags, counts and patterns must be equal, numbers equal to 1e-12
relative (1e-14 absolute for residuals near zero). One count is not part of the answer
and may differ: the number of events a load's sweep visited (`search.events`), which
depends on the vertex the LP starts it from."""

import math

import numpy as np
import pytest

import arch_enum as ae
from arch_enum import _native


def agree(mine, cli, path="doc", skip=()):
    if path in skip:
        return
    if isinstance(cli, dict):
        assert isinstance(mine, dict), path
        assert set(mine) == set(cli), f"{path}: keys differ: {set(mine) ^ set(cli)}"
        for k in cli:
            agree(mine[k], cli[k], f"{path}.{k}", skip)
    elif isinstance(cli, list):
        assert isinstance(mine, list) and len(mine) == len(cli), path
        for i, (a, b) in enumerate(zip(mine, cli)):
            agree(a, b, f"{path}[{i}]", skip)
    elif isinstance(cli, float) or isinstance(mine, float):
        assert isinstance(mine, (int, float)) and isinstance(cli, (int, float)), path
        assert math.isclose(mine, cli, rel_tol=1e-12, abs_tol=1e-14), f"{path}: {mine} vs {cli}"
    else:
        assert mine == cli, f"{path}: {mine!r} vs {cli!r}"


def document(x):
    """Data as the JSON document says it: +infinity is null, and a key whose value is null
    is left out (the typed results hold None where a key is absent)."""
    if isinstance(x, dict):
        return {k: document(v) for k, v in x.items() if document(v) is not None}
    if isinstance(x, list):
        return [document(v) for v in x]
    if isinstance(x, float) and x == math.inf:
        return None
    return x


def typed_agrees(result, cli, skip=()):
    """The typed result is the command's document, key for key (one schema): its
    ``to_dict()`` agrees with the command line's JSON."""
    agree(document(result.to_dict()), document(cli), skip=skip)


# (Arch keyword arguments, the same as command-line flags)
ARCHES = [
    (dict(alpha=0), ["--alpha", "0"]),
    (dict(alpha=0.5, blocks=12), ["--alpha", "0.5", "--blocks", "12"]),
    (dict(beta_right=-0.2, beta_left=3.0), ["--beta-right", "-0.2", "--beta-left", "3.0"]),
    (dict(alpha=1.0, weight="centroid"), ["--alpha", "1.0", "--weight", "centroid"]),
    (dict(alpha=0, blocks=20), ["--alpha", "0", "--blocks", "20"]),
    (dict(alpha=0, joints=[0.3, 1.2, 1.9, 2.8]), ["--alpha", "0", "--joints", "0.3,1.2,1.9,2.8"]),
]
MUS = ["0.2", "0.35", "0.8", "2", "inf"]


@pytest.mark.parametrize("arch_kw,flags", ARCHES)
@pytest.mark.parametrize("mu", MUS)
def test_solve(cli, arch_kw, flags, mu):
    code, doc = cli("solve", *flags, "--mu", mu, "--json")
    arch = ae.Arch(**arch_kw)
    raw = _native.solve(arch._spec(), float(mu))
    raw.pop("lines")
    agree(raw, doc)
    typed_agrees(ae.solve(arch, float(mu)), doc)
    # and the dataclass carries the same answer
    r = ae.solve(arch, float(mu))
    assert r.status == doc["status"] and r.mode == doc.get("mode")
    assert r.mu == (math.inf if doc["mu"] is None else doc["mu"])
    assert (r.eta is None) == (doc.get("eta") is None)
    if r.eta is not None:
        assert r.eta == pytest.approx(doc["eta"], rel=1e-12)
    if doc.get("pattern") is not None:
        assert [(c.kind, c.at) for c in r.pattern] == [(c["kind"], c["at"]) for c in doc["pattern"]]
        np.testing.assert_allclose([c.beta for c in r.pattern], [c["beta"] for c in doc["pattern"]],
                                   rtol=1e-12, atol=1e-14)
        assert r.reactions.h == pytest.approx(doc["reactions"]["h"], rel=1e-12, abs=1e-14)
        np.testing.assert_allclose(
            r.mechanism.rate, [x["rate"] for x in doc["mechanism"]["rates"]], rtol=1e-12,
            atol=1e-14)
        # the extreme rays: as many as the CLI lists, each summing to 1, and the
        # representative in their convex hull's span (one ray: the representative itself)
        rays = r.mechanism.rays
        assert rays.shape == (len(doc["mechanism"]["rays"]), len(r.mechanism.rate))
        np.testing.assert_allclose(rays.sum(axis=1), 1.0, rtol=1e-9)
        if r.mechanism.dof == 1:
            np.testing.assert_allclose(rays[0], r.mechanism.rate, rtol=1e-9, atol=1e-12)
    assert [s.eta for s in r.limit_states or ()] == pytest.approx(
        [s["eta"] for s in doc.get("limit_states") or []], rel=1e-12)
    assert (code == 0) == (r.status == "ok")


FILLED = [
    (dict(alpha=0, fill_ratio=0.9, fill_height=0.1), ["--alpha", "0", "--fill-ratio", "0.9", "--fill-height", "0.1"]),
    (dict(alpha=-0.5, blocks=12, fill_ratio=0.5, fill_height=0.2),
     ["--alpha", "-0.5", "--blocks", "12", "--fill-ratio", "0.5", "--fill-height", "0.2"]),
]


@pytest.mark.parametrize("arch_kw,flags", FILLED)
def test_solve_with_fill(cli, arch_kw, flags):
    """An arch with fill: the same least thickness, scan and limit states as the command
    line (whose JSON adds the fill as given, `fill`)."""
    code, doc = cli("solve", *flags, "--mu", "0.6", "--json")
    arch = ae.Arch(**arch_kw)
    raw = _native.solve(arch._spec(), 0.6)
    raw.pop("lines")
    assert doc.pop("fill")["weight_ratio"] == arch_kw["fill_ratio"]
    agree(raw, doc)
    r = ae.solve(arch, 0.6)
    assert r.thickness_scan.interval is True
    assert r.eta == pytest.approx(doc["eta"], rel=1e-12)
    bare = ae.solve(ae.Arch(**{k: v for k, v in arch_kw.items() if not k.startswith("fill")}), 0.6)
    assert bare.thickness_scan is None and bare.eta != r.eta


@pytest.mark.parametrize("arch_kw,flags", ARCHES[:4])
def test_curve(cli, arch_kw, flags):
    code, doc = cli("curve", *flags, "--mu-min", "0.25", "--mu-max", "5", "--points", "12",
                    "--json")
    assert code == 0
    mus = [p["mu"] for p in doc["points"]]
    arch = ae.Arch(**arch_kw)
    agree(_native.curve(arch._spec(), mus, None), doc)
    c = ae.curve(arch, mus)
    typed_agrees(c, doc)
    assert list(c.column("status")) == [p["status"] for p in doc["points"]]
    np.testing.assert_allclose(
        c.eta, [math.nan if p["eta"] is None else p["eta"] for p in doc["points"]], rtol=1e-12)


@pytest.mark.parametrize("arch_kw,flags", [ARCHES[0], ARCHES[1], ARCHES[3]])
def test_modes(cli, arch_kw, flags):
    code, doc = cli("modes", *flags, "--json")
    arch = ae.Arch(**arch_kw)
    agree(_native.modes(arch._spec()), doc)
    m = ae.modes(arch)
    typed_agrees(m, doc)
    assert m.status == doc["status"] and len(m.corners) == len(doc["corners"])
    assert [b.mode for b in m.branches] == [b["mode"] for b in doc["branches"]]


@pytest.mark.parametrize("eta,mu", [("0.2", "0.35"), ("0.12", "inf"), ("0.3", "0.25")])
def test_assess(cli, eta, mu):
    code, doc = cli("assess", "--alpha", "0", "--eta", eta, "--mu", mu, "--json")
    arch = ae.Arch(alpha=0)
    agree(_native.assess(arch._spec(), float(eta), float(mu)), doc)
    a = ae.assess(arch, float(eta), float(mu))
    typed_agrees(a, doc)
    assert a.stands == doc["stands"] and (a.eta_min is None) == (doc["eta_min"] is None)
    if a.eta_min is not None:
        assert a.eta_min == pytest.approx(doc["eta_min"], rel=1e-12)


@pytest.mark.parametrize("arch_kw,flags", FILLED)
def test_assess_with_fill(cli, arch_kw, flags):
    """`assess` of an arch with fill: the same verdict, factors and least friction as the
    command line (whose JSON adds the fill, `fill`)."""
    code, doc = cli("assess", *flags, "--eta", "0.15", "--mu", "0.6", "--json")
    assert code == 0
    assert doc.pop("fill")["weight_ratio"] == arch_kw["fill_ratio"]
    arch = ae.Arch(**arch_kw)
    agree(_native.assess(arch._spec(), 0.15, 0.6), doc)
    a = ae.assess(arch, 0.15, 0.6)
    assert a.stands == doc["stands"]
    assert a.mu_min == pytest.approx(doc["mu_min"], rel=1e-12)


@pytest.mark.parametrize("kw,flags", [
    (dict(horizontal="right"), ["--horizontal"]),
    (dict(horizontal="left"), ["--horizontal-left"]),
    (dict(point_load_deg=63.0), ["--point-load-deg", "63"]),
    (dict(point_load_joint=5), ["--point-load-joint", "5"]),
    (dict(point_load=1.0), ["--point-load", "1.0"]),
])
def test_load(cli, kw, flags):
    code, doc = cli("load", "--alpha", "0", "--blocks", "20", "--eta", "0.3", "--mu", "0.8",
                    *flags, "--json")
    arch = ae.Arch(alpha=0, blocks=20)
    r = ae.load(arch, 0.3, 0.8, **kw)
    agree(_native.load(*r._call), doc, skip={"doc.search.events"})
    typed_agrees(r, doc, skip={"doc.search.events"})
    assert r.status == doc["status"]
    assert r.lambda_ == pytest.approx(doc["lambda"], rel=1e-12)
    assert r.lambda_static == pytest.approx(doc["lambda_static"], rel=1e-12)
    assert [s.lambda_ for s in r.limit_states] == pytest.approx(
        [s["lambda"] for s in doc["limit_states"]], rel=1e-12)
    assert [s.mode for s in r.limit_states] == [s["mode"] for s in doc["limit_states"]]


def test_load_unresolved_keeps_what_it_decided(cli):
    # near where a branch ends the discretisations do not settle: lambda_c is not decided,
    # but lambda_static, the states found and "not unique" are
    code, doc = cli("load", "--alpha", "0.5", "--eta", "0.6125", "--mu", "1", "--horizontal",
                    "--json")
    r = ae.load(ae.Arch(alpha=0.5), 0.6125, 1.0, horizontal="right")
    typed_agrees(r, doc, skip={"doc.search.events"})
    assert (code, r.status, r.lambda_, r.unique) == (1, "unresolved", None, False)
    assert r.lambda_at_most == pytest.approx(doc["lambda_at_most"], rel=1e-12)
    assert r.lambda_at_most < r.lambda_static
    assert r.reduction_at_least == pytest.approx(1 - r.lambda_at_most / r.lambda_static)


def test_certify_and_verify_cross(cli, tmp_path):
    """A certificate from Python verifies with the command line, and one from the
    command line verifies in Python; the claims agree."""
    c = ae.certify(ae.Arch(alpha=0), mu=0.35)
    path = tmp_path / "py.json"
    c.save(path)
    code, doc = cli("verify", str(path), "--json")
    assert code == 0 and doc["status"] == "ok"
    mine = _native.verify(c.to_json())
    agree(mine, doc)

    cli_path = tmp_path / "cli.json"
    code, cdoc = cli("certify", "--alpha", "0", "--mu", "0.35", "--out", str(cli_path), "--json")
    assert code == 0
    v = ae.verify(cli_path)
    typed_agrees(v, cli("verify", str(cli_path), "--json")[1])
    # certify's document, but for where the certificate was written (not from Python)
    typed_agrees(c, {**cdoc, "file": None}, skip={"doc.certificate"})
    assert v.status == "ok" and v.eta_lo == cdoc["eta_lo"] and v.eta_hi == cdoc["eta_hi"]
    assert c.eta_lo == pytest.approx(cdoc["eta_lo"], rel=1e-12)
    assert c.eta_hi == pytest.approx(cdoc["eta_hi"], rel=1e-12)


def test_atlas(cli):
    """`ae.atlas` is `arch-enum atlas --json`, certified brackets included; bad ranges are a
    ValueError naming the Python argument."""
    flags = ["--alpha-min", "0.6", "--alpha-max", "0.9", "--columns", "4", "--mu-max-factor", "1.2",
             "--samples", "12", "--blocks", "12", "--certify"]
    code, doc = cli("atlas", *flags, "--json")
    assert code == 0
    raw = ae.atlas(0.6, 0.9, 1.2, blocks=12, columns=4, samples=12, certify=True)
    agree(raw, doc)
    kinds = {r["kind"] for r in raw["regions"]}
    assert {"unique", "non_unique", "no_equilibrium"} <= kinds
    assert all(p["certified"] for b in raw["boundaries"] for p in b["points"])
    with pytest.raises(ValueError, match="alpha_min"):
        ae.atlas(alpha_min=2.0)
    with pytest.raises(ValueError, match="columns"):
        ae.atlas(columns=1)
    with pytest.raises(ValueError, match="weight"):
        ae.atlas(weight="heavy")

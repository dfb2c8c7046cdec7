"""Every result converts to a pandas DataFrame: one row per limit state, corner or sample
where the result lists them, else one row of its fields, with the same numbers."""

import math

import pytest

import arch_enum as ae

pd = pytest.importorskip("pandas")

SEMI = ae.Arch(alpha=0)


def test_every_result_has_a_frame():
    s = ae.solve(SEMI, 0.35)
    f = s.to_pandas()
    assert len(f) == len(s.limit_states) >= 1
    assert f["eta"].iloc[0] == s.limit_states[0].eta
    assert "reactions.h" in f.columns
    m = ae.modes(SEMI)
    assert len(m.to_pandas()) == len(m.corners) >= 1
    a = ae.assess(SEMI, 0.2, 0.35)
    fa = a.to_pandas()
    assert len(fa) == 1 and fa["geometric_factor"].iloc[0] == a.geometric_factor
    ld = ae.load(ae.Arch(alpha=0, blocks=20), 0.3, 0.8, horizontal="right")
    fl = ld.to_pandas()
    assert len(fl) == len(ld.limit_states) >= 1
    assert fl["lambda"].iloc[0] == ld.limit_states[0].lambda_
    c = ae.certify(SEMI, 0.35)
    assert len(c.to_pandas()) == 1
    assert len(ae.verify(c).to_pandas()) == 1
    assert len(ae.curve(SEMI, [0.4, 0.5, math.inf]).to_pandas()) == 3


def test_every_document_has_a_frame():
    """``run`` documents (and load_curve, critical) convert too: one row per item of the
    command's natural list, the same numbers; ``rows`` picks another list, by name."""
    doc = ae.run("solve", SEMI, mu=0.35)
    assert isinstance(doc, dict) and doc == ae.run("solve", SEMI, mu=0.35).to_dict()
    f = doc.to_pandas()
    assert len(f) == len(doc["limit_states"]) >= 1
    assert f["eta"].iloc[0] == doc["limit_states"][0]["eta"]
    assert len(ae.run("curve", SEMI, mu_min=0.4, mu_max=1, points=4).to_pandas()) == 4
    modes = ae.run("modes", SEMI)
    assert len(modes.to_pandas()) == len(modes["corners"]) >= 1
    filled = ae.run("modes", ae.Arch(alpha=0, fill_ratio=0.9, fill_height=0.0566))
    assert len(filled.to_pandas()) == len(filled["samples"]) >= 12
    assert len(ae.run("assess", SEMI, eta=0.2, mu=0.6).to_pandas()) == 1
    loads = ae.run("atlas", horizontal="right", mu=[1.0], alpha_min=0.45, alpha_max=0.55,
                   columns=3, factors=3)
    assert len(loads.to_pandas()) == len(loads["cells"]) == 9
    crossing = ae.critical(span=10, rise=5, ring=0.6, width=1, unit_weight=20, mu=0.6,
                           axles=[100], samples=5)
    influence = crossing.to_pandas("influence")
    assert len(influence) == len(crossing["influence"]) and "at_m" in influence.columns
    with pytest.raises(ValueError) as e:
        crossing.to_pandas("nothing")
    assert "rows" in str(e.value) and "influence" in str(e.value)

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
    assert fl["lambda_"].iloc[0] == ld.limit_states[0].lambda_
    c = ae.certify(SEMI, 0.35)
    assert len(c.to_pandas()) == 1
    assert len(ae.verify(c).to_pandas()) == 1
    assert len(ae.curve(SEMI, [0.4, 0.5, math.inf]).to_pandas()) == 3

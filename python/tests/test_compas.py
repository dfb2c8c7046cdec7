"""to_compas(): compas objects in the XZ plane, z up, scaled by the radius; a round trip
through compas.json_dumps/json_loads; the same document as `arch-enum solve --compas`."""

import math

import numpy as np
import pytest

import arch_enum as ae



def test_to_compas_objects_and_round_trip():
    import compas
    from compas.geometry import Point, Polyline

    r = ae.solve(ae.Arch(alpha=0), mu=0.35)
    R = 5.0
    d = r.to_compas(radius=R)
    assert isinstance(d["outline"], Polyline) and isinstance(d["thrust_line"], Polyline)
    assert isinstance(d["friction_line"], Polyline)
    assert all(isinstance(p, Point) for p in d["hinges"] + d["sliding"])
    assert [p.name for p in d["hinges"]] == [c.kind for c in r.pattern if c.kind.startswith("hinge")]
    assert [p.name for p in d["sliding"]] == [c.kind for c in r.pattern if c.kind.startswith("slide")]
    # the XZ plane, z up, lengths times the radius: the same lines as the arrays
    thrust = np.array([[p.x, p.y, p.z] for p in d["thrust_line"].points])
    assert np.all(thrust[:, 1] == 0.0)
    np.testing.assert_allclose(thrust[:, [0, 2]], R * r.thrust_line, rtol=0, atol=1e-12)
    outline = np.array([[p.x, p.z] for p in d["outline"].points])
    np.testing.assert_allclose(outline, R * r.outline, rtol=0, atol=1e-12)
    assert abs(outline[:, 1].max() - R * (1 + r.eta / 2)) < 1e-9  # the crown's extrados
    assert d["arch_enum"]["eta"] == r.eta and d["arch_enum"]["radius"] == R
    # round trip
    again = compas.json_loads(compas.json_dumps(d))
    assert set(again) == set(d)
    for key in ("outline", "thrust_line", "friction_line"):
        assert isinstance(again[key], Polyline)
        assert [list(p) for p in again[key].points] == [list(p) for p in d[key].points]
    assert [list(p) for p in again["hinges"]] == [list(p) for p in d["hinges"]]
    assert again["arch_enum"] == d["arch_enum"]


def test_compas_at_infinite_friction():
    d = ae.solve(ae.Arch(alpha=0), mu=math.inf).to_compas()
    assert d["friction_line"] is None and d["sliding"] == []
    assert len(d["hinges"]) == 5 and d["arch_enum"]["mu"] is None


def test_cli_compas_file_is_the_same_document(cli, tmp_path):
    import compas

    path = tmp_path / "arch.json"
    code, _ = cli("solve", "--alpha", "0.5", "--blocks", "12", "--mu", "inf", "--compas",
                  str(path), "--radius", "3", parse=False)
    assert code == 0
    from_file = compas.json_load(str(path))
    mine = ae.solve(ae.Arch(alpha=0.5, blocks=12), mu=math.inf).to_compas(radius=3)
    assert set(from_file) == set(mine)
    assert from_file["arch_enum"]["mode"] == mine["arch_enum"]["mode"]
    for key in ("outline", "thrust_line"):
        a = np.array([list(p) for p in from_file[key].points])
        b = np.array([list(p) for p in mine[key].points])
        # the CLI solves its LPs with HiGHS, the wheel with microlp
        np.testing.assert_allclose(a, b, rtol=0, atol=1e-9)
    assert [p.name for p in from_file["hinges"]] == [p.name for p in mine["hinges"]]

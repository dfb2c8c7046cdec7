"""Engineering inputs in Python: ``geometry`` and ``Arch.from_span_rise`` agree with the
command line's ``--span --rise --ring`` (the same numbers, bit for bit), and bad lengths
raise ``ValueError`` naming the argument."""

import math

import pytest

import arch_enum as ae


def test_the_engineers_semicircle():
    g = ae.geometry(10.0, 5.0, 0.6)
    assert g["intrados_radius_m"] == 5.0
    assert g["alpha"] == 0.0
    assert abs(g["radius_m"] - 5.3) < 1e-14
    assert g["eta"] == 0.6 / (5.0 + 0.3)
    assert ae.geometry(10.0, 5.0)["eta"] is None


def test_from_span_rise_is_the_arch_of_the_cli(cli):
    arch = ae.Arch.from_span_rise(12.0, 3.0)
    g = ae.geometry(12.0, 3.0, 0.5)
    py = ae.assess(arch, g["eta"], 0.6)
    code, cli_doc = cli("assess", "--span", "12", "--rise", "3", "--ring", "0.5", "--mu", "0.6",
                        "--json")
    assert code == 0
    cli = cli_doc
    assert cli["geometry"]["eta"] == g["eta"]
    assert cli["geometry"]["alpha"] == arch.alpha
    assert py.stands == cli["stands"]
    assert py.geometric_factor == cli["geometric_factor"]
    assert math.isclose(arch.springings[0], -arch.alpha, abs_tol=0.0)


@pytest.mark.parametrize("args, name", [((0.0, 1.0), "span"), ((10.0, -1.0), "rise"),
                                         ((10.0, 5.0, math.inf), "ring")])
def test_bad_lengths_name_the_argument(args, name):
    with pytest.raises(ValueError, match=name):
        ae.geometry(*args)

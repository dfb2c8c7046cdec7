"""arch_enum imports and answers without its optional dependencies (compas, pandas,
matplotlib): they are imported only by to_compas() and to_pandas().

scripts/test.sh runs this file first in a virtual environment that has only the wheel,
numpy and pytest, with ARCH_ENUM_NO_OPTIONAL=1 (then the optional packages must really be
absent); the later full run checks the same with the packages hidden from import."""

import importlib.util
import os
import subprocess
import sys
import textwrap

OPTIONAL = ("compas", "pandas", "matplotlib")

SCRIPT = textwrap.dedent(
    """
    import sys
    for name in {hide!r}:
        sys.modules[name] = None  # an import of it raises ImportError
    import arch_enum as ae
    r = ae.solve(ae.Arch(alpha=0), mu=0.35)
    print(f"{{r.eta:.11f}}")
    assert not any(m in sys.modules and sys.modules[m] is not None for m in {optional!r})
    c = ae.curve(ae.Arch(alpha=0), [0.35, 1.0])
    for call, what in ((r.to_compas, "compas"), (c.to_pandas, "pandas")):
        try:
            call()
        except ImportError as e:
            assert what in str(e), e
        else:
            raise AssertionError(what + " was imported")
    assert r.compas_json().startswith("{{")  # the document itself needs no compas
    print("ok")
    """
)


def run(hide):
    out = subprocess.run([sys.executable, "-c", SCRIPT.format(hide=hide, optional=OPTIONAL)],
                         capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["0.15291973385", "ok"]


def test_import_without_optional_dependencies():
    if os.environ.get("ARCH_ENUM_NO_OPTIONAL") == "1":
        # the environment really lacks them
        missing = [m for m in OPTIONAL if importlib.util.find_spec(m) is None]
        assert missing == list(OPTIONAL), f"installed: {set(OPTIONAL) - set(missing)}"
        run(hide=())
    else:
        run(hide=OPTIONAL)

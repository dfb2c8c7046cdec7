"""Every command of the command line, from Python, answered by the command line itself.

``run(command, arch, **options)`` runs ``arch-enum COMMAND ... --json`` in-process (the
binary's own entry point, inside the extension module, with the GIL released) and returns
its JSON document as a dict: the numbers are the CLI's to the last digit, and there is one
schema, the CLI's. Options are the command's flags with ``_`` for ``-``
(``unit_weight=20`` is ``--unit-weight 20``; ``critical=True`` is ``--critical``; a sequence
is a comma-separated list: ``axles=[100, 100]``). ``horizontal="right"`` or ``"left"`` is
the horizontal acceleration. Bad input raises ``ValueError`` naming the Python argument, an
option the command does not take raises ``TypeError``.

The functions below are ``run`` for the questions that have no dataclass of their own:
``load_curve``, ``critical`` (a vehicle at its critical position), ``certify_load``,
``report`` (HTML) and ``plot`` (SVG).
"""

from __future__ import annotations

import json
import re
from typing import Any, List, Optional

import numpy as np

from . import _native
from ._results import Arch, _scalar

#: Commands that answer with a JSON document (``serve`` runs forever; ``plot`` and
#: ``report`` have their own functions).
JSON_COMMANDS = ("solve", "curve", "modes", "assess", "load", "load-curve", "certify", "atlas")

_FLAG = re.compile(r"--([a-z][a-z0-9-]*)")

#: Flags given once per value (``plot curve --alpha 0 --alpha 1``): a sequence repeats them.
#: Every other sequence is one comma-separated value (``--axles 100,100``).
REPEATED = ("alpha",)


def _python_name(flag: str) -> str:
    return flag.replace("-", "_")


def _arch_flags(arch: Optional[Arch]) -> List[str]:
    """The flags of an :class:`Arch` (none for ``None``: the options then describe it,
    e.g. ``span``, ``rise`` and ``ring``)."""
    if arch is None:
        return []
    if not isinstance(arch, Arch):
        raise TypeError(f"arch must be an arch_enum.Arch or None, got {type(arch).__name__}")
    f = [f"--alpha={arch.alpha!r}"] if arch.alpha is not None else [
        f"--beta-right={arch.beta_right!r}", f"--beta-left={arch.beta_left!r}"]
    if arch.blocks is not None:
        f.append(f"--blocks={arch.blocks}")
    if arch.joints is not None:
        f.append("--joints=" + ",".join(repr(j) for j in arch.joints))
    f.append(f"--weight={arch.weight}")
    if arch.fill_ratio is not None:
        f += [f"--fill-ratio={arch.fill_ratio!r}", f"--fill-height={arch.fill_height!r}"]
    return f


def _number(name: str, v: Any) -> str:
    """A number as the command line reads it (a whole number stays whole)."""
    if isinstance(v, (int, np.integer)) and not isinstance(v, (bool, np.bool_)):
        return str(int(v))
    return repr(_scalar(name, v))


def _value(name: str, v: Any) -> str:
    """One option's value as the command line reads it."""
    if isinstance(v, str):
        if "\0" in v:
            raise ValueError(f"invalid value for {name}: it holds a NUL character")
        return v
    if isinstance(v, np.ndarray) and v.ndim != 1:
        raise ValueError(f"invalid value for {name}: an array of shape {v.shape} "
                         "(valid: a number or a 1-D sequence)")
    if isinstance(v, (list, tuple, np.ndarray)):
        items = list(v)
        if not items:
            raise ValueError(f"invalid value for {name}: an empty sequence")
        return ",".join(_number(f"{name}[{i}]", x) for i, x in enumerate(items))
    return _number(name, v)


def _option_flags(options: dict) -> List[str]:
    """``key=value`` options as flags (``None`` and ``False`` are left out)."""
    out = []
    for key, v in options.items():
        if v is None or v is False or (isinstance(v, np.bool_) and not v):
            continue
        if key == "horizontal":
            if v not in ("right", "left"):
                raise ValueError(
                    f'invalid value for horizontal: {v!r} (valid values: "right", "left")')
            out.append("--horizontal" if v == "right" else "--horizontal-left")
            continue
        flag = "--" + key.replace("_", "-")
        if v is True or isinstance(v, np.bool_):
            out.append(flag)
        elif key in REPEATED and isinstance(v, (list, tuple, np.ndarray)):
            out += [f"{flag}={_number(f'{key}[{i}]', x)}" for i, x in enumerate(v)]
        elif isinstance(v, (dict, set, bytes)) or callable(v):
            raise TypeError(f"{key} must be a number, a string, True or a sequence, "
                            f"got {type(v).__name__}")
        else:
            out.append(f"{flag}={_value(key, v)}")
    return out


def _error(function: str, code: int, out: bytes, err: str) -> Exception:
    """The exception for a command that did not answer: the CLI's message with each flag
    named as the Python argument."""
    message = err.strip()
    try:
        message = json.loads(out)["message"]
    except (ValueError, KeyError, TypeError):
        pass
    message = message.split("\n\nUsage:")[0].split("\nUsage:")[0]
    message = re.sub(r"^error: ", "", message.strip())
    unknown = re.search(r"unexpected argument '--([a-z0-9-]+)", message)
    if unknown:
        return TypeError(f"{function}() got an unexpected keyword argument "
                         f"'{_python_name(unknown.group(1))}'")
    message = _FLAG.sub(lambda m: _python_name(m.group(1)), message)
    message = re.sub(r" <[A-Z_]+>", "", message)
    return ValueError(message) if code == 2 else RuntimeError(message)


def _call(function: str, argv: List[str]) -> tuple:
    code, out, err = _native.run_command(argv)
    return code, bytes(out), err


#: The list whose items are the rows of :meth:`Document.to_pandas`, by command (the first
#: present in the document; none: one row of the whole document).
ROWS = {
    "solve": ("limit_states",),
    "curve": ("points",),
    "modes": ("corners", "samples"),
    "load": ("limit_states",),
    "load-curve": ("points",),
    # the load map's cells first (its document has boundaries too), else the atlas's
    # boundaries
    "atlas": ("cells", "boundaries"),
}


class Document(dict):
    """A command's JSON document: a ``dict`` (the CLI's schema, key for key) that also
    converts to a ``pandas.DataFrame`` like the typed results do."""

    def __init__(self, doc: dict, command: str) -> None:
        super().__init__(doc)
        self.command = command

    def to_dict(self) -> dict:
        """The document as a plain ``dict``."""
        return dict(self)

    def to_pandas(self, rows: Optional[str] = None) -> Any:
        """A ``pandas.DataFrame`` (needs ``pandas``): one row per item of the list
        ``rows`` (default: the command's natural list: limit states, points, corners, the
        samples of ``modes`` with fill, the atlas's boundaries or its load map's cells), else one row of the
        document; nested fields become dotted columns (``reactions.h``)."""
        try:
            import pandas as pd
        except ImportError as e:  # pragma: no cover - exercised without pandas
            raise ImportError("to_pandas() needs the optional dependency pandas") from e
        if rows is None:
            rows = next((k for k in ROWS.get(self.command, ()) if self.get(k)), None)
        elif not isinstance(self.get(rows), list):
            lists = sorted(k for k, v in self.items() if isinstance(v, list))
            raise ValueError(f"invalid value for rows: {rows!r} (valid values: {', '.join(lists)})")
        return pd.json_normalize(self[rows] if rows is not None else [dict(self)])


def run(command: str, arch: Optional[Arch] = None, **options: Any) -> "Document":
    """Runs ``arch-enum COMMAND --json`` with ``arch`` and ``options`` as its flags and
    returns its JSON document as a :class:`Document` (a ``dict`` with ``to_pandas``;
    ``status`` says when the question has no answer, e.g. ``"no_equilibrium"``).
    ``command`` is one of :data:`JSON_COMMANDS`."""
    if command not in JSON_COMMANDS:
        raise ValueError(f"invalid value for command: {command!r} (valid values: "
                         f"{', '.join(JSON_COMMANDS)}; plot() and report() draw)")
    argv = [command, *_arch_flags(arch), *_option_flags(options), "--json"]
    code, out, err = _call("run", argv)
    try:
        doc = json.loads(out)
    except ValueError:
        raise _error("run", code, out, err) from None
    if code == 2 or (isinstance(doc, dict) and doc.get("status") == "error"):
        raise _error("run", 2, out, err)
    return Document(doc, command)


def load_curve(arch: Optional[Arch] = None, **options: Any) -> Document:
    """The load multiplier against friction at a fixed thickness (``arch-enum load-curve
    --json``): ``eta``, one live load (``horizontal``, ``point_load``/``point_load_deg``/
    ``point_load_joint``, or a vehicle ``axles`` with ``at``) and ``mu_min``, ``mu_max``,
    ``points``; samples and the exact corners of lambda(mu)."""
    return run("load-curve", arch, **options)


def critical(arch: Optional[Arch] = None, **options: Any) -> Document:
    """A vehicle crossing the arch (``arch-enum load --critical --json``): the critical
    position X* of least collapse multiplier, located exactly, the adequacy factor
    ``lambda`` there (and in kN: ``units.lambda_kn``), the second local minimum, and the
    influence line. Options as ``load`` takes them: the bridge (``span``, ``rise``,
    ``ring``, ``width``, ``unit_weight``, ``mu``, ``fill_weight``, ``fill_depth``) and the
    vehicle (``axles``, ``spacing``, ``dispersal``, ``effective_width``, ``samples``)."""
    return run("load", arch, critical=True, **options)


def certify_load(arch: Optional[Arch] = None, **options: Any) -> Document:
    """A certificate of a live load's largest admissible multiplier lambda_static and of its
    limit states (``arch-enum certify`` with a load, ``--json``): the document, whose
    ``certificate`` :func:`arch_enum.verify` re-checks independently."""
    return run("certify", arch, **options)


def report(arch: Optional[Arch] = None, *, title: Optional[str] = None,
           **options: Any) -> str:
    """The assessment report (``arch-enum report --out -``): one self-contained HTML page
    with the inputs, the answers, every limit state, the certificate and its verification,
    the figures and the scope. Options as ``assess`` takes them and, optionally, a live
    load as ``load`` takes it."""
    argv = ["report", "--out=-"] + ([f"--title={_value('title', title)}"] if title else [])
    code, out, err = _call("report", argv + _arch_flags(arch) + _option_flags(options))
    if code != 0:
        raise _error("report", code, out, err)
    return out.decode("utf-8")


def plot(figure: str, arch: Optional[Arch] = None, **options: Any) -> str:
    """The figure ``arch-enum plot FIGURE`` draws (``curve``, ``arch``, ``load``,
    ``load-curve``, ``influence``, ``eccentricity``, ``atlas``, ``map``), as SVG text."""
    figures = ("curve", "arch", "load", "load-curve", "influence", "eccentricity", "atlas",
               "map")
    if figure not in figures:
        raise ValueError(f"invalid value for figure: {figure!r} (valid values: "
                         f"{', '.join(figures)})")
    if options.get("png") or options.get("png_width") is not None:
        raise ValueError("invalid png/png_width: plot() returns SVG text; "
                         "the command line writes PNG files")
    argv = ["plot", figure, *_arch_flags(arch), *_option_flags(options), "--out=-"]
    code, out, err = _call("plot", argv)
    if code != 0:
        raise _error("plot", code, out, err)
    return out.decode("utf-8")

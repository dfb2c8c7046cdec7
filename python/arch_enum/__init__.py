"""arch_enum: exact limit analysis of circular masonry arches with limited friction.

The Python face of the Rust library ``arch-enum`` (the same code as the command line
``arch-enum``; no numerics in Python). Each function answers the question of one
command and returns a frozen dataclass:

>>> import arch_enum as ae
>>> r = ae.solve(ae.Arch(alpha=0), mu=0.35)
>>> print(f"{r.eta:.11f} {r.mode}")
0.15291973385 mixed_sliding_rotational

Lengths are divided by the mean radius r (eta = t/r), angles are radians
counter-clockwise from the horizontal through the centre (a symmetric arch of opening
alpha has beta_right = -alpha, beta_left = pi + alpha). ``math.inf`` is mu = infinity
(no sliding). Bad input raises ``ValueError`` naming the argument and its valid range;
"no equilibrium", "unresolved" and the like are a ``status`` in the result.
"""

from __future__ import annotations

import json
import os
from typing import Any, Optional, Union

import numpy as np

from . import _native
from ._commands import (
    JSON_COMMANDS,
    Document,
    certify_load,
    critical,
    load_curve,
    plot,
    report,
    run,
)
from ._extras import Lines
from ._results import Arch, _scalar, _whole
from ._types import (
    ArchInfo,
    AssessResult,
    Branch,
    CertifyResult,
    Checks,
    Contact,
    Corner,
    CurvePoint,
    CurveResult,
    LimitState,
    LiveLoad,
    LoadContact,
    LoadLimitState,
    LoadResult,
    Mechanism,
    ModesResult,
    Reactions,
    SafestState,
    Search,
    SolveResult,
    ThicknessLimit,
    VerifyResult,
    VerticalBranch,
)

__version__: str = _native.__version__
#: The LP solver this build of the library uses (``"microlp"`` in the wheel: pure Rust).
LP_SOLVER: str = _native.LP_SOLVER

__all__ = [
    "Document",
    "geometry",
    "atlas",
    "Arch",
    "ArchInfo",
    "AssessResult",
    "Branch",
    "CertifyResult",
    "Checks",
    "Contact",
    "Corner",
    "CurvePoint",
    "CurveResult",
    "LP_SOLVER",
    "LimitState",
    "Lines",
    "LiveLoad",
    "LoadContact",
    "LoadLimitState",
    "LoadResult",
    "Mechanism",
    "ModesResult",
    "Reactions",
    "SafestState",
    "Search",
    "SolveResult",
    "ThicknessLimit",
    "VerifyResult",
    "VerticalBranch",
    "assess",
    "certify",
    "certify_load",
    "critical",
    "curve",
    "JSON_COMMANDS",
    "load",
    "load_curve",
    "modes",
    "plot",
    "report",
    "run",
    "solve",
    "verify",
]


def _made(result: Any, **private: Any) -> Any:
    """``result`` knowing what it was made from (its input arch, the call): the figures of
    ``_extras`` need them."""
    for k, v in private.items():
        object.__setattr__(result, k, v)
    return result


def _arch(arch: Any) -> Arch:
    if not isinstance(arch, Arch):
        raise TypeError(f"arch must be an arch_enum.Arch, got {type(arch).__name__}")
    return arch


def _friction(a: Arch, mu: Any) -> float:
    """``mu`` as a number: ``"ms"`` is the arch's own mu_ms (the vertical branch)."""
    if isinstance(mu, str) and mu.strip().lower() == "ms":
        return _native.mu_ms(a._spec())
    if isinstance(mu, str):
        raise TypeError(f"mu must be a number or 'ms', got {mu!r}")
    return _scalar("mu", mu)


def geometry(span: float, rise: float, ring: Optional[float] = None) -> dict:
    """The engineer's description of a symmetric arch (metres): the clear ``span`` and
    ``rise`` of the intrados and, optionally, the ``ring`` thickness, with what they give:
    ``intrados_radius_m``, ``alpha``, ``beta_right``, ``beta_left``, and with a ring
    ``radius_m`` (r = R_i + t/2) and ``eta`` (t/r) to pass to ``assess`` or ``load``
    (``--span --rise --ring`` on the command line; ``Arch.from_span_rise`` builds the arch)."""
    g = _native.geometry(_scalar("span", span), _scalar("rise", rise),
                         None if ring is None else _scalar("ring", ring))
    return {k: v for k, v in g.items() if k not in ("least_ring_m", "ring_over_least")}


def solve(arch: Arch, mu: Union[float, str]) -> SolveResult:
    """The least thickness eta*(mu) of ``arch`` at friction ``mu`` (> 0, ``math.inf``, or
    ``"ms"``: the arch's own mu_ms, the corner of the vertical branch with its purely
    sliding limit states), its collapse mode, pattern, reactions and mechanism, and every
    limit state with eta in [eta_s, 2) (``arch-enum solve``)."""
    a = _arch(arch)
    d = _native.solve(a._spec(), _friction(a, mu))
    return _made(SolveResult._of(d), _input=a, _lines=d.get("lines"))


def curve(arch: Arch, mu: Any, *, threads: Optional[int] = None) -> CurveResult:
    """eta*(mu) at every friction coefficient of ``mu`` (a number or a 1-D array; each
    > 0 or ``math.inf``), in the order given (``arch-enum curve``). The solves run in
    parallel on ``threads`` threads (default: every core) with the GIL released."""
    a = _arch(arch)
    if isinstance(mu, (bool, np.bool_)):
        raise TypeError(f"mu must be numbers, got {mu!r}")
    try:
        mus = np.asarray(mu, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"mu must be a number or an array of numbers, got {mu!r}") from None
    if mus.ndim > 1:
        raise ValueError(
            f"invalid value for mu: an array of shape {mus.shape} (valid: a number or a 1-D array)"
        )
    if threads is not None:
        threads = _whole("threads", threads, 1, 1024, ", or None for every core")
    d = _native.curve(a._spec(), [float(m) for m in mus.ravel()], threads)
    return _made(CurveResult._of(d), _input=a)


def modes(arch: Arch) -> ModesResult:
    """The whole eta-mu limit curve of ``arch``: branches with their collapse modes,
    exact corners and the limit states above the boundary (``arch-enum modes``). With fill
    the curve is traced in eta as mu_min(eta), a document of another shape: ``run("modes",
    arch)`` returns it (a ``ValueError`` naming ``fill_ratio`` here)."""
    a = _arch(arch)
    if a.fill_ratio is not None:
        raise ValueError(
            "invalid fill_ratio: with fill the limit curve is traced in eta as mu_min(eta), "
            "a document of its own: ae.run('modes', arch) returns it"
        )
    return _made(ModesResult._of(_native.modes(a._spec())), _input=a)


def atlas(
    alpha_min: float = -1.4,
    alpha_max: float = 1.2,
    mu_max_factor: float = 10.0,
    *,
    weight: str = "centreline",
    blocks: Optional[int] = None,
    columns: int = 53,
    samples: int = 40,
    certify: bool = False,
) -> dict:
    """The atlas of uniqueness over symmetric arches of opening alpha in [``alpha_min``,
    ``alpha_max``] and friction mu from mu_ms(alpha) to ``mu_max_factor`` mu_ms(alpha)
    (``arch-enum atlas --json``), as its JSON document: ``regions`` (kind and polygon of
    [alpha, mu] vertices), ``boundaries`` (between ``non_unique`` and ``unique`` on continuous
    arches solved from what ends the branch: ``exact``, ``eta``, ``condition``), ``tips``,
    ``top`` (the largest mu/mu_ms of the non-unique band), ``columns`` (every sample),
    ``undecided``. ``certify=True`` certifies both sides of every located boundary point (see
    docs/uniqueness.md). The load map is ``run("atlas", horizontal=..., mu=[...])``."""
    if not isinstance(certify, (bool, np.bool_)):
        raise TypeError(f"certify must be True or False, got {certify!r}")
    return _native.atlas(
        _scalar("alpha_min", alpha_min),
        _scalar("alpha_max", alpha_max),
        _scalar("mu_max_factor", mu_max_factor),
        weight,
        None if blocks is None else _whole("blocks", blocks, 1, 100_000),
        _whole("columns", columns, 2, 2000),
        _whole("samples", samples, 2, 2000),
        bool(certify),
    )


def assess(arch: Arch, eta: float, mu: float) -> AssessResult:
    """A given thickness ratio ``eta`` (0 < eta < 2) at friction ``mu``: does it stand,
    with what geometric and friction factors of safety, and the safest state
    (``arch-enum assess``)."""
    a = _arch(arch)
    d = _native.assess(a._spec(), _scalar("eta", eta), _scalar("mu", mu))
    return _made(AssessResult._of(d), _input=a)


def load(
    arch: Arch,
    eta: float,
    mu: float,
    *,
    horizontal: Optional[str] = None,
    point_load: Optional[float] = None,
    point_load_deg: Optional[float] = None,
    point_load_joint: Optional[int] = None,
) -> LoadResult:
    """The collapse multiplier of a live load at (``eta``, ``mu``) with every limit
    state (``arch-enum load``). Give exactly one load: ``horizontal="right"`` or
    ``"left"`` (a body force lambda x self-weight: an acceleration lambda g), or a
    vertical point load lambda (units of gamma t d r) at the extrados point of angle
    ``point_load`` (radians) or ``point_load_deg`` (degrees; within 1e-9 rad of a joint
    it is that joint), or at joint ``point_load_joint`` of a discrete arch."""
    a = _arch(arch)
    given = [k for k, v in (("horizontal", horizontal), ("point_load", point_load),
                            ("point_load_deg", point_load_deg),
                            ("point_load_joint", point_load_joint)) if v is not None]
    if len(given) != 1:
        raise ValueError(
            "invalid horizontal/point_load/point_load_deg/point_load_joint: give exactly one "
            f"live load (got {', '.join(given) if given else 'none'})"
        )
    kind, towards_right, beta, beta_deg, joint = "point", True, None, None, None
    if horizontal is not None:
        if horizontal not in ("right", "left"):
            raise ValueError(
                f"invalid value for horizontal: {horizontal!r} (valid values: \"right\", \"left\")"
            )
        kind, towards_right = "horizontal", horizontal == "right"
    elif point_load is not None:
        beta = _scalar("point_load", point_load)
    elif point_load_deg is not None:
        beta_deg = _scalar("point_load_deg", point_load_deg)
    else:
        # the range (the arch's joints) is checked by the library, which names it
        joint = _whole("point_load_joint", point_load_joint, 0, 2**32)
    call = (a._spec(), _scalar("eta", eta), _scalar("mu", mu), kind, towards_right, beta,
            beta_deg, joint)
    return _made(LoadResult._of(_native.load(*call)), _input=a, _call=call)


def certify(arch: Arch, mu: float, gap: float = 1e-12) -> CertifyResult:
    """A certificate for eta*(mu): an admissible state at eta_hi, a Farkas certificate at
    eta_lo with (eta_hi - eta_lo)/eta_hi <= ``gap`` (1e-15 to 1e-4), and the limit
    states (``arch-enum certify``). Check it with :func:`verify`."""
    a = _arch(arch)
    m = _scalar("mu", mu)
    return _made(CertifyResult._of(_native.certify(a._spec(), m, _scalar("gap", gap))), _input=a)


def verify(certificate: Union[CertifyResult, dict, str, "os.PathLike[str]"]) -> VerifyResult:
    """Re-checks a certificate independently (no LP, no solver; interval arithmetic)
    (``arch-enum verify``). ``certificate`` is a :class:`CertifyResult`, the certificate
    document (a dict), its JSON text, or the path of a certificate file."""
    if isinstance(certificate, CertifyResult):
        text = certificate.to_json()
    elif isinstance(certificate, dict):
        text = json.dumps(certificate)
    elif isinstance(certificate, os.PathLike) or (
        isinstance(certificate, str) and not certificate.lstrip().startswith(("{", "["))
    ):
        try:
            with open(certificate, encoding="utf-8") as f:
                text = f.read()
        except OSError as e:
            raise ValueError(
                f"invalid value for certificate: cannot read the file {os.fspath(certificate)!r} "
                f"({e.strerror}); give a CertifyResult, a dict, JSON text or a path"
            ) from None
    elif isinstance(certificate, str):
        text = certificate
    else:
        raise TypeError(
            "certificate must be a CertifyResult, a dict, JSON text or a path, got "
            f"{type(certificate).__name__}"
        )
    return VerifyResult._of(_native.verify(text))

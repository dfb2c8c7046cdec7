"""The result types: frozen dataclasses built from the command line's JSON documents.

No numerics here: every number comes from the Rust library (``arch_enum._native``).
Conventions as in the library: lengths divided by the mean radius r (eta = t/r), angles
in radians counter-clockwise from the horizontal through the centre, forces in units of
gamma t d r. ``math.inf`` stands for mu = infinity (no sliding) and for the other
quantities the JSON documents write as ``null`` = +infinity.
"""

from __future__ import annotations

import dataclasses
import json
import math
from dataclasses import dataclass
from typing import Any, Dict, List, Optional, Tuple

import numpy as np

from . import _native


def _inf(v: Optional[float]) -> float:
    """A JSON number where ``null`` stands for +infinity."""
    return math.inf if v is None else float(v)


def _scalar(name: str, v: Any, unit: str = "") -> float:
    """A real number (``math.inf`` allowed; the library checks the range): an int, a float
    or a NumPy real; not a bool, a string or bytes."""
    if isinstance(v, (bool, np.bool_, str, bytes)):
        raise TypeError(f"{name} must be a number{unit}, got {v!r}")
    try:
        return float(v)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be a number{unit}, got {v!r}") from None


def _whole(name: str, v: Any, lo: int, hi: int, hint: str = "") -> int:
    """A whole number in [lo, hi] (a bool or a float is not one)."""
    import operator

    if isinstance(v, (bool, np.bool_)):
        raise TypeError(f"{name} must be a whole number, got {v!r}")
    try:
        n = operator.index(v)
    except TypeError:
        raise TypeError(f"{name} must be a whole number, got {v!r}") from None
    if not lo <= n <= hi:
        raise ValueError(f"invalid value for {name}: {n} (valid range: {lo} to {hi}{hint})")
    return n


def _opt(v: Optional[float]) -> Optional[float]:
    return None if v is None else float(v)


def _array(values: Any) -> np.ndarray:
    """A read-only 1-D float array (``None`` entries become NaN)."""
    a = np.array([math.nan if v is None else v for v in values], dtype=float)
    a.flags.writeable = False
    return a


def _points(pts: Any) -> np.ndarray:
    """(n, 2) read-only float array of (x, y) points."""
    a = np.array(pts, dtype=float).reshape(-1, 2)
    a.flags.writeable = False
    return a


def _plain(v: Any) -> Any:
    """Plain Python data: dataclasses as dicts, arrays as lists."""
    if dataclasses.is_dataclass(v) and not isinstance(v, type):
        return {f.name: _plain(getattr(v, f.name)) for f in dataclasses.fields(v)}
    if isinstance(v, np.ndarray):
        return v.tolist()
    if isinstance(v, (list, tuple)):
        return [_plain(x) for x in v]
    if isinstance(v, dict):
        return {k: _plain(x) for k, x in v.items()}
    return v


class _Result:
    # the field whose items are the rows of ``to_pandas`` (None: one row of the fields)
    _rows: Optional[str] = None

    def to_dict(self) -> Dict[str, Any]:
        """The fields as plain Python data (nested dicts and lists; arrays as lists;
        infinity stays ``math.inf``)."""
        return _plain(self)

    def to_pandas(self) -> Any:
        """A ``pandas.DataFrame`` (needs ``pandas``): one row per item of the list the
        result holds (limit states, corners, ...), or one row of its fields; nested fields
        are flattened into dotted columns (``reactions.h``)."""
        try:
            import pandas as pd
        except ImportError as e:  # pragma: no cover - exercised without pandas
            raise ImportError("to_pandas() needs the optional dependency pandas") from e
        d = self.to_dict()
        rows = d[self._rows] if self._rows is not None else [d]
        return pd.json_normalize(rows)


@dataclass(frozen=True)
class Arch(_Result):
    """A circular arch, validated when built (``ValueError`` naming the argument).

    Give ``alpha`` (a symmetric arch of opening alpha radians, -pi/2 < alpha < pi/2;
    0 is the semicircle) or ``beta_right`` < ``beta_left`` (the springings, radians);
    optionally ``blocks`` (N equal voussoirs) or ``joints`` (the joint angles of a given
    stereotomy); ``weight`` is ``"centreline"`` (Heyman, the default) or ``"centroid"``.
    ``fill_ratio`` g_f = gamma_f/gamma and ``fill_height`` h = h_c/r (given together) put fill
    above the extrados up to a level road h r above its highest point (``--fill-ratio
    --fill-height``): ``solve`` then answers the least thickness of the arch with its fill
    (g_f and h held), ``load`` its live loads at a given thickness.
    """

    alpha: Optional[float] = None
    beta_right: Optional[float] = None
    beta_left: Optional[float] = None
    blocks: Optional[int] = None
    joints: Optional[Tuple[float, ...]] = None
    weight: str = "centreline"
    fill_ratio: Optional[float] = None
    fill_height: Optional[float] = None

    def __post_init__(self) -> None:
        def number(name: str, v: Any) -> Optional[float]:
            unit = "" if name.startswith("fill") else " (radians)"
            return None if v is None else _scalar(name, v, unit)

        for name in ("alpha", "beta_right", "beta_left", "fill_ratio", "fill_height"):
            object.__setattr__(self, name, number(name, getattr(self, name)))
        if (self.fill_ratio is None) != (self.fill_height is None):
            raise ValueError(
                "invalid fill_ratio/fill_height: give both (the fill's weight ratio g_f >= 0 "
                "and the road's height h >= 0 above the extrados, over r), or neither"
            )
        if self.blocks is not None:
            # the library names the range (1 to 100000) of a whole number that fits
            object.__setattr__(self, "blocks", _whole("blocks", self.blocks, -(2**62), 2**62))
        if self.joints is not None:
            if isinstance(self.joints, (str, bytes)):
                raise TypeError(f"joints must be a sequence of numbers, got {self.joints!r}")
            try:
                j = np.asarray(self.joints, dtype=float)
            except (TypeError, ValueError):
                raise TypeError(
                    f"joints must be a sequence of numbers (angles in radians), got {self.joints!r}"
                ) from None
            if j.ndim != 1:
                raise ValueError(
                    f"invalid value for joints: an array of shape {j.shape} "
                    "(valid: a sequence of angles in radians)"
                )
            object.__setattr__(self, "joints", tuple(float(v) for v in j))
        if not isinstance(self.weight, str):
            raise TypeError(f"weight must be a string, got {self.weight!r}")
        object.__setattr__(self, "_info", _native.arch(self._spec()))

    @classmethod
    def from_span_rise(
        cls,
        span: float,
        rise: float,
        *,
        blocks: Optional[int] = None,
        joints: Optional[Tuple[float, ...]] = None,
        weight: str = "centreline",
    ) -> "Arch":
        """The symmetric arch of an intrados of clear ``span`` and ``rise`` (metres; rise =
        span/2 is the semicircle, above it a horseshoe), as ``--span --rise`` on the
        command line; ``geometry(span, rise, ring)`` gives eta for a ring."""
        g = _native.geometry(_scalar("span", span), _scalar("rise", rise), None)
        return cls(alpha=g["alpha"], blocks=blocks, joints=joints, weight=weight)

    def _spec(self) -> tuple:
        joints = None if self.joints is None else list(self.joints)
        fill = None if self.fill_ratio is None else (self.fill_ratio, self.fill_height)
        return (
            self.alpha,
            self.beta_right,
            self.beta_left,
            self.blocks,
            joints,
            self.weight,
            fill,
        )

    @property
    def springings(self) -> Tuple[float, float]:
        """(beta_R, beta_L) in radians."""
        return (self._info["beta_right"], self._info["beta_left"])  # type: ignore[attr-defined]

    @property
    def span(self) -> float:
        """beta_L - beta_R (also the total weight in units of gamma t d r)."""
        br, bl = self.springings
        return bl - br

    @property
    def joint_angles(self) -> Optional[np.ndarray]:
        """The joint angles of a discrete arch (springings included), else ``None``."""
        j = self._info.get("joint_angles")  # type: ignore[attr-defined]
        return None if j is None else _array(j)

    @property
    def symmetric(self) -> bool:
        """Whether the arch (springings and joints) is mirror-symmetric."""
        return bool(self._info["symmetric"])  # type: ignore[attr-defined]


@dataclass(frozen=True)
class Contact(_Result):
    """An active contact: joint angle ``beta`` (radians), ``kind`` (``hinge_extrados``,
    ``hinge_intrados``, ``slide_plus``, ``slide_minus``) and where (``springing`` or
    ``interior``); ``side`` of the loaded section for a point load's own joint."""

    beta: float
    kind: str
    at: str
    side: Optional[str] = None

    @staticmethod
    def _of(d: Dict[str, Any]) -> "Contact":
        return Contact(float(d["beta"]), d["kind"], d["at"], d.get("side"))


def _pattern(p: Any) -> Optional[Tuple[Contact, ...]]:
    return None if p is None else tuple(Contact._of(c) for c in p)


@dataclass(frozen=True)
class VerticalBranch(_Result):
    """At mu = mu_ms: from ``eta_min`` up every admissible state is a limit state with the
    purely sliding mechanism on ``pattern`` (the vertical branch of the limit curve)."""

    eta_min: float
    mode: str
    pattern: Tuple[Contact, ...]

    @staticmethod
    def _of(d: Optional[Dict[str, Any]]) -> Optional["VerticalBranch"]:
        if d is None:
            return None
        return VerticalBranch(float(d["eta_min"]), d["mode"], tuple(Contact._of(c) for c in d["pattern"]))


@dataclass(frozen=True)
class Reactions(_Result):
    """The redundant reactions at the right springing: h, v (forces) and w (moment)."""

    h: float
    v: float
    w: float

    @staticmethod
    def _of(d: Optional[Dict[str, Any]]) -> Optional["Reactions"]:
        return None if d is None else Reactions(float(d["h"]), float(d["v"]), float(d["w"]))


@dataclass(frozen=True, eq=False)
class Mechanism(_Result):
    """A mechanism on the active contacts: the rates (summing to 1) at each contact, the
    dimension of the mechanism cone, the external power and the frictional dissipation,
    the residuals of compatibility (|B lambda|) and complementarity, and (``solve`` only)
    ``rays``: the extreme rays of the cone as a (k, n) array, each row rates on the same
    contacts summing to 1 (one row when ``dof`` is 1; ``None`` under a live load)."""

    beta: np.ndarray
    kind: Tuple[str, ...]
    rate: np.ndarray
    dof: int
    power: float
    dissipation: float
    symmetric: bool
    compatibility_residual: float
    complementarity_residual: float
    rays: Optional[np.ndarray]

    @staticmethod
    def _of(d: Optional[Dict[str, Any]]) -> Optional["Mechanism"]:
        if d is None:
            return None
        rates = d["rates"]
        return Mechanism(
            beta=_array([r["beta"] for r in rates]),
            kind=tuple(r["kind"] for r in rates),
            rate=_array([r["rate"] for r in rates]),
            dof=int(d["dof"]),
            power=float(d["power"]),
            dissipation=float(d["dissipation"]),
            symmetric=bool(d["symmetric"]),
            compatibility_residual=float(d["compatibility_residual"]),
            complementarity_residual=float(d["complementarity_residual"]),
            rays=_rays(d.get("rays"), len(rates)),
        )


def _rays(rays: Optional[List[List[float]]], n: int) -> Optional[np.ndarray]:
    """The extreme rays as a read-only (k, n) array, or None where none were given."""
    if rays is None:
        return None
    a = np.array(rays, dtype=float).reshape(len(rays), n)
    a.flags.writeable = False
    return a


@dataclass(frozen=True, eq=False)
class LimitState(_Result):
    """A limit state: an admissible state whose active contacts carry a mechanism."""

    eta: float
    mode: str
    pattern: Tuple[Contact, ...]
    reactions: Reactions
    mechanism: Mechanism

    @staticmethod
    def _of(d: Dict[str, Any]) -> "LimitState":
        return LimitState(
            float(d["eta"]),
            d["mode"],
            _pattern(d["pattern"]) or (),
            Reactions._of(d["reactions"]),  # type: ignore[arg-type]
            Mechanism._of(d["mechanism"]),  # type: ignore[arg-type]
        )


@dataclass(frozen=True)
class Checks(_Result):
    """The checks of the limit state at eta_s: the static eta of the LP, Newton's
    residual, the largest activation over the arch, the LP bracket of eta_s."""

    eta_static: float
    newton_residual: float
    max_phi: float
    eta_bracket: Tuple[float, float]

    @staticmethod
    def _of(d: Optional[Dict[str, Any]]) -> Optional["Checks"]:
        if d is None:
            return None
        lo, hi = d["eta_bracket"]
        return Checks(float(d["eta_static"]), float(d["newton_residual"]), float(d["max_phi"]),
                      (float(lo), float(hi)))


@dataclass(frozen=True)
class Search(_Result):
    """How every limit state above eta_s was searched (``complete``: all were found)."""

    complete: bool
    method: Optional[str]
    events: Optional[int]
    reason: Optional[str]

    @staticmethod
    def _of(d: Optional[Dict[str, Any]]) -> Optional["Search"]:
        if d is None:
            return None
        return Search(bool(d["complete"]), d.get("method"), d.get("events"), d.get("reason"))


@dataclass(frozen=True, eq=False)
class Lines(_Result):
    """The samples of the state drawn: joint angles ``beta``, normal force ``n``, the
    eccentricities ``e_m`` = M/N and ``e_t`` = (T/N)/mu * eta/2 (NaN where N = 0)."""

    beta: np.ndarray
    n: np.ndarray
    e_m: np.ndarray
    e_t: np.ndarray


def _f64(b: bytes) -> np.ndarray:
    """A read-only 1-D float array from the bytes of little-endian f64 (the native module
    hands the lines over so, without a Python float per number)."""
    return np.frombuffer(b, dtype="<f8")


def _lines(d: Optional[Dict[str, Any]]) -> Tuple[Optional[Lines], np.ndarray, Optional[np.ndarray],
                                                  np.ndarray]:
    if d is None:
        empty = _points([])
        return None, empty, None, empty
    lines = Lines(_f64(d["beta"]), _f64(d["n"]), _f64(d["e_m"]), _f64(d["e_t"]))
    friction = _f64(d["friction_line"]).reshape(-1, 2) if d["friction_line"] else None
    return lines, _f64(d["thrust_line"]).reshape(-1, 2), friction, _f64(d["outline"]).reshape(-1, 2)


@dataclass(frozen=True, eq=False)
class SolveResult(_Result):
    """The least thickness eta*(mu) and every limit state with eta in [eta_s, 2)
    (``arch-enum solve``).

    ``status`` is ``"ok"`` (answered), ``"no_equilibrium"`` (no thickness stands at
    this mu), ``"unresolved"`` (``eta_bracket`` holds what is known) or
    ``"no_collapse"``; ``message`` says why when not ok. ``mode``, ``pattern``,
    ``reactions`` and ``mechanism`` describe the least limit state, and
    ``thrust_line``, ``friction_line`` ((n, 2) arrays of x, y in units of r; the
    friction line is ``None`` at mu = inf) and ``outline`` are that state's lines. With fill,
    ``thickness_scan`` is the scan of the thickness range that bracketed eta_s (``nodes``,
    ``eta_from``, ``eta_to``, ``lowest_admissible``, ``interval``, ``gaps``).
    """

    _rows = "limit_states"

    status: str
    arch: Arch
    mu: float
    friction_angle_deg: float
    eta: Optional[float]
    mode: Optional[str]
    mode_standard: Optional[bool]
    pattern: Optional[Tuple[Contact, ...]]
    reactions: Optional[Reactions]
    mechanism: Optional[Mechanism]
    checks: Optional[Checks]
    mu_ms: Optional[float]
    eta_bracket: Optional[Tuple[float, float]]
    message: Optional[str]
    attained: Optional[bool]
    mechanism_at_eta: Optional[bool]
    unique: Optional[bool]
    limit_states: Tuple[LimitState, ...]
    search: Optional[Search]
    vertical_branch: Optional[VerticalBranch]
    eta_drawn: Optional[float]
    thrust_line: np.ndarray
    friction_line: Optional[np.ndarray]
    outline: np.ndarray
    lines: Optional[Lines]
    thickness_scan: Optional[Dict[str, Any]] = None

    @staticmethod
    def _of(arch: Arch, d: Dict[str, Any]) -> "SolveResult":
        lines, thrust, friction, outline = _lines(d.get("lines"))
        bracket = d.get("eta_bracket")
        return SolveResult(
            status=d["status"],
            arch=arch,
            mu=_inf(d["mu"]),
            friction_angle_deg=float(d["friction_angle_deg"]),
            eta=_opt(d.get("eta")),
            mode=d.get("mode"),
            mode_standard=d.get("mode_standard"),
            pattern=_pattern(d.get("pattern")),
            reactions=Reactions._of(d.get("reactions")),
            mechanism=Mechanism._of(d.get("mechanism")),
            checks=Checks._of(d.get("checks")),
            mu_ms=_opt(d.get("mu_ms")),
            eta_bracket=None if bracket is None else (float(bracket[0]), float(bracket[1])),
            message=d.get("message"),
            attained=d.get("attained"),
            mechanism_at_eta=d.get("mechanism_at_eta"),
            unique=d.get("unique"),
            limit_states=tuple(LimitState._of(s) for s in d.get("limit_states") or ()),
            search=Search._of(d.get("search")),
            vertical_branch=VerticalBranch._of(d.get("vertical_branch")),
            eta_drawn=None if d.get("lines") is None else float(d["lines"]["eta"]),
            thrust_line=thrust,
            friction_line=friction,
            outline=outline,
            lines=lines,
            thickness_scan=d.get("thickness_scan"),
        )

    def _repr_svg_(self) -> Optional[str]:
        """The arch to scale at the least limit state with its lines of thrust and
        friction and the mechanism (the library's ``plot arch`` figure)."""
        if self.lines is None:
            return None
        return _native.solve_svg(self.arch._spec(), self.mu)

    def to_compas(self, radius: float = 1.0) -> Dict[str, Any]:
        """The least limit state as compas objects (needs ``compas`` >= 2): ``outline``,
        ``thrust_line`` and ``friction_line`` (``None`` at mu = inf) as ``Polyline``,
        ``hinges`` and ``sliding`` as lists of ``Point`` (named by contact kind), in the
        XZ plane with z up, lengths multiplied by ``radius``; ``arch_enum`` holds eta,
        mu (``None`` = inf), the mode and the radius. The same document as
        ``arch-enum solve ... --compas FILE --radius R``."""
        try:
            import compas  # noqa: F401
        except ImportError as e:  # pragma: no cover - exercised without compas
            raise ImportError(
                "to_compas() needs the optional dependency compas: pip install 'compas>=2'"
            ) from e
        return compas.json_loads(self.compas_json(radius))

    def compas_json(self, radius: float = 1.0) -> str:
        """The COMPAS document of :meth:`to_compas` as JSON text (no compas needed)."""
        if self.lines is None:
            raise ValueError(f"no limit state to draw (status {self.status}): {self.message}")
        return _native.solve_compas(self.arch._spec(), self.mu, float(radius))


@dataclass(frozen=True, eq=False)
class CurveResult(_Result):
    """eta*(mu) sampled at the given friction coefficients (``arch-enum curve``): one
    entry per mu, in the order given. ``eta`` is NaN where ``status`` is not ``"ok"``
    (``message`` says why); ``mu_ms`` is the least friction at which some thickness
    stands (``None`` when none does)."""

    arch: Arch
    mu_ms: Optional[float]
    mu: np.ndarray
    friction_angle_deg: np.ndarray
    eta: np.ndarray
    status: Tuple[str, ...]
    mode: Tuple[Optional[str], ...]
    pattern: Tuple[Optional[Tuple[Contact, ...]], ...]
    message: Tuple[Optional[str], ...]

    @staticmethod
    def _of(arch: Arch, d: Dict[str, Any]) -> "CurveResult":
        pts = d["points"]
        return CurveResult(
            arch=arch,
            mu_ms=_opt(d["mu_ms"]),
            mu=_array([_inf(p["mu"]) for p in pts]),
            friction_angle_deg=_array([p["friction_angle_deg"] for p in pts]),
            eta=_array([p["eta"] for p in pts]),
            status=tuple(p["status"] for p in pts),
            mode=tuple(p["mode"] for p in pts),
            pattern=tuple(_pattern(p["pattern"]) for p in pts),
            message=tuple(p.get("message") for p in pts),
        )

    def __len__(self) -> int:
        return len(self.mu)

    def to_pandas(self) -> Any:
        """A ``pandas.DataFrame``, one row per mu (needs ``pandas``)."""
        try:
            import pandas as pd
        except ImportError as e:  # pragma: no cover - exercised without pandas
            raise ImportError("to_pandas() needs the optional dependency pandas") from e
        return pd.DataFrame(
            {
                "mu": self.mu,
                "friction_angle_deg": self.friction_angle_deg,
                "eta": self.eta,
                "status": list(self.status),
                "mode": list(self.mode),
                "pattern": list(self.pattern),
                "message": list(self.message),
            }
        )


@dataclass(frozen=True)
class Branch(_Result):
    """A branch of the eta-mu limit curve: one collapse mode for mu in [mu_min, mu_max]
    (``math.inf`` = unbounded), eta between eta_min and eta_max; ``samples`` for a branch
    of limit states above the boundary (else ``None``)."""

    mode: str
    mode_standard: bool
    mu_min: float
    mu_max: float
    eta_min: float
    eta_max: float
    pattern: Tuple[Contact, ...]
    samples: Optional[int] = None

    @staticmethod
    def _of(d: Dict[str, Any]) -> "Branch":
        return Branch(d["mode"], bool(d["mode_standard"]), _inf(d["mu_min"]), _inf(d["mu_max"]),
                      _inf(d["eta_min"]), _inf(d["eta_max"]), _pattern(d["pattern"]) or (),
                      d.get("samples"))


@dataclass(frozen=True)
class Corner(_Result):
    """A corner (``kink``) or smooth transition of eta_s(mu) (``mu`` may be ``math.inf``:
    an asymptote). Slopes d eta_s / d mu on each side; ``None`` where the JSON says
    ``null`` (the vertical purely-sliding branch, or undefined at mu = inf)."""

    mu: float
    friction_angle_deg: float
    eta: float
    kink: bool
    slope_left: Optional[float]
    slope_right: Optional[float]
    pattern: Tuple[Contact, ...]
    between: Tuple[str, str]
    mode: str
    exact: bool
    residual: Optional[float]

    @staticmethod
    def _of(d: Dict[str, Any]) -> "Corner":
        return Corner(_inf(d["mu"]), float(d["friction_angle_deg"]), float(d["eta"]),
                      bool(d["kink"]), _opt(d["slope_left"]), _opt(d["slope_right"]),
                      _pattern(d["pattern"]) or (), tuple(d["between"]),  # type: ignore[arg-type]
                      d["mode"], bool(d["exact"]), _opt(d["residual"]))


@dataclass(frozen=True)
class ThicknessLimit(_Result):
    """Where the boundary reaches the thickness limit eta -> 2 above mu_ms."""

    mu: float
    eta: float
    pattern: Tuple[Contact, ...]
    exact: bool


@dataclass(frozen=True, eq=False)
class ModesResult(_Result):
    """The whole eta-mu limit curve (``arch-enum modes``): branches with their collapse
    modes, exact corners, smooth transitions and the limit states above the boundary.
    ``status`` is ``"ok"``, ``"no_equilibrium"``, ``"no_collapse"`` or ``"unresolved"``."""

    _rows = "corners"

    status: str
    arch: Arch
    branches: Tuple[Branch, ...]
    corners: Tuple[Corner, ...]
    transitions: Tuple[Corner, ...]
    limit_branches: Tuple[Branch, ...]
    thickness_limit: Optional[ThicknessLimit]
    mu_min: Optional[float]
    mu_ms: Optional[float]
    unresolved: Tuple[Tuple[float, str], ...]
    no_collapse: np.ndarray
    no_equilibrium: np.ndarray

    @staticmethod
    def _of(arch: Arch, d: Dict[str, Any]) -> "ModesResult":
        t = d["thickness_limit"]
        return ModesResult(
            status=d["status"],
            arch=arch,
            branches=tuple(Branch._of(b) for b in d["branches"]),
            corners=tuple(Corner._of(c) for c in d["corners"]),
            transitions=tuple(Corner._of(c) for c in d["transitions"]),
            limit_branches=tuple(Branch._of(b) for b in d["limit_branches"]),
            thickness_limit=None if t is None else ThicknessLimit(
                float(t["mu"]), float(t["eta"]), _pattern(t["pattern"]) or (), bool(t["exact"])),
            mu_min=_opt(d["mu_min"]),
            mu_ms=_opt(d["mu_ms"]),
            unresolved=tuple((_inf(u["mu"]), u["message"]) for u in d["unresolved"]),
            no_collapse=_array(d["no_collapse"]),
            no_equilibrium=_array(d["no_equilibrium"]),
        )

    def _repr_svg_(self) -> Optional[str]:
        """The limit-state diagram of the arch (the library's ``plot curve`` figure)."""
        if self.mu_ms is None:
            return None
        return _native.modes_svg(self.arch._spec())


@dataclass(frozen=True)
class SafestState(_Result):
    """The admissible state of largest margin: reactions h, v, w and the margin."""

    h: float
    v: float
    w: float
    margin: float


@dataclass(frozen=True)
class AssessResult(_Result):
    """A given thickness ``eta`` at a given friction ``mu`` (``arch-enum assess``):
    whether it stands, eta*(mu) (``eta_min``), the geometric factor eta / eta*, the least
    friction mu_min(eta) at which it stands and the friction factor mu / mu_min, the
    collapse mode of eta*(mu) and the safest state. Factors are ``None`` when they do not
    exist or are infinite (the JSON's ``null``)."""

    status: str
    arch: Arch
    eta: float
    eta_min: Optional[float]
    stands: bool
    geometric_factor: Optional[float]
    mu: float
    mu_min: Optional[float]
    mu_min_exact: Optional[bool]
    mu_min_pattern: Tuple[Contact, ...]
    friction_factor: Optional[float]
    mode: Optional[str]
    safest_state: Optional[SafestState]
    message: Optional[str]

    @staticmethod
    def _of(arch: Arch, d: Dict[str, Any]) -> "AssessResult":
        s = d["safest_state"]
        return AssessResult(
            status=d["status"],
            arch=arch,
            eta=float(d["eta"]),
            eta_min=_opt(d["eta_min"]),
            stands=bool(d["stands"]),
            geometric_factor=_opt(d["geometric_factor"]),
            mu=_inf(d["mu"]),
            mu_min=_opt(d["mu_min"]),
            mu_min_exact=d["mu_min_exact"],
            mu_min_pattern=_pattern(d["mu_min_pattern"]) or (),
            friction_factor=_opt(d["friction_factor"]),
            mode=d["mode"],
            safest_state=None if s is None else SafestState(
                float(s["h"]), float(s["v"]), float(s["w"]), float(s["margin"])),
            message=d.get("message"),
        )

    def _repr_svg_(self) -> Optional[str]:
        """The arch at ``eta`` with its safest line of thrust (the library's
        ``plot arch --eta`` figure); ``None`` when it does not stand."""
        if not self.stands:
            return None
        return _native.assess_svg(self.arch._spec(), self.eta, self.mu)


@dataclass(frozen=True)
class LiveLoad(_Result):
    """The live load: ``kind`` ``"horizontal"`` (``towards`` ``"right"``/``"left"``)
    or ``"point"`` (at extrados angle ``beta``; ``at_joint`` on a discrete arch)."""

    kind: str
    beta: Optional[float]
    towards: Optional[str]
    at_joint: Optional[bool]


@dataclass(frozen=True, eq=False)
class LoadLimitState(_Result):
    """A limit state of the live load: its multiplier ``lambda_``, mode, pattern,
    reactions, mechanism, the live-load power, and for the least of a continuum of
    limit states the upper end ``continuum_to``."""

    lambda_: float
    mode: str
    pattern: Tuple[Contact, ...]
    reactions: Reactions
    mechanism: Mechanism
    live_power: float
    continuum_to: Optional[float]


@dataclass(frozen=True, eq=False)
class LoadResult(_Result):
    """The collapse multiplier of a live load at (eta, mu) (``arch-enum load``):
    ``lambda_`` (the least limit state: the collapse), ``lambda_static`` (the static
    maximum), every limit state below it, ``unique`` and ``reduction``. ``status`` is
    ``"ok"`` or a no-answer status with ``message``."""

    _rows = "limit_states"

    status: str
    arch: Arch
    eta: float
    mu: float
    load: LiveLoad
    lambda_: Optional[float]
    lambda_static: Optional[float]
    lambda_min: Optional[float]
    unique: Optional[bool]
    mechanism_at_static: Optional[bool]
    reduction: Optional[float]
    limit_states: Tuple[LoadLimitState, ...]
    search: Optional[Dict[str, Any]]
    message: Optional[str]

    @staticmethod
    def _of(arch: Arch, d: Dict[str, Any], call: Tuple[Any, ...]) -> "LoadResult":
        ld = d["load"]
        r = LoadResult(
            status=d["status"],
            arch=arch,
            eta=float(d["eta"]),
            mu=_inf(d["mu"]),
            load=LiveLoad(ld["kind"], _opt(ld.get("beta")), ld.get("towards"), ld.get("at_joint")),
            lambda_=_opt(d["lambda"]),
            lambda_static=_opt(d["lambda_static"]),
            lambda_min=_opt(d["lambda_min"]),
            unique=d["unique"],
            mechanism_at_static=d["mechanism_at_static"],
            reduction=_opt(d["reduction"]),
            limit_states=tuple(
                LoadLimitState(
                    float(s["lambda"]), s["mode"], _pattern(s["pattern"]) or (),
                    Reactions._of(s["reactions"]),  # type: ignore[arg-type]
                    Mechanism._of(s["mechanism"]),  # type: ignore[arg-type]
                    float(s["live_power"]), _opt(s["continuum_to"]))
                for s in d["limit_states"]
            ),
            search=d["search"],
            message=d.get("message"),
        )
        object.__setattr__(r, "_call", call)  # the arguments, for the figure
        return r

    def _repr_svg_(self) -> Optional[str]:
        """Every limit state of the load, one panel each (the library's ``plot load``
        figure); ``None`` when there is none."""
        if not self.limit_states:
            return None
        return _native.load_svg(*self._call)  # type: ignore[attr-defined]


@dataclass(frozen=True, eq=False)
class CertifyResult(_Result):
    """A certificate of eta*(mu) (``arch-enum certify``): ``status`` ``"ok"``,
    ``"gap_not_reached"`` (the best certificate found, wider than asked) or
    ``"not_certified"`` (``message`` says why; no certificate). ``certificate`` is the
    certificate document, to :meth:`save` or to pass to :func:`arch_enum.verify`."""

    status: str
    claim: Optional[str]
    mu: float
    eta_lo: Optional[float]
    eta_hi: Optional[float]
    gap_requested: Optional[float]
    gap_relative: Optional[float]
    certificate: Optional[Dict[str, Any]]
    message: Optional[str]

    @staticmethod
    def _of(d: Dict[str, Any], mu: float) -> "CertifyResult":
        return CertifyResult(
            status=d["status"],
            claim=d.get("claim"),
            mu=_inf(d["mu"]) if "mu" in d else mu,
            eta_lo=_opt(d.get("eta_lo")),
            eta_hi=_opt(d.get("eta_hi")),
            gap_requested=_opt(d.get("gap_requested")),
            gap_relative=_opt(d.get("gap_relative")),
            certificate=d.get("certificate"),
            message=d.get("message"),
        )

    def to_json(self) -> str:
        """The certificate as the JSON text ``arch-enum certify --out`` writes."""
        if self.certificate is None:
            raise ValueError(f"no certificate (status {self.status}): {self.message}")
        return json.dumps(self.certificate, indent=2)

    def save(self, path: Any) -> None:
        """Writes the certificate (readable by ``arch-enum verify`` and
        :func:`arch_enum.verify`)."""
        with open(path, "w", encoding="utf-8") as f:
            f.write(self.to_json() + "\n")


@dataclass(frozen=True)
class VerifyResult(_Result):
    """The independent re-check of a certificate (``arch-enum verify``): ``status``
    ``"ok"`` (it holds: ``statement`` says what is proved) or ``"rejected"``
    (``reason``; nothing is proved)."""

    status: str
    claim: Optional[str]
    mu: float
    eta_lo: Optional[float]
    eta_hi: Optional[float]
    checks: Tuple[str, ...]
    statement: Optional[str]
    limit_states: Optional[str]
    reason: Optional[str]

    @staticmethod
    def _of(d: Dict[str, Any]) -> "VerifyResult":
        return VerifyResult(
            status=d["status"],
            claim=d.get("claim"),
            mu=_inf(d.get("mu")),
            eta_lo=_opt(d.get("eta_lo")),
            eta_hi=_opt(d.get("eta_hi")),
            checks=tuple(d.get("checks") or ()),
            statement=d.get("statement"),
            limit_states=d.get("limit_states"),
            reason=d.get("reason"),
        )

"""The result types: frozen dataclasses, one per type of the command line's JSON documents.

GENERATED from the Rust types that print those documents (``arch-enum schema``) by
``tests/it/python_types.rs``: do not edit. Regenerate with
``PYTHON_TYPES_UPDATE=1 cargo test --release --test it python_types``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Dict, Optional, Tuple

import numpy as np

from . import _convert as _c
from . import _extras as _x


@dataclass(frozen=True, eq=False)
class ArchInfo(_x.ArchInfoExtras, _c.Result):
    """The arch a document answers for.

    Attributes:
        beta_right: The right springing β_R (radians).
        beta_left: The left springing β_L (radians).
        weight: `centreline` (Heyman's weight) or `centroid` (the true centroid).
        joints: `continuous` (a joint at every section) or `discrete` (voussoirs).
        symmetric: Whether the arch (springings and joints) is mirror-symmetric.
        joint_angles: The joint angles of a discrete arch, springings included (absent
            when continuous).
    """

    beta_right: float
    beta_left: float
    weight: str
    joints: str
    symmetric: bool
    joint_angles: Optional[np.ndarray] = None

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "ArchInfo":
        return cls(
            beta_right=_c.number(d["beta_right"]),
            beta_left=_c.number(d["beta_left"]),
            weight=d["weight"],
            joints=d["joints"],
            symmetric=bool(d["symmetric"]),
            joint_angles=None if (v := d.get("joint_angles")) is None else _c.numbers(v),
        )


@dataclass(frozen=True, eq=False)
class AssessResult(_x.AssessExtras, _c.Result):
    """A given thickness η at a given friction μ (`assess`): whether it stands, η*(μ)
    (`eta_min`), the geometric factor η / η*, the least friction μ_min(η) at which it stands
    and the friction factor μ / μ_min, the collapse mode of η*(μ) and the safest state.
    Factors are `null` when they do not exist or are infinite.

    Attributes:
        version: The document format's version (2).
        status: `ok`, or why η*(μ) is missing (`no_equilibrium`, `unresolved`, ...).
        arch: The arch.
        eta: The thickness ratio assessed.
        stands: Whether the arch stands at (η, μ).
        mu_min_pattern: The active pattern of the state at μ_min.
        eta_min: η*(μ) (`null` when nothing stands at μ or η* is unresolved; 0 when
            every η stands).
        fill: The fill (absent without fill).
        friction_factor: μ / μ_min (`null` when μ_min does not exist or the factor is
            infinite).
        geometric_factor: η / η*(μ) (`null`: none, or infinite when every η stands).
        message: Why η*(μ) is missing, when it is.
        mode: The collapse mode of η*(μ).
        mu: μ (`null` = ∞).
        mu_min: μ_min(η), the least friction at which η stands (`null` when none does).
        mu_min_exact: Whether `mu_min` is exact (Newton on the active pattern, verified)
            or an LP bound.
        safest_state: The admissible state of largest margin, when the arch stands.
    """

    version: int
    status: str
    arch: ArchInfo
    eta: float
    stands: bool
    mu_min_pattern: Tuple[Contact, ...]
    eta_min: Optional[float] = None
    fill: Optional[Fill] = None
    friction_factor: Optional[float] = None
    geometric_factor: Optional[float] = None
    message: Optional[str] = None
    mode: Optional[str] = None
    mu: Optional[float] = None
    mu_min: Optional[float] = None
    mu_min_exact: Optional[bool] = None
    safest_state: Optional[SafestState] = None

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "AssessResult":
        return cls(
            version=int(d["version"]),
            status=d["status"],
            arch=ArchInfo._of(d["arch"]),
            eta=_c.number(d["eta"]),
            stands=bool(d["stands"]),
            mu_min_pattern=tuple(Contact._of(y) for y in d["mu_min_pattern"]),
            eta_min=None if (v := d.get("eta_min")) is None else float(v),
            fill=None if (v := d.get("fill")) is None else Fill._of(v),
            friction_factor=None if (v := d.get("friction_factor")) is None else float(v),
            geometric_factor=None if (v := d.get("geometric_factor")) is None else float(v),
            message=d.get("message"),
            mode=d.get("mode"),
            mu=None if (v := d.get("mu", _c.ABSENT)) is _c.ABSENT else _c.number(v),
            mu_min=None if (v := d.get("mu_min")) is None else float(v),
            mu_min_exact=None if (v := d.get("mu_min_exact")) is None else bool(v),
            safest_state=None if (v := d.get("safest_state")) is None else SafestState._of(v),
        )


@dataclass(frozen=True, eq=False)
class Branch(_c.Result):
    """A branch of the η–μ limit curve: one collapse mode for μ in [mu_min, mu_max] (`null`:
    unbounded), η between eta_min and eta_max.

    Attributes:
        mode: The collapse mode.
        mode_standard: Whether the mode's name is one of the contract's list (else a
            descriptive one).
        mu_min: Where the branch starts.
        mu_max: Where it ends (`null`: ∞).
        eta_min: Its least η.
        eta_max: Its largest η.
        pattern: The active contacts along it.
    """

    mode: str
    mode_standard: bool
    mu_min: float
    mu_max: float
    eta_min: float
    eta_max: float
    pattern: Tuple[Contact, ...]

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "Branch":
        return cls(
            mode=d["mode"],
            mode_standard=bool(d["mode_standard"]),
            mu_min=_c.number(d["mu_min"]),
            mu_max=_c.number(d["mu_max"]),
            eta_min=_c.number(d["eta_min"]),
            eta_max=_c.number(d["eta_max"]),
            pattern=tuple(Contact._of(y) for y in d["pattern"]),
        )


@dataclass(frozen=True, eq=False)
class Candidate(_c.Result):
    """A pattern the enumeration tried (`--explain`).

    Attributes:
        pattern: Its active contacts.
        tried: Whether its equations were solved.
        verdict: What became of it.
        eta: Its thickness, when solved.
    """

    pattern: Tuple[Contact, ...]
    tried: bool
    verdict: str
    eta: Optional[float] = None

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "Candidate":
        return cls(
            pattern=tuple(Contact._of(y) for y in d["pattern"]),
            tried=bool(d["tried"]),
            verdict=d["verdict"],
            eta=None if (v := d.get("eta")) is None else float(v),
        )


@dataclass(frozen=True, eq=False)
class CertifiedArch(_c.Result):
    """The arch of a certificate as `verify` describes it.

    Attributes:
        beta_left: The left springing β_L (radians).
        beta_right: The right springing β_R (radians).
        joints: `continuous` or `discrete`.
        weight: `centreline` or `centroid`.
        fill: The fill (absent without fill).
        joint_angles: The joints of a discrete arch (absent for a continuous one).
    """

    beta_left: float
    beta_right: float
    joints: str
    weight: str
    fill: Optional[Dict[str, Any]] = None
    joint_angles: Optional[np.ndarray] = None

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "CertifiedArch":
        return cls(
            beta_left=_c.number(d["beta_left"]),
            beta_right=_c.number(d["beta_right"]),
            joints=d["joints"],
            weight=d["weight"],
            fill=None if (v := d.get("fill")) is None else dict(v),
            joint_angles=None if (v := d.get("joint_angles")) is None else _c.numbers(v),
        )


@dataclass(frozen=True, eq=False)
class CertifyResult(_x.CertifyExtras, _c.Result):
    """The answer of `certify`: the certificate with the bracket it proves. `status` is `ok`,
    `gap_not_reached` (the best certificate found, wider than asked) or `not_certified`
    (`message` says why; no certificate).

    Attributes:
        status: `ok`, `gap_not_reached` or `not_certified`.
        version: The document format's version (2).
        at_m: Where the vehicle stands, metres from the left springing (a vehicle's
            certificate).
        certificate: The certificate document, as `certify --out` writes it (what
            `verify` reads).
        claim: What is claimed (`least_thickness`, `no_equilibrium`,
            `largest_multiplier`, ...).
        eta: The load certificate's thickness ratio.
        eta_hi: The upper end of the proved bracket of η*.
        eta_lo: The lower end of the proved bracket of η*.
        file: The file the certificate was written to (`--out`).
        gap_relative: (hi − lo)/hi of the proved bracket.
        gap_requested: The relative gap asked for.
        lambda_hi: The upper end of the proved bracket of λ (load certificates).
        lambda_lo: The lower end of the proved bracket of λ (load certificates).
        load: The live load (load certificates).
        message: Why there is no certificate.
        mu: μ (`null` = ∞).
    """

    status: str
    version: int
    at_m: Optional[float] = None
    certificate: Optional[Dict[str, Any]] = None
    claim: Optional[str] = None
    eta: Optional[float] = None
    eta_hi: Optional[float] = None
    eta_lo: Optional[float] = None
    file: Optional[str] = None
    gap_relative: Optional[float] = None
    gap_requested: Optional[float] = None
    lambda_hi: Optional[float] = None
    lambda_lo: Optional[float] = None
    load: Optional[Dict[str, Any]] = None
    message: Optional[str] = None
    mu: Optional[float] = None

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "CertifyResult":
        return cls(
            status=d["status"],
            version=int(d["version"]),
            at_m=None if (v := d.get("at_m")) is None else float(v),
            certificate=None if (v := d.get("certificate")) is None else dict(v),
            claim=d.get("claim"),
            eta=None if (v := d.get("eta")) is None else float(v),
            eta_hi=None if (v := d.get("eta_hi")) is None else float(v),
            eta_lo=None if (v := d.get("eta_lo")) is None else float(v),
            file=d.get("file"),
            gap_relative=None if (v := d.get("gap_relative")) is None else float(v),
            gap_requested=None if (v := d.get("gap_requested")) is None else float(v),
            lambda_hi=None if (v := d.get("lambda_hi")) is None else float(v),
            lambda_lo=None if (v := d.get("lambda_lo")) is None else float(v),
            load=None if (v := d.get("load")) is None else dict(v),
            message=d.get("message"),
            mu=None if (v := d.get("mu", _c.ABSENT)) is _c.ABSENT else _c.number(v),
        )


@dataclass(frozen=True, eq=False)
class Checks(_c.Result):
    """The checks of the limit state at η_s: the static η of the LP, Newton's residual, the
    largest activation over the arch, the LP's bracket of η_s.

    Attributes:
        eta_static: η_s of the static LPs (before Newton).
        newton_residual: The residual of the pattern's equations after Newton.
        max_phi: The largest activation φ over the arch (≤ 0 up to rounding:
            admissible).
        eta_bracket: The LPs' bracket of η_s.
    """

    eta_static: float
    newton_residual: float
    max_phi: float
    eta_bracket: Tuple[float, ...]

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "Checks":
        return cls(
            eta_static=_c.number(d["eta_static"]),
            newton_residual=_c.number(d["newton_residual"]),
            max_phi=_c.number(d["max_phi"]),
            eta_bracket=_c.pair(d["eta_bracket"]),
        )


@dataclass(frozen=True, eq=False)
class Contact(_c.Result):
    """One active activation function at one joint.

    Attributes:
        beta: Joint angle (radians from the horizontal).
        kind: Which activation function is active.
        at: Springing or interior joint.
    """

    beta: float
    kind: str
    at: str

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "Contact":
        return cls(
            beta=_c.number(d["beta"]),
            kind=d["kind"],
            at=d["at"],
        )


@dataclass(frozen=True, eq=False)
class Corner(_c.Result):
    """A corner (`kink`) or smooth transition of η_s(μ), located exactly (`mu` `null`: an
    asymptote at μ = ∞).

    Attributes:
        mu: Where it is.
        friction_angle_deg: atan μ in degrees.
        eta: η_s there.
        kink: True for a corner (the slopes differ), false for a smooth transition.
        slope_left: dη_s/dμ on the side of smaller μ (`null`: the vertical
            purely-sliding branch at μ_ms, or undefined at μ = ∞).
        slope_right: dη_s/dμ on the side of larger μ (`null` at μ = ∞).
        pattern: The active contacts there (both branches' together).
        between: The modes on the side of smaller and of larger μ.
        mode: The mode of the state at the corner.
        exact: Whether Newton located it to rounding (else a bracket's midpoint).
        residual: Newton's residual there (`null`: not located by Newton).
    """

    mu: float
    friction_angle_deg: float
    eta: float
    kink: bool
    slope_left: Optional[float]
    slope_right: Optional[float]
    pattern: Tuple[Contact, ...]
    between: Tuple[str, ...]
    mode: str
    exact: bool
    residual: Optional[float]

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "Corner":
        return cls(
            mu=_c.number(d["mu"]),
            friction_angle_deg=_c.number(d["friction_angle_deg"]),
            eta=_c.number(d["eta"]),
            kink=bool(d["kink"]),
            slope_left=None if (v := d["slope_left"]) is None else float(v),
            slope_right=None if (v := d["slope_right"]) is None else float(v),
            pattern=tuple(Contact._of(y) for y in d["pattern"]),
            between=tuple(d["between"]),
            mode=d["mode"],
            exact=bool(d["exact"]),
            residual=None if (v := d["residual"]) is None else float(v),
        )


@dataclass(frozen=True, eq=False)
class CurvePoint(_c.Result):
    """η*(μ) at one friction coefficient.

    Attributes:
        mu: The friction coefficient (`null`: ∞).
        friction_angle_deg: atan μ in degrees.
        status: `ok`, `no_equilibrium`, `unresolved` or `no_collapse`.
        eta: η*(μ) (absent unless `ok`).
        message: Why there is no answer.
        mode: The collapse mode.
        pattern: The active contacts of the least limit state.
    """

    mu: float
    friction_angle_deg: float
    status: str
    eta: Optional[float] = None
    message: Optional[str] = None
    mode: Optional[str] = None
    pattern: Optional[Tuple[Contact, ...]] = None

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "CurvePoint":
        return cls(
            mu=_c.number(d["mu"]),
            friction_angle_deg=_c.number(d["friction_angle_deg"]),
            status=d["status"],
            eta=None if (v := d.get("eta")) is None else float(v),
            message=d.get("message"),
            mode=d.get("mode"),
            pattern=None if (v := d.get("pattern")) is None else tuple(Contact._of(y) for y in v),
        )


@dataclass(frozen=True, eq=False)
class CurveResult(_x.CurveExtras, _c.Result):
    """η*(μ) sampled at the given friction coefficients (`curve`): one point per μ, in the
    order given.

    Attributes:
        version: The document format's version (2).
        status: `ok`.
        arch: The arch.
        points: One point per μ, in the order given.
        fill: The fill, as given (absent without fill).
        mu_ms: μ_ms, the least friction at which some thickness stands.
    """

    _rows = "points"

    version: int
    status: str
    arch: ArchInfo
    points: Tuple[CurvePoint, ...]
    fill: Optional[Fill] = None
    mu_ms: Optional[float] = None

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "CurveResult":
        return cls(
            version=int(d["version"]),
            status=d["status"],
            arch=ArchInfo._of(d["arch"]),
            points=tuple(CurvePoint._of(y) for y in d["points"]),
            fill=None if (v := d.get("fill")) is None else Fill._of(v),
            mu_ms=None if (v := d.get("mu_ms")) is None else float(v),
        )


@dataclass(frozen=True, eq=False)
class Fill(_c.Result):
    """The fill as given.

    Attributes:
        weight_ratio: g_f = γ_f/γ.
        depth_ratio: h = h_c/r.
        depth_at_least_ring_m: `solve` with span and rise: the road's depth h r* (m)
            above the extrados of the least ring (h held as the ring varies).
        depth_m: Depth above the highest extrados point (m), when given in metres.
        weight_kn_m3: Unit weight of the fill (kN/m³), when given in kN.
    """

    weight_ratio: float
    depth_ratio: float
    depth_at_least_ring_m: Optional[float] = None
    depth_m: Optional[float] = None
    weight_kn_m3: Optional[float] = None

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "Fill":
        return cls(
            weight_ratio=_c.number(d["weight_ratio"]),
            depth_ratio=_c.number(d["depth_ratio"]),
            depth_at_least_ring_m=None if (v := d.get("depth_at_least_ring_m")) is None else float(v),
            depth_m=None if (v := d.get("depth_m")) is None else float(v),
            weight_kn_m3=None if (v := d.get("weight_kn_m3")) is None else float(v),
        )


@dataclass(frozen=True, eq=False)
class LimitBranch(_c.Result):
    """A branch of limit states above the boundary η_s(μ), traced by samples.

    Attributes:
        mode: The collapse mode.
        mode_standard: Whether the mode's name is one of the contract's list (else a
            descriptive one).
        mu_min: Where the branch starts.
        mu_max: Where it ends (`null`: ∞).
        eta_min: Its least η.
        eta_max: Its largest η.
        pattern: The active contacts along it.
        samples: The samples that trace it.
    """

    mode: str
    mode_standard: bool
    mu_min: float
    mu_max: float
    eta_min: float
    eta_max: float
    pattern: Tuple[Contact, ...]
    samples: int

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "LimitBranch":
        return cls(
            mode=d["mode"],
            mode_standard=bool(d["mode_standard"]),
            mu_min=_c.number(d["mu_min"]),
            mu_max=_c.number(d["mu_max"]),
            eta_min=_c.number(d["eta_min"]),
            eta_max=_c.number(d["eta_max"]),
            pattern=tuple(Contact._of(y) for y in d["pattern"]),
            samples=int(d["samples"]),
        )


@dataclass(frozen=True, eq=False)
class LimitState(_c.Result):
    """A limit state: an admissible state whose active contacts carry a mechanism.

    Attributes:
        eta: Its thickness ratio η.
        mode: Its collapse mode.
        pattern: Its active contacts.
        reactions: Its reactions.
        mechanism: Its mechanism.
    """

    eta: float
    mode: str
    pattern: Tuple[Contact, ...]
    reactions: Reactions
    mechanism: Mechanism

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "LimitState":
        return cls(
            eta=_c.number(d["eta"]),
            mode=d["mode"],
            pattern=tuple(Contact._of(y) for y in d["pattern"]),
            reactions=Reactions._of(d["reactions"]),
            mechanism=Mechanism._of(d["mechanism"]),
        )


@dataclass(frozen=True, eq=False)
class LiveLoad(_c.Result):
    """The live load: `kind` `horizontal` (towards `right` or `left`) or `point` (at the
    extrados angle `beta`; `at_joint` on a discrete arch).

    Attributes:
        kind: `horizontal` or `point`.
        at_joint: Point load: whether it sits at a joint (both sides of its section are
            checked).
        beta: Angle of the loaded extrados point (radians); null for the horizontal
            load.
        towards: Horizontal load: `right` (towards +x, the right springing) or `left`.
    """

    kind: str
    at_joint: Optional[bool] = None
    beta: Optional[float] = None
    towards: Optional[str] = None

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "LiveLoad":
        return cls(
            kind=d["kind"],
            at_joint=None if (v := d.get("at_joint")) is None else bool(v),
            beta=None if (v := d.get("beta")) is None else float(v),
            towards=d.get("towards"),
        )


@dataclass(frozen=True, eq=False)
class LoadContact(_c.Result):
    """An active contact of a limit state under a live load: a contact, and at the point load's
    joint the side of the loaded section it is on.

    Attributes:
        beta: Joint angle (radians from the horizontal).
        kind: Which activation function is active.
        at: Springing or interior joint.
        side: At the point load's joint: `before` or `after` the loaded section.
    """

    beta: float
    kind: str
    at: str
    side: Optional[str] = None

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "LoadContact":
        return cls(
            beta=_c.number(d["beta"]),
            kind=d["kind"],
            at=d["at"],
            side=d.get("side"),
        )


@dataclass(frozen=True, eq=False)
class LoadLimitState(_c.Result):
    """A limit state of the live load: its multiplier, mode, pattern, reactions, mechanism and
    the live load's power; for the least of a continuum of limit states, `continuum_to`.

    Attributes:
        lambda_: (JSON `lambda`) Its multiplier λ.
        mode: Its collapse mode.
        pattern: Its active contacts.
        reactions: Its reactions.
        mechanism: Its mechanism.
        live_power: The live load's power on the mechanism.
        continuum_to: The largest λ of a continuum of limit states this one is the least
            of.
    """

    lambda_: float
    mode: str
    pattern: Tuple[LoadContact, ...]
    reactions: Reactions
    mechanism: Mechanism
    live_power: float
    continuum_to: Optional[float] = None

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "LoadLimitState":
        return cls(
            lambda_=_c.number(d["lambda"]),
            mode=d["mode"],
            pattern=tuple(LoadContact._of(y) for y in d["pattern"]),
            reactions=Reactions._of(d["reactions"]),
            mechanism=Mechanism._of(d["mechanism"]),
            live_power=_c.number(d["live_power"]),
            continuum_to=None if (v := d.get("continuum_to")) is None else float(v),
        )


@dataclass(frozen=True, eq=False)
class LoadResult(_x.LoadExtras, _c.Result):
    """The collapse multiplier of a live load at (η, μ) (`load`): `lambda` (the least limit
    state: the collapse), `lambda_static` (the static maximum), every limit state below it,
    `unique` and `reduction`. `status` is `ok` or a no-answer status with `message`.

    Attributes:
        version: The document format's version (2).
        status: `ok`, or why there is no answer.
        arch: The arch.
        eta: The thickness ratio η.
        load: The live load.
        limit_states: Every limit state with λ in [0, λ_static], ascending
            (`unresolved`: the ones found, each verified; others may lie below).
        lambda_: (JSON `lambda`) The collapse multiplier λ_c: the least limit state's.
        lambda_at_most: `unresolved` with limit states found: the least λ found, which
            the collapse multiplier does not exceed.
        lambda_min: The least admissible multiplier (negative loads allowed).
        lambda_static: The largest admissible multiplier (the static maximum).
        mechanism_at_static: Whether the state at λ_static carries a mechanism.
        message: Why there is no answer.
        mu: μ (`null` = ∞).
        reduction: 1 − λ_c / λ_static: how much non-associative friction lowers the
            collapse load.
        reduction_at_least: `unresolved` with a limit state found below λ_static: 1 −
            `lambda_at_most`/λ_static, which the reduction is at least.
        search: How the limit states were searched.
        unique: Whether exactly one limit state lies in [0, λ_static] (`null`: not
            decided).
        units: The answer in units (given the dimensions).
    """

    _rows = "limit_states"

    version: int
    status: str
    arch: ArchInfo
    eta: float
    load: LiveLoad
    limit_states: Tuple[LoadLimitState, ...]
    lambda_: Optional[float] = None
    lambda_at_most: Optional[float] = None
    lambda_min: Optional[float] = None
    lambda_static: Optional[float] = None
    mechanism_at_static: Optional[bool] = None
    message: Optional[str] = None
    mu: Optional[float] = None
    reduction: Optional[float] = None
    reduction_at_least: Optional[float] = None
    search: Optional[LoadSearch] = None
    unique: Optional[bool] = None
    units: Optional[Units] = None

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "LoadResult":
        return cls(
            version=int(d["version"]),
            status=d["status"],
            arch=ArchInfo._of(d["arch"]),
            eta=_c.number(d["eta"]),
            load=LiveLoad._of(d["load"]),
            limit_states=tuple(LoadLimitState._of(y) for y in d["limit_states"]),
            lambda_=None if (v := d.get("lambda")) is None else float(v),
            lambda_at_most=None if (v := d.get("lambda_at_most")) is None else float(v),
            lambda_min=None if (v := d.get("lambda_min")) is None else float(v),
            lambda_static=None if (v := d.get("lambda_static")) is None else float(v),
            mechanism_at_static=None if (v := d.get("mechanism_at_static")) is None else bool(v),
            message=d.get("message"),
            mu=None if (v := d.get("mu", _c.ABSENT)) is _c.ABSENT else _c.number(v),
            reduction=None if (v := d.get("reduction")) is None else float(v),
            reduction_at_least=None if (v := d.get("reduction_at_least")) is None else float(v),
            search=None if (v := d.get("search")) is None else LoadSearch._of(v),
            unique=None if (v := d.get("unique")) is None else bool(v),
            units=None if (v := d.get("units")) is None else Units._of(v),
        )


@dataclass(frozen=True, eq=False)
class LoadSearch(_c.Result):
    """How the limit states under the load were searched.

    Attributes:
        method: The method.
        events: The points it checked.
    """

    method: str
    events: int

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "LoadSearch":
        return cls(
            method=d["method"],
            events=int(d["events"]),
        )


@dataclass(frozen=True, eq=False)
class Mechanism(_x.MechanismExtras, _c.Result):
    """A mechanism on the active contacts: the rates, the dimension of the mechanism cone, the
    external power and the frictional dissipation, the residuals of compatibility and
    complementarity, and (`solve` only) the cone's extreme rays.

    Attributes:
        rates: The rate at each active contact (summing to 1).
        dof: The dimension of the mechanism cone (1: a unique mechanism up to scale).
        power: The power of the weight (and of the live load) on the mechanism.
        dissipation: The power dissipated by friction.
        symmetric: Whether the mechanism is its own mirror image.
        compatibility_residual: |B λ|: how far the rates are from compatible.
        complementarity_residual: How far the rates are from complementary to the active
            contacts.
        rays: The extreme rays of the mechanism cone (rates on the contacts of `rates`,
            in their order, each summing to 1): one when `dof` is 1, every vertex of the
            cone's section otherwise (`solve` only; absent elsewhere).
    """

    rates: Tuple[Rate, ...]
    dof: int
    power: float
    dissipation: float
    symmetric: bool
    compatibility_residual: float
    complementarity_residual: float
    rays: Optional[np.ndarray] = None

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "Mechanism":
        return cls(
            rates=tuple(Rate._of(y) for y in d["rates"]),
            dof=int(d["dof"]),
            power=_c.number(d["power"]),
            dissipation=_c.number(d["dissipation"]),
            symmetric=bool(d["symmetric"]),
            compatibility_residual=_c.number(d["compatibility_residual"]),
            complementarity_residual=_c.number(d["complementarity_residual"]),
            rays=None if (v := d.get("rays")) is None else _c.matrix(v),
        )


@dataclass(frozen=True, eq=False)
class ModesResult(_x.ModesExtras, _c.Result):
    """The whole η–μ limit curve (`modes`): branches with their collapse modes, exact corners,
    smooth transitions and the limit states above the boundary. `status` is `ok`,
    `no_equilibrium`, `no_collapse` or `unresolved`.

    Attributes:
        version: The document format's version (2).
        status: `ok`, `no_equilibrium`, `no_collapse` or `unresolved`.
        arch: The arch.
        branches: The branches of η_s(μ), in order of μ.
        corners: Kinks of η_s(μ).
        transitions: Smooth pattern changes of η_s(μ).
        limit_branches: Limit states above the boundary, by samples.
        unresolved: Where the curve is not decided.
        no_collapse: Sampled μ at which the arch stands at every thickness (no
            collapse).
        no_equilibrium: Sampled μ at which no thickness stands.
        mu_min: The least friction at which the arch stands at some thickness (μ_ms);
            the same value as `mu_ms`, under the name the contract gives it.
        mu_ms: μ_ms.
        thickness_limit: Where the boundary reaches the thickness limit η → 2 above μ_ms
            (then no purely-sliding corner, and `mu_min` is this μ), else `null`.
    """

    _rows = "corners"

    version: int
    status: str
    arch: ArchInfo
    branches: Tuple[Branch, ...]
    corners: Tuple[Corner, ...]
    transitions: Tuple[Corner, ...]
    limit_branches: Tuple[LimitBranch, ...]
    unresolved: Tuple[Unresolved, ...]
    no_collapse: np.ndarray
    no_equilibrium: np.ndarray
    mu_min: Optional[float] = None
    mu_ms: Optional[float] = None
    thickness_limit: Optional[ThicknessLimit] = None

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "ModesResult":
        return cls(
            version=int(d["version"]),
            status=d["status"],
            arch=ArchInfo._of(d["arch"]),
            branches=tuple(Branch._of(y) for y in d["branches"]),
            corners=tuple(Corner._of(y) for y in d["corners"]),
            transitions=tuple(Corner._of(y) for y in d["transitions"]),
            limit_branches=tuple(LimitBranch._of(y) for y in d["limit_branches"]),
            unresolved=tuple(Unresolved._of(y) for y in d["unresolved"]),
            no_collapse=_c.numbers(d["no_collapse"]),
            no_equilibrium=_c.numbers(d["no_equilibrium"]),
            mu_min=None if (v := d.get("mu_min")) is None else float(v),
            mu_ms=None if (v := d.get("mu_ms")) is None else float(v),
            thickness_limit=None if (v := d.get("thickness_limit")) is None else ThicknessLimit._of(v),
        )


@dataclass(frozen=True, eq=False)
class Rate(_c.Result):
    """One contact's rate in a mechanism.

    Attributes:
        beta: The joint angle (radians).
        kind: The contact (`hinge_extrados`, `hinge_intrados`, `slide_plus`,
            `slide_minus`).
        rate: Its rate (the rates of a mechanism sum to 1).
    """

    beta: float
    kind: str
    rate: float

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "Rate":
        return cls(
            beta=_c.number(d["beta"]),
            kind=d["kind"],
            rate=_c.number(d["rate"]),
        )


@dataclass(frozen=True, eq=False)
class Reactions(_c.Result):
    """The redundant reactions at the right springing: h, v (forces) and w (moment), in units
    of γ t d r (and r).

    Attributes:
        h: Horizontal force.
        v: Vertical force.
        w: Moment.
    """

    h: float
    v: float
    w: float

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "Reactions":
        return cls(
            h=_c.number(d["h"]),
            v=_c.number(d["v"]),
            w=_c.number(d["w"]),
        )


@dataclass(frozen=True, eq=False)
class SafestState(_c.Result):
    """The admissible state of largest margin: the reactions h, v, w and the margin.

    Attributes:
        h: Horizontal reaction.
        v: Vertical reaction.
        w: Moment reaction.
        margin: Its margin: the least distance of any contact from activation, relative.
    """

    h: float
    v: float
    w: float
    margin: float

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "SafestState":
        return cls(
            h=_c.number(d["h"]),
            v=_c.number(d["v"]),
            w=_c.number(d["w"]),
            margin=_c.number(d["margin"]),
        )


@dataclass(frozen=True, eq=False)
class Search(_c.Result):
    """How every limit state above η_s was searched (`complete`: all were found).

    Attributes:
        complete: Whether the search is complete: every limit state in [η_s, 2) is
            listed.
        events: The points the search checked.
        method: `ridge`, `sweep` or the like.
        reason: Why the search could not be completed.
    """

    complete: bool
    events: Optional[int] = None
    method: Optional[str] = None
    reason: Optional[str] = None

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "Search":
        return cls(
            complete=bool(d["complete"]),
            events=None if (v := d.get("events")) is None else int(v),
            method=d.get("method"),
            reason=d.get("reason"),
        )


@dataclass(frozen=True, eq=False)
class SolveResult(_x.SolveExtras, _c.Result):
    """The least thickness η*(μ) and every limit state with η in [η_s, 2) (`solve`). `status`
    is `ok` (answered), `no_equilibrium` (no thickness stands at this μ), `unresolved`
    (`eta_bracket` holds what is known) or `no_collapse`; `message` says why when not ok.
    `mode`, `pattern`, `reactions` and `mechanism` describe the least limit state.

    Attributes:
        version: The document format's version (2).
        status: `ok`, `no_equilibrium`, `unresolved` or `no_collapse`.
        arch: The arch.
        mu: The friction coefficient μ (`null`: ∞, no sliding).
        friction_angle_deg: atan μ in degrees.
        attained: Whether η_s is attained by a bounded state.
        candidates: With `--explain`: the patterns the enumeration tried.
        checks: The checks of the least limit state.
        eta: η*(μ) = η_s, the least thickness ratio t/r at which the arch stands.
        eta_bracket: What is known of η_s when it is `unresolved`: [lower, upper].
        fill: The fill (an arch with fill only).
        limit_states: Every limit state with η in [η_s, 2), ascending (with
            `search.complete` false: the ones found, each verified; others may exist).
        mechanism: The mechanism of the least limit state, with the extreme rays of its
            cone.
        mechanism_at_eta: Whether the least admissible state carries a non-associative
            mechanism.
        message: Why there is no answer (status not `ok`).
        mode: The collapse mode of the least limit state.
        mode_standard: false when the mode name is a descriptive one outside the
            contract's list
        mu_ms: μ_ms, the least friction at which some thickness stands (with
            `no_equilibrium`).
        pattern: The active contacts of the least limit state.
        reactions: The reactions of the least limit state.
        search: How the limit states were searched.
        thickness_scan: With fill: the scan of the thickness range
            (`crate::limit::filled`).
        unique: Whether exactly one limit state has η in [η_s, 2) (`null`: search not
            completed; `false` also when it was not completed but two limit states were
            found).
        vertical_branch: At μ = μ_ms: the purely sliding limit states of every η ≥ η_s.
    """

    _rows = "limit_states"

    version: int
    status: str
    arch: ArchInfo
    mu: float
    friction_angle_deg: float
    attained: Optional[bool] = None
    candidates: Optional[Tuple[Candidate, ...]] = None
    checks: Optional[Checks] = None
    eta: Optional[float] = None
    eta_bracket: Optional[Tuple[float, ...]] = None
    fill: Optional[Fill] = None
    limit_states: Optional[Tuple[LimitState, ...]] = None
    mechanism: Optional[Mechanism] = None
    mechanism_at_eta: Optional[bool] = None
    message: Optional[str] = None
    mode: Optional[str] = None
    mode_standard: Optional[bool] = None
    mu_ms: Optional[float] = None
    pattern: Optional[Tuple[Contact, ...]] = None
    reactions: Optional[Reactions] = None
    search: Optional[Search] = None
    thickness_scan: Optional[ThicknessScan] = None
    unique: Optional[bool] = None
    vertical_branch: Optional[VerticalBranch] = None

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "SolveResult":
        return cls(
            version=int(d["version"]),
            status=d["status"],
            arch=ArchInfo._of(d["arch"]),
            mu=_c.number(d["mu"]),
            friction_angle_deg=_c.number(d["friction_angle_deg"]),
            attained=None if (v := d.get("attained")) is None else bool(v),
            candidates=None if (v := d.get("candidates")) is None else tuple(Candidate._of(y) for y in v),
            checks=None if (v := d.get("checks")) is None else Checks._of(v),
            eta=None if (v := d.get("eta")) is None else float(v),
            eta_bracket=None if (v := d.get("eta_bracket")) is None else _c.pair(v),
            fill=None if (v := d.get("fill")) is None else Fill._of(v),
            limit_states=None if (v := d.get("limit_states")) is None else tuple(LimitState._of(y) for y in v),
            mechanism=None if (v := d.get("mechanism")) is None else Mechanism._of(v),
            mechanism_at_eta=None if (v := d.get("mechanism_at_eta")) is None else bool(v),
            message=d.get("message"),
            mode=d.get("mode"),
            mode_standard=None if (v := d.get("mode_standard")) is None else bool(v),
            mu_ms=None if (v := d.get("mu_ms")) is None else float(v),
            pattern=None if (v := d.get("pattern")) is None else tuple(Contact._of(y) for y in v),
            reactions=None if (v := d.get("reactions")) is None else Reactions._of(v),
            search=None if (v := d.get("search")) is None else Search._of(v),
            thickness_scan=None if (v := d.get("thickness_scan")) is None else ThicknessScan._of(v),
            unique=None if (v := d.get("unique")) is None else bool(v),
            vertical_branch=None if (v := d.get("vertical_branch")) is None else VerticalBranch._of(v),
        )


@dataclass(frozen=True, eq=False)
class ThicknessLimit(_c.Result):
    """Where the boundary reaches the thickness limit η → 2 above μ_ms.

    Attributes:
        mu: Where.
        eta: η there.
        pattern: The active contacts there.
        exact: Whether located by Newton.
    """

    mu: float
    eta: float
    pattern: Tuple[Contact, ...]
    exact: bool

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "ThicknessLimit":
        return cls(
            mu=_c.number(d["mu"]),
            eta=_c.number(d["eta"]),
            pattern=tuple(Contact._of(y) for y in d["pattern"]),
            exact=bool(d["exact"]),
        )


@dataclass(frozen=True, eq=False)
class ThicknessScan(_c.Result):
    """The scan of the thickness range of an arch with fill: `interval` when every scanned η
    above the lowest admissible one is admissible too, else the inadmissible ones (`gaps`).

    Attributes:
        nodes: The thicknesses scanned.
        eta_from: The least η scanned.
        eta_to: The largest η scanned.
        interval: Whether every scanned η above the lowest admissible one is admissible
            too.
        gaps: The inadmissible η above the lowest admissible one.
        lowest_admissible: The least admissible η scanned (absent: none).
    """

    nodes: int
    eta_from: float
    eta_to: float
    interval: bool
    gaps: np.ndarray
    lowest_admissible: Optional[float] = None

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "ThicknessScan":
        return cls(
            nodes=int(d["nodes"]),
            eta_from=_c.number(d["eta_from"]),
            eta_to=_c.number(d["eta_to"]),
            interval=bool(d["interval"]),
            gaps=_c.numbers(d["gaps"]),
            lowest_admissible=None if (v := d.get("lowest_admissible")) is None else float(v),
        )


@dataclass(frozen=True, eq=False)
class Units(_c.Result):
    """The answer in units (given the arch's dimensions).

    Attributes:
        force_unit_kn: γ t d r in kN (the unit of a point load, and of the horizontal
            force per unit λ).
        acceleration_ms2: λ g in m/s² (a horizontal load).
        acceleration_static_ms2: λ_static g in m/s².
        lambda_kn: λ in kN.
        lambda_static_kn: λ_static in kN.
    """

    force_unit_kn: float
    acceleration_ms2: Optional[float] = None
    acceleration_static_ms2: Optional[float] = None
    lambda_kn: Optional[float] = None
    lambda_static_kn: Optional[float] = None

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "Units":
        return cls(
            force_unit_kn=_c.number(d["force_unit_kn"]),
            acceleration_ms2=None if (v := d.get("acceleration_ms2")) is None else float(v),
            acceleration_static_ms2=None if (v := d.get("acceleration_static_ms2")) is None else float(v),
            lambda_kn=None if (v := d.get("lambda_kn")) is None else float(v),
            lambda_static_kn=None if (v := d.get("lambda_static_kn")) is None else float(v),
        )


@dataclass(frozen=True, eq=False)
class Unresolved(_c.Result):
    """A friction coefficient at which the curve is not decided, and why.

    Attributes:
        mu: Where.
        message: Why.
    """

    mu: float
    message: str

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "Unresolved":
        return cls(
            mu=_c.number(d["mu"]),
            message=d["message"],
        )


@dataclass(frozen=True, eq=False)
class VerifyResult(_c.Result):
    """The independent re-check of a certificate: `status` `ok` (it holds: `statement` says
    what is proved) or `rejected` (`reason`; nothing is proved).

    Attributes:
        arch: The certificate's arch.
        checks: One line per check that passed, each saying whether it was proved
            (interval arithmetic) or checked (floating point, evidence only).
        claim: What is claimed.
        status: `ok` or `rejected`.
        version: The document format's version (2).
        eta: The load certificate's thickness ratio.
        eta_hi: The upper end of the bracket of η*.
        eta_lo: The lower end of the bracket of η*.
        lambda_hi: The upper end of the bracket of λ (load certificates).
        lambda_lo: The lower end of the bracket of λ (load certificates).
        limit_states: What the limit-state search lists (certificates with a search
            section).
        load: The live load (load certificates).
        mu: μ (`null` = ∞).
        reason: Why the certificate is rejected.
        statement: The proved statement, in one line.
    """

    arch: CertifiedArch
    checks: Tuple[str, ...]
    claim: str
    status: str
    version: int
    eta: Optional[float] = None
    eta_hi: Optional[float] = None
    eta_lo: Optional[float] = None
    lambda_hi: Optional[float] = None
    lambda_lo: Optional[float] = None
    limit_states: Optional[str] = None
    load: Optional[Dict[str, Any]] = None
    mu: Optional[float] = None
    reason: Optional[str] = None
    statement: Optional[str] = None

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "VerifyResult":
        return cls(
            arch=CertifiedArch._of(d["arch"]),
            checks=tuple(d["checks"]),
            claim=d["claim"],
            status=d["status"],
            version=int(d["version"]),
            eta=None if (v := d.get("eta")) is None else float(v),
            eta_hi=None if (v := d.get("eta_hi")) is None else float(v),
            eta_lo=None if (v := d.get("eta_lo")) is None else float(v),
            lambda_hi=None if (v := d.get("lambda_hi")) is None else float(v),
            lambda_lo=None if (v := d.get("lambda_lo")) is None else float(v),
            limit_states=d.get("limit_states"),
            load=None if (v := d.get("load")) is None else dict(v),
            mu=None if (v := d.get("mu", _c.ABSENT)) is _c.ABSENT else _c.number(v),
            reason=d.get("reason"),
            statement=d.get("statement"),
        )


@dataclass(frozen=True, eq=False)
class VerticalBranch(_c.Result):
    """The vertical branch at μ = μ_ms: from `eta_min` up, every admissible state is a limit
    state with the purely sliding mechanism on `pattern`.

    Attributes:
        eta_min: The least thickness of the branch (η_s).
        mode: Its mode (purely sliding).
        pattern: The sliding contacts.
    """

    eta_min: float
    mode: str
    pattern: Tuple[Contact, ...]

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "VerticalBranch":
        return cls(
            eta_min=_c.number(d["eta_min"]),
            mode=d["mode"],
            pattern=tuple(Contact._of(y) for y in d["pattern"]),
        )

"""The input type ``Arch`` and the checks of arguments (the result types are generated
from the command line's JSON Schema: ``_types.py``).

No numerics here: every number comes from the Rust library (``arch_enum._native``).
Conventions as in the library: lengths divided by the mean radius r (eta = t/r), angles
in radians counter-clockwise from the horizontal through the centre, forces in units of
gamma t d r. ``math.inf`` stands for mu = infinity (no sliding) and for the other
quantities the JSON documents write as ``null`` = +infinity.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional, Tuple

import numpy as np

from . import _convert as _c
from . import _native


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


@dataclass(frozen=True)
class Arch(_c.Result):
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
        return None if j is None else _c.numbers(j)

    @property
    def symmetric(self) -> bool:
        """Whether the arch (springings and joints) is mirror-symmetric."""
        return bool(self._info["symmetric"])  # type: ignore[attr-defined]

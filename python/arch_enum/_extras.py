"""What the generated result types (``_types.py``) do beyond holding their document:
figures, columns, saving. Hand-written mixins; the data and its names come from the
schema. A result made by a function of this package knows its input arch (``_input``)
and, for ``solve``, the lines of the state drawn (``_lines``); the figures need them.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from typing import Any, Dict, Optional, Tuple

import numpy as np

from . import _native


def _f64(b: bytes) -> np.ndarray:
    """A read-only 1-D float array from the bytes of little-endian f64 (the native module
    hands the lines over so, without a Python float per number)."""
    return np.frombuffer(b, dtype="<f8")


@dataclass(frozen=True, eq=False)
class Lines:
    """The samples of the state drawn: joint angles ``beta``, normal force ``n``, the
    eccentricities ``e_m`` = M/N and ``e_t`` = (T/N)/mu * eta/2 (NaN where N = 0)."""

    beta: np.ndarray
    n: np.ndarray
    e_m: np.ndarray
    e_t: np.ndarray


class ArchInfoExtras:
    @property
    def springings(self) -> Tuple[float, float]:
        """(beta_R, beta_L) in radians."""
        return (self.beta_right, self.beta_left)  # type: ignore[attr-defined]


class MechanismExtras:
    """Columns of the rates: ``beta``, ``kind`` and ``rate`` of each contact."""

    @property
    def beta(self) -> np.ndarray:
        """The joint angle of each rate (read-only array)."""
        return _column([r.beta for r in self.rates])  # type: ignore[attr-defined]

    @property
    def kind(self) -> Tuple[str, ...]:
        """The contact kind of each rate."""
        return tuple(r.kind for r in self.rates)  # type: ignore[attr-defined]

    @property
    def rate(self) -> np.ndarray:
        """The rates (summing to 1; read-only array)."""
        return _column([r.rate for r in self.rates])  # type: ignore[attr-defined]


def _no_points() -> np.ndarray:
    """A read-only (0, 2) array: no line drawn."""
    a = np.zeros((0, 2))
    a.flags.writeable = False
    return a


def _column(values: Any) -> np.ndarray:
    a = np.array([math.nan if v is None else v for v in values], dtype=float)
    a.flags.writeable = False
    return a


class SolveExtras:
    """The lines of the state drawn (the least limit state): ``thrust_line``,
    ``friction_line`` ((n, 2) arrays of x, y in units of r; ``None`` at mu = inf),
    ``outline``, ``lines`` (the samples) and ``eta_drawn``; the figure and the COMPAS
    document of that state."""

    def _line(self, key: str) -> Optional[np.ndarray]:
        d = getattr(self, "_lines", None)
        if d is None or not d[key]:
            return None
        return _f64(d[key]).reshape(-1, 2)

    @property
    def lines(self) -> Optional[Lines]:
        """The samples along the arch of the state drawn (``None``: none drawn)."""
        d = getattr(self, "_lines", None)
        if d is None:
            return None
        return Lines(_f64(d["beta"]), _f64(d["n"]), _f64(d["e_m"]), _f64(d["e_t"]))

    @property
    def eta_drawn(self) -> Optional[float]:
        """The thickness of the state drawn."""
        d = getattr(self, "_lines", None)
        return None if d is None else float(d["eta"])

    @property
    def thrust_line(self) -> np.ndarray:
        """The line of thrust, (n, 2) (empty when no state is drawn)."""
        line = self._line("thrust_line")
        return _no_points() if line is None else line

    @property
    def friction_line(self) -> Optional[np.ndarray]:
        """The line of friction, (n, 2) (``None`` at mu = inf or when none is drawn)."""
        return self._line("friction_line")

    @property
    def outline(self) -> np.ndarray:
        """The arch's outline, (n, 2) (empty when no state is drawn)."""
        line = self._line("outline")
        return _no_points() if line is None else line

    def _repr_svg_(self) -> Optional[str]:
        """The arch to scale at the least limit state with its lines of thrust and
        friction and the mechanism (the library's ``plot arch`` figure)."""
        if getattr(self, "_lines", None) is None:
            return None
        return _native.solve_svg(self._input._spec(), self.mu)  # type: ignore[attr-defined]

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
        if getattr(self, "_lines", None) is None:
            raise ValueError(
                f"no limit state to draw (status {self.status}): {self.message}"  # type: ignore[attr-defined]
            )
        return _native.solve_compas(
            self._input._spec(), self.mu, float(radius)  # type: ignore[attr-defined]
        )


class CurveExtras:
    """Columns over the points: ``mu``, ``friction_angle_deg``, ``eta`` (NaN where a
    point has none), ``mode``, ``pattern``, ``message``, and :meth:`column` for any field
    of a point (``column("status")``)."""

    def column(self, name: str) -> Any:
        """The field ``name`` of every point: a read-only float array for numbers (NaN
        where a point has none), else a tuple."""
        values = [getattr(p, name) for p in self.points]  # type: ignore[attr-defined]
        if name in ("mu", "friction_angle_deg", "eta"):
            return _column(values)
        return tuple(values)

    @property
    def mu(self) -> np.ndarray:
        """The friction coefficients, in the order given."""
        return self.column("mu")

    @property
    def friction_angle_deg(self) -> np.ndarray:
        """atan(mu) in degrees."""
        return self.column("friction_angle_deg")

    @property
    def eta(self) -> np.ndarray:
        """eta*(mu) (NaN where a point is not ``ok``)."""
        return self.column("eta")

    @property
    def mode(self) -> Tuple[Optional[str], ...]:
        """The collapse mode of each point."""
        return self.column("mode")

    @property
    def pattern(self) -> Tuple[Any, ...]:
        """The active pattern of each point."""
        return self.column("pattern")

    @property
    def message(self) -> Tuple[Optional[str], ...]:
        """Why a point is not ``ok`` (else ``None``)."""
        return self.column("message")

    def __len__(self) -> int:
        return len(self.points)  # type: ignore[attr-defined]


class ModesExtras:
    def _repr_svg_(self) -> Optional[str]:
        """The limit-state diagram of the arch (the library's ``plot curve`` figure)."""
        if self.mu_ms is None:  # type: ignore[attr-defined]
            return None
        return _native.modes_svg(self._input._spec())  # type: ignore[attr-defined]


class AssessExtras:
    def _repr_svg_(self) -> Optional[str]:
        """The arch at ``eta`` with its safest line of thrust (the library's
        ``plot arch --eta`` figure); ``None`` when it does not stand."""
        if not self.stands:  # type: ignore[attr-defined]
            return None
        return _native.assess_svg(
            self._input._spec(), self.eta, self.mu  # type: ignore[attr-defined]
        )


class LoadExtras:
    def _repr_svg_(self) -> Optional[str]:
        """Every limit state of the load, one panel each (the library's ``plot load``
        figure); ``None`` when there is none."""
        if not self.limit_states:  # type: ignore[attr-defined]
            return None
        return _native.load_svg(*self._call)  # type: ignore[attr-defined]


class CertifyExtras:
    def to_json(self) -> str:
        """The certificate as the JSON text ``arch-enum certify --out`` writes."""
        if self.certificate is None:  # type: ignore[attr-defined]
            raise ValueError(
                f"no certificate (status {self.status}): {self.message}"  # type: ignore[attr-defined]
            )
        return json.dumps(self.certificate, indent=2)  # type: ignore[attr-defined]

    def save(self, path: Any) -> None:
        """Writes the certificate (readable by ``arch-enum verify`` and
        :func:`arch_enum.verify`)."""
        with open(path, "w", encoding="utf-8") as f:
            f.write(self.to_json() + "\n")

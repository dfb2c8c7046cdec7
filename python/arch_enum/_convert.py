"""The converters of the generated result types (``_types.py``): JSON values as Python
ones. No numerics here. ``null`` is +infinity for a number that is always present (the
command line's convention), ``math.inf`` in Python.
"""

from __future__ import annotations

import dataclasses
import keyword
import math
from typing import Any, Dict, Optional

import numpy as np


#: What ``dict.get`` gives for a key a document leaves out (where ``null`` means +infinity).
ABSENT = object()


def number(v: Optional[float]) -> float:
    """A JSON number where ``null`` stands for +infinity."""
    return math.inf if v is None else float(v)


def pair(v: Any) -> tuple:
    """A list of a fixed number of numbers as a tuple of floats."""
    return tuple(number(x) for x in v)


def numbers(v: Any) -> np.ndarray:
    """A list of numbers as a read-only 1-D float array (``null`` is +infinity)."""
    a = np.array([math.inf if x is None else x for x in v], dtype=float)
    a.flags.writeable = False
    return a


def matrix(v: Any) -> np.ndarray:
    """A list of equally long lists of numbers as a read-only 2-D float array."""
    a = np.array(v, dtype=float).reshape(len(v), -1) if len(v) else np.zeros((0, 0))
    a.flags.writeable = False
    return a


def key(name: str) -> str:
    """The JSON key of a field (``lambda_`` is ``lambda``)."""
    return name[:-1] if name.endswith("_") and keyword.iskeyword(name[:-1]) else name


def plain(v: Any) -> Any:
    """Plain Python data: dataclasses as dicts keyed as the JSON documents, arrays as
    lists."""
    if dataclasses.is_dataclass(v) and not isinstance(v, type):
        return {key(f.name): plain(getattr(v, f.name)) for f in dataclasses.fields(v)}
    if isinstance(v, np.ndarray):
        return v.tolist()
    if isinstance(v, (list, tuple)):
        return [plain(x) for x in v]
    if isinstance(v, dict):
        return {k: plain(x) for k, x in v.items()}
    return v


class Result:
    """What every result type has: ``to_dict`` and ``to_pandas``."""

    # the field whose items are the rows of ``to_pandas`` (None: one row of the fields)
    _rows: Optional[str] = None

    def to_dict(self) -> Dict[str, Any]:
        """The fields as plain Python data (nested dicts and lists; arrays as lists;
        infinity stays ``math.inf``): the command's JSON document, key for key."""
        return plain(self)

    def to_pandas(self) -> Any:
        """A ``pandas.DataFrame`` (needs ``pandas``): one row per item of the list the
        result holds (limit states, corners, points, ...), or one row of its fields;
        nested fields are flattened into dotted columns (``reactions.h``)."""
        try:
            import pandas as pd
        except ImportError as e:  # pragma: no cover - exercised without pandas
            raise ImportError("to_pandas() needs the optional dependency pandas") from e
        d = self.to_dict()
        rows = (d[self._rows] or []) if self._rows is not None else [d]
        return pd.json_normalize(rows)

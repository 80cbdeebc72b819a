"""The numbers every face reads the same way, checked by the library's own
functions (stratum/registry/spec.hpp), so Python and the CLI cannot disagree."""
from __future__ import annotations

import numbers

import numpy as np

from . import _stratum
from ._stratum import InvalidArgument

_THREADS = "must be an integer in [0, 1024] (0: every core)"
_SEED = "must be an integer in [0, 2^64) = [0, 18446744073709551615]"


def _is_integer(value) -> bool:
    return not isinstance(value, bool) and isinstance(value, numbers.Integral) and type(value).__name__ != "bool_"


def threads(value) -> int:
    """The thread rule of every face: 0 = every core, else 1..1024."""
    if not _is_integer(value) or not -2**63 <= value < 2**63:
        raise InvalidArgument(f"invalid threads = {value!r}: {_THREADS}")
    return _stratum.resolve_threads(int(value))


def seed(value) -> int:
    """A seed: exactly the integers in [0, 2^64)."""
    if not _is_integer(value):
        raise InvalidArgument(f"invalid seed = {value!r}: {_SEED}")
    return _stratum.parse_seed(str(int(value)))


def text(name, value, optional=False) -> str:
    """A string argument (None too where `optional`: then "")."""
    if value is None and optional:
        return ""
    if not isinstance(value, str):
        raise InvalidArgument(f"invalid {name} = {value!r}: must be a string" + (" or None" if optional else ""))
    return value


def real(name, value) -> float:
    """A real number: an int or float (numpy's too), never a string ('0.1'), a bool or a complex number."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise InvalidArgument(f"invalid {name} = {value!r}: must be a real number")
    return float(value)


def real_array(name, value, shape_text="an array of real numbers") -> np.ndarray:
    """`value` as float64, refusing what numpy would cast silently or
    loosely: complex numbers (the imaginary part dropped with only a
    warning), strings ("0.5" read as a number) and objects."""
    try:
        raw = np.asarray(value)
    except (TypeError, ValueError):
        raise InvalidArgument(f"invalid {name} = {type(value).__name__} object: must be {shape_text}") from None
    if raw.dtype.kind not in "biuf":
        what = {"c": "complex numbers", "U": "strings", "S": "bytes", "O": "objects"}.get(raw.dtype.kind, str(raw.dtype))
        raise InvalidArgument(f"invalid {name} = array of {what}: must be {shape_text}")
    return raw.astype(np.float64, copy=False)

"""The numbers every face reads the same way, checked by the library's own
functions (stratum/registry/spec.hpp), so Python and the CLI cannot disagree."""
from __future__ import annotations

import numbers

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

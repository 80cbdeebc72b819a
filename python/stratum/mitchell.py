"""Mitchell's comparison of patterns by random-edge discrepancy (LECTURE.md
§12; Mitchell 1992, "Ray tracing and irregularities of distribution").

>>> import stratum
>>> s = stratum.study_mitchell(counts=(16,), realizations=4, lines=500)
>>> [p["sampler"] for p in s["patterns"]]
['zaremba', 'jittered', 'poisson-disk', 'n-rooks', 'random']
>>> cell = s["patterns"][1]["cells"][0]        # jittered at N = 16
>>> sorted(cell)
['max', 'mean', 'n', 'requested', 'rms', 'rms_values']
"""
from __future__ import annotations

import numbers

from . import _checks, _stratum
from ._stratum import InvalidArgument

__all__ = ["study_mitchell"]


def _integer(name, value, low, high, allowed):
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or not low <= value <= high:
        raise InvalidArgument(f"invalid {name} = {value!r}: {allowed}")
    return int(value)


def study_mitchell(counts=(16, 256, 1600), realizations: int = 20, lines: int = 10000, seed: int = 0,
                   threads: int = 1, samplers=()) -> dict:
    """Random-edge discrepancy of Zaremba, jittered, Poisson-disk (periodic),
    N-rooks and random patterns at each count, over `realizations` K pattern
    realizations with `lines` L random lines each, beside each pattern's
    radially averaged power spectrum. Same numbers as ``stratum study mitchell``.
    ``samplers``: extra registry patterns ("name" or "name:randomizer", 2D)
    compared after Mitchell's five, as ``--sampler`` does.

    Returns a dict: "patterns" (one per pattern: "label", "sampler",
    "params", "cells" (per count: "requested", "n" actually used, "rms",
    "mean", "max" each {"mean", "se"}, and "rms_values" per realization),
    "spectrum" ({"n", "frequency" (normalized by sqrt(n)), "power"}) and
    "example" (one realization's points, flat x, y)), "notes" (count
    substitutions), "table" (the text table), and the options.
    """
    if isinstance(counts, (str, bytes)) or not hasattr(counts, "__iter__"):
        raise InvalidArgument(f"invalid counts = {counts!r}: must be a sequence of integers in [2, 10^6]")
    counts = [_integer("counts", n, 2, 10**6, "each count must be an integer in [2, 10^6]") for n in counts]
    if not counts:
        raise InvalidArgument("invalid counts = []: give at least one count")
    realizations = _integer("realizations", realizations, 1, 10**5, "must be an integer in [1, 10^5]")
    lines = _integer("lines", lines, 1, 10**8, "must be an integer in [1, 10^8]")
    seed = _checks.seed(seed)
    threads = _checks.threads(threads)
    if isinstance(samplers, (str, bytes)):
        samplers = [samplers]
    return _stratum.study_mitchell(counts, realizations, lines, seed, threads, [str(s) for s in samplers])

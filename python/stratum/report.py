"""The lecture reproduced as one HTML page (LECTURE.md §1–13), as `stratum report`."""
from __future__ import annotations

from . import _checks, _stratum

__all__ = ["report", "report_sections", "lecture_slides"] if hasattr(_stratum, "report") else []


def report_sections() -> list[dict]:
    """Every section of the report: id, lecture (the LECTURE.md section) and title."""
    return _stratum.report_sections()


def lecture_slides() -> list[dict]:
    """The lecture slide by slide: lecture (the LECTURE.md section), title,
    formula ("" where the slide states none), and the report section and
    anchor on the page ("figure-…", "table-…", or "" for the whole section)
    that reproduce it."""
    return _stratum.lecture_slides()


def report(directory: str = "report", quick: bool = False, samplers=(), only=(), threads: int = 1, seed: int = 0,
           cache: str = ".stratum-cache", verbose: bool = False) -> dict:
    """Writes DIRECTORY/index.html, report.json and figures/; returns
    {"index": path, "seconds": s, "numbers": {section id: measurements}}.

    samplers: extra registry samplers (specs NAME[(KEY=VALUE,...)][:RANDOMIZER],
    docs/samplers.md) added to the pattern comparisons; only: section ids to
    run (default all). threads: 1 by default, as every function of the
    package (threads=0: every core).
    Raises stratum.InvalidArgument on bad options, before any work."""
    index, numbers, seconds = _stratum.report(str(directory), bool(quick), list(samplers), list(only),
                                              _checks.threads(threads), _checks.seed(seed), str(cache), bool(verbose))
    return {"index": index, "seconds": seconds, "numbers": numbers}

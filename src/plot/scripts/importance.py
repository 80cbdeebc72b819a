"""Figure for `stratum study importance --plot` (LECTURE.md §3): left, the
variance ratio of area vs solid-angle sampling of a square light against
size / distance (measured with ±1 standard error, and predicted), one line per
distance; right, the efficiency ratio. The hemisphere comparisons (uniform vs
cosine) are listed in the title.
Usage: python3 importance.py DATA.json OUT.png"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import LogFormatterSciNotation, LogLocator  # noqa: E402

with open(sys.argv[1]) as handle:
    data = json.load(handle)

figure, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2))
distances = sorted({row["distance"] for row in data["light"]})
for distance in distances:
    rows = sorted((r for r in data["light"] if r["distance"] == distance), key=lambda r: r["size"])
    x = [r["size"] / distance for r in rows]
    ratio = [r["variance_ratio"] for r in rows]
    error = [r["variance_ratio_stderr"] or 0 for r in rows]
    line = left.errorbar(x, ratio, yerr=error, marker="o", capsize=3, label=f"distance {distance:g}")
    left.plot(x, [r["predicted_variance_ratio"] for r in rows], linestyle=":", color=line[0].get_color())
    right.plot(x, [r["efficiency_ratio"] for r in rows], marker="o", label=f"distance {distance:g}")
for axes, name in ((left, "variance ratio (area / solid angle)"), (right, "efficiency ratio (solid angle / area)")):
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlabel("light size / distance")
    axes.set_ylabel(name)
    for axis in (axes.xaxis, axes.yaxis):  # more than one labelled tick on short log ranges
        low, high = axis.get_view_interval()
        if low > 0 and high / low < 30:
            axis.set_minor_locator(LogLocator(subs=(2.0, 5.0)))
            axis.set_minor_formatter(LogFormatterSciNotation(labelOnlyBase=False, minor_thresholds=(100, 100)))
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(fontsize="small")
left.set_title("measured (±1 s.e.), predicted dotted", fontsize="medium")


def ratio_text(row):
    value = row["variance_ratio"]
    if value is None or value > 1e15:
        return "cosine-weighted sampling has zero variance (the ratio is infinite)"
    return f"uniform has {value:.3g}× the variance of cosine-weighted sampling"


hemisphere = "; ".join(f'{r["scene"]}: {ratio_text(r)}' for r in data["hemisphere"])
figure.suptitle(f'Solid-angle against area sampling of a square light, {data["runs"]} runs × {data["samples"]} '
                f'samples.\nHemisphere: {hemisphere}.', fontsize="medium")
figure.tight_layout()
figure.savefig(sys.argv[2], dpi=110)

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
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(fontsize="small")
left.set_title("measured (±1 s.e.), predicted dotted", fontsize="medium")


def ratio_text(row):
    value = row["variance_ratio"]
    return "variance 0 (exact)" if value is None or value > 1e15 else f"{value:.3g}"


hemisphere = "; ".join(f'{r["scene"]}: uniform/cosine variance ratio {ratio_text(r)}' for r in data["hemisphere"])
figure.suptitle(f'Importance sampling, {data["runs"]} runs x {data["samples"]} samples\n{hemisphere}',
                fontsize="medium")
figure.tight_layout()
figure.savefig(sys.argv[2], dpi=110)

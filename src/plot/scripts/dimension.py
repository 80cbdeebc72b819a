"""Figure for `stratum study dimension --plot`: one log-log panel per d with
the product rule's error, the Monte Carlo RMSE (and its exact σ/√N) and the
Owen-scrambled Sobol' RMSE against N, slopes in the legend (LECTURE.md §6).
Usage: python3 dimension.py DATA.json OUT.png"""
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

with open(sys.argv[1]) as handle:
    data = json.load(handle)

series = data["series"]
columns = min(3, len(series))  # 10.8 in at 100 dpi: legible without scaling down on a 1100 px page
rows = math.ceil(len(series) / columns)
figure, axes = plt.subplots(rows, columns, figsize=(3.6 * columns, 3.0 * rows), squeeze=False, sharey=True)


def slope_text(value):
    return "n/a" if value is None else f"{value:.2f}"


def draw(ax, n, values, **style):
    points = [(a, b) for a, b in zip(n, values) if b is not None and b > 0]
    if points:
        ax.loglog(*zip(*points), **style)


for index, s in enumerate(series):
    ax = axes[index // columns][index % columns]
    n = s["n"]
    draw(ax, n, s["product_error"], marker="s", label=f'{data["rule"]} ({slope_text(s["product_slope"])})')
    draw(ax, n, s["mc_rmse"], marker="o", label=f'MC ({slope_text(s["mc_slope"])})')
    draw(ax, n, s["mc_predicted"], linestyle=":", color="gray", label="σ/√N")
    if s["sobol_rmse"]:
        draw(ax, n, s["sobol_rmse"], marker="^", label=f"Sobol' ({slope_text(s['sobol_slope'])})")
    ax.set_title(f'd = {s["d"]}', fontsize="medium")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    if index % columns == 0:
        ax.set_ylabel("error")
    if index // columns == rows - 1:
        ax.set_xlabel("N")
for index in range(len(series), rows * columns):
    axes[index // columns][index % columns].axis("off")
figure.suptitle(f'The {data["rule"]} product rule against Monte Carlo on {data["integrand"]}, {data["runs"]} runs per N')
figure.tight_layout()
figure.savefig(sys.argv[2], dpi=100)

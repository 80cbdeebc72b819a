"""Pattern comparison for the report (LECTURE.md §12): each pattern's points
(one realization) above its radially averaged power spectrum, wrapped into
balanced rows of at most six patterns. (The random-edge table is on the page itself.)
Data: {"patterns": [{"label", "example": [x0, y0, x1, y1, ...],
       "spectrum": {"n", "frequency", "power"}}]}
Usage: python3 report_patterns.py DATA.json OUT.png"""
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

with open(sys.argv[1]) as handle:
    data = json.load(handle)
patterns = data["patterns"]
blocks = math.ceil(len(patterns) / 4)  # at most 4 a row: 10.4 in at 100 dpi, not scaled down on the page
columns = math.ceil(len(patterns) / blocks)  # balanced rows
figure = plt.figure(figsize=(2.6 * columns, 5.0 * blocks))
grid = figure.add_gridspec(2 * blocks, columns, height_ratios=[3.0, 2.2] * blocks)
for index, pattern in enumerate(patterns):
    block, column = divmod(index, columns)
    spectrum = pattern["spectrum"]
    axes = figure.add_subplot(grid[2 * block, column])
    example = pattern["example"]
    axes.scatter(example[0::2], example[1::2], s=max(1.0, 400.0 / max(1, spectrum["n"])), color="black")
    axes.set_xlim(0, 1)
    axes.set_ylim(0, 1)
    axes.set_aspect("equal")
    axes.set_xticks([])
    axes.set_yticks([])
    axes.set_title(f'{pattern["label"]} (N = {spectrum["n"]})', fontsize=10)
    axes = figure.add_subplot(grid[2 * block + 1, column])
    axes.plot(spectrum["frequency"], spectrum["power"], color="tab:blue")
    axes.axhline(1.0, color="gray", linewidth=0.8, linestyle="--")
    axes.set_xlabel("frequency / √N")
    if column == 0:
        axes.set_ylabel("radial power")
    axes.set_ylim(bottom=0)
figure.tight_layout()
figure.savefig(sys.argv[2], dpi=data.get("dpi", 100))

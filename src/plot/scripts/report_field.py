"""Local-discrepancy pictures for the report (LECTURE.md §10): for each panel
a heat map of Delta(x, y) = n(x, y)/N - x*y over the unit square, the points
on top, and the anchored box [0,x) x [0,y) where |Delta| is largest.
Data: {"columns": C, "title": "...", "panels": [{"title", "resolution": R,
       "values": (R+1)^2 numbers, row j is y = j/R, column i is x = i/R,
       "x", "y" (points), "box": {"x", "y", "closed" (bool), "value"}}]}
Usage: python3 report_field.py DATA.json OUT.png"""
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.patches import Rectangle  # noqa: E402

with open(sys.argv[1]) as handle:
    data = json.load(handle)
panels = data["panels"]
columns = min(data.get("columns", len(panels)), len(panels))
rows = math.ceil(len(panels) / columns)
figure, axes_grid = plt.subplots(rows, columns, figsize=(4.6 * columns, 4.0 * rows + 0.4), squeeze=False)
# One colour scale for every panel, symmetric about 0, so panels compare.
limit = max(max(abs(v) for v in panel["values"]) for panel in panels) or 1.0
image = None
for index, axes in enumerate(axes_grid.flat):
    if index >= len(panels):
        axes.axis("off")
        continue
    panel = panels[index]
    side = panel["resolution"] + 1
    values = np.asarray(panel["values"], dtype=float).reshape(side, side)
    image = axes.imshow(values, origin="lower", extent=(0, 1, 0, 1), cmap="RdBu_r", vmin=-limit, vmax=limit,
                        interpolation="nearest")
    axes.scatter(panel["x"], panel["y"], s=8, color="black", linewidths=0, zorder=3)
    box = panel.get("box")
    if box:
        axes.add_patch(Rectangle((0, 0), box["x"], box["y"], fill=False, edgecolor="gold", linewidth=2.0,
                                 linestyle="-" if box.get("closed") else "--", zorder=4))
        axes.plot([box["x"]], [box["y"]], marker="o", markersize=7, markerfacecolor="none", markeredgecolor="gold",
                  markeredgewidth=2, zorder=5)
    axes.set_xlim(0, 1)
    axes.set_ylim(0, 1)
    axes.set_aspect("equal")
    axes.set_xlabel("x")
    axes.set_ylabel("y")
    axes.set_title(panel.get("title", ""), fontsize=10)
if image is not None:
    bar = figure.colorbar(image, ax=axes_grid.ravel().tolist(), shrink=0.85)
    bar.set_label("Δ(x, y) = n(x, y)/N − xy")
if data.get("title"):
    figure.suptitle(data["title"])
figure.savefig(sys.argv[2], dpi=data.get("dpi", 90), bbox_inches="tight")

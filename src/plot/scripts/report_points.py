"""Point-set panels for the report (and any face): each panel a scatter of 2D
points in the unit square or the unit disk, optionally coloured by stratum,
with grid lines and 1D projections drawn as ticks under and beside it.
Data: {"columns": C, "size": inches per panel, "title": "...",
       "panels": [{"title", "x", "y", "color" (optional ints), "grid" (optional
       cells per axis), "disk" (bool), "side" (bool: the upper half of
       the disk, for a hemisphere seen from the side), "projections" (bool), "line" (optional
       {"angle", "offset"}: the line cos(angle) x + sin(angle) y = offset, drawn
       with the side cos(angle) x + sin(angle) y < offset shaded), "lines"
       (optional [[xs, ys], ...]: polylines drawn under the points)}]}
Usage: python3 report_points.py DATA.json OUT.png"""
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def draw_line(axes, line):
    """The line clipped to the unit square, and its lower side shaded."""
    nx, ny, offset = math.cos(line["angle"]), math.sin(line["angle"]), line["offset"]
    grid = np.linspace(0.0, 1.0, 401)
    gx, gy = np.meshgrid(grid, grid)
    axes.contourf(gx, gy, (nx * gx + ny * gy < offset).astype(float), levels=[0.5, 1.5], colors=["tab:red"],
                  alpha=0.12, zorder=0)
    ends = []
    for t in (0.0, 1.0):  # crossings of x = t and y = t
        if abs(ny) > 1e-12:
            y = (offset - nx * t) / ny
            if -1e-9 <= y <= 1 + 1e-9:
                ends.append((t, y))
        if abs(nx) > 1e-12:
            x = (offset - ny * t) / nx
            if -1e-9 <= x <= 1 + 1e-9:
                ends.append((x, t))
    if len(ends) >= 2:
        ends.sort()
        axes.plot([ends[0][0], ends[-1][0]], [ends[0][1], ends[-1][1]], color="tab:red", linewidth=1.6, zorder=4)


with open(sys.argv[1]) as handle:
    data = json.load(handle)
panels = data["panels"]
columns = min(data.get("columns", len(panels)), len(panels))
rows = math.ceil(len(panels) / columns)
size = data.get("size", 3.0)
figure, axes_grid = plt.subplots(rows, columns, figsize=(size * columns, size * rows + 0.4), squeeze=False)
for index, axes in enumerate(axes_grid.flat):
    if index >= len(panels):
        axes.axis("off")
        continue
    panel = panels[index]
    disk = panel.get("disk", False)
    low = -1.0 if disk else 0.0
    color = panel.get("color")
    marker_size = max(2.0, min(18.0, 2400.0 / max(1, len(panel["x"]))))
    axes.scatter(panel["x"], panel["y"], s=marker_size, c=color if color is not None else "tab:blue",
                 cmap="hsv" if color is not None else None, linewidths=0)
    if disk:
        axes.add_patch(plt.Circle((0, 0), 1, fill=False, color="0.5", linewidth=0.8))
    for polyline in panel.get("lines", []):
        axes.plot(polyline[0], polyline[1], color="0.35", linewidth=0.6, zorder=1)
    cells = panel.get("grid", 0)
    for k in range(1, cells):
        axes.axhline(k / cells, color="0.8", linewidth=0.5, zorder=0)
        axes.axvline(k / cells, color="0.8", linewidth=0.5, zorder=0)
    if panel.get("projections", False):
        # 1D projections as ticks just outside the square.
        axes.plot(panel["x"], [-0.04] * len(panel["x"]), "|", color="k", markersize=6, clip_on=False)
        axes.plot([-0.04] * len(panel["y"]), panel["y"], "_", color="k", markersize=6, clip_on=False)
    if panel.get("line"):
        draw_line(axes, panel["line"])
    margin = 0.06 if panel.get("projections", False) else 0.01
    axes.set_xlim(low - margin, 1.01)
    axes.set_ylim(-0.04 if panel.get("side", False) else low - margin, 1.01)
    axes.set_aspect("equal")
    axes.set_xticks([])
    axes.set_yticks([])
    axes.set_title(panel.get("title", ""), fontsize=10)
if data.get("title"):
    figure.suptitle(data["title"])
figure.tight_layout()
figure.savefig(sys.argv[2], dpi=data.get("dpi", 90))

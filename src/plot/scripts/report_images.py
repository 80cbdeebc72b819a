"""Renders side by side for the report (LECTURE.md §1-3, 8, 9): each panel a
linear RGB image tonemapped as `stratum render` writes PNGs (exposure 1,
clamp to [0, 1], sRGB curve), drawn without smoothing so that noise stays
visible at any size.
Data: {"columns": C (optional), "size": inches per panel (optional),
       "panels": [{"title", "width", "height", "rgb": [row-major, top row
       first, width*height*3 linear values], "boxes": [[x, y, w, h], ...]
       (optional: regions outlined, in pixels)}
       | {"title", "width", "height", "heat": [width*height values], "scale"}
         (a heat map from 0 to scale, magma)
       | {"blank": true}]}
Usage: python3 report_images.py DATA.json OUT.png"""
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.patches  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def srgb(linear):
    v = np.clip(linear, 0.0, 1.0)
    return np.where(v <= 0.0031308, 12.92 * v, 1.055 * np.power(v, 1 / 2.4) - 0.055)


with open(sys.argv[1]) as handle:
    data = json.load(handle)
panels = data["panels"]
# At most 4 panels a row (10.4 in at 100 dpi): never scaled down on the page.
columns = min(data.get("columns", len(panels)), len(panels), 4)
rows = math.ceil(len(panels) / columns)
size = data.get("size", 2.6)
figure, axes_grid = plt.subplots(rows, columns, figsize=(size * columns, (size + 0.45) * rows), squeeze=False)
for index, axes in enumerate(axes_grid.flat):
    axes.axis("off")
    if index >= len(panels):
        continue
    panel = panels[index]
    if panel.get("blank"):
        continue
    if "heat" in panel:
        values = np.asarray(panel["heat"], dtype=float).reshape(panel["height"], panel["width"])
        axes.imshow(values, cmap="magma", vmin=0.0, vmax=panel["scale"], interpolation="nearest")
    else:
        pixels = np.asarray(panel["rgb"], dtype=float).reshape(panel["height"], panel["width"], 3)
        axes.imshow(srgb(pixels), interpolation="nearest")
    for x, y, w, h in panel.get("boxes", []):
        axes.add_patch(matplotlib.patches.Rectangle((x - 0.5, y - 0.5), w, h, fill=False, edgecolor="#00e5ff",
                                                    linewidth=1.5))
    axes.set_title(panel.get("title", ""), fontsize=9)
figure.tight_layout()
figure.savefig(sys.argv[2], dpi=data.get("dpi", 100))

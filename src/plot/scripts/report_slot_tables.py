"""Time-slot tables for the report (LECTURE.md §8): each panel an m x m grid
of spatial strata, row 0 at the top as on the lecture's slide, every cell
showing its time slot as a number and coloured by it (early dark, late
light), with each row's and column's sum written outside the grid.
Data: {"panels": [{"title", "order": m, "slots": [m*m row-major]}]}
Usage: python3 report_slot_tables.py DATA.json OUT.png"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

with open(sys.argv[1]) as handle:
    data = json.load(handle)
panels = data["panels"]
figure, axes_list = plt.subplots(1, len(panels), figsize=(3.6 * len(panels), 3.8), squeeze=False)
for axes, panel in zip(axes_list[0], panels):
    m = panel["order"]
    slots = np.asarray(panel["slots"], dtype=int).reshape(m, m)
    axes.imshow(slots, cmap="viridis", vmin=0, vmax=m * m - 1)
    for r in range(m):
        for c in range(m):
            light = slots[r, c] > (m * m - 1) * 0.6
            axes.text(c, r, str(slots[r, c]), ha="center", va="center", fontsize=13,
                      color="black" if light else "white")
        axes.text(m - 0.3, r, f"{slots[r].sum()}", ha="left", va="center", fontsize=9, color="0.3")
    for c in range(m):
        axes.text(c, m - 0.35, f"{slots[:, c].sum()}", ha="center", va="top", fontsize=9, color="0.3")
    axes.set_xlim(-0.5, m + 0.3)
    axes.set_ylim(m + 0.2, -0.5)
    axes.set_xticks([])
    axes.set_yticks([])
    for side in axes.spines.values():
        side.set_visible(False)
    axes.set_title(panel.get("title", ""), fontsize=10)
figure.tight_layout()
figure.savefig(sys.argv[2], dpi=data.get("dpi", 100))

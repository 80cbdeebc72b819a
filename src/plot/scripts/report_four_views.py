"""Rank chart for the report's four views (LECTURE.md §13): one row per
pattern, one column per measurement, each cell coloured by the pattern's rank
in that column (1 = best, light yellow; the worst dark) and labelled with the measured value.
Data: {"patterns": [names], "views": [column names], "values": [[per view]],
       "ranks": [[1-based ranks per view]]}
Usage: python3 report_four_views.py DATA.json OUT.png"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

with open(sys.argv[1]) as handle:
    data = json.load(handle)
patterns, views, values, ranks = data["patterns"], data["views"], data["values"], data["ranks"]
count = len(patterns)
# At most 11 in at 100 dpi (the page is 1100 px wide), so that 8-point text stays above 10 px.
width = min(11.0, 1.25 * len(views) + 2.2)
figure, axes = plt.subplots(figsize=(width, 0.48 * count + 1.8))
image = axes.imshow(ranks, cmap="viridis_r", vmin=1, vmax=max(count, 2), aspect="auto")
for row in range(count):
    for column in range(len(views)):
        value = values[row][column]
        text = "n/a" if value is None else f"{value:.3g}"
        # viridis_r: the best ranks are light (dark text), the worst dark (light text).
        colour = "black" if ranks[row][column] <= (count + 1) / 2 else "white"
        axes.text(column, row, f"{text}\n#{ranks[row][column]}", ha="center", va="center", fontsize=8, color=colour)
axes.set_xticks(range(len(views)))
axes.set_xticklabels([name.replace(" (", "\n(") for name in views], fontsize=8)
axes.set_yticks(range(count))
axes.set_yticklabels(patterns, fontsize=9)
axes.xaxis.tick_top()
colorbar = figure.colorbar(image, ax=axes, fraction=0.04, pad=0.02)
colorbar.set_label("rank (1 = best)")
colorbar.ax.invert_yaxis()
figure.tight_layout()
figure.savefig(sys.argv[2], dpi=data.get("dpi", 100))

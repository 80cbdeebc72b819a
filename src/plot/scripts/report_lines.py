"""Line plots for the report (and any face): panels of series y(x), on log
or linear axes, with optional error bars and dotted reference curves.
Data: {"columns": C, "title": "...", "panels": [{"title", "xlabel", "ylabel",
       "xlog", "ylog", "series": [{"label", "x", "y", "yerr" (optional),
       "reference" (bool: dotted, no markers), "dashed" (bool: a dashed line, no
       markers: a prediction drawn over measurements)}]}]}
Usage: python3 report_lines.py DATA.json OUT.png"""
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import LogFormatterSciNotation, LogLocator  # noqa: E402


def label_log_ticks(axis):
    """Labels 1, 2 and 5 times each power of ten when the axis spans little more than a decade, so that a log
    axis always shows more than one labelled tick."""
    low, high = axis.get_view_interval()
    if low > 0 and high / low < 30:
        axis.set_minor_locator(LogLocator(subs=(2.0, 5.0)))
        axis.set_minor_formatter(LogFormatterSciNotation(labelOnlyBase=False, minor_thresholds=(100, 100)))

with open(sys.argv[1]) as handle:
    data = json.load(handle)
panels = data["panels"]
# At most two panels a row, 5 in at 100 dpi: 1000 px, never scaled down on the page (max 1100 px).
columns = min(data.get("columns", len(panels)), len(panels), 2)
rows = math.ceil(len(panels) / columns)
figure, axes_grid = plt.subplots(rows, columns, figsize=(5.0 * columns, 3.8 * rows + 0.4), squeeze=False)
for index, axes in enumerate(axes_grid.flat):
    if index >= len(panels):
        axes.axis("off")
        continue
    panel = panels[index]
    for series in panel["series"]:
        if series.get("reference", False):
            axes.plot(series["x"], series["y"], linestyle=":", color="0.4", label=series.get("label"))
        elif series.get("dashed", False):
            axes.plot(series["x"], series["y"], linestyle="--", linewidth=1.5, label=series.get("label"))
        elif series.get("yerr") is not None:
            axes.errorbar(series["x"], series["y"], yerr=series["yerr"], marker="o", markersize=3, capsize=2,
                          label=series.get("label"))
        else:
            axes.plot(series["x"], series["y"], marker="o", markersize=3, label=series.get("label"))
    if panel.get("xlog", False):
        axes.set_xscale("log")
    if panel.get("ylog", False):
        axes.set_yscale("log")
    axes.set_xlabel(panel.get("xlabel", ""))
    axes.set_ylabel(panel.get("ylabel", ""))
    axes.set_title(panel.get("title", ""), fontsize=10)
    if panel.get("xlog", False):
        label_log_ticks(axes.xaxis)
    if panel.get("ylog", False):
        label_log_ticks(axes.yaxis)
    axes.grid(True, which="both", alpha=0.3)
    if any(series.get("label") for series in panel["series"]):
        axes.legend(fontsize=8)
if data.get("title"):
    figure.suptitle(data["title"])
figure.tight_layout()
figure.savefig(sys.argv[2], dpi=data.get("dpi", 100))

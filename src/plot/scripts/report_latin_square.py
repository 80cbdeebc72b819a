"""Latin squares for the report (LECTURE.md §7): each square drawn as its grid
of symbols, every cell tinted by its symbol, so that "each symbol once per row
and column" can be read off the picture.
Data: {"squares": [{"title": "...", "symbols": [[row of symbol strings], ...]}]}
(first row drawn at the top).
Usage: python3 report_latin_square.py DATA.json OUT.png"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

with open(sys.argv[1]) as handle:
    data = json.load(handle)
squares = data["squares"]
figure, axes_list = plt.subplots(1, len(squares), figsize=(3.2 * len(squares), 3.4), squeeze=False)
for axes, square in zip(axes_list[0], squares):
    symbols = square["symbols"]
    m = len(symbols)
    alphabet = sorted({s for row in symbols for s in row})
    colours = plt.get_cmap("tab10" if len(alphabet) <= 10 else "tab20")
    for r, row in enumerate(symbols):
        for c, symbol in enumerate(row):
            index = alphabet.index(symbol)
            axes.add_patch(plt.Rectangle((c, m - 1 - r), 1, 1, color=colours(index % colours.N), alpha=0.35))
            axes.text(c + 0.5, m - 0.5 - r, symbol, ha="center", va="center", fontsize=max(8, 40 // m))
    for k in range(m + 1):
        axes.axhline(k, color="0.3", linewidth=0.6)
        axes.axvline(k, color="0.3", linewidth=0.6)
    axes.set_xlim(0, m)
    axes.set_ylim(0, m)
    axes.set_aspect("equal")
    axes.set_xticks([])
    axes.set_yticks([])
    axes.set_title(square.get("title", ""), fontsize=10)
figure.tight_layout()
figure.savefig(sys.argv[2], dpi=data.get("dpi", 100))

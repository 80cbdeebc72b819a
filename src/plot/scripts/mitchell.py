"""Figure for `stratum study mitchell --plot`: each pattern's points (one
realization) above its radially averaged power spectrum, and the table of
random-edge discrepancies (Mitchell 1992) below.
Usage: python3 mitchell.py DATA.json OUT.png"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

with open(sys.argv[1]) as handle:
    data = json.load(handle)

patterns = data["patterns"]
columns = len(patterns)
figure = plt.figure(figsize=(3.2 * columns, 9.0))
grid = figure.add_gridspec(3, columns, height_ratios=[3.0, 2.2, 1.6])
for column, pattern in enumerate(patterns):
    spectrum = pattern["spectrum"]
    axes = figure.add_subplot(grid[0, column])
    example = pattern["example"]
    axes.scatter(example[0::2], example[1::2], s=max(1.0, 400.0 / max(1, spectrum["n"])), color="black")
    axes.set_xlim(0, 1)
    axes.set_ylim(0, 1)
    axes.set_aspect("equal")
    axes.set_xticks([])
    axes.set_yticks([])
    axes.set_title(f'{pattern["label"]} (N = {spectrum["n"]})')
    axes = figure.add_subplot(grid[1, column])
    axes.plot(spectrum["frequency"], spectrum["power"], color="tab:blue")
    axes.axhline(1.0, color="gray", linewidth=0.8, linestyle="--")
    axes.set_xlabel("frequency / sqrt(N)")
    if column == 0:
        axes.set_ylabel("radial power")
    axes.set_ylim(bottom=0)

table_axes = figure.add_subplot(grid[2, :])
table_axes.axis("off")
header = ["pattern"] + [f"N = {n}" for n in data["counts"]]
rows = []
for pattern in patterns:
    row = [pattern["label"]]
    for cell in pattern["cells"]:
        text = f'{cell["rms"]:.4g} ± {cell["rms_se"]:.2g}'
        if cell["n"] != cell["requested"]:
            text += f' (n = {cell["n"]})'
        row.append(text)
    rows.append(row)
table = table_axes.table(cellText=rows, colLabels=header, loc="center", cellLoc="center")
table.scale(1.0, 1.3)
table_axes.set_title(
    f'random-edge discrepancy: RMS over {data["lines"]} lines, mean ± s.e. over {data["realizations"]} realizations')
figure.tight_layout()
figure.savefig(sys.argv[2], dpi=100)

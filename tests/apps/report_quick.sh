#!/usr/bin/env bash
# `stratum report --quick` (issue 6): writes the page into OUT with a cold
# reference cache and checks that every section of `stratum report --list`
# is there with at least one figure, that every figure the page names is a
# PNG on disk, and that report.json holds every section's numbers. The page
# is then opened in headless Chromium by report_browser_check.py (ctest
# fixture report_quick).
# Usage: report_quick.sh STRATUM OUT
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"
out=$2
rm -rf "$out" "$out.cache"
SECONDS=0
"$stratum" report --quick -o "$out" --cache "$out.cache" 2>"$tmp/progress" >"$tmp/stdout" \
  && ok || fail "report --quick: $(tail -5 "$tmp/progress")"
echo "report --quick took ${SECONDS} s (cold reference cache)"
grep -q "report written to $out/index.html" "$tmp/stdout" && ok || fail "prints where the page is: $(cat "$tmp/stdout")"
"$stratum" report --list | awk '{print $1}' >"$tmp/ids"
[ "$(wc -l <"$tmp/ids")" -ge 1 ] && ok || fail "report --list lists sections"
/usr/bin/python3 - "$out" "$tmp/ids" <<'PY' && ok || fail "every section with its figures and numbers"
import html.parser, json, pathlib, sys
out, ids = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]).read_text().split()

class Page(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.section, self.images = None, {}
    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "section":
            self.section = attrs["id"]
            self.images[self.section] = []
        elif tag == "img":
            self.images[self.section].append(attrs["src"])

page = Page()
page.feed((out / "index.html").read_text())
assert list(page.images) == ids, f"sections {list(page.images)} != {ids}"
for section, images in page.images.items():
    assert images, f"section {section} has no figure"
    for src in images:
        data = (out / src).read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{src} is not a PNG"
numbers = json.loads((out / "report.json").read_text())
assert numbers["quick"] is True and sorted(numbers["sections"]) == sorted(ids), sorted(numbers["sections"])
for section in ids:
    assert numbers["sections"][section]["numbers"], f"section {section} reports no number"
# The lecture's numbers beside ours: Mitchell's (1992) table as printed, with the ratio.
mitchell = {"zaremba": [0.0504, 0.00478, 0.00111], "jittered": [0.0538, 0.00595, 0.00146],
            "poisson-disk": [0.0613, 0.00767, 0.00241], "n-rooks": [0.0637, 0.0123, 0.00488],
            "random": [0.0924, 0.0224, 0.00866]}
patterns = numbers["sections"]["patterns"]["numbers"]
for pattern, values in mitchell.items():
    cells = patterns["mitchell_1992"][pattern]
    assert [c["mitchell"] for c in cells] == values, (pattern, cells)
    for cell, ours in zip(cells, patterns["patterns"][pattern]["cells"]):
        assert cell["ours"] == ours["rms"] and abs(cell["ratio"] - ours["rms"] / cell["mitchell"]) < 1e-12, cell
assert len(patterns["random_expected_rms"]) == 3
# The edge-discrepancy slide: 1, 2, 4, 8 samples on the 8x8 grid, each at least the bound 1/(2N), on the page.
edge = numbers["sections"]["edge-discrepancy"]["numbers"]
assert sorted({p["n"] for p in edge["grid_patterns"]}) == [1, 2, 4, 8], edge["grid_patterns"]
for p in edge["grid_patterns"]:
    assert 0.5 / p["n"] - 1e-12 <= p["edge_discrepancy"] <= 1, p
page_text = (out / "index.html").read_text()
assert 'id="edge-discrepancy"' in page_text
for p in edge["grid_patterns"]:
    assert p["name"].replace("×", "×") in page_text, p["name"]
# Honest statistics: ratios over seeds with intervals that hold their estimates, an efficiency
# ratio only where the times differ beyond their noise, §9 at equal rays and at equal time.
def check_repeated(comparison, where):
    assert comparison["repeats"] >= 3 and "Student-t" in comparison["interval_method"], where
    for label, row in comparison["rows"].items():
        assert len(row["mse_per_seed"]) == len(row["seconds_per_seed"]) == comparison["repeats"], (where, label)
        for key in ("mse_ratio", "time_ratio"):
            assert row[key]["low"] <= row[key]["estimate"] <= row[key]["high"], (where, label, key)
        resolved = row["time_ratio"]["low"] > 1 or row["time_ratio"]["high"] < 1
        assert row["time_resolved"] == resolved and (row["efficiency_ratio"] is None) == (not resolved), (where, label)
space_time = numbers["sections"]["space-time"]["numbers"]
for key in ("motion_blur", "motion_close_up"):
    check_repeated(space_time[key], key)
    assert 0 < space_time[key]["time_dependent_pixels"] <= space_time[key]["pixels"], key
check_repeated(numbers["sections"]["variance"]["numbers"], "variance")
importance = numbers["sections"]["importance"]["numbers"]
for key in ("light_strategy", "light_strategy_large", "hemisphere"):
    check_repeated(importance[key], key)
path = numbers["sections"]["path-tracing"]["numbers"]
check_repeated(path["equal_rays"], "equal_rays")
check_repeated(path["equal_time"], "equal_time")
assert path["equal_time"]["equal_time_seconds"] > 0 and path["equal_time_winner"] in ("complete", "incomplete", "neither")
assert path["equal_time_decided_by"] in ("efficiency_ratio", "mse_ratio")
# §4: the exact jittered variance on both edges; §13: the product rules and the periodic Poisson disk.
stratification = numbers["sections"]["stratification"]["numbers"]
assert len(stratification["jittered_prediction"]) == len(stratification["counts"])
assert all(r["edge"] > 0 and r["slanted_edge"] > 0 for r in stratification["jittered_prediction"])
assert "jittered:none" in stratification["slanted_edge"]["samplers"]
views = numbers["sections"]["four-views"]["numbers"]
assert views["quadrature"]["gauss_legendre"]["gaussian_error"] < views["quadrature"]["midpoint"]["gaussian_error"]
assert "poisson-disk(periodic=1)" in views["patterns"]
# The lecture slide by slide: every slide reproduced by a figure or table of this run, each linked from the
# index; every section shows a formula of its slides under its heading.
slides = numbers["slides"]
assert len(slides) >= 26 and all(s["run"] and s["shown"] for s in slides), [s for s in slides if not s["shown"]]
for s in slides:
    if s["anchor"]:
        assert f'id="{s["anchor"]}"' in page_text and f'href="#{s["anchor"]}"' in page_text, s
for section in ids:
    body = page_text.split(f'<section id="{section}">', 1)[1].split("</section>", 1)[0]
    assert '<dd class="formula">' in body.split("<p>", 1)[0], f"section {section} shows no formula under its heading"
print(f"{len(ids)} sections, {sum(map(len, page.images.values()))} figures")
PY
[ -z "$(ls -A "$out" | grep partial)" ] && ok || fail "no staging folder left behind"
finish

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
print(f"{len(ids)} sections, {sum(map(len, page.images.values()))} figures")
PY
[ -z "$(ls -A "$out" | grep partial)" ] && ok || fail "no staging folder left behind"
finish

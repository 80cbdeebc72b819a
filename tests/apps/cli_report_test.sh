#!/usr/bin/env bash
# CLI tests of `stratum report`: one section end to end, a rerun replacing
# the page, and the bad-input contract (message naming the option, non-zero
# exit, no page left as if complete). The whole --quick page is tested by
# report_quick.sh and report_browser_check.py.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"

"$stratum" report --only disk-maps --quick -o "$tmp/r" --cache "$tmp/cache" >"$tmp/out" 2>/dev/null && ok || fail "one section"
grep -q 'id="disk-maps"' "$tmp/r/index.html" && ok || fail "section in the page"
[ "$(grep -c '<section' "$tmp/r/index.html")" = 1 ] && ok || fail "--only keeps one section"
ls "$tmp/r/figures/"disk-maps-*.png >/dev/null && ok || fail "figure written"
"$stratum" report --only disk-maps --quick --seed 2 -o "$tmp/r" >/dev/null 2>&1 && ok || fail "rerun into the same folder"
grep -q "seed 2" "$tmp/r/index.html" && ok || fail "rerun replaced the page"
"$stratum" report --list | grep -q '^disk-maps' && ok || fail "--list"
"$stratum" report --slides | grep -q '^§11  qmc  *The radical inverse  \[i = Σ' && ok || fail "--slides: $("$stratum" report --slides | grep qmc)"

expect_error "sampler" report --quick --sampler no-such-sampler -o "$tmp/bad1"
[ ! -e "$tmp/bad1" ] && ok || fail "nothing written for an unknown sampler"
expect_error "randomizer" report --quick --sampler sobol:no-such -o "$tmp/bad2"
expect_error "only" report --quick --only no-such-section -o "$tmp/bad3"
expect_error "threads" report --quick --threads 5000 -o "$tmp/bad4"
touch "$tmp/file"
expect_error "directory" report --quick -o "$tmp/file"
expect_error "directory" report --quick -o "$tmp/file/sub"
# A failure midway (here: the figures cannot be drawn) leaves the previous page untouched and no staging folder.
cp "$tmp/r/index.html" "$tmp/before.html"
if STRATUM_PYTHON=/bin/false "$stratum" report --only disk-maps --quick -o "$tmp/r" >/dev/null 2>"$tmp/err"; then
  fail "report succeeded without Python"
else
  ok
fi
cmp -s "$tmp/r/index.html" "$tmp/before.html" && ok || fail "previous page changed by a failed run"
[ -z "$(ls -A "$tmp/r" | grep stratum-tmp)" ] && ok || fail "staging folder left by a failed run"
finish

#!/usr/bin/env bash
# CLI tests of `stratum render`: outputs and the bad-input contract
# (message naming the argument, non-zero exit, no partial image).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"
scenes=$(cd "$(dirname "$0")/../../scenes" && pwd)

"$stratum" render -o "$tmp/box.png" --exr "$tmp/box.exr" --width 24 --height 24 --spp 2 --quiet && ok || fail "default scene"
/usr/bin/python3 - "$tmp/box.png" <<'PY' && ok || fail "png is a 24x24 RGB image"
import sys, matplotlib.image as im
a = im.imread(sys.argv[1]); assert a.shape[:2] == (24, 24) and a.shape[2] >= 3, a.shape
assert a.max() > 0.5  # the light is in view
PY
[ -s "$tmp/box.exr" ] && ok || fail "exr written"
"$stratum" render "$scenes/soft-shadow.json" -o "$tmp/soft.png" --width 16 --height 16 --light-strategy solid-angle \
  --sampler jittered --time-pattern magic-square --spp 16 --quiet && ok || fail "soft-shadow scene, solid angle, magic-square time"

"$stratum" render "$scenes/glossy-mis.json" -o "$tmp/gm.png" --width 16 --height 10 --spp 4 --light-strategy mis --quiet && ok || fail "glossy-mis scene, mis"
expect_error "light-strategy" render --light-strategy cone -o "$tmp/x.png"
printf '{\n  "materials": {},\n  "shapes": [,]\n}\n' >"$tmp/broken.json"
expect_error "line 3, column 14" render "$tmp/broken.json" -o "$tmp/x.png"
echo '{"materials": {}, "shapes": [], "colour": 1}' >"$tmp/unknown.json"
expect_error "colour" render "$tmp/unknown.json" -o "$tmp/x.png"
expect_error "scene" render "$tmp/missing.json" -o "$tmp/x.png"
expect_error "spp" render --spp 0 -o "$tmp/x.png"
expect_error "integrator" render --integrator bdpt -o "$tmp/x.png"
expect_error "time-pattern magic-square needs spp" render --time-pattern magic-square --spp 8 -o "$tmp/x.png"
expect_error "width" render --width 100000 --height 10 -o "$tmp/x.png"
expect_error "output" render --width 8 --height 8 --spp 1 -o "$tmp/no/such/dir/x.png"
expect_error "output" render --width 8 --height 8 --spp 1 -o "$tmp/x.unknownformat"
# --frame: frame 0 is the render without frames; frame 1 continues the pixels' sequences (other samples).
"$stratum" render --width 8 --height 8 --spp 2 -q -o "$tmp/f.png" && "$stratum" render --width 8 --height 8 --spp 2 -q \
  --frame 0 -o "$tmp/f0.png" && "$stratum" render --width 8 --height 8 --spp 2 -q --frame 1 -o "$tmp/f1.png" && ok \
  || fail "render --frame"
cmp -s "$tmp/f.png" "$tmp/f0.png" && ok || fail "--frame 0 differs from the render without --frame"
! cmp -s "$tmp/f0.png" "$tmp/f1.png" && ok || fail "--frame 1 rendered frame 0's samples"
rm -f "$tmp"/f*.png
expect_error "frame = -1" render --frame -1 -o "$tmp/x.png"
expect_error "frame = 268435456: must be in \[0, 268435455\] at spp 16" render --spp 16 --frame 268435456 -o "$tmp/x.png"
expect_error "frame" render --frame 4294967296 -o "$tmp/x.png"
[ ! -e "$tmp/x.png" ] && ok || fail "a failed render left x.png"
[ -z "$(ls -A "$tmp" | grep '^\.')" ] && ok || fail "temporary files left: $(ls -A "$tmp")"

# --reference: rendered once, then loaded from the cache (said on stderr),
# giving the same EXR and the same PNG, byte for byte.
ref=(render --reference --reference-spp 16 --cache "$tmp/refs" --width 12 --height 10 --quiet)
"$stratum" "${ref[@]}" -o "$tmp/r1.png" --exr "$tmp/r1.exr" --variance "$tmp/r1v.exr" 2>"$tmp/r1.err" && ok || fail "render --reference"
grep -q "rendered and cached" "$tmp/r1.err" && ok || fail "first --reference not rendered: $(cat "$tmp/r1.err")"
"$stratum" "${ref[@]}" -o "$tmp/r2.png" --exr "$tmp/r2.exr" --variance "$tmp/r2v.exr" 2>"$tmp/r2.err" && ok || fail "render --reference again"
grep -q "loaded from the cache" "$tmp/r2.err" && ok || fail "second --reference missed the cache: $(cat "$tmp/r2.err")"
cmp -s "$tmp/r1.exr" "$tmp/r2.exr" && cmp -s "$tmp/r1v.exr" "$tmp/r2v.exr" && ok || fail "cached reference EXR differs"
cmp -s "$tmp/r1.exr" "$tmp/r1v.exr" && fail "the variance image is the image" || ok
cmp -s "$tmp/r1.png" "$tmp/r2.png" && ok || fail "cached reference PNG differs"
[ "$(ls "$tmp/refs" | wc -l)" = 3 ] && ok || fail "cache holds the reference, its variance and metadata: $(ls "$tmp/refs")"
# A damaged entry (cut short, or its variance replaced) is rendered again with a warning, never reported as cached.
entry=$(ls "$tmp/refs"/*.exr | grep -v variance)
truncate -s 100 "$entry"
"$stratum" "${ref[@]}" -o "$tmp/r4.png" 2>"$tmp/r4.err" && ok || fail "render --reference over a damaged cache: $(cat "$tmp/r4.err")"
grep -q "warning: the cached reference $entry is not sound" "$tmp/r4.err" && grep -q "rendered and cached" "$tmp/r4.err" \
  && ok || fail "a damaged cache entry was not rendered again: $(cat "$tmp/r4.err")"
cmp -s "$tmp/r1.png" "$tmp/r4.png" && ok || fail "the re-rendered reference differs"
cp "$tmp/r1.exr" "${entry%.exr}.variance.exr"
"$stratum" "${ref[@]}" -o "$tmp/r5.png" 2>"$tmp/r5.err" && grep -q "is not the file its metadata describes" "$tmp/r5.err" \
  && ok || fail "a swapped variance image was trusted: $(cat "$tmp/r5.err")"
"$stratum" "${ref[@]}" -o "$tmp/r6.png" 2>"$tmp/r6.err" && grep -q "loaded from the cache" "$tmp/r6.err" \
  && ok || fail "the repaired entry missed the cache: $(cat "$tmp/r6.err")"
"$stratum" render --reference --reference-spp 16 --cache "$tmp/refs" --width 12 --height 11 -q -o "$tmp/r3.png" 2>"$tmp/r3.err"
grep -q "rendered and cached" "$tmp/r3.err" && ok || fail "another resolution hit the cache"
expect_error "reference-spp" render --reference --reference-spp 0 -o "$tmp/x.png"
"$stratum" render --width 8 --height 8 --spp 4 -q -o "$tmp/v.png" --variance "$tmp/v.exr" && [ -s "$tmp/v.exr" ] && ok || fail "--variance"
expect_error "variance" render --width 8 --height 8 --spp 1 -o "$tmp/x.png" --variance "$tmp/v.png"
[ ! -e "$tmp/x.png" ] && ok || fail "a refused --variance left x.png"
# progress: none when stderr is not a terminal, a line per pass with --progress, none with --quiet
"$stratum" render --width 8 --height 8 --spp 4 --passes 2 -o "$tmp/pg.png" >/dev/null 2>"$tmp/pg.err" &&
  ! grep -q "rendering: pass" "$tmp/pg.err" && ok || fail "a progress bar on a stderr that is not a terminal"
"$stratum" render --width 8 --height 8 --spp 4 --passes 2 --progress -o "$tmp/pg.png" >/dev/null 2>"$tmp/pg.err" &&
  [ "$(grep -c "rendering: pass" "$tmp/pg.err")" = 2 ] && ok || fail "--progress: $(cat "$tmp/pg.err")"
"$stratum" render --width 8 --height 8 --spp 4 --passes 2 --progress --quiet -o "$tmp/pg.png" 2>"$tmp/pg.err" &&
  ! grep -q "rendering: pass" "$tmp/pg.err" && ok || fail "--progress --quiet printed progress"
# every registry sampler drives the renderer or is refused with the reason: latin-square (3-D) renders,
# a space-time pattern is a --time-pattern
"$stratum" render --width 8 --height 8 --spp 16 --sampler latin-square -q -o "$tmp/latin.png" && [ -s "$tmp/latin.png" ] &&
  ok || fail "render --sampler latin-square"
expect_error "time-pattern" render --width 8 --height 8 --spp 16 --sampler spacetime-cook -q -o "$tmp/st.png"
[ ! -e "$tmp/st.png" ] && ok || fail "a refused space-time sampler left st.png"

finish

#!/usr/bin/env bash
# CLI tests of `stratum warp`: every registry warp runs, rows hold the point
# then its pdf, closed-form values, --sampler/--seed, @FILE parameters, and
# the bad-input contract (message naming the argument, non-zero exit, no
# partial output file).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"
py=/usr/bin/python3

# Every listed warp with its example parameters writes n rows; output_dim + 1 columns.
example() {
  case $1 in
    piecewise-1d) echo "--warp-param values=1,3,0.5,2 --warp-param width=4" ;;
    piecewise-2d) echo "--warp-param values=1,2,3,4,5,6 --warp-param width=3 --warp-param height=2" ;;
    alias) echo "--warp-param values=1,3,0.5,2" ;;
  esac
}
for map in $("$stratum" warp --list | grep -v '^ ' | awk '{print $1}'); do
  # shellcheck disable=SC2046
  "$stratum" warp --map "$map" -n 50 $(example "$map") --format npy -o "$tmp/w.npy" \
    && $py -c "
import numpy as np; a = np.load('$tmp/w.npy'); assert a.shape[0] == 50 and a.shape[1] in (2, 3, 4), a.shape
assert np.all(np.isfinite(a)) and np.all(a[:, -1] > 0), a" && ok || fail "warp --map $map"
done
[ "$("$stratum" warp --list | grep -c -e '^disk-concentric ' -e '^normal ' -e '^cone ')" = 3 ] && ok || fail "--list"

# Closed forms: uniform hemisphere pdf 1/(2π); every disk point inside with pdf 1/π; cone points in the cap.
"$stratum" warp --map hemisphere-uniform -n 200 --format csv -o "$tmp/h.csv" && ok || fail "csv write"
$py -c "
import numpy as np; a = np.loadtxt('$tmp/h.csv', delimiter=',')
assert a.shape == (200, 4); assert np.allclose(a[:, 3], 1 / (2 * np.pi)); assert np.all(a[:, 2] >= 0)
assert np.allclose((a[:, :3] ** 2).sum(1), 1)" && ok || fail "hemisphere rows"
"$stratum" warp --map disk-polar -n 300 --sampler sobol --seed 4 | $py -c "
import sys, numpy as np; a = np.loadtxt(sys.stdin); assert a.shape == (300, 3)
assert np.all((a[:, :2] ** 2).sum(1) <= 1) and np.allclose(a[:, 2], 1 / np.pi)" && ok || fail "disk rows"
"$stratum" warp --map cone -n 300 --warp-param cos_theta_max=0.8 | $py -c "
import sys, numpy as np; a = np.loadtxt(sys.stdin); assert np.all(a[:, 2] >= 0.8 - 1e-12)
assert np.allclose(a[:, 3], 1 / (2 * np.pi * 0.2))" && ok || fail "cone rows"
# 1D warps draw 1D input; a 3×3 triangle returns points in space; @FILE parameters.
"$stratum" warp --map normal -n 2000 --warp-param mu=3 --warp-param sigma=0.5 | $py -c "
import sys, numpy as np; a = np.loadtxt(sys.stdin); assert a.shape == (2000, 2)
assert abs(a[:, 0].mean() - 3) < 5 * 0.5 / np.sqrt(2000), a[:, 0].mean()" && ok || fail "normal rows"
printf '0 0 0\n1 0 0\n0 2 0\n' > "$tmp/v.txt"
"$stratum" warp --map triangle -n 100 --warp-param vertices=@"$tmp/v.txt" | $py -c "
import sys, numpy as np; a = np.loadtxt(sys.stdin); assert a.shape == (100, 4)
assert np.all(a[:, 2] == 0) and np.allclose(a[:, 3], 1.0)" && ok || fail "triangle from @FILE"
# Same seed, same output; another seed, another output.
a=$("$stratum" warp --map sphere-uniform -n 50 --seed 7 | md5sum)
b=$("$stratum" warp --map sphere-uniform -n 50 --seed 7 | md5sum)
c=$("$stratum" warp --map sphere-uniform -n 50 --seed 8 | md5sum)
[ "$a" = "$b" ] && [ "$a" != "$c" ] && ok || fail "seeding"

expect_error "invalid map = nosuch: valid maps are disk-polar" warp --map nosuch -n 4
expect_error "invalid n = 0" warp --map disk-polar -n 0
expect_error "invalid n = -2" warp --map disk-polar -n -2
expect_error "invalid cos_theta_max = 1.5" warp --map cone -n 4 --warp-param cos_theta_max=1.5
expect_error "invalid cos_theta_max = -2" warp --map cone -n 4 --warp-param cos_theta_max=-2
expect_error "invalid vertices" warp --map triangle -n 4 --warp-param vertices=0,0,1,1,2,2
expect_error "invalid radius = 0" warp --map tent -n 4 --warp-param radius=0
expect_error "invalid rate = -1" warp --map exponential -n 4 --warp-param rate=-1
expect_error "invalid sigma = 0" warp --map normal -n 4 --warp-param sigma=0
expect_error "invalid a = -1" warp --map linear -n 4 --warp-param a=-1
expect_error "not both be zero" warp --map linear -n 4 --warp-param a=0 --warp-param b=0
expect_error "invalid weights" warp --map bilinear -n 4 --warp-param weights=0,0,0,0
expect_error "invalid warp-param = radius=1: disk-polar takes no parameters" warp --map disk-polar -n 4 --warp-param radius=1
expect_error "invalid cos_theta_max = x: must be a finite real in \[-1, 1)" warp --map cone -n 4 --warp-param cos_theta_max=x
expect_error "invalid warp-param = 0.5" warp --map cone -n 4 --warp-param 0.5
expect_error "invalid vertices = /nonexistent/v.txt: does not exist" warp --map triangle -n 4 --warp-param vertices=@/nonexistent/v.txt
expect_error "sampler" warp --map disk-polar -n 4 --sampler nosuch
expect_error "format" warp --map disk-polar -n 4 --format xls
expect_error "invalid cos_theta_max = 3" warp --map cone -n 4 --warp-param cos_theta_max=3 -o "$tmp/bad.txt"
[ ! -e "$tmp/bad.txt" ] && ok || fail "partial file left after bad parameter"
expect_error "output" warp --map disk-polar -n 4 -o /nonexistent/x.txt
[ -z "$(ls -A "$tmp" | grep -v -e '^out$' -e '^err$' -e '^w\.npy$' -e '^h\.csv$' -e '^v\.txt$')" ] && ok || fail "stray files: $(ls -A "$tmp")"

# --pdf-at / --invert: the pdf at given points and their preimages, against the forward warp's own output.
"$stratum" warp -m disk-concentric -n 64 -s sobol:owen --seed 3 -o "$tmp/fw.txt" && ok || fail "forward warp"
awk '{print $1, $2}' "$tmp/fw.txt" >"$tmp/fw_points.txt"
"$stratum" points -s sobol:owen --seed 3 -n 64 -d 2 -o "$tmp/fw_u.txt" && ok || fail "the warp's input"
"$stratum" warp -m disk-concentric --pdf-at "$tmp/fw_points.txt" -o "$tmp/pdf_at.txt" && ok || fail "--pdf-at"
"$stratum" warp -m disk-concentric --invert "$tmp/fw_points.txt" -o "$tmp/inv.txt" && ok || fail "--invert"
/usr/bin/python3 - "$tmp/fw.txt" "$tmp/pdf_at.txt" "$tmp/fw_u.txt" "$tmp/inv.txt" <<'PY' && ok || fail "--pdf-at = forward pdf, --invert = input"
import sys
import numpy as np
fw, pdf_at, u, inv = (np.loadtxt(f) for f in sys.argv[1:5])
assert np.array_equal(fw, pdf_at), "pdf at the warped points differs from the forward table"
assert np.allclose(u, inv, atol=1e-12), np.abs(u - inv).max()
PY
printf '0\n1\n' >"$tmp/normal_points.txt"
"$stratum" warp -m normal --pdf-at "$tmp/normal_points.txt" | awk 'NR==1 && ($2 - 0.3989422804014327)^2 < 1e-24 {ok=1} END {exit !ok}' && ok || fail "normal pdf at 0"
expect_error "disk-concentric maps to 2-D points: give 2 columns" warp -m disk-concentric --invert "$tmp/fw.txt"
expect_error "drop -n" warp -m disk-concentric --invert "$tmp/fw_points.txt" -n 4
expect_error "not both" warp -m disk-concentric --invert "$tmp/fw_points.txt" --pdf-at "$tmp/fw_points.txt"
finish

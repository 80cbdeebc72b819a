#!/usr/bin/env bash
# CLI tests of the messages (docs/cli.md): each names the user's own value and
# what is allowed, exits 2 for bad input, and no result is inf or nan.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"

expect_status() {  # expect_status CODE args...: the exit status is CODE
  local code=$1; shift
  "$stratum" "$@" >"$tmp/out" 2>"$tmp/err"
  local got=$?
  [ "$got" = "$code" ] && ok || fail "'$*' exited $got, not $code: $(cat "$tmp/err")"
}

# --- numbers: the schema's syntax for every option --------------------------
expect_error "invalid n = 99999999999999999999: must be an integer in \[-2^63, 2^63)" points -s halton -n 99999999999999999999
expect_status 2 points -s halton -n 99999999999999999999
expect_error "invalid start = -1: must be an integer in \[0, 2^64)" points -s halton -n 2 --start -1
expect_error "invalid n = 0x10: must be an integer" points -s halton -n 0x10
expect_error "invalid n = 1e3: must be an integer" points -s halton -n 1e3
expect_error "invalid n = abc: must be an integer" points -s halton -n abc
# "010" is ten, as in -p KEY=VALUE (never octal eight).
[ "$("$stratum" points -s halton -n 010 -d 1 | wc -l)" = 10 ] && ok || fail "-n 010 is not read as ten"
[ "$("$stratum" points -s halton -n 4 -d 010 | head -1 | wc -w)" = 10 ] && ok || fail "-d 010 is not read as ten"
expect_error "invalid seed = 0x10" points -s halton -n 4 --seed 0x10
expect_error "invalid radius = inf: must be a finite real" points -s poisson-disk --radius inf
expect_error "invalid radius = nan: must be a finite real" points -s poisson-disk --radius nan
expect_error "invalid radius = 1e999: must be a finite real" points -s poisson-disk --radius 1e999
expect_error "invalid sizes = abc: must be a finite real" study importance --sizes abc

# --- subcommands -------------------------------------------------------------
expect_error "unknown subcommand 'foo': valid subcommands are samplers, describe, points" foo
expect_status 2 foo
expect_error "unknown subcommand 'foo' of study: valid subcommands are mitchell, dimension, importance" study foo
expect_error "unknown subcommand 'latin-square'" latin-square -n 4
# Without a subcommand: which ones there are (not CLI11's bare "A subcommand is required"), exit 2.
expect_error "stratum: error: give a subcommand: one of samplers, describe, points"
expect_status 2
expect_error "give a subcommand of study: one of mitchell, dimension, importance, mis (stratum study SUBCOMMAND --help" study
expect_status 2 points --no-such-option
expect_status 0 --version

# --- an allocation the system refuses: a message and exit 3, not std::bad_alloc --
# Not under AddressSanitizer (the asan preset sets ASAN_OPTIONS): its shadow memory needs far more address
# space than the ulimit leaves, so the process cannot start at all.
if [ -n "${ASAN_OPTIONS:-}" ]; then
  echo "skipped under AddressSanitizer: the refused-allocation case (ulimit -v)"
else
  (ulimit -v 600000; "$stratum" points -s random -n 50000000 -d 4 -o "$tmp/big.npy") >"$tmp/out" 2>"$tmp/err"
  code=$?
  [ "$code" = 3 ] && ok || fail "refused allocation exited $code: $(cat "$tmp/err")"
  grep -q "out of memory: the system refused an allocation this command needs" "$tmp/err" && ok || fail "no out-of-memory message: $(cat "$tmp/err")"
  grep -q "bad_alloc" "$tmp/err" && fail "std::bad_alloc shown" || ok
  [ -e "$tmp/big.npy" ] && fail "a refused allocation left big.npy" || ok
fi

# --- warps: -m first, results finite, inverses inside [0, 1] -----------------
expect_error "invalid map = (missing): give -m MAP, one of disk-polar, " warp
expect_error "invalid map = (missing)" warp -n 4
# 1e-320 is subnormal: the one number parser refuses it before the warp is built (Python's typed
# floats reach the warp's own probe instead: test_messages.py).
expect_error "invalid rate = 1e-320: is below the smallest normal double" warp -m exponential -n 4 --warp-param rate=1e-320
"$stratum" warp -m exponential -n 4 --warp-param rate=1e-300 >"$tmp/out" 2>"$tmp/err" && ok || fail "rate=1e-300 is representable: $(cat "$tmp/err")"
grep -qi "inf\|nan" "$tmp/out" && fail "warp printed inf or nan: $(cat "$tmp/out")" || ok

# --- integrands, converge and integrate: no inf or nan as a result ----------
expect_error "invalid integrand-param = a=1e+200: genz-gaussian is nan at x = (0.5, ...)" \
  integrate --integrand genz-gaussian -n 16 --integrand-param a=1e200
"$stratum" converge --integrand genz-gaussian --samplers random --n 16:64 --runs 4 --integrand-param a=1000 \
  >"$tmp/out" 2>"$tmp/err" && ok || fail "converge a=1000: $(cat "$tmp/err")"
grep -qiw "inf\|nan\|-nan" "$tmp/out" && fail "converge printed inf or nan: $(cat "$tmp/out")" || ok
grep -q "undefined" "$tmp/out" && ok || fail "converge at variance 0: no 'undefined' efficiency: $(cat "$tmp/out")"
"$stratum" integrate --integrand step -s grid -n 64 --runs 4 >"$tmp/out" 2>&1 && ok || fail "integrate grid runs 4"
grep -q "standard error  unavailable: the 4 runs gave identical estimates" "$tmp/out" && ok \
  || fail "identical runs are not flagged: $(cat "$tmp/out")"

# --- measures: a value that over- or underflows is refused, not printed -------
expect_error "invalid d = 2000: l2-star's terms .* underflow double precision past d = 644" discrepancy -m l2-star -s random -n 16 -d 2000
expect_error "invalid d = 5000: cd of these 16 points is inf: not representable" discrepancy -m cd -s random -n 16 -d 5000
"$stratum" discrepancy -m l2-star -s random -n 16 -d 644 >/dev/null && ok || fail "l2-star at d = 644 refused"

# --- point files -------------------------------------------------------------
printf '\xef\xbb\xbf0.1 0.2\n0.3 0.4\n' >"$tmp/bom.txt"
"$stratum" discrepancy -m l2-star "$tmp/bom.txt" >"$tmp/out" 2>"$tmp/err" && ok || fail "BOM refused: $(cat "$tmp/err")"
printf '0.1 0.2\n0.3 \x01\xff\x80zz\n' >"$tmp/bin.txt"
expect_error "line 2, column 2 is '\\\\x01\\\\xff\\\\x80zz': not a number" discrepancy -m l2-star "$tmp/bin.txt"
LC_ALL=C grep -q $'\x01' "$tmp/err" && fail "raw bytes echoed: $(cat -v "$tmp/err")" || ok
printf '# header\n0.1 0.2\n\n0.3 1.5\n' >"$tmp/range.txt"
expect_error "invalid input = $tmp/range.txt: line 4, column 2 is 1.5: coordinates must be in \[0, 1\]" \
  discrepancy -m l2-star "$tmp/range.txt"
expect_error "range.txt: line 4, column 2 is 1.5" local-discrepancy "$tmp/range.txt"
/usr/bin/python3 - "$tmp" <<'PY'
import struct, sys
folder = sys.argv[1]
def npy(name, header):
    header = header + " " * (118 - len(header)) + "\n"
    with open(f"{folder}/{name}", "wb") as f:
        f.write(b"\x93NUMPY\x01\x00" + struct.pack("<H", len(header)) + header.encode("latin-1") + b"\0" * 16)
npy("nodescr.npy", "{'fortran_order': False, 'shape': (1, 2), }")
npy("negative.npy", "{'descr': '<f8', 'fortran_order': False, 'shape': (-16, 2), }")
npy("bytes.npy", "{'descr': '<f8\x01\x02', 'fortran_order': False, 'shape': (1, 2), }")
PY
expect_error "nodescr.npy: holds dtype (none), allowed '<f8'" discrepancy -m l2-star "$tmp/nodescr.npy"
expect_error "negative.npy: has shape (-16, 2), allowed (n, d) or (n,) of non-negative integers" discrepancy -m l2-star "$tmp/negative.npy"
expect_error "bytes.npy: holds dtype '<f8\\\\x01\\\\x02'" discrepancy -m l2-star "$tmp/bytes.npy"

# --- spectrum: -r is --resolution only ---------------------------------------
expect_status 2 spectrum --sampler random -n 100 -r 2
"$stratum" spectrum --sampler random -n 100 --realizations 2 -k 4 >/dev/null && ok || fail "spectrum --realizations"

# --- --plot to a full disk: one line naming the figure, no Python traceback -----
full="$tmp/full"
mkdir -p "$full"
if mount -t tmpfs -o size=64k tmpfs "$full" 2>/dev/null; then
  trap 'umount "$full" 2>/dev/null; rm -rf "$tmp"' EXIT
  yes 0123456789 >"$full/fill" 2>/dev/null
  if "$stratum" converge --integrand disk --samplers random --n 16:64 --runs 2 --plot "$full/c.png" \
    >"$tmp/out" 2>"$tmp/err"; then
    fail "--plot on a full disk: exit 0"
  else
    grep -q "cannot write the figure $full/c.png: No space left on device" "$tmp/err" && ok \
      || fail "--plot full: $(cat "$tmp/err")"
    grep -q "Traceback" "$tmp/err" && fail "--plot full printed a traceback: $(cat "$tmp/err")" || ok
  fi
  [ -e "$full/c.png" ] && fail "--plot full left c.png" || ok
  umount "$full"
else
  echo "note: no tmpfs mount here; --plot on a full disk not tested"
fi

if "$stratum" render --help >/dev/null 2>&1; then
  # --- scenes and configs: place of the fault, empty files -------------------
  printf '{"camera": {"position": [0, 0, 1e999]}}\n' >"$tmp/s.json"
  expect_error "invalid scene = $tmp/s.json: has the number 1e999 at line 1, column 32" render "$tmp/s.json" -o "$tmp/x.png"
  : >"$tmp/empty.json"
  expect_error "invalid scene = $tmp/empty.json: is empty: it must hold a JSON document" render "$tmp/empty.json" -o "$tmp/x.png"
  expect_error "invalid configs = $tmp/empty.json: is empty" compare --configs "$tmp/empty.json"
  printf ' \n' >"$tmp/blank.json"
  expect_error "holds only white space" compare --configs "$tmp/blank.json"
  expect_error "invalid configs = $tmp/blank.json: give a built-in comparison or configurations, not both" \
    compare --builtin path --configs "$tmp/blank.json"
  # --- render options: no silent 0, no variance from one sample ---------------
  expect_error "invalid width = 0: must be an integer in \[1, 16384\]" render -o "$tmp/x.png" --width 0
  expect_error "invalid height = 0: must be an integer in \[1, 16384\]" render -o "$tmp/x.png" --height 0
  expect_error "invalid width = 0: must be an integer in \[1, 16384\]" compare --width 0  # the same words as render
  expect_error "invalid height = 16385: must be an integer in \[1, 16384\]" compare --height 16385
  expect_error "invalid passes = 0: must be in \[1, 2^24\]" render -o "$tmp/x.png" --passes 0
  expect_error "invalid variance = $tmp/v.exr: needs spp 2 or more" \
    render -o "$tmp/x.png" --spp 1 --variance "$tmp/v.exr" --width 8 --height 8
  [ -e "$tmp/x.png" ] || [ -e "$tmp/v.exr" ] && fail "a refused render left a file" || ok
  # --- compare says what it drops from the built-in box ----------------------
  "$stratum" compare --builtin shadow-rays --width 8 --height 8 --reference-spp 16 --cache "$tmp/cache" --json \
    >"$tmp/c.json" 2>"$tmp/err" && ok || fail "compare: $(cat "$tmp/err")"
  /usr/bin/python3 -c 'import json,sys; n=json.load(open(sys.argv[1]))["scene_note"]; assert "lens" in n and "motion" in n, n' \
    "$tmp/c.json" && ok || fail "compare JSON lacks scene_note"
fi

finish

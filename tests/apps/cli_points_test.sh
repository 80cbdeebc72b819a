#!/usr/bin/env bash
# CLI tests: output shapes, formats and the bad-input contract (message naming
# the argument, non-zero exit, no partial output file).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"

"$stratum" samplers | grep -q '^halton ' && ok || fail "samplers lists halton"
"$stratum" samplers --json | /usr/bin/python3 -c 'import json,sys; d=json.load(sys.stdin); assert any(s["name"]=="halton" for s in d["samplers"])' && ok || fail "samplers --json"
# the typed flags beside the words: sobol is progressive, spacetime-cook a space-time pattern, jittered neither
"$stratum" samplers --json | /usr/bin/python3 -c 'import json,sys; f={s["name"]: s["flags"] for s in json.load(sys.stdin)["samplers"]}; assert f["sobol"]["progressive"] and f["sobol"]["prefix_unbiased"] == ["owen-hash"]; assert f["spacetime-cook"]["space_time"]; assert not f["jittered"]["progressive"] and not f["jittered"]["space_time"]' && ok || fail "samplers --json flags"

lines=$("$stratum" points --sampler halton -n 100 -d 3 | wc -l)
[ "$lines" = 100 ] && ok || fail "points prints 100 lines, got $lines"
fields=$("$stratum" points --sampler halton -n 5 -d 3 | head -1 | wc -w)
[ "$fields" = 3 ] && ok || fail "points prints 3 columns, got $fields"
# The radical inverse in any base: van der Corput in base 10 reads the index's digits backwards (123 -> 0.321).
vdc=$("$stratum" points -s "halton(bases=10):none" -n 124 -d 1 | sed -n 124p)
[ "$vdc" = 0.321 ] && ok || fail "halton(bases=10) point 123 is $vdc, not 0.321"
expect_error "invalid bases = (1 value): give one base per dimension: d = 2" points -s halton -n 4 -d 2 -p bases=3
first=$("$stratum" points --sampler halton -n 6 -d 1 --randomize none | sed -n 6p)
[ "$first" = 0.625 ] && ok || fail "halton point 5 is 0.625, got $first"

"$stratum" points --sampler halton -n 64 -d 2 --format npy -o "$tmp/p.npy" && ok || fail "npy write"
/usr/bin/python3 -c "import numpy,sys; a=numpy.load('$tmp/p.npy'); assert a.shape==(64,2), a.shape" && ok || fail "npy shape"
"$stratum" points --sampler halton -n 64 -d 2 --randomize none --format csv -o "$tmp/p.csv" && ok || fail "csv write"
[ "$(head -1 "$tmp/p.csv")" = "0,0" ] && ok || fail "csv first row"

a=$("$stratum" points --sampler random -n 20000 -d 4 --seed 3 --threads 1 | md5sum)
b=$("$stratum" points --sampler random -n 20000 -d 4 --seed 3 --threads 2 | md5sum)
[ "$a" = "$b" ] && ok || fail "threads change the output"

# kronecker, faure and lattice-sequence: one test each through the CLI.
k=$("$stratum" points -s kronecker -n 2 -d 2 --randomize none | sed -n 2p)
[ "$k" = "0.7548776662466927 0.5698402909980532" ] && ok || fail "kronecker point 1 is R_2's alpha, got $k"
k=$("$stratum" points -s kronecker -n 4 -d 1 -p alpha=0.25 -p offset=0.5 | tr '\n' ' ')
[ "$k" = "0.5 0.75 0 0.25 " ] && ok || fail "kronecker alpha=0.25 offset=0.5, got $k"
expect_error "invalid alpha" points -s kronecker -n 4 -d 2 -p alpha=0.5
expect_error "invalid alpha\[0] = 1.5: must be a finite real in (0, 1)" points -s kronecker -n 4 -d 1 -p alpha=1.5
f=$("$stratum" points -s faure -n 4 -d 3 --randomize none | sed -n 4p)
[ "$f" = "0.1111111111111111 0.4444444444444444 0.7777777777777778" ] && ok || fail "faure point 3, got $f"
expect_error "randomize" points -s faure -n 4 -d 3 --randomize lms
l=$("$stratum" points -s lattice-sequence -n 4 -d 2 --randomize none -p generator=1,3 | tr '\n' ' ')
[ "$l" = "0 0 0.5 0.5 0.25 0.75 0.75 0.25 " ] && ok || fail "lattice-sequence generator=1,3, got $l"
expect_error "invalid d = 33" points -s lattice-sequence -n 4 -d 33
expect_error "invalid generator" points -s lattice-sequence -n 4 -d 2 -p generator=1,0

expect_error "sampler" points --sampler nosuch -n 4
# random is index-addressable: point i of --start K is point K + i of a longer run.
"$stratum" points -s random --seed 3 -n 12 -d 2 >"$tmp/out" && tail -n 5 "$tmp/out" >"$tmp/err" \
  && "$stratum" points -s random --seed 3 -n 5 -d 2 --start 7 | cmp -s - "$tmp/err" && ok || fail "random --start 7"
expect_error "invalid start = 1: jittered is a finite pattern" points -s jittered -n 16 --start 1
expect_error "halton" points --sampler nosuch -n 4
expect_error "invalid n = 0" points --sampler halton -n 0
expect_error "invalid n = -3" points --sampler halton -n -3
expect_error "invalid n = abc: must be an integer" points --sampler halton -n abc
expect_error "invalid d = 0" points --sampler halton -n 4 -d 0
expect_error "invalid d = 2000" points --sampler halton -n 4 -d 2000
expect_error "needs 21.3 PiB for 1000000000000000 x 3 points of random, " points --sampler random -n 1000000000000000 -d 3
expect_error "format" points --sampler halton -n 4 --format xls
expect_error "randomize" points --sampler halton -n 4 --randomize shuffle
# sobol's bits (scipy's Sobol bits): two digits of the LMS-scrambled points, from a spec or -p.
kept=$("$stratum" points -s 'sobol(bits=2):lms' -n 16 -d 3 --seed 4)
[ "$kept" = "$("$stratum" points -s sobol:lms -p bits=2 -n 16 -d 3 --seed 4)" ] && ok || fail "bits by spec and -p differ"
echo "$kept" | awk '{ for (i = 1; i <= NF; ++i) if ($i * 4 != int($i * 4)) bad = 1 } END { exit bad }' && ok \
  || fail "bits=2 left a coordinate that is not a multiple of 1/4: $kept"
[ "$(echo "$kept" | tr ' ' '\n' | sort -u | wc -l)" = 4 ] && ok || fail "bits=2: not the 4 values 0, 1/4, 1/2, 3/4"
expect_error "invalid bits = 65" points -s 'sobol(bits=65)' -n 4
expect_error "output" points --sampler halton -n 4 -o /nonexistent/x.txt
[ ! -e /nonexistent/x.txt ] && ok || fail "partial file left"
[ "$(id -u)" != 0 ] && chmod 555 "$tmp" && { expect_error "output" points --sampler halton -n 4 -o "$tmp/ro.txt"; chmod 755 "$tmp"; }
[ -z "$(ls -A "$tmp" | grep -v -e '^out$' -e '^err$' -e '^p\.')" ] && ok || fail "stray files: $(ls -A "$tmp")"

finish

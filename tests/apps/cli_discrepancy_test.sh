#!/usr/bin/env bash
# CLI tests of `stratum discrepancy`: values against scipy (an independent
# implementation of the L2 discrepancies), the three file formats, --measure
# all, JSON, thread invariance and the bad-input contract (message naming the
# argument, line or row and column; non-zero exit; nothing on stdout).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"
py=/usr/bin/python3

expect_error() {  # expect_error WORD args...: non-zero exit, WORD in stderr, empty stdout
  local word=$1; shift
  if "$stratum" "$@" >"$tmp/out" 2>"$tmp/err"; then fail "'$*' succeeded"; return; fi
  grep -q -- "$word" "$tmp/err" && ok || fail "'$*' stderr lacks '$word': $(cat "$tmp/err")"
  [ ! -s "$tmp/out" ] && ok || fail "'$*' printed to stdout: $(head -3 "$tmp/out")"
}

# 37 random points in 3D, written as txt, csv and npy, and scipy's values for them.
$py - "$tmp" <<'EOF'
import sys, numpy as np
from scipy.stats import qmc
tmp = sys.argv[1]
x = np.random.default_rng(20240607).random((37, 3))
np.savetxt(f"{tmp}/x.txt", x, fmt="%.17g")
np.savetxt(f"{tmp}/x.csv", x, fmt="%.17g", delimiter=",")
np.save(f"{tmp}/x.npy", x)
with open(f"{tmp}/scipy.txt", "w") as out:
    for name, method in (("l2-star", "L2-star"), ("cd", "CD"), ("wd", "WD"), ("md", "MD")):
        value = qmc.discrepancy(x, method=method)
        print(name, repr(value if method == "L2-star" else value ** 0.5), file=out)
EOF

# The registry value is the discrepancy itself: scipy's root (L2-star) or the root of scipy's square (CD, WD, MD).
for format in txt csv npy; do
  "$stratum" discrepancy "$tmp/x.$format" --measure all --json >"$tmp/all.json" 2>"$tmp/err" || fail "all on $format: $(cat "$tmp/err")"
  $py - "$tmp/all.json" "$tmp/scipy.txt" <<'EOF' && ok || fail "values of x.$format differ from scipy's"
import json, sys
result = {m["name"]: m for m in json.load(open(sys.argv[1]))["measures"]}
for line in open(sys.argv[2]):
    name, value = line.split()
    got = result[name]
    assert got["kind"] == "exact", got
    assert abs(got["value"] - float(value)) <= 1e-12 * float(value), (name, got["value"], value)
    assert abs(got["extras"]["squared"] - got["value"] ** 2) <= 1e-12 * got["value"] ** 2, got
EOF
done

# Text output: one line per measure with the kind; --measure all lists only measures defined for d.
"$stratum" discrepancy "$tmp/x.txt" --measure cd >"$tmp/cd.txt" || fail "cd text"
grep -q '^cd  *[0-9.e-]* (exact; squared = ' "$tmp/cd.txt" && ok || fail "cd text line: $(cat "$tmp/cd.txt")"
[ "$(wc -l <"$tmp/cd.txt")" = 1 ] && ok || fail "one line for one measure"
"$stratum" discrepancy "$tmp/x.txt" --measure all >"$tmp/all.txt" || fail "all text"
for name in l2-star cd wd md; do grep -q "^$name " "$tmp/all.txt" && ok || fail "all lacks $name"; done
grep -q '^edge ' "$tmp/all.txt" && fail "edge (2D only) listed for d = 3" || ok
"$stratum" discrepancy --sampler halton -n 64 -d 2 --measure all >"$tmp/all2.txt" || fail "all 2D"
for name in l2-star cd star; do grep -q "^$name " "$tmp/all2.txt" && ok || fail "2D all lacks $name"; done

# A --measure-param that one measure rejects for this d: that measure is skipped with the reason, the others still print.
"$stratum" discrepancy "$tmp/x.txt" --measure all --measure-param algorithm=fast >"$tmp/skip.txt" || fail "all with algorithm=fast"
grep -q '^l2-star  *[0-9]' "$tmp/skip.txt" && ok || fail "l2-star fast runs for d = 3"
$py -c "
import numpy as np; np.save('$tmp/x5.npy', np.random.default_rng(1).random((20, 5)))"
"$stratum" discrepancy "$tmp/x5.npy" --measure all --measure-param algorithm=fast >"$tmp/skip5.txt" || fail "all d = 5"
grep -q '^l2-star  *skipped: invalid algorithm = fast' "$tmp/skip5.txt" && ok || fail "l2-star skipped: $(cat "$tmp/skip5.txt")"
grep -q '^cd  *[0-9]' "$tmp/skip5.txt" && ok || fail "cd still printed after a skip"

# The fast L2-star algorithm and Warnock's agree (to 1e-10 relative) through the CLI.
"$stratum" discrepancy --sampler random -n 3000 -d 2 --seed 9 --measure l2-star --measure-param algorithm=fast --json >"$tmp/f.json"
"$stratum" discrepancy --sampler random -n 3000 -d 2 --seed 9 --measure l2-star --measure-param algorithm=warnock --json >"$tmp/w.json"
$py -c "
import json; f=json.load(open('$tmp/f.json'))['measures'][0]['value']; w=json.load(open('$tmp/w.json'))['measures'][0]['value']
assert abs(f - w) <= 1e-10 * w, (f, w)" && ok || fail "fast and warnock differ"

# A sampler's points measured directly equal the same points measured from a file; threads change nothing.
"$stratum" points --sampler random -n 500 -d 4 --seed 3 --format npy -o "$tmp/r.npy"
a=$("$stratum" discrepancy "$tmp/r.npy" --measure wd)
b=$("$stratum" discrepancy --sampler random -n 500 -d 4 --seed 3 --measure wd --threads 2)
[ "$a" = "$b" ] && ok || fail "file vs sampler: '$a' vs '$b'"
a=$("$stratum" discrepancy --sampler random -n 2000 -d 5 --seed 1 --measure md --threads 1)
b=$("$stratum" discrepancy --sampler random -n 2000 -d 5 --seed 1 --measure md --threads 2)
[ "$a" = "$b" ] && ok || fail "threads change md: '$a' vs '$b'"
"$stratum" discrepancy --sampler halton -n 16 --measure l2-star --json | $py -c '
import json, sys; d = json.load(sys.stdin); assert d["n"] == 16 and d["d"] == 2 and d["skipped"] == [], d
m = d["measures"][0]; assert m["name"] == "l2-star" and m["lower"] is None and m["upper"] is None, m' && ok || fail "json shape"

# Bad input.
printf '0.1 0.2\n0.3 1.5\n' >"$tmp/out_of_cube.txt"
expect_error "out_of_cube.txt: line 2, column 2 is 1.5: coordinates must be in \[0, 1\]" discrepancy "$tmp/out_of_cube.txt" --measure cd
printf '0.1 0.2\n0.3 nan\n' >"$tmp/nan.txt"
expect_error "line 2, column 2 is 'nan'" discrepancy "$tmp/nan.txt" --measure cd
printf '0.1,0.2\n0.3,inf\n' >"$tmp/inf.csv"
expect_error "line 2, column 2 is 'inf'" discrepancy "$tmp/inf.csv" --measure cd
$py -c "import numpy as np; a=np.full((3,2),0.5); a[2,0]=np.nan; np.save('$tmp/nan.npy', a)"
expect_error "point\[2\]\[0\] is nan" discrepancy "$tmp/nan.npy" --measure cd
printf '0.1 0.2\n\n# comment\n0.3\n' >"$tmp/ragged.txt"
expect_error "line 4 has 1 values, line 1 (the first point) has 2" discrepancy "$tmp/ragged.txt" --measure cd
printf '0.1 0.2\n0.3 abc\n' >"$tmp/word.txt"
expect_error "line 2, column 2 is 'abc': not a number" discrepancy "$tmp/word.txt" --measure cd
printf '0.1,,0.2\n' >"$tmp/hole.csv"
expect_error "line 1, column 2 is '': not a number" discrepancy "$tmp/hole.csv" --measure cd
: >"$tmp/empty.txt"
expect_error "holds no points" discrepancy "$tmp/empty.txt" --measure cd
printf '0.1 0.2\n' >"$tmp/one.txt"
expect_error "invalid n = 1" discrepancy "$tmp/one.txt" --measure cd
$py -c "import numpy as np; np.save('$tmp/f32.npy', np.full((3,2),0.5,dtype=np.float32)); np.save('$tmp/fortran.npy', np.asfortranarray(np.full((3,2),0.5)))"
expect_error "'<f4'" discrepancy "$tmp/f32.npy" --measure cd
expect_error "Fortran order" discrepancy "$tmp/fortran.npy" --measure cd
head -c 150 "$tmp/x.npy" >"$tmp/cut.npy"
expect_error "data bytes" discrepancy "$tmp/cut.npy" --measure cd
printf 'not a numpy file' >"$tmp/fake.npy"
expect_error "not a .npy file" discrepancy "$tmp/fake.npy" --measure cd
expect_error "cannot be opened" discrepancy "$tmp/missing.txt" --measure cd
expect_error "invalid measure = nosuch" discrepancy "$tmp/x.txt" --measure nosuch
expect_error "l2-star, cd" discrepancy "$tmp/x.txt" --measure nosuch
expect_error "edge is defined for d in \[2, 2\]" discrepancy "$tmp/x.txt" --measure edge
expect_error "invalid algorithm = fast" discrepancy "$tmp/x5.npy" --measure l2-star --measure-param algorithm=fast
expect_error "invalid algorithm = quick" discrepancy "$tmp/x.txt" --measure l2-star --measure-param algorithm=quick
expect_error "invalid measure-param = lines=5: cd takes no parameters" discrepancy "$tmp/x.txt" --measure cd --measure-param lines=5
expect_error "invalid measure-param = bogus" discrepancy "$tmp/x.txt" --measure all --measure-param bogus=1
expect_error "invalid measure-param = lines" discrepancy "$tmp/x.txt" --measure cd --measure-param lines
expect_error "invalid input" discrepancy --measure cd
expect_error "invalid input" discrepancy "$tmp/x.txt" --sampler halton -n 4 --measure cd
expect_error "invalid n" discrepancy --sampler halton --measure cd
expect_error "invalid -n/-d" discrepancy "$tmp/x.txt" -n 5 --measure cd
expect_error "invalid threads = -1" discrepancy "$tmp/x.txt" --measure cd --threads -1
expect_error "sampler" discrepancy --sampler nosuch -n 4 --measure cd
expect_error "measure" discrepancy "$tmp/x.txt"

finish

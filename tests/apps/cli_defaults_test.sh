#!/usr/bin/env bash
# One default across subcommands (docs/cli.md): every --seed is 0 and every
# --threads is 0 (every core), read from each subcommand's own --help, and a
# run without them equals one that gives them.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"

subcommands() {  # subcommands WORDS...: the subcommands listed by `stratum WORDS --help`
  "$stratum" "$@" --help | sed -n '/^Subcommands:/,$p' | awk 'NR > 1 && /^  [a-z]/ {print $1}'
}
seeded=0 threaded=0
check() {  # check WORDS...: this subcommand's defaults, then its own subcommands'
  local help
  help=$("$stratum" "$@" --help) || { fail "'$* --help' failed"; return; }
  if grep -q -- '--seed' <<<"$help"; then
    grep -qE -- '--seed UINT=0 ' <<<"$help" && ok || fail "'$*': seed default is not 0: $(grep -- '--seed' <<<"$help")"
    seeded=$((seeded + 1))
  fi
  if grep -q -- '--threads' <<<"$help"; then
    grep -qE -- '--threads INT=0 ' <<<"$help" && ok || fail "'$*': threads default is not 0: $(grep -- '--threads' <<<"$help")"
    threaded=$((threaded + 1))
  fi
  local sub
  for sub in $(subcommands "$@"); do check "$@" "$sub"; done
}
for command in $(subcommands); do check "$command"; done
# Every randomized subcommand was found (not a vacuous pass): points, warp,
# integrate, converge, discrepancy, local-discrepancy, koksma-hlawka,
# spectrum, pair-correlation, optimize blue-noise, render, compare, report
# and the four studies.
[ "$seeded" -ge 15 ] && ok || fail "only $seeded subcommands have --seed"
[ "$threaded" -ge 14 ] && ok || fail "only $threaded subcommands have --threads"

# The defaults are the values used: no --seed is --seed 0, no --threads is every core.
"$stratum" points -s sobol:owen -n 64 -d 3 >"$tmp/a" && "$stratum" points -s sobol:owen -n 64 -d 3 --seed 0 >"$tmp/b" &&
  cmp -s "$tmp/a" "$tmp/b" && ok || fail "points: no --seed differs from --seed 0"
"$stratum" points -s sobol:owen -n 64 -d 3 --seed 1 >"$tmp/c" && ! cmp -s "$tmp/a" "$tmp/c" && ok ||
  fail "points: --seed 1 gives the points of seed 0"
"$stratum" integrate --integrand genz-gaussian -d 2 -s random -n 256 --runs 4 --json >"$tmp/a" &&
  "$stratum" integrate --integrand genz-gaussian -d 2 -s random -n 256 --runs 4 --seed 0 --threads 1 --json >"$tmp/b" &&
  /usr/bin/python3 -c "import json,sys; a,b=(json.load(open(f)) for f in sys.argv[1:]); assert a['estimate']==b['estimate'], (a,b)" \
    "$tmp/a" "$tmp/b" && ok || fail "integrate: the defaults differ from --seed 0 --threads 1 in the estimate"
finish

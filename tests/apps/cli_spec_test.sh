#!/usr/bin/env bash
# The sampler spec NAME[(KEY=VALUE,...)][:RANDOMIZER] (docs/samplers.md) on
# every sampler-taking subcommand: the same specs are accepted, the same bad
# ones refused with the same message; -p/--randomize conflicts; strict seeds;
# the thread rule (0 = every core).
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"

# run_with NAME SPEC [extra args]: subcommand NAME with the sampler SPEC, 32 points.
run_with() {
  local name=$1 spec=$2; shift 2
  case $name in
    points) "$stratum" points --sampler "$spec" -n 32 "$@" ;;
    discrepancy) "$stratum" discrepancy --sampler "$spec" -n 32 --measure cd "$@" ;;
    local-discrepancy) "$stratum" local-discrepancy --sampler "$spec" -n 32 -r 4 "$@" ;;
    koksma-hlawka) "$stratum" koksma-hlawka --sampler "$spec" -n 32 "$@" ;;
    spectrum) "$stratum" spectrum --sampler "$spec" -n 32 -k 4 --json "$@" ;;
    warp) "$stratum" warp --map disk-concentric -n 32 --sampler "$spec" "$@" ;;
    integrate) "$stratum" integrate --integrand disk --sampler "$spec" -n 32 "$@" ;;
    converge) "$stratum" converge --integrand disk --samplers "$spec" --n 32 --runs 2 "$@" ;;
    mitchell) "$stratum" study mitchell --sampler "$spec" --counts 32 --realizations 1 --lines 100 "$@" ;;
    render) "$stratum" render --sampler "$spec" --spp 32 --light-samples 32 --width 4 --height 4 -q -o "$tmp/r.png" "$@" ;;
  esac
}
# Every subcommand with -s/--sampler, -p and --randomize; `study mitchell --sampler` takes extra
# patterns (specs too, but no -p/--randomize, and not one of its own five: jittered, poisson-disk(periodic=1)).
with_params="points discrepancy local-discrepancy koksma-hlawka spectrum warp integrate converge"
renderer=false
if has_render; then renderer=true; fi
$renderer && with_params="$with_params render"
options=$with_params
commands="$options mitchell"

# Accepted everywhere.
for name in $commands; do
  for spec in 'sobol:owen' 'sobol' 'halton:permute'; do
    run_with "$name" "$spec" >"$tmp/out" 2>"$tmp/err" && ok || fail "$name accepts $spec: $(cat "$tmp/err")"
  done
done
for name in $with_params; do
  for spec in 'poisson-disk(periodic=1)' 'jittered(strata=4x8)'; do
    run_with "$name" "$spec" >"$tmp/out" 2>"$tmp/err" && ok || fail "$name accepts $spec: $(cat "$tmp/err")"
  done
done

# The spec and its parts give the same points.
a=$("$stratum" points -s 'poisson-disk(periodic=1)' -n 16 --seed 3)
b=$("$stratum" points -s poisson-disk -p periodic=1 -n 16 --seed 3)
c=$("$stratum" points -s poisson-disk -n 16 --seed 3)
[ -n "$a" ] && [ "$a" = "$b" ] && ok || fail "poisson-disk(periodic=1) differs from -p periodic=1"
[ "$a" != "$c" ] && ok || fail "periodic=1 had no effect"
a=$("$stratum" points -s sobol:owen -n 8 --seed 5)
b=$("$stratum" points -s sobol --randomize owen -n 8 --seed 5)
[ -n "$a" ] && [ "$a" = "$b" ] && ok || fail "sobol:owen differs from --randomize owen"
a=$("$stratum" points -s 'jittered(strata=4x8)' -n 32 --seed 1)
b=$("$stratum" points -s jittered -p strata=4x8 -n 32 --seed 1)
c=$("$stratum" points -s jittered -p strata=8x4 -n 32 --seed 1)
[ -n "$a" ] && [ "$a" = "$b" ] && [ "$a" != "$c" ] && ok || fail "jittered(strata=4x8) and -p strata=4x8"
a=$("$stratum" points -s 'lattice(generator=1,5)' -n 8 --randomize none)
b=$("$stratum" points -s lattice -p generator=1,5 -n 8 --randomize none)
[ -n "$a" ] && [ "$a" = "$b" ] && ok || fail "lattice(generator=1,5) differs from -p generator=1,5"
# converge: parameters through the spec, lists split outside parentheses.
"$stratum" converge --integrand disk --samplers 'jittered(strata=4x8),lattice(generator=1,7):cp,sobol:owen' --n 32 \
  --runs 2 --json >"$tmp/c.json" && ok || fail "converge with a list of specs"
[ "$(grep -c '"name": "' "$tmp/c.json")" -ge 3 ] && ok || fail "converge lists three samplers: $(cat "$tmp/c.json")"

# same_error WORDS SPEC [extra args]: every subcommand refuses SPEC with one
# message (its first line), and the message has WORDS.
same_error() {
  local words=$1 spec=$2; shift 2
  local first="" name
  for name in $commands; do
    if run_with "$name" "$spec" "$@" >"$tmp/out" 2>"$tmp/err"; then fail "$name accepted $spec $*"; continue; fi
    [ -s "$tmp/out" ] && fail "$name wrote output for the bad $spec"
    local message
    message=$(head -n 1 "$tmp/err")
    grep -qF -- "$words" <<<"$message" || fail "$name $spec: '$message' lacks '$words'"
    if [ -z "$first" ]; then first=$message; ok; continue; fi
    [ "$message" = "$first" ] && ok || fail "$name $spec: '$message' differs from '$first'"
  done
}
same_error "invalid sampler = sobl:owen: unknown sampler 'sobl' at position 1; did you mean sobol" 'sobl:owen'
same_error "invalid sampler = nosuch: unknown sampler 'nosuch' at position 1; valid samplers are" 'nosuch'
same_error "unknown key 'periodc' at position 14; poisson-disk takes candidates, periodic" 'poisson-disk(periodc=1)'
same_error "randomizer 'owen-hash' at position 8 is not one halton accepts; halton accepts" 'halton:owen-hash'
same_error "unbalanced parentheses: '(' at position 8 is never closed" 'lattice(generator=1,55'
same_error "unbalanced parentheses: ')' at position 6 has no '('" 'sobol)'
same_error "empty key at position 10" 'jittered(=4x8)'
same_error "empty value for key 'strata' at position 17" 'jittered(strata=)'
same_error "duplicate key 'periodic' at position 25 (first at position 14)" 'poisson-disk(periodic=1,periodic=0)'
same_error "empty randomizer after ':' at position 6" 'sobol:'
# The two forms at once.
commands=$options same_error "invalid randomize = xor: conflicts with the randomizer of the sampler spec sobol:owen" \
  'sobol:owen' --randomize xor
commands=$with_params same_error "invalid param = periodic=0: conflicts with periodic=1 in the sampler spec" \
  'poisson-disk(periodic=1)' -p periodic=0
commands=$with_params same_error "invalid param = bogus=1: poisson-disk takes candidates, periodic" 'poisson-disk' -p bogus=1
if $renderer; then
  # The renderer's sets are the sampler's under its parameters: cmj(aspect=2) is not cmj; the spec and -p agree.
  render_exr() { "$stratum" render --spp 16 --width 8 --height 8 -q "$@"; }
  render_exr -s 'cmj(aspect=2)' -o "$tmp/a.exr" && render_exr -s cmj -p aspect=2 -o "$tmp/b.exr" &&
    render_exr -s cmj -o "$tmp/c.exr" && ok || fail "render -s 'cmj(aspect=2)'"
  cmp -s "$tmp/a.exr" "$tmp/b.exr" && ! cmp -s "$tmp/a.exr" "$tmp/c.exr" && ok ||
    fail "render: cmj(aspect=2) and -p aspect=2 differ, or equal plain cmj"
  # The shadow-ray arrays are sets of the same sampler: strata=4x4 needs 16 light samples.
  rm -f "$tmp/r.png"
  expect_error "invalid light-samples = 1: the sampler jittered(strata=4x4) cannot draw that many points per shading \
point (invalid n = 1: must equal the product of strata=4x4)" render -s 'jittered(strata=4x4)' --spp 16 -q -o "$tmp/r.png"
  expect_error "invalid sampler = zsobol(resolution=8): resolution is the renderer's own for an image sampler" \
    render -s 'zsobol(resolution=8)' --spp 4 --width 8 --height 8 -q -o "$tmp/r.png"
  [ ! -e "$tmp/r.png" ] && ok || fail "a refused render wrote its output"
fi
# The parameters of what is not the sampler have their own flags.
expect_error "invalid sampler = random" integrate --integrand disk --sampler 'random(a=1)' -n 8
expect_error "invalid param = a=2: random takes no parameters" integrate --integrand genz-gaussian --sampler random -n 8 -p a=2
"$stratum" integrate --integrand genz-gaussian -d 2 --integrand-param a=2,3 --sampler random -n 8 >/dev/null && ok ||
  fail "integrate --integrand-param"
expect_error "invalid param = cos_theta_max=0.5: random takes no parameters" warp --map cone -n 4 -p cos_theta_max=0.5

# Seeds: exactly the integers in [0, 2^64), on every subcommand that takes one.
for seed in -1 18446744073709551616 99999999999999999999999 1e3 abc 0x10 ''; do
  for name in $commands; do
    if run_with "$name" sobol --seed "$seed" >"$tmp/out" 2>"$tmp/err"; then fail "$name --seed '$seed' accepted"; continue; fi
    grep -qF -- "invalid seed = ${seed:-''}: must be an integer in [0, 2^64)" "$tmp/err" && ok ||
      fail "$name --seed '$seed': $(cat "$tmp/err")"
  done
  for sub in "study dimension --dims 1 --n 4:8 --runs 2" "study importance --runs 2 --samples 16"; do
    # shellcheck disable=SC2086
    if "$stratum" $sub --seed "$seed" >"$tmp/out" 2>"$tmp/err"; then fail "$sub --seed '$seed' accepted"; continue; fi
    grep -qF -- "invalid seed = ${seed:-''}" "$tmp/err" && ok || fail "$sub --seed '$seed': $(cat "$tmp/err")"
  done
done
expect_error "invalid start = -1: must be an integer in" points -s sobol -n 2 --start -1
expect_error "invalid start = 1e3: must be an integer in" points -s sobol -n 2 --start 1e3
top=$("$stratum" points -s random -n 2 --seed 18446744073709551615) && ok || fail "--seed 2^64 - 1 refused"
below=$("$stratum" points -s random -n 2 --seed 18446744073709551614)
[ -n "$top" ] && [ "$top" != "$below" ] && ok || fail "seeds 2^64 - 1 and 2^64 - 2 give the same points"

# Threads: 0 = every core, the same points as 1; below 0 or above 1024 refused with one message.
a=$("$stratum" points -s sobol:owen -n 10000 --threads 0 | md5sum)
b=$("$stratum" points -s sobol:owen -n 10000 --threads 1 | md5sum)
[ "$a" = "$b" ] && ok || fail "--threads 0 and --threads 1 differ"
for name in points discrepancy koksma-hlawka spectrum integrate converge mitchell; do
  run_with "$name" sobol --threads 0 >/dev/null 2>"$tmp/err" && ok || fail "$name --threads 0: $(cat "$tmp/err")"
  for bad in -1 1025 two; do
    if run_with "$name" sobol --threads "$bad" >/dev/null 2>"$tmp/err"; then fail "$name --threads $bad accepted"; continue; fi
    grep -qF "invalid threads = $bad: must be an integer in [0, 1024] (0: every core)" "$tmp/err" && ok ||
      fail "$name --threads $bad: $(cat "$tmp/err")"
  done
done

# Every sampler-taking --help points at the grammar.
for sub in points discrepancy local-discrepancy koksma-hlawka spectrum warp integrate converge "study mitchell"; do
  # shellcheck disable=SC2086
  "$stratum" $sub --help | grep -q "docs/samplers.md" && ok || fail "$sub --help lacks docs/samplers.md"
done
finish

#!/usr/bin/env bash
# Ctrl-C (SIGINT sent to the child) during `stratum render`: the first one
# stops the render, which writes its partial image, says what it holds and
# exits 130; a second one ends it at once, leaving no output. Other long
# commands end with 130 and no output. A hang fails at the 20 s timeouts.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"
stratum=$(realpath "$stratum")

# The signals go to stratum itself (not through timeout(1), which hands a
# SIGINT on to its child twice: to it and to its process group); a watchdog
# ends a hung child after 20 s. A script's background commands start with
# SIGINT ignored (POSIX): env --default-signal gives them the default back,
# as a command typed at a terminal has.
run() { exec env --default-signal=INT "$stratum" "$@"; }
watchdog() { (sleep 20; kill -KILL "$1" 2>/dev/null) & }

hidden() { ls -A "$1" | grep '^\.' || true; }  # staging files left in folder $1
wait_cpu() {  # wait_cpu PID SECONDS: until the process has run SECONDS of CPU time (past its set-up, on a busy machine too)
  local ticks=$(getconf CLK_TCK) used
  for _ in $(seq 400); do
    used=$(awk '{print $14 + $15}' "/proc/$1/stat" 2>/dev/null) || return
    [ "$used" -ge $(($2 * ticks)) ] && return
    sleep 0.05
  done
}

# --- one SIGINT: the partial image, a message, exit 130 ---------------------------------
mkdir "$tmp/one"
(run render --width 64 --height 64 --spp 4096 --passes 4096 --threads 2 -q -o "$tmp/one/r.png" 2>"$tmp/one.err") &
renderer=$!
watchdog "$renderer"
wait_cpu "$renderer" 2
kill -INT "$renderer"
wait "$renderer"
status=$?
[ "$status" = 130 ] && ok || fail "one SIGINT: exit $status, not 130: $(cat "$tmp/one.err")"
grep -q "stopped by Ctrl-C: $tmp/one/r.png holds the [1-9][0-9]* of 4096 passes completed ([1-9][0-9]* of 4096 spp" \
  "$tmp/one.err" && ok || fail "one SIGINT: message: $(cat "$tmp/one.err")"
/usr/bin/python3 - "$tmp/one/r.png" <<'PY' && ok || fail "one SIGINT: the partial image is not a 64x64 render"
import sys, matplotlib.image as im
a = im.imread(sys.argv[1]); assert a.shape[:2] == (64, 64) and a.shape[2] >= 3, a.shape
assert a.max() > 0.5  # the light is in view: pixels were rendered
PY
[ -z "$(hidden "$tmp/one")" ] && ok || fail "one SIGINT left $(hidden "$tmp/one")"

# --- two SIGINTs: the second ends the render at once, no output --------------------------
# One pixel of 1024 samples of 65536 shadow rays each (half a minute): the
# first SIGINT is seen between pixels, so the render goes on (and is alive
# after it); only the second one can end it.
mkdir "$tmp/two"
(run render --width 1 --height 1 --spp 1024 --passes 1 --light-samples 65536 -q -o "$tmp/two/r.png" 2>"$tmp/two.err") &
renderer=$!
watchdog "$renderer"
wait_cpu "$renderer" 2
kill -INT "$renderer"
sleep 0.5
kill -0 "$renderer" 2>/dev/null && ok || fail "two SIGINTs: the first one ended the render of a pixel"
kill -INT "$renderer"
wait "$renderer"
status=$?
[ "$status" = 130 ] && ok || fail "two SIGINTs: exit $status, not 130: $(cat "$tmp/two.err")"
[ -z "$(ls -A "$tmp/two")" ] && ok || fail "two SIGINTs left $(ls -A "$tmp/two")"

# --- other long commands: exit 130, no output --------------------------------------------
long_command() {  # long_command NAME ARGS...: SIGINT after 1.5 s; exit 130 and an empty folder
  local name=$1; shift
  mkdir "$tmp/$name"
  (cd "$tmp/$name" && run "$@" >"$tmp/$name.out" 2>"$tmp/$name.err") &
  local child=$!
  watchdog "$child"
  sleep 1.5
  kill -INT "$child"
  wait "$child"
  local status=$?
  [ "$status" = 130 ] && ok || fail "$name: exit $status, not 130: $(cat "$tmp/$name.err")"
  [ -z "$(ls -A "$tmp/$name")" ] && ok || fail "$name left $(ls -A "$tmp/$name")"
}
long_command discrepancy discrepancy -s random -n 400000 -d 4 -m l2-star --measure-param algorithm=warnock
long_command converge converge --integrand genz-gaussian -d 8 --samplers random,sobol:owen --n 1024:16777216:4 \
  --runs 256 --plot c.png
long_command study study dimension --runs 64 --n 16:16777216 --plot study.png
finish

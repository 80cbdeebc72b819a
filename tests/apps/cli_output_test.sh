#!/usr/bin/env bash
# CLI tests of what happens to outputs (docs/outputs.md):
# special files written to, links written through, permissions and hard links
# kept, every output checked before the work, all-or-none outputs, full
# disks, signals; and of hostile inputs (FIFOs, deep JSON, integer overflow).
# Never /dev/null or /dev/full: FIFOs, links and a small tmpfs in $tmp.
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"
full="$tmp/full"
mkdir -p "$full"
trap 'umount "$full" 2>/dev/null; rm -rf "$tmp"' EXIT

hidden() { ls -A "$1" | grep '^\.' || true; }  # staging or temporary files left in folder $1

# --- points: special files, links, permissions, hard links --------------------
"$stratum" points -s halton -n 16 >"$tmp/expected.txt" || fail "points to stdout"
mkfifo "$tmp/fifo"
timeout 30 cat "$tmp/fifo" >"$tmp/from-fifo" &
reader=$!
timeout 30 "$stratum" points -s halton -n 16 -o "$tmp/fifo" 2>"$tmp/err" && ok || fail "points into a FIFO: $(cat "$tmp/err")"
wait "$reader"
[ -p "$tmp/fifo" ] && ok || fail "the FIFO was replaced by a regular file"
cmp -s "$tmp/from-fifo" "$tmp/expected.txt" && ok || fail "the FIFO's reader did not get the points"

mkdir "$tmp/real"
echo old >"$tmp/real/p.txt"
ln -s real/p.txt "$tmp/link.txt"
"$stratum" points -s halton -n 16 -o "$tmp/link.txt" && ok || fail "points through a symlink"
[ -L "$tmp/link.txt" ] && ok || fail "the symlink was replaced"
cmp -s "$tmp/real/p.txt" "$tmp/expected.txt" && ok || fail "the symlink's target was not written"

echo old >"$tmp/private.txt"
chmod 600 "$tmp/private.txt"
"$stratum" points -s halton -n 16 -o "$tmp/private.txt" && ok || fail "points over a 0600 file"
[ "$(stat -c %a "$tmp/private.txt")" = 600 ] && ok || fail "permissions reset to $(stat -c %a "$tmp/private.txt")"

echo old >"$tmp/h1.txt"
ln "$tmp/h1.txt" "$tmp/h2.txt"
expect_error "has 2 hard links" points -s halton -n 16 -o "$tmp/h1.txt"
[ "$(cat "$tmp/h2.txt")" = old ] && [ "$(stat -c %h "$tmp/h1.txt")" = 2 ] && ok || fail "a hard link was split or overwritten"

# --- format and extension -----------------------------------------------------
expect_error "invalid format = txt: does not match the output" points -s halton -n 16 -o "$tmp/x.npy" --format txt
[ ! -e "$tmp/x.npy" ] && ok || fail "a mismatched --format left a file"
expect_error "invalid format = csv: needs an output name ending in .csv" points -s halton -n 16 --format csv -o "$tmp/p.dat"
"$stratum" points -s halton -n 16 -o "$tmp/y.npy" && ok || fail "points -o y.npy"
head -c 6 "$tmp/y.npy" | grep -q NUMPY && ok || fail "-o y.npy without --format is not .npy"
"$stratum" discrepancy "$tmp/y.npy" --measure cd >"$tmp/out" 2>"$tmp/err" && ok || fail "its own reader refuses y.npy: $(cat "$tmp/err")"

# --- kill -9 leftovers are cleaned at the next write into the folder -------------
mkdir "$tmp/stale"
sh -c 'exit 0' &
dead=$!
wait "$dead"
touch "$tmp/stale/.q.txt.stratum-tmp.$dead-0.txt"
"$stratum" points -s halton -n 4 -o "$tmp/stale/q.txt" && ok || fail "points into the stale folder"
[ -z "$(hidden "$tmp/stale")" ] && ok || fail "a dead process's staging file was kept: $(hidden "$tmp/stale")"

# --- SIGTERM during a long write leaves no staging file -----------------------------
mkdir "$tmp/signal"
"$stratum" points -s random -n 4000000 -d 2 -o "$tmp/signal/p.txt" 2>/dev/null &
writer=$!
for _ in $(seq 600); do [ -n "$(hidden "$tmp/signal")" ] && break; sleep 0.05; done
kill -TERM "$writer"
wait "$writer"
status=$?
[ "$status" -ne 0 ] && ok || fail "SIGTERM during the write: exit 0"
[ -z "$(ls -A "$tmp/signal")" ] && ok || fail "SIGTERM during the write left: $(ls -A "$tmp/signal")"

# --- stdout: every write checked ---------------------------------------------------
if mount -t tmpfs -o size=64k tmpfs "$full" 2>"$tmp/err"; then
  if "$stratum" points -s random -n 100000 -d 4 >"$full/out.txt" 2>"$tmp/err"; then
    fail "stdout on a full disk: exit 0"
  else
    grep -q "stdout" "$tmp/err" && grep -q "No space left on device" "$tmp/err" && ok || fail "stdout full: $(cat "$tmp/err")"
  fi
  rm -f "$full/out.txt"
  expect_error "No space left on device" points -s random -n 100000 -d 4 -o "$full/p.txt"
  [ -z "$(ls -A "$full")" ] && ok || fail "a full disk left: $(ls -A "$full")"
  if has_render; then  # an EXR of 128x128 floats is 200 KB: it cannot fit
    expect_error "invalid exr = $full/r.exr" render --width 128 --height 128 --spp 1 -q -o "$tmp/r.png" --exr "$full/r.exr"
    [ -z "$(ls -A "$full")" ] && [ ! -e "$tmp/r.png" ] && ok || fail "a full disk left files: $(ls -A "$full") $(ls "$tmp/r.png" 2>&1)"
  fi
  umount "$full"
else
  echo "SKIP: full-disk cases (cannot mount a tmpfs: $(cat "$tmp/err"))"
fi
if "$stratum" points -s halton -n 16 >&- 2>"$tmp/err"; then fail "closed stdout: exit 0"; else
  grep -q "stdout" "$tmp/err" && ok || fail "closed stdout: $(cat "$tmp/err")"
fi

# --- inputs that are not regular files: refused at once ------------------------------
mkfifo "$tmp/in.fifo"
expect_input_refused() {  # expect_input_refused args...: exit 2 within the timeout, "regular file" in stderr
  timeout 20 "$stratum" "$@" >"$tmp/out" 2>"$tmp/err"
  local status=$?
  [ "$status" = 2 ] && grep -q "regular file" "$tmp/err" && ok || fail "'$*': exit $status: $(cat "$tmp/err")"
}
expect_input_refused discrepancy "$tmp/in.fifo" --measure cd
expect_input_refused warp --map triangle -n 4 --warp-param "vertices=@$tmp/in.fifo"
expect_error "invalid vertices = /nonexistent/v.txt: does not exist" warp --map triangle -n 4 --warp-param vertices=@/nonexistent/v.txt

if has_render; then
  # --- render: outputs checked before the work, all or none ----------------------------
  mkdir "$tmp/folder.png"
  timeout 120 "$stratum" render --spp 16777216 -q -o "$tmp/folder.png" 2>"$tmp/err"
  status=$?
  [ "$status" = 2 ] && grep -q "is a folder" "$tmp/err" && ok || fail "-o FOLDER: exit $status: $(cat "$tmp/err")"
  [ -z "$(hidden "$tmp")" ] && ok || fail "-o FOLDER left $(hidden "$tmp")"
  expect_error "invalid variance = $tmp/no/such/v.exr" render --width 8 --height 8 --spp 2 -q -o "$tmp/first.png" --variance "$tmp/no/such/v.exr"
  [ ! -e "$tmp/first.png" ] && ok || fail "a bad --variance path was found after the PNG was written"
  expect_error "same file as --output" render --width 8 --height 8 --spp 2 -q -o "$tmp/same.exr" --exr "$tmp/same.exr"
  expect_error "same file as --exr" render --width 8 --height 8 --spp 2 -q -o "$tmp/s.png" --exr "$tmp/same.exr" --variance "$tmp/./same.exr"
  [ ! -e "$tmp/same.exr" ] && [ ! -e "$tmp/s.png" ] && ok || fail "same-file outputs wrote something"
  ln -s first.png "$tmp/render-link.png"
  "$stratum" render --width 8 --height 8 --spp 2 -q -o "$tmp/render-link.png" && ok || fail "render through a symlink"
  [ -L "$tmp/render-link.png" ] && [ -s "$tmp/first.png" ] && ok || fail "render replaced the symlink"

  # --- SIGINT and SIGTERM during a long render -----------------------------------------
  mkdir "$tmp/render-signal"
  for signal in INT TERM; do
    # A script's background commands start with SIGINT ignored: env gives it the default back, as at a terminal.
    env --default-signal=INT "$stratum" render --width 64 --height 64 --spp 16777216 --passes 1000000 -q \
      -o "$tmp/render-signal/r.png" 2>/dev/null &
    renderer=$!
    for _ in $(seq 200); do [ -n "$(hidden "$tmp/render-signal")" ] && break; sleep 0.05; done
    sleep 0.5
    kill -"$signal" "$renderer"
    wait "$renderer"
    [ -z "$(hidden "$tmp/render-signal")" ] && ok || fail "SIG$signal during a render left $(hidden "$tmp/render-signal")"
  done

  # --- hostile scenes and configs -------------------------------------------------------
  /usr/bin/python3 -c "print('[' * 100000 + ']' * 100000)" >"$tmp/deep.json"
  timeout 60 "$stratum" render "$tmp/deep.json" -q -o "$tmp/deep.png" 2>"$tmp/err"
  status=$?
  [ "$status" = 2 ] && grep -q "deeper than 256 levels at line 1, column 257" "$tmp/err" && ok || fail "deep scene: exit $status: $(head -c 300 "$tmp/err")"
  [ "$(wc -c <"$tmp/err")" -lt 400 ] && ok || fail "deep scene: a message of $(wc -c <"$tmp/err") bytes"
  timeout 60 "$stratum" compare --configs "$tmp/deep.json" 2>"$tmp/err"
  status=$?
  [ "$status" = 2 ] && grep -q "invalid configs = $tmp/deep.json: nests" "$tmp/err" && ok || fail "deep configs: exit $status: $(head -c 300 "$tmp/err")"
  expect_input_refused render "$tmp/in.fifo" -q -o "$tmp/fifo-scene.png"
  expect_input_refused compare --configs "$tmp/in.fifo"
  cat >"$tmp/mesh.json" <<EOF
{"materials": {"m": {"reflectance": [0.5, 0.5, 0.5]}},
 "shapes": [{"type": "mesh", "file": "in.fifo", "material": "m"}]}
EOF
  expect_input_refused render "$tmp/mesh.json" -q -o "$tmp/mesh.png"
  cat >"$tmp/overflow.json" <<EOF
{"materials": {"m": {"reflectance": [0.5, 0.5, 0.5]}},
 "shapes": [{"type": "triangles", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "indices": [[0, 1, 4294967298]], "material": "m"}]}
EOF
  expect_error "invalid shapes\[0\].indices\[0\]\[2\] = 4294967298" render "$tmp/overflow.json" --spp 1 -q -o "$tmp/overflow.png"
fi

finish

#!/usr/bin/env bash
# demo.sh STRATUM OUTDIR: lists the registry, writes 256 points of every
# sampler (2D where it allows, else its smallest d; default randomization;
# seed 1) to OUTDIR/points/NAME.txt, and plots them all in OUTDIR/patterns.png.
set -euo pipefail
stratum=$1 out=$2
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out/points"
"$stratum" samplers | tee "$out/samplers.txt"
"$stratum" samplers --json >"$out/samplers.json"
/usr/bin/python3 -c '
import json, sys
for s in json.load(open(sys.argv[1]))["samplers"]:
    print(s["name"], min(max(2, s["min_dim"]), s["max_dim"]))' "$out/samplers.json" |
while read -r name d; do
  for n in 256 16 4 1; do  # some patterns take only squares or powers of two
    if "$stratum" points --sampler "$name" -n "$n" -d "$d" --seed 1 -o "$out/points/$name.txt" 2>/dev/null; then
      echo "wrote $out/points/$name.txt ($n points, d = $d)"
      break
    fi
  done
done
/usr/bin/python3 "$here/plot_points.py" "$out/points" "$out/patterns.png"

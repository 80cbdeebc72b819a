#!/usr/bin/env bash
# demo.sh STRATUM OUTDIR: lists the registry and writes 256 points of every
# sampler (2D, its default randomization) to OUTDIR/points/NAME.txt.
set -euo pipefail
stratum=$1 out=$2
mkdir -p "$out/points"
"$stratum" samplers | tee "$out/samplers.txt"
"$stratum" samplers --json >"$out/samplers.json"
for name in $(/usr/bin/python3 -c 'import json,sys; [print(s["name"]) for s in json.load(open(sys.argv[1]))["samplers"]]' "$out/samplers.json"); do
  for n in 256 16 4 1; do  # some patterns take only squares or powers of two
    if "$stratum" points --sampler "$name" -n "$n" -d 2 --seed 1 -o "$out/points/$name.txt" 2>/dev/null; then
      echo "wrote $out/points/$name.txt ($n points)"
      break
    fi
  done
done

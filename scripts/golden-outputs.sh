#!/bin/sh
# golden-outputs.sh BINARY OUTDIR: writes every output a change that must not alter results is
# compared on: world and nav for seeds 1-5 at 128 and 256 pixels, eval stereo on the real pairs,
# eval terrain over seeds 1..50, commstime (PAR and SEQ delta) and linktest (one way, both
# ways) with their traces. Compare two folders with scripts/compare-outputs.py.
set -eu
if [ $# -ne 2 ]; then
  echo "usage: sh scripts/golden-outputs.sh BINARY OUTDIR" >&2
  exit 2
fi
binary=$(realpath "$1")
out=$2
pairs="$(dirname "$0")/../../shared/data/stereo/PAIRS.tsv"
rm -rf "$out"
mkdir -p "$out"
for size in 128 256; do
  for seed in 1 2 3 4 5; do
    world="$out/world-$size-$seed"
    echo "world and nav, seed $seed at $size" >&2
    "$binary" world --seed "$seed" --size "$size" --out "$world" --json >"$world.json"
    "$binary" nav "$world/left.pgm" "$world/right.pgm" --scene "$world/scene.json" \
      --out "$out/nav-$size-$seed" --json >"$out/nav-$size-$seed.json"
  done
done
if [ -f "$pairs" ]; then
  "$binary" eval stereo "$pairs" --json >"$out/eval-stereo.json"
else
  echo "golden-outputs: $pairs is absent; eval stereo left out" >&2
fi
"$binary" eval terrain --seeds 1..50 --json >"$out/eval-terrain.json"
for delta in par seq; do
  "$binary" commstime --delta "$delta" --loops 1000 --json \
    --trace "$out/commstime-$delta.trace.json" >"$out/commstime-$delta.json"
done
for mode in oneway both; do
  "$binary" linktest --mode "$mode" --json --trace "$out/linktest-$mode.trace.json" \
    >"$out/linktest-$mode.json"
done

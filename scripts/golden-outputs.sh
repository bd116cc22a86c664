#!/bin/sh
# golden-outputs.sh BINARY OUTDIR: writes every output a change that must not alter results is
# compared on: world and nav for seeds 1-5 at 128 and 256 pixels, eval stereo on the real pairs,
# eval terrain over seeds 1..50, commstime (PAR and SEQ delta) and linktest (one way, both
# ways) with their traces; emulate on both platforms (JSON, products, trace) and its memory
# sweep; fault runs of each kind; reproduce on two scenes; every shipped campaign at fixed runs
# and seeds. Compare two folders with scripts/compare-outputs.py.
set -eu
if [ $# -ne 2 ]; then
  echo "usage: sh scripts/golden-outputs.sh BINARY OUTDIR" >&2
  exit 2
fi
binary=$(realpath "$1")
out=$2
root="$(dirname "$0")/.."
pairs="$root/../shared/data/stereo/PAIRS.tsv"
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
echo "eval terrain, seeds 1..50" >&2
"$binary" eval terrain --seeds 1..50 --json >"$out/eval-terrain.json"
for delta in par seq; do
  "$binary" commstime --delta "$delta" --loops 1000 --json \
    --trace "$out/commstime-$delta.trace.json" >"$out/commstime-$delta.json"
done
for mode in oneway both; do
  "$binary" linktest --mode "$mode" --json --trace "$out/linktest-$mode.trace.json" \
    >"$out/linktest-$mode.json"
done
for platform in pc-card onboard; do
  for seed in 1 2; do
    echo "emulate on $platform, seed $seed" >&2
    folder="$out/emulate-$platform-$seed"
    "$binary" emulate --platform "$platform" --seed "$seed" --out "$folder" \
      --trace "$folder.trace.json" --json >"$folder.json"
  done
done
echo "emulate sweep" >&2
"$binary" emulate --platform onboard --seed 1 --sweep-external-kb 32,64,128,256,1024 \
  --out "$out/emulate-sweep" --json >"$out/emulate-sweep.json"
echo "fault runs" >&2
i=0
for spec in hang:module1@1.05s power:module0@matching+0.5s leak:module1@2s \
  seu:module0@matching+0.2s,buffer=disparity stuck:module1@zones,over=allocated,value=0 \
  link:module0.link0@2s linkbit:module0.link0@1s,dir=out ackloss:module1.link0@1.5s,dir=in; do
  i=$((i + 1))
  "$binary" fault --platform onboard --seed 2 --inject "$spec" --json \
    --trace "$out/fault-$i.trace.json" >"$out/fault-$i.json"
done
"$binary" fault --platform onboard --seed 3 --edac --scrub 5 --link-checksums --terrain-check \
  --inject seu:module0@range+0.1s --inject linkbit:module1.link0@3s --json >"$out/fault-protected.json"
echo "reproduce, seeds 1..2" >&2
"$binary" reproduce --seeds 1..2 --sweep-external-kb 64,256,1024 --out "$out/reproduce" \
  --json >"$out/reproduce.json"
for campaign in "$root"/campaigns/*.toml; do
  name=$(basename "$campaign" .toml)
  echo "campaign $name" >&2
  "$binary" campaign "$campaign" --runs 120 --seeds 2..3 --jobs 2 --out "$out/campaign-$name" \
    --json >"$out/campaign-$name.json"
  "$binary" campaign "$campaign" --seeds 2..3 --replay 7 --out "$out/campaign-$name-replay" \
    --json >"$out/campaign-$name-replay.json"
done

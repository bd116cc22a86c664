#!/bin/sh
# Runs every benchmark executable and keeps its JSON report.
set -eu
build="$1"
out="$2"
mkdir -p "$out"
for bench in "$build"/benches/*_bench; do
  [ -x "$bench" ] || continue
  name=$(basename "$bench")
  echo "== $name"
  "$bench" --benchmark_out="$out/$name.json" --benchmark_out_format=json
done
echo "bench: JSON reports are in $out"

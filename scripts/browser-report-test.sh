#!/bin/sh
# CTest's report.browser: a small run of every command with an output folder, its report, and
# the report checked in headless Chromium (scripts/check-report-in-browser.sh). A broken page is
# checked first and must fail, so that the checks are known to bite.
#
#   sh scripts/browser-report-test.sh MARSOKHOD OUT_DIR
set -eu
marsokhod="$1"
out="$2"
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"
mkdir -p "$out"

cat >"$out/broken.html" <<'PAGE'
<!DOCTYPE html><html><head><title>broken</title></head><body><h2>Summary</h2>
<img src="data:image/png;base64,AAAA"><canvas id="c"></canvas><script>notDefined();</script>
</body></html>
PAGE
if sh "$here/check-report-in-browser.sh" "$out/broken.html" 0 "$out/broken" >"$out/broken.log"; then
  echo "browser-report-test: the check passed a broken page" >&2
  cat "$out/broken.log" >&2
  exit 1
fi

run() { "$marsokhod" "$@" >>"$out/runs.log" 2>&1; }
run world --seed 3 --size 64 --out "$out/world"
run nav "$out/world/left.pgm" "$out/world/right.pgm" --out "$out/nav"
run emulate --platform onboard --seed 3 --size 128 --out "$out/emulate" --trace "$out/emulate/trace.json"
run reproduce --seeds 1 --sweep-external-kb 256,1024 --out "$out/reproduce"
run campaign "$here/../campaigns/hang-power.toml" --runs 8 --seeds 2..2 --out "$out/campaign"
run traverse --rocks 0 --goal-m 8 --size 64 --out "$out/traverse"
run eval traverse --seeds 1..2 --rocks 0,0.05 --goal-m 8 --size 64 --out "$out/sweep"
run eval terrain --seeds 1..2 --size 64 --terrain-size 16 --pictures "$out/terrain"
run fault --platform onboard --inject hang:module0@1s --out "$out/fault"
run report "$out/world" "$out/nav" "$out/emulate" "$out/reproduce" "$out/fault" "$out/campaign" \
  "$out/traverse" "$out/sweep" "$out/terrain" --out "$out/report.html"
sh "$here/check-report-in-browser.sh" "$out/report.html" 9 "$out/browser"

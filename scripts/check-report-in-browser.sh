#!/bin/sh
# Opens a report in headless Chromium with the network off and checks what a person would see:
# no console message at all (a script error, a picture or script that failed to load), every
# chart drew points, every picture decoded, and the expected number of sections (the summary
# and one per folder). Saves a screenshot and the page as the browser built it.
#
#   sh scripts/check-report-in-browser.sh REPORT.html FOLDERS OUT_DIR
#
# Exit 0 when every check holds, 1 when one fails, 2 when it cannot run (no browser).
set -eu
if [ $# -ne 3 ]; then
  echo "usage: sh scripts/check-report-in-browser.sh REPORT.html FOLDERS OUT_DIR" >&2
  exit 2
fi
report="$1" folders="$2" out="$3"
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
  echo "check-report: chromium is not installed (make test installs it)" >&2
  exit 2
fi
if [ ! -f "$report" ]; then
  echo "check-report: $report: no such file" >&2
  exit 2
fi
mkdir -p "$out"
url="file://$(cd "$(dirname "$report")" && pwd)/$(basename "$report")"

# Every request leaves through a proxy that is not there and every name resolves to nothing:
# a page that fetched anything would log the failure.
open_page() {
  set -- --headless --disable-gpu --disable-dev-shm-usage --no-first-run --no-default-browser-check \
    --user-data-dir="$out/profile" --proxy-server=127.0.0.1:9 \
    --host-resolver-rules="MAP * ~NOTFOUND" --virtual-time-budget=10000 "$@"
  if [ "$(id -u)" -eq 0 ]; then
    set -- --no-sandbox "$@"
  fi
  timeout 120 "$browser" "$@"
}
open_page --enable-logging=stderr --v=0 --dump-dom "$url" >"$out/dom.html" 2>"$out/browser.log"
open_page --window-size=1400,3000 --screenshot="$out/report.png" "$url" >/dev/null 2>&1 || true

count() { grep -o "$1" "$out/dom.html" | wc -l; }
failed=0
check() {
  if [ "$2" = "$3" ]; then
    echo "check-report: $1: $2"
  else
    echo "check-report: FAILED $1: $2, expected $3"
    failed=1
  fi
}
console=$(grep -c -E "CONSOLE|Uncaught" "$out/browser.log" || true)
check "console messages" "$console" 0
check "sections" "$(count '<h2>')" "$((folders + 1))"
canvases=$(count '<canvas ')
check "charts with points drawn" "$(count 'data-points="[1-9]')" "$canvases"
images=$(count '<img ')
check "pictures decoded" "$(count 'data-loaded="yes"')" "$images"
if [ "$canvases" -eq 0 ] && [ "$images" -eq 0 ]; then
  echo "check-report: FAILED the page holds no chart and no picture"
  failed=1
fi
if [ "$console" != 0 ]; then
  grep -E "CONSOLE|Uncaught" "$out/browser.log" | head -5
fi
load_ms=$(grep -o 'data-load-ms="[0-9]*"' "$out/dom.html" | grep -o '[0-9]*' || true)
echo "check-report: load event after ${load_ms:-?} ms"
echo "check-report: screenshot $out/report.png, page $out/dom.html"
exit "$failed"

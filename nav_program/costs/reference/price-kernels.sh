#!/bin/sh
# Prices every reference kernel in this folder with the occam-probe kit (the INMOS occam 2
# compiler inside the t4 emulator): the loop alone (`probe.sh -b`), in cycles per unit of its
# nav::Work kind. Writes the kit's figures as TOML (default: measured.toml beside this script),
# which tests/nav_program/costs/work_costs_probe_test.cpp compares with the cost table.
#
#   nav_program/costs/reference/price-kernels.sh [-k KIT_DIR] [-B BUILD_DIR] [-o OUT.toml]
#
# KIT_DIR: the kit (default $OCCAM_PROBE_KIT, else ../shared/tools/occam-probe beside the
# project); BUILD_DIR: its build (default $OCCAM_PROBE_BUILD, else $HOME/.cache/occam-probe;
# the kit's setup.sh makes it). Without the kit or its build it says so and exits 0.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
kit=${OCCAM_PROBE_KIT:-$root/../shared/tools/occam-probe}
build=${OCCAM_PROBE_BUILD:-$HOME/.cache/occam-probe}
out=$here/measured.toml
while getopts k:B:o: opt; do
  case $opt in
    k) kit=$OPTARG ;;
    B) build=$OPTARG ;;
    o) out=$OPTARG ;;
    *) echo "usage: $0 [-k KIT_DIR] [-B BUILD_DIR] [-o OUT.toml]" >&2; exit 2 ;;
  esac
done
if [ ! -x "$kit/probe.sh" ]; then
  echo "price-kernels: skipping: no occam-probe kit at $kit (give -k or OCCAM_PROBE_KIT)"
  exit 0
fi
if [ ! -f "$build/env.sh" ]; then
  echo "price-kernels: skipping: the kit is not built in $build (run $kit/setup.sh, or give -B)"
  exit 0
fi
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
{
  echo "# The occam-probe kit's figures for the reference kernels: oc 2.01.01, HALT mode, range"
  echo "# checks on, the measured loop alone (probe.sh -b), kit cycle model (FPU serial, bitcnt 2)."
  echo "# Written by nav_program/costs/reference/price-kernels.sh; do not edit by hand."
} > "$tmp"
for kernel in "$here"/*.occ; do
  kind=$(sed -n 's/^-- work-kind: *//p' "$kernel" | head -n 1)
  [ -n "$kind" ] || { echo "price-kernels: $kernel has no '-- work-kind:' line" >&2; exit 1; }
  printf 'price-kernels: %s ...' "$kind" >&2
  result=$("$kit/probe.sh" -B "$build" -b "$kernel" 2>&1 | grep '^RESULT .* region ') || {
    echo " failed: run $kit/probe.sh -B $build -b $kernel to see why" >&2
    exit 1
  }
  field() { echo "$result" | tr ' ' '\n' | sed -n "s/^$1=//p"; }
  echo " $(field cycles_per_unit) cycles a unit" >&2
  {
    echo ""
    echo "[$kind]"
    echo "kernel = \"$(basename "$kernel")\""
    echo "units = $(field units)"
    echo "instructions_per_unit = $(field instr_per_unit)"
    echo "cycles_per_unit = $(field cycles_per_unit)"
    echo "cycles_per_unit_e3 = $(field E3)"
  } >> "$tmp"
done
mv "$tmp" "$out"
trap - EXIT
echo "price-kernels: wrote $out"

#!/bin/sh
# Installs every Debian package the build, the tests and the benchmarks need, and nothing that
# is already there. Runs apt-get as root, through sudo otherwise.
set -eu

packages="g++ cmake ninja-build pkgconf libboost-context-dev libeigen3-dev libfmt-dev libgtest-dev
libbenchmark-dev libcli11-dev libtomlplusplus-dev nlohmann-json3-dev libpng-dev clang-format
libjs-chart.js chromium libplplot-dev plplot-driver-cairo fonts-dejavu-core"

missing=""
for package in $packages; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing="$missing $package"
  fi
done

if [ -z "$missing" ]; then
  echo "setup: all build dependencies are installed"
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
  as_root=""
elif command -v sudo >/dev/null 2>&1; then
  as_root="sudo"
else
  echo "setup: missing packages:$missing" >&2
  echo "setup: not root and no sudo; install them as root and run make again" >&2
  exit 1
fi

echo "setup: installing$missing"
export DEBIAN_FRONTEND=noninteractive
$as_root apt-get update -qq
# shellcheck disable=SC2086
$as_root apt-get install -y -qq --no-install-recommends $missing

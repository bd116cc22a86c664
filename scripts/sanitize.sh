#!/bin/sh
# `make sanitize`: builds with AddressSanitizer and UBSan (preset `sanitize`, folder
# build/sanitize) the tests of the layers where fibers, raw memory and file parsing live, and
# runs them: the io layer every reader goes through, the emulator, the occam layer, the overswitch
# (whose failover kills and restarts processes), and the image readers and codecs. The
# image-processing, world and command tests are left out: under the sanitizers they would take
# most of CI's 20-minute budget (building them means building every layer) and exercise no
# fiber switch. The reader mutation test (docs/testing.md) runs too: it needs every reader's
# layer, but it is where hostile file input is checked. `sh scripts/sanitize.sh all` builds and
# runs the whole suite instead.
set -eu

scope="${1:-layers}"
build="build/sanitize"

cmake --preset sanitize >/dev/null

if [ "$scope" = "all" ]; then
  cmake --build --preset sanitize
  ctest --preset sanitize
  exit 0
fi

# Test executables are named <folder>_<file stem> (tests/CMakeLists.txt).
targets=$(ninja -C "$build" -t targets all | sed -n 's/^\([a-z_0-9]*_test\): .*/\1/p' |
  grep -E '^(io_|emulator_|occam_port_|overswitch_|imaging_(image|image_io|image_mutation|png_codec|pnm_codec|pfm_codec)_test$|fuzz_reader_mutation_test$)' |
  sort -u)
if [ -z "$targets" ]; then
  echo "sanitize: no test targets found in $build" >&2
  exit 1
fi
# shellcheck disable=SC2086 # one target per word
cmake --build --preset sanitize --target $targets

ctest --preset sanitize --no-tests=error -L '^(io|emulator|occam_port|overswitch)$'
# gtest suites of the image readers and codecs.
ctest --preset sanitize --no-tests=error -L '^imaging$' \
  -R '^(Image(View|Mutation|Read|RoundTrip|Write)?|Read(Gray8|Pfm)|Png[A-Za-z]*|Pnm[A-Za-z]*|Pfm[A-Za-z]*)\.'
# Every file reader on seeded mutations of its valid files (tests/fuzz/reader_mutation_test.cpp).
ctest --preset sanitize --no-tests=error -L '^fuzz$' -R '^Registry/ReaderMutation\.'

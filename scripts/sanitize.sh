#!/bin/sh
# `make sanitize`: builds with AddressSanitizer and UBSan (preset `sanitize`, folder
# build/sanitize) the tests of the layers where fibers, raw memory and file parsing live, and
# runs them: the io layer every reader goes through, the emulator, the occam layer, the
# navigation program on the emulated nodes, the overswitch (whose failover kills and restarts
# processes), and the imaging layer's readers, codecs and rig files. The world, navigation,
# evaluation and command tests are left out: under the sanitizers they would take most of CI's
# budget and exercise no fiber switch. The reader mutation test (docs/testing.md) runs too: it
# needs every reader's layer, but it is where hostile file input is checked.
# `sh scripts/sanitize.sh all` builds and runs the whole suite instead.
set -eu

scope="${1:-layers}"

# Leaks in third-party caches that live as long as the process (scripts/lsan-suppressions.txt).
LSAN_OPTIONS="suppressions=$(cd "$(dirname "$0")" && pwd)/lsan-suppressions.txt${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
export LSAN_OPTIONS

cmake --preset sanitize >/dev/null

if [ "$scope" = "all" ]; then
  cmake --build --preset sanitize
  ctest --preset sanitize
  exit 0
fi

# Test executables are named <layer>_tests (tests/CMakeLists.txt).
cmake --build --preset sanitize --target io_tests imaging_tests emulator_tests occam_port_tests \
  nav_program_tests overswitch_tests fuzz_reader_mutation_test

# The world-scene cycles (nav_program_tests, Seeds1To20/WorldSceneCycle) are left out: forty
# rendered sites, whose renderer is world's, and the same cycle NavigationProgram runs here.
ctest --preset sanitize --no-tests=error -L '^(io|imaging|emulator|occam_port|nav_program|overswitch)$' \
  -E '^Seeds1To20/WorldSceneCycle\.'
# Every file reader on seeded mutations of its valid files (tests/fuzz/reader_mutation_test.cpp).
ctest --preset sanitize --no-tests=error -L '^fuzz$' -R '^Registry/ReaderMutation\.'

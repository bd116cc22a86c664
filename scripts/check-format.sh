#!/bin/sh
# `make format-check`: every C++ file of the tree formatted as .clang-format says, checked with
# clang-format's dry run (no file is changed). `make format` rewrites them.
set -eu
cd "$(dirname "$0")/.."

if ! command -v clang-format >/dev/null 2>&1; then
  echo "format-check: clang-format is not installed (sh scripts/setup.sh installs it)" >&2
  exit 1
fi
files=$(git ls-files '*.cpp' '*.hpp')
count=$(echo "$files" | wc -l)
# shellcheck disable=SC2086 # one file per word
if ! clang-format --dry-run -Werror $files; then
  echo "format-check: the files above differ from .clang-format; run 'make format'" >&2
  exit 1
fi
echo "format-check: $count files formatted ($(clang-format --version))"

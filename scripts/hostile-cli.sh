#!/bin/sh
# Runs the real command line on mutated input files of every reader and on fixed hostile files
# (a FIFO without a writer, /dev/zero, a folder, a 3 GB sparse file, an unreadable file), each
# under `ulimit -v 4000000` and `timeout 10`. A run is bad when it times out (124), dies by a
# signal (>= 128), exits other than 0/1/2, or exits 1/2 with a message not naming the file or
# with a library's internal message ("[json.exception...", "basic_filebuf::...", "std::...").
# Prints per reader the runs, exit 0/1/2 counts and bad runs; writes OUT/summary.json and
# OUT/bad.txt (command, status, first message line). Exit status 1 when any run was bad.
#
#   sh scripts/hostile-cli.sh [--count N] [--seed S] [--out DIR] [--binary MARSOKHOD]
#                             [--tool READER_CORPUS]
# Mutants come from reader_corpus (tests/fuzz), the engine of the mutation test: the same seed
# gives the same files. docs/testing.md tells how to replay a bad run.
set -u

count=40
seed=1
out=build/release/hostile-cli
binary=build/release/apps/marsokhod
tool=build/release/tests/fuzz/reader_corpus
while [ $# -gt 0 ]; do
  case "$1" in
  --count) count="$2"; shift 2 ;;
  --seed) seed="$2"; shift 2 ;;
  --out) out="$2"; shift 2 ;;
  --binary) binary="$2"; shift 2 ;;
  --tool) tool="$2"; shift 2 ;;
  -h | --help) sed -n '2,13p' "$0"; exit 0 ;;
  *) echo "hostile-cli: unknown option '$1' (try --help)" >&2; exit 2 ;;
  esac
done
for program in "$binary" "$tool"; do
  if [ ! -x "$program" ]; then
    echo "hostile-cli: $program is not built (cmake --build build/release --target marsokhod reader_corpus)" >&2
    exit 2
  fi
done

rm -rf "$out"
mkdir -p "$out/base" "$out/runs"
out=$(cd "$out" && pwd)
# A valid 128 x 128 pair and its scene.json: the files a mutated file is used beside.
if ! "$binary" world --out "$out/base" --size 128 --seed 1 >"$out/base/world.log" 2>&1; then
  echo "hostile-cli: marsokhod world failed (see $out/base/world.log)" >&2
  exit 2
fi
left="$out/base/left.pgm"
right="$out/base/right.pgm"
number=0
# Pieces of library messages that must not reach a user (as in tests/fuzz/reader_verdict.cpp).
internal='\[json\.exception|basic_string|basic_filebuf|vector::|map::at|std::|filesystem error|iostream error|bad_optional|bad_variant'

# run N READER FILE NAMED: the reader's command on FILE in run folder N; the message must
# contain NAMED. The outcome goes to runs/N/result ("reader status") and runs/N/bad, so that
# runs can go in parallel; the tally reads them at the end.
run() {
  number="$1" reader="$2" file="$3" named="$4"
  dir="$out/runs/$number"
  mkdir -p "$dir"
  case "$reader" in
  platform | processor) set -- commstime --platform "$file" --loops 10 ;;
  rig) if [ $((number % 2)) -eq 0 ]; then set -- rig --rig "$file"; else set -- nav "$left" "$right" --rig "$file" --out "$dir"; fi ;;
  scene) set -- nav "$left" "$right" --scene "$file" --out "$dir" ;;
  calibration) set -- nav "$left" "$right" --calibration "$file" --out "$dir" ;;
  pairs) set -- eval stereo "$file" --out "$dir" ;;
  image) set -- image info "$file" ;;
  gray8) set -- nav "$file" "$file" --out "$dir" ;;
  pfm) set -- nav "$left" "$right" --disparity "$file" --out "$dir" ;;
  # 4 MB modules: a placement that stays valid runs its cycle to the end (exit 0) rather than
  # into a memory fault whose message need not name the file.
  placement) set -- emulate --platform onboard --external-kb 4096 --placement "$file" --out "$dir" ;;
  # One scene and one run: the file is read whole, and a campaign that stays valid ends in time.
  # A traverse reads the same file for its faults (--faults), on every other run.
  campaign) if [ $((number % 2)) -eq 0 ]; then set -- campaign "$file" --runs 1 --seeds 2..2 --out "$dir"; else set -- traverse --platform onboard --faults "$file" --max-cycles 1 --goal-m 5 --size 64 --out "$dir"; fi ;;
  *) echo "hostile-cli: no command for reader $reader" >&2; return ;;
  esac
  (ulimit -v 4000000 && exec timeout 10 "$binary" "$@") >"$dir/stdout" 2>"$dir/stderr" </dev/null
  status=$?
  bad=""
  if [ "$status" -eq 124 ]; then
    bad="timed out"
  elif [ "$status" -ge 128 ]; then
    bad="killed by signal $((status - 128))"
  elif [ "$status" -gt 2 ]; then
    bad="exit status $status"
  elif [ "$status" -ne 0 ] && ! grep -qF -- "$named" "$dir/stderr"; then
    bad="message does not name $named"
  elif [ "$status" -ne 0 ] && grep -qE "$internal" "$dir/stderr"; then
    bad="internal message"
  fi
  echo "$reader $status" >"$dir/result"
  if [ -n "$bad" ]; then
    {
      echo "[$reader] $bad: marsokhod $*"
      echo "    $(head -c 300 "$dir/stderr" | head -n 1)"
    } >"$dir/bad"
  fi
}

readers=$("$tool" list | cut -d' ' -f1)
for reader in $readers; do
  name=$("$tool" list | awk -v r="$reader" '$1 == r { print $2 }')
  "$tool" mutate "$reader" "$count" "$seed" "$out/mutants/$reader" || exit 2
  i=0
  while [ "$i" -lt "$count" ]; do
    folder="$out/mutants/$reader/$i/$reader"
    file="$folder/$name"
    # A mutated processor file is reached through the platform file beside it.
    [ "$reader" = processor ] && file="$folder/platform.toml"
    number=$((number + 1))
    run "$number" "$reader" "$file" "$folder/"
    i=$((i + 1))
  done
done

# Fixed hostile files. A processor file is reached through a platform file naming it.
hostile="$out/hostile"
mkdir -p "$hostile/folder"
mkfifo "$hostile/fifo"
truncate -s 3G "$hostile/sparse"
printf 'x = 1\n' >"$hostile/unreadable"
chmod 000 "$hostile/unreadable"
# fixed CASE PARALLEL FIRST: that case for every reader in run folders FIRST, FIRST+1, ..., at
# most PARALLEL at a time: FIFO, /dev/zero and folder runs may wait for their timeout, so they
# all go together; a run reading the 3 GB file takes 3 GB of memory, so three at a time.
fixed() {
  case_path="$1" parallel="$2" number="$3" running=0
  for reader in $readers; do
    file="$case_path"
    if [ "$reader" = processor ]; then
      file="$hostile/platform-$number.toml"
      sed "s|^processor = .*|processor = \"$case_path\"|" "$out/mutants/processor/0/processor/platform.toml" >"$file"
    fi
    run "$number" "$reader" "$file" "$case_path" &
    number=$((number + 1)) running=$((running + 1))
    if [ "$running" -ge "$parallel" ]; then
      wait
      running=0
    fi
  done
  wait
}
fixed "$hostile/fifo" 100 100000 &
fixed /dev/zero 100 200000 &
fixed "$hostile/folder" 100 300000 &
wait
fixed "$hostile/sparse" 3 400000
if [ "$(id -u)" -eq 0 ]; then
  echo "hostile-cli: skipped the unreadable-file case of every reader: running as root, permissions do not bite"
else
  fixed "$hostile/unreadable" 100 500000
fi
chmod 600 "$hostile/unreadable"
rm -f "$hostile/sparse"

cat "$out"/runs/*/bad >"$out/bad.txt" 2>/dev/null
total_bad=0
printf '%-12s %6s %6s %6s %6s %6s %6s\n' reader runs exit0 exit1 exit2 other bad >"$out/table.txt"
{
  printf '{\n  "count": %s,\n  "seed": %s,\n  "readers": {' "$count" "$seed"
  separator=""
  for reader in $readers; do
    counts=$(cat "$out"/runs/*/result | awk -v r="$reader" '$1 == r { n++; if ($2 <= 2) e[$2]++; else o++ }
      END { printf "%d %d %d %d %d", n, e[0], e[1], e[2], o }')
    b=$(grep -c "^\[$reader\]" "$out/bad.txt")
    set -- $counts
    printf '%-12s %6s %6s %6s %6s %6s %6s\n' "$reader" "$1" "$2" "$3" "$4" "$5" "$b" >>"$out/table.txt"
    printf '%s\n    "%s": {"runs": %s, "exit0": %s, "exit1": %s, "exit2": %s, "other": %s, "bad": %s}' \
      "$separator" "$reader" "$1" "$2" "$3" "$4" "$5" "$b"
    separator=","
    total_bad=$((total_bad + b))
  done
  printf '\n  },\n  "bad": %s\n}\n' "$total_bad"
} >"$out/summary.json"
cat "$out/table.txt"
echo "summary: $out/summary.json; bad runs: $out/bad.txt"
if [ "$(wc -l <"$out/bad.txt")" -gt 0 ]; then
  head -n 40 "$out/bad.txt"
  exit 1
fi

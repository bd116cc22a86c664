#!/usr/bin/env python3
"""compare-outputs.py A B: the folders of scripts/golden-outputs.sh, file by file and byte for
byte. In the JSON summaries (not the traces) the host's timings (a command's own "seconds", keys in
milliseconds, wall or host time, runs per minute) are set aside; emulated and model seconds are
compared, and each folder's own path is replaced by ROOT.
Exits 1 when a file differs or is missing."""
import json
import os
import re
import sys

TIMING = re.compile(r"^seconds$|seconds_per_seed$|_ms$|_ms_|^ms|elapsed|wall|^host_|runs_per_minute")


def normalised(path, root):
    data = open(path, "rb").read().replace(os.path.abspath(root).encode(), b"ROOT")
    if path.endswith(".md"):
        return re.sub(rb"[0-9.]+ runs per minute", b"N runs per minute", data)
    if not path.endswith(".json") or "trace" in os.path.basename(path):
        return data

    def strip(value):
        if isinstance(value, dict):
            return {k: strip(v) for k, v in value.items() if not TIMING.search(k)}
        if isinstance(value, list):
            return [strip(v) for v in value]
        return value

    return json.dumps(strip(json.loads(data)), sort_keys=True).encode()


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: compare-outputs.py A B")
    first, second = sys.argv[1], sys.argv[2]
    compared = differ = 0
    for folder, _, files in os.walk(first):
        for name in sorted(files):
            a = os.path.join(folder, name)
            b = os.path.join(second, os.path.relpath(a, first))
            compared += 1
            if not os.path.exists(b) or normalised(a, first) != normalised(b, second):
                print("DIFF", os.path.relpath(a, first))
                differ += 1
    print(f"{compared} files compared, {differ} differ")
    sys.exit(1 if differ else 0)


main()

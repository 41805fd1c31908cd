#!/bin/sh
# The demo's time against process start-up (issue 40, "a quick demo"): times `shapevo --version`
# (start-up alone: loading the program and its libraries, then exit) and the README's demo,
# `shapevo run configs/spaceship.toml` (a fresh output folder each time, its progress lines to
# /dev/null), alternately, ROUNDS rounds (A B A B ...), after one warm-up round of each; prints
# each one's median and min-max wall time and the ratio of the medians. With OLD, the rounds
# also time OLD's two (A B A' B' ...), so a change is measured side by side in one run.
#
#   experiments/demo_startup.sh [BIN [ROUNDS [OLD]]]     (default build/shapevo, 15 rounds)
#
# Run from anywhere; needs python3 (standard library) for the clock.
set -eu
cd "$(dirname "$0")/.."
bin=${1:-build/shapevo}
rounds=${2:-15}
old=${3:-}
exec python3 - "$bin" "$rounds" "$old" <<'PY'
import os, shutil, statistics, subprocess, sys, tempfile, time

binary, rounds, old = sys.argv[1], int(sys.argv[2]), sys.argv[3]
sides = [("", binary)] + ([("old ", old)] if old else [])
work = tempfile.mkdtemp(prefix="demo_startup.")
out = os.path.join(work, "run")


def timed(words):
    shutil.rmtree(out, ignore_errors=True)  # not timed
    start = time.perf_counter()
    subprocess.run(words, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


cases = []
for prefix, b in sides:
    cases.append((prefix + "start-up (--version)", [b, "--version"]))
    cases.append((prefix + "demo (run configs/spaceship.toml)", [b, "run", "configs/spaceship.toml", "--out", out]))
seconds = {name: [] for name, _ in cases}
try:
    for name, words in cases:  # warm-up: page cache, font cache
        timed(words)
    for _ in range(rounds):
        for name, words in cases:
            seconds[name].append(timed(words))
finally:
    shutil.rmtree(work, ignore_errors=True)
print(f"{rounds} rounds, alternating; wall seconds of the whole process")
for name, s in seconds.items():
    print(f"  {name:45s} median {statistics.median(s):.3f}  (min {min(s):.3f}, max {max(s):.3f})")
for prefix, _ in sides:
    demo = statistics.median(seconds[prefix + "demo (run configs/spaceship.toml)"])
    start = statistics.median(seconds[prefix + "start-up (--version)"])
    print(f"  {prefix}ratio demo / start-up (medians): {demo / start:.2f}")
PY

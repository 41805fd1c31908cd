#!/usr/bin/python3
"""Wall time of a whole shapevo process, for docs/performance.md's "The demo, whole process":
runs a command N times (a fresh --out folder each time) and prints the median, min and max.

Usage (from the repository root):

    experiments/time_demo.py [--runs 20] [--bin build/shapevo] [-- ARGS...]

Without ARGS it times `run configs/spaceship.toml -q --out DIR` and `--version` (process start-up).
Standard library only.
"""
import argparse
import os
import shutil
import statistics
import subprocess
import tempfile
import time


def time_runs(words, runs, out=None):
    seconds = []
    for _ in range(runs):
        if out:
            shutil.rmtree(out, ignore_errors=True)
        start = time.perf_counter()
        subprocess.run(words, check=True, stdout=subprocess.DEVNULL)
        seconds.append(time.perf_counter() - start)
    return seconds


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=20)
    ap.add_argument("--bin", default="build/shapevo")
    ap.add_argument("args", nargs="*")
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "run")
        cases = [("run " + " ".join(a.args), [a.bin] + a.args, None)] if a.args else [
            ("run configs/spaceship.toml", [a.bin, "run", "configs/spaceship.toml", "-q", "--out", out], out),
            ("--version", [a.bin, "--version"], None)]
        for name, words, folder in cases:
            time_runs(words, 2, folder)  # warm the page cache
            s = time_runs(words, a.runs, folder)
            print(f"{name}: median {statistics.median(s):.3f} s (min {min(s):.3f}, max {max(s):.3f}), {a.runs} runs")


if __name__ == "__main__":
    main()

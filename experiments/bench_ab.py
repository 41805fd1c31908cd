#!/usr/bin/env python3
"""Compare two builds' Google Benchmark programs side by side, A B A B, in one run.

Usage (from the repository root):

    python3 experiments/bench_ab.py OLD_BUILD NEW_BUILD [--rounds 3] [--min-time 0.2]
                                   [--programs bench_derive,bench_score,...] [--filter REGEX] [--cpu N]

For every program in bench/ that both builds have, runs OLD then NEW, `--rounds` times in turn
(so drift on a shared machine hits both), each with --benchmark_format=json, and prints one
Markdown row per benchmark: the median CPU time of OLD and NEW over the rounds, their min–max,
and NEW / OLD. The exit code is 0 whatever the numbers: read the table. Standard library only.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys


def run(cmd, args):
    out = subprocess.run(cmd + ["--benchmark_format=json"] + args, check=True, capture_output=True, text=True).stdout
    times = {}
    for b in json.loads(out)["benchmarks"]:
        if b.get("run_type", "iteration") != "iteration" or b.get("error_occurred"):
            continue
        times[b["name"]] = (b["cpu_time"], b["time_unit"])
    return times


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--min-time", default="0.2")
    ap.add_argument("--programs", default="")
    ap.add_argument("--filter", default="")
    ap.add_argument("--cpu", default="")
    a = ap.parse_args()
    names = a.programs.split(",") if a.programs else sorted(
        n for n in os.listdir(os.path.join(a.new, "bench")) if n.startswith("bench_") and "." not in n)
    print("| benchmark | old (median, min–max) | new (median, min–max) | new / old |")
    print("| --- | ---: | ---: | ---: |")
    for prog in names:
        paths = [os.path.join(d, "bench", prog) for d in (a.old, a.new)]
        if not all(os.path.exists(p) for p in paths):
            continue
        args = ["--benchmark_min_time=" + a.min_time]
        if a.filter:
            args.append("--benchmark_filter=" + a.filter)
        samples = [{}, {}]
        for _ in range(a.rounds):
            for side, path in enumerate(paths):
                cmd = (["taskset", "-c", a.cpu] if a.cpu else []) + [path]
                for name, t in run(cmd, args).items():
                    samples[side].setdefault(name, []).append(t)
        for name in samples[1]:
            if name not in samples[0]:
                continue
            unit = samples[1][name][0][1]
            old = [t for t, _ in samples[0][name]]
            new = [t for t, _ in samples[1][name]]
            mo, mn = statistics.median(old), statistics.median(new)
            print(f"| `{prog}` {name} | {mo:.4g} {unit} ({min(old):.4g}–{max(old):.4g}) | "
                  f"{mn:.4g} {unit} ({min(new):.4g}–{max(new):.4g}) | {mn / mo:.3f} |")
        sys.stdout.flush()


if __name__ == "__main__":
    main()

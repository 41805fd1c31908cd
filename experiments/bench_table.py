#!/usr/bin/env python3
"""Run shapevo's Google Benchmark programs and print one Markdown table.

Usage (from the repository root, after `cd build && ninja`):

    python3 experiments/bench_table.py [BUILD_DIR] [--cpu N] [--min-time S] [--repetitions N] [--filter REGEX]

BUILD_DIR defaults to build/. Each of bench_derive, bench_score, bench_operators and
bench_generation is run with --benchmark_format=json (pinned with `taskset -c N` if --cpu is
given; bench_generation is never pinned, since it compares 1 and 2 evaluator threads); the table shows wall and CPU time per iteration and the key counters in human units. With
--repetitions N each benchmark runs N times and the table shows the medians plus the coefficient
of variation of the wall time (useful on noisy virtual machines).
Standard library only.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

PROGRAMS = ["bench_derive", "bench_score", "bench_operators", "bench_generation"]
# Counters with their own column; any other user counter goes to "other".
KEY_COUNTERS = ["items_per_second", "evals/s", "voxel_rows/s", "grid_rows/s", "primitives/s"]
HEADERS = ["items/s", "evals/s", "rasterized rows/s", "grid rows/s", "primitives/s"]
STANDARD_FIELDS = {
    "name", "family_index", "per_family_instance_index", "run_name", "run_type", "repetitions",
    "repetition_index", "threads", "iterations", "real_time", "cpu_time", "time_unit", "label",
    "aggregate_name", "aggregate_unit", "error_occurred", "error_message", "bytes_per_second",
}
NS_PER_UNIT = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}


def human(value):
    """3 significant digits with k, M, G, T suffixes."""
    if value is None:
        return ""
    v = float(value)
    for suffix, scale in (("T", 1e12), ("G", 1e9), ("M", 1e6), ("k", 1e3)):
        if abs(v) >= scale:
            return f"{v / scale:.3g} {suffix}"
    return f"{v:.3g}"


def human_time(value, unit):
    ns = float(value) * NS_PER_UNIT.get(unit, 1.0)
    for suffix, scale in (("s", 1e9), ("ms", 1e6), ("µs", 1e3)):
        if ns >= scale:
            return f"{ns / scale:.3g} {suffix}"
    return f"{ns:.3g} ns"


def run(path, args, pin):
    cmd = [path, "--benchmark_format=json"]
    if args.min_time is not None:
        cmd.append(f"--benchmark_min_time={args.min_time}")
    if args.repetitions and args.repetitions > 1:
        cmd += [f"--benchmark_repetitions={args.repetitions}", "--benchmark_report_aggregates_only=true"]
    if args.filter:
        cmd.append(f"--benchmark_filter={args.filter}")
    if pin and args.cpu is not None:
        if not shutil.which("taskset"):
            sys.exit("bench_table: --cpu needs taskset (util-linux)")
        cmd = ["taskset", "-c", str(args.cpu)] + cmd
    print(f"running: {' '.join(cmd)}", file=sys.stderr, flush=True)
    done = subprocess.run(cmd, stdout=subprocess.PIPE, text=True)
    if done.returncode != 0:
        sys.exit(f"bench_table: {path} exited with status {done.returncode}")
    return json.loads(done.stdout)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("build_dir", nargs="?", default="build", help="CMake build directory (default: build)")
    parser.add_argument("--cpu", type=int, help="pin the single-threaded programs to this CPU with taskset -c")
    parser.add_argument("--min-time", help="passed as --benchmark_min_time (seconds)")
    parser.add_argument("--repetitions", type=int, help="repeat each benchmark N times; report medians and CV")
    parser.add_argument("--filter", help="passed as --benchmark_filter (regex)")
    args = parser.parse_args()

    results = []
    for name in PROGRAMS:
        path = os.path.join(args.build_dir, "bench", name)
        if not os.access(path, os.X_OK):
            sys.exit(f"bench_table: {path} not found or not executable (build with: cd {args.build_dir} && ninja)")
        results.append((name, run(path, args, pin=name != "bench_generation")))

    ctx = results[0][1].get("context", {})
    load = ", ".join(f"{x:.2f}" for x in ctx.get("load_avg", []))
    print(f"{ctx.get('host_name', '?')}: {ctx.get('num_cpus', '?')} CPUs at {ctx.get('mhz_per_cpu', '?')} MHz, "
          f"load average {load or '?'}, libbenchmark built as {ctx.get('library_build_type', '?')}"
          + (f", single-threaded programs pinned to CPU {args.cpu}" if args.cpu is not None else ""))
    print()
    print("| program | benchmark | time/iter (wall) | CPU/iter | " + " | ".join(HEADERS) + " | other |")
    print("|---|---|---:|---:|" + "---:|" * len(HEADERS) + "---|")
    for program, data in results:
        rows = data.get("benchmarks", [])
        cv = {b["run_name"]: b["real_time"] for b in rows if b.get("aggregate_name") == "cv"}
        if any(b.get("run_type") == "aggregate" for b in rows):
            rows = [b for b in rows if b.get("aggregate_name") == "median"]
        for b in rows:
            if b.get("error_occurred"):
                print(f"| {program} | {b['name']} | error: {b.get('error_message', '')} |")
                continue
            unit = b.get("time_unit", "ns")
            cols = [human(b.get(k)) + ("/s" if b.get(k) is not None else "") for k in KEY_COUNTERS]
            other = [f"{k}={human(v)}" for k, v in b.items()
                     if k not in STANDARD_FIELDS and k not in KEY_COUNTERS and isinstance(v, (int, float))]
            if b.get("run_name") in cv:
                other.insert(0, f"cv {100 * cv[b['run_name']]:.1f}%")
            if b.get("label"):
                other.append(b["label"])
            name = b.get("run_name", b["name"]) + (" (median)" if b.get("aggregate_name") == "median" else "")
            print(f"| {program} | {name} | {human_time(b['real_time'], unit)} | {human_time(b['cpu_time'], unit)} | "
                  + " | ".join(cols) + " | " + "; ".join(other) + " |")


if __name__ == "__main__":
    main()

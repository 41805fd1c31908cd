#!/usr/bin/env python3
"""Run bench_lists (the PCGR list operations, bench/bench_lists.cpp) and print a Markdown table:
per benchmark the median wall time per call and the min-max over the repetitions, with its
counters. Repetitions are interleaved at random across benchmarks (A B A B ...), so the tree and
the every-box ray casts are measured side by side.

Usage (from the repository root, after `ninja -C build bench_lists`):

    python3 experiments/list_operations_bench.py [BUILD_DIR] [--repetitions N]

Runs: BUILD_DIR/bench/bench_lists --benchmark_repetitions=N --benchmark_report_aggregates_only=true
      --benchmark_enable_random_interleaving=true --benchmark_format=json
Standard library only.
"""
import argparse
import json
import subprocess
import sys


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("build", nargs="?", default="build")
    parser.add_argument("--repetitions", type=int, default=5)
    args = parser.parse_args()
    command = [f"{args.build}/bench/bench_lists", f"--benchmark_repetitions={args.repetitions}",
               "--benchmark_report_aggregates_only=true", "--benchmark_enable_random_interleaving=true",
               "--benchmark_format=json"]
    result = json.loads(subprocess.run(command, check=True, capture_output=True, text=True).stdout)
    rows = {}
    for b in result["benchmarks"]:
        if b.get("run_type") != "aggregate":
            continue
        row = rows.setdefault(b["run_name"], {"counters": {}})
        row[b["aggregate_name"]] = b["real_time"]
        row["unit"] = b["time_unit"]
        if b["aggregate_name"] == "median":
            skip = {"name", "family_index", "per_family_instance_index", "run_name", "run_type", "repetitions",
                    "repetition_index", "threads", "iterations", "real_time", "cpu_time", "time_unit",
                    "aggregate_name", "aggregate_unit"}
            row["counters"] = {k: v for k, v in b.items() if k not in skip and isinstance(v, (int, float))}
    print(f"| benchmark | median ({next(iter(rows.values()))['unit']}) | min - max | counters |")
    print("|---|---:|---|---|")
    for name, row in rows.items():
        counters = ", ".join(f"{k} {v:g}" for k, v in row["counters"].items())
        print(f"| {name} | {row['median']:.1f} | {row['min']:.1f} - {row['max']:.1f} | {counters} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())

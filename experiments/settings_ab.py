#!/usr/bin/env python3
"""Settings side by side: one scene, the same seeds, runs that differ only in `--set` values.

Every variant runs with every seed at equal wall time on one thread, two runs at a time,
seed-major (seed 1 of every variant, then seed 2, ...), so that each variant shares the machine
alike. Writes a CSV (variant, seed, seconds, best so far at that time) and prints a table of
mean ± std and the worst seed at the sampled times, the same rows into --md if given.

  /usr/bin/python3 experiments/settings_ab.py tree-sketch --seeds 6 --seconds 40 \\
      --variant off search.hybrid_scout_interval=0 --variant scout search.hybrid_scout_interval=400 \\
      --set ga.population=200 --csv experiments/results/scout-tree-sketch.csv

(`--set` applies to every variant: compare_methods.py's populations are 150 for the spaceships,
200 for the trees, 100 for the city and the castle.)
"""
import argparse
import concurrent.futures
import csv
import math
import os
import shutil
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TIMES = [1, 3, 10, 20, 40, 100, 300]


def best_at(folder, times):
    """The best fitness reached by each time in `times` (None past the run's end), from curve.csv."""
    rows, best = [], -math.inf
    with open(os.path.join(folder, "curve.csv")) as f:
        for r in csv.DictReader(f):
            best = max(best, float(r["best"]))
            rows.append((float(r["seconds"]), best))
    out = []
    for t in times:
        seen = [b for s, b in rows if s <= t]
        out.append(seen[-1] if seen and rows[-1][0] >= 0.95 * t else None)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scene", help="a config name in configs/")
    ap.add_argument("--variant", nargs="+", action="append", required=True, metavar=("NAME", "SET"),
                    help="a name and its key=value settings (repeat for each variant)")
    ap.add_argument("--set", action="append", default=[], help="key=value for every variant")
    ap.add_argument("--seeds", type=int, default=5)
    ap.add_argument("--seconds", type=float, default=40)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "shapevo"))
    ap.add_argument("--out", default=os.path.join(ROOT, "runs", "settings-ab"))
    ap.add_argument("--csv")
    ap.add_argument("--md")
    ap.add_argument("--summarise-only", action="store_true", help="read the runs already in --out")
    args = ap.parse_args()
    config = os.path.join(ROOT, "configs", args.scene + ".toml")
    if not os.path.isfile(config):
        sys.exit(f"settings_ab: no config {config}")
    common = [f"run.wall_time={args.seconds}", "checkpoint.interval=0", "checkpoint.seconds=0",
              "ga.generations=1000000000"] + args.set
    jobs = []
    for seed in range(1, args.seeds + 1):
        for name, *sets in args.variant:
            folder = os.path.join(args.out, args.scene, name, f"seed{seed}")
            if not args.summarise_only:
                shutil.rmtree(folder, ignore_errors=True)
            cmd = [args.bin, "run", config, "--seed", str(seed), "--threads", "1", "-q", "--out", folder]
            cmd += [a for s in common + sets for a in ("--set", s)]
            jobs.append((name, seed, folder, cmd))

    def run(job):
        r = subprocess.run(job[3], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if r.returncode != 0:
            sys.exit(f"settings_ab: {' '.join(job[3])} failed ({r.returncode}): {r.stderr.strip()}")
        return job

    if args.summarise_only:
        done = jobs
    else:
        with concurrent.futures.ThreadPoolExecutor(2) as pool:
            done = list(pool.map(run, jobs))
    times = [t for t in TIMES if t <= args.seconds]
    best = {(name, seed): best_at(folder, times) for name, seed, folder, _ in done}
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["variant", "seed", "seconds", "best"])
            for (name, seed), values in best.items():
                for t, b in zip(times, values):
                    w.writerow([name, seed, t, "" if b is None else repr(b)])
    lines = [f"{args.scene}, {args.seeds} seeds x {args.seconds:g} s, one thread each, two runs at a time "
             f"(--set {' '.join(args.set) or '-'}): mean ± std (worst seed)", "",
             "| variant | settings | " + " | ".join(f"{t} s" for t in times) + " | final per seed |",
             "|---|---|" + "---|" * len(times) + "---|"]
    for name, *sets in args.variant:
        cells = []
        for k in range(len(times)):
            v = [best[(name, s)][k] for s in range(1, args.seeds + 1) if best[(name, s)][k] is not None]
            sd = statistics.stdev(v) if len(v) > 1 else 0.0
            cells.append(f"{statistics.fmean(v):.4f} ± {sd:.4f} ({min(v):.4f})" if v else "–")
        finals = ", ".join(f"{best[(name, s)][-1]:.4f}" for s in range(1, args.seeds + 1) if best[(name, s)][-1] is not None)
        lines.append(f"| {name} | {' '.join(sets) or '-'} | " + " | ".join(cells) + f" | {finals} |")
    print("\n".join(lines))
    if args.md:
        with open(args.md, "w") as f:
            f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()

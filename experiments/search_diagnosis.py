#!/usr/bin/env python3
"""Why the GA stalls (issue 17, line 1): runs the paper's GA (search.method = "ga", the scene's
config as shipped) with search.diagnostics = true on each scene for SECONDS of wall time, SEEDS
seeds, one rank with two evaluation threads, then summarises the runs' diagnostics.csv files
(src/run/diagnostics_log.hpp) into a table per scene and time, and plots them.

For each scene and each sampled time (1, 2, 5, 10, 20, 40 s ...): the best fitness (mean and the
seeds' values), distinct genomes and distinct structures in the population (share of the
population), mean chromosome length, microseconds per evaluation, the share of selections that
picked a new individual, and, over the generations since the previous sampled time, the share
of each operator's children that were better / equal / worse than their parent.

usage: experiments/search_diagnosis.py [--bin build/shapevo] [--seconds 40] [--seeds 5]
           [--scenes tree-sketch spaceship-paper] [--out experiments/results/search-diagnosis]
           [--docs docs/figures]     (plots docs/figures/search-diagnosis-<scene>.png; needs matplotlib)
           [--summarise-only] (read the CSVs already in --out)
"""
import argparse
import csv
import os
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OPS = ["grow", "cut", "alter", "crossover", "copy"]


def run(a, scene, seed, folder):
    if os.path.exists(folder):
        subprocess.run(["rm", "-rf", folder], check=True)
    subprocess.run([a.bin, "run", os.path.join(ROOT, "configs", scene + ".toml"), "-q", "--threads", "2",
                    "--seed", str(seed), "--set", "search.method=ga", "--set", "search.diagnostics=true",
                    "--set", "run.wall_time=%g" % a.seconds, "--set", "ga.generations=100000000",
                    "--set", "checkpoint.seconds=0", "--set", "checkpoint.interval=100000000", "--out", folder],
                   check=True, stdout=subprocess.DEVNULL)


def read(path):
    with open(path) as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def at(rows, t):
    """The last row at or before t seconds (None before the first)."""
    best = None
    for r in rows:
        if r["seconds"] <= t:
            best = r
    return best


def window(rows, t0, t1):
    return [r for r in rows if t0 < r["seconds"] <= t1]


def summarise(scene, runs, times, population):
    lines = ["| s | best: mean (seeds) | distinct genomes | distinct structures | mean genes | µs / evaluation"
             " | new parents | better children: grow / cut / alter / crossover | equal children (all) |",
             "| ---: | --- | ---: | ---: | ---: | ---: | ---: | --- | ---: |"]
    prev = 0.0
    for t in times:
        snap = [at(rows, t) for rows in runs]
        snap = [s for s in snap if s]
        if not snap:
            continue
        win = [r for rows in runs for r in window(rows, prev, t)]
        better = []
        for op in OPS[:4]:
            n = sum(r[op + "_better"] + r[op + "_equal"] + r[op + "_worse"] for r in win)
            better.append("%.1f %%" % (100.0 * sum(r[op + "_better"] for r in win) / n) if n else "-")
        total = sum(r[op + "_" + res] for r in win for op in OPS for res in ("better", "equal", "worse"))
        equal = sum(r[op + "_equal"] for r in win for op in OPS)
        parents = [r["distinct_parents"] for r in win if r["distinct_parents"] > 0]
        cost = [r["us_per_evaluation"] for r in win if r["us_per_evaluation"] > 0]
        lines.append("| %g | %.3f (%s) | %.0f %% | %.0f %% | %.0f | %s | %s | %s | %s |" % (
            t, statistics.mean(s["best"] for s in snap), " ".join("%.2f" % s["best"] for s in snap),
            100.0 * statistics.mean(s["distinct_genomes"] for s in snap) / population,
            100.0 * statistics.mean(s["distinct_structures"] for s in snap) / population,
            statistics.mean(s["mean_genes"] for s in snap),
            "%.0f" % statistics.median(cost) if cost else "-",
            "%.0f %%" % (100.0 * statistics.mean(parents)) if parents else "-",
            " / ".join(better), "%.0f %%" % (100.0 * equal / total) if total else "-"))
        prev = t
    return "\n".join(lines)


def plot(path, scene, runs):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 2, figsize=(12, 8))
    panels = [("best", "best fitness"), ("distinct_genomes", "distinct genomes in the population"),
              ("mean_genes", "mean chromosome length (genes)"), (None, "children better than their parent (share, 20-generation mean)")]
    for ax, (key, title) in zip(axes.flat, panels):
        for i, rows in enumerate(runs):
            xs = [r["seconds"] for r in rows]
            if key:
                ys = [r[key] for r in rows]
            else:
                ys = []
                for j in range(len(rows)):
                    w = rows[max(0, j - 19): j + 1]
                    n = sum(r[op + "_" + res] for r in w for op in OPS for res in ("better", "equal", "worse"))
                    ys.append(sum(r[op + "_better"] for r in w for op in OPS) / n if n else float("nan"))
            ax.plot(xs, ys, label="seed %d" % (i + 1), linewidth=1)
        ax.set_xscale("log")
        ax.set_title(title)
        ax.set_xlabel("seconds")
        ax.grid(True, alpha=0.3)
    axes.flat[0].legend()
    fig.suptitle("%s: the paper's GA, %d seeds (diagnostics.csv)" % (scene, len(runs)))
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "shapevo"))
    ap.add_argument("--seconds", type=float, default=40)
    ap.add_argument("--seeds", type=int, default=5)
    ap.add_argument("--scenes", nargs="+", default=["tree-sketch", "spaceship-paper"])
    ap.add_argument("--out", default=os.path.join(ROOT, "experiments", "results", "search-diagnosis"))
    ap.add_argument("--docs")
    ap.add_argument("--summarise-only", action="store_true")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    times = [t for t in (1, 2, 5, 10, 20, 40, 80, 160, 300) if t <= a.seconds]
    for scene in a.scenes:
        runs = []
        for seed in range(1, a.seeds + 1):
            csv_path = os.path.join(a.out, "%s-seed%d.csv" % (scene, seed))
            if not a.summarise_only:
                folder = os.path.join("/tmp", "shapevo-diagnosis-%s-%d" % (scene, seed))
                run(a, scene, seed, folder)
                subprocess.run(["cp", os.path.join(folder, "diagnostics.csv"), csv_path], check=True)
                subprocess.run(["rm", "-rf", folder], check=True)
            runs.append(read(csv_path))
        population = max(r["distinct_genomes"] for rows in runs for r in rows)
        with open(os.path.join(ROOT, "configs", scene + ".toml")) as f:
            for line in f:
                if line.strip().startswith("population"):
                    population = float(line.split("=")[1].split("#")[0])
        print("### %s\n" % scene)
        print(summarise(scene, runs, times, population))
        print(flush=True)
        if a.docs:
            plot(os.path.join(a.docs, "search-diagnosis-%s.png" % scene), scene, runs)


if __name__ == "__main__":
    sys.exit(main())

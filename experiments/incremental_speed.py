#!/usr/bin/env python3
"""Incremental scoring in whole runs (issue 15): `shapevo run` with score.incremental on and off,
same seed, same generation count, one thread, back to back (A B A B ...). With the same seed the
two runs evolve exactly the same models (the switch changes only the time; the script checks
that best.genome is byte-identical), so evaluations per second compare like for like. Reports,
per scene, the median and min-max over repetitions of evals/s for each mode and of their paired
ratio, and the wall time of each mode.

With --quality: quality per second instead. tree-logo on 2 MPI ranks (mpirun -np 2, one
thread each), seeds 1-5, each with the switch off and on, for --seconds of wall time; reports for
each mode the median (min-max) over seeds of the seconds until the best model's silhouette IoU
(curve.csv's iou column) first reached 0.95 and 0.98 ("-" if it did not).

With --memory: memory instead. Every shipped scene (configs/*.toml) runs once with its defaults
(incremental scoring on) on one thread for --seconds; summary.json gives the island's caches
(cache_bytes), what its models keep for their children (model_bytes), the process's peak
resident size and the population: reported per island and per individual.

usage: experiments/incremental_speed.py [--bin build/shapevo] [--reps 5]
           [--scenes tree-logo:1500 tree-sketch:1200 spaceship:50 ...] [--csv FILE]
       experiments/incremental_speed.py --quality [--seconds 30] [--seeds 5]
       experiments/incremental_speed.py --memory [--seconds 20] [--csv FILE]
A scene is CONFIG[:GENERATIONS] (configs/CONFIG.toml; GENERATIONS overrides ga.generations).
"""
import argparse
import csv
import json
import os
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_SCENES = ["tree-logo:1500", "tree-sketch:1200", "spaceship:50", "spaceship-paper:50",
                  "castle-volume:400", "tree-volume:600"]


def run(binary, config, generations, incremental, out):
    args = [binary, "run", os.path.join(ROOT, "configs", config + ".toml"), "-q", "--threads", "1",
            "--set", "run.wall_time=0", "--set", "checkpoint.seconds=0",
            "--set", "checkpoint.interval=1000000", "--set", "score.incremental=" + ("true" if incremental else "false"),
            "--out", out]
    if generations:
        args += ["--set", "ga.generations=%d" % generations]
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    with open(os.path.join(out, "best.genome"), "rb") as f:
        best = f.read()
    return s["evaluations"] / s["wall_seconds"], s["wall_seconds"], best


def time_to(binary, seed, incremental, seconds, out, levels):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    args = ["mpirun", "--oversubscribe", "--bind-to", "none", "-np", "2", binary, "run",
            os.path.join(ROOT, "configs", "tree-logo.toml"), "-q", "--threads", "1", "--seed", str(seed),
            "--set", "run.wall_time=%g" % seconds, "--set", "score.incremental=" + ("true" if incremental else "false"),
            "--out", out]
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL, env=env)
    reached = {}
    with open(os.path.join(out, "curve.csv")) as f:
        for row in csv.DictReader(f):
            for level in levels:
                if level not in reached and float(row["iou"]) >= level:
                    reached[level] = float(row["seconds"])
    return reached


def quality(a):
    levels = [0.95, 0.98]
    times = {(inc, level): [] for inc in (False, True) for level in levels}
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for seed in range(1, a.seeds + 1):
            for inc in ([False, True] if seed % 2 else [True, False]):
                reached = time_to(a.bin, seed, inc, a.seconds, os.path.join(tmp, "q-%d-%d" % (seed, inc)), levels)
                for level in levels:
                    times[(inc, level)].append(reached.get(level))
                    rows.append({"seed": seed, "incremental": int(inc), "iou": level, "seconds": reached.get(level, "")})
    print("| tree-logo, 2 ranks | seconds to IoU 0.95 | seconds to IoU 0.98 |")
    print("| --- | --- | --- |")
    for inc in (False, True):
        cells = []
        for level in levels:
            got = [t for t in times[(inc, level)] if t is not None]
            cell = spread(got, "%.1f") if got else "-"
            if len(got) < len(times[(inc, level)]):
                cell += ", %d of %d seeds" % (len(got), len(times[(inc, level)]))
            cells.append(cell)
        print("| %s | %s | %s |" % ("incremental" if inc else "full", cells[0], cells[1]))
    return rows


def memory(a):
    rows = []
    print("| scene | generations | population | caches | models | per individual (caches + models) | peak resident |")
    print("| --- | ---: | ---: | ---: | ---: | ---: | ---: |")
    configs = sorted(f[:-5] for f in os.listdir(os.path.join(ROOT, "configs")) if f.endswith(".toml"))
    with tempfile.TemporaryDirectory() as tmp:
        for config in configs:
            out = os.path.join(tmp, config)
            subprocess.run([a.bin, "run", os.path.join(ROOT, "configs", config + ".toml"), "-q", "--threads", "1",
                            "--set", "run.wall_time=%g" % a.seconds, "--set", "ga.generations=1000000000",
                            "--set", "checkpoint.seconds=0", "--set", "checkpoint.interval=1000000", "--out", out],
                           check=True, stdout=subprocess.DEVNULL)
            with open(os.path.join(out, "summary.json")) as f:
                s = json.load(f)
            n = max(1, s["population"])
            row = {"scene": config, "generations": s["generations"], "population": s["population"],
                   "cache_bytes": s["cache_bytes"], "model_bytes": s["model_bytes"], "max_rss_bytes": s["max_rss_bytes"]}
            rows.append(row)
            print("| %s | %d | %d | %.1f MB | %.1f MB | %.0f + %.0f KB | %.0f MB |" % (
                config, s["generations"], s["population"], s["cache_bytes"] / 1e6, s["model_bytes"] / 1e6,
                s["cache_bytes"] / n / 1e3, s["model_bytes"] / n / 1e3, s["max_rss_bytes"] / 1e6), flush=True)
    return rows


def spread(values, fmt):
    return (fmt + " (" + fmt + "-" + fmt + ")") % (statistics.median(values), min(values), max(values))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "shapevo"))
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--scenes", nargs="+", default=DEFAULT_SCENES)
    ap.add_argument("--csv")
    ap.add_argument("--quality", action="store_true")
    ap.add_argument("--seconds", type=float, default=30)
    ap.add_argument("--seeds", type=int, default=5)
    ap.add_argument("--memory", action="store_true")
    a = ap.parse_args()
    if a.quality or a.memory:
        rows = quality(a) if a.quality else memory(a)
        if a.csv:
            with open(a.csv, "w", newline="") as f:
                w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
                w.writeheader()
                w.writerows(rows)
        return
    rows = []
    print("| scene | generations | full evals/s | incremental evals/s | speed-up | full s | incremental s |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    with tempfile.TemporaryDirectory() as tmp:
        for scene in a.scenes:
            config, _, gens = scene.partition(":")
            gens = int(gens) if gens else 0
            rate = {False: [], True: []}
            wall = {False: [], True: []}
            for rep in range(a.reps):
                genomes = {}
                for inc in ([False, True] if rep % 2 == 0 else [True, False]):
                    r, w, best = run(a.bin, config, gens, inc, os.path.join(tmp, "%s-%d-%d" % (config, rep, inc)))
                    rate[inc].append(r)
                    wall[inc].append(w)
                    genomes[inc] = best
                    rows.append({"scene": config, "generations": gens, "rep": rep, "incremental": int(inc),
                                 "evals_per_s": r, "wall_s": w})
                if genomes[False] != genomes[True]:
                    sys.exit("incremental_speed: %s: the two modes found different best models" % config)
            ratio = [i / f for i, f in zip(rate[True], rate[False])]
            print("| %s | %s | %s | %s | %s | %s | %s |" % (
                config, gens or "config", spread(rate[False], "%.0f"), spread(rate[True], "%.0f"),
                spread(ratio, "%.2f"), spread(wall[False], "%.2f"), spread(wall[True], "%.2f")), flush=True)
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)


if __name__ == "__main__":
    main()

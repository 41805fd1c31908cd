#!/usr/bin/env python3
"""Island scaling on this machine (issue 16): evaluations per second of 2 ranks over 1 rank in
sync and async mode, and of 4 ranks over 2 ranks (oversubscribed on a 2-core machine), on the
spaceship, tree-logo, tree-sketch and castle-volume scenes, with the share of wall time each rank
spent waiting for others (summary.json's wait_share_max / wait_share_mean).

Every run stops on a wall-time budget (run.wall_time), so that islands which finish their
generations at different speeds never wait for each other at the end; one evaluation thread per
rank; ranks are not bound to cores (--bind-to none). Repetitions cycle through every
configuration back to back, so the machine's drift hits them alike, and each ratio is taken per
repetition (paired), then the median and min-max over repetitions are reported.

The issue's measure, evaluations per second, also measures evolution: an island's models grow
or shrink, and with them the cost of an evaluation (castle-volume's single island builds castles
that cost 8x those of the 2-rank run's islands). `--same-work` therefore also measures the
run-time system alone: migration off (so each island of a 2-rank run evolves exactly as a
1-rank run of its seed), and for each island the time it would have needed alone to reach the
generation it reached in the 2-rank run, over the 2-rank run's wall time; the speed-up is the sum
over islands (ideal 2.0). The run's seed is chosen so that island 1's seed is 1.

A seeded sync run repeats byte for byte, so without `--vary-seed` every repetition of a sync
configuration measures the same trajectory (one sample of evolution), while async runs differ
from repetition to repetition. `--vary-seed` gives repetition k the seed k in every configuration,
so that sync and async ratios both sample evolution alike (the `--same-work` runs keep their seeds).

usage: experiments/island_scaling.py [--bin build/shapevo] [--seconds 6] [--reps 5]
                                     [--scenes spaceship tree-logo ...] [--csv FILE] [--same-work]
                                     [--vary-seed]
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
RUNS = [(1, "sync"), (2, "sync"), (2, "async"), (4, "sync"), (4, "async")]
RATIOS = [("2 ranks / 1, sync", (2, "sync"), (1, "sync")),
          ("2 ranks / 1, async", (2, "async"), (1, "sync")),
          ("4 ranks / 2, sync", (4, "sync"), (2, "sync")),
          ("4 ranks / 2, async", (4, "async"), (2, "async"))]


SEED_OF_ISLAND_0 = (1 - 0x9e3779b97f4a7c15) % 2**64  # island r's seed is seed + r * 0x9e3779b97f4a7c15


def run_once(binary, scene, ranks, mode, seconds, out, extra=()):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    cmd = ["mpirun", "--oversubscribe", "--bind-to", "none", "-np", str(ranks), binary, "run",
           os.path.join(ROOT, "configs", scene + ".toml"), "--threads", "1", "--out", out, "-q",
           "--set", "run.wall_time=%g" % seconds, "--set", "ga.generations=100000000",
           "--set", "migration.mode=" + mode, *extra]
    subprocess.run(cmd, check=True, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    return {"evals_per_s": s["evaluations"] / s["wall_seconds"], "wait_max": s.get("wait_share_max", 0.0),
            "wait_mean": s.get("wait_share_mean", 0.0), "generations": s["generations"],
            "wait_outside_max": s.get("wait_share_outside_checkpoints_max", 0.0)}


def island_generations(binary, run_dir):
    """Generations each island completed, from the final checkpoint (inspect's island table)."""
    text = subprocess.run([binary, "inspect", run_dir], check=True, capture_output=True, text=True).stdout
    out, table = [], False
    for line in text.splitlines():
        if line.strip().startswith("island"):
            table = True
        elif table and line.split() and line.split()[0].isdigit():
            out.append(int(line.split()[5]))
    return out


def seconds_to_reach(curve_csv, generation):
    """Seconds a 1-rank run needed to complete `generation` (extrapolated past its end)."""
    with open(curve_csv) as f:
        rows = [(int(r["generation"]), float(r["seconds"])) for r in csv.DictReader(f)]
    for g, t in rows:
        if g >= generation:
            return t
    g, t = rows[-1]
    return t * generation / g


def same_work(a):
    """Per scene and mode, the sum over islands of (time alone to reach its generation) / wall time."""
    speed = {}
    with tempfile.TemporaryDirectory() as tmp:
        for rep in range(1, a.reps + 1):
            for scene in a.scenes:
                alone = []
                for r, seed in enumerate((SEED_OF_ISLAND_0, 1)):
                    out = os.path.join(tmp, "%s-alone%d-%d" % (scene, r, rep))
                    run_once(a.bin, scene, 1, "sync", 1.3 * a.seconds, out,
                             ("--seed", str(seed), "--set", "migration.interval=0"))
                    alone.append(os.path.join(out, "curve.csv"))
                for mode in ("sync", "async"):
                    out = os.path.join(tmp, "%s-2-%s-%d" % (scene, mode, rep))
                    run_once(a.bin, scene, 2, mode, a.seconds, out, ("--seed", str(SEED_OF_ISLAND_0),
                                                                     "--set", "migration.interval=0"))
                    with open(os.path.join(out, "summary.json")) as f:
                        wall = json.load(f)["wall_seconds"]
                    gens = island_generations(a.bin, out)
                    x = sum(seconds_to_reach(alone[r], g) for r, g in enumerate(gens)) / wall
                    speed.setdefault((scene, mode), []).append(x)
                    print("rep %d %-14s same work, 2 ranks %-5s: islands at generations %s, speed-up %.2fx" %
                          (rep, scene, mode, gens, x), file=sys.stderr, flush=True)
    print("\n| scene | same work, 2 ranks sync | same work, 2 ranks async |\n|---|---|---|")
    for scene in a.scenes:
        cells = []
        for mode in ("sync", "async"):
            q = speed[(scene, mode)]
            cells.append("%.2f× (%.2f–%.2f)" % (statistics.median(q), min(q), max(q)))
        print("| %s | %s |" % (scene, " | ".join(cells)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "shapevo"))
    ap.add_argument("--seconds", type=float, default=6.0, help="wall time of every run")
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--scenes", nargs="+", default=["spaceship", "tree-logo", "tree-sketch", "castle-volume"])
    ap.add_argument("--csv", help="write every run's figures here")
    ap.add_argument("--same-work", action="store_true", help="also the same-work speed-up (migration off)")
    ap.add_argument("--vary-seed", action="store_true", help="repetition k runs every configuration with seed k "
                    "(not the --same-work runs, whose seeds are fixed)")
    a = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for rep in range(1, a.reps + 1):
            for scene in a.scenes:
                for ranks, mode in RUNS:
                    out = os.path.join(tmp, "%s-%d-%s-%d" % (scene, ranks, mode, rep))
                    r = run_once(a.bin, scene, ranks, mode, a.seconds, out,
                                 ("--seed", str(rep)) if a.vary_seed else ())
                    r.update(scene=scene, ranks=ranks, mode=mode, rep=rep)
                    rows.append(r)
                    print("rep %d %-14s %d rank(s) %-5s %9.0f evals/s  wait mean %5.2f %%  max %5.2f %%" %
                          (rep, scene, ranks, mode, r["evals_per_s"], 100 * r["wait_mean"], 100 * r["wait_max"]),
                          file=sys.stderr, flush=True)
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=["scene", "ranks", "mode", "rep", "evals_per_s", "wait_mean", "wait_max",
                                              "wait_outside_max", "generations"])
            w.writeheader()
            w.writerows(rows)
    by = {(r["scene"], r["ranks"], r["mode"], r["rep"]): r for r in rows}
    print("| scene | " + " | ".join(name for name, _, _ in RATIOS) +
          " | waiting, 2 ranks sync (max) | waiting, 2 ranks async (max) | async, outside checkpoints (max) |")
    print("|---" * (len(RATIOS) + 4) + "|")
    for scene in a.scenes:
        cells = []
        for _, top, bottom in RATIOS:
            q = [by[(scene, *top, k)]["evals_per_s"] / by[(scene, *bottom, k)]["evals_per_s"] for k in range(1, a.reps + 1)]
            cells.append("%.2f× (%.2f–%.2f)" % (statistics.median(q), min(q), max(q)))
        for mode in ("sync", "async"):
            w = [by[(scene, 2, mode, k)]["wait_max"] for k in range(1, a.reps + 1)]
            cells.append("%.2f %% (%.2f–%.2f)" % (100 * statistics.median(w), 100 * min(w), 100 * max(w)))
        w = [by[(scene, 2, "async", k)]["wait_outside_max"] for k in range(1, a.reps + 1)]
        cells.append("%.2f %% (%.2f–%.2f)" % (100 * statistics.median(w), 100 * min(w), 100 * max(w)))
        print("| %s | %s |" % (scene, " | ".join(cells)))
    if a.same_work:
        same_work(a)


if __name__ == "__main__":
    main()

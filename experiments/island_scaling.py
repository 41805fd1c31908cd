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

usage: experiments/island_scaling.py [--bin build/shapevo] [--seconds 6] [--reps 5]
                                     [--scenes spaceship tree-logo ...] [--csv FILE]
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


def run_once(binary, scene, ranks, mode, seconds, out):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    cmd = ["mpirun", "--oversubscribe", "--bind-to", "none", "-np", str(ranks), binary, "run",
           os.path.join(ROOT, "configs", scene + ".toml"), "--threads", "1", "--out", out, "-q",
           "--set", "run.wall_time=%g" % seconds, "--set", "ga.generations=100000000",
           "--set", "migration.mode=" + mode]
    subprocess.run(cmd, check=True, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    return {"evals_per_s": s["evaluations"] / s["wall_seconds"], "wait_max": s.get("wait_share_max", 0.0),
            "wait_mean": s.get("wait_share_mean", 0.0), "generations": s["generations"]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "shapevo"))
    ap.add_argument("--seconds", type=float, default=6.0, help="wall time of every run")
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--scenes", nargs="+", default=["spaceship", "tree-logo", "tree-sketch", "castle-volume"])
    ap.add_argument("--csv", help="write every run's figures here")
    a = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for rep in range(1, a.reps + 1):
            for scene in a.scenes:
                for ranks, mode in RUNS:
                    out = os.path.join(tmp, "%s-%d-%s-%d" % (scene, ranks, mode, rep))
                    r = run_once(a.bin, scene, ranks, mode, a.seconds, out)
                    r.update(scene=scene, ranks=ranks, mode=mode, rep=rep)
                    rows.append(r)
                    print("rep %d %-14s %d rank(s) %-5s %9.0f evals/s  wait mean %5.2f %%  max %5.2f %%" %
                          (rep, scene, ranks, mode, r["evals_per_s"], 100 * r["wait_mean"], 100 * r["wait_max"]),
                          file=sys.stderr, flush=True)
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=["scene", "ranks", "mode", "rep", "evals_per_s", "wait_mean", "wait_max",
                                              "generations"])
            w.writeheader()
            w.writerows(rows)
    by = {(r["scene"], r["ranks"], r["mode"], r["rep"]): r for r in rows}
    print("| scene | " + " | ".join(name for name, _, _ in RATIOS) +
          " | waiting, 2 ranks sync (max) | waiting, 2 ranks async (max) |")
    print("|---" * (len(RATIOS) + 3) + "|")
    for scene in a.scenes:
        cells = []
        for _, top, bottom in RATIOS:
            q = [by[(scene, *top, k)]["evals_per_s"] / by[(scene, *bottom, k)]["evals_per_s"] for k in range(1, a.reps + 1)]
            cells.append("%.2f× (%.2f–%.2f)" % (statistics.median(q), min(q), max(q)))
        for mode in ("sync", "async"):
            w = [by[(scene, 2, mode, k)]["wait_max"] for k in range(1, a.reps + 1)]
            cells.append("%.2f %% (%.2f–%.2f)" % (100 * statistics.median(w), 100 * min(w), 100 * max(w)))
        print("| %s | %s |" % (scene, " | ".join(cells)))


if __name__ == "__main__":
    main()

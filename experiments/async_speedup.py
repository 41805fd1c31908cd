#!/usr/bin/env python3
"""Async islands with a generation budget (issue 40, item 6): evaluations per second of 1 rank,
2 ranks sync and 2 ranks async, each run given the same generation budget (ga.generations), one
evaluation thread per rank, ranks not bound to cores (--bind-to none). Each repetition runs every
configuration back to back (A B C A B C ...), so the machine's drift hits them alike; the ratios
are paired per repetition, then the median and min-max over repetitions are printed, with the CPU
time of each run (user + system of mpirun and its ranks) and, for async runs, the generations each
island reached (an island that finishes first goes on evolving until the slowest has).

With --baseline OTHER/shapevo, 2-rank async runs of that binary join each repetition (a column of
their own), to compare a change side by side.

Evaluations per second are summary.json's evaluations over its wall_seconds (the island loop's
time, start-up excluded).

usage: experiments/async_speedup.py [--bin build/shapevo] [--baseline OLD/shapevo] [--reps 3]
                                    [--generations 1500] [--scenes spaceship tree-logo]
"""
import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run_once(binary, scene, ranks, mode, generations, out):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    cmd = ["mpirun", "--oversubscribe", "--bind-to", "none", "-np", str(ranks), binary, "run",
           os.path.join(ROOT, "configs", scene + ".toml"), "--threads", "1", "--out", out, "-q",
           "--set", "ga.generations=%d" % generations, "--set", "migration.mode=" + mode]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    subprocess.run(cmd, check=True, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    elapsed = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)  # mpirun reaps its ranks: theirs count too
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    return {"evals_per_s": s["evaluations"] / s["wall_seconds"], "evaluations": s["evaluations"],
            "wall": s["wall_seconds"], "process_wall": elapsed, "cpu": cpu,
            "wait_max": s.get("wait_share_max", 0.0), "islands": island_generations(binary, out)}


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


def spread(values, fmt="%.2f"):
    return (fmt + " (" + fmt + "–" + fmt + ")") % (statistics.median(values), min(values), max(values))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "shapevo"))
    ap.add_argument("--baseline", help="another shapevo whose 2-rank async runs join each repetition")
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--generations", type=int, default=1500)
    ap.add_argument("--scenes", nargs="+", default=["spaceship", "tree-logo"])
    a = ap.parse_args()
    runs = [("1 rank", a.bin, 1, "sync"), ("2 ranks sync", a.bin, 2, "sync"), ("2 ranks async", a.bin, 2, "async")]
    if a.baseline:
        runs.append(("2 ranks async, baseline", a.baseline, 2, "async"))
    by = {}
    with tempfile.TemporaryDirectory() as tmp:
        for rep in range(1, a.reps + 1):
            for scene in a.scenes:
                for k, (label, binary, ranks, mode) in enumerate(runs):
                    out = os.path.join(tmp, "%s-%d-%d" % (scene, k, rep))
                    r = run_once(binary, scene, ranks, mode, a.generations, out)
                    by[(scene, label, rep)] = r
                    print("rep %d %-10s %-24s %8.0f evals/s  %9d evaluations  wall %6.2f s  cpu %6.2f s  "
                          "wait max %5.1f%%  islands at %s" % (rep, scene, label, r["evals_per_s"], r["evaluations"],
                                                               r["wall"], r["cpu"], 100 * r["wait_max"], r["islands"]),
                          file=sys.stderr, flush=True)
    labels = [r[0] for r in runs]
    print("\n| scene | " + " | ".join(labels[1:]) + " |")
    print("|---|" + "---|" * (len(labels) - 1))
    for scene in a.scenes:
        cells = []
        for label in labels[1:]:
            q = [by[(scene, label, k)]["evals_per_s"] / by[(scene, "1 rank", k)]["evals_per_s"] for k in range(1, a.reps + 1)]
            cells.append("**%.2f×** (%.2f–%.2f)" % (statistics.median(q), min(q), max(q)))
        print("| %s (evaluations/s over 1 rank's) | %s |" % (scene, " | ".join(cells)))
    print("\n| scene | run | evaluations/s | wall s | CPU s | CPU s per 100k evaluations | slowest rank's waiting |")
    print("|---|---|---|---|---|---|---|")
    for scene in a.scenes:
        for label in labels:
            rs = [by[(scene, label, k)] for k in range(1, a.reps + 1)]
            print("| %s | %s | %s | %s | %s | %s | %s |" % (
                scene, label, spread([r["evals_per_s"] for r in rs], "%.0f"), spread([r["wall"] for r in rs]),
                spread([r["cpu"] for r in rs]), spread([1e5 * r["cpu"] / r["evaluations"] for r in rs]),
                spread([100 * r["wait_max"] for r in rs], "%.1f") + " %"))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""A model of shapevo's time per generation and per checkpoint as the island count P grows to
1,024 (issue 16, line 5): measured costs from this machine plus published latencies of an
InfiniBand cluster. It prints, per P, each term's share of a generation and which dominates.

Terms, per generation of an island whose generations take t seconds of computing:
  meeting     sync: one all-reduce of one record every K generations: ceil(log2 P) steps of
              latency alpha (InfiniBand) or, for P = 2 here, the measured meeting cost.
  imbalance   sync: a meeting waits for the slowest island's K-generation block. With
              independent Gaussian fluctuations of standard deviation s per block, the slowest of
              P exceeds the mean by s * E_P, E_P the expected largest of P standard normals
              (E_2 = 0.564, E_1024 = 3.26; about sqrt(2 ln P) for large P), so the mean waiting
              share measured with 2 ranks, w2, becomes w2 * E_P / E_2. Systematic differences
              between islands (bigger models on one) add to it at any P. Async mode has no such
              term.
  migration   one ring exchange every I generations: constant in P (two messages to neighbours).
  status      async: P - 1 statuses reach rank 0 every 0.2 s; rank 0 takes each in `recv` s.
  checkpoint  every C generations: each rank writes its island file (measured here, in parallel),
              then rank 0 reads every island file to hash it for the MANIFEST: P * S / B seconds.

usage: experiments/scaling_model.py [--t 0.001] [--w2 0.04] ...  (defaults: measured here, see
docs/history/2026-12-performance-log.md, "Islands: scaling")
"""
import argparse
import math


def expected_max_of_normals(n):
    """E[max of n independent standard normals], by integrating x n phi(x) Phi(x)^(n-1)."""
    total, step = 0.0, 1e-3
    x = -10.0
    while x < 10.0:
        phi = math.exp(-x * x / 2) / math.sqrt(2 * math.pi)
        cdf = 0.5 * (1 + math.erf(x / math.sqrt(2)))
        total += x * n * phi * cdf ** (n - 1) * step
        x += step
    return total


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--t", type=float, default=1.0e-3, help="seconds of computing per generation of one island")
    ap.add_argument("--K", type=int, default=20, help="generations between sync meetings")
    ap.add_argument("--I", type=int, default=20, help="generations between migrations")
    ap.add_argument("--C", type=int, default=500, help="generations between checkpoints")
    ap.add_argument("--w2", type=float, default=0.04, help="sync waiting share measured with 2 ranks (same work)")
    ap.add_argument("--meeting2", type=float, default=8e-6, help="seconds per meeting measured with 2 ranks here")
    ap.add_argument("--alpha", type=float, default=3e-6, help="InfiniBand latency per all-reduce step, seconds")
    ap.add_argument("--migration", type=float, default=17e-6, help="seconds per sync ring exchange (measured here)")
    ap.add_argument("--recv", type=float, default=1e-6, help="seconds rank 0 spends taking one async status")
    ap.add_argument("--write", type=float, default=5e-3, help="seconds for one rank to write its island file")
    ap.add_argument("--S", type=float, default=135e3, help="bytes of one island file")
    ap.add_argument("--B", type=float, default=1e9, help="bytes per second rank 0 reads to hash island files")
    a = ap.parse_args()
    print("t = %.3g s per generation, meetings every %d, migration every %d, checkpoints every %d generations"
          % (a.t, a.K, a.I, a.C))
    print("| islands P | meeting | imbalance (sync) | migration | status (async, rank 0) | checkpoint | "
          "sync total | async total | dominant (sync) |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    for P in (2, 8, 64, 256, 1024):
        meeting = (a.meeting2 if P == 2 else math.ceil(math.log2(P)) * a.alpha) / a.K / a.t
        imbalance = a.w2 * expected_max_of_normals(P) / expected_max_of_normals(2)
        migration = a.migration / a.I / a.t
        status = (P - 1) / 0.2 * a.recv  # share of rank 0's time
        checkpoint = (a.write + P * a.S / a.B) / a.C / a.t
        terms = {"meeting": meeting, "imbalance": imbalance, "migration": migration, "checkpoint": checkpoint}
        sync = sum(terms.values())
        asyn = migration + status + checkpoint
        dominant = max(terms, key=terms.get)
        print("| %d | %.2f %% | %.1f %% | %.2f %% | %.2f %% | %.1f %% | %.1f %% | %.1f %% | %s |" % (
            P, 100 * meeting, 100 * imbalance, 100 * migration, 100 * status, 100 * checkpoint, 100 * sync,
            100 * asyn, dominant))


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Render an OBJ model (shapevo output or target mesh) as three orthographic views to a PNG.

usage: experiments/view_model.py MODEL.obj [MORE.obj ...] -o views.png
Needs Debian's python3-matplotlib. Each model is drawn in its own colour, translucent.
"""
import argparse

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection


def read_obj(path):
    verts, faces = [], []
    for line in open(path):
        p = line.split()
        if not p:
            continue
        if p[0] == "v":
            verts.append(tuple(float(x) for x in p[1:4]))
        elif p[0] == "f":
            idx = [int(t.split("/")[0]) for t in p[1:]]
            idx = [i - 1 if i > 0 else len(verts) + i for i in idx]
            for k in range(1, len(idx) - 1):
                faces.append((idx[0], idx[k], idx[k + 1]))
    return verts, faces


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("models", nargs="+")
    ap.add_argument("-o", "--output", required=True)
    a = ap.parse_args()
    views = [("top (x-z)", 0, 2), ("side (z-y)", 2, 1), ("front (x-y)", 0, 1)]
    fig, axes = plt.subplots(1, 3, figsize=(15, 5))
    colours = ["tab:blue", "tab:red", "tab:green", "tab:orange"]
    for m, path in enumerate(a.models):
        verts, faces = read_obj(path)
        for ax, (title, i, j) in zip(axes, views):
            polys = [[(verts[v][i], verts[v][j]) for v in f] for f in faces]
            ax.add_collection(PolyCollection(polys, facecolor=colours[m % 4], alpha=0.15, edgecolor="none"))
            ax.set_title(title)
    for ax in axes:
        ax.autoscale()
        ax.set_aspect("equal")
    fig.legend([plt.Rectangle((0, 0), 1, 1, color=colours[m % 4]) for m in range(len(a.models))], a.models)
    fig.savefig(a.output, dpi=80)


if __name__ == "__main__":
    main()

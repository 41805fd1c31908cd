#!/usr/bin/env python3
"""Damage a mesh the way real files are damaged, for docs/own-mesh.md's example:
read an OBJ (v and f lines only), give every face its own copies of its corners (a seam along
every edge, as a triangle soup from a scanner or an exporter has), drop every K-th face (holes)
and write the result as an OFF file, a format shapevo reads through Assimp.

    experiments/make_damaged_mesh.py IN.obj OUT.off [K]      (K: default 17)
"""
import sys


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    every = int(sys.argv[3]) if len(sys.argv) == 4 else 17
    vertices, faces = [], []
    for line in open(sys.argv[1]):
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "v":
            vertices.append(parts[1:4])
        elif parts[0] == "f":
            faces.append([int(p.split("/")[0]) - 1 for p in parts[1:]])
    kept = [f for i, f in enumerate(faces) if (i + 1) % every != 0]
    out_vertices, out_faces = [], []
    for f in kept:
        out_faces.append(list(range(len(out_vertices), len(out_vertices) + len(f))))
        out_vertices.extend(vertices[i] for i in f)
    with open(sys.argv[2], "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(out_vertices), len(out_faces)))
        for v in out_vertices:
            out.write(" ".join(v) + "\n")
        for f in out_faces:
            out.write("%d %s\n" % (len(f), " ".join(map(str, f))))
    print("%s: %d of %d faces kept (%d dropped), %d vertices, every face on its own corners" %
          (sys.argv[2], len(kept), len(faces), len(faces) - len(kept), len(out_vertices)))


if __name__ == "__main__":
    main()

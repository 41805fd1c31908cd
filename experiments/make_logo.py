#!/usr/bin/env python3
"""Draws the logo of the mosaic scene (configs/graph-mosaic-logo.toml): a power symbol, a thick
ring open at the top with a bar through the gap, black on white, 256 x 256 pixels (a pixel is
black when its centre is inside). Writes a grey PNG with the standard library only.

Usage: experiments/make_logo.py OUT.png   (experiments/make_graph_targets.sh calls it)"""
import math
import struct
import sys
import zlib

SIZE = 256
C = SIZE / 2


def inside(x, y):
    dx, dy = x - C, C - y  # y up
    r = math.hypot(dx, dy)
    angle = math.degrees(math.atan2(dx, dy))  # 0 = straight up
    ring = 64 <= r <= 104 and abs(angle) > 35
    bar = abs(dx) <= 18 and 8 <= dy <= 118
    return ring or bar


def png(path, rows):
    raw = b"".join(b"\x00" + bytes(row) for row in rows)
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    header = struct.pack(">IIBBBBB", SIZE, SIZE, 8, 0, 0, 0, 0)
    with open(path, "xb") as f:  # never replaces a file
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


if __name__ == "__main__":
    png(sys.argv[1], [[0 if inside(x + 0.5, y + 0.5) else 255 for x in range(SIZE)] for y in range(SIZE)])

#!/usr/bin/env python3
"""Write docs/own-logo.md's example logo: a white heart on a transparent background, 284 x 303 pixels
(an odd size and aspect on purpose), as an RGBA PNG. Plain Python (zlib only).

    experiments/make_heart_logo.py heart.png
"""
import math
import struct
import sys
import zlib

W, H = 284, 303


def inside(x, y):
    u = (x - W / 2) / (W * 0.42)
    v = -(y - H * 0.45) / (H * 0.42)
    return (u * u + v * v - 1) ** 3 - u * u * v ** 3 <= 0


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    raw = b"".join(b"\0" + b"".join(bytes((255, 255, 255, 255) if inside(x, y) else (0, 0, 0, 0)) for x in range(W))
                   for y in range(H))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    with open(sys.argv[1], "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", W, H, 8, 6, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


if __name__ == "__main__":
    main()

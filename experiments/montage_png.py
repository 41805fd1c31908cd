#!/usr/bin/env python3
"""Put PNG pictures side by side in one PNG (for the documentation's rows of samples).

Plain Python (zlib only; PNGs read by experiments/render_obj.py's reader: 8-bit, not interlaced),
scales nothing, pads shorter pictures with white.

    experiments/montage_png.py OUT.png IN1.png IN2.png ...
"""
import os
import struct
import sys
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from render_obj import read_png  # noqa: E402  (width, height, rows of (r, g, b))


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    pictures = [read_png(p) for p in sys.argv[2:]]
    width, height = sum(p[0] for p in pictures), max(p[1] for p in pictures)
    out = bytearray()
    for y in range(height):
        out.append(0)
        for w, h, rows in pictures:
            out += bytes(c for pixel in rows[y] for c in pixel) if y < h else b'\xff' * (3 * w)

    def chunk(kind, body):
        return struct.pack('>I', len(body)) + kind + body + struct.pack('>I', zlib.crc32(kind + body) & 0xffffffff)
    png = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', width, height, 8, 2, 0, 0, 0))
    png += chunk(b'IDAT', zlib.compress(bytes(out), 9)) + chunk(b'IEND', b'')
    open(sys.argv[1], 'wb').write(png)


if __name__ == '__main__':
    main()

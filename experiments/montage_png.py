#!/usr/bin/env python3
"""Put PNG pictures side by side in one PNG (for the documentation's rows of samples).

Plain Python (zlib only): reads 8-bit RGB or RGBA PNGs without interlacing (what
experiments/render_obj.py and shapevo write), scales nothing, pads shorter pictures with white.

    experiments/montage_png.py OUT.png IN1.png IN2.png ...
"""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, 'rb').read()
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        sys.exit(f'{path}: not a PNG')
    pos, idat, width = 8, b'', 0
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b'IHDR':
            width, height, depth, colour, _, _, interlace = struct.unpack('>IIBBBBB', body)
            if depth != 8 or colour not in (2, 6) or interlace:
                sys.exit(f'{path}: only 8-bit RGB/RGBA PNGs without interlacing')
            bpp = 3 if colour == 2 else 4
        elif kind == b'IDAT':
            idat += body
        pos += 12 + n
    raw, rows, prev = zlib.decompress(idat), [], bytearray(width * bpp)
    stride = width * bpp
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line[j] for k in range(width) for j in range(k * bpp, k * bpp + 3)))
        prev = line
    return width, height, rows


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    pictures = [read_png(p) for p in sys.argv[2:]]
    width, height = sum(p[0] for p in pictures), max(p[1] for p in pictures)
    out = bytearray()
    for y in range(height):
        out.append(0)
        for w, h, rows in pictures:
            out += rows[y] if y < h else b'\xff' * (3 * w)

    def chunk(kind, body):
        return struct.pack('>I', len(body)) + kind + body + struct.pack('>I', zlib.crc32(kind + body) & 0xffffffff)
    png = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', width, height, 8, 2, 0, 0, 0))
    png += chunk(b'IDAT', zlib.compress(bytes(out), 9)) + chunk(b'IEND', b'')
    open(sys.argv[1], 'wb').write(png)


if __name__ == '__main__':
    main()

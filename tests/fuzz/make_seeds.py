#!/usr/bin/env python3
"""Regenerates the binary seed files of tests/fuzz/corpus (PNG, binary PLY, binary STL).

The text seeds (OBJ, ASCII PLY and STL, grammars) are written by hand. Run from anywhere:
    python3 tests/fuzz/make_seeds.py
Only the standard library is used; the output is byte-for-byte reproducible.
"""
import os
import struct
import zlib

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")


def write(folder, name, data):
    with open(os.path.join(HERE, folder, name), "wb") as f:
        f.write(data)


# --- PNG: every colour type, bit depths 1 to 16, tRNS, PLTE, Adam7, filters, split IDAT ---

def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


SIGNATURE = b"\x89PNG\r\n\x1a\n"


def png(w, h, depth, colour, rows, interlace=0, extra=b"", before_idat=b""):
    ihdr = struct.pack(">IIBBBBB", w, h, depth, colour, 0, 0, interlace)
    raw = b"".join(b"\0" + r for r in rows)
    return (SIGNATURE + chunk(b"IHDR", ihdr) + before_idat + chunk(b"IDAT", zlib.compress(raw, 9)) + extra +
            chunk(b"IEND", b""))


def packbits(values, depth):
    bits = "".join(format(v, "0%db" % depth) for v in values)
    bits += "0" * (-len(bits) % 8)
    return bytes(int(bits[i:i + 8], 2) for i in range(0, len(bits), 8))


def pngs():
    write("png", "grey8_1x1.png", png(1, 1, 8, 0, [b"\x80"]))
    write("png", "rgb8_3x2.png",
          png(3, 2, 8, 2, [bytes([255, 0, 0, 0, 255, 0, 0, 0, 255]), bytes([10, 20, 30, 200, 100, 50, 255, 255, 255])],
              before_idat=chunk(b"gAMA", struct.pack(">I", 45455)) + chunk(b"sRGB", b"\0")))
    write("png", "grey1_9x2.png", png(9, 2, 1, 0, [packbits([1, 0, 1, 0, 1, 0, 1, 0, 1], 1), packbits([0] * 9, 1)]))
    write("png", "grey2_trns_4x1.png",
          png(4, 1, 2, 0, [packbits([0, 1, 2, 3], 2)], before_idat=chunk(b"tRNS", struct.pack(">H", 2))))
    write("png", "palette4_trns_5x3.png",
          png(5, 3, 4, 3, [packbits([0, 1, 2, 3, 0], 4), packbits([3, 2, 1, 0, 1], 4), packbits([2] * 5, 4)],
              before_idat=chunk(b"PLTE", bytes([0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0, 255])) +
              chunk(b"tRNS", bytes([0, 128]))))
    write("png", "greyalpha16_2x2.png",
          png(2, 2, 16, 4, [struct.pack(">4H", 0, 65535, 65535, 32768), struct.pack(">4H", 1000, 0, 50000, 1)],
              extra=chunk(b"tEXt", b"Comment\0fuzz seed")))
    write("png", "rgb16_trns_2x2.png",
          png(2, 2, 16, 2, [struct.pack(">6H", 1, 2, 3, 4, 5, 6), struct.pack(">6H", 1, 2, 3, 65535, 0, 0)],
              before_idat=chunk(b"tRNS", struct.pack(">3H", 1, 2, 3))))
    # Adam7-interlaced 8-bit RGBA 5x5, passes laid out by hand (filter byte 0 on every pass row).
    size = 5
    px = [[bytes([(x * 50) % 256, (y * 50) % 256, 128, 255 if (x + y) % 2 else 64]) for x in range(size)]
          for y in range(size)]
    raw = b""
    for x0, y0, dx, dy in [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2),
                           (0, 1, 1, 2)]:
        for y in range(y0, size, dy):
            row = b"".join(px[y][x] for x in range(x0, size, dx))
            if row:
                raw += b"\0" + row
    ihdr = struct.pack(">IIBBBBB", size, size, 8, 6, 0, 0, 1)
    write("png", "rgba8_adam7_5x5.png",
          SIGNATURE + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))
    # 8-bit RGBA 2x5, one row per filter type (None, Sub, Up, Average, Paeth), IDAT in two chunks.
    data = zlib.compress(b"".join(bytes([f]) + bytes(range(16 * f, 16 * f + 8)) for f in range(5)))
    ihdr = struct.pack(">IIBBBBB", 2, 5, 8, 6, 0, 0, 0)
    write("png", "rgba8_filters_split_idat_2x5.png",
          SIGNATURE + chunk(b"IHDR", ihdr) + chunk(b"IDAT", data[:7]) + chunk(b"IDAT", data[7:]) +
          chunk(b"IEND", b""))


# --- meshes: a tetrahedron (closed), a quad ---

VERTS = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def plys():
    hdr = ("ply\nformat binary_little_endian 1.0\ncomment tetrahedron\nelement vertex 4\n"
           "property float x\nproperty float y\nproperty float z\nproperty uchar alpha\n"
           "element face 4\nproperty list uchar int vertex_indices\n"
           "element material 1\nproperty short s\nproperty ushort u\nproperty uint i\nproperty char c\n"
           "property int8 c8\nproperty float64 d\nend_header\n").encode()
    body = b"".join(struct.pack("<fffB", *v, 200) for v in VERTS)
    body += b"".join(struct.pack("<B3i", 3, *f) for f in FACES)
    body += struct.pack("<hHIbbd", -3, 7, 9, -1, 2, 0.5)
    write("ply", "tetra_binary.ply", hdr + body)
    hdr = ("ply\r\nformat binary_little_endian 1.0\r\nelement vertex 4\r\nproperty double x\r\n"
           "property double y\r\nproperty double z\r\nelement face 1\r\n"
           "property list ushort uint16 vertex_indices\r\nend_header\r\n").encode()
    body = b"".join(struct.pack("<ddd", *v) for v in VERTS) + struct.pack("<H4H", 4, 0, 1, 2, 3)
    write("ply", "quad_binary_crlf.ply", hdr + body)


def stls():
    def binary(header, faces):
        b = header.ljust(80, b"\0") + struct.pack("<I", len(faces))
        for f in faces:
            b += struct.pack("<3f", 0, 0, 0) + b"".join(struct.pack("<3f", *VERTS[i]) for i in f) + struct.pack("<H", 0)
        return b
    write("stl", "tetra_binary.stl", binary(b"binary tetrahedron", FACES))
    # Starts with "solid" but has the exact binary size: must be read as binary.
    write("stl", "tetra_binary_solid_header.stl", binary(b"solid but binary", FACES))


if __name__ == "__main__":
    pngs()
    plys()
    stls()

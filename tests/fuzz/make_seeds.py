#!/usr/bin/env python3
"""Regenerates the binary seed files of tests/fuzz/corpus (PNG, binary PLY, binary STL) and the
seeds of fuzz_mesh_import (corpus/mesh_import: one byte naming the format, then a small file).

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


# --- fuzz_mesh_import: byte 0 picks the extension (kExtensions in fuzz_mesh_import.cpp) ---

IMPORT_EXTENSIONS = [".off", ".gltf", ".glb", ".fbx", ".3mf", ".dae", ".3ds", ".x",
                     ".ac", ".ase", ".b3d", ".ms3d", ".nff", ".smd", ".amf", ".blend"]
CUBE_VERTS = [((i & 1) * 2 - 1, (i >> 1 & 1) * 2 - 1, (i >> 2 & 1) * 2 - 1) for i in range(8)]
CUBE_QUADS = [(0, 4, 6, 2), (1, 3, 7, 5), (0, 1, 5, 4), (2, 6, 7, 3), (0, 2, 3, 1), (4, 5, 7, 6)]
CUBE_TRIS = [t for q in CUBE_QUADS for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]


def seed(ext, name, data):
    if isinstance(data, str):
        data = data.encode()
    write("mesh_import", name, bytes([IMPORT_EXTENSIONS.index(ext)]) + data)


def gltf_parts(move=(0, 0, 0)):
    buf = b"".join(struct.pack("<3f", *v) for v in CUBE_VERTS) + b"".join(struct.pack("<3I", *t) for t in CUBE_TRIS)
    doc = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "translation": list(move)}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"byteLength": len(buf)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 96},
                        {"buffer": 0, "byteOffset": 96, "byteLength": len(buf) - 96}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3",
                       "min": [-1, -1, -1], "max": [1, 1, 1]},
                      {"bufferView": 1, "componentType": 5125, "count": 36, "type": "SCALAR"}],
    }
    return doc, buf


def imports():
    import base64
    import io
    import json
    import zipfile
    os.makedirs(os.path.join(HERE, "mesh_import"), exist_ok=True)
    off = "OFF\n8 6 0\n" + "".join("%d %d %d\n" % v for v in CUBE_VERTS)
    seed(".off", "cube_quads.off", off + "".join("4 %d %d %d %d\n" % q for q in CUBE_QUADS))
    seed(".off", "tetra_colours.off", "COFF\n4 4 6\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n"
                                      "0 0 1 9 9 9 255\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
    doc, buf = gltf_parts((1, 2, 3))
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(buf).decode()
    seed(".gltf", "cube_embedded.gltf", json.dumps(doc, separators=(",", ":")))
    doc, buf = gltf_parts()
    js = json.dumps(doc, separators=(",", ":")).encode()
    js += b" " * (-len(js) % 4)
    buf += b"\0" * (-len(buf) % 4)
    glb = (struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(js) + 8 + len(buf)) + struct.pack("<I4s", len(js), b"JSON") +
           js + struct.pack("<I4s", len(buf), b"BIN\0") + buf)
    seed(".glb", "cube.glb", glb)
    dae = ('<?xml version="1.0" encoding="utf-8"?>\n<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" '
           'version="1.4.1"><asset><unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>'
           '<library_geometries><geometry id="g"><mesh><source id="p"><float_array id="pa" count="24">' +
           " ".join("%d %d %d" % v for v in CUBE_VERTS) +
           '</float_array><technique_common><accessor source="#pa" count="8" stride="3"><param name="X" type="float"/>'
           '<param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>'
           '<vertices id="v"><input semantic="POSITION" source="#p"/></vertices><polylist count="6">'
           '<input semantic="VERTEX" source="#v" offset="0"/><vcount>4 4 4 4 4 4</vcount><p>' +
           " ".join("%d %d %d %d" % q for q in CUBE_QUADS) +
           '</p></polylist></mesh></geometry></library_geometries><library_visual_scenes><visual_scene id="s">'
           '<node id="n"><translate>1 0 0</translate><rotate>0 1 0 90</rotate><scale>1 2 1</scale>'
           '<instance_geometry url="#g"/></node></visual_scene></library_visual_scenes>'
           '<scene><instance_visual_scene url="#s"/></scene></COLLADA>\n')
    seed(".dae", "cube_polylist.dae", dae)
    model = ('<?xml version="1.0" encoding="UTF-8"?>\n<model unit="millimeter" xmlns="http://schemas.microsoft.com/'
             '3dmanufacturing/core/2015/02"><resources><object id="1" type="model"><mesh><vertices>' +
             "".join('<vertex x="%d" y="%d" z="%d"/>' % v for v in CUBE_VERTS) + "</vertices><triangles>" +
             "".join('<triangle v1="%d" v2="%d" v3="%d"/>' % t for t in CUBE_TRIS) +
             '</triangles></mesh></object></resources><build><item objectid="1"/></build></model>\n')
    zipped = io.BytesIO()
    with zipfile.ZipFile(zipped, "w", zipfile.ZIP_STORED) as z:
        for name, text in [
            ("[Content_Types].xml", '<?xml version="1.0" encoding="UTF-8"?>\n<Types xmlns="http://schemas.'
             'openxmlformats.org/package/2006/content-types"><Default Extension="rels" ContentType="application/'
             'vnd.openxmlformats-package.relationships+xml"/><Default Extension="model" ContentType="application/'
             'vnd.ms-package.3dmanufacturing-3dmodel+xml"/></Types>\n'),
            ("_rels/.rels", '<?xml version="1.0" encoding="UTF-8"?>\n<Relationships xmlns="http://schemas.'
             'openxmlformats.org/package/2006/relationships"><Relationship Target="/3D/3dmodel.model" Id="rel0" '
             'Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>\n'),
            ("3D/3dmodel.model", model)]:
            info = zipfile.ZipInfo(name, date_time=(2020, 1, 1, 0, 0, 0))
            z.writestr(info, text)
    seed(".3mf", "cube.3mf", zipped.getvalue())
    amf = ('<?xml version="1.0" encoding="UTF-8"?>\n<amf unit="millimeter"><object id="0"><mesh><vertices>' +
           "".join("<vertex><coordinates><x>%d</x><y>%d</y><z>%d</z></coordinates></vertex>" % v for v in CUBE_VERTS) +
           "</vertices><volume>" + "".join("<triangle><v1>%d</v1><v2>%d</v2><v3>%d</v3></triangle>" % t for t in CUBE_TRIS) +
           "</volume></mesh></object></amf>\n")
    seed(".amf", "cube.amf", amf)
    nff = "".join("p 4\n" + "".join("%d %d %d\n" % CUBE_VERTS[i] for i in q) for q in CUBE_QUADS)
    seed(".nff", "cube.nff", nff)
    x = ("xof 0302txt 0064\nMesh cube {\n 8;\n" + ",\n".join(" %d;%d;%d;" % v for v in CUBE_VERTS) + ";\n 6;\n" +
         ",\n".join(" 4;%d,%d,%d,%d;" % q for q in CUBE_QUADS) + ";\n}\n")
    seed(".x", "cube.x", x)
    ac = ("AC3Db\nMATERIAL \"m\" rgb 1 1 1 amb 0.2 0.2 0.2 emis 0 0 0 spec 0 0 0 shi 0 trans 0\nOBJECT world\nkids 1\n"
          "OBJECT poly\nname \"cube\"\nloc 0 1 0\nnumvert 8\n" + "".join("%d %d %d\n" % v for v in CUBE_VERTS) +
          "numsurf 6\n" + "".join("SURF 0x10\nmat 0\nrefs 4\n" + "".join("%d 0 0\n" % i for i in q) for q in CUBE_QUADS) +
          "kids 0\n")
    seed(".ac", "cube.ac", ac)
    smd = ("version 1\nnodes\n0 \"root\" -1\nend\nskeleton\ntime 0\n0 0 0 0 0 0 0\nend\ntriangles\n" +
           "".join("mat\n" + "".join("0 %d %d %d 0 0 1 0 0\n" % CUBE_VERTS[i] for i in t) for t in CUBE_TRIS) + "end\n")
    seed(".smd", "cube.smd", smd)
    seed(".fbx", "header_only.fbx", b"Kaydara FBX Binary  \x00\x1a\x00" + struct.pack("<I", 7400) + b"\0" * 13)
    seed(".fbx", "ascii.fbx", "; FBX 7.4.0 project file\nFBXHeaderExtension:  {\n FBXHeaderVersion: 1003\n "
                              "FBXVersion: 7400\n}\nObjects:  {\n Geometry: 1, \"Geometry::cube\", \"Mesh\" {\n"
                              "  Vertices: *24 {\n   a: " + ",".join("%d,%d,%d" % v for v in CUBE_VERTS) +
                              "\n  }\n  PolygonVertexIndex: *24 {\n   a: " +
                              ",".join("%d,%d,%d,%d" % (q[0], q[1], q[2], -q[3] - 1) for q in CUBE_QUADS) +
                              "\n  }\n }\n Model: 2, \"Model::cube\", \"Mesh\" {\n }\n}\nConnections:  {\n"
                              " C: \"OO\",1,2\n C: \"OO\",2,0\n}\n")
    seed(".3ds", "header_only.3ds", struct.pack("<HI", 0x4D4D, 6 + 6 + 6) + struct.pack("<HI", 0x3D3D, 6) +
         struct.pack("<HI", 0x0002, 6))


if __name__ == "__main__":
    pngs()
    plys()
    stls()
    imports()

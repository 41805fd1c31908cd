#!/usr/bin/env python3
"""Render an OBJ model (as shapevo writes it, with its MTL colours and textures if any) to a PNG picture.

A small z-buffered rasterizer in plain Python (no packages beyond the standard library), for the
pictures in the documentation: flat Lambert shading, a perspective camera looking at the model's
bounding box from a chosen direction, a ground shadow-free light from over the camera's shoulder.
Textured materials (`map_Kd FILE.png`, 8-bit non-interlaced PNGs) are sampled at the faces'
`vt` coordinates (perspective-correct, nearest texel, repeating; v = 0 is the image's bottom).

    experiments/render_obj.py MODEL.obj OUT.png [--size 480x360] [--azimuth 35] [--elevation 25]
"""
import argparse, math, os, struct, zlib


def read_png(path):
    """(width, height, rows of (r, g, b) byte triples) of an 8-bit, non-interlaced PNG."""
    data = open(path, 'rb').read()
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        raise SystemExit(f'{path}: not a PNG')
    at, idat, palette = 8, b'', None
    while at < len(data):
        n, kind = struct.unpack('>I4s', data[at:at + 8])
        body = data[at + 8:at + 8 + n]
        if kind == b'IHDR':
            w, h, depth, ctype, _, _, interlace = struct.unpack('>IIBBBBB', body)
        elif kind == b'PLTE':
            palette = [tuple(body[i:i + 3]) for i in range(0, len(body), 3)]
        elif kind == b'IDAT':
            idat += body
        at += 12 + n
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[ctype]
    if depth != 8 or interlace:
        raise SystemExit(f'{path}: only 8-bit non-interlaced PNGs are supported here')
    raw, stride, prev, rows = zlib.decompress(idat), w * channels, bytearray(w * channels), []
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = prev[i], prev[i - channels] if i >= channels else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        prev = line
        if ctype == 3:
            rows.append([palette[v] for v in line])
        elif channels <= 2:
            rows.append([(line[x * channels],) * 3 for x in range(w)])
        else:
            rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(w)])
    return w, h, rows


def read_obj(path):
    """Vertices, triangles, and per triangle its colour and (texture, its corners' UVs) or None."""
    verts, uvs, tris, looks = [], [], [], []
    materials, current = {}, ((0.78, 0.78, 0.78), None)
    base = os.path.dirname(path)
    for line in open(path):
        t = line.split()
        if not t:
            continue
        if t[0] == 'v':
            verts.append(tuple(float(x) for x in t[1:4]))
        elif t[0] == 'vt':
            uvs.append((float(t[1]), float(t[2])))
        elif t[0] == 'mtllib':
            name = None
            for m in open(os.path.join(base, ' '.join(t[1:]))):
                u = m.split()
                if u and u[0] == 'newmtl':
                    name = u[1]
                    materials[name] = ((0.78, 0.78, 0.78), None)
                elif u and u[0] == 'Kd' and name:
                    materials[name] = (tuple(float(x) for x in u[1:4]), materials[name][1])
                elif u and u[0] == 'map_Kd' and name:
                    materials[name] = (materials[name][0], read_png(os.path.join(base, ' '.join(u[1:]))))
        elif t[0] == 'usemtl':
            current = materials.get(t[1], current)
        elif t[0] == 'f':
            corners = [x.split('/') for x in t[1:]]
            idx = [int(c[0]) - 1 for c in corners]
            tex = [int(c[1]) - 1 if len(c) > 1 and c[1] else None for c in corners]
            for k in range(1, len(idx) - 1):
                tris.append((idx[0], idx[k], idx[k + 1]))
                textured = current[1] is not None and None not in (tex[0], tex[k], tex[k + 1])
                looks.append((current[0], (current[1], (uvs[tex[0]], uvs[tex[k]], uvs[tex[k + 1]])) if textured else None))
    return verts, tris, looks


def to_linear(byte):
    s = byte / 255
    return s / 12.92 if s <= 0.04045 else ((s + 0.055) / 1.055) ** 2.4


def srgb(c):
    c = max(0.0, min(1.0, c))
    return int(255 * (12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055) + 0.5)


def write_png(path, w, h, rgb):
    raw = b''.join(b'\x00' + bytes(rgb[y * w * 3:(y + 1) * w * 3]) for y in range(h))
    def chunk(kind, data):
        return struct.pack('>I', len(data)) + kind + data + struct.pack('>I', zlib.crc32(kind + data) & 0xffffffff)
    with open(path, 'wb') as f:
        f.write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0)) +
                chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b''))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('model')
    ap.add_argument('out')
    ap.add_argument('--size', default='480x360')
    ap.add_argument('--azimuth', type=float, default=35.0, help='degrees about +y, from +z towards +x')
    ap.add_argument('--elevation', type=float, default=25.0, help='degrees above the horizon')
    a = ap.parse_args()
    W, H = (int(x) for x in a.size.split('x'))
    verts, tris, looks = read_obj(a.model)
    if not verts:
        raise SystemExit(f'{a.model}: no vertices')
    lo = [min(v[k] for v in verts) for k in range(3)]
    hi = [max(v[k] for v in verts) for k in range(3)]
    centre = [(lo[k] + hi[k]) / 2 for k in range(3)]
    radius = max(1e-6, math.dist(lo, hi) / 2)
    az, el = math.radians(a.azimuth), math.radians(a.elevation)
    fwd = (-math.sin(az) * math.cos(el), -math.sin(el), -math.cos(az) * math.cos(el))  # camera looks along fwd
    right = (math.cos(az), 0.0, -math.sin(az))
    up = (fwd[1] * right[2] - fwd[2] * right[1], fwd[2] * right[0] - fwd[0] * right[2], fwd[0] * right[1] - fwd[1] * right[0])
    up = tuple(-x for x in up)
    fov = math.radians(30)
    dist = radius / math.sin(fov / 2) * 1.05
    eye = [centre[k] - fwd[k] * dist for k in range(3)]
    f = (H / 2) / math.tan(fov / 2)
    light = (0.35 * right[0] + 0.8 * up[0] - 0.5 * fwd[0], 0.35 * right[1] + 0.8 * up[1] - 0.5 * fwd[1],
             0.35 * right[2] + 0.8 * up[2] - 0.5 * fwd[2])
    ln = math.sqrt(sum(x * x for x in light))
    light = tuple(x / ln for x in light)
    proj = []
    for v in verts:
        d = [v[k] - eye[k] for k in range(3)]
        z = sum(d[k] * fwd[k] for k in range(3))
        x = sum(d[k] * right[k] for k in range(3))
        y = sum(d[k] * up[k] for k in range(3))
        proj.append((W / 2 + f * x / z, H / 2 - f * y / z, z))
    zbuf = [math.inf] * (W * H)
    img = bytearray()
    for y in range(H):  # a soft vertical background gradient
        g = int(235 - 35 * y / H)
        img += bytes((g, g, min(255, g + 10))) * W
    for (i, j, k), (col, texture) in zip(tris, looks):
        a0, b0, c0 = verts[i], verts[j], verts[k]
        u = [b0[m] - a0[m] for m in range(3)]
        w = [c0[m] - a0[m] for m in range(3)]
        n = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
        nl = math.sqrt(sum(x * x for x in n))
        if nl == 0:
            continue
        n = tuple(x / nl for x in n)
        if sum(n[m] * fwd[m] for m in range(3)) > 0:
            n = tuple(-x for x in n)  # light both sides of thin or flipped faces
        shade = 0.25 + 0.75 * max(0.0, sum(n[m] * light[m] for m in range(3)))
        pix = bytes(srgb(col[m] * shade) for m in range(3))
        if texture:
            (tw, th, texels), corner_uv = texture
            lin = {}
        (x0, y0, z0), (x1, y1, z1), (x2, y2, z2) = proj[i], proj[j], proj[k]
        if min(z0, z1, z2) <= 0:
            continue
        area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
        if area == 0:
            continue
        xmin, xmax = max(0, int(min(x0, x1, x2))), min(W - 1, int(max(x0, x1, x2)) + 1)
        ymin, ymax = max(0, int(min(y0, y1, y2))), min(H - 1, int(max(y0, y1, y2)) + 1)
        for py in range(ymin, ymax + 1):
            cy = py + 0.5
            for px in range(xmin, xmax + 1):
                cx = px + 0.5
                w0 = ((x1 - cx) * (y2 - cy) - (x2 - cx) * (y1 - cy)) / area
                w1 = ((x2 - cx) * (y0 - cy) - (x0 - cx) * (y2 - cy)) / area
                w2 = 1 - w0 - w1
                if w0 < 0 or w1 < 0 or w2 < 0:
                    continue
                z = w0 * z0 + w1 * z1 + w2 * z2
                o = py * W + px
                if z < zbuf[o]:
                    zbuf[o] = z
                    if texture:  # perspective-correct: interpolate uv / z and 1 / z
                        q0, q1, q2 = w0 / z0, w1 / z1, w2 / z2
                        q = q0 + q1 + q2
                        tu = (q0 * corner_uv[0][0] + q1 * corner_uv[1][0] + q2 * corner_uv[2][0]) / q
                        tv = (q0 * corner_uv[0][1] + q1 * corner_uv[1][1] + q2 * corner_uv[2][1]) / q
                        tx = min(tw - 1, int((tu - math.floor(tu)) * tw))
                        ty = min(th - 1, int((1 - (tv - math.floor(tv))) * th))
                        texel = texels[ty][tx]
                        if texel not in lin:
                            lin[texel] = bytes(srgb(to_linear(texel[m]) * col[m] * shade) for m in range(3))
                        img[3 * o:3 * o + 3] = lin[texel]
                    else:
                        img[3 * o:3 * o + 3] = pix
    write_png(a.out, W, H, img)


if __name__ == '__main__':
    main()

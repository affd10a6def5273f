#!/usr/bin/env python3
"""Renders a face-coloured PLY (meshseg segment --colored-ply) to a PNG.

For judging segmentations by eye on a machine without a viewer: standard
library only (struct, zlib), orthographic views, z-buffer, the region colour
shaded by the face's angle to the view. Reads the binary little-endian PLY
with double vertices and per-face uchar colours that meshseg writes.

  scripts/render_ply.py seg.ply out.png [--size 700] [--view=iso|-iso|x|-x|y|-y|z|-z]
                        [--box XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX]

--box draws only the faces inside the box, scaled to fill the image (a
close look at a hole or a slot of a large plate).
"""
import argparse
import math
import struct
import sys
import zlib

VIEWS = {
    "iso": (1.0, 1.0, 1.0), "-iso": (-1.0, -1.0, -1.0),
    "x": (1.0, 0.0, 0.0), "-x": (-1.0, 0.0, 0.0),
    "y": (0.0, 1.0, 0.0), "-y": (0.0, -1.0, 0.0),
    "z": (0.0, 0.0, 1.0), "-z": (0.0, 0.0, -1.0),
}


def read_ply(path):
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    if "format binary_little_endian 1.0" not in header:
        sys.exit(f"{path}: only binary little-endian PLY is read")
    counts = {}
    for line in header:
        parts = line.split()
        if parts[:1] == ["element"]:
            counts[parts[1]] = int(parts[2])
    nv, nf = counts.get("vertex", 0), counts.get("face", 0)
    pos = end
    vertices = [struct.unpack_from("<ddd", data, pos + 24 * i) for i in range(nv)]
    pos += 24 * nv
    faces = []
    for _ in range(nf):
        n = data[pos]
        idx = struct.unpack_from(f"<{n}i", data, pos + 1)
        pos += 1 + 4 * n
        rgb = tuple(data[pos:pos + 3])
        pos += 3
        faces.append((idx, rgb))
    return vertices, faces


def basis(view):
    d = [c / math.sqrt(sum(x * x for x in view)) for c in view]
    up = (0.0, 0.0, 1.0) if abs(d[2]) < 0.9 else (0.0, 1.0, 0.0)
    u = (up[1] * d[2] - up[2] * d[1], up[2] * d[0] - up[0] * d[2], up[0] * d[1] - up[1] * d[0])
    un = math.sqrt(sum(x * x for x in u))
    u = tuple(x / un for x in u)
    w = (d[1] * u[2] - d[2] * u[1], d[2] * u[0] - d[0] * u[2], d[0] * u[1] - d[1] * u[0])
    return d, u, w


def render(vertices, faces, view, size):
    d, u, w = basis(view)
    proj = [(sum(a * b for a, b in zip(p, u)), sum(a * b for a, b in zip(p, w)),
             sum(a * b for a, b in zip(p, d))) for p in vertices]
    used = sorted({i for idx, _ in faces for i in idx}) or range(len(proj))
    xs = [proj[i][0] for i in used]
    ys = [proj[i][1] for i in used]
    scale = (size - 20) / max(max(xs) - min(xs), max(ys) - min(ys), 1e-12)
    x0, y0 = min(xs), min(ys)
    screen = [((p[0] - x0) * scale + 10, (size - 10) - (p[1] - y0) * scale, p[2]) for p in proj]
    depth = [[-math.inf] * size for _ in range(size)]
    image = [[(255, 255, 255)] * size for _ in range(size)]
    for idx, rgb in faces:
        for k in range(1, len(idx) - 1):
            a, b, c = (vertices[idx[0]], vertices[idx[k]], vertices[idx[k + 1]])
            n = [(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                 (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                 (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])]
            nn = math.sqrt(sum(x * x for x in n)) or 1.0
            shade = 0.35 + 0.65 * abs(sum(x * y for x, y in zip(n, d))) / nn
            colour = tuple(int(ch * shade) for ch in rgb)
            p0, p1, p2 = screen[idx[0]], screen[idx[k]], screen[idx[k + 1]]
            area = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1])
            if area == 0:
                continue
            lo_x = max(0, int(min(p0[0], p1[0], p2[0])))
            hi_x = min(size - 1, int(max(p0[0], p1[0], p2[0])) + 1)
            lo_y = max(0, int(min(p0[1], p1[1], p2[1])))
            hi_y = min(size - 1, int(max(p0[1], p1[1], p2[1])) + 1)
            for y in range(lo_y, hi_y + 1):
                for x in range(lo_x, hi_x + 1):
                    l1 = ((p2[0] - p1[0]) * (y - p1[1]) - (p2[1] - p1[1]) * (x - p1[0])) / area
                    l2 = ((p0[0] - p2[0]) * (y - p2[1]) - (p0[1] - p2[1]) * (x - p2[0])) / area
                    l3 = 1.0 - l1 - l2
                    if min(l1, l2, l3) < -1e-9:
                        continue
                    z = l1 * p0[2] + l2 * p1[2] + l3 * p2[2]
                    if z > depth[y][x]:
                        depth[y][x] = z
                        image[y][x] = colour
    return image


def write_png(path, image):
    size_y, size_x = len(image), len(image[0])
    raw = b"".join(b"\x00" + bytes(ch for px in row for ch in px) for row in image)

    def chunk(kind, body):
        return (struct.pack(">I", len(body)) + kind + body +
                struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF))

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", size_x, size_y, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw, 6)))
        f.write(chunk(b"IEND", b""))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("ply")
    parser.add_argument("png")
    parser.add_argument("--size", type=int, default=700)
    parser.add_argument("--view", choices=sorted(VIEWS), default="iso")
    parser.add_argument("--box", help="XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX: draw only faces inside")
    args = parser.parse_args()
    vertices, faces = read_ply(args.ply)
    if args.box:
        box = [float(x) for x in args.box.split(",")]
        if len(box) != 6:
            sys.exit(f"--box needs 6 numbers, got {args.box}")
        inside = [all(box[k] <= v[k] <= box[k + 3] for k in range(3)) for v in vertices]
        faces = [(idx, rgb) for idx, rgb in faces if all(inside[i] for i in idx)]
        if not faces:
            sys.exit(f"{args.ply}: no face inside --box {args.box}")
    # The view direction points from the part to the eye; depth grows towards it.
    write_png(args.png, render(vertices, faces, VIEWS[args.view], args.size))


if __name__ == "__main__":
    main()

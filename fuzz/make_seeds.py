#!/usr/bin/env python3
"""Writes the seed corpus of every fuzz target into fuzz/corpus/<target>/.

Seeds are small on purpose (libFuzzer runs faster on short inputs and
mutates them into long ones): hand-written files that reach each parser's
features (every PLY type, both byte orders, lists, extra elements, OBJ
corner forms, OFF colour variants, CRLF), and the first bytes of real files
from shared/data (read, never edited), cut to at most 4 KiB; binary STL
excerpts get their triangle count fixed so they stay well-formed.

Usage: python3 fuzz/make_seeds.py [SHARED_DATA_DIR]   (default ../shared/data)
Re-running rewrites the seeds; inputs the fuzzer found are not kept here
(scripts/fuzz.sh keeps them under build-fuzz/corpus/).
"""
import gzip
import os
import struct
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CORPUS = os.path.join(ROOT, "fuzz", "corpus")
EXCERPT = 4096

TETRA_V = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TETRA_F = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def put(target, name, data):
    folder = os.path.join(CORPUS, target)
    os.makedirs(folder, exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


def ascii_stl(crlf=False):
    lines = ["solid tetra"]
    for f in TETRA_F:
        lines += ["  facet normal 0 0 0", "    outer loop"]
        lines += ["      vertex %g %g %g" % TETRA_V[i] for i in f]
        lines += ["    endloop", "  endfacet"]
    lines.append("endsolid tetra")
    return ("\r\n" if crlf else "\n").join(lines) + "\n"


def binary_stl(header=b"binary tetra"):
    out = header.ljust(80, b" ") + struct.pack("<I", len(TETRA_F))
    for f in TETRA_F:
        out += struct.pack("<3f", 0, 0, 0)
        for i in f:
            out += struct.pack("<3f", *TETRA_V[i])
        out += b"\0\0"
    return out


def ply(encoding, vtype="float", with_normals=False, extra=False, itype="int", ctype="uchar"):
    head = ["ply", "format %s 1.0" % encoding, "comment seed"]
    head += ["element vertex %d" % len(TETRA_V)]
    head += ["property %s %s" % (vtype, c) for c in "xyz"]
    if with_normals:
        head += ["property %s %s" % (vtype, c) for c in ("nx", "ny", "nz")]
        head += ["property uchar red", "property uchar green", "property uchar blue"]
    head += ["element face %d" % len(TETRA_F)]
    head += ["property list %s %s vertex_indices" % (ctype, itype)]
    if extra:
        head += ["property list uchar float texcoord", "element edge 1",
                 "property int vertex1", "property int vertex2"]
    head.append("end_header")
    text = "\n".join(head) + "\n"
    if encoding == "ascii":
        body = ""
        for v in TETRA_V:
            body += " ".join(str(c) for c in v)
            if with_normals:
                body += " 0 0 1 255 0 0"
            body += "\n"
        for f in TETRA_F:
            body += "3 %d %d %d" % f + (" 2 0.5 0.5" if extra else "") + "\n"
        if extra:
            body += "0 1\n"
        return text.encode() + body.encode()
    order = "<" if encoding == "binary_little_endian" else ">"
    fmt = {"float": "f", "double": "d", "int": "i", "uint": "I", "short": "h",
           "ushort": "H", "uchar": "B", "char": "b", "int8": "b", "uint8": "B",
           "int16": "h", "uint16": "H", "int32": "i", "uint32": "I", "float32": "f",
           "float64": "d"}
    body = b""
    for v in TETRA_V:
        body += struct.pack(order + "3" + fmt[vtype], *v)
        if with_normals:
            body += struct.pack(order + "3" + fmt[vtype], 0, 0, 1) + bytes([255, 0, 0])
    for f in TETRA_F:
        body += struct.pack(order + fmt[ctype], 3) + struct.pack(order + "3" + fmt[itype], *f)
        if extra:
            body += struct.pack(order + "B2f", 2, 0.5, 0.5)
    if extra:
        body += struct.pack(order + "2i", 0, 1)
    return text.encode() + body


def excerpt(path, size=EXCERPT):
    with open(path, "rb") as f:
        return f.read(size)


def binary_stl_excerpt(path, triangles):
    data = excerpt(path, 84 + 50 * triangles)
    n = (len(data) - 84) // 50
    return data[:80] + struct.pack("<I", n) + data[84:84 + 50 * n]


def upload_request(text):
    """Serialises an UploadRequest given in protobuf text format."""
    proto_dir = os.path.join(ROOT, "proto")
    return subprocess.run(
        ["protoc", "-I", proto_dir, "--encode=meshseg.v1.UploadRequest",
         os.path.join(proto_dir, "meshseg", "v1", "service.proto")],
        input=text.encode(), check=True, capture_output=True).stdout


# A 3 x 2 x 2 volume whose values name their index (the volume readers'
# tests use the same kind of ramp), in every sample type.
VOLUME_DIMS = (3, 2, 2)
VOLUME_TYPES = {"uint8": "B", "uint16": "H", "int16": "h", "float32": "f"}


def samples(vtype, big=False):
    n = VOLUME_DIMS[0] * VOLUME_DIMS[1] * VOLUME_DIMS[2]
    values = [x * 0.5 if vtype == "float32" else (x * 7 - 40 if vtype == "int16" else x * 3)
              for x in range(n)]
    return struct.pack((">" if big else "<") + VOLUME_TYPES[vtype] * n, *values)


def nrrd(vtype, nrrd_type, big=False, encoding="raw", geometry="directions", crlf=False):
    head = ["NRRD0004", "# seed", "type: %s" % nrrd_type, "dimension: 3",
            "sizes: %d %d %d" % VOLUME_DIMS, "endian: %s" % ("big" if big else "little"),
            "encoding: %s" % encoding]
    if geometry == "directions":
        head += ["space: 3D-right-handed",
                 "space directions: (0.5,0,0) (0,0.75,0) (0,0,1.25)",
                 "space origin: (1.5,-2,3.25)", "kinds: domain domain domain"]
    else:
        head += ["spacings: 0.5 0.75 1.25", "byte skip: 0", "key:=value"]
    data = samples(vtype, big)
    if encoding == "gzip":
        data = gzip.compress(data, mtime=0)
    eol = "\r\n" if crlf else "\n"
    return (eol.join(head) + eol + eol).encode() + data


def metaimage(vtype, big=False, data_file="LOCAL"):
    met = {"uint8": "MET_UCHAR", "uint16": "MET_USHORT", "int16": "MET_SHORT",
           "float32": "MET_FLOAT"}[vtype]
    head = ("ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = %s\n"
            "CompressedData = False\nTransformMatrix = 1 0 0 0 1 0 0 0 1\nOffset = 1.5 -2 3.25\n"
            "ElementSpacing = 0.5 0.75 1.25\nDimSize = %d %d %d\nElementType = %s\n"
            "ElementDataFile = %s\n") % ((("True" if big else "False"),) + VOLUME_DIMS + (met, data_file))
    return head.encode() + (samples(vtype, big) if data_file == "LOCAL" else b"")


def raw_volume(vtype, big=False, dims=VOLUME_DIMS):
    """fuzz/volume_targets.h FuzzRawVolume: a 73-byte layout, then the samples."""
    flags = list(VOLUME_TYPES).index(vtype) | (4 if big else 0)
    layout = struct.pack("<B3q3d3d", flags, *dims, 0.5, 0.75, 1.25, 1.5, -2, 3.25)
    return layout + samples(vtype, big)


def main():
    data = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "..", "shared", "data")

    put("stl_ascii", "tetra.stl", ascii_stl())
    put("stl_ascii", "tetra_crlf.stl", ascii_stl(crlf=True))
    put("stl_ascii", "no_endloop.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
        "vertex 1 0 0\nvertex 0 1 0\n")
    put("stl_ascii", "tray_bottom_excerpt.stl", excerpt(os.path.join(data, "tray_bottom_1002.stl")))
    put("stl_ascii", "aagnet_partB_excerpt.stl",
        excerpt(os.path.join(data, "cad", "whjdark_AAGNet__partB.stl")))

    put("stl_binary", "tetra.stl", binary_stl())
    put("stl_binary", "tetra_solid_header.stl", binary_stl(b"solid but binary"))
    put("stl_binary", "plate_holes_excerpt.stl",
        binary_stl_excerpt(os.path.join(data, "plate_holes.stl"), 40))
    put("stl_binary", "torus_excerpt.stl", binary_stl_excerpt(os.path.join(data, "torus.stl"), 40))

    put("obj", "tetra.obj", "".join("v %g %g %g\n" % v for v in TETRA_V) +
        "".join("f %d %d %d\n" % tuple(i + 1 for i in f) for f in TETRA_F))
    put("obj", "corner_forms.obj", "# comment\nmtllib x.mtl\no part\nv 0 0 0\nv 1 0 0 1\nv 1 1 0\n"
        "v 0 1 0\nvt 0 0\nvn 0 0 1\ng top\nusemtl m\ns 1\nf 1/1/1 2/1/1 3/1/1\nf -4//1 -2//1 -1//1\n"
        "f 1/1 3/1 4/1 2/1\nl 1 2\np 3\n")
    put("obj", "aagnet_partB.obj", excerpt(os.path.join(data, "cad", "whjdark_AAGNet__partB_stl.obj")))
    put("obj", "abc_excerpt.obj", excerpt(os.path.join(data, "abc_00007974_5.obj")))

    put("off", "tetra.off", "OFF\n4 4 6\n" + "".join("%g %g %g\n" % v for v in TETRA_V) +
        "".join("3 %d %d %d\n" % f for f in TETRA_F))
    put("off", "coff_one_line_counts.off", "COFF 4 4 0\n" +
        "".join("%g %g %g 255 0 0 255\n" % v for v in TETRA_V) +
        "".join("3 %d %d %d 0 255 0\n" % f for f in TETRA_F))
    put("off", "quad_comments.off", "# a square\nOFF\n\n4 1\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n")
    put("off", "fandisk_excerpt.off", excerpt(os.path.join(data, "fandisk.off")))

    put("ply_ascii", "tetra.ply", ply("ascii"))
    put("ply_ascii", "tetra_normals_colours.ply", ply("ascii", with_normals=True))
    put("ply_ascii", "tetra_extra_elements.ply", ply("ascii", extra=True))
    put("ply_ascii", "bunny_excerpt.ply", excerpt(os.path.join(data, "bunny_zipper_res2.ply")))
    put("ply_ascii", "points_only.ply", "ply\nformat ascii 1.0\nelement vertex 2\nproperty double x\n"
        "property double y\nproperty double z\nproperty double nx\nproperty double ny\n"
        "property double nz\nend_header\n0 0 0 0 0 1\n1 1 1 1 0 0\n")

    put("ply_binary", "tetra_le_float.ply", ply("binary_little_endian"))
    put("ply_binary", "tetra_be_double.ply", ply("binary_big_endian", vtype="double"))
    put("ply_binary", "tetra_le_normals.ply", ply("binary_little_endian", with_normals=True))
    put("ply_binary", "tetra_be_uint_ushort.ply",
        ply("binary_big_endian", vtype="int16", itype="uint", ctype="ushort", extra=True))
    put("ply_binary", "tetra_le_int8_indices.ply",
        ply("binary_little_endian", vtype="float64", itype="uint8", ctype="int8"))
    put("ply_binary", "abc_gt_excerpt.ply", excerpt(os.path.join(data, "abc_00016513_gt.ply")))

    put("xyz", "three_columns.xyz", "0 0 0\n1 0 0\n0 1 0\n")
    put("xyz", "six_columns_commas.xyz", "# x,y,z,nx,ny,nz\n0,0,0,0,0,1\n1,0,0,0,0,1\n\n0,1,0,0,0,1\n")
    put("xyz", "scan_excerpt.xyz", excerpt(os.path.join(data, "abc_00016513_scan.xyz")))
    put("xyz", "bullet_excerpt.xyz", excerpt(os.path.join(data, "broken_bullet_50k.xyz")))

    put("pwn", "three_points.pwn", "3\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n0 0 1\n0 0 1\n")
    put("pwn", "crlf_exponents.pwn", "2\r\n1e-3 -2.5E+2 .5\r\n0 0 0\r\n1 0 0\r\n0 -1 0\r\n")

    put("nrrd", "uint8_raw.nrrd", nrrd("uint8", "uchar"))
    put("nrrd", "uint16_gzip.nrrd", nrrd("uint16", "unsigned short", encoding="gzip"))
    put("nrrd", "int16_big_spacings.nrrd", nrrd("int16", "short", big=True, geometry="spacings"))
    put("nrrd", "float_crlf.nrrd", nrrd("float32", "float", crlf=True))
    put("nrrd", "detached.nhdr", nrrd("uint8", "uint8", geometry="spacings")[:-12]
        .replace(b"encoding: raw\n", b"encoding: raw\ndata file: part.raw\n"))

    put("mha", "uint8.mha", metaimage("uint8"))
    put("mha", "int16_big.mha", metaimage("int16", big=True))
    put("mha", "float.mha", metaimage("float32"))
    put("mhd", "uint16_local.mhd", metaimage("uint16"))
    put("mhd", "detached.mhd", metaimage("uint8", data_file="part.zraw"))

    for vtype in VOLUME_TYPES:
        put("raw", "%s_le" % vtype, raw_volume(vtype))
    put("raw", "int16_be", raw_volume("int16", big=True))
    put("raw", "wrong_size", raw_volume("uint8", dims=(3, 2, 3)))

    # Content sniffing sees every format without its extension.
    for target in ("stl_ascii", "stl_binary", "obj", "off", "ply_ascii", "ply_binary", "xyz", "pwn",
                   "nrrd", "mha"):
        folder = os.path.join(CORPUS, target)
        for name in sorted(os.listdir(folder))[:2]:
            put("sniffed", "%s_%s" % (target, name.rsplit(".", 1)[0]), excerpt(os.path.join(folder, name)))

    put("upload_header", "plain", upload_request(
        'header { file_name: "part.stl" total_size: 1000 }'))
    put("upload_header", "all_fields", upload_request(
        'header { file_name: "dir/part.PLY" format_hint: "ply" total_size: 2147483648 '
        'sha256: "9f86d081884c7d659a2feaa0c55ad015a3bf4f1b2b0b822cd15d6c15b0f00a08" '
        'options { distance_tolerance: 0.5 angle_tolerance_deg: 5 } }'))
    put("upload_header", "bad_values", upload_request(
        'header { file_name: "x" format_hint: "step" total_size: -1 sha256: "zz" '
        'options { distance_tolerance: -0.0 angle_tolerance_deg: 1e308 } }'))
    put("upload_header", "chunk_not_header", upload_request('chunk: "solid x"'))


if __name__ == "__main__":
    main()

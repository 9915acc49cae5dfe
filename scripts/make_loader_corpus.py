#!/usr/bin/env python3
"""Writes the loader corpus in tests/fuzz/corpus/: small mesh files, each a few KB at most, that the core test
LoaderCorpus.* replays through loadMesh (and that seed the libFuzzer harness). Files named accept-* must load
as sound solids, refuse-* must be refused with a clear message; every one of them, read as any of the four
formats, must keep loadMesh's promise. Run it again after adding a case; the output is deterministic."""
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "tests", "fuzz", "corpus")

CUBE_V = [(0, 0, 0), (10, 0, 0), (10, 10, 0), (0, 10, 0), (0, 0, 10), (10, 0, 10), (10, 10, 10), (0, 10, 10)]
CUBE_F = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4),
          (3, 7, 6), (3, 6, 2), (0, 4, 7), (0, 7, 3), (1, 2, 6), (1, 6, 5)]


def cube(origin=(0, 0, 0), size=10.0, inward=False):
    vs = [tuple(o + c / 10.0 * size for o, c in zip(origin, v)) for v in CUBE_V]
    fs = [(a, c, b) if inward else (a, b, c) for a, b, c in CUBE_F]
    return vs, fs


def join(*meshes):
    vs, fs = [], []
    for mv, mf in meshes:
        base = len(vs)
        vs += mv
        fs += [tuple(i + base for i in f) for f in mf]
    return vs, fs


def num(x):
    return repr(float(x)) if not isinstance(x, str) else x


def off(mesh, replace=None):
    vs, fs = mesh
    lines = ["OFF", "%d %d 0" % (len(vs), len(fs))]
    for i, v in enumerate(vs):
        coords = [num(c) for c in v]
        if replace and replace[0] == i:
            coords[0] = replace[1]
        lines.append(" ".join(coords))
    lines += ["3 %d %d %d" % f for f in fs]
    return "\n".join(lines) + "\n"


def obj(mesh, replace=None):
    vs, fs = mesh
    lines = []
    for i, v in enumerate(vs):
        coords = [num(c) for c in v]
        if replace and replace[0] == i:
            coords[0] = replace[1]
        lines.append("v " + " ".join(coords))
    lines += ["f %d %d %d" % tuple(i + 1 for i in f) for f in fs]
    return "\n".join(lines) + "\n"


def ply_ascii(mesh, replace=None):
    vs, fs = mesh
    head = ("ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
            "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (len(vs), len(fs)))
    lines = []
    for i, v in enumerate(vs):
        coords = [num(c) for c in v]
        if replace and replace[0] == i:
            coords[0] = replace[1]
        lines.append(" ".join(coords))
    lines += ["3 %d %d %d" % f for f in fs]
    return head + "\n".join(lines) + "\n"


def ply_binary(mesh, x_of_vertex6=None, face_count=None):
    vs, fs = mesh
    head = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty double x\nproperty double y\n"
            "property double z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
            % (len(vs), face_count if face_count is not None else len(fs))).encode()
    body = b""
    for i, v in enumerate(vs):
        x = x_of_vertex6 if (x_of_vertex6 is not None and i == 6) else v[0]
        body += struct.pack("<3d", x, v[1], v[2])
    for f in fs:
        body += struct.pack("<B3i", 3, *f)
    return head + body


def stl_ascii(mesh, replace_token=None):
    vs, fs = mesh
    lines = ["solid corpus"]
    for n, f in enumerate(fs):
        lines += [" facet normal 0 0 0", "  outer loop"]
        for k, i in enumerate(f):
            coords = [num(c) for c in vs[i]]
            if replace_token and n == 0 and k == 1:
                coords[0] = replace_token
            lines.append("   vertex " + " ".join(coords))
        lines += ["  endloop", " endfacet"]
    lines.append("endsolid corpus")
    return "\n".join(lines) + "\n"


def stl_binary(mesh, announced=None):
    vs, fs = mesh
    data = b"binary corpus".ljust(80, b"\0") + struct.pack("<I", len(fs) if announced is None else announced)
    for f in fs:
        data += struct.pack("<3f", 0, 0, 0)
        for i in f:
            data += struct.pack("<3f", *vs[i])
        data += b"\0\0"
    return data


def double_cone(segments):
    vs = [(0.0, 0.0, 0.0)]
    fs = []
    for z, up in ((10.0, True), (-10.0, False)):
        centre = len(vs)
        vs.append((0.0, 0.0, z))
        ring = len(vs)
        for i in range(segments):
            a = 2 * math.pi * i / segments
            vs.append((round(5 * math.cos(a), 6), round(5 * math.sin(a), 6), z))
        for i in range(segments):
            p, q = ring + i, ring + (i + 1) % segments
            fs += [(0, q, p), (centre, p, q)] if up else [(0, p, q), (centre, q, p)]
    return vs, fs


FLAT_TETRA = ([(0, 0, 0), (10, 0, 0), (0, 10, 0), (3, 3, 0)], [(0, 1, 2), (0, 3, 1), (1, 3, 2), (2, 3, 0)])


def cases():
    c = cube()
    yield "accept-off-cube.off", off(c)
    yield "accept-off-comments-and-colours.off", ("# cube\nOFF 8 12 0\n" + "\n".join(
        " ".join(num(x) for x in v) + " # corner" for v in c[0]) + "\n" +
        "\n".join("3 %d %d %d 0.5 0.5 0.5" % f for f in c[1]) + "\n")
    yield "accept-obj-cube.obj", obj(c)
    yield "accept-ply-ascii-cube.ply", ply_ascii(c)
    yield "accept-ply-binary-cube.ply", ply_binary(c)
    yield "accept-stl-ascii-cube.stl", stl_ascii(c)
    yield "accept-stl-binary-cube.stl", stl_binary(c)
    yield "accept-off-cube-with-cavity.off", off(join(cube((0, 0, 0), 30), cube((10, 10, 10), 10)))
    yield "accept-off-inside-out-cube.off", off(cube(inward=True))
    # Number tokens other readers misread (issue 14, item 3).
    for token, name in (("1e39", "1e39"), ("0x10", "hex"), ("nan", "nan"), ("inf", "inf"), ("1e999", "1e999"),
                        ("-4e38", "minus-4e38"), ("0x1p3", "hexfloat")):
        yield "refuse-off-coordinate-%s.off" % name, off(c, (6, token))
        yield "refuse-obj-coordinate-%s.obj" % name, obj(c, (6, token))
        yield "refuse-ply-ascii-coordinate-%s.ply" % name, ply_ascii(c, (6, token))
    yield "refuse-stl-ascii-coordinate-hex.stl", stl_ascii(c, "0x10")
    yield "refuse-stl-ascii-coordinate-1e39.stl", stl_ascii(c, "1e39")
    yield "refuse-ply-binary-coordinate-1e39.ply", ply_binary(c, x_of_vertex6=1e39)
    yield "refuse-off-index-hex.off", off(c).replace("3 0 2 1\n", "3 0 2 0x1\n")
    yield "refuse-off-count-1e39.off", off(c).replace("8 12 0", "8 1e39 0")
    yield "refuse-off-lying-counts.off", off(c).replace("8 12 0", "8 120000000 0")
    yield "refuse-off-truncated.off", off(c)[:-40]
    yield "refuse-ply-lying-face-count.ply", ply_binary(c, face_count=50000000)
    yield "refuse-stl-binary-lying-count.stl", stl_binary(c, announced=4000000000)
    # Mesh checks (item 5).
    yield "refuse-off-overlapping-shells.off", off(join(cube(), cube((5, 5, 5))))
    yield "refuse-off-flat-tetrahedron.off", off(FLAT_TETRA)
    yield "refuse-off-double-cone.off", off(double_cone(48))
    yield "refuse-obj-open-cube.obj", obj((c[0], c[1][:-1]))


def main():
    os.makedirs(OUT, exist_ok=True)
    for name, content in cases():
        data = content.encode() if isinstance(content, str) else content
        assert len(data) <= 8192, name
        with open(os.path.join(OUT, name), "wb") as f:
            f.write(data)


if __name__ == "__main__":
    main()

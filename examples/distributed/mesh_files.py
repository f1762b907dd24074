"""mesh_files.py: the cluster route's file formats - OBJ, OFF and PLY (ASCII and binary) meshes in,
the `.ma` skeleton out - read and written as the coverage-axis tool does (examples/io/mesh_io.cpp),
so a skeleton made here is byte-identical to the tool's on the same file.

Reading follows the tool's rules: polygons are fan-triangulated (v0 vk vk+1), OBJ indices are
1-based (negative ones count back from the last vertex), empty faces are skipped, faces with 1 or 2
vertices, bad numbers and out-of-range indices are errors (MeshError, with the file and line)."""
import os
import struct

import numpy as np

MESH_EXTENSIONS = (".obj", ".off", ".ply")


class MeshError(Exception):
    """A mesh file could not be read: the message names the file (and the line when known)."""


def _fail(path, line, what):
    raise MeshError("%s:%d: %s" % (path, line, what) if line else "%s: %s" % (path, what))


def _number(path, line, token):
    try:
        return float(token)  # accepts inf/nan and a leading '+', as the tool's parser does
    except ValueError:
        _fail(path, line, "bad number '%s'" % token)


def _index(path, line, token):
    try:
        return int(token)
    except ValueError:
        _fail(path, line, "bad face index '%s'" % token)


def _fan(poly, triangles):
    for k in range(1, len(poly) - 1):
        triangles.append((poly[0], poly[k], poly[k + 1]))


def _content_lines(text):
    """(line number, tokens) of every line with content after its '#' comment is stripped."""
    for number, line in enumerate(text.split("\n"), 1):
        tokens = line.split("#", 1)[0].split()
        if tokens:
            yield number, tokens


def _read_obj(path, text):
    vertices, triangles, forward = [], [], (0, 0)
    for number, t in _content_lines(text):
        if t[0] == "v":
            if len(t) < 4:
                _fail(path, number, "vertex needs 3 coordinates")
            vertices.append([_number(path, number, c) for c in t[1:4]])
        elif t[0] == "f":
            poly = []
            for token in t[1:]:
                idx = _index(path, number, token.split("/", 1)[0])
                if idx < 0:
                    if len(vertices) + idx < 0:
                        _fail(path, number, "face index %d out of range (%d vertices)" % (idx, len(vertices)))
                    poly.append(len(vertices) + idx)
                elif idx == 0:
                    _fail(path, number, "face index 0 (OBJ indices start at 1)")
                else:
                    if idx > len(vertices) and idx > forward[0]:
                        forward = (idx, number)  # may refer to a vertex defined later
                    poly.append(idx - 1)
            if 0 < len(poly) < 3:
                _fail(path, number, "face with %d vertices (need at least 3)" % len(poly))
            _fan(poly, triangles)
    if not vertices:
        _fail(path, 0, "no vertices")
    if forward[0] > len(vertices):
        _fail(path, forward[1], "face index %d out of range (%d vertices)" % (forward[0], len(vertices)))
    return vertices, triangles


def _read_off(path, text):
    lines = _content_lines(text)
    number, t = next(lines, (0, None))
    if t is None:
        _fail(path, 0, "empty file (expected OFF header)")
    keyword = t[0]
    if not (keyword.endswith("OFF") and all(c in "STCN" for c in keyword[:-3])):
        _fail(path, number, "not an OFF file (header '%s')" % keyword)
    normals = "N" in keyword[:-3]
    counts = t[1:]
    if len(counts) < 2:
        number, counts = next(lines, (0, []))
    if len(counts) < 2:
        _fail(path, number, "missing vertex and face counts")
    nv, nf = _index(path, number, counts[0]), _index(path, number, counts[1])
    vertices, triangles = [], []
    for i in range(nv):
        number, t = next(lines, (0, None))
        if t is None:
            _fail(path, 0, "file truncated: expected %d vertices, found %d" % (nv, i))
        if len(t) < (6 if normals else 3):
            _fail(path, number, "vertex needs %s" % ("6 values (x y z nx ny nz)" if normals else "3 coordinates"))
        vertices.append([_number(path, number, c) for c in t[:3]])
    for i in range(nf):
        number, t = next(lines, (0, None))
        if t is None:
            _fail(path, 0, "file truncated: expected %d faces, found %d" % (nf, i))
        k = _index(path, number, t[0])
        if k == 0:
            continue
        if k < 3 or len(t) < k + 1:
            _fail(path, number, "face with %d vertices (need at least 3, listed)" % k)
        poly = [_index(path, number, x) for x in t[1:k + 1]]
        if any(i < 0 or i >= nv for i in poly):
            _fail(path, number, "face index out of range (%d vertices)" % nv)
        _fan(poly, triangles)
    if not vertices:
        _fail(path, 0, "no vertices")
    return vertices, triangles


_PLY_TYPES = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
              "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I",
              "float": "f", "float32": "f", "double": "d", "float64": "d"}


def _read_ply(path, data):
    end = data.find(b"end_header")
    if not data.startswith(b"ply") or end < 0:
        _fail(path, 1, "not a PLY file")
    body_start = data.index(b"\n", end) + 1
    header = data[:end].decode("ascii", "replace").split("\n")
    fmt, elements = None, []  # elements: [name, count, [(name, type, list count type or None)]]
    for line in header:
        t = line.split()
        if not t:
            continue
        if t[0] == "format":
            fmt = t[1]
        elif t[0] == "element":
            elements.append([t[1], int(t[2]), []])
        elif t[0] == "property" and elements:
            if t[1] == "list":
                elements[-1][2].append((t[4], _PLY_TYPES[t[3]], _PLY_TYPES[t[2]]))
            else:
                elements[-1][2].append((t[2], _PLY_TYPES[t[1]], None))
    if fmt not in ("ascii", "binary_little_endian", "binary_big_endian"):
        _fail(path, 2, "unsupported PLY format '%s'" % fmt)
    order = "<" if fmt == "binary_little_endian" else ">"
    tokens = iter(data[body_start:].split()) if fmt == "ascii" else None
    offset = body_start

    def value(kind):
        nonlocal offset
        if tokens is not None:
            token = next(tokens, None)
            if token is None:
                _fail(path, 0, "file truncated")
            return float(token) if kind in "fd" else int(token)
        size = struct.calcsize(kind)
        if offset + size > len(data):
            _fail(path, 0, "file truncated")
        (v,) = struct.unpack_from(order + kind, data, offset)
        offset += size
        return v

    vertices, triangles = [], []
    for name, count, props in elements:
        for _ in range(count):
            row = {}
            for pname, kind, list_kind in props:
                row[pname] = [value(kind) for _ in range(value(list_kind))] if list_kind else value(kind)
            if name == "vertex":
                vertices.append([float(row["x"]), float(row["y"]), float(row["z"])])
            elif name == "face":
                poly = row.get("vertex_indices", row.get("vertex_index", []))
                if 0 < len(poly) < 3:
                    _fail(path, 0, "face with %d vertices (need at least 3)" % len(poly))
                _fan(poly, triangles)
    if not vertices:
        _fail(path, 0, "no vertices")
    if any(i < 0 or i >= len(vertices) for tri in triangles for i in tri):
        _fail(path, 0, "face index out of range (%d vertices)" % len(vertices))
    return vertices, triangles


def read_mesh(path):
    """(vertices (n, 3) float64, triangles (m, 3) uint32) of an .obj, .off or .ply file."""
    ext = os.path.splitext(path)[1].lower()
    if ext not in MESH_EXTENSIONS:
        _fail(path, 0, "unknown mesh format '%s' (expected .obj, .off or .ply)" % ext)
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        _fail(path, 0, "cannot open: %s" % e.strerror)
    if ext == ".ply":
        vertices, triangles = _read_ply(path, data)
    else:
        text = data.decode("utf-8", "replace")
        vertices, triangles = (_read_obj if ext == ".obj" else _read_off)(path, text)
    return (np.array(vertices, dtype=np.float64).reshape(-1, 3),
            np.array(triangles, dtype=np.uint32).reshape(-1, 3))


def ma_bytes(skeleton):
    """The skeleton as the tool's `.ma` text: "nv ne nf", "v x y z r" (%.9g), "e i j" (the
    skeleton's edges, then every face edge not among them, in face order), "f i j k"."""
    edges = [(int(a), int(b)) for a, b in np.asarray(skeleton.edges).reshape(-1, 2)]
    faces = [tuple(int(i) for i in f) for f in np.asarray(skeleton.faces).reshape(-1, 3)]
    have = {(min(a, b), max(a, b)) for a, b in edges}
    for f in faces:
        for k in range(3):
            a, b = f[k], f[(k + 1) % 3]
            if (min(a, b), max(a, b)) not in have:
                have.add((min(a, b), max(a, b)))
                edges.append((a, b))
    centers = np.asarray(skeleton.centers).reshape(-1, 3)
    radii = np.asarray(skeleton.radii).reshape(-1)
    out = ["%d %d %d\n" % (len(radii), len(edges), len(faces))]
    out += ["v %.9g %.9g %.9g %.9g\n" % (c[0], c[1], c[2], r) for c, r in zip(centers.tolist(), radii.tolist())]
    out += ["e %d %d\n" % e for e in edges]
    out += ["f %d %d %d\n" % f for f in faces]
    return "".join(out).encode("ascii")

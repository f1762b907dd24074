#!/usr/bin/env python3
"""make_formats.py: writes the reader test models of tests/data/formats from the bundled models.

fox.obj (triangle mesh) becomes: fox.off, fox.ply (binary), fox.stl (binary), fox_ascii.stl,
fox.gltf + fox.bin (external buffer), fox_embedded.gltf (data URI), fox.glb, fox_nodes.gltf
(the mesh stored in node-local coordinates under a matrix node and a TRS node, so its world
coordinates are fox.obj's; a second, non-default scene holds a decoy copy) and fox.dae (Collada,
read through assimp). The first 500 points of fish_points.xyz (x y z nx ny nz) become the point
cloud variants: fish500.xyz, fish500_nonormals.xyz, fish500.ply (binary, normals),
fish500_nonormals.ply (ascii), fish500.obj (v + vn), fish500_nonormals.obj, fish500.pts (count
line, x y z intensity r g b) and fish500_plain.pts (x y z only, no count line).
Positions are rounded to float32 where the format stores floats. Run from anywhere:
    python3 tests/data/formats/make_formats.py
"""
import base64
import json
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.dirname(HERE)


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def read_obj(path):
    v, f = [], []
    for line in open(path):
        t = line.split()
        if not t:
            continue
        if t[0] == "v":
            v.append(tuple(float(x) for x in t[1:4]))
        elif t[0] == "f":
            idx = [int(x.split("/")[0]) - 1 for x in t[1:]]
            for k in range(1, len(idx) - 1):
                f.append((idx[0], idx[k], idx[k + 1]))
    return v, f


def out(name, data, mode="w"):
    with open(os.path.join(HERE, name), mode) as fh:
        fh.write(data)


def num(x):
    return "%.9g" % x


# ---- meshes from fox.obj ----
V, F = read_obj(os.path.join(DATA, "fox.obj"))
V = [tuple(f32(c) for c in p) for p in V]

out("fox.off", "OFF\n%d %d 0\n" % (len(V), len(F)) +
    "".join("%s %s %s\n" % tuple(map(num, p)) for p in V) +
    "".join("3 %d %d %d\n" % t for t in F))

ply = ("ply\nformat binary_little_endian 1.0\ncomment derived from fox.obj\nelement vertex %d\n"
       "property float x\nproperty float y\nproperty float z\nelement face %d\n"
       "property list uchar int vertex_indices\nend_header\n" % (len(V), len(F))).encode()
ply += b"".join(struct.pack("<3f", *p) for p in V)
ply += b"".join(struct.pack("<B3i", 3, *t) for t in F)
out("fox.ply", ply, "wb")


def normal(t):
    a, b, c = V[t[0]], V[t[1]], V[t[2]]
    u = [b[i] - a[i] for i in range(3)]
    w = [c[i] - a[i] for i in range(3)]
    n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
    s = math.sqrt(sum(x * x for x in n)) or 1.0
    return [x / s for x in n]


stl = b"binary STL derived from fox.obj".ljust(80, b" ") + struct.pack("<I", len(F))
for t in F:
    stl += struct.pack("<3f", *normal(t)) + b"".join(struct.pack("<3f", *V[i]) for i in t) + b"\0\0"
out("fox.stl", stl, "wb")
ascii_stl = "solid fox\n"
for t in F:
    ascii_stl += "  facet normal %s %s %s\n    outer loop\n" % tuple(map(num, normal(t)))
    for i in t:
        ascii_stl += "      vertex %s %s %s\n" % tuple(map(num, V[i]))
    ascii_stl += "    endloop\n  endfacet\n"
out("fox_ascii.stl", ascii_stl + "endsolid fox\n")


def gltf_buffer(points):
    pos = b"".join(struct.pack("<3f", *p) for p in points)
    idx = b"".join(struct.pack("<3H", *t) for t in F)
    idx += b"\0" * (-len(idx) % 4)
    lo = [min(p[i] for p in points) for i in range(3)]
    hi = [max(p[i] for p in points) for i in range(3)]
    return pos + idx, len(pos), len(idx), lo, hi


def gltf_doc(points, uri, nodes, scenes):
    data, npos, nidx, lo, hi = gltf_buffer(points)
    doc = {
        "asset": {"version": "2.0", "generator": "coverage-axis tests/data/formats/make_formats.py"},
        "scene": 0, "scenes": scenes, "nodes": nodes,
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(points), "type": "VEC3", "min": lo, "max": hi},
            {"bufferView": 1, "componentType": 5123, "count": 3 * len(F), "type": "SCALAR"}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": npos, "target": 34962},
                        {"buffer": 0, "byteOffset": npos, "byteLength": 3 * 2 * len(F), "target": 34963}],
        "buffers": [{"byteLength": len(data)}],
    }
    if uri is not None:
        doc["buffers"][0]["uri"] = uri
    return doc, data


plain_nodes = [{"mesh": 0}]
doc, data = gltf_doc(V, "fox.bin", plain_nodes, [{"nodes": [0]}])
out("fox.gltf", json.dumps(doc, indent=1) + "\n")
out("fox.bin", data, "wb")
doc, data = gltf_doc(V, "data:application/octet-stream;base64," + base64.b64encode(data).decode(),
                     plain_nodes, [{"nodes": [0]}])
out("fox_embedded.gltf", json.dumps(doc, indent=1) + "\n")
doc, data = gltf_doc(V, None, plain_nodes, [{"nodes": [0]}])
js = json.dumps(doc).encode()
js += b" " * (-len(js) % 4)
glb = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(js) + 8 + len(data))
glb += struct.pack("<I4s", len(js), b"JSON") + js + struct.pack("<I4s", len(data), b"BIN\0") + data
out("fox.glb", glb, "wb")

# Node transforms: root matrix M (rotation 90 degrees about z, translation (1, 2, 3)), child TRS
# (translation (-5, 0, 2), rotation 30 degrees about x, uniform scale 2). The mesh is stored as
# inverse(M * T * R * S) * p so that its world coordinates are fox.obj's.
c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
half = math.radians(30) / 2
child = {"mesh": 0, "translation": [-5.0, 0.0, 2.0], "rotation": [math.sin(half), 0.0, 0.0, math.cos(half)],
         "scale": [2.0, 2.0, 2.0]}
root = {"children": [1], "matrix": [0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 1, 2, 3, 1]}
decoy = {"mesh": 0, "translation": [100.0, 0.0, 0.0]}


def to_local(p):
    # inverse of M: subtract (1, 2, 3), rotate by -90 degrees about z
    q = [p[0] - 1, p[1] - 2, p[2] - 3]
    q = [q[1], -q[0], q[2]]
    # inverse of T
    q = [q[0] + 5, q[1], q[2] - 2]
    # inverse of R (rotation about x by -30 degrees)
    q = [q[0], c * q[1] + s * q[2], -s * q[1] + c * q[2]]
    # inverse of S
    return tuple(f32(x / 2) for x in q)


doc, data = gltf_doc([to_local(p) for p in V],
                     None, [root, child, decoy], [{"nodes": [0]}, {"nodes": [2]}])
doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
out("fox_nodes.gltf", json.dumps(doc, indent=1) + "\n")

dae = """<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><contributor><authoring_tool>make_formats.py (derived from fox.obj)</authoring_tool></contributor>
    <unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>
  <library_geometries>
    <geometry id="fox" name="fox"><mesh>
      <source id="fox-pos"><float_array id="fox-pos-array" count="%d">%s</float_array>
        <technique_common><accessor source="#fox-pos-array" count="%d" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common></source>
      <vertices id="fox-vtx"><input semantic="POSITION" source="#fox-pos"/></vertices>
      <triangles count="%d"><input semantic="VERTEX" source="#fox-vtx" offset="0"/><p>%s</p></triangles>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes><visual_scene id="scene"><node id="fox-node">
    <instance_geometry url="#fox"/></node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
""" % (3 * len(V), " ".join(num(x) for p in V for x in p), len(V), len(F), " ".join(str(i) for t in F for i in t))
out("fox.dae", dae)

# ---- point clouds from fish_points.xyz ----
P = []
for line in open(os.path.join(DATA, "fish_points.xyz")):
    t = line.split()
    if len(t) == 6:
        P.append(tuple(float(x) for x in t))
    if len(P) == 500:
        break
P = [tuple(f32(x) for x in p) for p in P]
out("fish500.xyz", "".join(" ".join(map(num, p)) + "\n" for p in P))
out("fish500_nonormals.xyz", "".join(" ".join(map(num, p[:3])) + "\n" for p in P))
ply = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
       "property float z\nproperty float nx\nproperty float ny\nproperty float nz\nend_header\n" % len(P)).encode()
out("fish500.ply", ply + b"".join(struct.pack("<6f", *p) for p in P), "wb")
out("fish500_nonormals.ply", "ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
    "property float z\nend_header\n" % len(P) + "".join(" ".join(map(num, p[:3])) + "\n" for p in P))
out("fish500.obj", "".join("v %s %s %s\n" % tuple(map(num, p[:3])) for p in P) +
    "".join("vn %s %s %s\n" % tuple(map(num, p[3:])) for p in P))
out("fish500_nonormals.obj", "".join("v %s %s %s\n" % tuple(map(num, p[:3])) for p in P))
out("fish500.pts", "%d\n" % len(P) + "".join(
    "%s %s %s %d %d %d %d\n" % (num(p[0]), num(p[1]), num(p[2]), -1000 + i % 2000, i % 256, (2 * i) % 256, 128)
    for i, p in enumerate(P)))
out("fish500_plain.pts", "".join(" ".join(map(num, p[:3])) + "\n" for p in P))

#!/usr/bin/env python3
"""make_formats.py: writes the reader test models of tests/data/formats from the bundled models.

fox.obj (triangle mesh) becomes: fox.off, fox.ply (binary), fox.stl (binary), fox_ascii.stl,
fox.gltf + fox.bin (external buffer), fox_embedded.gltf (data URI), fox.glb, fox_nodes.gltf
(the mesh stored in node-local coordinates under a matrix node and a TRS node, so its world
coordinates are fox.obj's; a second, non-default scene holds a decoy copy), and for the formats read
through assimp fox.dae (Collada), fox.ac (AC3D), fox.md3 (Quake 3, positions in 1/64 units),
fox.3ds, fox.x (DirectX text), fox.fbx (FBX 7.4 ASCII), fox_binary.fbx (FBX 7.4 binary) and
fox.blend (Blender 2.48 layout), each in its format's own axes and winding so that assimp's
conversions give fox.obj's triangles back. The first 500 points of
fish_points.xyz (x y z nx ny nz) become the point cloud variants: fish500.xyz,
fish500_nonormals.xyz, fish500.ply (binary, normals), fish500_nonormals.ply (ascii), fish500.obj
(v + vn), fish500_nonormals.obj, fish500.pts (count line, x y z intensity r g b) and
fish500_plain.pts (x y z only, no count line).
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

# 3DS: main chunk > editor > object "fox" > triangle mesh (vertex list, face list); 16-bit counts.
# 3DS is z-up: assimp turns (x, y, z) into (x, z, -y), so the file stores (x, -z, y)
def chunk(cid, body):
    return struct.pack("<HI", cid, 6 + len(body)) + body


vertices = chunk(0x4110, struct.pack("<H", len(V)) + b"".join(struct.pack("<3f", p[0], -p[2], p[1]) for p in V))
faces = chunk(0x4120, struct.pack("<H", len(F)) + b"".join(struct.pack("<4H", t[0], t[1], t[2], 0) for t in F))
editor = chunk(0x3D3D, chunk(0x3D3E, struct.pack("<I", 3)) + chunk(0x4000, b"fox\0" + chunk(0x4100, vertices + faces)))
out("fox.3ds", chunk(0x4D4D, chunk(0x0002, struct.pack("<I", 3)) + editor), "wb")

# AC3D (text): one poly object under the world, one material; each triangle a surface of 3 refs
out("fox.ac", "AC3Db\nMATERIAL \"fox\" rgb 1 1 1 amb 0.2 0.2 0.2 emis 0 0 0 spec 0.5 0.5 0.5 shi 10 trans 0\n"
    "OBJECT world\nkids 1\nOBJECT poly\nname \"fox\"\nnumvert %d\n" % len(V) +
    "".join("%s %s %s\n" % tuple(map(num, p)) for p in V) + "numsurf %d\n" % len(F) +
    "".join("SURF 0x10\nmat 0\nrefs 3\n%d 0 0\n%d 0 0\n%d 0 0\n" % t for t in F) + "kids 0\n")

# Quake 3 MD3: one frame, one surface without shaders; positions are int16 in units of 1/64 (fox
# fits: |coordinate| < 512), z-up and clockwise, which assimp turns into (x, z, -y) and
# counter-clockwise: the file stores (x, -z, y) and each triangle's winding reversed
MD3_SCALE = 64
frame = struct.pack("<10f16s", *[min(p[i] for p in V) for i in range(3)], *[max(p[i] for p in V) for i in range(3)],
                    0, 0, 0, max(math.sqrt(sum(x * x for x in p)) for p in V), b"fox")
triangles = b"".join(struct.pack("<3I", t[0], t[2], t[1]) for t in F)
st = struct.pack("<%df" % (2 * len(V)), *([0.0] * 2 * len(V)))
xyz = b"".join(struct.pack("<3hH", *(round(c * MD3_SCALE) for c in (p[0], -p[2], p[1])), 0) for p in V)
surface_head = 108
surface = struct.pack("<4s64s10i", b"IDP3", b"fox", 0, 1, 0, len(V), len(F), surface_head, surface_head,
                      surface_head + len(triangles), surface_head + len(triangles) + len(st),
                      surface_head + len(triangles) + len(st) + len(xyz)) + triangles + st + xyz
md3_head = 108
out("fox.md3", struct.pack("<4si64s9i", b"IDP3", 15, b"fox", 0, 1, 0, 1, 0, md3_head, md3_head + len(frame),
                           md3_head + len(frame), md3_head + len(frame) + len(surface)) + frame + surface, "wb")

# DirectX .x (text): left-handed, so it stores z negated and each triangle's winding reversed,
# which assimp's conversion to right-handed coordinates undoes
out("fox.x", "xof 0303txt 0032\nMesh fox {\n %d;\n" % len(V) +
    ",\n".join(" %s;%s;%s;" % (num(p[0]), num(p[1]), num(-p[2])) for p in V) + ";\n %d;\n" % len(F) +
    ",\n".join(" 3;%d,%d,%d;" % (t[0], t[2], t[1]) for t in F) + ";\n}\n")

# FBX 7.4, the same node tree in the ASCII and the binary encoding: a mesh geometry (polygon
# vertex indices, the last of each polygon stored as -1 - index) under a model under the root
class Id(int):
    """An object id: 64-bit in the binary encoding."""


FBX_TREE = [
    ("FBXHeaderExtension", [], [("FBXHeaderVersion", [1003], []), ("FBXVersion", [7400], [])]),
    ("GlobalSettings", [], [("Version", [1000], [])]),
    ("Objects", [], [
        ("Geometry", [Id(1000), "Geometry::fox", "Mesh"], [
            ("Vertices", [[float(x) for p in V for x in p]], []),
            ("PolygonVertexIndex", [[i for t in F for i in (t[0], t[1], -1 - t[2])]], []),
            ("GeometryVersion", [124], [])]),
        ("Model", [Id(2000), "Model::fox", "Mesh"], [("Version", [232], [])])]),
    ("Connections", [], [("C", ["OO", Id(1000), Id(2000)], []), ("C", ["OO", Id(2000), Id(0)], [])]),
]


def fbx_ascii(nodes, depth=0):
    text = ""
    for name, props, children in nodes:
        values = []
        for v in props:
            if isinstance(v, list):
                values.append("*%d {\n%s\ta: %s\n%s}" % (len(v), "\t" * (depth + 1),
                              ",".join(num(x) if isinstance(x, float) else str(x) for x in v), "\t" * depth))
            else:
                values.append('"%s"' % v if isinstance(v, str) else str(v))
        text += "\t" * depth + name + ": " + ", ".join(values)
        if children:
            text += " {\n" + fbx_ascii(children, depth + 1) + "\t" * depth + "}"
        text += "\n"
    return text


def fbx_property(v):
    if isinstance(v, str):
        return b"S" + struct.pack("<I", len(v)) + v.encode()
    if isinstance(v, list):
        floats = isinstance(v[0], float)
        data = struct.pack("<%d%s" % (len(v), "d" if floats else "i"), *v)
        return (b"d" if floats else b"i") + struct.pack("<III", len(v), 0, len(data)) + data
    return b"L" + struct.pack("<q", v) if isinstance(v, Id) else b"I" + struct.pack("<i", v)


def fbx_binary(nodes, offset):
    data = b""
    for name, props, children in nodes:
        head = 13 + len(name)
        plist = b"".join(fbx_property(v) for v in props)
        nested = fbx_binary(children, offset + head + len(plist)) + b"\0" * 13 if children else b""
        end = offset + head + len(plist) + len(nested)
        data += struct.pack("<IIIB", end, len(props), len(plist), len(name)) + name.encode() + plist + nested
        offset = end
    return data


out("fox.fbx", "; FBX 7.4.0 project file\n" + fbx_ascii(FBX_TREE))
prefix = b"Kaydara FBX Binary  \0\x1a\0" + struct.pack("<I", 7400)
out("fox_binary.fbx", prefix + fbx_binary(FBX_TREE, len(prefix)) + b"\0" * 13, "wb")

# Blender .blend (2.48 layout, 64-bit pointers, little-endian): file blocks of a scene, its base,
# an object and its mesh (legacy MVert / MFace arrays), described by an SDNA block that declares
# only the structures and fields assimp reads (every structure a multiple of 4 bytes long: the SDNA
# tables are aligned to 4 from the end of the file header)
BLEND_BASIC = [("char", 1), ("short", 2), ("int", 4), ("float", 4), ("void", 0)]
BLEND_STRUCTS = [
    ("ListBase", [("void", "*first"), ("void", "*last")]),
    ("ID", [("void", "*next"), ("void", "*prev"), ("char", "name[66]"), ("short", "flag")]),
    ("Scene", [("ID", "id"), ("void", "*camera"), ("void", "*world"), ("void", "*basact"), ("ListBase", "base")]),
    ("Base", [("Base", "*next"), ("Base", "*prev"), ("Object", "*object")]),
    ("Object", [("ID", "id"), ("short", "type"), ("short", "pad"), ("float", "obmat[4][4]"), ("Object", "*parent"), ("void", "*data")]),
    ("Mesh", [("ID", "id"), ("int", "totface"), ("int", "totedge"), ("int", "totvert"), ("MFace", "*mface"),
              ("MVert", "*mvert"), ("void", "**mat")]),
    ("MVert", [("float", "co[3]"), ("short", "no[3]"), ("char", "flag"), ("char", "bweight")]),
    ("MFace", [("int", "v1"), ("int", "v2"), ("int", "v3"), ("int", "v4"), ("short", "mat_nr"), ("char", "edcode"),
               ("char", "flag")]),
]
BLEND_TYPES = [t for t, _ in BLEND_BASIC] + [name for name, _ in BLEND_STRUCTS]


def blend_size(ftype, fname, sizes):
    if fname.startswith("*"):
        return 8
    n = 1
    for dim in fname[fname.find("[") + 1:-1].split("][") if "[" in fname else []:
        n *= int(dim)
    return sizes[ftype] * n


def blend_sdna():
    sizes = dict(BLEND_BASIC)
    for name, fields in BLEND_STRUCTS:
        sizes[name] = sum(blend_size(t, f, sizes) for t, f in fields)
    names = [f for _, fields in BLEND_STRUCTS for _, f in fields]

    def strings(tag, items):
        data = tag + struct.pack("<I", len(items)) + b"".join(x.encode() + b"\0" for x in items)
        return data + b"\0" * (-len(data) % 4)

    data = b"SDNA" + strings(b"NAME", names) + strings(b"TYPE", BLEND_TYPES)
    data += b"TLEN" + b"".join(struct.pack("<H", sizes[t]) for t in BLEND_TYPES)
    data += b"\0" * (-len(data) % 4)
    data += b"STRC" + struct.pack("<I", len(BLEND_STRUCTS))
    for name, fields in BLEND_STRUCTS:
        data += struct.pack("<HH", BLEND_TYPES.index(name), len(fields))
        data += b"".join(struct.pack("<HH", BLEND_TYPES.index(t), names.index(f)) for t, f in fields)
    return data, sizes


def blend_block(code, address, structure, count, data):
    index = [name for name, _ in BLEND_STRUCTS].index(structure) if structure else 0
    return code + struct.pack("<IQII", len(data), address, index, count) + data


def blend_id(name):
    return struct.pack("<QQ", 0, 0) + name.encode().ljust(66, b"\0") + struct.pack("<h", 0)


SCENE, BASE, OBJECT, MESH, MVERTS, MFACES = 0x1000, 0x2000, 0x3000, 0x4000, 0x5000, 0x6000
sdna, blend_sizes = blend_sdna()
identity = [1.0 if r == c else 0.0 for r in range(4) for c in range(4)]
blend = b"BLENDER-v248"
blend += blend_block(b"SC\0\0", SCENE, "Scene", 1, blend_id("SCfox") + struct.pack("<5Q", 0, 0, 0, BASE, BASE))
blend += blend_block(b"DATA", BASE, "Base", 1, struct.pack("<3Q", 0, 0, OBJECT))
blend += blend_block(b"OB\0\0", OBJECT, "Object", 1,
                     blend_id("OBfox") + struct.pack("<hh16fQQ", 1, 0, *identity, 0, MESH))
blend += blend_block(b"ME\0\0", MESH, "Mesh", 1,
                     blend_id("MEfox") + struct.pack("<3i3Q", len(F), 0, len(V), MFACES, MVERTS, 0))
blend += blend_block(b"DATA", MVERTS, "MVert", len(V), b"".join(struct.pack("<3f3hbb", *p, 0, 0, 0, 0, 0) for p in V))
blend += blend_block(b"DATA", MFACES, "MFace", len(F), b"".join(struct.pack("<4ihbb", *t, 0, 0, 0, 0) for t in F))
blend += blend_block(b"DNA1", 0x7000, None, 1, sdna) + blend_block(b"ENDB", 0, None, 0, b"")
assert len(blend_id("")) == blend_sizes["ID"] and all(blend_sizes[name] % 4 == 0 for name, _ in BLEND_STRUCTS)
out("fox.blend", blend, "wb")

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

#!/usr/bin/env python3
"""make_dropped.py: writes the files of tests/data/dropped, whose geometry is sound but some part
the tool never uses fails assimp's validation (so assimp refuses the whole file), and on request
the variants of them whose geometry itself is broken.

The geometry is made here: ellipsoids (latitude-longitude grids, closed, outward-facing).
- keys_past_duration.b3d (Blitz3D): a body ellipsoid under a root node, an "arm" node with a
  position track, and an animation of 20 frames whose keys run from frame 1 to 21, the off-by-one
  of exporters that count frames from 1 (assimp: "aiNodeAnim::mPositionKeys[20].mTime ... is
  larger than aiAnimation::mDuration").
- empty_mesh.b3d (Blitz3D): three ellipsoids in a row, each in its node (Box.000 to Box.002), and
  a node Box.003 whose mesh has no vertices and no triangles (assimp: "The mesh  contains no
  vertices"; Blitz3D meshes have no names).
- camera_light.dae (Collada): three ellipsoids, a camera whose far clip plane is nearer than its
  near one and a spot light whose inner cone is wider than its outer one (assimp:
  "aiCamera::mClipPlaneFar must be >= aiCamera::mClipPlaneNear").
With --twins DIR it writes their sound twins into DIR instead, under the same names: the
animation 21 frames long, no Box.003 node, no camera and no light; the geometry is the same, so a
reader that drops the faulty parts gives the twins' meshes.
With --broken DIR it writes variants whose geometry itself is broken into DIR instead:
- bad_index.b3d: keys_past_duration.b3d with a triangle index past the vertex list;
- nan_vertex.b3d: keys_past_duration.b3d with a vertex at NaN;
- empty_face.dae: camera_light.dae whose first ellipsoid starts with a face of no vertices.
Run from anywhere:
    python3 tests/data/dropped/make_dropped.py [--twins DIR | --broken DIR]
"""
import math
import os
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def ellipsoid(center, radii, slices=12, stacks=8):
    """Vertices and outward counter-clockwise triangles of a latitude-longitude ellipsoid."""
    cx, cy, cz = center
    rx, ry, rz = radii
    v = [(cx, cy + ry, cz)]
    for i in range(1, stacks):
        phi = math.pi * i / stacks
        for j in range(slices):
            theta = 2 * math.pi * j / slices
            v.append((cx + rx * math.sin(phi) * math.cos(theta), cy + ry * math.cos(phi),
                      cz + rz * math.sin(phi) * math.sin(theta)))
    v.append((cx, cy - ry, cz))
    bottom = len(v) - 1

    def ring(i, j):  # vertex j of ring i (1 .. stacks - 1)
        return 1 + (i - 1) * slices + j % slices

    f = []
    for j in range(slices):
        f.append((0, ring(1, j + 1), ring(1, j)))
        f.append((bottom, ring(stacks - 1, j), ring(stacks - 1, j + 1)))
    for i in range(1, stacks - 1):
        for j in range(slices):
            a, b, c, d = ring(i, j), ring(i, j + 1), ring(i + 1, j), ring(i + 1, j + 1)
            f.append((a, b, d))
            f.append((a, d, c))
    return v, f


# ---- Blitz3D: chunks of a 4-byte tag, a 32-bit little-endian size and the payload ----

def chunk(tag, *parts):
    body = b"".join(parts)
    return tag + struct.pack("<I", len(body)) + body


def i32(*xs):
    return struct.pack("<%di" % len(xs), *xs)


def f32(*xs):
    return struct.pack("<%df" % len(xs), *xs)


def b3d_node(name, *children, position=(0, 0, 0)):
    # name, position, scale, rotation (w x y z), then the child chunks
    return chunk(b"NODE", name.encode() + b"\0", f32(*position), f32(1, 1, 1), f32(1, 0, 0, 0), *children)


def b3d_mesh(v, f):
    # no brush; vertices without normals, colours or texture coordinates; triangles of brush -1.
    # Blitz3D is left-handed and assimp flips the winding back, so triangles are stored reversed.
    vrts = chunk(b"VRTS", i32(0, 0, 0), *(f32(*p) for p in v))
    tris = chunk(b"TRIS", i32(-1), *(i32(a, c, b) for a, b, c in f))
    return chunk(b"MESH", i32(-1), vrts, tris)


def keys_past_duration_b3d(break_geometry=None, twin=False):
    v, f = ellipsoid((0, 0, 0), (1.0, 0.45, 0.35))
    if break_geometry == "index":
        f[5] = (f[5][0], len(v) + 7, f[5][2])
    elif break_geometry == "nan":
        v[4] = (float("nan"), v[4][1], v[4][2])
    frames = 21 if twin else 20
    # frames 1 .. frames + 1: the last key lies one frame past the animation's duration
    keys = chunk(b"KEYS", i32(1), *(i32(k) + f32(0.8, 0.02 * k, 0) for k in range(1, 22)))
    anim = chunk(b"ANIM", i32(0), i32(frames), f32(30.0))
    arm = b3d_node("arm", keys, position=(0.8, 0, 0))
    root = b3d_node("body", b3d_mesh(v, f), anim, arm)
    return chunk(b"BB3D", i32(1), root)


def empty_mesh_b3d(twin=False):
    parts = []
    for k in range(3):
        v, f = ellipsoid((2.2 * k, 0, 0), (1.0, 0.6, 0.5))
        parts.append(b3d_node("Box.00%d" % k, b3d_mesh(v, f)))
    if not twin:
        parts.append(b3d_node("Box.003", b3d_mesh([], [])))
    return chunk(b"BB3D", i32(1), b3d_node("track", *parts))


# ---- Collada ----

def dae_geometry(name, v, f, empty_face=False):
    n = name.replace(".", "_")
    indices = " ".join(str(i) for t in f for i in t)
    if empty_face:  # a polygon list whose first polygon has no vertices
        faces = '<polylist count="%d"><input semantic="VERTEX" source="#%s-vtx" offset="0"/><vcount>0 %s</vcount>' \
                '<p>%s</p></polylist>' % (len(f) + 1, n, " ".join("3" for _ in f), indices)
    else:
        faces = '<triangles count="%d"><input semantic="VERTEX" source="#%s-vtx" offset="0"/><p>%s</p></triangles>' \
                % (len(f), n, indices)
    return """    <geometry id="%s" name="%s"><mesh>
      <source id="%s-pos"><float_array id="%s-pos-array" count="%d">%s</float_array>
        <technique_common><accessor source="#%s-pos-array" count="%d" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common></source>
      <vertices id="%s-vtx"><input semantic="POSITION" source="#%s-pos"/></vertices>
      %s
    </mesh></geometry>
""" % (n, name, n, n, 3 * len(v), " ".join("%.6g" % x for p in v for x in p), n, len(v), n, n, faces)


CAMERA_LIGHT = """  <library_cameras><camera id="Camera" name="Camera"><optics><technique_common><perspective>
    <yfov>40</yfov><aspect_ratio>1.5</aspect_ratio><znear>100</znear><zfar>0.1</zfar>
  </perspective></technique_common></optics></camera></library_cameras>
  <library_lights><light id="Spot" name="Spot"><technique_common><spot>
    <color>1 1 1</color><constant_attenuation>1</constant_attenuation><linear_attenuation>0</linear_attenuation>
    <quadratic_attenuation>0</quadratic_attenuation><falloff_angle>60</falloff_angle><falloff_exponent>0</falloff_exponent>
  </spot></technique_common>
    <extra><technique profile="FCOLLADA"><outer_cone>20</outer_cone></technique></extra></light></library_lights>
"""
CAMERA_LIGHT_NODES = """    <node id="Camera-node" name="Camera"><translate>0 0 10</translate><instance_camera url="#Camera"/></node>
    <node id="Spot-node" name="Spot"><translate>0 5 0</translate><instance_light url="#Spot"/></node>
"""


def camera_light_dae(break_geometry=None, twin=False):
    parts = []
    for k in range(3):
        v, f = ellipsoid((2.2 * k, 0, 0), (1.0, 0.6, 0.5))
        parts.append(("Box.00%d" % k, v, f))
    geometries = "".join(dae_geometry(name, v, f, empty_face=(break_geometry == "face" and k == 0))
                         for k, (name, v, f) in enumerate(parts))
    nodes = "".join('    <node id="%s-node" name="%s"><instance_geometry url="#%s"/></node>\n'
                    % (n.replace(".", "_"), n, n.replace(".", "_")) for n, _, _ in parts)
    return """<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><contributor><authoring_tool>make_dropped.py</authoring_tool></contributor>
    <unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>
%s  <library_geometries>
%s  </library_geometries>
  <library_visual_scenes><visual_scene id="scene">
%s%s  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
""" % ("" if twin else CAMERA_LIGHT, geometries, nodes, "" if twin else CAMERA_LIGHT_NODES)


def write(folder, name, data):
    with open(os.path.join(folder, name), "wb" if isinstance(data, bytes) else "w") as fh:
        fh.write(data)


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--twins":
        out = sys.argv[2]
        write(out, "keys_past_duration.b3d", keys_past_duration_b3d(twin=True))
        write(out, "empty_mesh.b3d", empty_mesh_b3d(twin=True))
        write(out, "camera_light.dae", camera_light_dae(twin=True))
    elif len(sys.argv) == 3 and sys.argv[1] == "--broken":
        out = sys.argv[2]
        write(out, "bad_index.b3d", keys_past_duration_b3d("index"))
        write(out, "nan_vertex.b3d", keys_past_duration_b3d("nan"))
        write(out, "empty_face.dae", camera_light_dae("face"))
    elif len(sys.argv) == 1:
        write(HERE, "keys_past_duration.b3d", keys_past_duration_b3d())
        write(HERE, "empty_mesh.b3d", empty_mesh_b3d())
        write(HERE, "camera_light.dae", camera_light_dae())
    else:
        sys.exit(__doc__)

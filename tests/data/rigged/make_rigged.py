"""make_rigged.py: builds the rigged test characters of tests/data/rigged in headless Blender.

Three characters, each from simple meshes (cylinders, spheres, boxes) joined, remeshed into one
closed surface and decimated to a couple of thousand triangles, bound to an armature with
automatic weights (parent with ARMATURE_AUTO, Blender's bone heat), with an action of a few
keyframes; each is exported as <name>.glb (glTF 2.0 binary, +Y up) and <name>.fbx (FBX binary,
no leaf bones), the snake also as snake.dae (Collada 1.4). The mesh is bound at the armature's rest pose, the objects carry identity
transforms, and the action's first frame is the rest pose (the scene is left on it for export).
    humanoid   a figure with a head, arms and legs (15 joints)
    quadruped  a four-legged animal with a neck, head and a three-joint tail (18 joints)
    snake      a tapering tentacle along +Y driven by a chain of 8 joints
The joints each character gets are listed in RIGS below; tests/unit/io/test_skin.cpp checks the
files against them. Regenerate (Blender 3.4, Debian's `blender` package) from the repository root:
    blender -b --factory-startup --python tests/data/rigged/make_rigged.py [-- NAME...]
FBX files hold a creation time, so a regenerated file differs in bytes but not in content.
"""
import math
import os
import sys

import bpy

HERE = os.path.dirname(os.path.abspath(__file__))

# Each rig: joints as (name, parent, head xyz, tail xyz), parents before children; the parts as
# (kind, location, size, rotation xyz in degrees); the keyframes as (frame, joint, euler xyz).
RIGS = {
    "humanoid": {
        "joints": [
            ("hips", None, (0, 0, 0.95), (0, 0, 1.10)),
            ("spine", "hips", (0, 0, 1.10), (0, 0, 1.30)),
            ("chest", "spine", (0, 0, 1.30), (0, 0, 1.50)),
            ("neck", "chest", (0, 0, 1.50), (0, 0, 1.62)),
            ("head", "neck", (0, 0, 1.62), (0, 0, 1.90)),
            ("upper_arm.L", "chest", (0.20, 0, 1.45), (0.48, 0, 1.45)),
            ("forearm.L", "upper_arm.L", (0.48, 0, 1.45), (0.74, 0, 1.45)),
            ("upper_arm.R", "chest", (-0.20, 0, 1.45), (-0.48, 0, 1.45)),
            ("forearm.R", "upper_arm.R", (-0.48, 0, 1.45), (-0.74, 0, 1.45)),
            ("thigh.L", "hips", (0.10, 0, 0.90), (0.10, 0, 0.50)),
            ("shin.L", "thigh.L", (0.10, 0, 0.50), (0.10, 0, 0.10)),
            ("foot.L", "shin.L", (0.10, 0, 0.10), (0.10, -0.15, 0.03)),
            ("thigh.R", "hips", (-0.10, 0, 0.90), (-0.10, 0, 0.50)),
            ("shin.R", "thigh.R", (-0.10, 0, 0.50), (-0.10, 0, 0.10)),
            ("foot.R", "shin.R", (-0.10, 0, 0.10), (-0.10, -0.15, 0.03)),
        ],
        "parts": [
            ("cylinder", (0, 0, 1.22), (0.17, 0.11, 0.36), (0, 0, 0)),      # torso
            ("sphere", (0, 0, 1.76), (0.12, 0.12, 0.14), (0, 0, 0)),        # head
            ("cylinder", (0, 0, 1.56), (0.05, 0.05, 0.10), (0, 0, 0)),      # neck
            ("cylinder", (0.46, 0, 1.45), (0.05, 0.05, 0.30), (0, 90, 0)),  # arm L
            ("cylinder", (-0.46, 0, 1.45), (0.05, 0.05, 0.30), (0, 90, 0)),  # arm R
            ("cylinder", (0.10, 0, 0.50), (0.07, 0.07, 0.46), (0, 0, 0)),   # leg L
            ("cylinder", (-0.10, 0, 0.50), (0.07, 0.07, 0.46), (0, 0, 0)),  # leg R
            ("box", (0.10, -0.06, 0.04), (0.06, 0.12, 0.04), (0, 0, 0)),    # foot L
            ("box", (-0.10, -0.06, 0.04), (0.06, 0.12, 0.04), (0, 0, 0)),   # foot R
        ],
        "voxel": 0.025,
        "keys": [(1, "upper_arm.L", (0, 0, 0)), (10, "upper_arm.L", (0, 0, 40)), (20, "upper_arm.L", (0, 0, 0)),
                 (1, "thigh.R", (0, 0, 0)), (10, "thigh.R", (30, 0, 0)), (20, "thigh.R", (0, 0, 0)),
                 (1, "head", (0, 0, 0)), (10, "head", (0, 0, 20)), (20, "head", (0, 0, 0))],
    },
    "quadruped": {
        "joints": [
            ("pelvis", None, (0, 0.35, 0.70), (0, 0.10, 0.72)),
            ("spine", "pelvis", (0, 0.10, 0.72), (0, -0.15, 0.74)),
            ("chest", "spine", (0, -0.15, 0.74), (0, -0.38, 0.76)),
            ("neck", "chest", (0, -0.38, 0.76), (0, -0.55, 0.95)),
            ("head", "neck", (0, -0.55, 0.95), (0, -0.80, 0.95)),
            ("tail.1", "pelvis", (0, 0.45, 0.72), (0, 0.63, 0.76)),
            ("tail.2", "tail.1", (0, 0.63, 0.76), (0, 0.81, 0.80)),
            ("tail.3", "tail.2", (0, 0.81, 0.80), (0, 0.99, 0.84)),
            ("front_upper.L", "chest", (0.12, -0.32, 0.62), (0.12, -0.32, 0.36)),
            ("front_lower.L", "front_upper.L", (0.12, -0.32, 0.36), (0.12, -0.32, 0.06)),
            ("front_upper.R", "chest", (-0.12, -0.32, 0.62), (-0.12, -0.32, 0.36)),
            ("front_lower.R", "front_upper.R", (-0.12, -0.32, 0.36), (-0.12, -0.32, 0.06)),
            ("hind_upper.L", "pelvis", (0.12, 0.32, 0.62), (0.12, 0.32, 0.36)),
            ("hind_lower.L", "hind_upper.L", (0.12, 0.32, 0.36), (0.12, 0.32, 0.06)),
            ("hind_upper.R", "pelvis", (-0.12, 0.32, 0.62), (-0.12, 0.32, 0.36)),
            ("hind_lower.R", "hind_upper.R", (-0.12, 0.32, 0.36), (-0.12, 0.32, 0.06)),
            ("ear.L", "head", (0.06, -0.62, 1.02), (0.08, -0.62, 1.12)),
            ("ear.R", "head", (-0.06, -0.62, 1.02), (-0.08, -0.62, 1.12)),
        ],
        "parts": [
            ("cylinder", (0, 0, 0.73), (0.17, 0.15, 0.46), (90, 0, 0)),     # body along y
            ("cylinder", (0, -0.48, 0.86), (0.07, 0.07, 0.16), (40, 0, 0)),  # neck
            ("sphere", (0, -0.68, 0.95), (0.09, 0.15, 0.09), (0, 0, 0)),     # head
            ("cylinder", (0, 0.74, 0.78), (0.04, 0.04, 0.30), (-78, 0, 0)),  # tail
            ("cylinder", (0.12, -0.32, 0.34), (0.05, 0.05, 0.30), (0, 0, 0)),  # legs
            ("cylinder", (-0.12, -0.32, 0.34), (0.05, 0.05, 0.30), (0, 0, 0)),
            ("cylinder", (0.12, 0.32, 0.34), (0.05, 0.05, 0.30), (0, 0, 0)),
            ("cylinder", (-0.12, 0.32, 0.34), (0.05, 0.05, 0.30), (0, 0, 0)),
            ("cone", (0.06, -0.62, 1.07), (0.03, 0.03, 0.07), (0, 0, 0)),   # ears
            ("cone", (-0.06, -0.62, 1.07), (0.03, 0.03, 0.07), (0, 0, 0)),
        ],
        "voxel": 0.02,
        "keys": [(1, "tail.1", (0, 0, 0)), (8, "tail.1", (0, 0, 30)), (16, "tail.1", (0, 0, -30)), (24, "tail.1", (0, 0, 0)),
                 (1, "front_upper.L", (0, 0, 0)), (12, "front_upper.L", (25, 0, 0)), (24, "front_upper.L", (0, 0, 0)),
                 (1, "neck", (0, 0, 0)), (12, "neck", (-15, 0, 0)), (24, "neck", (0, 0, 0))],
    },
    "snake": {
        "joints": [("seg.%d" % i, None if i == 0 else "seg.%d" % (i - 1), (0, 0.15 * i, 0.1), (0, 0.15 * (i + 1), 0.1))
                   for i in range(8)],
        "parts": [("tentacle", (0, 0.6, 0.1), (0.09, 0.02, 1.2), (0, 0, 0))],
        "voxel": 0.012,
        "keys": [(1, "seg.%d" % i, (0, 0, 0)) for i in range(1, 8)] +
                [(10, "seg.%d" % i, (0, 0, 12 * (1 if i % 2 else -1))) for i in range(1, 8)] +
                [(20, "seg.%d" % i, (0, 0, 0)) for i in range(1, 8)],
    },
}

TARGET_TRIANGLES = 2400
# characters also exported as Collada (text, so only the smallest, to keep the files small)
COLLADA = {"snake"}


def clear_scene():
    bpy.ops.wm.read_factory_settings(use_empty=True)


def add_part(kind, loc, size, rot):
    rot = tuple(math.radians(a) for a in rot)
    if kind == "cylinder":
        bpy.ops.mesh.primitive_cylinder_add(vertices=24, radius=1, depth=2, location=loc, rotation=rot)
        bpy.context.object.scale = (size[0], size[1], size[2] / 2)
    elif kind == "cone":
        bpy.ops.mesh.primitive_cone_add(vertices=16, radius1=1, depth=2, location=loc, rotation=rot)
        bpy.context.object.scale = (size[0], size[1], size[2] / 2)
    elif kind == "sphere":
        bpy.ops.mesh.primitive_uv_sphere_add(segments=24, ring_count=12, radius=1, location=loc, rotation=rot)
        bpy.context.object.scale = size
    elif kind == "box":
        bpy.ops.mesh.primitive_cube_add(size=2, location=loc, rotation=rot)
        bpy.context.object.scale = size
    elif kind == "tentacle":
        # a cone along +Y, from radius size[0] at its base to size[1] at its tip, length size[2]
        bpy.ops.mesh.primitive_cone_add(vertices=24, radius1=size[0], radius2=size[1], depth=size[2], location=loc,
                                        rotation=(math.radians(-90), 0, 0))
    else:
        raise ValueError(kind)
    return bpy.context.object


def build_mesh(name, rig):
    parts = [add_part(*p) for p in rig["parts"]]
    bpy.ops.object.select_all(action="DESELECT")
    for p in parts:
        p.select_set(True)
    bpy.context.view_layer.objects.active = parts[0]
    bpy.ops.object.transform_apply(location=True, rotation=True, scale=True)
    bpy.ops.object.join()
    body = bpy.context.object
    body.name = name
    body.data.name = name
    # one closed surface out of the overlapping parts, then a small triangle count
    remesh = body.modifiers.new("remesh", "REMESH")
    remesh.mode = "VOXEL"
    remesh.voxel_size = rig["voxel"]
    bpy.ops.object.modifier_apply(modifier=remesh.name)
    triangles = sum(len(p.vertices) - 2 for p in body.data.polygons)
    decimate = body.modifiers.new("decimate", "DECIMATE")
    decimate.ratio = min(1.0, TARGET_TRIANGLES / max(1, triangles))
    bpy.ops.object.modifier_apply(modifier=decimate.name)
    tri = body.modifiers.new("triangulate", "TRIANGULATE")
    bpy.ops.object.modifier_apply(modifier=tri.name)
    return body


def build_armature(name, rig):
    bpy.ops.object.armature_add(enter_editmode=True, location=(0, 0, 0))
    arm = bpy.context.object
    arm.name = name + "_rig"
    arm.data.name = name + "_rig"
    eb = arm.data.edit_bones
    for b in list(eb):
        eb.remove(b)
    for jname, parent, head, tail in rig["joints"]:
        b = eb.new(jname)
        b.head = head
        b.tail = tail
        b.roll = 0
        if parent:
            b.parent = eb[parent]
            b.use_connect = tuple(eb[parent].tail) == tuple(head)
    bpy.ops.object.mode_set(mode="OBJECT")
    return arm


def bind(body, arm):
    bpy.ops.object.select_all(action="DESELECT")
    body.select_set(True)
    arm.select_set(True)
    bpy.context.view_layer.objects.active = arm
    bpy.ops.object.parent_set(type="ARMATURE_AUTO")
    # every joint must drive some of the surface, every vertex must be driven
    names = {g.index: g.name for g in body.vertex_groups}
    used = set()
    for v in body.data.vertices:
        ws = [(g.group, g.weight) for g in v.groups if g.weight > 0]
        if not ws:
            raise RuntimeError("%s: vertex %d has no weight" % (body.name, v.index))
        used.update(names[g] for g, _ in ws)
    missing = [j[0] for j in RIGS[body.name]["joints"] if j[0] not in used]
    if missing:
        raise RuntimeError("%s: joints without weights: %s" % (body.name, missing))


def animate(name, arm, rig):
    arm.animation_data_create()
    action = bpy.data.actions.new(name + "_wave")
    arm.animation_data.action = action
    bpy.context.view_layer.objects.active = arm
    bpy.ops.object.mode_set(mode="POSE")
    last = 1
    for frame, joint, euler in rig["keys"]:
        pb = arm.pose.bones[joint]
        pb.rotation_mode = "XYZ"
        pb.rotation_euler = tuple(math.radians(a) for a in euler)
        pb.keyframe_insert("rotation_euler", frame=frame)
        last = max(last, frame)
    bpy.ops.object.mode_set(mode="OBJECT")
    scene = bpy.context.scene
    scene.frame_start, scene.frame_end = 1, last
    scene.frame_set(1)  # the rest pose: what the files' nodes hold


def export(name, body, arm):
    bpy.ops.object.select_all(action="DESELECT")
    body.select_set(True)
    arm.select_set(True)
    bpy.ops.export_scene.gltf(filepath=os.path.join(HERE, name + ".glb"), export_format="GLB", use_selection=True,
                              export_materials="NONE", export_texcoords=False, export_normals=False,
                              export_colors=False, export_skins=True, export_animations=True, export_yup=True)
    bpy.ops.export_scene.fbx(filepath=os.path.join(HERE, name + ".fbx"), use_selection=True,
                             object_types={"ARMATURE", "MESH"}, add_leaf_bones=False, bake_anim=True,
                             bake_anim_use_all_actions=False, bake_anim_use_nla_strips=False,
                             use_mesh_modifiers=False, mesh_smooth_type="OFF", use_armature_deform_only=True)
    if name in COLLADA:
        bpy.ops.wm.collada_export(filepath=os.path.join(HERE, name + ".dae"), selected=True, include_armatures=True,
                                  include_children=True, include_animations=True, deform_bones_only=True,
                                  use_texture_copies=False)


def main():
    names = [a for a in sys.argv[sys.argv.index("--") + 1:]] if "--" in sys.argv else list(RIGS)
    for name in names:
        rig = RIGS[name]
        clear_scene()
        body = build_mesh(name, rig)
        arm = build_armature(name, rig)
        bind(body, arm)
        animate(name, arm, rig)
        export(name, body, arm)
        print("%s: %d vertices, %d triangles, %d joints" % (name, len(body.data.vertices), len(body.data.polygons),
                                                          len(rig["joints"])))


main()

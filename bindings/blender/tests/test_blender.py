"""test_blender.py: headless test of the add-on, run inside Blender by run_test.sh:
    blender -b --factory-startup --python-exit-code 1 --python test_blender.py -- ADDON.zip CLI DATA_DIR
Installs and enables the add-on zip (its bundled library, no $CA_LIBRARY), then on a transformed
torus with a modifier and on the fox imported from OBJ runs the operator and checks the skeleton
object against the coverage-axis tool on the same world-space mesh: ball count, b1, centres and
radii (within the .ma file's 9 significant digits; within 1e-9 of the bbox diagonal against the
binding itself), the radius attribute, the ball empties; that a cancelled job leaves the scene
unchanged; and the reconstruction-error operator. The rig: the tool's skinned fox (--rig OUT.glb)
imported, and the add-on's Create Armature on the fox: turning one leaf bone moves the vertices
weighted to it and no other vertex; the armature's bones and vertex groups are the binding's rig."""
import json
import math
import os
import subprocess
import sys
import tempfile

import bpy
import numpy as np

zip_path, cli, data = sys.argv[sys.argv.index("--") + 1:][:3]
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def run_cli(vertices, triangles, tmp, name):
    """The tool's skeleton of the same mesh (written with full precision): balls and its JSON summary."""
    obj_path, ma_path = os.path.join(tmp, name + ".obj"), os.path.join(tmp, name + ".ma")
    with open(obj_path, "w") as f:
        f.writelines("v %r %r %r\n" % tuple(v) for v in vertices.tolist())
        f.writelines("f %d %d %d\n" % tuple(i + 1 for i in t) for t in triangles.tolist())
    out = subprocess.run([cli, obj_path, "-o", ma_path, "--json", "--quiet"], check=True, capture_output=True,
                         text=True).stdout
    with open(ma_path) as f:
        balls = [[float(x) for x in line.split()[1:5]] for line in f if line.startswith("v ")]
    return np.array(balls), json.loads(out)


def compare(name, source, tmp):
    from coverage_axis_blender import job
    ca = job.binding()
    vertices, triangles = job.mesh_arrays(source, bpy.context.evaluated_depsgraph_get())
    before = set(bpy.data.objects.keys())
    bpy.ops.object.select_all(action="DESELECT")
    source.select_set(True)
    bpy.context.view_layer.objects.active = source
    check(bpy.ops.object.coverage_axis_skeletonize(balls=True) == {"FINISHED"}, name + ": operator finished")
    sk_obj = bpy.data.objects[source.name + "_skeleton"]
    balls, summary = run_cli(vertices, triangles, tmp, name)
    centers = np.array(sk_obj["coverage_axis_centers"]).reshape(-1, 3)
    radii = np.array(sk_obj["coverage_axis_radii"])
    check(len(sk_obj.data.vertices) == len(balls) == summary["selected"],
          "%s: %d balls, the tool %d" % (name, len(sk_obj.data.vertices), len(balls)))
    check(sk_obj["coverage_axis_betti1"] == summary["betti1"],
          "%s: b1 %d, the tool %d" % (name, sk_obj["coverage_axis_betti1"], summary["betti1"]))
    mine = np.hstack([centers, radii[:, None]])
    check(mine.shape == balls.shape and bool(np.all(np.abs(mine - balls) <= 5e-9 * np.abs(balls))),
          name + ": centres and radii equal the tool's to its 9 printed digits")
    diagonal = float(np.linalg.norm(vertices.max(0) - vertices.min(0)))
    direct = ca.skeletonize(vertices, triangles)
    check(float(np.abs(centers - direct.centers).max()) <= 1e-9 * diagonal,
          name + ": centres within 1e-9 of the bbox diagonal of the binding's")
    check(len(sk_obj.data.edges) == summary["edges"] and len(sk_obj.data.polygons) == summary["faces"],
          "%s: %d edges, %d faces (the tool %d, %d)" % (name, len(sk_obj.data.edges), len(sk_obj.data.polygons),
                                                         summary["edges"], summary["faces"]))
    co = np.empty(3 * len(sk_obj.data.vertices))
    sk_obj.data.vertices.foreach_get("co", co)
    r = np.empty(len(sk_obj.data.vertices))
    sk_obj.data.attributes["radius"].data.foreach_get("value", r)
    check(np.allclose(co.reshape(-1, 3), centers, rtol=0, atol=1e-6 * diagonal) and
          np.allclose(r, radii, rtol=0, atol=1e-6 * diagonal), name + ": mesh vertices and radius attribute")
    empties = [o for o in bpy.data.objects if o.parent == sk_obj and o.type == "EMPTY"]
    check(len(empties) == len(balls) and set(bpy.data.objects.keys()) - before ==
          {sk_obj.name} | {e.name for e in empties}, name + ": one sphere empty per ball, nothing else added")
    return sk_obj, vertices, triangles


def posed_positions(mesh_obj):
    """The mesh's vertices after its modifiers and armature (object space)."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = mesh_obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    co = np.empty(3 * len(mesh.vertices))
    mesh.vertices.foreach_get("co", co)
    evaluated.to_mesh_clear()
    return co.reshape(-1, 3)


def turn_one_bone(name, armature_obj, mesh_obj):
    """Turns the leaf bone with the most weighted vertices: those with weight >= 0.05 on it move,
    those with none stay (every other bone is at rest)."""
    names = {g.index: g.name for g in mesh_obj.vertex_groups}
    weights = {}
    for v in mesh_obj.data.vertices:
        for g in v.groups:
            if g.weight > 0:
                weights.setdefault(names[g.group], {})[v.index] = g.weight
    leaves = sorted(b.name for b in armature_obj.data.bones if not b.children and b.name in weights)
    check(len(leaves) > 0, name + ": leaf bones with weighted vertices")
    if not leaves:
        return
    bone = max(leaves, key=lambda b: len(weights[b]))
    rest = posed_positions(mesh_obj)
    pose_bone = armature_obj.pose.bones[bone]
    pose_bone.rotation_mode = "XYZ"
    pose_bone.rotation_euler = (0.7, 0.4, 0.2)
    bpy.context.view_layer.update()
    posed = posed_positions(mesh_obj)
    pose_bone.rotation_euler = (0.0, 0.0, 0.0)
    bpy.context.view_layer.update()
    moved = np.linalg.norm(posed - rest, axis=1)
    diagonal = float(np.linalg.norm(rest.max(0) - rest.min(0)))
    w = np.array([weights[bone].get(i, 0.0) for i in range(len(moved))])
    heavy, free = moved[w >= 0.05], moved[w == 0]
    check(len(heavy) > 0 and bool(np.all(heavy > 1e-4 * diagonal)),
          "%s: turning %s moves its %d vertices of weight >= 0.05" % (name, bone, len(heavy)))
    check(len(free) > 0 and float(free.max()) < 1e-5 * diagonal,
          "%s: and none of the %d vertices not weighted to it (largest move %.2g of the diagonal)" %
          (name, len(free), float(free.max()) / diagonal if len(free) else 0.0))


def check_rig(tmp, fox_path):
    # the tool's skinned glTF
    glb = os.path.join(tmp, "fox_rig.glb")
    subprocess.run([cli, fox_path, "-o", os.path.join(tmp, "fox_rig.ma"), "--rig", glb, "--quiet"], check=True)
    before = set(bpy.data.objects.keys())
    if "bool" not in np.__dict__:
        np.bool = bool  # Blender 3.4's glTF importer uses this alias, which numpy 1.24 removed
    bpy.ops.import_scene.gltf(filepath=glb)
    added = [bpy.data.objects[n] for n in set(bpy.data.objects.keys()) - before]
    armatures = [o for o in added if o.type == "ARMATURE"]
    meshes = [o for o in added if o.type == "MESH"]
    check(len(armatures) == 1 and len(meshes) == 1, "--rig glb: imports as one armature and one mesh")
    if len(armatures) == 1 and len(meshes) == 1:
        turn_one_bone("--rig glb", armatures[0], meshes[0])

    # the add-on's Create Armature on the fox from OBJ
    from coverage_axis_blender import job
    ca = job.binding()
    bpy.ops.object.select_all(action="DESELECT")
    bpy.ops.wm.obj_import(filepath=fox_path)
    fox = [o for o in bpy.context.selected_objects if o.type == "MESH"][0]
    bpy.context.view_layer.objects.active = fox
    check(bpy.ops.object.coverage_axis_armature() == {"FINISHED"}, "Create Armature finished")
    armature = bpy.data.objects.get(fox.name + "_rig")
    check(armature is not None and armature.type == "ARMATURE", "Create Armature: an armature object")
    if armature is None:
        return
    v, t = job.base_mesh_arrays(fox)
    rig = ca.rig(v, t, ca.skeletonize(v, t))
    check(len(armature.data.bones) == len(rig) and len(fox.vertex_groups) == len(rig),
          "Create Armature: %d bones and vertex groups, the binding's rig %d joints" %
          (len(armature.data.bones), len(rig)))
    parents = np.asarray(rig.parents).reshape(-1)
    check(all((armature.data.bones["joint_%d" % j].parent.name if parents[j] >= 0 else None) ==
              ("joint_%d" % parents[j] if parents[j] >= 0 else None) for j in range(len(rig))),
          "Create Armature: bones parented as the joints")
    joints, weights = np.asarray(rig.joints), np.asarray(rig.weights)
    names = {g.index: g.name for g in fox.vertex_groups}
    same = True
    for vert in fox.data.vertices:
        mine = {names[g.group]: g.weight for g in vert.groups}
        want = {"joint_%d" % j: w for j, w in zip(joints[vert.index], weights[vert.index]) if w > 0}
        same = same and set(mine) == set(want) and all(abs(mine[k] - want[k]) < 1e-6 for k in want)
    check(same, "Create Armature: vertex groups hold the rig's weights")
    check(any(m.type == "ARMATURE" and m.object == armature for m in fox.modifiers),
          "Create Armature: an Armature modifier on the mesh")
    turn_one_bone("Create Armature", armature, fox)


def main():
    bpy.ops.preferences.addon_install(filepath=zip_path)
    bpy.ops.preferences.addon_enable(module="coverage_axis_blender")
    from coverage_axis_blender import job
    ca = job.binding()
    loaded = ca.load_library()
    check("coverage_axis_blender" in loaded, "the bundled library is loaded: " + loaded)
    rna = bpy.ops.object.coverage_axis_skeletonize.get_rna_type().properties
    d = dict(ca.defaults("candidates"), **ca.defaults("select"), **ca.defaults("connect"))
    shown = {k: rna[k].default for k in ("delta", "cover_samples", "target_count")}
    check(math.isclose(shown["delta"], d["delta"], rel_tol=1e-6) and shown["cover_samples"] == d["cover_samples"]
          and shown["target_count"] == d["target_count"] and rna["solver"].default == d["solver"],
          "the operator's panel shows the library's defaults %s" % shown)
    bpy.ops.object.select_all(action="SELECT")
    bpy.ops.object.delete()

    with tempfile.TemporaryDirectory() as tmp:
        bpy.ops.mesh.primitive_torus_add(major_segments=32, minor_segments=12, major_radius=1.0, minor_radius=0.35,
                                         location=(3.0, -1.0, 0.5), rotation=(0.4, 0.0, 0.7))
        torus = bpy.context.active_object
        torus.scale = (2.0, 2.0, 2.0)
        torus.modifiers.new("triangulate", "TRIANGULATE")
        torus.modifiers.new("subdivide", "SUBSURF").levels = 1
        v, t = job.mesh_arrays(torus, bpy.context.evaluated_depsgraph_get())
        # subdividing a triangle mesh once gives a vertex per vertex, edge (3 per vertex) and triangle (2)
        check(len(v) == 6 * 32 * 12 and abs(float(v[:, 0].mean()) - 3.0) < 0.05,
              "torus: modifiers and world transform applied (%d vertices)" % len(v))
        sk_obj, v, t = compare("torus", torus, tmp)
        check(sk_obj["coverage_axis_betti1"] == 1, "torus: b1 = 1")

        bpy.ops.object.select_all(action="DESELECT")
        bpy.context.view_layer.objects.active = sk_obj
        sk_obj.select_set(True)
        check(bpy.ops.object.coverage_axis_error() == {"FINISHED"}, "error operator finished")
        want = ca.evaluate(v, t, job.skeleton_of_object(ca, sk_obj))
        check(math.isclose(sk_obj["coverage_axis_hd_two_sided"], want["hd_two_sided"], rel_tol=1e-12) and
              want["hd_two_sided"] > 0, "error operator: Hausdorff %.4f %%" % want["hd_two_sided"])

        # cancel: the operator's job, cancelled as Esc does, adds nothing
        names, meshes = set(bpy.data.objects.keys()), len(bpy.data.meshes)
        cancelled = job.Job(ca, [("torus", v, t)], {}).start()
        cancelled.cancel()
        cancelled.wait()
        added = job.add_results(bpy, bpy.context.collection, cancelled)
        check(getattr(cancelled.error, "status", None) == ca.CA_ERROR_CANCELLED and not added and
              set(bpy.data.objects.keys()) == names and len(bpy.data.meshes) == meshes,
              "cancel: CA_ERROR_CANCELLED and the scene unchanged")

        bpy.ops.wm.obj_import(filepath=os.path.join(data, "fox.obj"))
        fox = [o for o in bpy.context.selected_objects if o.type == "MESH"][0]
        compare("fox", fox, tmp)
        check_rig(tmp, os.path.join(data, "fox.obj"))

    print("blender: %d failed" % len(failures))
    if failures:
        sys.exit(1)


main()

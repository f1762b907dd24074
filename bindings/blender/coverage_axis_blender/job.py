"""job.py: the add-on's work outside Blender's UI: the evaluated mesh of an object in world space as
numpy arrays, a background job that skeletonizes meshes on a worker thread (progress, cancel), the
skeleton's Blender objects (a mesh with a `radius` attribute, optionally sphere empties), and a rig
as an armature with a vertex group per joint (docs/rig.md)."""
import threading

import numpy as np

# Stages in the order the library reports them; each gets an equal share of the progress bar (the
# library reports fractions within a stage).
STAGES = ("sampling", "inside", "delaunay", "candidates", "coverage", "selection", "connect")


def binding(library_path=""):
    """The coverage_axis package bundled in the add-on (else an installed one), its library loaded
    from library_path when given. Raises ImportError (LibraryNotFoundError) with what was tried."""
    try:
        from . import coverage_axis as ca
    except ImportError:
        import coverage_axis as ca
    ca.load_library(library_path or None)
    return ca


def mesh_arrays(obj, depsgraph):
    """The object's mesh with its modifiers applied, in world coordinates: vertices (n, 3) float64
    and triangles (m, 3) uint32."""
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    try:
        mesh.calc_loop_triangles()
        co = np.empty(3 * len(mesh.vertices), dtype=np.float32)
        mesh.vertices.foreach_get("co", co)
        tri = np.empty(3 * len(mesh.loop_triangles), dtype=np.int32)
        mesh.loop_triangles.foreach_get("vertices", tri)
    finally:
        evaluated.to_mesh_clear()
    m = np.array(obj.matrix_world, dtype=np.float64)
    vertices = co.reshape(-1, 3).astype(np.float64) @ m[:3, :3].T + m[:3, 3]
    return np.ascontiguousarray(vertices), tri.reshape(-1, 3).astype(np.uint32)


class Job:
    """Skeletonizes [(name, vertices, triangles)] one after another on a worker thread.
    .fraction (0..1) follows the library's progress; cancel() may be called from any thread;
    after done(): .results [(name, skeleton)] or .error (the exception; CA_ERROR_CANCELLED after
    a cancel)."""

    def __init__(self, ca, meshes, options, threads=0):
        self.ca, self.meshes, self.options = ca, meshes, options
        self.context = ca.Context(threads=threads, progress=self._progress)
        self.fraction, self.stage, self.results, self.error = 0.0, "", [], None
        self._index = 0
        self._thread = threading.Thread(target=self._run, name="coverage-axis", daemon=True)

    def start(self):
        self._thread.start()
        return self

    def _progress(self, stage, fraction):
        k = STAGES.index(stage) if stage in STAGES else len(STAGES) - 1
        within = (k + fraction) / len(STAGES)
        self.stage, self.fraction = stage, (self._index + within) / len(self.meshes)
        return False

    def _run(self):
        try:
            for self._index, (name, vertices, triangles) in enumerate(self.meshes):
                self.results.append((name, self.ca.skeletonize(vertices, triangles, context=self.context,
                                                               **self.options)))
        except Exception as e:  # reported by the operator in Blender's UI
            self.error, self.results = e, []

    def cancel(self):
        self.context.cancel()

    def done(self):
        return not self._thread.is_alive()

    def wait(self):
        self._thread.join()
        return self


def add_skeleton_object(bpy, collection, source_name, skeleton, balls=False):
    """A mesh object of the skeleton in world space: one vertex per ball, its edges and faces, the
    float attribute `radius`; the exact (double) centres and radii in the custom properties
    coverage_axis_centers / coverage_axis_radii; optionally a sphere empty per ball, parented."""
    centers, radii = np.asarray(skeleton.centers), np.asarray(skeleton.radii)
    faces = np.asarray(skeleton.faces).reshape(-1, 3).tolist()
    in_face = {frozenset(e) for f in faces for e in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0]))}
    edges = [e for e in np.asarray(skeleton.edges).reshape(-1, 2).tolist() if frozenset(e) not in in_face]
    mesh = bpy.data.meshes.new(source_name + "_skeleton")
    mesh.from_pydata(centers.tolist(), edges, faces)
    mesh.update()
    radius = mesh.attributes.new("radius", "FLOAT", "POINT")
    radius.data.foreach_set("value", radii.astype(np.float32))
    obj = bpy.data.objects.new(source_name + "_skeleton", mesh)
    obj["coverage_axis_source"] = source_name
    obj["coverage_axis_centers"] = centers.reshape(-1).tolist()
    obj["coverage_axis_radii"] = radii.tolist()
    obj["coverage_axis_betti1"] = int(skeleton.stats.get("betti1", 0))
    collection.objects.link(obj)
    if balls:
        for i, (c, r) in enumerate(zip(centers.tolist(), radii.tolist())):
            empty = bpy.data.objects.new("%s_ball%d" % (source_name, i), None)
            empty.empty_display_type, empty.empty_display_size, empty.location = "SPHERE", r, c
            empty.parent = obj
            collection.objects.link(empty)
    return obj


def add_results(bpy, collection, done, balls=False):
    """The skeleton objects of a finished job (none after an error or a cancel: the scene stays as it was)."""
    if done.error is not None:
        return []
    return [add_skeleton_object(bpy, collection, name, skeleton, balls) for name, skeleton in done.results]


def skeleton_of_object(ca, obj):
    """The coverage_axis.Skeleton stored on a skeleton object (exact centres and radii, the mesh's
    edges and faces)."""
    mesh = obj.data
    edges = np.empty(2 * len(mesh.edges), dtype=np.int32)
    mesh.edges.foreach_get("vertices", edges)
    faces = [tuple(p.vertices) for p in mesh.polygons if len(p.vertices) == 3]
    centers = np.array(obj["coverage_axis_centers"], dtype=np.float64).reshape(-1, 3)
    return ca.Skeleton(centers, np.array(obj["coverage_axis_radii"], dtype=np.float64),
                       edges.reshape(-1, 2), np.array(faces, dtype=np.uint32).reshape(-1, 3))


def base_mesh_arrays(obj):
    """The object's own mesh (no modifiers: its vertices are the ones vertex groups weight) in world
    coordinates: vertices (n, 3) float64 and triangles (m, 3) uint32."""
    mesh = obj.data
    mesh.calc_loop_triangles()
    co = np.empty(3 * len(mesh.vertices), dtype=np.float32)
    mesh.vertices.foreach_get("co", co)
    tri = np.empty(3 * len(mesh.loop_triangles), dtype=np.int32)
    mesh.loop_triangles.foreach_get("vertices", tri)
    m = np.array(obj.matrix_world, dtype=np.float64)
    vertices = co.reshape(-1, 3).astype(np.float64) @ m[:3, :3].T + m[:3, 3]
    return np.ascontiguousarray(vertices), tri.reshape(-1, 3).astype(np.uint32)


def add_armature(bpy, context, source, rig):
    """An armature object (world space) with a bone per joint of `rig` (a coverage_axis.Rig of the
    source's own vertices in world space): named joint_<j>, its head at the joint (the point it
    turns about, as in the glTF skin), its tail towards its children (a tip: on along its parent's
    direction), parented as the joints are; on the source, a vertex group per joint with the rig's
    weights and an Armature modifier."""
    positions, parents = np.asarray(rig.positions), np.asarray(rig.parents).reshape(-1)
    n = len(parents)
    extent = float(np.ptp(positions, axis=0).max()) if n > 1 else 1.0
    children = [[] for _ in range(n)]
    for j in range(1, n):
        children[parents[j]].append(j)
    armature = bpy.data.armatures.new(source.name + "_rig")
    obj = bpy.data.objects.new(source.name + "_rig", armature)
    context.collection.objects.link(obj)
    previous = context.view_layer.objects.active
    context.view_layer.objects.active = obj
    bpy.ops.object.mode_set(mode="EDIT")
    bones = []
    for j in range(n):
        bone = armature.edit_bones.new("joint_%d" % j)
        head = positions[j]
        if children[j]:
            tail = positions[children[j]].mean(axis=0)
        elif parents[j] >= 0:
            tail = head + 0.5 * (head - positions[parents[j]])
        else:
            tail = head
        if np.linalg.norm(tail - head) < 1e-3 * extent:
            tail = head + np.array([0.0, 0.0, 0.05 * extent])
        bone.head, bone.tail = head.tolist(), tail.tolist()
        if parents[j] >= 0:
            bone.parent = bones[parents[j]]
        bones.append(bone)
    bpy.ops.object.mode_set(mode="OBJECT")
    joints, weights = np.asarray(rig.joints), np.asarray(rig.weights)
    groups = [source.vertex_groups.new(name="joint_%d" % j) for j in range(n)]
    for i in range(len(joints)):
        for j, w in zip(joints[i].tolist(), weights[i].tolist()):
            if w > 0:
                groups[j].add([i], w, "REPLACE")
    modifier = source.modifiers.new("Coverage Axis rig", "ARMATURE")
    modifier.object = obj
    context.view_layer.objects.active = previous
    return obj

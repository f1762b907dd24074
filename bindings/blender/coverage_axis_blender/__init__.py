"""coverage_axis_blender: Blender add-on over the coverage_axis Python binding.
Object > Skeletonize (Coverage Axis): skeletonizes the selected mesh objects (modifiers and world
transform applied) on a worker thread, with Blender's progress bar and Esc to cancel, and adds each
skeleton as a mesh object (vertices, edges, faces, a `radius` attribute; optionally a sphere empty
per ball). Object > Coverage Axis Reconstruction Error measures a skeleton object against its
source mesh. Object > Create Armature (Coverage Axis) rigs the active mesh: an armature of the
skeleton's curve skeleton and a vertex group per bone (docs/rig.md). The library is the one bundled in the add-on, else the preference's path, else the
binding's own search (CA_LIBRARY, `make install`'s path, the system's)."""
import bpy
from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty, StringProperty

from . import job

bl_info = {
    "name": "Coverage Axis",
    "author": "The coverage-axis authors",
    "version": (0, 2, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Object > Skeletonize (Coverage Axis); Sidebar > Coverage Axis",
    "description": "Medial skeletons (balls, edges, faces) of meshes by Coverage Axis (Dou et al., EG 2022)",
    "category": "Object",
}

# the operator's options (names of the binding's options) and the library defaults read at register
OPTIONS = ("delta", "target_count", "cover_samples", "solver", "effort", "method")


def _library_defaults():
    """The library's defaults, or {} when it cannot be loaded yet (the preference may name it later)."""
    try:
        ca = job.binding(_preferences().library_path if _preferences() else "")
        return dict(ca.defaults("candidates"), **ca.defaults("select"), **ca.defaults("connect"))
    except (ImportError, RuntimeError):
        return {}


def _preferences():
    addon = bpy.context.preferences.addons.get(__name__)
    return addon.preferences if addon else None


class CoverageAxisPreferences(bpy.types.AddonPreferences):
    bl_idname = __name__
    library_path: StringProperty(name="Library", subtype="FILE_PATH",
                                 description="libcoverage_axis shared library (empty: bundled or installed)")
    threads: IntProperty(name="Threads", min=0, default=0, description="Worker threads (0 = all cores)")

    def draw(self, context):
        self.layout.prop(self, "library_path")
        self.layout.prop(self, "threads")
        try:
            self.layout.label(text="Loaded: " + job.binding(self.library_path).load_library())
        except (ImportError, RuntimeError) as e:
            self.layout.label(text=str(e)[:200], icon="ERROR")


def _binding(operator):
    prefs = _preferences()
    try:
        return job.binding(prefs.library_path if prefs else "")
    except (ImportError, RuntimeError) as e:
        operator.report({"ERROR"}, "Coverage Axis: %s (set the library in the add-on's preferences)" % e)
        return None


class OBJECT_OT_coverage_axis_skeletonize(bpy.types.Operator):
    """Skeletonize the selected meshes with Coverage Axis"""
    bl_idname = "object.coverage_axis_skeletonize"
    bl_label = "Skeletonize (Coverage Axis)"
    bl_options = {"REGISTER", "UNDO"}

    delta: FloatProperty(name="Delta", min=0.0, max=1.0, precision=4, step=0.1,
                         description="Dilation, fraction of the longest bounding-box side")
    target_count: IntProperty(name="Target balls", min=0, description="At most this many balls (0 = off: use delta)")
    cover_samples: IntProperty(name="Samples", min=1, description="Surface samples to cover")
    solver: EnumProperty(name="Solver", items=[("exact", "Exact", "Set cover by LP bound, local search, CBC"),
                                               ("greedy", "Greedy", "Classic greedy"),
                                               ("capp", "Coverage Axis++", "Score greedy")])
    effort: EnumProperty(name="Effort", items=[("fast", "Fast", "LP bound and local search"),
                                               ("prove", "Prove", "Branch and bound until proven optimal")])
    method: EnumProperty(name="Connection", items=[("auto", "Auto", "Medial for meshes"),
                                                   ("medial", "Medial", "Regions on the medial mesh"),
                                                   ("power", "Power", "Regular triangulation")])
    balls: BoolProperty(name="Ball empties", default=False, description="A sphere empty per ball")

    _job = None
    _timer = None

    @classmethod
    def poll(cls, context):
        return any(o.type == "MESH" for o in context.selected_objects)

    def _options(self, ca):
        # options the user did not set take the library's defaults (not the properties' placeholders)
        defaults = dict(ca.defaults("candidates"), **ca.defaults("select"), **ca.defaults("connect"))
        return {name: getattr(self, name) if self.properties.is_property_set(name) else defaults[name]
                for name in OPTIONS}

    def _start(self, context):
        ca = _binding(self)
        if ca is None:
            return None
        depsgraph = context.evaluated_depsgraph_get()
        meshes = [(o.name,) + job.mesh_arrays(o, depsgraph) for o in context.selected_objects if o.type == "MESH"]
        prefs = _preferences()
        return job.Job(ca, meshes, self._options(ca), prefs.threads if prefs else 0).start()

    def _finish(self, context, done):
        if done.error is not None:
            cancelled = getattr(done.error, "status", None) == done.ca.CA_ERROR_CANCELLED
            self.report({"WARNING"} if cancelled else {"ERROR"}, "Coverage Axis: %s" % done.error)
            return {"CANCELLED"}
        for obj in job.add_results(bpy, context.collection, done, self.balls):
            self.report({"INFO"}, "%s: %d balls, b1 = %d" % (obj.name, len(obj.data.vertices),
                                                            obj["coverage_axis_betti1"]))
        return {"FINISHED"}

    def execute(self, context):  # scripts, background mode and the redo panel: wait for the job
        started = self._start(context)
        return self._finish(context, started.wait()) if started else {"CANCELLED"}

    def invoke(self, context, event):
        if bpy.app.background:
            return self.execute(context)
        self._job = self._start(context)
        if self._job is None:
            return {"CANCELLED"}
        wm = context.window_manager
        self._timer = wm.event_timer_add(0.1, window=context.window)
        wm.progress_begin(0.0, 1.0)
        wm.modal_handler_add(self)
        return {"RUNNING_MODAL"}

    def modal(self, context, event):
        if event.type == "ESC":
            self._job.cancel()
        if event.type == "TIMER":
            context.window_manager.progress_update(self._job.fraction)
            if self._job.done():
                context.window_manager.event_timer_remove(self._timer)
                context.window_manager.progress_end()
                return self._finish(context, self._job)
        return {"PASS_THROUGH"}


class OBJECT_OT_coverage_axis_error(bpy.types.Operator):
    """Measure the active skeleton's reconstruction error against its source mesh"""
    bl_idname = "object.coverage_axis_error"
    bl_label = "Coverage Axis Reconstruction Error"

    @classmethod
    def poll(cls, context):
        o = context.active_object
        return o is not None and "coverage_axis_source" in o and o["coverage_axis_source"] in bpy.data.objects

    def execute(self, context):
        ca = _binding(self)
        if ca is None:
            return {"CANCELLED"}
        skeleton_obj = context.active_object
        source = bpy.data.objects[skeleton_obj["coverage_axis_source"]]
        vertices, triangles = job.mesh_arrays(source, context.evaluated_depsgraph_get())
        try:
            e = ca.evaluate(vertices, triangles, job.skeleton_of_object(ca, skeleton_obj))
        except ca.CoverageAxisError as err:
            self.report({"ERROR"}, "Coverage Axis: %s" % err)
            return {"CANCELLED"}
        for key in ("hd_two_sided", "hd_surface_to_recon", "hd_recon_to_surface"):
            skeleton_obj["coverage_axis_" + key] = e[key]
        self.report({"INFO"}, "Hausdorff %.3f %% of the bbox diagonal (surface -> skeleton %.3f %%, "
                              "skeleton -> surface %.3f %%)" % (e["hd_two_sided"], e["hd_surface_to_recon"],
                                                               e["hd_recon_to_surface"]))
        return {"FINISHED"}


class OBJECT_OT_coverage_axis_armature(bpy.types.Operator):
    """Rig the active mesh: an armature along its Coverage Axis skeleton, a vertex group per bone"""
    bl_idname = "object.coverage_axis_armature"
    bl_label = "Create Armature (Coverage Axis)"
    bl_options = {"REGISTER", "UNDO"}

    max_joints: IntProperty(name="Joints", min=1, default=64, description="At most this many bones")
    joint_spacing: FloatProperty(name="Spacing", min=0.001, max=1.0, default=0.1, precision=3,
                                 description="Bones along a branch about this long (fraction of the longest side)")

    @classmethod
    def poll(cls, context):
        o = context.active_object
        return o is not None and o.type == "MESH" and context.mode == "OBJECT"

    def execute(self, context):
        ca = _binding(self)
        if ca is None:
            return {"CANCELLED"}
        source = context.active_object
        vertices, triangles = job.base_mesh_arrays(source)
        prefs = _preferences()
        try:
            with ca.Context(threads=prefs.threads if prefs else 0) as ctx:
                skeleton = ca.skeletonize(vertices, triangles, context=ctx)
                rig = ca.rig(vertices, triangles, skeleton, context=ctx, max_joints=self.max_joints,
                             joint_spacing=self.joint_spacing)
        except ca.CoverageAxisError as err:
            self.report({"ERROR"}, "Coverage Axis: %s" % err)
            return {"CANCELLED"}
        obj = job.add_armature(bpy, context, source, rig)
        self.report({"INFO"}, "%s: %d bones, %d branches" % (obj.name, len(rig), rig.branch_count))
        return {"FINISHED"}


class VIEW3D_PT_coverage_axis(bpy.types.Panel):
    bl_label = "Coverage Axis"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Coverage Axis"

    def draw(self, context):
        self.layout.operator(OBJECT_OT_coverage_axis_skeletonize.bl_idname)
        self.layout.operator(OBJECT_OT_coverage_axis_error.bl_idname)
        self.layout.operator(OBJECT_OT_coverage_axis_armature.bl_idname)
        o = context.active_object
        if o is not None and "coverage_axis_hd_two_sided" in o:
            self.layout.label(text="Hausdorff: %.3f %%" % o["coverage_axis_hd_two_sided"])


def _menu(self, context):
    self.layout.operator(OBJECT_OT_coverage_axis_skeletonize.bl_idname)
    self.layout.operator(OBJECT_OT_coverage_axis_error.bl_idname)
    self.layout.operator(OBJECT_OT_coverage_axis_armature.bl_idname)


CLASSES = (CoverageAxisPreferences, OBJECT_OT_coverage_axis_skeletonize, OBJECT_OT_coverage_axis_error,
           OBJECT_OT_coverage_axis_armature, VIEW3D_PT_coverage_axis)


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    # show the library's defaults in the operator's panel (when it can be loaded now)
    for name, value in _library_defaults().items():
        if name in OPTIONS and name in OBJECT_OT_coverage_axis_skeletonize.__annotations__:
            OBJECT_OT_coverage_axis_skeletonize.__annotations__[name].keywords["default"] = value
    bpy.utils.unregister_class(OBJECT_OT_coverage_axis_skeletonize)
    bpy.utils.register_class(OBJECT_OT_coverage_axis_skeletonize)
    bpy.types.VIEW3D_MT_object.append(_menu)


def unregister():
    bpy.types.VIEW3D_MT_object.remove(_menu)
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)

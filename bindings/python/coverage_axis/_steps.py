"""_steps.py: the pipeline's steps over the C ABI - candidates(), select(), connect(), evaluate(),
proxies() - their results, and skeletonize(), the three steps in one call.

Options are keyword arguments named as the fields of the C option structs (ca_candidate_options,
ca_select_options, ca_connect_options, ca_evaluate_options, ca_proxy_options); an option not given (or None) keeps
the library's default, read from its ca_*_defaults function (defaults() lists them). Enumerations
take their names ("exact", "prove", "medial", ...) or the C values."""
import ctypes

from . import _arrays
from ._context import Context
from ._library import (CA_ERROR_INVALID_ARGUMENT, CA_ERROR_INVALID_INPUT, CA_ERROR_TARGET_NOT_REACHED,
                       CA_ERROR_TIME_LIMIT, CoverageAxisError, SearchStoppedError, TargetNotReachedError,
                       _CandidateOptions, _ConnectOptions,
                       _CorrespondenceOptions, _EvaluateOptions, _Evaluation, _ProxyOptions, _ProxyStats, _RigOptions,
                       _SelectOptions, _SelectStats, _SkeletonStats, _SkeletonView, _SurfaceView, fill_defaults, lib,
                       output_struct, struct_dict)
from ._structs import _BoneColliderOptions, _BoneColliderStats, _ContextDesc, _ProxyPlacement, _SkinView

# the header's #define values, by name
ENUMS = {
    "generator": {"voronoi": 0, "random": 1},
    "dilation": {"offset": 0, "scale": 1},
    "solver": {"exact": 0, "greedy": 1, "capp": 2},
    "effort": {"fast": 0, "prove": 1},
    "method": {"power": 0, "medial": 1, "auto": 2},
    "shapes": {"spheres": 0, "capsules": 1},
    "mode": {"inscribed": 0, "conservative": 1},
}
_MASKS = ("ignorable_samples", "forced_in", "forced_out")
_STEPS = {
    "context": ("ca_context_desc_defaults", _ContextDesc),
    "candidates": ("ca_candidate_options_defaults", _CandidateOptions),
    "select": ("ca_select_options_defaults", _SelectOptions),
    "connect": ("ca_connect_options_defaults", _ConnectOptions),
    "evaluate": ("ca_evaluate_options_defaults", _EvaluateOptions),
    "correspond": ("ca_correspondence_options_defaults", _CorrespondenceOptions),
    "rig": ("ca_rig_options_defaults", _RigOptions),
    "proxies": ("ca_proxy_options_defaults", _ProxyOptions),
    "bone_colliders": ("ca_bone_collider_options_defaults", _BoneColliderOptions),
}
_NOT_OPTIONS = {"struct_size", "alloc", "free", "alloc_user", "log", "log_user", "progress", "progress_user",
                "reserved_abi2_tail",  # padding, never read
                "ignorable_samples_count", "forced_in_count", "forced_out_count",  # the masks' lengths
                "skip_joints", "skip_count"}  # bone_colliders(): its own argument


def _option_names(step):
    return [name for name, _ in _STEPS[step][1]._fields_ if name not in _NOT_OPTIONS and name not in _MASKS]


def _named(name, value):
    for key, code in ENUMS.get(name, {}).items():
        if code == value:
            return key
    return value


def defaults(step):
    """The library's defaults of a step's options ("context", "candidates", "select", "connect",
    "evaluate", "correspond", "rig", "proxies", "bone_colliders") as a dict, enumerations by name."""
    s = fill_defaults(*_STEPS[step])
    return {name: _named(name, getattr(s, name)) for name in _option_names(step)}


def _options(step, given):
    """The step's option struct: the library's defaults, then the given options (None = default)."""
    s = fill_defaults(*_STEPS[step])
    names = _option_names(step)
    for name, value in given.items():
        if name not in names:
            raise TypeError("%s() got an unknown option %r (options: %s)" % (step, name, ", ".join(names)))
        if value is None:
            continue
        if name in ENUMS and isinstance(value, str):
            if value not in ENUMS[name]:
                raise CoverageAxisError(CA_ERROR_INVALID_ARGUMENT, "%s: %r is not one of %s" %
                                        (name, value, ", ".join(ENUMS[name])))
            value = ENUMS[name][value]
        try:
            setattr(s, name, int(value) if isinstance(value, bool) else value)
        except TypeError as e:
            raise CoverageAxisError(CA_ERROR_INVALID_ARGUMENT, "%s: %s" % (name, e))
    return s


def _run(context, function, *args):
    if context is not None:
        return context.run(function, *args)
    with Context() as ctx:
        return ctx.run(function, *args)


def _make(context, function, *args):
    """The object a step makes: function(*args, &out) run in the context; its pointer."""
    out = ctypes.c_void_p()
    _run(context, function, *args, ctypes.byref(out))
    return out


def _over_skeleton(context, function, vertices, triangles, skeleton, opts, *out):
    """function(&surface view, &skeleton view, &opts, *out) over the caller's surface and skeleton
    (evaluate(), correspond(), rig()); the views' buffers live until it returns."""
    view, keep = _surface(vertices, triangles, None)
    sv, keep_skeleton = _skeleton_view(skeleton)
    return _run(context, function, ctypes.byref(view), ctypes.byref(sv), ctypes.byref(opts), *out)


# point_normals= of candidates() and skeletonize(): how far a point cloud's normals are trusted
_POINT_NORMALS = {"given": 0, "unoriented": 1, "estimate": 2}
# CandidateSet.normals: the normals a point cloud's candidates used (ca_candidate_set_normals)
_NORMALS_USED = {0: "none", 1: "given", 2: "oriented", 3: "estimated"}


def _surface(vertices, triangles, normals, point_normals=None):
    """A ca_surface_view over the caller's arrays, and the buffers it borrows (point_normals None:
    the library's default)."""
    if point_normals is not None and point_normals not in _POINT_NORMALS:
        raise CoverageAxisError(CA_ERROR_INVALID_ARGUMENT, "point_normals must be one of %s, not %r" %
                                (", ".join(_POINT_NORMALS), point_normals))
    pos = _arrays.points(vertices, "vertices")
    tri = _arrays.indices(triangles, "triangles", 3)
    view = fill_defaults("ca_surface_view_defaults", _SurfaceView)
    view.positions, view.vertex_count, view.position_stride = pos.address, pos.count, pos.stride
    view.triangles, view.triangle_count, view.triangle_stride = tri.address, tri.count, tri.stride
    if point_normals is not None:
        view.point_normals = _POINT_NORMALS[point_normals]
    keep = [pos, tri]
    if normals is not None:
        nrm = _arrays.points(normals, "normals")
        if nrm.count != pos.count:
            raise CoverageAxisError(CA_ERROR_INVALID_INPUT, "normals: %d rows for %d vertices (one normal per "
                                    "vertex, or None)" % (nrm.count, pos.count))
        view.normals, view.normal_stride, view.normal_count = nrm.address, nrm.stride, nrm.count
        keep.append(nrm)
    return view, keep


class _Handle:
    """Owns one library object and destroys it when the last reference goes. The arrays viewing
    the object's memory reference the handle (not the result object holding them: no cycle)."""

    def __init__(self, ptr, destroy):
        self._lib, self._ptr, self._destroy = lib(), ptr, destroy

    def __del__(self):
        if getattr(self, "_ptr", None):
            getattr(self._lib, self._destroy)(self._ptr)
            self._ptr = None

    def get(self, name):
        return getattr(self._lib, name)(self._ptr)

    def view(self, getter, count, width, ctype=ctypes.c_double):
        return _arrays.view(self.get(getter), count, width, ctype, self)

    def pointer(self, getter, ctype):
        """The getter's array as a ctypes pointer to read item by item."""
        return ctypes.cast(self.get(getter), ctypes.POINTER(ctype))

    def read(self, getter, struct_type, *args):
        """A struct_type filled by getter(object, *args, &struct) (stats, a placement); a failure raises."""
        out = output_struct(struct_type)
        status = getattr(self._lib, getter)(self._ptr, *args, ctypes.byref(out))
        if status:
            raise CoverageAxisError(status, "%s failed" % getter)
        return out


class CandidateSet:
    """Step 1's result: surface samples and inner candidate balls (read-only arrays, no copies)."""

    def __init__(self, ptr):
        h = self._handle = _Handle(ptr, "ca_candidate_set_destroy")
        self.count = h.get("ca_candidate_set_count")
        self.sample_count = h.get("ca_candidate_set_sample_count")
        self.reference_length = h.get("ca_candidate_set_reference_length")  # the length delta is a fraction of
        self.flipped = bool(h.get("ca_candidate_set_flipped"))  # the mesh faced inward and was flipped
        self.normals = _NORMALS_USED.get(h.get("ca_candidate_set_normals"), "none")  # a cloud's normals used
        self.outliers = h.get("ca_candidate_set_outlier_count")  # cloud points dropped as outliers
        self.centers = h.view("ca_candidate_set_centers", self.count, 3)
        self.radii = h.view("ca_candidate_set_radii", self.count, 1)
        self.samples = h.view("ca_candidate_set_samples", self.sample_count, 3)


class Selection:
    """Step 2's result: the selected balls (indices into the candidate set), their undilated and
    dilated radii, the uncovered samples (skip_uncoverable) and the solver's statistics."""

    def __init__(self, ptr, candidate_set):
        h = self._handle = _Handle(ptr, "ca_selection_destroy")
        self.candidate_set = candidate_set
        self.count = h.get("ca_selection_count")
        self.indices = h.view("ca_selection_indices", self.count, 1, ctypes.c_uint32)
        self.centers = h.view("ca_selection_centers", self.count, 3)
        self.radii = h.view("ca_selection_radii", self.count, 1)
        self.dilated_radii = h.view("ca_selection_dilated_radii", self.count, 1)
        self.uncovered = h.view("ca_selection_uncovered", h.get("ca_selection_uncovered_count"), 1, ctypes.c_uint32)
        stats = h.read("ca_selection_stats", _SelectStats)
        self.stats = {name: _named(name, v) for name, v in struct_dict(stats).items()}
        self.stats["proven_optimal"] = bool(stats.proven_optimal)


class Skeleton:
    """Medial balls (centers (n, 3), radii (n,)), edges (m, 2) and faces (k, 3) into the balls, in
    the input's units, and statistics. Results of connect() view the library's memory; a Skeleton
    may also be built from the caller's own arrays (for evaluate())."""

    def __init__(self, centers, radii, edges=(), faces=(), stats=None):
        self.centers, self.radii, self.edges, self.faces = centers, radii, edges, faces
        self.stats = dict(stats or {})

    def __len__(self):
        return len(self.radii)

    @classmethod
    def _from_handle(cls, ptr):
        h = _Handle(ptr, "ca_skeleton_destroy")
        n = h.get("ca_skeleton_vertex_count")
        stats = h.read("ca_skeleton_stats_get", _SkeletonStats)
        return cls(h.view("ca_skeleton_centers", n, 3), h.view("ca_skeleton_radii", n, 1),
                   h.view("ca_skeleton_edges", h.get("ca_skeleton_edge_count"), 2, ctypes.c_uint32),
                   h.view("ca_skeleton_faces", h.get("ca_skeleton_face_count"), 3, ctypes.c_uint32),
                   {name: _named(name, v) for name, v in struct_dict(stats).items()})


def candidates(vertices, triangles=None, normals=None, *, context=None, point_normals=None, **options):
    """Step 1: samples of the surface and inner candidate balls. A mesh (vertices (n, 3), triangles
    (m, 3)) or a point cloud (no triangles; normals (n, 3) or None: estimated). point_normals:
    "given" (oriented; checked, re-oriented if their signs disagree; the library's default),
    "unoriented" (re-oriented) or "estimate" (ignored); CandidateSet.normals says which were used.
    Options: generator, cover_samples, voronoi_samples, random_candidates, seed, connect_samples."""
    view, keep = _surface(vertices, triangles, normals, point_normals)
    opts = _options("candidates", options)
    return CandidateSet(_make(context, lib().ca_candidates, ctypes.byref(view), ctypes.byref(opts)))


def select(candidate_set, *, context=None, ignorable_samples=None, forced_in=None, forced_out=None, **options):
    """Step 2: the fewest dilated candidate balls covering every sample.
    Options: dilation ("offset" | "scale"; scale=S alone selects "scale"), delta, scale, solver,
    time_limit_s, skip_uncoverable, target_count, target_tolerance, divide_threshold, effort, target_error
    (% of the bbox diagonal: the fewest balls within that two-sided Hausdorff distance; stats hd_reached),
    probe_fit (1: the target_error and target_count searches measure fitted skeletons, as connect(fit=1)).
    Masks (one flag per sample or ball, truthy = set): ignorable_samples, forced_in, forced_out."""
    if options.get("scale") is not None and options.get("dilation") is None:
        options["dilation"] = "scale"
    opts = _options("select", options)
    masks = [_arrays.mask(ignorable_samples, "ignorable_samples", candidate_set.sample_count),
             _arrays.mask(forced_in, "forced_in", candidate_set.count),
             _arrays.mask(forced_out, "forced_out", candidate_set.count)]
    for name, m in zip(_MASKS, masks):
        setattr(opts, name, ctypes.addressof(m) if m is not None and len(m) else None)
        setattr(opts, name + "_count", len(m) if m is not None else 0)
    out = ctypes.c_void_p()
    try:
        _run(context, lib().ca_select, candidate_set._handle._ptr, ctypes.byref(opts), ctypes.byref(out))
    except CoverageAxisError as e:
        # the failures with a result: the library returned its best selection
        if e.status == CA_ERROR_TARGET_NOT_REACHED:
            raise TargetNotReachedError(e.message, Selection(out, candidate_set)) from None
        if e.status == CA_ERROR_TIME_LIMIT and out.value:
            raise SearchStoppedError(e.message, Selection(out, candidate_set)) from None
        raise
    finally:
        del masks
    return Selection(out, candidate_set)


def connect(selection, *, context=None, **options):
    """Step 3: edges and triangles between the selected balls.
    Options: method ("auto" | "medial" | "power"), remove_outside, fill_holes, reconnect."""
    opts = _options("connect", options)
    return Skeleton._from_handle(_make(context, lib().ca_connect, selection.candidate_set._handle._ptr,
                                       selection._handle._ptr, ctypes.byref(opts)))


_connect_step = connect  # skeletonize()'s connect= option hides the function's name


def evaluate(vertices, triangles, skeleton, *, context=None, **options):
    """Hausdorff distances between the surface and the skeleton's reconstruction (union of balls,
    cones and slabs), in % of the bounding-box diagonal, as a dict.
    Options: surface_samples, envelope_samples, seed."""
    out = output_struct(_Evaluation)
    _over_skeleton(context, lib().ca_evaluate, vertices, triangles, skeleton, _options("evaluate", options),
                   ctypes.byref(out))
    return struct_dict(out)


def _skeleton_view(skeleton):
    """A ca_skeleton_view over a Skeleton's arrays (lengths checked), and the buffers it borrows."""
    c = _arrays.points(skeleton.centers, "skeleton.centers", packed=True)  # ca_skeleton_view has no strides
    r = _arrays.points(_column(skeleton.radii), "skeleton.radii", 1, packed=True)
    e = _arrays.indices(skeleton.edges, "skeleton.edges", 2)
    f = _arrays.indices(skeleton.faces, "skeleton.faces", 3)
    if r.count != c.count:
        raise CoverageAxisError(CA_ERROR_INVALID_ARGUMENT, "skeleton: %d centers, %d radii" % (c.count, r.count))
    sv = fill_defaults("ca_skeleton_view_defaults", _SkeletonView)
    sv.centers, sv.radii, sv.vertex_count = c.address, r.address, c.count
    sv.edges, sv.edge_count, sv.faces, sv.face_count = e.address, e.count, f.address, f.count
    return sv, [c, r, e, f]


class Proxies:
    """Engine proxies (proxies()): `primitives`, one dict per primitive in the input's units,
    {"kind": "sphere", "center": (x, y, z), "radius": r} or {"kind": "capsule", "a": (x, y, z),
    "radius_a": ra, "b": (x, y, z), "radius_b": rb} (the objects of the tool's --proxies-json), and
    `stats` (ca_proxy_stats: Hausdorff distances in % of the bbox diagonal, outside bounds, volumes)."""

    def __init__(self, primitives, stats):
        self.primitives, self.stats = primitives, stats

    def __len__(self):
        return len(self.primitives)


def proxies(candidate_set, skeleton, *, context=None, **options):
    """At most `count` spheres, or tapered capsules and spheres, for game engines from a skeleton of
    the candidate set's mesh (docs/proxies.md). Options: shapes ("spheres" | "capsules"), mode
    ("inscribed": inside the shape | "conservative": containing the whole surface), count,
    surface_samples, evaluate_samples, volume_samples, seed."""
    sv, keep = _skeleton_view(skeleton)
    opts = _options("proxies", options)
    h = _Handle(_make(context, lib().ca_proxies, candidate_set._handle._ptr, ctypes.byref(sv), ctypes.byref(opts)),
                "ca_proxy_set_destroy")
    del keep
    n = h.get("ca_proxy_set_count")
    kinds = h.pointer("ca_proxy_set_kinds", ctypes.c_int32)
    c = h.pointer("ca_proxy_set_centers", ctypes.c_double)
    r = h.pointer("ca_proxy_set_radii", ctypes.c_double)
    primitives = []
    for i in range(n):
        a, b = tuple(c[6 * i + k] for k in range(3)), tuple(c[6 * i + 3 + k] for k in range(3))
        if kinds[i] == 1:
            primitives.append({"kind": "capsule", "a": a, "radius_a": r[2 * i], "b": b, "radius_b": r[2 * i + 1]})
        else:
            primitives.append({"kind": "sphere", "center": a, "radius": r[2 * i]})
    return Proxies(primitives, struct_dict(h.read("ca_proxy_set_stats", _ProxyStats)))


class BoneColliders:
    """Bone colliders (bone_colliders()): `colliders`, one dict per collider, each in ITS JOINT'S
    frame: {"joint": j, "kind": "sphere" | "capsule", "center": (x, y, z), "rotation": (x, y, z, w),
    "axis": (x, y, z), "radius_top", "radius_bottom", "height" (ca_proxy_placement's conventions),
    "contained": fraction of its part's fresh samples held, "overlap": volume shared with its
    parent's collider}, and `stats` (ca_bone_collider_stats)."""

    def __init__(self, colliders, stats):
        self.colliders, self.stats = colliders, stats

    def __len__(self):
        return len(self.colliders)


def bone_colliders(candidate_set, parents, vertex_joints, vertex_weights, inverse_bind=None, *, skip_joints=None,
                   context=None, **options):
    """One tapered capsule or sphere per joint of a skin of the candidate set's mesh, fitted to the
    part of the surface the joint dominates (docs/bone_colliders.md). `parents`: one per joint, -1
    for a root; `vertex_joints`, `vertex_weights`: (vertex_count, influences), 1 to 8 influences;
    `inverse_bind`: (joint_count, 16) column-major matrices (None: identity); `skip_joints`: joint
    indices to give none. Options: mode ("conservative" | "inscribed"), shapes ("capsules" |
    "spheres"), min_share, min_size, surface_samples, evaluate_samples, seed."""
    opts = _options("bone_colliders", options)
    par = [int(p) for p in (parents.tolist() if hasattr(parents, "tolist") else parents)]
    par_arr = (ctypes.c_int32 * max(len(par), 1))(*par)
    first = vertex_joints[0] if len(vertex_joints) else []
    influences = len(first) if hasattr(first, "__len__") else 0
    if influences == 0:
        raise CoverageAxisError(CA_ERROR_INVALID_INPUT, "vertex_joints: expected shape (n, influences), 1 to 8 influences")
    vj = _arrays.indices(vertex_joints, "vertex_joints", influences)
    vw = _arrays.points(vertex_weights, "vertex_weights", influences, packed=True)
    if vj.count != vw.count:
        raise CoverageAxisError(CA_ERROR_INVALID_INPUT, "vertex_weights: %d rows, vertex_joints has %d" % (vw.count, vj.count))
    keep = [par_arr, vj, vw]
    view = fill_defaults("ca_skin_view_defaults", _SkinView)
    view.joint_count, view.parents = len(par), ctypes.cast(par_arr, ctypes.c_void_p)
    view.vertex_count, view.influences = vj.count, influences
    view.vertex_joints, view.vertex_weights = vj.address, vw.address
    if inverse_bind is not None:
        ib = _arrays.points(inverse_bind, "inverse_bind", 16, packed=True)
        if ib.count != len(par):
            raise CoverageAxisError(CA_ERROR_INVALID_INPUT, "inverse_bind: %d matrices for %d joints" % (ib.count, len(par)))
        view.inverse_bind = ib.address
        keep.append(ib)
    if skip_joints is not None and len(skip_joints):
        skip = _arrays.indices(skip_joints, "skip_joints", 1)
        opts.skip_joints, opts.skip_count = skip.address, skip.count
        keep.append(skip)
    h = _Handle(_make(context, lib().ca_bone_colliders_build, candidate_set._handle._ptr, None, ctypes.byref(view),
                      ctypes.byref(opts)), "ca_bone_colliders_destroy")
    del keep
    n = h.get("ca_bone_colliders_count")
    joints = h.pointer("ca_bone_colliders_joints", ctypes.c_uint32)
    contained = h.pointer("ca_bone_colliders_contained", ctypes.c_double)
    overlap = h.pointer("ca_bone_colliders_overlap", ctypes.c_double)
    colliders = []
    for i in range(n):
        pl = h.read("ca_bone_colliders_placement", _ProxyPlacement, i)
        colliders.append({"joint": joints[i], "kind": "capsule" if pl.kind == 1 else "sphere",
                          "center": tuple(pl.center), "rotation": tuple(pl.rotation), "axis": tuple(pl.axis),
                          "radius_top": pl.radius_top, "radius_bottom": pl.radius_bottom, "height": pl.height,
                          "contained": contained[i], "overlap": overlap[i]})
    return BoneColliders(colliders, struct_dict(h.read("ca_bone_colliders_stats", _BoneColliderStats)))


def _column(values):
    """(n,) radii as (n, 1) rows, for points()."""
    if _arrays.np is not None:
        return _arrays.np.asarray(values).reshape(-1, 1)
    return [(v,) for v in values]


def skeletonize(vertices, triangles=None, normals=None, *, context=None, connect=None, point_normals=None,
                **options):
    """candidates() -> select() -> connect() in one call; options of all three steps (connect= is
    method=; point_normals= as in candidates()). The skeleton's stats hold the selection's and the
    skeleton's statistics (the skeleton's where both have a name, e.g. components) and the
    candidate count."""
    steps = {step: {} for step in ("candidates", "select", "connect")}
    if connect is not None:
        options.setdefault("method", connect)
    for name, value in options.items():
        step = next((s for s in steps if name in _option_names(s) or (s == "select" and name in _MASKS)), None)
        if step is None:
            raise TypeError("skeletonize() got an unknown option %r" % name)
        steps[step][name] = value
    cset = candidates(vertices, triangles, normals, context=context, point_normals=point_normals,
                      **steps["candidates"])
    try:
        sel = select(cset, context=context, **steps["select"])
    except TargetNotReachedError as e:  # the best skeleton travels with the error
        e.skeleton = _connect_step(e.selection, context=context, **steps["connect"])
        e.skeleton.stats = dict(e.selection.stats, **e.skeleton.stats, candidates=cset.count)
        raise
    except SearchStoppedError as e:  # the time limit: connected when the context's budget allows
        try:
            e.skeleton = _connect_step(e.selection, context=context, **steps["connect"])
            e.skeleton.stats = dict(e.selection.stats, **e.skeleton.stats, candidates=cset.count)
        except CoverageAxisError:
            pass
        raise
    sk = _connect_step(sel, context=context, **steps["connect"])
    sk.stats = dict(sel.stats, **sk.stats, candidates=cset.count)
    return sk

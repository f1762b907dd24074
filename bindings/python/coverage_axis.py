"""coverage_axis.py: Python binding of the coverage-axis C ABI through ctypes (standard library
only). It loads libcoverage_axis.so (path from $CA_LIBRARY, else the system's search path),
checks the ABI version, and wraps the three steps, the evaluation and the error codes.

    import coverage_axis as ca
    sk = ca.skeletonize(vertices, triangles, delta=0.02)   # vertices: [(x, y, z)], triangles: [(i, j, k)]
    sk.centers, sk.radii, sk.edges, sk.faces, sk.stats
    ca.evaluate(vertices, triangles, sk)                   # Hausdorff distances, % of the bbox diagonal
"""
import ctypes
import os
from ctypes import POINTER, Structure, c_char_p, c_double, c_int32, c_int64, c_size_t, c_uint8, c_uint32, c_uint64, c_void_p

ABI_VERSION = 2

STATUS_NAMES = {
    0: "CA_OK", 1: "CA_ERROR_INVALID_ARGUMENT", 2: "CA_ERROR_NULL_POINTER", 3: "CA_ERROR_STRUCT_SIZE",
    4: "CA_ERROR_INVALID_INPUT", 5: "CA_ERROR_DEGENERATE_INPUT", 6: "CA_ERROR_UNCOVERABLE", 7: "CA_ERROR_GEOMETRY",
    8: "CA_ERROR_SOLVER", 9: "CA_ERROR_CANCELLED", 10: "CA_ERROR_OUT_OF_MEMORY", 11: "CA_ERROR_BUFFER_TOO_SMALL",
    12: "CA_ERROR_INTERNAL", 13: "CA_ERROR_NO_CANDIDATES",
}
SOLVERS = {"exact": 0, "greedy": 1, "capp": 2}
EFFORTS = {"fast": 0, "prove": 1}
CONNECT = {"power": 0, "medial": 1, "auto": 2}
GENERATORS = {"voronoi": 0, "random": 1}


class CoverageAxisError(Exception):
    """A call returned a status other than CA_OK; .status is the code, str() the library's message."""

    def __init__(self, status, message):
        super().__init__("%s: %s" % (STATUS_NAMES.get(status, status), message))
        self.status = status


class _SurfaceView(Structure):
    _fields_ = [("struct_size", c_uint32), ("positions", POINTER(c_double)), ("vertex_count", c_size_t),
                ("position_stride", c_size_t), ("triangles", POINTER(c_uint32)), ("triangle_count", c_size_t),
                ("triangle_stride", c_size_t), ("normals", POINTER(c_double)), ("normal_stride", c_size_t)]


class _CandidateOptions(Structure):
    _fields_ = [("struct_size", c_uint32), ("generator", c_int32), ("cover_samples", c_uint32),
                ("voronoi_samples", c_uint32), ("random_candidates", c_uint32), ("seed", c_uint64),
                ("connect_samples", c_uint32)]


class _SelectOptions(Structure):
    _fields_ = [("struct_size", c_uint32), ("dilation", c_int32), ("delta", c_double), ("scale", c_double),
                ("solver", c_int32), ("time_limit_s", c_double), ("skip_uncoverable", c_int32),
                ("ignorable_samples", POINTER(c_uint8)), ("forced_in", POINTER(c_uint8)), ("forced_out", POINTER(c_uint8)),
                ("target_count", c_uint32), ("target_tolerance", c_double), ("divide_threshold", c_uint32),
                ("effort", c_int32)]


class _SelectStats(Structure):
    _fields_ = [("struct_size", c_uint32), ("proven_optimal", c_int32), ("solver", c_int32), ("objective", c_double),
                ("lower_bound", c_double), ("gap", c_double), ("delta_absolute", c_double), ("time_reduce_s", c_double),
                ("time_solve_s", c_double), ("time_total_s", c_double), ("rows_before", c_uint64),
                ("cols_before", c_uint64), ("rows_after", c_uint64), ("cols_after", c_uint64), ("forced", c_uint64),
                ("components", c_uint64), ("probes", c_uint64), ("parts", c_uint64), ("scale_used", c_double),
                ("time_coverage_s", c_double), ("cbc_components", c_uint64), ("rowgen_rounds", c_uint64)]


class _ConnectOptions(Structure):
    _fields_ = [("struct_size", c_uint32), ("method", c_int32), ("remove_outside", c_int32), ("fill_holes", c_int32),
                ("reconnect", c_int32)]


class _SkeletonStats(Structure):
    _fields_ = [("struct_size", c_uint32), ("vertices", c_uint64), ("edges", c_uint64), ("faces", c_uint64),
                ("components", c_uint64), ("isolated", c_uint64), ("betti1", c_int64), ("time_s", c_double),
                ("method", c_int32)]


class _SkeletonView(Structure):
    _fields_ = [("struct_size", c_uint32), ("centers", POINTER(c_double)), ("radii", POINTER(c_double)),
                ("vertex_count", c_size_t), ("edges", POINTER(c_uint32)), ("edge_count", c_size_t),
                ("faces", POINTER(c_uint32)), ("face_count", c_size_t)]


class _EvaluateOptions(Structure):
    _fields_ = [("struct_size", c_uint32), ("surface_samples", c_uint32), ("envelope_samples", c_uint32),
                ("seed", c_uint64)]


class _Evaluation(Structure):
    _fields_ = [("struct_size", c_uint32), ("hd_surface_to_recon", c_double), ("mean_surface_to_recon", c_double),
                ("hd_recon_to_surface", c_double), ("mean_recon_to_surface", c_double), ("hd_two_sided", c_double),
                ("diagonal", c_double), ("surface_samples_used", c_uint64), ("envelope_samples_used", c_uint64),
                ("time_s", c_double)]


def _load():
    lib = ctypes.CDLL(os.environ.get("CA_LIBRARY", "libcoverage_axis.so"))
    P = c_void_p
    sig = {
        "ca_version": (c_uint32, []), "ca_abi_version": (c_uint32, []), "ca_status_string": (c_char_p, [c_int32]),
        "ca_context_create": (c_int32, [P, POINTER(P)]), "ca_context_destroy": (None, [P]),
        "ca_context_last_error": (c_char_p, [P]),
        "ca_surface_view_defaults": (c_int32, [POINTER(_SurfaceView), c_uint32]),
        "ca_candidate_options_defaults": (c_int32, [POINTER(_CandidateOptions), c_uint32]),
        "ca_candidates": (c_int32, [P, POINTER(_SurfaceView), POINTER(_CandidateOptions), POINTER(P)]),
        "ca_candidate_set_destroy": (None, [P]), "ca_candidate_set_count": (c_size_t, [P]),
        "ca_select_options_defaults": (c_int32, [POINTER(_SelectOptions), c_uint32]),
        "ca_select": (c_int32, [P, P, POINTER(_SelectOptions), POINTER(P)]),
        "ca_selection_destroy": (None, [P]), "ca_selection_stats": (c_int32, [P, POINTER(_SelectStats)]),
        "ca_connect_options_defaults": (c_int32, [POINTER(_ConnectOptions), c_uint32]),
        "ca_connect": (c_int32, [P, P, P, POINTER(_ConnectOptions), POINTER(P)]),
        "ca_skeleton_destroy": (None, [P]), "ca_skeleton_vertex_count": (c_size_t, [P]),
        "ca_skeleton_centers": (POINTER(c_double), [P]), "ca_skeleton_radii": (POINTER(c_double), [P]),
        "ca_skeleton_edge_count": (c_size_t, [P]), "ca_skeleton_edges": (POINTER(c_uint32), [P]),
        "ca_skeleton_face_count": (c_size_t, [P]), "ca_skeleton_faces": (POINTER(c_uint32), [P]),
        "ca_skeleton_stats_get": (c_int32, [P, POINTER(_SkeletonStats)]),
        "ca_skeleton_view_defaults": (c_int32, [POINTER(_SkeletonView), c_uint32]),
        "ca_evaluate_options_defaults": (c_int32, [POINTER(_EvaluateOptions), c_uint32]),
        "ca_evaluate": (c_int32, [P, POINTER(_SurfaceView), POINTER(_SkeletonView), POINTER(_EvaluateOptions),
                                  POINTER(_Evaluation)]),
    }
    for name, (res, args) in sig.items():
        f = getattr(lib, name)
        f.restype, f.argtypes = res, args
    if lib.ca_abi_version() != ABI_VERSION:
        raise ImportError("libcoverage_axis ABI version %d, this binding needs %d" % (lib.ca_abi_version(), ABI_VERSION))
    return lib


_lib = _load()


def _init(defaults, struct):
    """Fills a struct with the library's defaults for this binding's layout (its ctypes size)."""
    status = defaults(ctypes.byref(struct), ctypes.sizeof(struct))
    if status:
        raise CoverageAxisError(status, "%s: the library does not accept struct_size %d" %
                                (type(struct).__name__, ctypes.sizeof(struct)))


def version():
    v = _lib.ca_version()
    return "%d.%d.%d" % (v // 10000, v // 100 % 100, v % 100)


class _Context:
    def __enter__(self):
        self.ptr = c_void_p()
        status = _lib.ca_context_create(None, ctypes.byref(self.ptr))
        if status:
            raise CoverageAxisError(status, "cannot create a context")
        return self

    def check(self, status):
        if status:
            raise CoverageAxisError(status, _lib.ca_context_last_error(self.ptr).decode())

    def __exit__(self, *exc):
        _lib.ca_context_destroy(self.ptr)


def _surface(vertices, triangles, normals=None):
    flat = [float(c) for v in vertices for c in v]
    tris = [int(i) for t in triangles for i in t] if triangles else []
    if any(i < 0 or i > 0xFFFFFFFF for i in tris):
        raise CoverageAxisError(4, "triangle indices must be in [0, 2^32)")
    pos = (c_double * len(flat))(*flat)
    tri = (c_uint32 * len(tris))(*tris)
    view = _SurfaceView()
    _init(_lib.ca_surface_view_defaults, view)
    view.positions = pos
    view.vertex_count = len(flat) // 3
    view.triangles = tri
    view.triangle_count = len(tris) // 3
    keep = [pos, tri]
    if normals is not None:
        nflat = [float(c) for n in normals for c in n]
        nrm = (c_double * len(nflat))(*nflat)
        view.normals = nrm
        keep.append(nrm)
    return view, keep


class Skeleton:
    """Medial balls (centers, radii), edges and faces, in the input's units, plus statistics."""

    def __init__(self, centers, radii, edges, faces, stats):
        self.centers, self.radii, self.edges, self.faces, self.stats = centers, radii, edges, faces, stats


def skeletonize(vertices, triangles=None, normals=None, delta=0.02, scale=None, cover_samples=1500,
                voronoi_samples=4000, generator="voronoi", random_candidates=10000, solver="exact",
                time_limit_s=60.0, skip_uncoverable=False, seed=1, target_count=0, connect="auto",
                effort="fast"):
    """Runs candidates -> selection -> connection. Raises CoverageAxisError on bad input."""
    view, keep = _surface(vertices, triangles, normals)
    co = _CandidateOptions()
    _init(_lib.ca_candidate_options_defaults, co)
    co.generator, co.cover_samples, co.voronoi_samples = GENERATORS[generator], cover_samples, voronoi_samples
    co.random_candidates, co.seed = random_candidates, seed
    so = _SelectOptions()
    _init(_lib.ca_select_options_defaults, so)
    if scale is not None:
        so.dilation, so.scale = 1, scale
    else:
        so.delta = delta
    so.solver, so.time_limit_s, so.skip_uncoverable = SOLVERS[solver], time_limit_s, int(skip_uncoverable)
    so.target_count = target_count
    so.effort = EFFORTS[effort]
    cop = _ConnectOptions()
    _init(_lib.ca_connect_options_defaults, cop)
    cop.method = CONNECT[connect]
    with _Context() as ctx:
        cset, sel, sk = c_void_p(), c_void_p(), c_void_p()
        try:
            ctx.check(_lib.ca_candidates(ctx.ptr, ctypes.byref(view), ctypes.byref(co), ctypes.byref(cset)))
            ctx.check(_lib.ca_select(ctx.ptr, cset, ctypes.byref(so), ctypes.byref(sel)))
            ctx.check(_lib.ca_connect(ctx.ptr, cset, sel, ctypes.byref(cop), ctypes.byref(sk)))
            n, ne, nf = (_lib.ca_skeleton_vertex_count(sk), _lib.ca_skeleton_edge_count(sk),
                         _lib.ca_skeleton_face_count(sk))
            c, r = _lib.ca_skeleton_centers(sk), _lib.ca_skeleton_radii(sk)
            e, f = _lib.ca_skeleton_edges(sk), _lib.ca_skeleton_faces(sk)
            ss = _SelectStats(struct_size=ctypes.sizeof(_SelectStats))
            ctx.check(_lib.ca_selection_stats(sel, ctypes.byref(ss)))
            ks = _SkeletonStats(struct_size=ctypes.sizeof(_SkeletonStats))
            ctx.check(_lib.ca_skeleton_stats_get(sk, ctypes.byref(ks)))
            stats = {"proven_optimal": bool(ss.proven_optimal), "objective": ss.objective,
                     "lower_bound": ss.lower_bound, "gap": ss.gap, "delta_absolute": ss.delta_absolute,
                     "components": ks.components, "isolated": ks.isolated, "betti1": ks.betti1,
                     "candidates": _lib.ca_candidate_set_count(cset)}
            return Skeleton([(c[3 * i], c[3 * i + 1], c[3 * i + 2]) for i in range(n)], [r[i] for i in range(n)],
                            [(e[2 * i], e[2 * i + 1]) for i in range(ne)],
                            [(f[3 * i], f[3 * i + 1], f[3 * i + 2]) for i in range(nf)], stats)
        finally:
            _lib.ca_skeleton_destroy(sk)
            _lib.ca_selection_destroy(sel)
            _lib.ca_candidate_set_destroy(cset)
            del keep


def evaluate(vertices, triangles, skeleton, surface_samples=30000, envelope_samples=100000, seed=1):
    """Hausdorff distances between the surface and the skeleton's reconstruction, % of the bbox diagonal."""
    view, keep = _surface(vertices, triangles)
    n = len(skeleton.radii)
    cflat = [float(x) for c in skeleton.centers for x in c]
    eflat = [int(i) for e in skeleton.edges for i in e]
    fflat = [int(i) for f in skeleton.faces for i in f]
    c_arr, r_arr = (c_double * len(cflat))(*cflat), (c_double * n)(*skeleton.radii)
    e_arr, f_arr = (c_uint32 * len(eflat))(*eflat), (c_uint32 * len(fflat))(*fflat)
    sv = _SkeletonView()
    _init(_lib.ca_skeleton_view_defaults, sv)
    sv.centers, sv.radii, sv.vertex_count = c_arr, r_arr, n
    sv.edges, sv.edge_count, sv.faces, sv.face_count = e_arr, len(eflat) // 2, f_arr, len(fflat) // 3
    eo = _EvaluateOptions()
    _init(_lib.ca_evaluate_options_defaults, eo)
    eo.surface_samples, eo.envelope_samples, eo.seed = surface_samples, envelope_samples, seed
    out = _Evaluation(struct_size=ctypes.sizeof(_Evaluation))
    with _Context() as ctx:
        ctx.check(_lib.ca_evaluate(ctx.ptr, ctypes.byref(view), ctypes.byref(sv), ctypes.byref(eo), ctypes.byref(out)))
    del keep
    return {name: getattr(out, name) for name, _ in _Evaluation._fields_ if name != "struct_size"}

"""_library.py: finds and loads the shared library libcoverage_axis, declares the signature of
every ca_* function the binding calls, checks the ABI version, and turns statuses into
CoverageAxisError.

The library is the path given to load_library(path) (an application's own setting, e.g. a
preference), else $CA_LIBRARY: either, when given, is the only place tried (a wrong setting is
reported, not replaced by another copy). Without them, first found wins: a libcoverage_axis.so*
bundled in this package's folder, the path `make install` wrote into _install_path.py, then
ctypes.util.find_library("coverage_axis") (the system's search path).
It is loaded on first use, so `import coverage_axis` works without it."""
import ctypes
import ctypes.util
import glob
import os
import threading
from ctypes import POINTER, CFUNCTYPE, c_char_p, c_double, c_int32, c_size_t, c_uint32, c_uint64, c_void_p

from ._structs import (_CandidateOptions, _ConnectOptions, _ContextDesc, _CorrespondenceOptions, _EvaluateOptions,
                       _Evaluation, _ProxyOptions, _ProxyPlacement, _ProxyStats, _RigOptions, _SelectOptions,
                       _SelectStats, _SkeletonStats, _SkeletonView, _SurfaceView, _SkinView, _BoneColliderOptions,
                       _BoneColliderStats)

ABI_VERSION = 3

# the header's pinned status codes, CA_OK = 0 ... CA_ERROR_TARGET_NOT_REACHED = 15
STATUS_NAMES = ("CA_OK", "CA_ERROR_INVALID_ARGUMENT", "CA_ERROR_NULL_POINTER", "CA_ERROR_STRUCT_SIZE",
                "CA_ERROR_INVALID_INPUT", "CA_ERROR_DEGENERATE_INPUT", "CA_ERROR_UNCOVERABLE", "CA_ERROR_GEOMETRY",
                "CA_ERROR_SOLVER", "CA_ERROR_CANCELLED", "CA_ERROR_OUT_OF_MEMORY", "CA_ERROR_BUFFER_TOO_SMALL",
                "CA_ERROR_INTERNAL", "CA_ERROR_NO_CANDIDATES", "CA_ERROR_TIME_LIMIT",
                "CA_ERROR_TARGET_NOT_REACHED")
(CA_OK, CA_ERROR_INVALID_ARGUMENT, CA_ERROR_NULL_POINTER, CA_ERROR_STRUCT_SIZE, CA_ERROR_INVALID_INPUT,
 CA_ERROR_DEGENERATE_INPUT, CA_ERROR_UNCOVERABLE, CA_ERROR_GEOMETRY, CA_ERROR_SOLVER, CA_ERROR_CANCELLED,
 CA_ERROR_OUT_OF_MEMORY, CA_ERROR_BUFFER_TOO_SMALL, CA_ERROR_INTERNAL, CA_ERROR_NO_CANDIDATES,
 CA_ERROR_TIME_LIMIT, CA_ERROR_TARGET_NOT_REACHED) = range(16)

LOG_FN = CFUNCTYPE(None, c_void_p, c_int32, c_char_p)
PROGRESS_FN = CFUNCTYPE(c_int32, c_void_p, c_char_p, c_double)


class CoverageAxisError(Exception):
    """A call failed: .status is the ca_status code (CA_ERROR_*), .message the explanation."""

    def __init__(self, status, message):
        name = STATUS_NAMES[status] if 0 <= status < len(STATUS_NAMES) else "status %d" % status
        super().__init__("%s: %s" % (name, message))
        self.status = status
        self.message = message


class SearchStoppedError(CoverageAxisError):
    """select() or skeletonize() with target_error or target_count: the context's time limit ended
    the search after a probe (status CA_ERROR_TIME_LIMIT). .selection holds the best selection so
    far (its stats' hd_reached and probes), and from skeletonize() .skeleton its skeleton (None when
    no time was left to connect it)."""

    def __init__(self, message, selection):
        super().__init__(CA_ERROR_TIME_LIMIT, message)
        self.selection = selection
        self.skeleton = None


class TargetNotReachedError(CoverageAxisError):
    """select() or skeletonize() with target_error: no probe reached it. .selection holds the
    selection of lowest HD found (its stats' hd_reached), and from skeletonize() .skeleton its
    skeleton."""

    def __init__(self, message, selection):
        super().__init__(CA_ERROR_TARGET_NOT_REACHED, message)
        self.selection = selection
        self.skeleton = None


class LibraryNotFoundError(ImportError):
    """libcoverage_axis could not be found or loaded; the message lists every place tried."""


P = c_void_p
_SIGNATURES = {
    "ca_version": (c_uint32, []), "ca_version_string": (c_char_p, []), "ca_abi_version": (c_uint32, []), "ca_status_string": (c_char_p, [c_int32]),
    "ca_context_desc_defaults": (c_int32, [POINTER(_ContextDesc), c_uint32]),
    "ca_context_create": (c_int32, [POINTER(_ContextDesc), POINTER(P)]), "ca_context_destroy": (None, [P]),
    "ca_context_request_cancel": (None, [P]), "ca_context_clear_cancel": (None, [P]),
    "ca_context_last_error": (c_char_p, [P]),
    "ca_surface_view_defaults": (c_int32, [POINTER(_SurfaceView), c_uint32]),
    "ca_candidate_options_defaults": (c_int32, [POINTER(_CandidateOptions), c_uint32]),
    "ca_candidates": (c_int32, [P, POINTER(_SurfaceView), POINTER(_CandidateOptions), POINTER(P)]),
    "ca_candidate_set_destroy": (None, [P]), "ca_candidate_set_count": (c_size_t, [P]),
    "ca_candidate_set_centers": (P, [P]), "ca_candidate_set_radii": (P, [P]),
    "ca_candidate_set_sample_count": (c_size_t, [P]), "ca_candidate_set_samples": (P, [P]),
    "ca_candidate_set_reference_length": (c_double, [P]), "ca_candidate_set_flipped": (c_int32, [P]),
    "ca_candidate_set_normals": (c_int32, [P]),
    "ca_candidate_set_outlier_count": (c_uint64, [P]),
    "ca_select_options_defaults": (c_int32, [POINTER(_SelectOptions), c_uint32]),
    "ca_select": (c_int32, [P, P, POINTER(_SelectOptions), POINTER(P)]),
    "ca_selection_destroy": (None, [P]), "ca_selection_count": (c_size_t, [P]),
    "ca_selection_indices": (P, [P]), "ca_selection_centers": (P, [P]), "ca_selection_radii": (P, [P]),
    "ca_selection_dilated_radii": (P, [P]), "ca_selection_uncovered_count": (c_size_t, [P]),
    "ca_selection_uncovered": (P, [P]), "ca_selection_stats": (c_int32, [P, POINTER(_SelectStats)]),
    "ca_connect_options_defaults": (c_int32, [POINTER(_ConnectOptions), c_uint32]),
    "ca_connect": (c_int32, [P, P, P, POINTER(_ConnectOptions), POINTER(P)]),
    "ca_skeleton_destroy": (None, [P]), "ca_skeleton_vertex_count": (c_size_t, [P]),
    "ca_skeleton_centers": (P, [P]), "ca_skeleton_radii": (P, [P]),
    "ca_skeleton_edge_count": (c_size_t, [P]), "ca_skeleton_edges": (P, [P]),
    "ca_skeleton_face_count": (c_size_t, [P]), "ca_skeleton_faces": (P, [P]),
    "ca_skeleton_stats_get": (c_int32, [P, POINTER(_SkeletonStats)]),
    "ca_skeleton_view_defaults": (c_int32, [POINTER(_SkeletonView), c_uint32]),
    "ca_evaluate_options_defaults": (c_int32, [POINTER(_EvaluateOptions), c_uint32]),
    "ca_evaluate": (c_int32, [P, POINTER(_SurfaceView), POINTER(_SkeletonView), POINTER(_EvaluateOptions),
                              POINTER(_Evaluation)]),
    # correspondence and rig
    "ca_correspondence_options_defaults": (c_int32, [POINTER(_CorrespondenceOptions), c_uint32]),
    "ca_correspond": (c_int32, [P, POINTER(_SurfaceView), POINTER(_SkeletonView), POINTER(_CorrespondenceOptions),
                                POINTER(P)]),
    "ca_correspondence_destroy": (None, [P]), "ca_correspondence_vertex_count": (c_size_t, [P]),
    "ca_correspondence_balls": (P, [P]), "ca_correspondence_weights": (P, [P]),
    "ca_correspondence_nearest_kinds": (P, [P]), "ca_correspondence_nearest_indices": (P, [P]),
    "ca_rig_options_defaults": (c_int32, [POINTER(_RigOptions), c_uint32]),
    "ca_rig_build": (c_int32, [P, POINTER(_SurfaceView), POINTER(_SkeletonView), POINTER(_RigOptions), POINTER(P)]),
    "ca_rig_destroy": (None, [P]), "ca_rig_joint_count": (c_size_t, [P]), "ca_rig_joint_positions": (P, [P]),
    "ca_rig_joint_parents": (P, [P]), "ca_rig_joint_balls": (P, [P]), "ca_rig_joint_branches": (P, [P]),
    "ca_rig_branch_count": (c_size_t, [P]), "ca_rig_vertex_count": (c_size_t, [P]),
    "ca_rig_vertex_joints": (P, [P]), "ca_rig_vertex_weights": (P, [P]), "ca_rig_vertex_branches": (P, [P]),
    "ca_proxy_options_defaults": (c_int32, [POINTER(_ProxyOptions), c_uint32]),
    "ca_proxies": (c_int32, [P, P, POINTER(_SkeletonView), POINTER(_ProxyOptions), POINTER(P)]),
    "ca_proxy_set_destroy": (None, [P]), "ca_proxy_set_count": (c_size_t, [P]),
    "ca_proxy_set_kinds": (P, [P]), "ca_proxy_set_centers": (P, [P]), "ca_proxy_set_radii": (P, [P]),
    "ca_proxy_set_stats": (c_int32, [P, POINTER(_ProxyStats)]),
    "ca_proxy_set_placement": (c_int32, [P, c_size_t, POINTER(_ProxyPlacement)]),
    "ca_skin_view_defaults": (c_int32, [POINTER(_SkinView), c_uint32]),
    "ca_bone_collider_options_defaults": (c_int32, [POINTER(_BoneColliderOptions), c_uint32]),
    "ca_bone_colliders_build": (c_int32, [P, P, POINTER(_SkeletonView), POINTER(_SkinView),
                                          POINTER(_BoneColliderOptions), POINTER(P)]),
    "ca_bone_colliders_destroy": (None, [P]), "ca_bone_colliders_count": (c_size_t, [P]),
    "ca_bone_colliders_joints": (P, [P]), "ca_bone_colliders_contained": (P, [P]),
    "ca_bone_colliders_overlap": (P, [P]),
    "ca_bone_colliders_stats": (c_int32, [P, POINTER(_BoneColliderStats)]),
    "ca_bone_colliders_placement": (c_int32, [P, c_size_t, POINTER(_ProxyPlacement)]),
}

_lock = threading.Lock()
_loaded = None


def _candidates(path):
    if path:
        yield "load_library()", path
        return
    if os.environ.get("CA_LIBRARY"):
        yield "$CA_LIBRARY", os.environ["CA_LIBRARY"]
        return
    here = os.path.dirname(os.path.abspath(__file__))
    for bundled in sorted(glob.glob(os.path.join(here, "libcoverage_axis.so*")) +
                          glob.glob(os.path.join(here, "libcoverage_axis*.dylib")) +
                          glob.glob(os.path.join(here, "coverage_axis*.dll"))):
        yield "bundled", bundled
    try:
        from ._install_path import LIBRARY
        yield "installed", LIBRARY
    except ImportError:
        pass
    found = ctypes.util.find_library("coverage_axis")
    if found:
        yield "find_library", found


def _open(path):
    tried = []
    for where, candidate in _candidates(path):
        try:
            lib = ctypes.CDLL(candidate)
        except OSError as e:
            tried.append("%s %s: %s" % (where, candidate, e))
            continue
        for name, (res, args) in _SIGNATURES.items():
            f = getattr(lib, name)
            f.restype, f.argtypes = res, args
        # a library of a later ABI also serves: it accepts every struct layout it ever published
        if lib.ca_abi_version() < ABI_VERSION:
            tried.append("%s %s: ABI version %d, this binding needs %d or later" %
                         (where, candidate, lib.ca_abi_version(), ABI_VERSION))
            continue
        return lib, candidate
    raise LibraryNotFoundError(
        "libcoverage_axis not found; set CA_LIBRARY=/path/to/libcoverage_axis.so, call "
        "coverage_axis.load_library(path), or run `make install`. Tried: " +
        ("; ".join(tried) if tried else "nothing (no $CA_LIBRARY, no bundled copy, no installed path, "
                                         "find_library found none)"))


def load_library(path=None):
    """Loads the library now (from `path` if given, else the search order above) and returns
    the path it was loaded from. Raises LibraryNotFoundError with every place tried."""
    global _loaded
    with _lock:
        if _loaded is None:
            _loaded = _open(path)
        elif path and os.path.realpath(path) != os.path.realpath(_loaded[1]):
            # objects made by the loaded copy must be destroyed by it: one library per process
            raise RuntimeError("libcoverage_axis is already loaded from %s" % _loaded[1])
        return _loaded[1]


def lib():
    """The loaded library (loading it on first use)."""
    if _loaded is None:
        load_library()
    return _loaded[0]


def fill_defaults(defaults_name, struct_type):
    """A struct_type filled by the library's ca_*_defaults for this binding's layout (its ctypes size)."""
    s = struct_type()
    status = getattr(lib(), defaults_name)(ctypes.byref(s), ctypes.sizeof(s))
    if status:
        raise CoverageAxisError(status, "%s: the library does not accept struct_size %d" %
                                (struct_type.__name__, ctypes.sizeof(s)))
    return s


def output_struct(struct_type):
    """An output struct with struct_size set (the library writes only that many bytes)."""
    return struct_type(struct_size=ctypes.sizeof(struct_type))


def struct_dict(s):
    """The fields of a ctypes struct as a dict, without struct_size."""
    return {name: getattr(s, name) for name, _ in s._fields_ if name != "struct_size"}

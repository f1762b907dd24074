"""coverage_axis: Python binding of the coverage-axis library (Coverage Axis skeletonization,
Dou et al., EG 2022) over its C ABI with ctypes. numpy arrays in and out when numpy is installed
(lists of tuples otherwise).

    import coverage_axis as ca
    sk = ca.skeletonize(vertices, triangles, delta=0.02)   # vertices (n, 3), triangles (m, 3)
    sk.centers, sk.radii, sk.edges, sk.faces, sk.stats
    ca.evaluate(vertices, triangles, sk)                   # Hausdorff distances, % of the bbox diagonal
    ca.correspond(vertices, triangles, sk)                 # per vertex: 4 balls, weights, nearest primitive
    ca.rig(vertices, triangles, sk)                        # joints (a tree) and per-vertex joint weights
    ca.proxies(cset, sk, mode="conservative", count=8)     # spheres and tapered capsules for engines

Steps one by one: candidates() -> select() -> connect(); a Context gives threads, progress, log
and a cancel() any thread may call. Errors raise CoverageAxisError (.status, .message)."""
from ._arrays import HAVE_NUMPY
from ._context import Context
from ._library import (ABI_VERSION, STATUS_NAMES, CoverageAxisError, LibraryNotFoundError, SearchStoppedError,
                       TargetNotReachedError,
                       lib as _lib, load_library)
from ._library import (CA_OK, CA_ERROR_INVALID_ARGUMENT, CA_ERROR_NULL_POINTER, CA_ERROR_STRUCT_SIZE,
                       CA_ERROR_INVALID_INPUT, CA_ERROR_DEGENERATE_INPUT, CA_ERROR_UNCOVERABLE, CA_ERROR_GEOMETRY,
                       CA_ERROR_SOLVER, CA_ERROR_CANCELLED, CA_ERROR_OUT_OF_MEMORY, CA_ERROR_BUFFER_TOO_SMALL,
                       CA_ERROR_INTERNAL, CA_ERROR_NO_CANDIDATES, CA_ERROR_TIME_LIMIT,
                       CA_ERROR_TARGET_NOT_REACHED)
from ._steps import (BoneColliders, CandidateSet, Proxies, Selection, Skeleton, bone_colliders, candidates, connect,
                     defaults, evaluate, proxies, select, skeletonize)
from ._rig import INFLUENCES, NEAREST_KINDS, Correspondence, Rig, correspond, rig

__all__ = ["HAVE_NUMPY", "Context", "ABI_VERSION", "STATUS_NAMES", "CoverageAxisError", "LibraryNotFoundError",
           "SearchStoppedError", "TargetNotReachedError",
           "load_library", "CandidateSet", "Proxies", "Selection", "Skeleton", "candidates", "connect", "defaults",
           "evaluate", "proxies", "select", "skeletonize", "version", "Correspondence", "Rig", "correspond", "rig",
           "BoneColliders", "bone_colliders",
           "INFLUENCES", "NEAREST_KINDS",
           "CA_OK", "CA_ERROR_INVALID_ARGUMENT", "CA_ERROR_NULL_POINTER", "CA_ERROR_STRUCT_SIZE",
           "CA_ERROR_INVALID_INPUT", "CA_ERROR_DEGENERATE_INPUT", "CA_ERROR_UNCOVERABLE", "CA_ERROR_GEOMETRY",
           "CA_ERROR_SOLVER", "CA_ERROR_CANCELLED", "CA_ERROR_OUT_OF_MEMORY", "CA_ERROR_BUFFER_TOO_SMALL",
           "CA_ERROR_INTERNAL", "CA_ERROR_NO_CANDIDATES", "CA_ERROR_TIME_LIMIT",
           "CA_ERROR_TARGET_NOT_REACHED"]


def version():
    """The linked library's version, "major.minor.patch"."""
    return _lib().ca_version_string().decode()

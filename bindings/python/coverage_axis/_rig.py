"""_rig.py: the correspondence and the rig over the C ABI - correspond() and rig() - and their
results (docs/rig.md). Both take the input surface (vertices (n, 3), triangles (m, 3) or None) and
a Skeleton in the same units (connect()'s, or the caller's arrays); options are keyword arguments
named as the fields of ca_correspondence_options / ca_rig_options (defaults("correspond"),
defaults("rig"))."""
import ctypes

from ._library import lib
from ._steps import _Handle, _options, _over_skeleton

INFLUENCES = 4  # CA_INFLUENCES: balls (joints) per vertex
NEAREST_KINDS = ("ball", "edge", "face")  # CA_NEAREST_BALL, _EDGE, _FACE


class Correspondence:
    """Per input vertex: balls (n, 4) and weights (n, 4) (decreasing, sum 1; an unused slot has
    weight 0 and repeats the first ball), and the nearest primitive: nearest_kinds (n,)
    (0 ball, 1 edge, 2 face: NEAREST_KINDS) and nearest_indices (n,) into the skeleton's balls,
    edges or faces. Read-only arrays over the library's memory."""

    def __init__(self, ptr):
        h = self._handle = _Handle(ptr, "ca_correspondence_destroy")
        n = self.count = h.get("ca_correspondence_vertex_count")
        self.balls = h.view("ca_correspondence_balls", n, INFLUENCES, ctypes.c_uint32)
        self.weights = h.view("ca_correspondence_weights", n, INFLUENCES)
        self.nearest_kinds = h.view("ca_correspondence_nearest_kinds", n, 1, ctypes.c_int32)
        self.nearest_indices = h.view("ca_correspondence_nearest_indices", n, 1, ctypes.c_uint32)

    def __len__(self):
        return self.count


class Rig:
    """A tree of joints: positions (j, 3), parents (j,) (-1 for the root, joint 0; a parent comes
    before its children), the ball each joint sits on and its branch; per input vertex joints
    (n, 4), weights (n, 4) (decreasing, sum 1; unused: weight 0, the first joint) and
    its branch. Read-only arrays over the library's memory."""

    def __init__(self, ptr):
        h = self._handle = _Handle(ptr, "ca_rig_destroy")
        j = self.joint_count = h.get("ca_rig_joint_count")
        n = self.vertex_count = h.get("ca_rig_vertex_count")
        self.branch_count = h.get("ca_rig_branch_count")
        self.positions = h.view("ca_rig_joint_positions", j, 3)
        self.parents = h.view("ca_rig_joint_parents", j, 1, ctypes.c_int32)
        self.joint_balls = h.view("ca_rig_joint_balls", j, 1, ctypes.c_uint32)
        self.joint_branches = h.view("ca_rig_joint_branches", j, 1, ctypes.c_uint32)
        self.joints = h.view("ca_rig_vertex_joints", n, INFLUENCES, ctypes.c_uint32)
        self.weights = h.view("ca_rig_vertex_weights", n, INFLUENCES)
        self.branches = h.view("ca_rig_vertex_branches", n, 1, ctypes.c_uint32)

    def __len__(self):
        return self.joint_count


def correspond(vertices, triangles, skeleton, *, context=None, **options):
    """Each vertex's nearest skeleton primitive and up to 4 ball weights that sum to 1 and change
    continuously over the surface. Options: smoothing."""
    out = ctypes.c_void_p()
    _over_skeleton(context, lib().ca_correspond, vertices, triangles, skeleton, _options("correspond", options),
                   ctypes.byref(out))
    return Correspondence(out)


def rig(vertices, triangles, skeleton, *, context=None, **options):
    """The skeleton's curve skeleton as a tree of joints and each vertex's joint weights.
    Options: root, max_joints, joint_spacing, min_branch, smoothing."""
    out = ctypes.c_void_p()
    _over_skeleton(context, lib().ca_rig_build, vertices, triangles, skeleton, _options("rig", options),
                   ctypes.byref(out))
    return Rig(out)

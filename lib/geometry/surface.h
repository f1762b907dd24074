// surface.h: the validated input surface in internal units. The caller's coordinates are mapped
// to the unit cube (min corner at 0, longest bbox side 1: the paper's convention, in which the
// default delta = 0.02 is defined); every result is mapped back with `Normalization`.
#pragma once
#include "common.h"
#include "mesh_topology.h"

namespace ca {

struct Normalization {
    Vec3 origin = Vec3::Zero();   // bbox min corner of the input (caller's units)
    double scale = 1;             // longest bbox side (caller's units)
    Vec3 to_internal(const Vec3& p) const { return (p - origin) / scale; }
    Vec3 to_user(const Vec3& p) const { return origin + p * scale; }
};

// Where a point cloud's normals come from: the caller's (oriented), the caller's re-oriented
// (normals.h), or estimated from the points. Meshes: none.
enum class NormalSource : int32_t { none = 0, given = 1, oriented = 2, estimated = 3 };

// How far the caller trusts a point cloud's normals (the C ABI's CA_POINT_NORMALS_*): oriented
// (checked: signs disagreeing between neighbours are re-oriented), right up to sign (re-oriented),
// or not at all (estimated).
enum class PointNormals : int32_t { trusted = 0, unoriented = 1, estimate = 2 };

// What the input is, read once from the prepared surface (Surface::kind): a closed or an open
// triangle mesh, a point cloud (its normals given, re-oriented or estimated), or nothing but the
// caller's arrays (samples and balls, no surface). Every stage asks this, not which arrays are
// empty, so the meaning of each mode is written in one place.
enum class InputKind : int32_t { arrays = 0, mesh = 1, open_mesh = 2, cloud = 3 };

class SurfaceKind {
public:
    explicit SurfaceKind(InputKind input, NormalSource normals = NormalSource::none) : input_(input), normals_(normals) {}
    InputKind input() const { return input_; }
    bool is_mesh() const { return input_ == InputKind::mesh || input_ == InputKind::open_mesh; }   // triangles
    bool is_open_mesh() const { return input_ == InputKind::open_mesh; }   // a mesh with holes (hole caps)
    bool is_cloud() const { return input_ == InputKind::cloud; }
    bool is_arrays() const { return input_ == InputKind::arrays; }
    bool has_surface() const { return !is_arrays(); }   // a mesh or a cloud to measure against
    NormalSource normals() const { return normals_; }   // point clouds: given, re-oriented or estimated
private:
    InputKind input_;
    NormalSource normals_;
};

struct Surface {
    Mesh mesh;                    // internal units; empty triangles for a point cloud
    std::vector<Vec3> normals;    // point clouds: unit outward normals, one per vertex
    bool point_cloud = false;
    // Meshes: every vertex lies in one plane (a water plane, a decal, a card). Such a mesh bounds
    // no volume: it has no inner balls and no 3-D Delaunay step; its skeleton is the sheet itself
    // (surface balls, candidates/surface_balls.cpp).
    bool flat = false;
    NormalSource normals_source = NormalSource::none;
    // sign_disagreement (normals.h) of the normals as given (-1: none given or not measured)
    // and of the normals used
    double disagreement_given = -1, disagreement = 0;
    // trusted normals disagreed, but orientation did not make them consistent (noise): kept as given
    bool sign_check_inconclusive = false;
    // point clouds: given normals that were zero ("none") and were estimated (all of them: the
    // cloud's normals are estimated)
    size_t normals_replaced = 0;
    bool flipped = false;         // the mesh faced inward and was flipped
    size_t dropped_triangles = 0; // zero-area triangles ignored
    size_t duplicate_triangles = 0; // repeats of a kept triangle merged into it (duplicates.h)
    // Meshes, found once from the half-edges for the later steps: the caps of the holes
    // (hole_caps.h, oriented like the mesh; empty when closed; found with the zero-area triangles
    // still in place, which seal T-junctions) and the topology (mesh_topology.h:
    // closedness, genus per part, indexed by mesh.triangles).
    Mesh caps;
    MeshTopology topology;
    Normalization norm;
    // A point cloud is marked point_cloud; a mesh has triangles (open: hole caps); caller arrays
    // have neither.
    SurfaceKind kind() const {
        if (point_cloud) return SurfaceKind(InputKind::cloud, normals_source);
        if (mesh.triangles.empty()) return SurfaceKind(InputKind::arrays);
        return SurfaceKind(caps.triangles.empty() ? InputKind::mesh : InputKind::open_mesh);
    }
};

// Validates raw caller data (finite coordinates, indices in range, non-degenerate, a point cloud
// not all in one plane, unit normals for point clouds) and normalises it. A flat mesh is valid
// and marked `flat`. `mesh.triangles` empty means a
// point cloud, which takes `normals` (one per vertex, trusted as `trust` says; empty or
// `estimate`: estimated by PCA and oriented) unless `require_normals` is false (the evaluation
// only measures distances: normals are dropped). Trusted normals whose signs disagree between
// neighbours (sign_disagreement above kMaxSignDisagreement) are re-oriented once, and the result
// replaces them when it at least halves the disagreement, or else the winding residual
// (patch_signs.h; otherwise noise, not signs, caused it: they are kept if they describe the
// surface); re-oriented normals that still disagree are refused (invalid_input); estimated ones are judged by the
// winding number when the candidates are built. Takes its arguments by value. The welding and
// merge test `monitor` every Monitor::kCheckEvery items; a stop returns monitor.stop_status("surface").
// A point cloud's normals are estimated, checked and oriented on `threads` threads (>= 1; the
// result is the same for any count).
Status prepare_surface(Mesh raw, std::vector<Vec3> normals, Surface& out, bool require_normals = true,
                       PointNormals trust = PointNormals::trusted, const Monitor& monitor = Monitor{},
                       int threads = 1);

// Axis-aligned bounding box of points (min, max); empty input gives (0, 0).
std::pair<Vec3, Vec3> bounding_box(const std::vector<Vec3>& pts);

}  // namespace ca

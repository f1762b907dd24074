// distance.h: exact unsigned distance from a point to a triangle mesh (closest point on any
// triangle) through an AABB tree over the triangles. Queries are const and thread-safe.
#pragma once
#include "common.h"
#include <memory>

namespace ca {

// Exact closest point on one triangle (Ericson, Real-Time Collision Detection, 5.1.5).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

namespace detail { struct TriangleTree; }

class MeshDistance {
public:
    explicit MeshDistance(const Mesh& mesh);   // keeps its own copy of what it needs
    // On a tree already built over the mesh (shared with WindingNumber; bvh.h).
    explicit MeshDistance(std::shared_ptr<const detail::TriangleTree> tree);
    ~MeshDistance();
    MeshDistance(MeshDistance&&) noexcept;
    MeshDistance& operator=(MeshDistance&&) noexcept;

    // Distance from p to the closest point of the surface; optionally that point and triangle.
    double distance(const Vec3& p, Vec3* closest = nullptr, uint32_t* triangle = nullptr) const;
    // Same, but stops early and returns `upper` when the distance is known to be >= upper.
    double distance_below(const Vec3& p, double upper) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// O(F) reference, for tests.
double mesh_distance_brute_force(const Mesh& mesh, const Vec3& p);

}  // namespace ca

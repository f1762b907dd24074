// winding.h: inside/outside by the generalised winding number w(q) = sum_f Omega_f(q) / 4pi
// (Jacobson et al. 2013), made O(log F) per query by the hierarchical approximation of
// Barill et al. 2018 (BVH over triangles; far clusters replaced by a dipole (+ quadrupole)
// expansion; exact near the query). Works for open meshes, holes, soups. Queries are const
// and safe from several threads at once.
#pragma once
#include "common.h"
#include <functional>
#include <memory>

namespace ca {

namespace detail { struct TriangleTree; }

class WindingNumber {
public:
    // `beta` is Barill's accuracy parameter: a cluster of radius r at distance d is expanded
    // when d > beta * r (2 is their default).
    explicit WindingNumber(const Mesh& mesh, double beta = 2.0);
    // On a tree already built over the mesh (shared with MeshDistance; bvh.h); `threads` > 1
    // builds the expansions of as many subtrees as threads at once (the same values). `stop` is
    // tested every few thousand nodes (from every thread); a stopped build answers 0 everywhere
    // and must not be used.
    explicit WindingNumber(std::shared_ptr<const detail::TriangleTree> tree, double beta = 2.0, int threads = 1,
                           const std::function<bool()>& stop = {});
    ~WindingNumber();
    WindingNumber(WindingNumber&&) noexcept;
    WindingNumber& operator=(WindingNumber&&) noexcept;

    double operator()(const Vec3& q) const;                 // hierarchical approximation
    // (*this)(q) > 0.5, always the same decision, mostly decided by a cheaper walk (winding.cpp)
    bool inside(const Vec3& q) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Exact O(F) reference (Van Oosterom-Strackee solid angle per triangle); for tests.
double winding_number_brute_force(const Mesh& mesh, const Vec3& q);

// Sum of signed tetrahedron volumes (origin, triangle). Negative for an inward-facing closed mesh.
double signed_volume(const Mesh& mesh);

}  // namespace ca

// power_route.cpp: the power-diagram connection route (paper 4.3): the regular triangulation of the
// selected balls (via Qhull) gives the raw edges and faces; the repairs are in repairs.cpp.
#include "connect.h"

#include "delaunay.h"
#include "distance.h"
#include "kdtree.h"
#include "union_find.h"
#include "parallel.h"
#include "winding.h"
#include "rng.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

namespace ca {
namespace detail {

namespace {


}  // namespace

Status connect_power(const CandidateSet& set, const Selection& sel, const Monitor& monitor, Skeleton& out) {
    const size_t k = sel.indices.size();
    if (k < 2) return Status::success();
    const std::vector<Vec3>& samples = !set.connect_samples.empty() ? set.connect_samples
                                       : !set.dense_samples.empty() ? set.dense_samples
                                                                    : set.cover_samples;
    std::vector<Vec3> pts;
    std::vector<double> weights;
    pts.reserve(k + samples.size());
    weights.reserve(k + samples.size());
    for (size_t i = 0; i < k; ++i) {
        pts.push_back(set.balls[sel.indices[i]].center);
        weights.push_back(sel.dilated_radii[i] * sel.dilated_radii[i]);
    }
    // Samples on a flat part of the surface are coplanar, a massive degeneracy for the 4-D hull
    // with "Qt" (it makes the hull slow). A seeded jitter of 1e-6 (internal units,
    // i.e. a millionth of the model) of their positions breaks it without changing the result.
    Rng rng(0x5eed);
    for (const Vec3& s : samples) {
        pts.push_back(s + 1e-6 * Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5));
        weights.push_back(sel.delta * sel.delta);
    }
    if (!monitor.report("connect", 0)) return monitor.stop_status("connect");
    std::vector<Tet> cells;
    Status st = regular_triangulation(pts, weights, cells, monitor, "connect");
    if (!st.ok()) return st;
    for (const Tet& cell : cells) {
        uint32_t v[4];
        int n = 0;
        for (uint32_t p : cell)
            if (p < k) v[n++] = p;
        for (int a = 0; a < n; ++a)
            for (int b = a + 1; b < n; ++b) {
                out.edges.push_back({std::min(v[a], v[b]), std::max(v[a], v[b])});
                for (int c = b + 1; c < n; ++c) {
                    Tri f{v[a], v[b], v[c]};
                    std::sort(f.begin(), f.end());
                    out.faces.push_back(f);
                }
            }
    }
    return Status::success();
}

}  // namespace detail
}  // namespace ca

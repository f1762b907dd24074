// connect_power.cpp: the power-diagram connection route (regular triangulation via Qhull).
#include "connect.h"

#include "delaunay.h"

#include <algorithm>

namespace ca {

static Status connect_power(const CandidateSet& set, const Selection& sel, const Monitor& monitor, Skeleton& out) {
    const size_t k = sel.indices.size();
    const std::vector<Vec3>& samples = set.dense_samples.empty() ? set.cover_samples : set.dense_samples;
    std::vector<Vec3> pts;
    std::vector<double> weights;
    pts.reserve(k + samples.size());
    for (size_t i = 0; i < k; ++i) {
        pts.push_back(set.balls[sel.indices[i]].center);
        weights.push_back(sel.dilated_radii[i] * sel.dilated_radii[i]);
    }
    for (const Vec3& s : samples) {
        pts.push_back(s);
        weights.push_back(sel.delta * sel.delta);
    }
    if (k < 2) return Status::success();
    if (!monitor.report("connect", 0)) return fail(Code::cancelled, "cancelled");
    std::vector<Tet> cells;
    Status st = regular_triangulation(pts, weights, cells);
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
    if (!monitor.report("connect", 1)) return fail(Code::cancelled, "cancelled");
    return Status::success();
}

Status connect_balls(const CandidateSet& set, const Selection& sel, const ConnectOptions& opt,
                     const Monitor& monitor, Skeleton& out) {
    out = Skeleton{};
    if (sel.indices.size() != sel.dilated_radii.size()) return fail(Code::internal, "inconsistent selection");
    for (uint32_t i : sel.indices)
        if (i >= set.balls.size()) return fail(Code::invalid_argument, "the selection does not belong to this candidate set");
    for (uint32_t i : sel.indices) out.balls.push_back(set.balls[i]);
    Status st;
    switch (opt.method) {
        case ConnectMethod::power: st = connect_power(set, sel, monitor, out); break;
        default: return fail(Code::invalid_argument, "unknown connection method");
    }
    if (!st.ok()) return st;
    canonicalize(out);
    return Status::success();
}

}  // namespace ca

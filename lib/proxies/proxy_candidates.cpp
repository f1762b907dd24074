// proxy_candidates.cpp: the primitives the choice picks from. A sphere per skeleton ball; with
// capsules also the medial cone of every edge, and capsules that span a chain: between each ball
// and the balls it reaches along edges, nearest first (hops), a bounded number per ball, so a
// straight limb of many balls can become one capsule (shapes capsules or all; boxes are fitted to
// surface points, hug_candidates.cpp). Also the primitive's signed distance.
#include "proxies.h"
#include "evaluate.h"

#include <algorithm>
#include <limits>
#include <set>

namespace ca {

namespace {

// Balls reached along edges from each ball, at least two hops away, for chain capsules: at most
// this many per ball, fewer on large skeletons so that the chain capsules number about
// kChainCandidates (each pair is found from both ends), at least kMinChainPartners per ball. The
// bound keeps the candidates (and the choice's cost table) near linear in the skeleton's size.
constexpr size_t kChainPartnersPerBall = 24;
constexpr size_t kMinChainPartners = 4;
constexpr size_t kChainCandidates = 1500;
constexpr size_t kMaxChainHops = 48;

}  // namespace

Proxy make_box(const Vec3& center, const Eigen::Matrix3d& axes, const Vec3& half) {
    Proxy p;
    p.kind = ProxyKind::box;
    p.a = p.b = Ball{center, 0.0};
    p.axes = axes;
    p.half = half;
    return p;
}

double proxy_distance(const Proxy& p, const Vec3& x) {
    switch (p.kind) {
    case ProxyKind::sphere: return sd_sphere(x, p.a.center, p.a.radius);
    case ProxyKind::capsule: return sd_cone(x, p.a.center, p.a.radius, p.b.center, p.b.radius);
    case ProxyKind::box: {
        // in the box's frame: q > 0 along an axis where x lies beyond that pair of faces
        const Vec3 q = (p.axes.transpose() * (x - p.a.center)).cwiseAbs() - p.half;
        return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
    }
    }
    return std::numeric_limits<double>::infinity();
}

Proxy shrunk(const Proxy& p, double by) {
    Proxy q = p;
    if (p.kind == ProxyKind::box) {
        q.half = (p.half.array() - by).cwiseMax(0.0);
        return q;
    }
    q.a.radius = std::max(0.0, p.a.radius - by);
    q.b.radius = std::max(0.0, p.b.radius - by);
    return q;
}

std::vector<Proxy> proxy_candidates(const Skeleton& skeleton_in, ProxyShapes shapes) {
    Skeleton sk = skeleton_in;
    canonicalize(sk);
    const size_t n = sk.balls.size();
    std::vector<Proxy> out;
    for (const Ball& b : sk.balls) out.push_back({ProxyKind::sphere, b, b});
    if (shapes == ProxyShapes::spheres || shapes == ProxyShapes::boxes) return out;  // boxes: fitted elsewhere

    std::vector<std::vector<uint32_t>> adjacent(n);
    for (const auto& e : sk.edges) {
        adjacent[e[0]].push_back(e[1]);
        adjacent[e[1]].push_back(e[0]);
    }
    for (auto& a : adjacent) std::sort(a.begin(), a.end());
    std::set<std::pair<uint32_t, uint32_t>> pairs;
    for (const auto& e : sk.edges) pairs.insert({e[0], e[1]});
    // breadth-first from each ball: the first `partners` balls two or more hops away
    const size_t partners_per_ball =
        std::clamp(2 * kChainCandidates / std::max<size_t>(n, 1), kMinChainPartners, kChainPartnersPerBall);
    std::vector<uint32_t> hops(n, UINT32_MAX);
    std::vector<uint32_t> queue;
    for (uint32_t s = 0; s < n; ++s) {
        queue.assign(1, s);
        hops[s] = 0;
        size_t partners = 0;
        for (size_t head = 0; head < queue.size() && partners < partners_per_ball; ++head) {
            const uint32_t v = queue[head];
            if (hops[v] >= 2) {
                pairs.insert({std::min(s, v), std::max(s, v)});
                ++partners;
            }
            if (hops[v] >= kMaxChainHops) continue;
            for (uint32_t w : adjacent[v])
                if (hops[w] == UINT32_MAX) {
                    hops[w] = hops[v] + 1;
                    queue.push_back(w);
                }
        }
        for (uint32_t v : queue) hops[v] = UINT32_MAX;
    }
    for (const auto& [i, j] : pairs) {
        const Ball &a = sk.balls[i], &b = sk.balls[j];
        // one ball inside the other: the hull is that ball, already a candidate
        if ((a.center - b.center).norm() <= std::abs(a.radius - b.radius)) continue;
        out.push_back({ProxyKind::capsule, a, b});
    }
    return out;
}

}  // namespace ca

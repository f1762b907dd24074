// correspondence.cpp: the nearest skeleton primitive and the continuous ball weights of surface
// points (correspondence.h): a blend over the primitives near each point, found through a
// hierarchy of their bounding spheres, then cut to the four largest weights continuously.
#include "correspondence.h"
#include "median.h"

#include "envelope.h"
#include "evaluate.h"
#include "parallel.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace ca {
namespace {

// A primitive weighs exp(-x) - exp(-kCut) at x = (d - d_min) / sigma: exactly 0 from kCut on.
constexpr double kCut = 10;
// A face's interior weight grows from 0 at its border to full where every barycentric
// coordinate reaches kFade.
constexpr double kFade = 0.1;

std::string at_ball(size_t i) { return "skeleton ball " + std::to_string(i); }

}  // namespace

Status check_options(const CorrespondOptions& opt) {
    if (!(std::isfinite(opt.smoothing) && opt.smoothing > 0))
        return fail(Code::invalid_argument, "smoothing must be a finite number above 0");
    return Status::success();
}

Status check_points(const std::vector<Vec3>& points) {
    if (points.empty()) return fail(Code::degenerate_input, "no points to correspond");
    for (size_t i = 0; i < points.size(); ++i)
        if (!points[i].allFinite())
            return fail(Code::invalid_input, "point " + std::to_string(i) + " has a NaN or infinite coordinate");
    return Status::success();
}

Status check_skeleton(const Skeleton& s) {
    const size_t nv = s.balls.size();
    if (nv == 0) return fail(Code::degenerate_input, "the skeleton has no vertices");
    if (nv > UINT32_MAX - 1) return fail(Code::invalid_argument, "the skeleton has more than 2^32 - 2 vertices");
    for (size_t i = 0; i < nv; ++i) {
        const Ball& b = s.balls[i];
        if (!b.center.allFinite() || !(std::isfinite(b.radius) && b.radius >= 0))
            return fail(Code::invalid_input, at_ball(i) + " has a NaN, infinite or negative value");
    }
    for (size_t e = 0; e < s.edges.size(); ++e) {
        const auto& edge = s.edges[e];
        if (edge[0] >= nv || edge[1] >= nv)
            return fail(Code::invalid_input, "skeleton edge " + std::to_string(e) + " references vertex " +
                                                 std::to_string(std::max(edge[0], edge[1])) + " of " + std::to_string(nv));
    }
    for (size_t f = 0; f < s.faces.size(); ++f)
        for (uint32_t v : s.faces[f])
            if (v >= nv)
                return fail(Code::invalid_input, "skeleton face " + std::to_string(f) + " references vertex " +
                                                     std::to_string(v) + " of " + std::to_string(nv));
    return Status::success();
}

namespace {

struct Prim {
    eval::Kind kind;
    uint32_t v[3];
    uint32_t index;     // ball, edge or face reported as the nearest primitive
    NearestKind report; // what `index` is (a face edge the caller did not list reports its face)
};

// Every edge as a cone (the caller's edges, then face edges not among them), every face as a slab,
// every ball on no edge or face as a sphere.
std::vector<Prim> primitives_of(const Skeleton& s) {
    std::vector<Prim> out;
    std::map<std::pair<uint32_t, uint32_t>, bool> seen;
    auto key = [](uint32_t a, uint32_t b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
    std::vector<char> used(s.balls.size(), 0);
    for (size_t e = 0; e < s.edges.size(); ++e) {
        const auto& ed = s.edges[e];
        used[ed[0]] = used[ed[1]] = 1;
        if (ed[0] == ed[1] || !seen.emplace(key(ed[0], ed[1]), true).second) continue;
        out.push_back({eval::Kind::cone, {ed[0], ed[1], 0}, uint32_t(e), NearestKind::edge});
    }
    for (size_t f = 0; f < s.faces.size(); ++f) {
        const Tri& t = s.faces[f];
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = t[k], b = t[(k + 1) % 3];
            used[a] = 1;
            if (a == b || !seen.emplace(key(a, b), true).second) continue;
            out.push_back({eval::Kind::cone, {a, b, 0}, uint32_t(f), NearestKind::face});
        }
        if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
            out.push_back({eval::Kind::slab, {t[0], t[1], t[2]}, uint32_t(f), NearestKind::face});
    }
    for (size_t i = 0; i < s.balls.size(); ++i)
        if (!used[i]) out.push_back({eval::Kind::sphere, {uint32_t(i), 0, 0}, uint32_t(i), NearestKind::ball});
    return out;
}

// The median ball radius, or a thousandth of the centres' extent where radii are 0.
double blend_scale(const Skeleton& s) {
    std::vector<double> r;
    Vec3 lo = s.balls[0].center, hi = lo;
    for (const Ball& b : s.balls) {
        r.push_back(b.radius);
        lo = lo.cwiseMin(b.center);
        hi = hi.cwiseMax(b.center);
    }
    const double scale = std::max(median_of(std::move(r)), 1e-3 * (hi - lo).norm());
    return scale > 0 ? scale : 1.0;
}

struct Bounds {
    std::vector<Vec3> c;
    std::vector<double> r;
};

Bounds bounds_of(const Skeleton& s, const std::vector<Prim>& prims) {
    Bounds b;
    for (const Prim& p : prims) {
        const int n = p.kind == eval::Kind::sphere ? 1 : p.kind == eval::Kind::cone ? 2 : 3;
        Vec3 c = Vec3::Zero();
        for (int k = 0; k < n; ++k) c += s.balls[p.v[k]].center;
        c /= n;
        double r = 0;
        for (int k = 0; k < n; ++k) r = std::max(r, (s.balls[p.v[k]].center - c).norm() + s.balls[p.v[k]].radius);
        b.c.push_back(c);
        b.r.push_back(r * (1 + 1e-12));
    }
    return b;
}

}  // namespace

struct BallBlend::Impl {
    std::vector<Prim> prims;
    eval::SphereBvh bvh;
    Impl(std::vector<Prim> p, Bounds b)
        : prims(std::move(p)), bvh(std::move(b.c), std::move(b.r)) {}
};

BallBlend::BallBlend(const Skeleton& s, const CorrespondOptions& opt) : s_(s) {
    sigma_ = opt.smoothing * blend_scale(s);
    std::vector<Prim> prims = primitives_of(s);
    Bounds b = bounds_of(s, prims);
    impl_ = std::make_unique<Impl>(std::move(prims), std::move(b));
}

BallBlend::~BallBlend() = default;

BallBlend::Term BallBlend::term(uint32_t item, const Vec3& p) const {
    const Prim& q = impl_->prims[item];
    const auto& B = s_.balls;
    Term t;
    t.count = q.kind == eval::Kind::sphere ? 1 : q.kind == eval::Kind::cone ? 2 : 3;
    for (int k = 0; k < t.count; ++k) t.ball[k] = q.v[k];
    const Ball& a = B[q.v[0]];
    switch (q.kind) {
        case eval::Kind::sphere:
            t.d = sd_sphere(p, a.center, a.radius);
            t.w[0] = 1;
            break;
        case eval::Kind::cone: {
            NearestSphere at;
            t.d = sd_cone(p, a.center, a.radius, B[q.v[1]].center, B[q.v[1]].radius, &at);
            t.w[0] = at.w[0];
            t.w[1] = at.w[1];
            break;
        }
        case eval::Kind::slab: {
            NearestSphere at;
            const double d = sd_slab(p, a.center, a.radius, B[q.v[1]].center, B[q.v[1]].radius, B[q.v[2]].center,
                                     B[q.v[2]].radius, &at);
            const double least = std::min({at.w[0], at.w[1], at.w[2]});
            // off the face's interior its distance is one of its edges' cones, which count already
            if (!(least > 0)) return Term{};
            t.d = d;
            t.fade = std::min(1.0, least / kFade);
            for (int k = 0; k < 3; ++k) t.w[k] = at.w[k];
            break;
        }
    }
    return t;
}

void BallBlend::blend(const Vec3& p, SparseWeights& out, NearestKind& kind, uint32_t& index) const {
    out.clear();
    uint32_t nearest = 0;
    const double dmin = impl_->bvh.nearest(p, eval::kInf, [&](uint32_t i, double best) {
        const double d = term(i, p).d;
        if (d < best) nearest = i;
        return d;
    });
    const Prim& q = impl_->prims[nearest];
    kind = q.report;
    index = q.index;
    if (q.kind == eval::Kind::cone) {
        const Term t = term(nearest, p);
        if (t.w[1] == 0 || t.w[0] == 0) {
            kind = NearestKind::ball;
            index = t.w[1] == 0 ? q.v[0] : q.v[1];
        }
    }
    const double floor = std::exp(-kCut);
    impl_->bvh.nearest(p, dmin + kCut * sigma_, [&](uint32_t i, double best) {
        const Term t = term(i, p);
        const double x = (t.d - dmin) / sigma_;
        if (x < kCut) {
            const double w = (std::exp(-std::max(0.0, x)) - floor) * t.fade;
            if (w > 0)
                for (int k = 0; k < t.count; ++k)
                    if (t.w[k] > 0) out.emplace_back(t.ball[k], w * t.w[k]);
        }
        return best;
    });
    if (out.empty()) {   // p is exactly where the nearest primitive is; its weights alone
        const Term t = term(nearest, p);
        for (int k = 0; k < t.count; ++k)
            if (t.w[k] > 0) out.emplace_back(t.ball[k], t.w[k]);
        if (out.empty()) out.emplace_back(t.ball[0], 1.0);
    }
    std::sort(out.begin(), out.end());
    size_t m = 0;
    double total = 0;
    for (size_t k = 0; k < out.size(); ++k) {
        if (m > 0 && out[m - 1].first == out[k].first) out[m - 1].second += out[k].second;
        else out[m++] = out[k];
    }
    out.resize(m);
    for (const auto& e : out) total += e.second;
    for (auto& e : out) e.second /= total;
}

void top_weights(SparseWeights w, std::array<uint32_t, kInfluences>& index, std::array<double, kInfluences>& weight) {
    std::sort(w.begin(), w.end(), [](const auto& a, const auto& b) {
        return a.second > b.second || (a.second == b.second && a.first < b.first);
    });
    const size_t n = std::min<size_t>(w.size(), kInfluences);
    const double next = w.size() > size_t(kInfluences) ? w[kInfluences].second : 0.0;
    double total = 0;
    for (size_t k = 0; k < n; ++k) total += w[k].second - next;
    for (size_t k = 0; k < size_t(kInfluences); ++k) {
        index[k] = k < n ? w[k].first : w[0].first;
        if (k >= n) weight[k] = 0;
        else if (total > 0) weight[k] = (w[k].second - next) / total;
        else weight[k] = 1.0 / double(n);   // the top five all equal: no order to keep
    }
}

Status correspond(const std::vector<Vec3>& points, const Skeleton& s, const CorrespondOptions& opt,
                  const Monitor& monitor, Correspondence& out) {
    out = Correspondence{};
    Status st = check_options(opt);
    if (!st.ok()) return st;
    st = check_points(points);
    if (!st.ok()) return st;
    st = check_skeleton(s);
    if (!st.ok()) return st;
    const BallBlend blend(s, opt);
    const size_t n = points.size();
    out.balls.resize(n);
    out.weights.resize(n);
    out.nearest_kind.resize(n);
    out.nearest_index.resize(n);
    const bool done = parallel_for(n, resolve_threads(opt.threads), 4096, monitor, "correspondence", [&](size_t b, size_t e) {
        SparseWeights w;
        for (size_t i = b; i < e; ++i) {
            blend.blend(points[i], w, out.nearest_kind[i], out.nearest_index[i]);
            top_weights(w, out.balls[i], out.weights[i]);
        }
    });
    if (!done) {
        out = Correspondence{};
        return monitor.stop_status("correspondence");
    }
    return Status::success();
}

}  // namespace ca

// proxies.cpp: the engine-proxy step (proxies.h, docs/proxies.md), in order:
//  - the candidates from the skeleton, each with its outside bound, and how far the skeleton's own
//    balls and edges are measured to reach outside; inscribed: every candidate whose bound exceeds
//    that is shrunk by the excess, so no proxy reaches farther out than the skeleton does;
//  - the choice on costs at surface points: inscribed, the point's distance to the primitive;
//    conservative, how far the primitive must grow to hold the point plus how far it reaches out;
//  - conservative: every surface cell goes to the chosen primitive that needs the least growth for
//    its corners, and each primitive grows to hold all of its cells;
//  - the stats.
#include "proxies.h"

#include "distance.h"
#include "parallel.h"
#include "sampling.h"
#include "timing.h"
#include "winding.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

namespace ca {

namespace {

// Surface points the choice is scored on (a seeded subset of the cells' corners).
constexpr size_t kChoicePoints = 4000;
// The choice stops adding primitives once its largest error is within this of what all candidates
// together reach (internal units: half a percent of the model's longest side), or when the next
// would lower neither its largest error nor its sum of squared errors by this fraction: more
// primitives would buy nothing worth an engine's time.
constexpr double kEnoughTolerance = 0.005;
constexpr double kMinGain = 0.01;
// Conservative: how finely the choice needs to know how far a candidate reaches outside (internal
// units), the price it pays for it.
constexpr double kPriceResolution = 0.005;
// Growth added to every conservative primitive beyond its cells' need: signed distances are
// computed to about 1e-16 of the model's size.
constexpr double kContainMargin = 1e-9;

Status check_request(const Mesh& mesh, const Skeleton& skeleton, const ProxyOptions& opt) {
    if (mesh.triangles.empty())
        return fail(Code::invalid_argument, "engine proxies need a triangle mesh surface (not a point cloud or caller arrays)");
    if (opt.shapes != ProxyShapes::spheres && opt.shapes != ProxyShapes::capsules)
        return fail(Code::invalid_argument, "proxy shapes must be spheres (0) or capsules (1)");
    if (opt.mode != ProxyMode::inscribed && opt.mode != ProxyMode::conservative)
        return fail(Code::invalid_argument, "proxy mode must be inscribed (0) or conservative (1)");
    if (opt.count == 0) return fail(Code::invalid_argument, "proxy count must be at least 1");
    if (opt.surface_samples == 0 || opt.evaluate_samples == 0 || opt.volume_samples == 0)
        return fail(Code::invalid_argument, "proxy surface_samples, evaluate_samples and volume_samples must be at least 1");
    const size_t nb = skeleton.balls.size();
    if (nb == 0) return fail(Code::degenerate_input, "the skeleton has no vertices");
    for (size_t i = 0; i < nb; ++i) {
        const Ball& b = skeleton.balls[i];
        if (!b.center.allFinite() || !(std::isfinite(b.radius) && b.radius >= 0))
            return fail(Code::invalid_input, "skeleton ball " + std::to_string(i) + " has a NaN, infinite or negative value");
    }
    for (size_t e = 0; e < skeleton.edges.size(); ++e)
        for (uint32_t v : skeleton.edges[e])
            if (v >= nb)
                return fail(Code::invalid_input, "skeleton edge " + std::to_string(e) + " references vertex " +
                                                     std::to_string(v) + " of " + std::to_string(nb));
    for (size_t f = 0; f < skeleton.faces.size(); ++f)
        for (uint32_t v : skeleton.faces[f])
            if (v >= nb)
                return fail(Code::invalid_input, "skeleton face " + std::to_string(f) + " references vertex " +
                                                     std::to_string(v) + " of " + std::to_string(nb));
    return Status::success();
}

}  // namespace

Status make_proxies(const Mesh& mesh, ShapeQueries shape, const Skeleton& skeleton, const ProxyOptions& opt,
                    const Monitor& monitor, ProxyResult& out) {
    const auto t0 = Clock::now();
    out = ProxyResult{};
    Status st = check_request(mesh, skeleton, opt);
    if (!st.ok()) return st;
    const int threads = resolve_threads(opt.threads);
    if (!monitor.report("proxies", 0.0)) return monitor.stop_status("proxies");

    // ---- candidates and their outside bounds; the skeleton's own bound ----
    std::vector<Proxy> candidates = proxy_candidates(skeleton, opt.shapes);
    std::vector<Proxy> own = proxy_candidates(Skeleton{skeleton.balls, {}, {}}, ProxyShapes::spheres);
    {
        Skeleton sk = skeleton;
        canonicalize(sk);
        for (const auto& e : sk.edges)
            own.push_back({ProxyKind::capsule, sk.balls[e[0]], sk.balls[e[1]]});
    }
    std::vector<double> bound(candidates.size()), own_reach(own.size());
    if (!parallel_for(own.size(), threads, 16, monitor, "proxies", 0.0, 0.1, [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i) own_reach[i] = outside_measured(own[i], shape);
        }))
        return monitor.stop_status("proxies");
    const double allowed = *std::max_element(own_reach.begin(), own_reach.end());
    // inscribed: a bound within the skeleton's reach needs no shrink, so no finer answer;
    // conservative: the bound is the choice's price of reaching outside, kPriceResolution is fine
    const double enough = opt.mode == ProxyMode::inscribed ? allowed : kPriceResolution;
    if (!parallel_for(candidates.size(), threads, 16, monitor, "proxies", 0.1, 0.3, [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i) bound[i] = outside_bound(candidates[i], shape, enough);
        }))
        return monitor.stop_status("proxies");
    const double t_bounds = seconds_since(t0);
    double radius_change = 0;
    if (opt.mode == ProxyMode::inscribed)
        for (size_t c = 0; c < candidates.size(); ++c)
            if (bound[c] > allowed) {
                candidates[c] = shrunk(candidates[c], bound[c] - allowed);
                radius_change = std::max(radius_change, bound[c] - allowed);
                bound[c] = allowed;
            }

    // ---- the choice on costs at surface points ----
    const SurfaceCells cells = surface_cells(mesh, opt.surface_samples);
    const std::vector<uint32_t> picked = random_subset(cells.points.size(), kChoicePoints, opt.seed);
    const size_t np = picked.size(), nc = candidates.size();
    std::vector<float> cost(nc * np);
    if (!parallel_for(nc, threads, 16, monitor, "proxies", 0.3, 0.6, [&](size_t b, size_t e) {
            for (size_t c = b; c < e; ++c)
                for (size_t i = 0; i < np; ++i) {
                    const double d = proxy_distance(candidates[c], cells.points[picked[i]]);
                    cost[c * np + i] = float(opt.mode == ProxyMode::inscribed ? std::max(d, 0.0) : d + bound[c]);
                }
        }))
        return monitor.stop_status("proxies");
    const double t_costs = seconds_since(t0);
    const std::vector<uint32_t> chosen = choose_proxies(cost, nc, np, opt.count, kEnoughTolerance, kMinGain, threads);
    const double t_choice = seconds_since(t0);
    if (!monitor.report("proxies", 0.7)) return monitor.stop_status("proxies");
    std::vector<Proxy> proxies;
    for (uint32_t c : chosen) proxies.push_back(candidates[c]);

    // ---- conservative: each cell to the primitive that needs the least growth for its three
    // corners; each primitive grown by the most its cells need (convex: it then holds them) ----
    if (opt.mode == ProxyMode::conservative) {
        const size_t k = proxies.size(), ncells = cells.cells.size();
        std::vector<uint32_t> owner(ncells);
        std::vector<double> need(ncells);
        if (!parallel_for(ncells, threads, 4096, monitor, "proxies", 0.7, 0.8, [&](size_t b, size_t e) {
                for (size_t i = b; i < e; ++i) {
                    const Tri& cell = cells.cells[i];
                    double best_key = std::numeric_limits<double>::infinity();
                    for (size_t j = 0; j < k; ++j) {
                        double n = -std::numeric_limits<double>::infinity();
                        for (uint32_t v : cell) n = std::max(n, proxy_distance(proxies[j], cells.points[v]));
                        const double key = n + bound[chosen[j]];
                        if (key < best_key) {
                            best_key = key;
                            owner[i] = uint32_t(j);
                            need[i] = n;
                        }
                    }
                }
            }))
            return monitor.stop_status("proxies");
        std::vector<double> grow(k, -std::numeric_limits<double>::infinity());
        std::vector<uint8_t> used(k, 0);
        for (size_t i = 0; i < ncells; ++i) {
            grow[owner[i]] = std::max(grow[owner[i]], need[i]);
            used[owner[i]] = 1;
        }
        std::vector<Proxy> grown;
        for (size_t j = 0; j < k; ++j) {
            if (!used[j]) continue;   // holds no cell: not needed for containment
            grown.push_back(shrunk(proxies[j], -(grow[j] + kContainMargin)));
            radius_change = std::max(radius_change, grow[j]);
        }
        proxies = std::move(grown);
    }

    out.proxies = proxies;
    const double t_grown = seconds_since(t0);
    st = proxy_stats(mesh, proxies, shape, opt, monitor, out.stats);
    if (!st.ok()) return st;
    out.stats.skeleton_outside = 100 * allowed / out.stats.diagonal;
    out.stats.radius_change = 100 * radius_change / out.stats.diagonal;
    out.stats.candidates = candidates.size();
    out.stats.surface_cells = cells.cells.size();
    out.stats.time_s = seconds_since(t0);
    monitor.note(0, "proxies: " + std::to_string(candidates.size()) + " candidates, " + std::to_string(cells.cells.size()) +
                        " cells; seconds: bounds " + std::to_string(t_bounds) + ", costs " + std::to_string(t_costs - t_bounds) +
                        ", choice " + std::to_string(t_choice - t_costs) + ", growth " + std::to_string(t_grown - t_choice) +
                        ", stats " + std::to_string(out.stats.time_s - t_grown));
    monitor.report("proxies", 1.0);
    return Status::success();
}

}  // namespace ca

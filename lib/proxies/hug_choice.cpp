// hug_choice.cpp: the conservative choice (docs/proxies.md): at most K candidates that together
// hold every surface point given, of least volume outside the shape. The candidates: every
// skeleton primitive at every offset of hug_candidates.cpp (it holds the points within that
// distance), with boxes (shapes boxes or all) fitted to groups of points, and one sphere around all
// points, so that one primitive always suffices. Each candidate's price is its volume outside
// the shape on the voxels of inside_grid.cpp (plus a price per primitive, 0.3 % of the shape's
// volume, so that no primitive is added for next to nothing); the choice is a weighted set cover with at most K columns
// (lib/cover/weighted_cover.h), whose solver also gives a lower bound on the price. The sum of
// the prices counts a volume twice where chosen primitives overlap outside the shape: the
// objective is an upper bound of the union's outside volume (measured in proxy_stats.cpp).
// Every candidate is computed on its own, in a fixed order: the same on any number of threads.
#include "proxies.h"

#include "kdtree.h"
#include "parallel.h"
#include "timing.h"
#include "weighted_cover.h"

#include <algorithm>
#include <cmath>

namespace ca {

namespace {

// Voxels of the inside grid over the mesh's box.
constexpr size_t kGridVoxels = 60000;
// Point groups of the box tree stop at this many points.
constexpr size_t kMinGroup = 12;
// Boxes are also fitted to the points a skeleton primitive holds at this offset (internal units).
constexpr double kBoxOffset = 0.025;
// Price of a primitive beside its outside volume, as a share of the shape's volume (on the
// voxels): a primitive is added only where it cuts the outside volume by more than that, so a
// capsule-shaped part stays one capsule rather than pieces that differ by a voxel or two.
constexpr double kColumnPriceShare = 0.003;
// Containment margin of a fitted box (its points lie on its faces up to rounding).
constexpr double kBoxMargin = 1e-9;
// The solver's time budget (a safety: the iteration and node limits end it first on the paper models).
constexpr double kSolverSeconds = 3.0;

struct Column {
    Proxy proxy;
    std::vector<uint32_t> rows;
    double volume = 0;
};

// The points within the primitive's bounding ball grown by `grow`, ascending.
std::vector<uint32_t> near_points(const PointTree& tree, const Proxy& p, double grow) {
    Vec3 c;
    double r;
    if (p.kind == ProxyKind::box) {
        c = p.a.center;
        r = p.half.norm();
    } else {
        c = 0.5 * (p.a.center + p.b.center);
        r = 0.5 * (p.b.center - p.a.center).norm() + std::max(p.a.radius, p.b.radius);
    }
    r += grow + 1e-9;
    std::vector<uint32_t> out;
    tree.for_each_within_squared(c, r * r, [&](size_t i) { out.push_back(uint32_t(i)); });
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

Status hug_choice(const Mesh& mesh, const ShapeQueries& shape, const Skeleton& skeleton, const std::vector<Vec3>& points,
                  const ProxyOptions& opt, int threads, const Monitor& monitor, HugChoice& out) {
    out = HugChoice{};
    const auto t0 = Clock::now();
    if (points.empty()) return fail(Code::degenerate_input, "proxies: no surface points");
    InsideGrid grid;
    Status st = inside_grid(mesh, shape, kGridVoxels, threads, monitor, grid);
    if (!st.ok()) return st;
    const double t_grid = seconds_since(t0);
    const PointTree tree(points);
    const double cell = grid.step * grid.step * grid.step;
    const double price =
        std::max(1e-12, kColumnPriceShare * cell * double(std::count(grid.inside.begin(), grid.inside.end(), uint8_t(1))));
    const bool with_boxes = opt.shapes == ProxyShapes::boxes || opt.shapes == ProxyShapes::all;
    const bool with_capsules = opt.shapes == ProxyShapes::capsules || opt.shapes == ProxyShapes::all;
    const std::vector<Proxy> bases = proxy_candidates(skeleton, with_capsules ? ProxyShapes::capsules : ProxyShapes::spheres);
    const std::vector<double>& offsets = hug_offsets();

    // ---- skeleton primitives at every offset (a larger offset only when it holds more points) ----
    std::vector<std::vector<Column>> grown(bases.size());
    std::vector<std::vector<uint32_t>> groups(bases.size());
    if (!parallel_for(bases.size(), threads, 8, monitor, "proxies", [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i) {
                const Proxy& p = bases[i];
                const std::vector<uint32_t> near = near_points(tree, p, offsets.back());
                std::vector<double> sd(near.size());
                for (size_t k = 0; k < near.size(); ++k) sd[k] = proxy_distance(p, points[near[k]]);
                const std::vector<double> volume = outside_volumes(p, offsets, grid);
                size_t held_before = 0;
                for (size_t o = 0; o < offsets.size(); ++o) {
                    Column c;
                    for (size_t k = 0; k < near.size(); ++k)
                        if (sd[k] <= offsets[o]) c.rows.push_back(near[k]);
                    if (with_boxes && offsets[o] == kBoxOffset && c.rows.size() >= 4) groups[i] = c.rows;
                    if (c.rows.empty() || c.rows.size() == held_before) continue;
                    held_before = c.rows.size();
                    c.proxy = shrunk(p, -offsets[o]);
                    c.volume = volume[o];
                    grown[i].push_back(std::move(c));
                }
            }
        }))
        return monitor.stop_status("proxies");
    std::vector<Column> columns;
    for (auto& g : grown)
        for (auto& c : g) columns.push_back(std::move(c));

    // ---- boxes fitted to groups of points; capsules fitted to the tree's groups ----
    if (with_boxes || with_capsules) {
        std::vector<std::vector<uint32_t>> tree_groups = point_groups(points, kMinGroup), all_groups;
        const size_t capsules = with_capsules ? tree_groups.size() : 0;
        if (with_capsules) all_groups = tree_groups;
        if (with_boxes) {
            std::vector<std::vector<uint32_t>> box_groups = std::move(tree_groups);
            for (auto& g : groups)
                if (!g.empty()) box_groups.push_back(std::move(g));
            std::sort(box_groups.begin(), box_groups.end());
            box_groups.erase(std::unique(box_groups.begin(), box_groups.end()), box_groups.end());
            for (auto& g : box_groups) all_groups.push_back(std::move(g));
        }
        std::vector<Column> boxes(all_groups.size());
        if (!parallel_for(all_groups.size(), threads, 8, monitor, "proxies", [&](size_t b, size_t e) {
                for (size_t i = b; i < e; ++i) {
                    Column& c = boxes[i];
                    c.proxy = shrunk(i < capsules ? fit_capsule(points, all_groups[i]) : fit_box(points, all_groups[i]),
                                     -kBoxMargin);
                    for (uint32_t k : near_points(tree, c.proxy, 0))
                        if (proxy_distance(c.proxy, points[k]) <= 0) c.rows.push_back(k);
                    c.volume = outside_volumes(c.proxy, {0.0}, grid)[0];
                }
            }))
            return monitor.stop_status("proxies");
        for (auto& c : boxes)
            if (!c.rows.empty()) columns.push_back(std::move(c));
    }

    // ---- one sphere around every point: one primitive always suffices ----
    {
        Vec3 lo = points.front(), hi = lo;
        for (const Vec3& x : points) {
            lo = lo.cwiseMin(x);
            hi = hi.cwiseMax(x);
        }
        const Vec3 c = 0.5 * (lo + hi);
        double r = 0;
        for (const Vec3& x : points) r = std::max(r, (x - c).norm());
        Column all;
        all.proxy = Proxy{ProxyKind::sphere, Ball{c, r + kBoxMargin}, Ball{c, r + kBoxMargin}};
        for (uint32_t k = 0; k < points.size(); ++k) all.rows.push_back(k);
        all.volume = outside_volumes(all.proxy, {0.0}, grid)[0];
        columns.push_back(std::move(all));
    }

    const double t_candidates = seconds_since(t0);
    // ---- the weighted cover ----
    WeightedCoverProblem problem;
    problem.rows = uint32_t(points.size());
    problem.max_columns = opt.count;
    for (const Column& c : columns) {
        problem.idx.insert(problem.idx.end(), c.rows.begin(), c.rows.end());
        problem.ptr.push_back(uint32_t(problem.idx.size()));
        problem.cost.push_back(c.volume + price);
    }
    WeightedCoverOptions wo;
    wo.time_limit_s = kSolverSeconds;
    WeightedCoverResult result;
    st = solve_weighted_cover(problem, wo, monitor, result);
    if (!st.ok()) return st;
    for (uint32_t j : result.selected) {
        out.chosen.push_back(columns[j].proxy);
        out.objective += columns[j].volume;
    }
    out.lower_bound = std::max(0.0, result.lower_bound - double(opt.count) * price);
    out.lower_bound = std::min(out.lower_bound, out.objective);
    out.candidates = columns.size();
    monitor.note(0, "proxies: hug: " + std::to_string(columns.size()) + " candidates, " + std::to_string(problem.idx.size()) +
                        " incidences; seconds: grid " + std::to_string(t_grid) + ", candidates " + std::to_string(t_candidates - t_grid) + ", cover " +
                        std::to_string(seconds_since(t0) - t_candidates) + (result.cbc_improved ? " (CBC improved)" : ""));
    return Status::success();
}

}  // namespace ca

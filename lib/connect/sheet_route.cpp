// sheet_route.cpp: edges and triangles of the surface balls (candidates/surface_balls.cpp). The
// medial surface of a zero-thickness sheet is the sheet itself, so surface balls are joined along
// the surface, not through a volume: the restricted Voronoi regions of the selected balls on the
// surface, read off surface points (the power-diagram samples and the cover samples), give the
// dual complex.
//  * Each point takes the label of the selected ball nearest to it by the distance to the ball's
//    sphere, |p - c| - r (surface balls are points or thin balls on the sheet; medial balls touch
//    the surface of their own part, so a medial part's surface keeps its own labels).
//  * Points are neighbours along the surface when one is among the other's kNeighbours nearest and
//    nearer than kReachSpacings median spacings (the 8th neighbour's distance): a cloud of surface
//    samples has no edges of its own.
//  * Two labels whose regions meet at neighbouring points are joined by an edge when at least one
//    of them is a surface ball (medial pairs are the volume route's); three labels pairwise joined,
//    one of the joins being such an edge, by a triangle (the dual of the point where their three
//    regions meet): a card, sail or plane becomes a patch of triangles, and a sheet touching a
//    medial part (a leaf on its twig, a card glued to a box) is joined to it.
#include "connect.h"
#include "median.h"

#include "kdtree.h"
#include "parallel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <iterator>
#include <set>

namespace ca {
namespace {

constexpr size_t kNeighbours = 8;
constexpr double kReachSpacings = 2.0;

uint64_t pair_key(uint32_t a, uint32_t b) { return (uint64_t(std::min(a, b)) << 32) | std::max(a, b); }

// The label of each point: the ball minimising |p - c| - r (ties: the lower index). Exact: the
// nearest centre bounds the best value, and only centres within that bound plus the largest
// radius can beat it.
bool nearest_ball_labels(const std::vector<Vec3>& pts, const std::vector<Ball>& balls, int threads, const Monitor& monitor,
                         std::vector<uint32_t>& label) {
    std::vector<Vec3> centers;
    double r_max = 0;
    for (const Ball& b : balls) centers.push_back(b.center), r_max = std::max(r_max, b.radius);
    const PointTree tree(centers);
    label.assign(pts.size(), 0);
    Monitor quiet = monitor;
    quiet.progress = nullptr;
    return parallel_for(pts.size(), threads, 1024, quiet, "connect", [&](size_t b, size_t e) {
        std::vector<std::pair<size_t, double>> hits;
        for (size_t i = b; i < e; ++i) {
            size_t idx = 0;
            double d2 = 0;
            if (tree.nearest(pts[i], 1, &idx, &d2) == 0) continue;
            double best = std::sqrt(d2) - balls[idx].radius;
            uint32_t arg = uint32_t(idx);
            const double bound = best + r_max;
            tree.within(pts[i], bound, hits);
            for (const auto& [j, dj2] : hits) {
                const double v = std::sqrt(dj2) - balls[j].radius;
                if (v < best || (v == best && j < arg)) best = v, arg = uint32_t(j);
            }
            label[i] = arg;
        }
    });
}

}  // namespace

namespace detail {

Status connect_sheets(const CandidateSet& set, const std::vector<uint8_t>& surface_ball, int threads, const Monitor& monitor,
                      Skeleton& s) {
    if (s.balls.size() < 2) return Status::success();
    std::vector<Vec3> pts = !set.connect_samples.empty() ? set.connect_samples : set.dense_samples;
    pts.insert(pts.end(), set.cover_samples.begin(), set.cover_samples.end());
    if (pts.size() < 2) return Status::success();
    std::vector<uint32_t> label;
    if (!nearest_ball_labels(pts, s.balls, threads, monitor, label)) return monitor.stop_status("connect");

    // neighbourhoods along the surface
    std::vector<std::array<uint32_t, kNeighbours>> nb(pts.size());
    std::vector<double> d8(pts.size(), 0), nd2(pts.size() * kNeighbours, std::numeric_limits<double>::infinity());
    for (auto& row : nb) row.fill(std::numeric_limits<uint32_t>::max());
    for_each_neighbourhood(pts, kNeighbours, [&](size_t i, const size_t* idx, const double* d2, size_t found) {
        size_t k = 0;
        for (size_t f = 0; f < found && k < kNeighbours; ++f)
            if (idx[f] != i) nb[i][k] = uint32_t(idx[f]), nd2[i * kNeighbours + k] = d2[f], ++k;
        d8[i] = found > 0 ? std::sqrt(d2[found - 1]) : 0;
    }, threads);
    if (monitor.stopped()) return monitor.stop_status("connect");
    const double reach = kReachSpacings * median_of(d8);
    const double reach2 = reach * reach;

    std::set<uint64_t> edges;
    for (const auto& e : s.edges) edges.insert(pair_key(e[0], e[1]));
    std::set<uint64_t> added;
    for (size_t i = 0; i < pts.size(); ++i) {
        if (monitor.stopped_at(i)) return monitor.stop_status("connect");
        for (size_t k = 0; k < kNeighbours; ++k) {
            const uint32_t j = nb[i][k];
            if (j == std::numeric_limits<uint32_t>::max() || nd2[i * kNeighbours + k] > reach2) continue;
            const uint32_t a = label[i], b = label[j];
            if (a == b || !(surface_ball[a] || surface_ball[b])) continue;
            added.insert(pair_key(a, b));
        }
    }
    for (uint64_t key : added) {
        s.edges.push_back({uint32_t(key >> 32), uint32_t(key & 0xffffffffu)});
        edges.insert(key);
    }
    // triangles: the 3-cliques of the edges, with a surface ball among their corners
    std::vector<std::vector<uint32_t>> adjacent(s.balls.size());
    for (uint64_t key : edges) {
        const uint32_t a = uint32_t(key >> 32), b = uint32_t(key & 0xffffffffu);
        adjacent[a].push_back(b), adjacent[b].push_back(a);
    }
    for (auto& list : adjacent) std::sort(list.begin(), list.end());
    std::set<std::array<uint32_t, 3>> faces;
    for (uint64_t key : added) {
        const uint32_t a = uint32_t(key >> 32), b = uint32_t(key & 0xffffffffu);
        std::vector<uint32_t> common;
        std::set_intersection(adjacent[a].begin(), adjacent[a].end(), adjacent[b].begin(), adjacent[b].end(),
                              std::back_inserter(common));
        for (uint32_t c : common) {
            std::array<uint32_t, 3> f{a, b, c};
            std::sort(f.begin(), f.end());
            faces.insert(f);
        }
    }
    // four regions meeting in about one point give a 4-cycle with neither diagonal: split it by
    // the shorter one (a hole of the patch that the sampling made, not the sheet)
    auto joined = [&](uint32_t a, uint32_t b) { return std::binary_search(adjacent[a].begin(), adjacent[a].end(), b); };
    for (uint64_t key : added) {
        const uint32_t a = uint32_t(key >> 32), b = uint32_t(key & 0xffffffffu);
        for (uint32_t c : adjacent[b]) {
            if (c == a || joined(a, c)) continue;
            for (uint32_t d : adjacent[a]) {
                if (d == b || d == c || !joined(c, d) || joined(b, d)) continue;
                const double ac = (s.balls[a].center - s.balls[c].center).norm(), bd = (s.balls[b].center - s.balls[d].center).norm();
                std::array<uint32_t, 3> f1 = ac <= bd ? std::array<uint32_t, 3>{a, b, c} : std::array<uint32_t, 3>{a, b, d};
                std::array<uint32_t, 3> f2 = ac <= bd ? std::array<uint32_t, 3>{a, c, d} : std::array<uint32_t, 3>{b, c, d};
                std::sort(f1.begin(), f1.end()), std::sort(f2.begin(), f2.end());
                faces.insert(f1), faces.insert(f2);
            }
        }
    }
    for (const auto& f : faces) s.faces.push_back({f[0], f[1], f[2]});
    canonicalize(s);
    return Status::success();
}

}  // namespace detail
}  // namespace ca

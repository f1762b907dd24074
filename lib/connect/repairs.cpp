// repairs.cpp: the repairs shared by both connection routes, in the order connect.cpp applies them:
// removal of the edges and triangles that leave the shape, filling of small holes (with the
// medial route's loop keeping), and reconnection of components. The inside test itself is in
// inside_test.cpp.
#include "connect.h"

#include "delaunay.h"
#include "distance.h"
#include "kdtree.h"
#include "union_find.h"
#include "parallel.h"
#include "winding.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

namespace ca {
namespace detail {

// reconnect: up to this many balls every pair is a candidate join; above it, each ball's
// kReconnectNeighbours nearest balls.
constexpr uint32_t kReconnectAllPairs = 200;
constexpr size_t kReconnectNeighbours = 32;

// Removes the triangles, then the edges (with their triangles), that fail the inside test.
// `failed` gets the faces that failed it themselves (sorted), which hole filling need not retest.
bool remove_outside(const InsideTest& test, double h, double tol, bool collapse, int threads, const Monitor& monitor,
                    Skeleton& s, std::vector<Tri>& failed) {
    std::vector<uint8_t> face_ok(s.faces.size(), 1), edge_ok(s.edges.size(), 1);
    if (!parallel_for(s.edges.size(), threads, 1024, monitor, "connect", [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i)
                edge_ok[i] = test.segment_inside(s.balls[s.edges[i][0]], s.balls[s.edges[i][1]], h, tol);
        }))
        return false;
    if (!parallel_for(s.faces.size(), threads, 256, monitor, "connect", [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i) {
                const Tri& f = s.faces[i];
                face_ok[i] = test.triangle_inside(s.balls[f[0]], s.balls[f[1]], s.balls[f[2]], h, tol);
            }
        }))
        return false;
    std::vector<std::array<uint32_t, 2>> edges;
    for (size_t i = 0; i < s.edges.size(); ++i)
        if (edge_ok[i]) edges.push_back(s.edges[i]);
    auto has_edge = [&](uint32_t a, uint32_t b) {
        return std::binary_search(edges.begin(), edges.end(), std::array<uint32_t, 2>{a, b});
    };
    std::vector<Tri> faces;
    failed.clear();
    for (size_t i = 0; i < s.faces.size(); ++i) {
        const Tri& f = s.faces[i];
        if (!face_ok[i]) failed.push_back(f);
        if (face_ok[i] && has_edge(f[0], f[1]) && has_edge(f[0], f[2]) && has_edge(f[1], f[2])) faces.push_back(f);
    }
    if (collapse) {
        // Removing a triangle can leave a new loop (its boundary, or with the other triangles of a
        // removed edge, a longer cycle). The removals are replayed as elementary collapses (same
        // homotopy type): each removed triangle, in order, is collapsed through one of its removed
        // edges that no earlier removed triangle used, or else through its longest edge that is on
        // no kept triangle, which is then removed too. The medial mesh has the shape's topology, so
        // the loops that removal alone would add (a removed triangle leaving its edges as a
        // cycle) are spurious.
        std::map<std::array<uint32_t, 2>, int> on_faces;
        for (const Tri& f : faces)   // sorted vertices
            ++on_faces[{f[0], f[1]}], ++on_faces[{f[0], f[2]}], ++on_faces[{f[1], f[2]}];
        std::set<std::array<uint32_t, 2>> alive(edges.begin(), edges.end()), used;
        for (const Tri& f : s.faces) {
            if (std::binary_search(faces.begin(), faces.end(), f)) continue;
            const std::array<uint32_t, 2> fe[3] = {{f[0], f[1]}, {f[0], f[2]}, {f[1], f[2]}};
            bool done = false;
            for (int a = 0; a < 3 && !done; ++a)
                if (!alive.count(fe[a]) && !used.count(fe[a])) used.insert(fe[a]), done = true;
            if (done) continue;
            int best = -1;
            double best_len = -1;
            for (int a = 0; a < 3; ++a) {
                if (!alive.count(fe[a]) || on_faces.count(fe[a])) continue;
                const double len = (s.balls[fe[a][0]].center - s.balls[fe[a][1]].center).squaredNorm();
                if (len > best_len) best_len = len, best = a;
            }
            if (best >= 0) alive.erase(fe[best]), used.insert(fe[best]);
        }
        edges.assign(alive.begin(), alive.end());
    }
    s.edges = std::move(edges);   // still sorted (canonical input)
    s.faces = std::move(faces);
    return true;
}

// Fills holes bounded by 3 or 4 edges. A chordless 4-cycle a-b-c-d that is not the rim of a fan
// (no fifth vertex joined to all four) gets its shorter diagonal (the other if that one fails)
// when both its triangles pass the inside test; then every 3-cycle without a face gets one when
// it passes (`failed`: sorted faces known to fail, skipped). The tests run in parallel; the
// result does not depend on the thread count. Input and output canonical. False if cancelled.
bool fill_small_holes(const InsideTest& test, double h, double tol, int threads, const Monitor& monitor,
                      const std::vector<Tri>& failed, Skeleton& s) {
    const uint32_t n = uint32_t(s.balls.size());
    std::vector<std::vector<uint32_t>> adj;
    auto build_adjacency = [&]() {
        adj.assign(n, {});
        for (const auto& e : s.edges) adj[e[0]].push_back(e[1]), adj[e[1]].push_back(e[0]);
        for (auto& a : adj) std::sort(a.begin(), a.end());
    };
    auto linked = [&](uint32_t a, uint32_t b) { return std::binary_search(adj[a].begin(), adj[a].end(), b); };
    auto len2 = [&](uint32_t a, uint32_t b) { return (s.balls[a].center - s.balls[b].center).squaredNorm(); };
    auto inside = [&](uint32_t a, uint32_t b, uint32_t c) {
        return test.triangle_inside(s.balls[a], s.balls[b], s.balls[c], h, tol);
    };
    {
        build_adjacency();
        std::vector<std::vector<std::array<uint32_t, 2>>> chords(n);   // per first vertex a
        if (!parallel_for(n, threads, 64, monitor, "connect", [&](size_t begin, size_t end) {
                std::vector<uint32_t> common;
                for (uint32_t a = uint32_t(begin); a < end; ++a)
                    for (uint32_t c = a + 1; c < n; ++c) {
                        if (linked(a, c)) continue;
                        common.clear();
                        std::set_intersection(adj[a].begin(), adj[a].end(), adj[c].begin(), adj[c].end(),
                                              std::back_inserter(common));
                        if (common.empty()) continue;
                        bool added = false;
                        for (size_t i = 0; i < common.size() && !added; ++i)       // 4-cycles a-b-c-d
                            for (size_t j = i + 1; j < common.size() && !added; ++j) {
                                const uint32_t b = common[i], d = common[j];
                                if (linked(b, d)) continue;
                                // a vertex joined to all four is the centre of a filled fan: no hole
                                bool cone = false;
                                for (uint32_t v : common) cone = cone || (v != b && v != d && linked(v, b) && linked(v, d));
                                if (cone) continue;
                                const bool ac_first = len2(a, c) <= len2(b, d);
                                for (int k = 0; k < 2 && !added; ++k) {
                                    const bool ac = (k == 0) == ac_first;
                                    if (ac ? inside(a, c, b) && inside(a, c, d) : inside(b, d, a) && inside(b, d, c)) {
                                        chords[a].push_back(ac ? std::array<uint32_t, 2>{a, c}
                                                               : std::array<uint32_t, 2>{std::min(b, d), std::max(b, d)});
                                        added = true;
                                    }
                                }
                            }
                    }
            }))
            return false;
        for (const auto& list : chords) s.edges.insert(s.edges.end(), list.begin(), list.end());
        canonicalize(s);
    }
    build_adjacency();
    std::vector<Tri> candidates;
    for (const auto& e : s.edges)
        for (uint32_t c : adj[e[1]]) {
            const Tri t{e[0], e[1], c};
            if (c > e[1] && linked(e[0], c) && !std::binary_search(s.faces.begin(), s.faces.end(), t) &&
                !std::binary_search(failed.begin(), failed.end(), t))
                candidates.push_back(t);
        }
    std::vector<uint8_t> ok(candidates.size(), 0);
    if (!parallel_for(candidates.size(), threads, 64, monitor, "connect", [&](size_t begin, size_t end) {
            for (size_t i = begin; i < end; ++i) ok[i] = inside(candidates[i][0], candidates[i][1], candidates[i][2]);
        }))
        return false;
    for (size_t i = 0; i < candidates.size(); ++i)
        if (ok[i]) s.faces.push_back(candidates[i]);
    canonicalize(s);
    return true;
}

// Joins components by the shortest inside segments between their balls (Kruskal order). With
// tol >= 0 (medial route) a first pass takes only segments that also pass the envelope rule,
// so that a component is joined by a longer segment that stays in the shape rather than by the
// shortest one whose cone bulges out (which raises the two-sided Hausdorff error); the second
// pass uses the centre-line rule alone. Both passes accept only edges between components, so
// the components reached and b1 are those of the centre-line rule alone. With `ball_part`, a
// third pass joins balls of one mesh part by segments whose test points are at most 4h outside
// the surface (a part of the shape gives one component; distinct parts stay apart).
void reconnect(const InsideTest& test, double h, double tol, Skeleton& s, const std::vector<uint32_t>* ball_part) {
    const uint32_t n = uint32_t(s.balls.size());
    UnionFind uf(n);
    size_t components = n;
    for (const auto& e : s.edges) components -= uf.unite(e[0], e[1]);
    if (components <= 1) return;
    struct Pair { double d2; uint32_t i, j; };
    std::vector<Pair> pairs;
    if (n <= kReconnectAllPairs) {
        for (uint32_t i = 0; i < n; ++i)
            for (uint32_t j = i + 1; j < n; ++j)
                if (uf.find(i) != uf.find(j)) pairs.push_back({(s.balls[i].center - s.balls[j].center).squaredNorm(), i, j});
    } else {
        // each ball with its nearest balls only: the pairs between parts that never join (an asset of
        // many separate parts) would otherwise cost n^2 segment tests
        std::vector<Vec3> centers;
        for (const Ball& b : s.balls) centers.push_back(b.center);
        const PointTree tree(centers);
        std::vector<size_t> idx(kReconnectNeighbours + 1);
        std::vector<double> d2(kReconnectNeighbours + 1);
        for (uint32_t i = 0; i < n; ++i) {
            const size_t found = tree.nearest(centers[i], idx.size(), idx.data(), d2.data());
            for (size_t k = 0; k < found; ++k) {
                const uint32_t j = uint32_t(idx[k]);
                if (j == i || uf.find(i) == uf.find(j)) continue;
                pairs.push_back({(centers[std::min(i, j)] - centers[std::max(i, j)]).squaredNorm(), std::min(i, j), std::max(i, j)});
            }
        }
        std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
        pairs.erase(std::unique(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.i == b.i && a.j == b.j; }),
                    pairs.end());
    }
    std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
        return a.d2 != b.d2 ? a.d2 < b.d2 : (a.i != b.i ? a.i < b.i : a.j < b.j);
    });
    const int passes = ball_part && ball_part->size() == n ? 3 : 2;
    for (int pass = tol >= 0 ? 0 : 1; pass < passes; ++pass)
        for (const Pair& p : pairs) {
            if (components <= 1) break;
            if (uf.find(p.i) == uf.find(p.j)) continue;
            if (pass == 2 && (*ball_part)[p.i] != (*ball_part)[p.j]) continue;
            if (!test.segment_inside(s.balls[p.i], s.balls[p.j], h, pass == 0 ? tol : -1, pass == 2 ? 4 * h : h, pass == 0))
                continue;
            uf.unite(p.i, p.j);
            s.edges.push_back({p.i, p.j});
            --components;
        }
}

// Medial route: the medial mesh has the shape's loops and the collapsing removal keeps them, so
// hole filling must not span one (a triangle over a thin handle passes the inside test when its
// own balls cover the handle's hole, and the loop would be lost). The triangles filling
// added are undone, last first, while b1 is below `target` and undoing one raises it; then added
// chords on no triangle are dropped while b1 is above `target` and dropping one lowers it.
// `target` is the smaller of b1 before removal and before filling: loops that removal added
// (where a removed edge left a cycle) may still be filled.
void keep_loops(const Skeleton& before, long target, Skeleton& s) {
    long b1 = topology(s).betti1;
    if (b1 >= target) return;
    std::vector<Tri> added;
    std::set_difference(s.faces.begin(), s.faces.end(), before.faces.begin(), before.faces.end(),
                        std::back_inserter(added));
    for (size_t i = added.size(); i-- > 0 && b1 < target;) {
        Skeleton t = s;
        t.faces.erase(std::lower_bound(t.faces.begin(), t.faces.end(), added[i]));
        const long b = topology(t).betti1;
        if (b > b1) s = std::move(t), b1 = b;
    }
    std::vector<std::array<uint32_t, 2>> chords;
    std::set_difference(s.edges.begin(), s.edges.end(), before.edges.begin(), before.edges.end(),
                        std::back_inserter(chords));
    for (size_t i = chords.size(); i-- > 0 && b1 > target;) {
        bool on_face = false;
        for (const Tri& f : s.faces)
            on_face = on_face || ((f[0] == chords[i][0] || f[1] == chords[i][0] || f[2] == chords[i][0]) &&
                                  (f[0] == chords[i][1] || f[1] == chords[i][1] || f[2] == chords[i][1]));
        if (on_face) continue;
        Skeleton t = s;
        t.edges.erase(std::lower_bound(t.edges.begin(), t.edges.end(), chords[i]));
        const TopologyStats ts = topology(t);
        if (ts.betti1 < b1 && ts.components == topology(s).components) s = std::move(t), b1 = ts.betti1;
    }
}

}  // namespace detail
}  // namespace ca

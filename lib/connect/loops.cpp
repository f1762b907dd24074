// loops.cpp: the last repair: the skeleton keeps no more loops than the shape has handles.
// While b1 exceeds the genus of the input (mesh_topology.h; only when it is known), the shortest
// cycle (total edge length) that is not a boundary of the complex is spanned by triangles that
// pass the inside test (a triangulation of the cycle's polygon; a fan for long cycles: the loop
// was a sheet with a missing piece), or else cut at its longest edge whose removal lowers b1
// without splitting a component, or else (a hole in a sheet: every edge on a triangle, so no cut
// lowers b1) spanned by triangles that pass the centre-line rule alone. The candidates are
// Horton's cycles (shortest path tree from each ball, closed by one edge), which contain a
// shortest non-bounding cycle.
#include "connect.h"

#include <algorithm>
#include <functional>
#include <queue>
#include <map>

namespace ca {
namespace detail {

namespace {

using Edge = std::array<uint32_t, 2>;
constexpr uint32_t kNone = UINT32_MAX;

uint32_t edge_index(const Skeleton& s, uint32_t a, uint32_t b) {
    const Edge key{std::min(a, b), std::max(a, b)};
    const auto it = std::lower_bound(s.edges.begin(), s.edges.end(), key);
    return it != s.edges.end() && *it == key ? uint32_t(it - s.edges.begin()) : kNone;
}

// Sorted edge indices of a closed vertex sequence (kNone in it if an edge is missing).
std::vector<uint32_t> cycle_edges(const Skeleton& s, const std::vector<uint32_t>& cycle) {
    std::vector<uint32_t> out;
    for (size_t i = 0; i < cycle.size(); ++i) out.push_back(edge_index(s, cycle[i], cycle[(i + 1) % cycle.size()]));
    std::sort(out.begin(), out.end());
    return out;
}

// Face boundaries of a canonical skeleton, as a basis over its edges.
Gf2Basis boundaries(const Skeleton& s) {
    Gf2Basis basis(s.edges.size());
    for (const Tri& f : s.faces) {
        std::vector<uint32_t> col{edge_index(s, f[0], f[1]), edge_index(s, f[0], f[2]), edge_index(s, f[1], f[2])};
        std::sort(col.begin(), col.end());
        basis.add(std::move(col));
    }
    return basis;
}

// Shortest cycle (vertex sequence) whose edges are not in `spanned`; empty if none.
std::vector<uint32_t> shortest_free_cycle(const Skeleton& s, const Gf2Basis& spanned) {
    const uint32_t n = uint32_t(s.balls.size());
    std::vector<std::vector<std::pair<uint32_t, uint32_t>>> adj(n);   // (neighbour, edge)
    std::vector<double> len(s.edges.size());
    for (uint32_t e = 0; e < s.edges.size(); ++e) {
        adj[s.edges[e][0]].push_back({s.edges[e][1], e});
        adj[s.edges[e][1]].push_back({s.edges[e][0], e});
        len[e] = (s.balls[s.edges[e][0]].center - s.balls[s.edges[e][1]].center).norm();
    }
    // per root: parent edge and the root's child on the path (cycles whose two paths leave the
    // root by the same branch are not simple and are found from another root)
    std::vector<std::vector<uint32_t>> parent(n), branch(n);
    struct Candidate { double length; uint32_t root, edge; };
    std::vector<Candidate> candidates;
    std::vector<double> dist(n);
    using Item = std::pair<double, uint32_t>;
    for (uint32_t r = 0; r < n; ++r) {
        if (adj[r].size() < 2) continue;
        std::fill(dist.begin(), dist.end(), -1.0);
        parent[r].assign(n, kNone);
        branch[r].assign(n, kNone);
        std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
        dist[r] = 0;
        branch[r][r] = r;
        queue.push({0, r});
        std::vector<uint8_t> done(n, 0);
        while (!queue.empty()) {
            const auto [d, u] = queue.top();
            queue.pop();
            if (done[u]) continue;
            done[u] = 1;
            for (const auto& [v, e] : adj[u]) {
                const double dv = d + len[e];
                if (done[v] || (dist[v] >= 0 && dist[v] <= dv)) continue;
                dist[v] = dv;
                parent[r][v] = e;
                branch[r][v] = u == r ? v : branch[r][u];
                queue.push({dv, v});
            }
        }
        for (uint32_t e = 0; e < s.edges.size(); ++e) {
            const uint32_t a = s.edges[e][0], b = s.edges[e][1];
            if (!done[a] || !done[b] || parent[r][a] == e || parent[r][b] == e || branch[r][a] == branch[r][b]) continue;
            candidates.push_back({dist[a] + dist[b] + len[e], r, e});
        }
    }
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
        return x.length != y.length ? x.length < y.length : (x.root != y.root ? x.root < y.root : x.edge < y.edge);
    });
    for (const Candidate& c : candidates) {
        const std::vector<uint32_t>& par = parent[c.root];
        auto path = [&](uint32_t v) {   // v, ..., root
            std::vector<uint32_t> p{v};
            while (v != c.root) {
                const Edge& e = s.edges[par[v]];
                v = e[0] == v ? e[1] : e[0];
                p.push_back(v);
            }
            return p;
        };
        std::vector<uint32_t> cycle = path(s.edges[c.edge][0]);
        std::vector<uint32_t> back = path(s.edges[c.edge][1]);
        cycle.insert(cycle.begin(), back.rbegin() + 1, back.rend());   // ... b, a, ..., root
        if (!spanned.spans(cycle_edges(s, cycle))) return cycle;
    }
    return {};
}

// Cycles up to this many vertices are spanned by any triangulation of the polygon whose triangles
// pass the inside test (dynamic programme over its diagonals, O(k^3) tests); longer ones by fans.
constexpr size_t kMaxTriangulated = 12;

// A triangulation of the closed polygon `cycle` whose every triangle passes `inside`; empty if none.
template <class Inside>
std::vector<Tri> triangulation(const std::vector<uint32_t>& cycle, Inside& inside) {
    const size_t k = cycle.size();
    // split[i][j]: the apex m of a valid triangulation of the sub-polygon i..j (0: unknown, -1: none)
    std::vector<std::vector<int>> split(k, std::vector<int>(k, 0));
    std::function<bool(size_t, size_t)> solvable = [&](size_t i, size_t j) {
        if (j < i + 2) return true;
        if (split[i][j] != 0) return split[i][j] > 0;
        split[i][j] = -1;
        for (size_t m = i + 1; m < j; ++m)
            if (inside(cycle[i], cycle[m], cycle[j]) && solvable(i, m) && solvable(m, j)) {
                split[i][j] = int(m);
                break;
            }
        return split[i][j] > 0;
    };
    std::vector<Tri> out;
    if (!solvable(0, k - 1)) return out;
    std::vector<std::pair<size_t, size_t>> todo{{0, k - 1}};
    while (!todo.empty()) {
        const auto [i, j] = todo.back();
        todo.pop_back();
        if (j < i + 2) continue;
        const size_t m = size_t(split[i][j]);
        out.push_back({cycle[i], cycle[m], cycle[j]});
        todo.push_back({i, m});
        todo.push_back({m, j});
    }
    return out;
}

// A repair is kept when it lowers b1 and keeps the components.
bool lowers_b1(const Skeleton& t, const TopologyStats& before) {
    const TopologyStats after = topology(t);
    return after.components == before.components && after.betti1 < before.betti1;
}

}  // namespace

size_t repair_loops(const InsideTest& test, double h, double tol, long genus, Skeleton& s) {
    if (genus < 0) return 0;
    canonicalize(s);
    std::vector<std::vector<uint32_t>> kept;   // loops neither filled nor cut (vertex sequences)
    // spanning triangles already tested, per rule: [0] the route's (envelope tol), [1] centre line only
    std::map<Tri, bool> tested[2];
    auto inside_by = [&](int rule) {
        return [&, rule](uint32_t a, uint32_t b, uint32_t c) {
            Tri t{a, b, c};
            std::sort(t.begin(), t.end());
            if (std::binary_search(s.faces.begin(), s.faces.end(), t)) return true;
            const auto it = tested[rule].find(t);
            if (it != tested[rule].end()) return it->second;
            return tested[rule][t] = test.triangle_inside(s.balls[t[0]], s.balls[t[1]], s.balls[t[2]], h, rule ? -1 : tol);
        };
    };
    for (;;) {
        const TopologyStats before = topology(s);
        Gf2Basis spanned = boundaries(s);
        long free_loops = before.betti1;
        for (auto it = kept.begin(); it != kept.end();) {
            std::vector<uint32_t> edges = cycle_edges(s, *it);
            if (std::count(edges.begin(), edges.end(), kNone)) { it = kept.erase(it); continue; }   // cut since
            free_loops -= spanned.add(std::move(edges));
            ++it;
        }
        if (free_loops <= genus) break;
        const std::vector<uint32_t> cycle = shortest_free_cycle(s, spanned);
        if (cycle.empty()) break;
        const size_t k = cycle.size();
        // Spans the cycle by triangles that pass `inside`; true if that lowered b1.
        auto span_by = [&](auto inside) {
            std::vector<Tri> span = k <= kMaxTriangulated ? triangulation(cycle, inside) : std::vector<Tri>{};
            for (size_t apex = 0; apex < k && span.empty() && k > kMaxTriangulated; ++apex) {   // a fan from each vertex
                for (size_t i = 1; i + 1 < k; ++i) {
                    const uint32_t a = cycle[apex], b = cycle[(apex + i) % k], c = cycle[(apex + i + 1) % k];
                    if (!inside(a, b, c)) { span.clear(); break; }
                    span.push_back({a, b, c});
                }
            }
            if (span.empty()) return false;
            Skeleton t = s;
            t.faces.insert(t.faces.end(), span.begin(), span.end());
            canonicalize(t);
            if (!lowers_b1(t, before)) return false;
            s = std::move(t);
            return true;
        };
        bool repaired = span_by(inside_by(0));
        if (!repaired) {   // cut: the longest edge of the cycle whose removal lowers b1
            std::vector<uint32_t> order = cycle_edges(s, cycle);
            std::sort(order.begin(), order.end(), [&](uint32_t x, uint32_t y) {
                const double lx = (s.balls[s.edges[x][0]].center - s.balls[s.edges[x][1]].center).squaredNorm();
                const double ly = (s.balls[s.edges[y][0]].center - s.balls[s.edges[y][1]].center).squaredNorm();
                return lx != ly ? lx > ly : x < y;
            });
            for (uint32_t e : order) {
                const Edge cut = s.edges[e];
                Skeleton t = s;
                t.edges.erase(t.edges.begin() + e);
                t.faces.erase(std::remove_if(t.faces.begin(), t.faces.end(), [&](const Tri& f) {
                                  return std::count(f.begin(), f.end(), cut[0]) && std::count(f.begin(), f.end(), cut[1]);
                              }),
                              t.faces.end());
                if (lowers_b1(t, before)) { s = std::move(t); repaired = true; break; }
            }
        }
        // a hole in a sheet (every edge on a triangle, so no cut lowers b1) whose spanning triangles
        // pass the centre-line rule but bulge past the envelope tolerance: spanned all the same
        if (!repaired && tol >= 0) repaired = span_by(inside_by(1));
        if (!repaired) kept.push_back(cycle);
    }
    const long b1 = topology(s).betti1;
    return size_t(std::max(0L, genus - b1));
}

}  // namespace detail
}  // namespace ca

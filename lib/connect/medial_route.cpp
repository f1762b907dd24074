// medial_route.cpp: the medial-axis connection route. The inner Voronoi diagram of the Voronoi
// samples is the medial mesh (vertices: circumcentres of inner Delaunay tetrahedra; edges: inner
// tetrahedra sharing a face; faces: Voronoi polygons dual to Delaunay edges whose closed ring of
// tetrahedra is all inner, fanned into triangles). The selected balls are snapped to medial
// vertices (anchors), every medial vertex is labelled by its nearest anchor along the medial mesh
// (multi-source Dijkstra), and anchors whose regions touch are joined (edges across region
// borders, triangles on fan triangles with three different labels).
#include "connect.h"

#include "delaunay.h"
#include "kdtree.h"
#include "parallel.h"
#include "point_winding.h"
#include "sampling.h"
#include "winding.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <queue>

namespace ca {

namespace {


constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

struct MedialMesh {
    std::vector<Vec3> vertices;                       // one per inner tetrahedron
    std::vector<std::array<uint32_t, 2>> edges;       // inner tetrahedra sharing a face
    std::vector<Tri> triangles;                       // fanned Voronoi polygons
};

// Tetrahedra and inner flags of the Voronoi samples: the candidate set's own, or computed here
// (random generator) from its Voronoi samples.
Status voronoi_diagram(const CandidateSet& set, int threads, const Monitor& monitor, std::vector<Vec3>& pts,
                       std::vector<Tet>& tets, std::vector<uint8_t>& inner) {
    if (!set.voronoi_tets.empty() && set.voronoi_inner.size() == set.voronoi_tets.size()) {
        pts = set.dense_samples;
        tets = set.voronoi_tets;
        inner = set.voronoi_inner;
        return Status::success();
    }
    const std::vector<Vec3>& raw = set.dense_samples.empty() ? set.cover_samples : set.dense_samples;
    pts.clear();
    for (uint32_t i : remove_near_duplicates(raw, 1e-7)) pts.push_back(raw[i]);
    Status st = delaunay_tetrahedra(pts, tets, monitor, "connect");
    if (!st.ok()) return st;
    // the inside test: the mesh's winding number, or a point cloud's own (point_winding.h)
    const PointCloudWinding* cloud = set.surface.kind().is_mesh() ? nullptr : set.queries.cloud_winding.get();
    const WindingNumber* winding = set.queries.winding.get();
    inner.assign(tets.size(), 0);
    const bool done = parallel_for(tets.size(), resolve_threads(threads), 8192, monitor, "connect", [&](size_t b, size_t e) {
        for (size_t t = b; t < e; ++t) {
            Vec3 c;
            const Tet& q = tets[t];
            inner[t] = circumcenter(pts[q[0]], pts[q[1]], pts[q[2]], pts[q[3]], c) && (cloud ? cloud->inside(c) : winding->inside(c));
        }
    });
    return done ? Status::success() : monitor.stop_status("connect");
}

// The medial mesh from the tetrahedra around each sample: per sample u (ascending), the faces and
// Delaunay edges whose smallest vertex is u are grouped by a small local sort of its incident
// tetrahedra, which gives the same elements in the same order as one global sort by
// (vertex indices, tetrahedron), with short sorts over data that stays in cache.
MedialMesh build_medial_mesh(const std::vector<Vec3>& pts, const std::vector<Tet>& tets,
                             const std::vector<uint8_t>& inner) {
    MedialMesh m;
    std::vector<uint32_t> vertex_of(tets.size(), kNone);
    for (size_t t = 0; t < tets.size(); ++t) {
        if (!inner[t]) continue;
        const Tet& q = tets[t];
        Vec3 c;
        if (!circumcenter(pts[q[0]], pts[q[1]], pts[q[2]], pts[q[3]], c)) continue;
        vertex_of[t] = uint32_t(m.vertices.size());
        m.vertices.push_back(c);
    }
    // tetrahedra incident to each sample, ascending (counting sort)
    const size_t np = pts.size();
    std::vector<uint32_t> start(np + 1, 0), incident(tets.size() * 4);
    for (const Tet& q : tets)
        for (uint32_t v : q) ++start[size_t(v) + 1];
    for (size_t i = 1; i <= np; ++i) start[i] += start[i - 1];
    {
        std::vector<uint32_t> fill(start.begin(), start.end() - 1);
        for (size_t t = 0; t < tets.size(); ++t)
            for (uint32_t v : tets[t]) incident[fill[v]++] = uint32_t(t);
    }
    struct FaceRef { uint32_t b, c, tet; };   // face (u, b, c), u < b < c
    struct EdgeRef { uint32_t v, tet; };      // Delaunay edge (u, v), u < v
    std::vector<FaceRef> faces;
    std::vector<EdgeRef> refs;
    std::vector<std::array<uint32_t, 2>> link;   // per ring tetrahedron: its two other vertices
    std::vector<uint32_t> ring;
    std::vector<uint8_t> used;
    for (uint32_t u = 0; u < np; ++u) {
        faces.clear();
        refs.clear();
        for (uint32_t a = start[u]; a < start[u + 1]; ++a) {
            const uint32_t t = incident[a];
            uint32_t o[3];
            int k = 0;
            for (uint32_t w : tets[t])
                if (w != u) o[k++] = w;
            std::sort(o, o + 3);
            for (uint32_t w : o)
                if (w > u) refs.push_back({w, t});
            // faces containing u with u smallest: pairs of the other vertices above u
            if (vertex_of[t] != kNone)
                for (int i = 0; i < 3; ++i)
                    for (int j = i + 1; j < 3; ++j)
                        if (o[i] > u) faces.push_back({o[i], o[j], t});
        }
        // faces shared by two inner tetrahedra -> medial edges
        std::sort(faces.begin(), faces.end(), [](const FaceRef& x, const FaceRef& y) {
            return x.b != y.b ? x.b < y.b : x.c != y.c ? x.c < y.c : x.tet < y.tet;
        });
        for (size_t i = 0; i + 1 < faces.size(); ++i)
            if (faces[i].b == faces[i + 1].b && faces[i].c == faces[i + 1].c)
                m.edges.push_back({vertex_of[faces[i].tet], vertex_of[faces[i + 1].tet]});
        // Delaunay edges -> ring of tetrahedra around them (all tetrahedra, to see outer ones)
        std::sort(refs.begin(), refs.end(), [](const EdgeRef& x, const EdgeRef& y) {
            return x.v != y.v ? x.v < y.v : x.tet < y.tet;
        });
        for (size_t b = 0; b < refs.size();) {
            size_t e = b;
            bool all_inner = true;
            while (e < refs.size() && refs[e].v == refs[b].v) all_inner = all_inner && vertex_of[refs[e].tet] != kNone, ++e;
            const size_t n = e - b;
            if (all_inner && n >= 3) {
                const uint32_t v = refs[b].v;
                link.clear();
                for (size_t r = b; r < e; ++r) {
                    std::array<uint32_t, 2> o{};
                    int k = 0;
                    for (uint32_t w : tets[refs[r].tet])
                        if (w != u && w != v) o[size_t(k++)] = w;
                    link.push_back(o);
                }
                // walk the link cycle: consecutive tetrahedra share one link vertex
                ring.assign(1, 0);
                used.assign(n, 0);
                used[0] = 1;
                uint32_t next_vertex = link[0][1];
                bool closed = false;
                for (size_t step = 1; step <= n; ++step) {
                    size_t found = n;
                    for (size_t r = 0; r < n; ++r)
                        if (!used[r] && (link[r][0] == next_vertex || link[r][1] == next_vertex)) { found = r; break; }
                    if (found == n) { closed = ring.size() == n && next_vertex == link[0][0]; break; }
                    used[found] = 1;
                    ring.push_back(uint32_t(found));
                    next_vertex = link[found][0] == next_vertex ? link[found][1] : link[found][0];
                }
                if (closed)
                    for (size_t r = 1; r + 1 < n; ++r)
                        m.triangles.push_back({vertex_of[refs[b + ring[0]].tet], vertex_of[refs[b + ring[r]].tet],
                                               vertex_of[refs[b + ring[r + 1]].tet]});
            }
            b = e;
        }
    }
    return m;
}

}  // namespace

namespace detail {

Status connect_medial(const CandidateSet& set, const Selection& sel, int threads, const Monitor& monitor, Skeleton& out) {
    const size_t k = sel.indices.size();
    if (k < 2) return Status::success();
    if (!monitor.report("connect", 0)) return monitor.stop_status("connect");
    std::vector<Vec3> pts;
    std::vector<Tet> tets;
    std::vector<uint8_t> inner;
    Status st = voronoi_diagram(set, threads, monitor, pts, tets, inner);
    if (!st.ok()) return st;
    const MedialMesh m = build_medial_mesh(pts, tets, inner);
    if (m.vertices.empty()) return fail(Code::geometry_failure, "the inner Voronoi diagram has no vertex");
    if (!monitor.report("connect", 0.2)) return monitor.stop_status("connect");

    // anchors: the medial vertex nearest to each selected ball
    const PointTree tree(m.vertices);
    std::vector<uint32_t> label(m.vertices.size(), kNone);
    std::vector<double> dist(m.vertices.size(), std::numeric_limits<double>::infinity());
    using Item = std::pair<double, uint32_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    // Two balls can have the same nearest medial vertex (small balls at thin tips): the later one
    // takes the nearest free vertex among a few, or else shares the region of the owner (an edge).
    std::vector<std::array<uint32_t, 2>> shared;
    constexpr size_t kSnapCandidates = 8;
    for (size_t i = 0; i < k; ++i) {
        size_t idx[kSnapCandidates];
        double d2[kSnapCandidates];
        const size_t found = tree.nearest(out.balls[i].center, kSnapCandidates, idx, d2);
        if (found == 0) continue;
        size_t pick = found;
        for (size_t c = 0; c < found && pick == found; ++c)
            if (label[idx[c]] == kNone) pick = c;
        if (pick == found) {
            shared.push_back({std::min(uint32_t(i), label[idx[0]]), std::max(uint32_t(i), label[idx[0]])});
            continue;
        }
        label[idx[pick]] = uint32_t(i);
        dist[idx[pick]] = 0;
        queue.push({0.0, uint32_t(idx[pick])});
    }
    // multi-source Dijkstra along the medial edges
    std::vector<uint32_t> offset(m.vertices.size() + 1, 0), adjacency(2 * m.edges.size());
    for (const auto& e : m.edges) ++offset[e[0] + 1], ++offset[e[1] + 1];
    for (size_t i = 1; i < offset.size(); ++i) offset[i] += offset[i - 1];
    {
        std::vector<uint32_t> fill(offset.begin(), offset.end() - 1);
        for (const auto& e : m.edges) adjacency[fill[e[0]]++] = e[1], adjacency[fill[e[1]]++] = e[0];
    }
    while (!queue.empty()) {
        const auto [d, u] = queue.top();
        queue.pop();
        if (d > dist[u]) continue;
        for (uint32_t a = offset[u]; a < offset[u + 1]; ++a) {
            const uint32_t w = adjacency[a];
            const double nd = d + (m.vertices[u] - m.vertices[w]).norm();
            if (nd < dist[w] || (nd == dist[w] && label[u] < label[w])) {
                dist[w] = nd;
                label[w] = label[u];
                queue.push({nd, w});
            }
        }
    }
    if (!monitor.report("connect", 0.4)) return monitor.stop_status("connect");
    out.edges.insert(out.edges.end(), shared.begin(), shared.end());
    for (const auto& e : m.edges) {
        const uint32_t a = label[e[0]], b = label[e[1]];
        if (a != kNone && b != kNone && a != b) out.edges.push_back({std::min(a, b), std::max(a, b)});
    }
    for (const Tri& t : m.triangles) {
        Tri f{label[t[0]], label[t[1]], label[t[2]]};
        std::sort(f.begin(), f.end());
        if (f[2] != kNone && f[0] != f[1] && f[1] != f[2]) out.faces.push_back(f);
    }
    return Status::success();
}

}  // namespace detail

}  // namespace ca

// hole_caps.cpp: the fans that cap the closed boundary loops of an open mesh (rule in hole_caps.h).
#include "hole_caps.h"

#include "duplicates.h"
#include "union_find.h"

#include <algorithm>
#include <array>
#include <limits>
#include <map>

namespace ca {

Mesh hole_caps(const Mesh& mesh, const Monitor& monitor) {
    // vertices with identical coordinates are one vertex (split seams are not holes)
    const std::vector<uint32_t> weld = weld_map(mesh.vertices, monitor);
    if (weld.size() != mesh.vertices.size()) return {};
    return hole_caps(mesh, half_edge_buckets(mesh, weld, monitor));
}

Mesh hole_caps(const Mesh& mesh, const HalfEdgeBuckets& edges) {
    // edges used by one triangle only, ascending: in the half-edge buckets, runs of one larger
    // vertex of length 1, kept with their direction
    const size_t nv = mesh.vertices.size();
    if (edges.start.size() != nv + 1) return {};   // stopped
    std::vector<std::array<uint32_t, 2>> boundary;   // directed as in its triangle
    for (uint32_t u = 0; u < nv; ++u) {
        const auto b = edges.key.begin() + edges.start[u], e = edges.key.begin() + edges.start[u + 1];
        for (auto k = b; k != e;) {
            auto run = k;
            while (run != e && (*run >> 1) == (*k >> 1)) ++run;
            const uint32_t w = uint32_t(*k >> 1);
            if (run - k == 1) boundary.push_back((*k & 1) ? std::array<uint32_t, 2>{w, u} : std::array<uint32_t, 2>{u, w});
            k = run;
        }
    }
    Mesh caps;
    if (boundary.empty()) return caps;
    UnionFind uf(mesh.vertices.size());
    std::vector<int> degree(mesh.vertices.size(), 0);
    for (const auto& e : boundary) uf.unite(e[0], e[1]), ++degree[e[0]], ++degree[e[1]];
    // per loop (root): closed (all degrees 2), centroid of its vertices
    std::map<uint32_t, std::pair<Vec3, int>> centroid;
    std::map<uint32_t, bool> closed;
    for (uint32_t v = 0; v < degree.size(); ++v) {
        if (degree[v] == 0) continue;
        const uint32_t r = uf.find(v);
        auto& c = centroid.emplace(r, std::make_pair(Vec3(Vec3::Zero()), 0)).first->second;
        c.first += mesh.vertices[v];
        ++c.second;
        auto it = closed.emplace(r, true).first;
        it->second = it->second && degree[v] == 2;
    }
    std::map<uint32_t, uint32_t> centre_vertex;
    for (const auto& [r, c] : centroid) {
        if (!closed[r] || c.second < 3) continue;
        centre_vertex[r] = uint32_t(caps.vertices.size());
        caps.vertices.push_back(c.first / double(c.second));
    }
    std::map<uint32_t, uint32_t> cap_vertex;   // welded mesh vertex -> caps vertex
    auto vertex = [&](uint32_t v) {
        auto it = cap_vertex.find(v);
        if (it != cap_vertex.end()) return it->second;
        const uint32_t id = uint32_t(caps.vertices.size());
        caps.vertices.push_back(mesh.vertices[v]);
        cap_vertex[v] = id;
        return id;
    };
    for (const auto& e : boundary) {
        const auto it = centre_vertex.find(uf.find(e[0]));
        if (it == centre_vertex.end()) continue;
        // cap vertices numbered in ascending mesh order, the triangle reversed against its edge
        const uint32_t lo = vertex(std::min(e[0], e[1])), hi = vertex(std::max(e[0], e[1]));
        caps.triangles.push_back(e[0] < e[1] ? Tri{it->second, hi, lo} : Tri{it->second, lo, hi});
    }
    // Boundary components with a vertex on more than two boundary edges (two holes meeting at a
    // corner; a T-junction whose sealing sliver was dropped as zero-area, beside a hole) are split
    // into simple cycles: walks along the edges' own direction, each cut off where it meets
    // itself. Every cycle of three or more vertices is capped like a loop; a walk that ends
    // (orientations disagree there) is an open curve and gets no cap, nor do fan triangles of zero
    // area (a slit's cycle has no width).
    std::map<uint32_t, std::vector<size_t>> out_edges;   // branching components only
    for (size_t k = 0; k < boundary.size(); ++k)
        if (!closed[uf.find(boundary[k][0])]) out_edges[boundary[k][0]].push_back(k);
    std::vector<uint8_t> used(boundary.size(), 0);
    for (const auto& [first, unused_list] : out_edges) {
        (void)unused_list;
        for (;;) {
            // a walk from `first` along unused edges; `path` holds its vertices, `on_path` their
            // positions in it
            std::vector<uint32_t> path{first};
            std::map<uint32_t, size_t> on_path{{first, 0}};
            uint32_t at = first;
            bool moved = false;
            for (;;) {
                const auto from = out_edges.find(at);
                if (from == out_edges.end()) break;
                size_t next = boundary.size();
                for (size_t k : from->second)
                    if (!used[k]) { next = k; break; }
                if (next == boundary.size()) break;
                used[next] = 1;
                moved = true;
                const uint32_t to = boundary[next][1];
                const auto seen = on_path.find(to);
                if (seen == on_path.end()) {
                    on_path[to] = path.size();
                    path.push_back(to);
                    at = to;
                    continue;
                }
                // the walk met itself: path[seen..] is a simple cycle, capped, and cut off
                std::vector<uint32_t> cycle(path.begin() + long(seen->second), path.end());
                for (size_t i = seen->second + 1; i < path.size(); ++i) on_path.erase(path[i]);
                path.resize(seen->second + 1);
                at = to;
                if (cycle.size() < 3) continue;
                Vec3 centre = Vec3::Zero();
                for (uint32_t v : cycle) centre += mesh.vertices[v];
                centre /= double(cycle.size());
                uint32_t c = std::numeric_limits<uint32_t>::max();   // the centre, added with the first triangle
                for (size_t i = 0; i < cycle.size(); ++i) {
                    const uint32_t a = cycle[i], b = cycle[(i + 1) % cycle.size()];
                    if ((mesh.vertices[a] - centre).cross(mesh.vertices[b] - centre).norm() <= 1e-14) continue;
                    if (c == std::numeric_limits<uint32_t>::max()) {
                        c = uint32_t(caps.vertices.size());
                        caps.vertices.push_back(centre);
                    }
                    caps.triangles.push_back(Tri{c, vertex(b), vertex(a)});
                }
            }
            if (!moved) break;
        }
    }
    return caps;
}

}  // namespace ca

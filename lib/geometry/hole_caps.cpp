// hole_caps.cpp: the fans that cap the closed boundary loops of an open mesh (rule in hole_caps.h).
#include "hole_caps.h"

#include "duplicates.h"
#include "union_find.h"

#include <algorithm>
#include <array>
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
    return caps;
}

}  // namespace ca

// hole_caps.cpp: keeps candidate balls of an open mesh from reaching out through its
// holes. A Voronoi ball is empty of samples, but a hole has no samples, so a ball under a hole
// (venus's base) bulges out through it; a random candidate's radius (distance to the mesh) has
// the same problem. Each closed boundary loop of the mesh (edges used by one triangle, vertices
// welded by position, every loop vertex on exactly two boundary edges) is capped by a fan of
// triangles from the loop's centroid, used only for distances: every candidate's radius is
// clamped to its distance to the caps. Closed meshes have no loop and are unchanged; open
// boundary curves that are not loops get no cap.
#include "candidates.h"

#include "distance.h"
#include "duplicates.h"
#include "parallel.h"
#include "union_find.h"

#include <algorithm>
#include <map>

namespace ca {

Mesh hole_caps(const Mesh& mesh, const Monitor& monitor) {
    // vertices with identical coordinates are one vertex (split seams are not holes)
    const std::vector<uint32_t> weld = weld_map(mesh.vertices, monitor);
    if (weld.size() != mesh.vertices.size()) return {};
    // edges used by one triangle only, ascending: the edges (u < w) bucketed by u (a counting
    // sort), each bucket's w sorted, runs of length 1 kept
    const size_t nv = mesh.vertices.size();
    std::vector<uint32_t> start(nv + 1, 0);
    auto for_each_edge = [&](auto&& f) {
        for (const Tri& t : mesh.triangles)
            for (int a = 0; a < 3; ++a) {
                const uint32_t u = weld[t[size_t(a)]], w = weld[t[size_t((a + 1) % 3)]];
                if (u != w) f(std::min(u, w), std::max(u, w));
            }
    };
    for_each_edge([&](uint32_t u, uint32_t) { ++start[u + 1]; });
    for (size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
    std::vector<uint32_t> other(start[nv]), fill(start.begin(), start.end() - 1);
    for_each_edge([&](uint32_t u, uint32_t w) { other[fill[u]++] = w; });
    fill = std::vector<uint32_t>();
    std::vector<std::array<uint32_t, 2>> boundary;
    for (uint32_t u = 0; u < nv; ++u) {
        const auto b = other.begin() + start[u], e = other.begin() + start[u + 1];
        std::sort(b, e);
        for (auto k = b; k != e;) {
            auto run = k;
            while (run != e && *run == *k) ++run;
            if (run - k == 1) boundary.push_back({u, *k});
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
        caps.triangles.push_back({it->second, vertex(e[0]), vertex(e[1])});
    }
    return caps;
}

bool clamp_to_hole_caps(CandidateSet& set, const MeshDistance& distance, int threads, const Monitor& monitor) {
    set.hole_clamped = 0;
    std::vector<uint8_t> clamped(set.balls.size(), 0);
    const bool done = parallel_for(set.balls.size(), threads, 4096, monitor, "candidates", [&](size_t b, size_t e) {
        for (size_t i = b; i < e; ++i) {
            Ball& ball = set.balls[i];
            const double d = distance.distance_below(ball.center, ball.radius);
            if (d < ball.radius) ball.radius = d, clamped[i] = 1;
        }
    });
    if (!done) return false;
    set.balls.erase(std::remove_if(set.balls.begin(), set.balls.end(), [](const Ball& x) { return !(x.radius > 0); }),
                    set.balls.end());
    for (uint8_t c : clamped) set.hole_clamped += c;
    return true;
}

}  // namespace ca

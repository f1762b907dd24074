// mesh_topology.cpp: genus per connected part of a mesh by the Euler characteristic (rule in
// mesh_topology.h).
#include "mesh_topology.h"

#include "duplicates.h"
#include "union_find.h"

#include <algorithm>

namespace ca {

MeshTopology mesh_topology(const Mesh& mesh) {
    MeshTopology out;
    const std::vector<uint32_t> weld = weld_map(mesh.vertices);
    std::vector<Tri> tris;
    std::vector<uint32_t> kept;   // input index of each welded triangle
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        Tri f = mesh.triangles[t];
        bool valid = true;
        for (uint32_t& v : f) {
            if (v >= weld.size()) valid = false;
            else v = weld[v];
        }
        if (!valid || f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) continue;
        tris.push_back(f);
        kept.push_back(uint32_t(t));
    }
    UnionFind uf(mesh.vertices.size());
    for (const Tri& f : tris) uf.unite(f[0], f[1]), uf.unite(f[0], f[2]);
    // parts numbered in order of their first triangle
    std::vector<int64_t> part_of_root(mesh.vertices.size(), -1);
    std::vector<uint32_t> part(tris.size());
    size_t parts = 0;
    for (size_t t = 0; t < tris.size(); ++t) {
        const uint32_t r = uf.find(tris[t][0]);
        if (part_of_root[r] < 0) part_of_root[r] = int64_t(parts++);
        part[t] = uint32_t(part_of_root[r]);
    }
    out.triangle_part.assign(mesh.triangles.size(), 0);
    for (size_t t = 0; t < tris.size(); ++t) out.triangle_part[kept[t]] = part[t];

    std::vector<long> V(parts, 0), E(parts, 0), F(parts, 0);
    std::vector<uint8_t> manifold(parts, 1);
    std::vector<uint8_t> used(mesh.vertices.size(), 0);
    std::vector<std::array<uint32_t, 3>> edges;   // (a, b, part) with a < b
    edges.reserve(3 * tris.size());
    for (size_t t = 0; t < tris.size(); ++t) {
        const Tri& f = tris[t];
        ++F[part[t]];
        for (int i = 0; i < 3; ++i) {
            const uint32_t a = f[size_t(i)], b = f[size_t((i + 1) % 3)];
            if (!used[a]) used[a] = 1, ++V[part[t]];
            edges.push_back({std::min(a, b), std::max(a, b), part[t]});
        }
    }
    std::sort(edges.begin(), edges.end());
    for (size_t i = 0; i < edges.size();) {
        size_t j = i;
        while (j < edges.size() && edges[j][0] == edges[i][0] && edges[j][1] == edges[i][1]) ++j;
        ++E[edges[i][2]];
        if (j - i != 2) manifold[edges[i][2]] = 0;   // open (1) or non-manifold (> 2) edge
        i = j;
    }
    out.part_genus.assign(parts, -1);
    out.genus = parts > 0 ? 0 : -1;
    for (size_t p = 0; p < parts; ++p) {
        const long chi = V[p] - E[p] + F[p];
        if (manifold[p] && chi <= 2 && (2 - chi) % 2 == 0) out.part_genus[p] = (2 - chi) / 2;
        if (out.part_genus[p] < 0) out.genus = -1;
        else if (out.genus >= 0) out.genus += out.part_genus[p];
    }
    return out;
}

HalfEdgeBuckets half_edge_buckets(const Mesh& mesh, const std::vector<uint32_t>& vertex, const Monitor& monitor) {
    const size_t nv = mesh.vertices.size();
    HalfEdgeBuckets out, stopped;
    if (!fill_checked(out.start, nv + 1, 0u, monitor)) return stopped;
    auto for_each = [&](auto&& f) {
        for (size_t k = 0; k < mesh.triangles.size(); ++k) {
            if (monitor.stopped_at(k)) return false;
            const Tri& t = mesh.triangles[k];
            for (int i = 0; i < 3; ++i) {
                uint32_t a = t[size_t(i)], b = t[size_t((i + 1) % 3)];
                if (!vertex.empty()) a = vertex[a], b = vertex[b];
                if (a != b) f(std::min(a, b), uint64_t(std::max(a, b)) * 2 + (b < a));
            }
        }
        return true;
    };
    if (!for_each([&](uint32_t u, uint64_t) { ++out.start[u + 1]; })) return stopped;
    for (size_t v = 0; v < nv; ++v) out.start[v + 1] += out.start[v];
    if (!fill_checked(out.key, size_t(out.start[nv]), uint64_t(0), monitor)) return stopped;
    std::vector<uint32_t> fill(out.start.begin(), out.start.end() - 1);
    if (!for_each([&](uint32_t u, uint64_t key) { out.key[fill[u]++] = key; })) return stopped;
    for (size_t u = 0; u < nv; ++u) {
        if (monitor.stopped_at(u)) return stopped;
        std::sort(out.key.begin() + out.start[u], out.key.begin() + out.start[u + 1]);
    }
    return out;
}

}  // namespace ca

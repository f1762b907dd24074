// mesh_topology.cpp: half-edge buckets, closedness and the genus per connected part of a mesh
// by the Euler characteristic (rules in mesh_topology.h).
#include "mesh_topology.h"

#include "bvh.h"
#include "duplicates.h"
#include "union_find.h"

#include <algorithm>

namespace ca {

MeshTopology mesh_topology(const Mesh& mesh, const std::vector<uint32_t>& weld, const HalfEdgeBuckets& edges,
                           const Monitor& monitor) {
    MeshTopology out, stopped;
    const size_t nv = mesh.vertices.size();
    if (edges.start.size() != nv + 1 || (!weld.empty() && weld.size() != nv)) return stopped;
    auto corner = [&](uint32_t v) { return weld.empty() ? v : weld[v]; };
    UnionFind uf(nv);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (monitor.stopped_at(t)) return stopped;
        const Tri& f = mesh.triangles[t];
        if (!(f[0] < nv && f[1] < nv && f[2] < nv)) continue;
        const Tri w = {corner(f[0]), corner(f[1]), corner(f[2])};
        if (w[0] != w[1] && w[1] != w[2] && w[0] != w[2]) uf.unite(w[0], w[1]), uf.unite(w[0], w[2]);
    }
    // parts numbered in order of their first (non-degenerate) triangle
    std::vector<int64_t> part_of_root;
    if (!fill_checked(part_of_root, nv, int64_t(-1), monitor)) return stopped;
    std::vector<long> V, E, F;
    std::vector<uint8_t> used(nv, 0);
    if (!fill_checked(out.triangle_part, mesh.triangles.size(), 0u, monitor)) return stopped;
    bool valid = true;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (monitor.stopped_at(t)) return stopped;
        const Tri& f = mesh.triangles[t];
        valid = valid && detail::triangle_ok(mesh, f);
        if (!(f[0] < nv && f[1] < nv && f[2] < nv)) continue;
        const Tri w = {corner(f[0]), corner(f[1]), corner(f[2])};
        if (w[0] == w[1] || w[1] == w[2] || w[0] == w[2]) continue;
        const uint32_t r = uf.find(w[0]);
        if (part_of_root[r] < 0) {
            part_of_root[r] = int64_t(F.size());
            V.push_back(0), E.push_back(0), F.push_back(0);
        }
        const uint32_t p = uint32_t(part_of_root[r]);
        out.triangle_part[t] = p;
        ++F[p];
        for (uint32_t v : w)
            if (!used[v]) used[v] = 1, ++V[p];
    }
    // each run of one larger vertex in a bucket is one edge; its length is the number of
    // triangles on it, its balance the half-edges up minus down
    const size_t parts = F.size();
    std::vector<uint8_t> manifold(parts, 1);
    out.part_open.assign(parts, 0);
    bool balanced = true;
    for (uint32_t u = 0; u < nv; ++u) {
        if (monitor.stopped_at(u)) return stopped;
        const auto b = edges.key.begin() + edges.start[u], e = edges.key.begin() + edges.start[u + 1];
        if (b == e) continue;
        const uint32_t p = uint32_t(part_of_root[uf.find(u)]);
        for (auto k = b; k != e;) {
            const uint64_t w = *k >> 1;
            long count = 0, balance = 0;
            for (; k != e && (*k >> 1) == w; ++k) ++count, balance += (*k & 1) ? -1 : 1;
            ++E[p];
            if (count != 2) manifold[p] = 0;   // open (1) or non-manifold (> 2) edge
            if (count == 1) out.part_open[p] = 1;
            if (balance != 0) balanced = false;
        }
    }
    out.closed = valid && balanced && parts > 0;
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

size_t MeshTopology::open_parts() const {
    return size_t(std::count(part_open.begin(), part_open.end(), uint8_t(1)));
}

MeshTopology mesh_topology(const Mesh& mesh) {
    const std::vector<uint32_t> weld = weld_map(mesh.vertices);
    return mesh_topology(mesh, weld, half_edge_buckets(mesh, weld));
}

HalfEdgeBuckets half_edge_buckets(const Mesh& mesh, const std::vector<uint32_t>& vertex, const Monitor& monitor) {
    const size_t nv = mesh.vertices.size();
    if (!vertex.empty() && vertex.size() != nv) return {};
    HalfEdgeBuckets out, stopped;
    if (!fill_checked(out.start, nv + 1, 0u, monitor)) return stopped;
    auto for_each = [&](auto&& f) {
        for (size_t k = 0; k < mesh.triangles.size(); ++k) {
            if (monitor.stopped_at(k)) return false;
            Tri t = mesh.triangles[k];
            if (t[0] >= nv || t[1] >= nv || t[2] >= nv) continue;
            if (!vertex.empty()) t = {vertex[t[0]], vertex[t[1]], vertex[t[2]]};
            if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
            for (int i = 0; i < 3; ++i) {
                const uint32_t a = t[size_t(i)], b = t[size_t((i + 1) % 3)];
                f(std::min(a, b), uint64_t(std::max(a, b)) * 2 + (b < a));
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

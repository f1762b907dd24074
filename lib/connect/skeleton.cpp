// skeleton.cpp: canonical form of a skeleton (sorted, unique edges and faces, every face edge
// present) and its topology: connected components (union-find), isolated balls, and the first
// Betti number of the 2-complex over GF(2), b1 = (E - V + C) - rank(boundary_2).
#include "skeleton.h"

#include "union_find.h"

#include <algorithm>
#include <numeric>

namespace ca {

namespace {

using Edge = std::array<uint32_t, 2>;

// Symmetric difference of two sorted index vectors (addition over GF(2)).
std::vector<uint32_t> xor_sorted(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b) {
    std::vector<uint32_t> out;
    out.reserve(a.size() + b.size());
    std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
    return out;
}

}  // namespace

void Gf2Basis::reduce(std::vector<uint32_t>& v) const {
    while (!v.empty() && column_with_pivot_[v.back()] >= 0) v = xor_sorted(v, columns_[size_t(column_with_pivot_[v.back()])]);
}

bool Gf2Basis::add(std::vector<uint32_t> v) {
    reduce(v);
    if (v.empty()) return false;
    column_with_pivot_[v.back()] = int64_t(columns_.size());
    columns_.push_back(std::move(v));
    return true;
}

bool Gf2Basis::spans(std::vector<uint32_t> v) const {
    reduce(v);
    return v.empty();
}

void canonicalize(Skeleton& s) {
    std::vector<Tri> faces;
    faces.reserve(s.faces.size());
    for (Tri f : s.faces) {
        std::sort(f.begin(), f.end());
        if (f[0] == f[1] || f[1] == f[2]) continue;   // degenerate face
        faces.push_back(f);
    }
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());

    std::vector<Edge> edges;
    edges.reserve(s.edges.size() + 3 * faces.size());
    for (Edge e : s.edges) {
        if (e[0] == e[1]) continue;                    // self-loop
        if (e[0] > e[1]) std::swap(e[0], e[1]);
        edges.push_back(e);
    }
    for (const Tri& f : faces) {
        edges.push_back({f[0], f[1]});
        edges.push_back({f[0], f[2]});
        edges.push_back({f[1], f[2]});
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

    s.edges = std::move(edges);
    s.faces = std::move(faces);
}

TopologyStats topology(const Skeleton& input) {
    Skeleton s = input;
    canonicalize(s);
    const size_t V = s.balls.size();
    // Elements referring to missing balls are ignored.
    auto valid = [V](uint32_t i) { return size_t(i) < V; };
    s.edges.erase(std::remove_if(s.edges.begin(), s.edges.end(),
                                 [&](const Edge& e) { return !valid(e[1]); }),
                  s.edges.end());
    s.faces.erase(std::remove_if(s.faces.begin(), s.faces.end(),
                                 [&](const Tri& f) { return !valid(f[2]); }),
                  s.faces.end());

    TopologyStats st;
    UnionFind uf(V);
    std::vector<char> has_edge(V, 0);
    size_t components = V;
    for (const Edge& e : s.edges) {
        has_edge[e[0]] = has_edge[e[1]] = 1;
        if (uf.unite(e[0], e[1])) --components;
    }
    st.components = components;
    st.isolated = size_t(std::count(has_edge.begin(), has_edge.end(), char(0)));

    // Boundary of each face as a sorted vector of edge indices (edges are sorted and unique).
    auto edge_index = [&](uint32_t a, uint32_t b) {
        const Edge key{a, b};
        return uint32_t(std::lower_bound(s.edges.begin(), s.edges.end(), key) - s.edges.begin());
    };
    Gf2Basis boundaries(s.edges.size());
    for (const Tri& f : s.faces) {
        std::vector<uint32_t> col{edge_index(f[0], f[1]), edge_index(f[0], f[2]),
                                  edge_index(f[1], f[2])};
        std::sort(col.begin(), col.end());
        boundaries.add(std::move(col));
    }
    const size_t rank2 = boundaries.rank();
    // dim ker(boundary_1) = E - rank(boundary_1) = E - (V - C)
    st.betti1 = long(s.edges.size()) - long(V) + long(components) - long(rank2);
    return st;
}

}  // namespace ca

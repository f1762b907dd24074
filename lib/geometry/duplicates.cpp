// duplicates.cpp: welding of equal vertices and merging of repeated triangles (duplicates.h).
#include "duplicates.h"

#include <algorithm>
#include <cstring>

namespace ca {

// One pass in index order over an open-addressing hash table of first occurrences: a vertex
// equal (==) to an earlier one gets that one's index, so each gets the smallest index at its
// position. Keys hash the coordinates' bits with -0 folded onto +0, which == treats as equal.
std::vector<uint32_t> weld_map(const std::vector<Vec3>& vertices, const Monitor& monitor) {
    const size_t nv = vertices.size();
    size_t size = 16;
    while (size < 2 * nv) size *= 2;
    constexpr uint32_t kEmpty = UINT32_MAX;
    std::vector<uint32_t> weld, table;
    if (!fill_checked(weld, nv, 0u, monitor) || !fill_checked(table, size, kEmpty, monitor)) return {};
    auto bits = [](double x) {
        x += 0.0;   // -0 -> +0
        uint64_t b;
        std::memcpy(&b, &x, sizeof b);
        return b;
    };
    for (size_t i = 0; i < nv; ++i) {
        if (monitor.stopped_at(i)) return {};
        const Vec3& v = vertices[i];
        uint64_t h = bits(v.x()) * 0x9E3779B97F4A7C15ull;
        h = (h ^ (h >> 31) ^ bits(v.y())) * 0xC2B2AE3D27D4EB4Full;
        h = (h ^ (h >> 29) ^ bits(v.z())) * 0x165667B19E3779F9ull;
        h ^= h >> 32;
        size_t slot = size_t(h) & (size - 1);
        while (table[slot] != kEmpty && vertices[table[slot]] != v) slot = (slot + 1) & (size - 1);
        if (table[slot] == kEmpty) table[slot] = uint32_t(i);
        weld[i] = table[slot];
    }
    return weld;
}

MergeCounts merge_duplicate_geometry(Mesh& mesh, const Monitor& monitor) {
    MergeCounts counts;
    MergeCounts stopped;
    stopped.stopped = true;
    const std::vector<uint32_t> weld = weld_map(mesh.vertices, monitor);
    if (weld.size() != mesh.vertices.size()) return stopped;
    const size_t nt = mesh.triangles.size();
    // welded corners; triangles with a repeated corner are dropped here
    std::vector<Tri> tris;
    reserve_large(tris, nt);
    for (size_t k = 0; k < nt; ++k) {
        if (monitor.stopped_at(k)) return stopped;
        const Tri& t = mesh.triangles[k];
        const Tri w = {weld[t[0]], weld[t[1]], weld[t[2]]};
        if (w[0] == w[1] || w[1] == w[2] || w[0] == w[2]) ++counts.degenerate;
        else tris.push_back(w);
    }
    // Group the triangles by their sorted corners (open-addressing hash table of first members);
    // `even` says whether a triangle's corner order is an even permutation of its sorted corners.
    const size_t n = tris.size();
    auto sorted = [](const Tri& t) {
        Tri s = t;
        if (s[0] > s[1]) std::swap(s[0], s[1]);
        if (s[1] > s[2]) std::swap(s[1], s[2]);
        if (s[0] > s[1]) std::swap(s[0], s[1]);
        return s;
    };
    auto even = [](const Tri& t) {   // cyclic rotations of an ascending triple are even
        return (t[0] < t[1] && t[1] < t[2]) || (t[1] < t[2] && t[2] < t[0]) || (t[2] < t[0] && t[0] < t[1]);
    };
    size_t size = 16;
    while (size < 2 * n) size *= 2;
    constexpr uint32_t kEmpty = UINT32_MAX;
    std::vector<uint32_t> table, group, same_way, other_way;   // same_way, other_way: per group (its first member)
    std::vector<uint8_t> same;   // per triangle: oriented as its group's first member
    if (!fill_checked(table, size, kEmpty, monitor) || !fill_checked(group, n, 0u, monitor) ||
        !fill_checked(same_way, n, 0u, monitor) || !fill_checked(other_way, n, 0u, monitor) ||
        !fill_checked(same, n, uint8_t(0), monitor))
        return stopped;
    for (size_t i = 0; i < n; ++i) {
        if (monitor.stopped_at(i)) return stopped;
        const Tri s = sorted(tris[i]);
        uint64_t h = (uint64_t(s[0]) * 0x9E3779B97F4A7C15ull) ^ (uint64_t(s[1]) * 0xC2B2AE3D27D4EB4Full) ^
                     (uint64_t(s[2]) * 0x165667B19E3779F9ull);
        h ^= h >> 29;
        size_t slot = size_t(h) & (size - 1);
        while (table[slot] != kEmpty && sorted(tris[table[slot]]) != s) slot = (slot + 1) & (size - 1);
        if (table[slot] == kEmpty) table[slot] = uint32_t(i);
        const uint32_t g = table[slot];
        group[i] = g;
        same[i] = even(tris[i]) == even(tris[g]);
        (same[i] ? same_way : other_way)[g]++;
    }
    // keep the first member in each orientation that is kept, compacting `tris` in place (the
    // pass reads only its own triangle, at or after the write position)
    std::vector<uint8_t> kept_same, kept_other;
    if (!fill_checked(kept_same, n, uint8_t(0), monitor) || !fill_checked(kept_other, n, uint8_t(0), monitor)) return stopped;
    size_t kept = 0;
    for (size_t i = 0; i < n; ++i) {
        if (monitor.stopped_at(i)) return stopped;
        const uint32_t g = group[i];
        const bool keep_same = same_way[g] >= other_way[g], keep_other = other_way[g] >= same_way[g];
        uint8_t& done = same[i] ? kept_same[g] : kept_other[g];
        if ((same[i] ? keep_same : keep_other) && !done) {
            done = 1;
            tris[kept++] = tris[i];
        } else {
            ++counts.duplicate;
        }
    }
    tris.resize(kept);
    mesh.triangles = std::move(tris);
    return counts;
}

}  // namespace ca

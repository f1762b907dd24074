// union_find.h: disjoint sets with path halving; unite keeps the smaller root (deterministic).
#pragma once
#include "large_pages.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace ca {

struct UnionFind {
    std::vector<uint32_t> parent;
    explicit UnionFind(size_t n) {
        reserve_large(parent, n);
        for (size_t i = 0; i < n; ++i) parent.push_back(uint32_t(i));
    }
    uint32_t find(uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    bool unite(uint32_t a, uint32_t b) {
        a = find(a);
        b = find(b);
        if (a == b) return false;
        parent[std::max(a, b)] = std::min(a, b);
        return true;
    }
};

}  // namespace ca

// test_duplicates.cpp: weld_map against the brute-force rule (each vertex maps to the smallest
// index with equal coordinates, -0 equal to +0).
#include "duplicates.h"
#include "rng.h"
#include <doctest/doctest.h>

using namespace ca;

TEST_CASE("weld_map: the smallest index with equal coordinates, -0 and +0 equal") {
    Rng rng(3);
    std::vector<Vec3> v;
    for (int i = 0; i < 3000; ++i) {
        // coordinates from {-1, -0, +0, 0.5, 1}: many repeats, and signed zeros
        const double pick[5] = {-1.0, -0.0, 0.0, 0.5, 1.0};
        Vec3 p;
        for (int k = 0; k < 3; ++k) p[k] = pick[rng.below(5)];
        v.push_back(p);
    }
    const std::vector<uint32_t> weld = weld_map(v);
    REQUIRE(weld.size() == v.size());
    size_t wrong = 0, merged = 0;
    for (size_t i = 0; i < v.size(); ++i) {
        size_t first = i;
        for (size_t j = 0; j < i; ++j)
            if (v[j] == v[i]) { first = j; break; }
        wrong += weld[i] != first;
        merged += first != i;
    }
    CHECK(wrong == 0);
    CHECK(merged > 2800);   // 5^3 = 125 positions, only 64 distinct (the zeros coincide)
}

// test_kdtree.cpp: PointTree's bounded nearest search and its visiting radius search against
// the plain queries they replace.
#include "kdtree.h"
#include "rng.h"
#include <doctest/doctest.h>

#include <algorithm>

using namespace ca;

namespace {

std::vector<Vec3> random_points(Rng& rng, size_t n) {
    std::vector<Vec3> pts(n);
    for (Vec3& p : pts) p = Vec3(rng.uniform(), rng.uniform(), rng.uniform());
    return pts;
}

}  // namespace

TEST_CASE("kdtree: nearest_below finds nearest()'s squared distance when it lies below the bound") {
    Rng rng(7);
    const std::vector<Vec3> pts = random_points(rng, 3000);
    const PointTree tree(pts);
    int found = 0, missed = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 q(rng.uniform() * 1.4 - 0.2, rng.uniform() * 1.4 - 0.2, rng.uniform() * 1.4 - 0.2);
        size_t idx = 0, idx_b = 0;
        double d2 = 0, d2_b = 0;
        REQUIRE(tree.nearest(q, 1, &idx, &d2) == 1);
        const double bound2 = d2 * (0.5 + 1.5 * rng.uniform());   // below or above the nearest
        if (tree.nearest_below(q, bound2, &idx_b, &d2_b)) {
            ++found;
            CHECK(d2_b == d2);
            CHECK((pts[idx_b] - q).squaredNorm() == doctest::Approx(d2));
        } else {
            ++missed;
            CHECK(!(d2 < bound2));
        }
    }
    CHECK(found > 500);
    CHECK(missed > 500);
    const std::vector<Vec3> none;
    const PointTree empty(none);
    size_t idx;
    double d2;
    CHECK(!empty.nearest_below(Vec3(0, 0, 0), 1.0, &idx, &d2));
}

TEST_CASE("kdtree: for_each_within_squared visits within_squared's hits, in its order") {
    Rng rng(9);
    const std::vector<Vec3> pts = random_points(rng, 3000);
    const PointTree tree(pts);
    std::vector<std::pair<size_t, double>> hits;
    size_t total = 0;
    for (int i = 0; i < 300; ++i) {
        const Vec3 q(rng.uniform(), rng.uniform(), rng.uniform());
        const double r2 = 0.02 * rng.uniform();
        tree.within_squared(q, r2, hits);
        std::vector<size_t> visited;
        const size_t n = tree.for_each_within_squared(q, r2, [&](size_t j) { visited.push_back(j); });
        CHECK(n == hits.size());
        REQUIRE(visited.size() == hits.size());
        for (size_t k = 0; k < hits.size(); ++k) CHECK(visited[k] == hits[k].first);
        total += n;
    }
    CHECK(total > 3000);
}

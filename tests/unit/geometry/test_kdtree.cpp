// test_kdtree.cpp: the k-d tree's capped count within a radius and bounded nearest search against
// brute force (a point exactly on the radius counts; the cap stops the count), and the
// neighbourhood loop giving the same neighbourhoods on two threads as on one; the visiting radius
// search against the listing one it replaces.
#include "kdtree.h"
#include "point_winding.h"
#include "rng.h"
#include <doctest/doctest.h>

#include <algorithm>
#include <vector>

using namespace ca;

namespace {

std::vector<Vec3> random_points(size_t n, uint64_t seed) {
    Rng rng(seed);
    std::vector<Vec3> pts(n);
    for (Vec3& p : pts) p = Vec3(rng.uniform(), rng.uniform(), rng.uniform());
    return pts;
}

// Squared distance as the tree computes it (coordinate by coordinate, in order).
double dist2(const Vec3& a, const Vec3& b) {
    double s = 0;
    for (int d = 0; d < 3; ++d) s += (a[d] - b[d]) * (a[d] - b[d]);
    return s;
}

}  // namespace

TEST_CASE("kdtree: capped count within a radius and bounded nearest search match brute force") {
    const std::vector<Vec3> pts = random_points(3000, 11);
    const PointTree tree(pts);
    const std::vector<Vec3> queries = random_points(300, 12);
    for (const Vec3& q : queries) {
        const double r2 = 0.01;
        size_t within = 0;
        double nearest = std::numeric_limits<double>::infinity();
        for (const Vec3& p : pts) {
            within += dist2(p, q) <= r2;
            nearest = std::min(nearest, dist2(p, q));
        }
        CHECK(tree.count_within_squared(q, r2, 1000000) == within);
        CHECK(tree.count_within_squared(q, r2, 5) == std::min<size_t>(within, 5));
        CHECK(tree.count_within_squared(q, r2, 0) == 0);
        // a bound above the nearest gives its squared distance, one at or below it the bound
        CHECK(tree.nearest_squared_below(q, 2 * nearest + 1e-12) == nearest);
        CHECK(tree.nearest_squared_below(q, nearest) == nearest);
        CHECK(tree.nearest_squared_below(q, 0.5 * nearest) == 0.5 * nearest);
    }
    // a point exactly at the radius is counted
    const std::vector<Vec3> line = {Vec3(0, 0, 0), Vec3(0.5, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)};
    const PointTree small(line);
    CHECK(small.count_within_squared(Vec3(0, 0, 0), 1.0, 10) == 3);
    CHECK(small.count_within_squared(Vec3(0, 0, 0), 0.25, 10) == 2);
    const std::vector<Vec3> none;
    const PointTree empty(none);
    CHECK(empty.count_within_squared(Vec3(0, 0, 0), 1.0, 10) == 0);
    CHECK(empty.nearest_squared_below(Vec3(0, 0, 0), 3.0) == 3.0);
}

TEST_CASE("kdtree: the neighbourhood loop and the tangent-plane areas are the same on two threads") {
    const std::vector<Vec3> pts = random_points(2000, 21);
    const size_t k = 12;
    auto collect = [&](int threads) {
        std::vector<std::vector<size_t>> idx(pts.size());
        std::vector<std::vector<double>> d2(pts.size());
        for_each_neighbourhood(pts, k, [&](size_t i, const size_t* id, const double* d, size_t found) {
            idx[i].assign(id, id + found);
            d2[i].assign(d, d + found);
        }, threads);
        return std::make_pair(idx, d2);
    };
    const auto one = collect(1), two = collect(2), many = collect(7);
    CHECK(one.first == two.first);
    CHECK(one.second == two.second);
    CHECK(one.first == many.first);
    CHECK(one.first[0].size() == k + 1);
    std::vector<Vec3> normals(pts.size());
    Rng rng(22);
    for (Vec3& n : normals) n = Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5).normalized();
    CHECK(tangent_voronoi_areas(pts, normals, 20, 1) == tangent_voronoi_areas(pts, normals, 20, 2));
}

TEST_CASE("kdtree: for_each_within_squared visits within_squared's hits, in its order") {
    const std::vector<Vec3> pts = random_points(3000, 9);
    const PointTree tree(pts);
    const std::vector<Vec3> queries = random_points(300, 10);
    Rng rng(13);
    std::vector<std::pair<size_t, double>> hits;
    size_t total = 0;
    for (const Vec3& q : queries) {
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

// test_kdtree.cpp: the k-d trees against brute force: PointTree's capped count within a radius
// (a point exactly on the radius counts; the cap stops the count), its neighbourhood loop giving
// the same neighbourhoods on two threads as on one, and its visiting radius search against the
// listing one it replaces; PackedPointTree's bounded nearest search on random, gridded (ties on
// node boundaries), repeated and non-finite point sets, and its test whether a ball reaches a
// point (one exactly on a ball's sphere is not reached).
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

TEST_CASE("kdtree: capped count within a radius matches brute force") {
    const std::vector<Vec3> pts = random_points(3000, 11);
    const PointTree tree(pts);
    const std::vector<Vec3> queries = random_points(300, 12);
    for (const Vec3& q : queries) {
        const double r2 = 0.01;
        size_t within = 0;
        for (const Vec3& p : pts) within += dist2(p, q) <= r2;
        CHECK(tree.count_within_squared(q, r2, 1000000) == within);
        CHECK(tree.count_within_squared(q, r2, 5) == std::min<size_t>(within, 5));
        CHECK(tree.count_within_squared(q, r2, 0) == 0);
    }
    // a point exactly at the radius is counted
    const std::vector<Vec3> line = {Vec3(0, 0, 0), Vec3(0.5, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)};
    const PointTree small(line);
    CHECK(small.count_within_squared(Vec3(0, 0, 0), 1.0, 10) == 3);
    CHECK(small.count_within_squared(Vec3(0, 0, 0), 0.25, 10) == 2);
    const std::vector<Vec3> none;
    const PointTree empty(none);
    CHECK(empty.count_within_squared(Vec3(0, 0, 0), 1.0, 10) == 0);
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

namespace {

// PackedPointTree's bounded nearest search against a scan of all points, for every query point.
void check_nearest(const std::vector<Vec3>& pts, const std::vector<Vec3>& queries) {
    const PackedPointTree tree(pts);
    for (const Vec3& q : queries) {
        double nearest = std::numeric_limits<double>::infinity();
        for (const Vec3& p : pts) nearest = std::min(nearest, dist2(p, q));
        // a bound above the nearest gives its squared distance, one at or below it the bound
        CHECK(tree.nearest_squared_below(q, 2 * nearest + 1e-12) == nearest);
        // just above (the Voronoi clamp's bound): a point on its node's box side must not be pruned
        CHECK(tree.nearest_squared_below(q, nearest * (1 + 1e-9) + 1e-300) == nearest);
        CHECK(tree.nearest_squared_below(q, std::numeric_limits<double>::infinity()) == nearest);
        CHECK(tree.nearest_squared_below(q, nearest) == nearest);
        CHECK(tree.nearest_squared_below(q, 0.5 * nearest) == 0.5 * nearest);
    }
}

}  // namespace

TEST_CASE("kdtree: PackedPointTree's bounded nearest search matches brute force") {
    check_nearest(random_points(3000, 9), random_points(300, 10));
    // a grid queried at grid points, midpoints and outside: ties, points on the nodes' box sides
    std::vector<Vec3> grid;
    for (int x = 0; x < 12; ++x)
        for (int y = 0; y < 12; ++y)
            for (int z = 0; z < 12; ++z) grid.push_back(Vec3(x, y, z) * 0.125);
    check_nearest(grid, {Vec3(0, 0, 0), Vec3(0.5, 0.625, 0.75), Vec3(0.5625, 0.5625, 0.5625), Vec3(2, -1, 0.5)});
    // one position many times (a leaf larger than the leaf size), and a single point
    std::vector<Vec3> repeated(50, Vec3(0.25, 0.5, 0.75));
    repeated.push_back(Vec3(0, 0, 0));
    check_nearest(repeated, {Vec3(0.25, 0.5, 0.75), Vec3(0, 0, 0.1), Vec3(0.3, 0.5, 0.7)});
    check_nearest({Vec3(1, 2, 3)}, {Vec3(1, 2, 3), Vec3(0, 0, 0)});
    // an empty set gives the bound
    const PackedPointTree empty(std::vector<Vec3>{});
    CHECK(empty.nearest_squared_below(Vec3(0, 0, 0), 3.0) == 3.0);
    // a non-finite coordinate: one scanned leaf, still the nearest finite point's distance
    std::vector<Vec3> odd = random_points(40, 14);
    odd[7] = Vec3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t j = 0; j < odd.size(); ++j)
        if (j != 7) nearest = std::min(nearest, dist2(odd[j], Vec3(0.5, 0.5, 0.5)));
    CHECK(PackedPointTree(odd).nearest_squared_below(Vec3(0.5, 0.5, 0.5), 4.0) == nearest);
}

TEST_CASE("kdtree: PackedPointTree's reaches() matches a scan of the balls") {
    Rng rng(15);
    std::vector<Vec3> centers = random_points(2000, 16);
    std::vector<double> reach2(centers.size());
    // mostly small balls, a few large ones (a node's largest reach is what prunes)
    for (double& r2 : reach2) r2 = rng.uniform() < 0.01 ? 0.05 * rng.uniform() : 1e-4 * rng.uniform();
    const PackedPointTree tree(centers, reach2);
    const std::vector<Vec3> queries = random_points(1000, 17);
    size_t hits = 0;
    for (const Vec3& q : queries) {
        bool any = false;
        for (size_t i = 0; i < centers.size(); ++i) any = any || dist2(q, centers[i]) < reach2[i];
        CHECK(tree.reaches(q) == any);
        hits += any;
    }
    CHECK(hits > 50);
    CHECK(hits < 950);
    // a query exactly on a ball's sphere is not reached; without reaches nothing is
    const std::vector<Vec3> one = {Vec3(0, 0, 0), Vec3(3, 0, 0)};
    const PackedPointTree ball(one, {1.0, 0.25});
    CHECK(!ball.reaches(Vec3(1, 0, 0)));
    CHECK(ball.reaches(Vec3(0.5, 0.5, 0)));
    CHECK(ball.reaches(Vec3(2.75, 0, 0)));
    CHECK(!ball.reaches(Vec3(2.5, 0, 0)));
    CHECK(!PackedPointTree(one).reaches(Vec3(0, 0, 0)));
}

// test_weighted_cover.cpp: the weighted set cover with at most K columns (lib/cover/weighted_cover.h)
// against brute force over every subset on small random instances: the answer covers every row,
// has at most K columns, costs what its columns cost, and the lower bound lies at or below the
// true optimum, which lies at or below the answer. Bad problems fail with a clear status.
#include <doctest/doctest.h>

#include "weighted_cover.h"

#include <random>

TEST_CASE("weighted cover: feasible, within K, bound <= optimum <= answer (brute force)") {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(0, 1);
    int optimal_found = 0;
    for (int trial = 0; trial < 60; ++trial) {
        ca::WeightedCoverProblem P;
        P.rows = 6 + uint32_t(trial % 6);
        const size_t C = 10 + size_t(trial % 5);
        P.max_columns = 1 + size_t(trial % 4);
        std::vector<std::vector<uint32_t>> cols(C);
        for (size_t j = 0; j < C; ++j) {
            for (uint32_t r = 0; r < P.rows; ++r)
                if (u(rng) < 0.35) cols[j].push_back(r);
            P.cost.push_back(double(cols[j].size()) * u(rng) + (u(rng) < 0.2 ? 0.0 : u(rng)));
        }
        // one column holds everything (feasible for every K), dear
        cols.push_back({});
        for (uint32_t r = 0; r < P.rows; ++r) cols.back().push_back(r);
        P.cost.push_back(double(P.rows) * 2);
        for (const auto& c : cols) {
            P.idx.insert(P.idx.end(), c.begin(), c.end());
            P.ptr.push_back(uint32_t(P.idx.size()));
        }
        // brute force
        double optimum = 1e300;
        for (uint32_t mask = 1; mask < (1u << cols.size()); ++mask) {
            if (size_t(__builtin_popcount(mask)) > P.max_columns) continue;
            std::vector<uint8_t> covered(P.rows, 0);
            double cost = 0;
            for (size_t j = 0; j < cols.size(); ++j)
                if (mask >> j & 1) {
                    cost += P.cost[j];
                    for (uint32_t r : cols[j]) covered[r] = 1;
                }
            if (std::all_of(covered.begin(), covered.end(), [](uint8_t v) { return v != 0; })) optimum = std::min(optimum, cost);
        }
        ca::WeightedCoverResult res;
        REQUIRE(ca::solve_weighted_cover(P, ca::WeightedCoverOptions{}, ca::Monitor{}, res).ok());
        CAPTURE(trial);
        CHECK(res.selected.size() <= P.max_columns);
        std::vector<uint8_t> covered(P.rows, 0);
        double cost = 0;
        for (uint32_t j : res.selected) {
            cost += P.cost[j];
            for (uint32_t r : cols[j]) covered[r] = 1;
        }
        CHECK(std::all_of(covered.begin(), covered.end(), [](uint8_t v) { return v != 0; }));
        CHECK(cost == doctest::Approx(res.objective));
        CHECK(res.lower_bound <= optimum + 1e-9);
        CHECK(optimum <= res.objective + 1e-9);
        optimal_found += res.objective <= optimum + 1e-9;
        if (res.proven_optimal) CHECK(res.objective <= optimum + 1e-9);
    }
    // the heuristics and CBC find the optimum on most of these small instances
    CHECK(optimal_found >= 50);
}

TEST_CASE("weighted cover: bad problems fail with a clear status") {
    ca::WeightedCoverProblem P;
    P.rows = 2;
    P.idx = {0, 1};
    P.ptr = {0, 1, 2};
    P.cost = {1.0, 1.0};
    P.max_columns = 0;
    ca::WeightedCoverResult r;
    CHECK(ca::solve_weighted_cover(P, {}, ca::Monitor{}, r).code == ca::Code::invalid_argument);
    P.max_columns = 2;
    P.cost[1] = -1;
    CHECK(ca::solve_weighted_cover(P, {}, ca::Monitor{}, r).code == ca::Code::invalid_argument);
    P.cost[1] = 1;
    P.idx[1] = 5;
    CHECK(ca::solve_weighted_cover(P, {}, ca::Monitor{}, r).code == ca::Code::invalid_argument);
    P.idx[1] = 0;  // row 1 covered by nothing
    CHECK(ca::solve_weighted_cover(P, {}, ca::Monitor{}, r).code == ca::Code::uncoverable);
    P.idx = {0, 1};
    P.max_columns = 1;  // two columns needed, one allowed
    CHECK(ca::solve_weighted_cover(P, {}, ca::Monitor{}, r).code == ca::Code::uncoverable);
    P.max_columns = 2;
    REQUIRE(ca::solve_weighted_cover(P, {}, ca::Monitor{}, r).ok());
    CHECK(r.selected.size() == 2);
    CHECK(r.objective == 2.0);
}

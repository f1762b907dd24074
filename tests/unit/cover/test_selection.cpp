// test_selection.cpp: the selection extensions against brute force on small geometric
// instances: target size (result <= K, a slightly smaller dilation needs more balls), kernel
// decomposition into components (same optimum), divide and conquer (valid cover, honest bound),
// and the anytime behaviour of a time-limited exact solve.
#include <doctest/doctest.h>

#include "selection.h"
#include "rng.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

using namespace ca;

namespace {

// Samples on a unit-ish sphere shell, balls inside, radii to the nearest sample scaled down.
CandidateSet random_set(Rng& rng, size_t m, size_t n) {
    CandidateSet set;
    for (size_t j = 0; j < m; ++j) {
        Vec3 p(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
        set.cover_samples.push_back(Vec3(0.5, 0.5, 0.5) + 0.45 * p.normalized());
    }
    for (size_t i = 0; i < n; ++i) {
        Vec3 p(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
        Ball b;
        b.center = Vec3(0.5, 0.5, 0.5) + (0.3 + 0.1 * rng.uniform()) * p.normalized();
        double d = 1e9;
        for (const Vec3& s : set.cover_samples) d = std::min(d, (s - b.center).norm());
        b.radius = d;
        set.balls.push_back(b);
    }
    return set;
}

// Smallest number of balls covering every sample at the given offset (m <= 64, n <= 20);
// a large number when no subset covers.
int brute_min(const CandidateSet& set, double delta) {
    const size_t m = set.cover_samples.size(), n = set.balls.size();
    std::vector<uint64_t> mask(n, 0);
    for (size_t i = 0; i < n; ++i)
        for (size_t j = 0; j < m; ++j)
            if ((set.cover_samples[j] - set.balls[i].center).norm() <= set.balls[i].radius + delta * (1 - 1e-9))
                mask[i] |= uint64_t(1) << j;
    const uint64_t all = m == 64 ? ~uint64_t(0) : (uint64_t(1) << m) - 1;
    int best = 1000;
    for (uint32_t s = 0; s < (1u << n); ++s) {
        const int cnt = __builtin_popcount(s);
        if (cnt >= best) continue;
        uint64_t u = 0;
        for (size_t i = 0; i < n; ++i)
            if (s >> i & 1) u |= mask[i];
        if (u == all) best = cnt;
    }
    return best;
}

bool covers_all(const CandidateSet& set, const Selection& sel) {
    for (const Vec3& s : set.cover_samples) {
        bool ok = false;
        for (size_t k = 0; k < sel.indices.size() && !ok; ++k)
            ok = (s - set.balls[sel.indices[k]].center).norm() <= sel.dilated_radii[k] * (1 + 1e-9);
        if (!ok) return false;
    }
    return true;
}

}  // namespace

TEST_CASE("selection: target size gives <= K balls at a dilation just above the smallest one") {
    for (uint64_t seed = 1; seed <= 4; ++seed) {
        Rng rng(seed);
        const CandidateSet set = random_set(rng, 40, 14);
        for (uint32_t K : {2u, 4u}) {
            SelectOptions o;
            o.target_count = K;
            o.target_tolerance = 1e-4;
            Selection sel;
            REQUIRE(select_balls(set, o, Monitor{}, sel).ok());
            CHECK(sel.indices.size() <= K);
            CHECK(sel.cover.proven_optimal == 1);
            CHECK(covers_all(set, sel));
            CHECK(brute_min(set, sel.delta) <= int(K));
            if (sel.delta > 2e-4) CHECK(brute_min(set, sel.delta - 2e-4) > int(K));
            CHECK(sel.probes > 2);
        }
    }
}

TEST_CASE("selection: target size with the scale dilation") {
    Rng rng(7);
    const CandidateSet set = random_set(rng, 30, 12);
    SelectOptions o;
    o.dilation = Dilation::scale;
    o.scale = 1.0;
    o.target_count = 3;
    o.target_tolerance = 1e-3;
    Selection sel;
    REQUIRE(select_balls(set, o, Monitor{}, sel).ok());
    CHECK(sel.indices.size() <= 3);
    CHECK(sel.scale >= 1.0);
    CHECK(sel.delta == 0);
    CHECK(covers_all(set, sel));
    SelectOptions smaller = o;
    smaller.target_count = 0;
    smaller.scale = sel.scale - 2e-3;
    smaller.skip_uncoverable = false;
    Selection s2;
    const Status st = select_balls(set, smaller, Monitor{}, s2);
    if (st.ok()) CHECK(s2.indices.size() > 3);  // otherwise: uncoverable, i.e. more than 3 balls too
}

TEST_CASE("selection: components of the kernel are solved separately with the same optimum") {
    // Two far-apart clusters of samples and balls: the kernel splits.
    int runs = 0;
    for (uint64_t seed = 1; seed <= 5; ++seed) {
        Rng rng(seed);
        CandidateSet a = random_set(rng, 20, 9), b = random_set(rng, 20, 9);
        CandidateSet set = a;
        for (const Vec3& s : b.cover_samples) set.cover_samples.push_back(s + Vec3(3, 0, 0));
        for (Ball x : b.balls) { x.center += Vec3(3, 0, 0); set.balls.push_back(x); }
        const int oa = brute_min(a, 0.3), ob = brute_min(b, 0.3);
        if (oa >= 1000 || ob >= 1000) continue;
        ++runs;
        SelectOptions o;
        o.delta = 0.3;
        Selection sel;
        REQUIRE(select_balls(set, o, Monitor{}, sel).ok());
        CHECK(sel.cover.proven_optimal == 1);
        CHECK(int(sel.indices.size()) == oa + ob);
        CHECK(covers_all(set, sel));
        if (sel.cover.rows_after > 0) CHECK(sel.cover.components >= 1);
    }
    CHECK(runs >= 3);
}

TEST_CASE("selection: divide and conquer gives a valid cover and an honest bound") {
    int split_runs = 0;
    for (uint64_t seed = 1; seed <= 6; ++seed) {
        Rng rng(seed);
        const CandidateSet set = random_set(rng, 48, 16);
        for (Solver solver : {Solver::exact, Solver::greedy}) {
            SelectOptions o;
            o.delta = 0.2;
            o.dc_threshold = 10;
            o.dc_part_samples = 12;
            o.cover.solver = solver;
            Selection sel;
            const Status st = select_balls(set, o, Monitor{}, sel);
            const int opt = brute_min(set, 0.2);
            if (opt >= 1000) { CHECK(st.code == Code::uncoverable); continue; }
            REQUIRE(st.ok());
            CHECK(sel.parts == 4);
            CHECK(covers_all(set, sel));
            CHECK(sel.cover.lower_bound <= sel.cover.objective);
            CHECK(sel.cover.lower_bound <= double(opt));
            CHECK(sel.cover.objective >= double(opt));
            if (sel.cover.proven_optimal) CHECK(sel.cover.objective == double(opt));
            ++split_runs;
        }
    }
    CHECK(split_runs > 4);
}

TEST_CASE("selection: a time-limited exact solve returns at once with a valid cover, never worse than greedy") {
    // Dense random coverage: hard enough that a 20 ms budget cannot prove optimality.
    Rng rng(3);
    Coverage cov;
    const size_t m = 400, n = 800;
    cov.n_samples = m;
    cov.n_balls = n;
    cov.ball_ptr.push_back(0);
    for (size_t i = 0; i < n; ++i) {
        for (size_t j = 0; j < m; ++j)
            if (rng.uniform() < 0.03) cov.ball_samples.push_back(uint32_t(j));
        cov.ball_ptr.push_back(uint32_t(cov.ball_samples.size()));
    }
    cov.build_transpose();
    for (size_t j = 0; j < m; ++j) REQUIRE(cov.sample_ptr[j + 1] > cov.sample_ptr[j]);
    CoverOptions g;
    g.solver = Solver::greedy;
    CoverResult greedy;
    REQUIRE(solve_set_cover(cov, g, false, Monitor{}, greedy).ok());
    CoverOptions o;
    o.time_limit_s = 0.02;
    CoverResult r;
    const auto t0 = std::chrono::steady_clock::now();
    REQUIRE(solve_set_cover(cov, o, false, Monitor{}, r).ok());
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    CHECK(secs < 2.0);  // CBC may overshoot a little (first LP); never by seconds here
    CHECK(r.objective <= greedy.objective);
    CHECK(r.lower_bound <= r.objective);
    CHECK(r.lower_bound > 0);
    CHECK(r.gap == doctest::Approx((r.objective - r.lower_bound) / r.objective));
    std::vector<uint8_t> hit(m, 0);
    for (uint32_t a : r.selected)
        for (uint32_t k = cov.ball_ptr[a]; k < cov.ball_ptr[a + 1]; ++k) hit[cov.ball_samples[k]] = 1;
    CHECK(std::count(hit.begin(), hit.end(), 0) == 0);
}

// test_setcover.cpp: the coverage relation (vs brute-force distances) and the set-cover solver
// (vs an independent brute-force minimum on small random instances): exactness, reduction
// soundness, heuristics' validity, masks, uncoverable samples, time limits, cancellation.
#include <doctest/doctest.h>

#include "coverage.h"
#include "parallel.h"
#include "setcover.h"
#include "setcover_internal.h"
#include "rng.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <thread>
#include <vector>

#if defined(__unix__)
#include <unistd.h>
#endif

using namespace ca;

namespace {

// Random coverage: ball i covers sample j with probability p; every sample gets at least one
// ball unless `allow_uncovered`.
Coverage random_cover(Rng& rng, size_t m, size_t n, double p, bool allow_uncovered = false) {
    std::vector<std::vector<uint32_t>> lists(n);
    std::vector<uint8_t> hit(m, 0);
    for (size_t i = 0; i < n; ++i)
        for (size_t j = 0; j < m; ++j)
            if (rng.uniform() < p) { lists[i].push_back(uint32_t(j)); hit[j] = 1; }
    if (!allow_uncovered)
        for (size_t j = 0; j < m; ++j)
            if (!hit[j]) {
                auto& l = lists[rng.below(n)];
                l.insert(std::upper_bound(l.begin(), l.end(), uint32_t(j)), uint32_t(j));
            }
    Coverage c;
    c.n_samples = m;
    c.n_balls = n;
    c.ball_ptr.push_back(0);
    for (auto& l : lists) {
        c.ball_samples.insert(c.ball_samples.end(), l.begin(), l.end());
        c.ball_ptr.push_back(uint32_t(c.ball_samples.size()));
    }
    c.build_transpose();
    return c;
}

uint32_t ball_mask(const Coverage& c, size_t i) {
    uint32_t mask = 0;
    for (uint32_t k = c.ball_ptr[i]; k < c.ball_ptr[i + 1]; ++k) mask |= 1u << c.ball_samples[k];
    return mask;
}

// Independent brute force (m <= 31): smallest number of allowed balls, including every forced_in
// one, covering every required sample; -1 if infeasible. Subsets by increasing size.
int brute_min(const Coverage& c, const std::vector<uint8_t>& ignorable = {},
              const std::vector<uint8_t>& forced_in = {}, const std::vector<uint8_t>& forced_out = {}) {
    uint32_t need = 0;
    for (size_t j = 0; j < c.n_samples; ++j)
        if (ignorable.empty() || !ignorable[j]) need |= 1u << j;
    uint32_t base = 0;
    int nforced = 0;
    std::vector<uint32_t> free;
    for (size_t i = 0; i < c.n_balls; ++i) {
        if (!forced_in.empty() && forced_in[i]) { base |= ball_mask(c, i); ++nforced; continue; }
        if (!forced_out.empty() && forced_out[i]) continue;
        free.push_back(ball_mask(c, i));
    }
    const int F = int(free.size());
    for (int k = 0; k <= F; ++k) {
        // enumerate k-subsets of free
        std::vector<int> idx(k);
        for (int t = 0; t < k; ++t) idx[t] = t;
        for (;;) {
            uint32_t m = base;
            for (int t = 0; t < k; ++t) m |= free[idx[t]];
            if ((m & need) == need) return nforced + k;
            int t = k - 1;
            while (t >= 0 && idx[t] == F - k + t) --t;
            if (t < 0) break;
            ++idx[t];
            for (int u = t + 1; u < k; ++u) idx[u] = idx[u - 1] + 1;
        }
    }
    return -1;
}

bool valid_cover(const Coverage& c, const std::vector<uint32_t>& sel, const std::vector<uint8_t>& ignorable = {},
                 const std::vector<uint32_t>& also_ignored = {}) {
    std::vector<uint8_t> cov(c.n_samples, 0);
    for (uint32_t a : sel) {
        if (a >= c.n_balls) return false;
        for (uint32_t k = c.ball_ptr[a]; k < c.ball_ptr[a + 1]; ++k) cov[c.ball_samples[k]] = 1;
    }
    for (uint32_t j : also_ignored) cov[j] = 1;
    for (size_t j = 0; j < c.n_samples; ++j)
        if (!cov[j] && (ignorable.empty() || !ignorable[j])) return false;
    return std::is_sorted(sel.begin(), sel.end()) && std::adjacent_find(sel.begin(), sel.end()) == sel.end();
}

// Two or three odd cycles (3, 5 or 7 rows, each column two neighbouring rows) and a few random
// columns of three rows: an odd cycle's LP is half its length, one ball below its minimum, so
// solvers must branch (or cut) to reach the optimum. Up to 21 rows, for the brute force.
Coverage odd_cycles(Rng& rng) {
    std::vector<std::vector<uint32_t>> cols;
    uint32_t rows = 0;
    for (int k = 0, cycles = 2 + int(rng.below(2)); k < cycles; ++k) {
        const uint32_t len = 3 + 2 * uint32_t(rng.below(3));
        for (uint32_t i = 0; i < len; ++i) cols.push_back({rows + i, rows + (i + 1) % len});
        rows += len;
    }
    for (int e = 0, extra = int(rng.below(4)); e < extra; ++e)
        cols.push_back({uint32_t(rng.below(rows)), uint32_t(rng.below(rows)), uint32_t(rng.below(rows))});
    Coverage c;
    c.n_samples = rows;
    c.n_balls = cols.size();
    c.ball_ptr.push_back(0);
    for (auto& l : cols) {
        std::sort(l.begin(), l.end());
        l.erase(std::unique(l.begin(), l.end()), l.end());
        c.ball_samples.insert(c.ball_samples.end(), l.begin(), l.end());
        c.ball_ptr.push_back(uint32_t(c.ball_samples.size()));
    }
    c.build_transpose();
    return c;
}

struct Instance {
    Coverage cov;
    std::vector<Vec3> centers;
    std::vector<double> radii;
};

// A few hundred small instances of several sizes and densities, fixed seeds.
std::vector<Instance> small_instances(uint64_t seed, int count) {
    Rng rng(seed);
    const double dens[] = {0.08, 0.15, 0.25, 0.4};
    std::vector<Instance> out;
    for (int t = 0; t < count; ++t) {
        const size_t m = 12 + rng.below(9), n = 10 + rng.below(9);
        Instance in;
        in.cov = random_cover(rng, m, n, dens[t % 4]);
        for (size_t i = 0; i < n; ++i) {
            in.centers.emplace_back(rng.uniform(), rng.uniform(), rng.uniform());
            in.radii.push_back(0.05 + rng.uniform());
        }
        out.push_back(std::move(in));
    }
    return out;
}

}  // namespace

TEST_CASE("set cover: exact equals the brute-force minimum and is proven optimal") {
    const auto insts = small_instances(1234, 320);
    int nontrivial = 0;
    for (size_t t = 0; t < insts.size(); ++t) {
        const Coverage& c = insts[t].cov;
        const int best = brute_min(c);
        REQUIRE(best >= 0);
        CoverOptions opt;
        opt.effort = Effort::prove;
        CoverResult res;
        Status st = solve_set_cover(c, opt, false, Monitor{}, res);
        INFO("instance " << t << " m=" << c.n_samples << " n=" << c.n_balls);
        REQUIRE(st.ok());
        CHECK(valid_cover(c, res.selected));
        CHECK(res.objective == double(res.selected.size()));
        CHECK(int(res.objective) == best);
        CHECK(res.proven_optimal == 1);
        CHECK(res.lower_bound == res.objective);
        CHECK(res.gap == 0.0);
        CHECK(res.rows_before == c.n_samples);
        CHECK(res.cols_before == c.n_balls);
        CHECK(res.rows_after <= res.rows_before);
        CHECK(res.cols_after <= res.cols_before);
        if (res.cols_after > 0) ++nontrivial;
    }
    CHECK(nontrivial > 20);  // the kernel (and so CBC) is exercised, not only the reduction
}

TEST_CASE("set cover: give_up_above decides as the full solve does, and stops early only above it") {
    const auto insts = small_instances(4321, 160);
    int gave_up = 0;
    for (size_t t = 0; t < insts.size(); ++t) {
        const Coverage& c = insts[t].cov;
        const int best = brute_min(c);
        REQUIRE(best >= 0);
        CoverOptions opt;
        opt.effort = Effort::prove;
        CoverResult full;
        REQUIRE(solve_set_cover(c, opt, false, Monitor{}, full).ok());
        for (int n = 1; n <= best + 1; ++n) {
            INFO("instance " << t << " minimum " << best << " give_up_above " << n);
            CoverOptions o = opt;
            o.give_up_above = uint32_t(n);
            CoverResult res;
            REQUIRE(solve_set_cover(c, o, false, Monitor{}, res).ok());
            CHECK(valid_cover(c, res.selected));
            CHECK(res.lower_bound <= double(best));  // a valid bound, stopped or not
            if (best <= n) {
                // nothing to give up: the same solve as without the option
                CHECK(res.selected == full.selected);
                CHECK(res.proven_optimal == 1);
            } else {
                // the decision: more than n balls, shown by the bound
                CHECK(res.objective > double(n));
                CHECK(res.lower_bound > double(n));
                gave_up += res.proven_optimal == 0;
            }
        }
    }
    CHECK(gave_up > 20);  // the solve does stop before its proof
}

TEST_CASE("set cover: row generation equals the brute-force minimum and the one-ILP path") {
    // 32 x 30 at density 0.3: about a fifth of these keep a kernel that neither the LP bound nor
    // the branching step closes, so the row-generation loop runs (several rounds each).
    Rng rng(4242);
    int with_rowgen = 0;
    for (int t = 0; t < 60; ++t) {
        const Coverage c = random_cover(rng, 32, 30, 0.3);
        const int best = brute_min(c);
        REQUIRE(best >= 0);
        CoverOptions opt;
        opt.effort = Effort::prove;  // row generation is part of the proving path
        opt.row_generation = true;
        CoverResult rg, one;
        REQUIRE(solve_set_cover(c, opt, false, Monitor{}, rg).ok());
        opt.row_generation = false;
        REQUIRE(solve_set_cover(c, opt, false, Monitor{}, one).ok());
        INFO("instance " << t << " rounds " << rg.rowgen_rounds);
        CHECK(valid_cover(c, rg.selected));
        CHECK(int(rg.objective) == best);
        CHECK(rg.proven_optimal == 1);
        CHECK(rg.lower_bound == rg.objective);
        CHECK(int(one.objective) == best);
        CHECK(one.proven_optimal == 1);
        CHECK(one.rowgen_rounds == 0);
        if (rg.rowgen_rounds > 0) ++with_rowgen;
    }
    CHECK(with_rowgen >= 8);
}

TEST_CASE("set cover: row generation over several rounds stays exact") {
    // Larger instances (no brute force): the row-generation path must match the one-ILP path,
    // both proven, and some must need several rounds (sub-optima that miss kernel rows).
    Rng rng(77);
    int multi = 0;
    for (int t = 0; t < 12; ++t) {
        const Coverage c = random_cover(rng, 70, 60, 0.1);
        CoverOptions opt;
        opt.effort = Effort::prove;  // row generation is part of the proving path
        opt.row_generation = true;
        CoverResult rg, one;
        REQUIRE(solve_set_cover(c, opt, false, Monitor{}, rg).ok());
        opt.row_generation = false;
        REQUIRE(solve_set_cover(c, opt, false, Monitor{}, one).ok());
        INFO("instance " << t << " rounds " << rg.rowgen_rounds);
        CHECK(valid_cover(c, rg.selected));
        CHECK(rg.proven_optimal == 1);
        CHECK(one.proven_optimal == 1);
        CHECK(rg.objective == one.objective);
        CHECK(rg.lower_bound == rg.objective);
        if (rg.rowgen_rounds >= 3) ++multi;
    }
    CHECK(multi >= 3);
}

TEST_CASE("set cover: the reduction alone keeps the optimum") {
    const auto insts = small_instances(99, 320);
    for (size_t t = 0; t < insts.size(); ++t) {
        const Coverage& c = insts[t].cov;
        std::vector<uint32_t> forced, kb, ks;
        Coverage ker;
        REQUIRE(detail::reduce_set_cover(c, CoverOptions{}, false, Monitor{}, forced, ker, kb, ks).ok());
        INFO("instance " << t);
        REQUIRE(ker.n_balls == kb.size());
        REQUIRE(ker.n_samples == ks.size());
        const int kopt = ker.n_samples == 0 ? 0 : brute_min(ker);
        REQUIRE(kopt >= 0);
        CHECK(int(forced.size()) + kopt == brute_min(c));
        // kernel balls keep their samples (restricted to kernel rows)
        for (size_t a = 0; a < ker.n_balls; ++a)
            for (uint32_t k = ker.ball_ptr[a]; k < ker.ball_ptr[a + 1]; ++k) {
                const uint32_t j = ks[ker.ball_samples[k]];
                const uint32_t* b0 = &c.ball_samples[c.ball_ptr[kb[a]]];
                const uint32_t* b1 = b0 + (c.ball_ptr[kb[a] + 1] - c.ball_ptr[kb[a]]);
                CHECK(std::binary_search(b0, b1, j));
            }
        // forced balls plus any kernel cover (here: all kernel balls) cover the original
        std::vector<uint32_t> sel = forced;
        sel.insert(sel.end(), kb.begin(), kb.end());
        std::sort(sel.begin(), sel.end());
        CHECK(valid_cover(c, sel));
        std::set<uint32_t> fs(forced.begin(), forced.end()), ks2(kb.begin(), kb.end());
        for (uint32_t f : forced) CHECK(ks2.count(f) == 0);
    }
}

TEST_CASE("set cover: greedy and capp give valid covers with valid bounds") {
    const auto insts = small_instances(777, 240);
    for (size_t t = 0; t < insts.size(); ++t) {
        const Instance& in = insts[t];
        const int best = brute_min(in.cov);
        for (Solver s : {Solver::greedy, Solver::capp}) {
            CoverOptions opt;
            opt.solver = s;
            opt.centers = &in.centers;
            opt.radii = &in.radii;
            CoverResult res;
            INFO("instance " << t << " solver " << int(s));
            REQUIRE(solve_set_cover(in.cov, opt, false, Monitor{}, res).ok());
            CHECK(valid_cover(in.cov, res.selected));
            CHECK(res.objective >= best);
            CHECK(res.lower_bound <= best);
            CHECK(res.lower_bound >= 0);
            CHECK(res.proven_optimal == 0);
            CHECK(res.gap >= 0.0);
            CHECK(res.gap <= 1.0);
            // redundancy removal: no selected ball can be dropped
            for (size_t k = 0; k < res.selected.size(); ++k) {
                std::vector<uint32_t> less = res.selected;
                less.erase(less.begin() + long(k));
                CHECK_FALSE(valid_cover(in.cov, less));
            }
            // deterministic
            CoverResult again;
            REQUIRE(solve_set_cover(in.cov, opt, false, Monitor{}, again).ok());
            CHECK(again.selected == res.selected);
        }
    }
}

TEST_CASE("set cover: capp needs centres and radii") {
    Rng rng(5);
    Coverage c = random_cover(rng, 10, 8, 0.3);
    CoverOptions opt;
    opt.solver = Solver::capp;
    CoverResult res;
    CHECK(solve_set_cover(c, opt, false, Monitor{}, res).code == Code::invalid_argument);
    std::vector<Vec3> centers(7, Vec3::Zero());
    std::vector<double> radii(7, 1.0);
    opt.centers = &centers;
    opt.radii = &radii;
    CHECK(solve_set_cover(c, opt, false, Monitor{}, res).code == Code::invalid_argument);  // wrong size
}

TEST_CASE("set cover: ignorable samples, forced_in and forced_out are honoured") {
    Rng rng(4242);
    int checked = 0;
    for (int t = 0; t < 200; ++t) {
        const size_t m = 12 + rng.below(7), n = 10 + rng.below(7);
        Coverage c = random_cover(rng, m, n, 0.2 + 0.2 * rng.uniform());
        std::vector<uint8_t> ign(m, 0), fin(n, 0), fout(n, 0);
        for (auto& v : ign) v = rng.uniform() < 0.2;
        for (size_t i = 0; i < n; ++i) {
            const double u = rng.uniform();
            if (u < 0.12) fin[i] = 1;
            else if (u < 0.35) fout[i] = 1;
        }
        const int best = brute_min(c, ign, fin, fout);
        for (Solver s : {Solver::exact, Solver::greedy}) {
            CoverOptions opt;
            opt.solver = s;
            opt.ignorable_samples = ign;
            opt.forced_in = fin;
            opt.forced_out = fout;
            CoverResult res;
            Status st = solve_set_cover(c, opt, false, Monitor{}, res);
            INFO("instance " << t << " solver " << int(s));
            if (best < 0) {
                CHECK(st.code == Code::uncoverable);
                continue;
            }
            REQUIRE(st.ok());
            ++checked;
            CHECK(valid_cover(c, res.selected, ign));
            for (size_t i = 0; i < n; ++i) {
                const bool in = std::binary_search(res.selected.begin(), res.selected.end(), uint32_t(i));
                if (fin[i]) CHECK(in);
                if (fout[i]) CHECK_FALSE(in);
            }
            CHECK(res.lower_bound <= best);
            if (s == Solver::exact) {
                CHECK(int(res.objective) == best);
                CHECK(res.proven_optimal == 1);
            } else {
                CHECK(res.objective >= best);
            }
        }
    }
    CHECK(checked > 150);

    // A sample covered only by a forced-out ball is fine when ignorable.
    Coverage c;
    c.n_samples = 3;
    c.n_balls = 2;
    c.ball_ptr = {0, 2, 3};
    c.ball_samples = {0, 1, 2};
    c.build_transpose();
    CoverOptions opt;
    opt.forced_out = {1, 0};
    CoverResult res;
    CHECK(solve_set_cover(c, opt, false, Monitor{}, res).code == Code::uncoverable);
    opt.ignorable_samples = {1, 1, 0};
    REQUIRE(solve_set_cover(c, opt, false, Monitor{}, res).ok());
    CHECK(res.selected == std::vector<uint32_t>{1});
    // a ball both forced in and forced out, or masks of the wrong size, are rejected
    opt.forced_in = {0, 1};
    opt.forced_out = {0, 1};
    CHECK(solve_set_cover(c, opt, false, Monitor{}, res).code == Code::invalid_argument);
    opt.forced_in = {1};
    opt.forced_out.clear();
    CHECK(solve_set_cover(c, opt, false, Monitor{}, res).code == Code::invalid_argument);
    opt.forced_in.clear();
    opt.ignorable_samples = {0, 0};
    CHECK(solve_set_cover(c, opt, false, Monitor{}, res).code == Code::invalid_argument);
}

TEST_CASE("set cover: uncoverable samples are reported, or skipped on request") {
    Rng rng(31);
    for (size_t n_unc : {size_t(3), size_t(12)}) {
        const size_t m = 40, n = 30;
        Coverage c = random_cover(rng, m, n, 0.1);
        // remove samples 5, 8, ... from every ball
        std::vector<uint32_t> unc;
        for (size_t k = 0; k < n_unc; ++k) unc.push_back(uint32_t(5 + 3 * k) % uint32_t(m));
        std::sort(unc.begin(), unc.end());
        Coverage d;
        d.n_samples = m;
        d.n_balls = n;
        d.ball_ptr.push_back(0);
        for (size_t a = 0; a < n; ++a) {
            for (uint32_t k = c.ball_ptr[a]; k < c.ball_ptr[a + 1]; ++k)
                if (!std::binary_search(unc.begin(), unc.end(), c.ball_samples[k])) d.ball_samples.push_back(c.ball_samples[k]);
            d.ball_ptr.push_back(uint32_t(d.ball_samples.size()));
        }
        d.build_transpose();
        CoverResult res;
        Status st = solve_set_cover(d, CoverOptions{}, false, Monitor{}, res);
        CHECK(st.code == Code::uncoverable);
        const std::string head = std::to_string(n_unc) + " of " + std::to_string(m) + " samples are covered by no candidate ball (first: ";
        CHECK(st.message.rfind(head, 0) == 0);
        CHECK(st.message.find(std::to_string(unc[0]) + ", " + std::to_string(unc[1])) != std::string::npos);
        CHECK((st.message.find(", ...)") != std::string::npos) == (n_unc > 10));
        st = solve_set_cover(d, CoverOptions{}, true, Monitor{}, res);
        REQUIRE(st.ok());
        CHECK(res.uncovered == unc);
        CHECK(valid_cover(d, res.selected, {}, unc));
        CHECK(res.rows_before == m - n_unc);
    }
}

TEST_CASE("set cover: a time-limited solve returns a valid cover and an honest bound") {
    Rng rng(2024);
    Coverage c = random_cover(rng, 300, 2000, 0.03);
    CoverOptions opt;
    opt.time_limit_s = 0.05;
    CoverResult res;
    REQUIRE(solve_set_cover(c, opt, false, Monitor{}, res).ok());
    CHECK(valid_cover(c, res.selected));
    CHECK(res.lower_bound <= res.objective);
    CHECK(res.lower_bound >= 1);
    CHECK(res.gap >= 0.0);
    CHECK(res.gap < 1.0);
    if (res.proven_optimal) CHECK(res.lower_bound == res.objective);
    CoverOptions g;
    g.solver = Solver::greedy;
    CoverResult gr;
    REQUIRE(solve_set_cover(c, g, false, Monitor{}, gr).ok());
    CHECK(res.objective <= gr.objective);  // never worse than greedy
    CHECK(gr.lower_bound <= res.objective);
}

TEST_CASE("set cover: cancellation and malformed coverage") {
    Rng rng(8);
    Coverage c = random_cover(rng, 20, 15, 0.2);
    std::atomic<int> flag{1};
    Monitor mon;
    mon.cancel_flag = &flag;
    CoverResult res;
    CHECK(solve_set_cover(c, CoverOptions{}, false, mon, res).code == Code::cancelled);
    Coverage bad = c;
    bad.ball_samples[0] = 99;  // out of range
    CHECK(solve_set_cover(bad, CoverOptions{}, false, Monitor{}, res).code == Code::invalid_input);
    bad = c;
    bad.ball_ptr.pop_back();
    CHECK(solve_set_cover(bad, CoverOptions{}, false, Monitor{}, res).code == Code::invalid_input);
    // an inconsistent transpose is not trusted: the answer stays right
    bad = c;
    std::reverse(bad.sample_balls.begin(), bad.sample_balls.end());
    REQUIRE(solve_set_cover(bad, CoverOptions{}, false, Monitor{}, res).ok());
    CHECK(int(res.objective) == brute_min(c));
    // no transpose at all is fine too
    bad = c;
    bad.sample_ptr.clear();
    bad.sample_balls.clear();
    REQUIRE(solve_set_cover(bad, CoverOptions{}, false, Monitor{}, res).ok());
    CHECK(int(res.objective) == brute_min(c));
    // empty problem
    Coverage e;
    e.ball_ptr = {0};
    REQUIRE(solve_set_cover(e, CoverOptions{}, false, Monitor{}, res).ok());
    CHECK(res.selected.empty());
    CHECK(res.proven_optimal == 1);
}

#if defined(__unix__)
TEST_CASE("set cover: the exact solver prints nothing, CBC included") {
    // The prove effort on random covers whose LP bound is below the best cover: CBC must branch
    // (cbc_components > 0 on at least one instance), and nothing reaches stdout while it does.
    std::fflush(stdout);
    char path[] = "/tmp/ca_setcover_stdoutXXXXXX";
    const int fd = mkstemp(path);
    REQUIRE(fd >= 0);
    const int saved = dup(1);
    dup2(fd, 1);
    CoverOptions opt;
    opt.effort = Effort::prove;
    size_t cbc_runs = 0;
    bool all_ok = true;
    for (uint64_t seed = 77; seed < 97 && cbc_runs == 0; ++seed) {
        Rng rng(seed);
        const Coverage c = random_cover(rng, 120, 160, 0.05);
        CoverResult res;
        all_ok = all_ok && solve_set_cover(c, opt, false, Monitor{}, res).ok();
        cbc_runs += res.cbc_components;
    }
    std::fflush(stdout);
    dup2(saved, 1);
    close(saved);
    const off_t size = lseek(fd, 0, SEEK_END);
    close(fd);
    unlink(path);
    CHECK(all_ok);
    REQUIRE(cbc_runs > 0);  // CBC ran on at least one instance
    CHECK(size == 0);
}
#endif

TEST_CASE("coverage: k-d tree query equals brute-force distances") {
    Rng rng(11);
    for (int t = 0; t < 5; ++t) {
        const size_t m = 300 + rng.below(200), n = 150;
        std::vector<Vec3> S, C;
        std::vector<double> R;
        for (size_t j = 0; j < m; ++j) S.emplace_back(rng.uniform(), rng.uniform(), rng.uniform());
        for (size_t i = 0; i < n; ++i) {
            C.emplace_back(rng.uniform(), rng.uniform(), rng.uniform());
            R.push_back(0.3 * rng.uniform());
        }
        // a sample exactly on a sphere counts as covered, and a zero radius covers a coincident point
        C.push_back(S[0] - Vec3(0.25, 0, 0));
        R.push_back(0.25);
        C.push_back(S[1]);
        R.push_back(0.0);
        Coverage cov;
        REQUIRE(build_coverage(S, C, R, Monitor{}, cov).ok());
        REQUIRE(cov.n_samples == m);
        REQUIRE(cov.n_balls == n + 2);
        REQUIRE(cov.ball_ptr.size() == n + 3);
        for (size_t i = 0; i < cov.n_balls; ++i) {
            std::vector<uint32_t> want;
            for (size_t j = 0; j < m; ++j)
                if ((S[j] - C[i]).norm() <= R[i] * (1 + 1e-12)) want.push_back(uint32_t(j));
            std::vector<uint32_t> got(cov.ball_samples.begin() + cov.ball_ptr[i], cov.ball_samples.begin() + cov.ball_ptr[i + 1]);
            CHECK(got == want);
        }
        CHECK(std::binary_search(cov.ball_samples.begin() + cov.ball_ptr[n], cov.ball_samples.begin() + cov.ball_ptr[n + 1], 0u));
        CHECK(std::binary_search(cov.ball_samples.begin() + cov.ball_ptr[n + 1], cov.ball_samples.begin() + cov.ball_ptr[n + 2], 1u));
        // transpose: sorted and consistent
        REQUIRE(cov.sample_ptr.size() == m + 1);
        for (size_t j = 0; j < m; ++j) {
            CHECK(std::is_sorted(cov.sample_balls.begin() + cov.sample_ptr[j], cov.sample_balls.begin() + cov.sample_ptr[j + 1]));
            for (uint32_t k = cov.sample_ptr[j]; k < cov.sample_ptr[j + 1]; ++k) {
                const uint32_t i = cov.sample_balls[k];
                CHECK(std::binary_search(cov.ball_samples.begin() + cov.ball_ptr[i], cov.ball_samples.begin() + cov.ball_ptr[i + 1], uint32_t(j)));
            }
        }
    }
}

TEST_CASE("coverage: bad input and cancellation") {
    std::vector<Vec3> S{Vec3(0, 0, 0)}, C{Vec3(0, 0, 0)};
    Coverage cov;
    CHECK(build_coverage(S, C, {}, Monitor{}, cov).code == Code::invalid_argument);
    CHECK(build_coverage(S, C, {-1.0}, Monitor{}, cov).code == Code::invalid_input);
    CHECK(build_coverage({Vec3(0, 0, std::nan(""))}, C, {1.0}, Monitor{}, cov).code == Code::invalid_input);
    REQUIRE(build_coverage({}, C, {1.0}, Monitor{}, cov).ok());
    CHECK(cov.ball_ptr == std::vector<uint32_t>{0, 0});
    std::atomic<int> flag{1};
    Monitor mon;
    mon.cancel_flag = &flag;
    CHECK(build_coverage(S, C, {1.0}, mon, cov).code == Code::cancelled);
}

TEST_CASE("coverage: a cancel from the first progress call of a many-batch build stops it there") {
    // 20 000 balls are several batches: the build must return at the first report that is
    // refused, with no further progress call, and leave the output untouched.
    Rng rng(31);
    std::vector<Vec3> S, C;
    for (int i = 0; i < 2000; ++i) S.emplace_back(rng.uniform(), rng.uniform(), rng.uniform());
    for (int i = 0; i < 20000; ++i) C.emplace_back(rng.uniform(), rng.uniform(), rng.uniform());
    const std::vector<double> radii(C.size(), 0.05);
    for (int threads : {1, 2}) {
        int calls = 0;
        Monitor mon;
        mon.progress = [&](const char* stage, double) {
            CHECK(std::string(stage) == "coverage");
            ++calls;
            return false;
        };
        Coverage cov;
        cov.n_balls = 7;
        CHECK(build_coverage(S, C, radii, mon, cov, threads).code == Code::cancelled);
        CHECK(calls == 1);
        CHECK(cov.n_balls == 7);
        // uncancelled, the same build reports once per batch and at the end
        calls = 0;
        mon.progress = [&](const char*, double) { return ++calls, true; };
        REQUIRE(build_coverage(S, C, radii, mon, cov, threads).ok());
        CHECK(calls >= 5);
        CHECK(cov.n_balls == C.size());
    }
}

namespace {
// The compact problem of a coverage in which every sample is covered (internal form).
sc::Problem to_problem(const Coverage& c) {
    sc::Problem P;
    P.R = uint32_t(c.n_samples);
    P.C = uint32_t(c.n_balls);
    P.cptr = c.ball_ptr;
    P.crow = c.ball_samples;
    P.rptr = c.sample_ptr;
    P.rcol = c.sample_balls;
    for (uint32_t i = 0; i < P.C; ++i) P.col_id.push_back(i);
    for (uint32_t j = 0; j < P.R; ++j) P.row_id.push_back(j);
    return P;
}
}  // namespace

TEST_CASE("set cover: the fast effort gives valid covers, valid bounds and the same result every time") {
    // Instances large enough that the LP bound, even one ball higher after branching, often leaves
    // a gap of two balls or more (where the fast effort does not run CBC); the prove effort gives
    // the optimum to compare with.
    Rng rng(9090);
    int unproven = 0, optimal = 0;
    for (int t = 0; t < 40; ++t) {
        const Coverage c = random_cover(rng, 100 + rng.below(40), 90 + rng.below(40), 0.05);
        CoverOptions fast, prove;
        prove.effort = Effort::prove;
        prove.time_limit_s = 0;
        CoverResult a, b, p;
        REQUIRE(solve_set_cover(c, fast, false, Monitor{}, a).ok());
        REQUIRE(solve_set_cover(c, fast, false, Monitor{}, b).ok());
        REQUIRE(solve_set_cover(c, prove, false, Monitor{}, p).ok());
        INFO("instance " << t << " fast " << a.objective << " >= " << a.lower_bound << ", optimum " << p.objective);
        REQUIRE(p.proven_optimal == 1);
        CHECK(valid_cover(c, a.selected));
        CHECK(a.selected == b.selected);             // deterministic
        CHECK(a.lower_bound == b.lower_bound);
        CHECK(a.lower_bound <= p.objective + 1e-9);   // a valid bound
        CHECK(a.objective >= p.objective);
        CHECK(a.gap == doctest::Approx((a.objective - a.lower_bound) / a.objective));
        if (a.proven_optimal) CHECK(a.objective == p.objective);
        else ++unproven;
        if (a.objective == p.objective) ++optimal;
    }
    // Components over 400 rows get CBC only for a one-ball gap, and the branching step only when
    // the LP is close to the next integer: there the early stop is the rule (no optimum to
    // compare with at this size).
    for (int t = 0; t < 3; ++t) {
        const Coverage c = random_cover(rng, 450 + rng.below(50), 300 + rng.below(50), 0.02);
        CoverOptions fast;
        CoverResult a, b;
        REQUIRE(solve_set_cover(c, fast, false, Monitor{}, a).ok());
        REQUIRE(solve_set_cover(c, fast, false, Monitor{}, b).ok());
        CHECK(valid_cover(c, a.selected));
        CHECK(a.selected == b.selected);
        CHECK(a.lower_bound == b.lower_bound);
        CHECK(a.lower_bound <= a.objective);
        unproven += !a.proven_optimal;
    }
    CHECK(unproven > 0);       // the fast path's early stop is exercised
    CHECK(optimal >= 30);      // and it mostly finds the optimum anyway
}

// run_cbc's answer on c is a proven minimum cover of `best` columns, with a bound no higher
static void check_cbc_minimum(const Coverage& c, const sc::CbcOutcome& out, int best) {
    REQUIRE(out.ok);
    CHECK(out.has_solution);
    CHECK(out.proven);
    CHECK(int(out.solution.size()) == best);
    CHECK(out.bound <= best + 1e-9);
    CHECK(valid_cover(c, out.solution));
}

TEST_CASE("set cover: run_cbc reads its answer by rounding and reaches the brute-force minimum") {
    // CBC's column values come back as 0.9999999 as often as 1: a cover read by truncation
    // is no cover, and the instance's optimum would be lost.
    const auto insts = small_instances(4321, 200);
    int solved = 0;
    for (size_t t = 0; t < insts.size(); ++t) {
        const Coverage& c = insts[t].cov;
        const int best = brute_min(c);
        REQUIRE(best >= 1);
        const sc::Problem P = to_problem(c);
        const sc::CbcOutcome out = sc::run_cbc(P, size_t(best) + 1, sc::CbcSettings{});
        INFO("instance " << t << " brute-force minimum " << best);
        check_cbc_minimum(c, out, best);
        // none smaller than the minimum exists: CBC proves it and returns no cover
        if (best >= 2) {
            const sc::CbcOutcome none = sc::run_cbc(P, size_t(best), sc::CbcSettings{});
            CHECK(none.ok);
            CHECK(!none.has_solution);
            CHECK(none.proven);
        }
        solved += out.has_solution;
    }
    CHECK(solved == int(insts.size()));
}

TEST_CASE("set cover: run_cbc under every search setting reaches the brute-force minimum on instances that need branching") {
    // Instances whose LP leaves a gap (odd cycles, sparse random ones up to 30 rows), searched
    // from no incumbent under each setting the solver uses: CBC's answer (column values such as
    // 0.9999999 after cuts and preprocessing) must read back as the optimal cover, with a bound
    // no higher than the optimum.
    Rng rng(8642);
    std::vector<Coverage> insts;
    for (int t = 0; t < 60; ++t)
        insts.push_back(t % 2 == 0 ? random_cover(rng, 22 + rng.below(9), 16 + rng.below(9), 0.12 + 0.08 * rng.uniform())
                                   : odd_cycles(rng));
    std::vector<sc::CbcSettings> settings(6);
    settings[1].lean = true;
    settings[2].heuristics = false;
    settings[3].strong_branching = false;
    settings[4].threads = 2;
    settings[5].lean = true;
    settings[5].heuristics = false;
    settings[5].strong_branching = false;
    for (size_t t = 0; t < insts.size(); ++t) {
        const Coverage& c = insts[t];
        const int best = brute_min(c);
        REQUIRE(best >= 1);
        const sc::Problem P = to_problem(c);
        for (size_t k = 0; k < settings.size(); ++k) {
            INFO("instance " << t << " setting " << k << " brute-force minimum " << best);
            const sc::CbcOutcome out = sc::run_cbc(P, c.n_balls + 1, settings[k]);
            check_cbc_minimum(c, out, best);
        }
    }
}

TEST_CASE("set cover: every exact solve's lower bound is at most the brute-force minimum") {
    // Both efforts, with and without row generation, on the instances the brute force reaches:
    // a bound above the optimum would let a solver claim a non-optimal cover proven. Besides the
    // small instances, ones that reach the LP phase (odd cycles, sparse instances up to 30 rows).
    std::vector<Coverage> insts;
    for (const Instance& in : small_instances(777, 160)) insts.push_back(in.cov);
    Rng rng(1357);
    for (int t = 0; t < 60; ++t)
        insts.push_back(t % 2 == 0 ? random_cover(rng, 22 + rng.below(9), 16 + rng.below(9), 0.12 + 0.08 * rng.uniform())
                                   : odd_cycles(rng));
    for (size_t t = 0; t < insts.size(); ++t) {
        const Coverage& c = insts[t];
        const int best = brute_min(c);
        for (int variant = 0; variant < 4; ++variant) {
            CoverOptions opt;
            opt.effort = variant & 1 ? Effort::prove : Effort::fast;
            opt.row_generation = variant & 2;
            CoverResult res;
            REQUIRE(solve_set_cover(c, opt, false, Monitor{}, res).ok());
            INFO("instance " << t << " variant " << variant << " bound " << res.lower_bound << " optimum " << best);
            CHECK(res.lower_bound <= best + 1e-9);
            CHECK(res.objective >= best);
            if (res.proven_optimal) CHECK(int(res.objective) == best);
        }
    }
}

TEST_CASE("set cover: an unknown effort is refused") {
    Rng rng(5);
    const Coverage c = random_cover(rng, 10, 10, 0.3);
    CoverOptions opt;
    opt.effort = static_cast<Effort>(7);
    CoverResult res;
    CHECK(solve_set_cover(c, opt, false, Monitor{}, res).code == Code::invalid_argument);
}

TEST_CASE("set cover: the core LP (column generation) has the whole LP's optimum") {
    const Deadline far = Deadline::after(3600);
    const auto insts = small_instances(4321, 120);
    Rng rng(11);
    for (size_t t = 0; t < insts.size(); ++t) {
        const sc::Problem P = to_problem(insts[t].cov);
        std::vector<uint32_t> all(P.C);
        for (uint32_t i = 0; i < P.C; ++i) all[i] = i;
        const std::vector<double> y = sc::lp_duals(P, 0);
        REQUIRE(y.size() == P.R);
        const double lp = sc::lagrangian(P, all, 1, far, &y).bound;
        // cores from the subgradient's reduced costs, and from random costs (a poor core that
        // needs several pricing rounds)
        std::vector<double> random_cost(P.C);
        for (double& v : random_cost) v = rng.uniform();
        for (const std::vector<double>& cost : {sc::lagrangian(P, all, 50, far).cost, random_cost}) {
            const std::vector<double> yc = sc::lp_duals_core(P, cost, 0);
            INFO("instance " << t);
            REQUIRE(yc.size() == P.R);
            CHECK(sc::lagrangian(P, all, 1, far, &yc).bound == doctest::Approx(lp).epsilon(1e-7));
        }
    }
}

namespace {
// Larger random problems than small_instances (a few hundred rows), fixed seeds.
std::vector<sc::Problem> medium_problems(uint64_t seed, int count) {
    Rng rng(seed);
    std::vector<sc::Problem> out;
    for (int t = 0; t < count; ++t) {
        const size_t m = 150 + rng.below(250), n = 100 + rng.below(200);
        out.push_back(to_problem(random_cover(rng, m, n, 0.01 + 0.03 * rng.uniform())));
    }
    return out;
}
std::vector<uint32_t> all_columns(const sc::Problem& P) {
    std::vector<uint32_t> all(P.C);
    for (uint32_t i = 0; i < P.C; ++i) all[i] = i;
    return all;
}
}  // namespace

TEST_CASE("set cover: the LP by row and column generation has the whole LP's optimum") {
    const Deadline far = Deadline::after(3600);
    std::vector<sc::Problem> problems = medium_problems(2024, 24);
    for (const Instance& in : small_instances(4321, 60)) problems.push_back(to_problem(in.cov));
    Rng rng(12);
    for (size_t t = 0; t < problems.size(); ++t) {
        const sc::Problem& P = problems[t];
        const std::vector<uint32_t> all = all_columns(P);
        const std::vector<double> y = sc::lp_duals(P, 0);
        REQUIRE(y.size() == P.R);
        const double lp = sc::lagrangian(P, all, 1, far, &y).bound;
        // starts: the volume ascent's multipliers (what the solver passes); none (every row
        // starts); a random tenth of the rows with random costs (many rows and columns to add)
        const sc::Lagrange V = sc::volume_ascent(P, all, 200, far);
        std::vector<double> none(P.R, 0.0), sparse(P.R, 0.0), random_cost(P.C);
        for (double& v : sparse) v = rng.uniform() < 0.1 ? rng.uniform() : 0.0;
        for (double& v : random_cost) v = rng.uniform();
        const std::pair<const std::vector<double>*, const std::vector<double>*> starts[] = {
            {&V.u, &V.cost}, {&none, &random_cost}, {&sparse, &random_cost}};
        for (const auto& st : starts) {
            const std::vector<double> yr = sc::lp_duals_rows(P, *st.first, *st.second, 0);
            INFO("problem " << t << " (" << P.R << " x " << P.C << ")");
            REQUIRE(yr.size() == P.R);
            CHECK(sc::lagrangian(P, all, 1, far, &yr).bound == doctest::Approx(lp).epsilon(1e-7));
        }
    }
}

TEST_CASE("set cover: branching on the LP never rules out the brute-force minimum, and often rules out one ball less") {
    const Deadline far = Deadline::after(3600);
    int beyond_lp = 0, below = 0;
    Rng rng(2468);
    for (int t = 0; t < 200; ++t) {
        // Random instances (up to 30 rows, for the brute force) and unions of odd cycles, whose
        // LP alone often leaves a gap.
        const Coverage c = t % 2 == 0 ? random_cover(rng, 22 + rng.below(9), 16 + rng.below(9), 0.12 + 0.08 * rng.uniform())
                                      : odd_cycles(rng);
        const sc::Problem P = to_problem(c);
        const int best = brute_min(c);
        REQUIRE(best > 0);
        INFO("brute-force minimum " << best);
        CHECK_FALSE(sc::no_cover_within(P, size_t(best), 8));  // a cover of that size exists
        CHECK_FALSE(sc::no_cover_within(P, size_t(best) + 1, 8));
        const std::vector<double> y = sc::lp_duals(P, 0);
        REQUIRE(y.size() == P.R);
        const bool by_lp = sc::lagrangian(P, all_columns(P), 1, far, &y).bound > double(best) - 1.0 + 1e-6;
        const bool ruled_out = sc::no_cover_within(P, size_t(best) - 1, 8);
        below += ruled_out;
        beyond_lp += ruled_out && !by_lp;  // branching was needed
        // told to stop at once, only the LP itself can rule it out
        CHECK(sc::no_cover_within(P, size_t(best) - 1, 8, [] { return true; }) == by_lp);
    }
    CHECK(below >= 150);
    CHECK(beyond_lp >= 5);
}

TEST_CASE("set cover: the search on the LP optimal face returns only smaller covers from its core, and often finds one") {
    const Deadline far = Deadline::after(3600);
    Rng rng(8642);
    int found = 0, through_cbc = 0;
    for (int t = 0; t < 150; ++t) {
        const Coverage c = random_cover(rng, 22 + rng.below(9), 20 + rng.below(15), 0.1 + 0.1 * rng.uniform());
        const sc::Problem P = to_problem(c);
        const int best = brute_min(c);
        REQUIRE(best > 0);
        const std::vector<double> y = sc::lp_duals(P, 0);
        REQUIRE(y.size() == P.R);
        const std::vector<double> cost = sc::lagrangian(P, all_columns(P), 1, far, &y).cost;
        REQUIRE(cost.size() == P.C);
        // the core: reduced cost at most kCoreMaxCost, or the cheapest column of a row (ties to
        // the lower index)
        std::vector<uint8_t> core(P.C, 0);
        for (uint32_t j = 0; j < P.C; ++j) core[j] = cost[j] <= sc::kCoreMaxCost;
        for (uint32_t r = 0; r < P.R; ++r) {
            uint32_t cheapest = P.rcol[P.rptr[r]];
            for (uint32_t q = P.rptr[r]; q < P.rptr[r + 1]; ++q)
                if (cost[P.rcol[q]] < cost[cheapest]) cheapest = P.rcol[q];
            core[cheapest] = 1;
        }
        INFO("instance " << t << ", brute-force minimum " << best);
        // nothing is smaller than the minimum
        CHECK(sc::core_cover(P, cost, size_t(best), 0, 1, Monitor{}).empty());
        // below an incumbent one ball above it: a minimum cover from the core, or nothing
        const std::vector<uint32_t> sel = sc::core_cover(P, cost, size_t(best) + 1, 0, 1, Monitor{});
        if (sel.empty()) continue;
        ++found;
        CHECK(valid_cover(c, sel));
        CHECK(int(sel.size()) == best);
        for (uint32_t j : sel) CHECK(core[j] == 1);
        // found by CBC, not by the reduction of the core alone
        std::vector<uint32_t> forced;
        sc::Problem K;
        REQUIRE(sc::reduce_problem(sc::restrict_columns(P, core), Monitor{}, forced, K).ok());
        through_cbc += K.R > 0;
    }
    CHECK(found >= 120);
    CHECK(through_cbc >= 60);

    // Costs that are not reduced costs at LP duals (no column at zero): the core is each row's
    // cheapest column, itself a cover, which any incumbent above the column count admits.
    for (int t = 0; t < 20; ++t) {
        const Coverage c = random_cover(rng, 22 + rng.below(9), 20 + rng.below(15), 0.15);
        const sc::Problem P = to_problem(c);
        std::vector<double> cost(P.C);
        for (double& x : cost) x = 0.01 + rng.uniform();
        std::vector<uint8_t> cheapest_of_a_row(P.C, 0);
        for (uint32_t r = 0; r < P.R; ++r) {
            uint32_t cheapest = P.rcol[P.rptr[r]];
            for (uint32_t q = P.rptr[r]; q < P.rptr[r + 1]; ++q)
                if (cost[P.rcol[q]] < cost[cheapest]) cheapest = P.rcol[q];
            cheapest_of_a_row[cheapest] = 1;
        }
        INFO("instance " << t);
        const std::vector<uint32_t> sel = sc::core_cover(P, cost, P.C + 1, 0, 1, Monitor{});
        CHECK(valid_cover(c, sel));
        CHECK_FALSE(sel.empty());
        for (uint32_t j : sel) CHECK(cheapest_of_a_row[j] == 1);
    }
}

TEST_CASE("set cover: the volume ascent gives a valid bound near the LP optimum") {
    const Deadline far = Deadline::after(3600);
    SUBCASE("small instances: below the brute-force minimum and the LP, at its own multipliers") {
        for (const Instance& in : small_instances(515, 120)) {
            const sc::Problem P = to_problem(in.cov);
            const std::vector<uint32_t> all = all_columns(P);
            const std::vector<double> y = sc::lp_duals(P, 0);
            REQUIRE(y.size() == P.R);
            const double lp = sc::lagrangian(P, all, 1, far, &y).bound;
            const sc::Lagrange V = sc::volume_ascent(P, all, 1000, far);
            const int best = brute_min(in.cov);
            CHECK(V.bound <= best + 1e-9);
            CHECK(V.bound <= lp + 1e-7);
            CHECK(sc::lagrangian(P, all, 1, far, &V.u).bound == doctest::Approx(V.bound).epsilon(1e-9));
            CHECK(sc::covers_problem(P, V.best));
            CHECK(int(V.best.size()) >= best);
        }
    }
    SUBCASE("medium problems: within 3 % of the LP") {
        const auto problems = medium_problems(77, 16);
        for (size_t t = 0; t < problems.size(); ++t) {
            const sc::Problem& P = problems[t];
            const std::vector<uint32_t> start = sc::greedy_cover(P);
            const std::vector<double> y = sc::lp_duals(P, 0);
            REQUIRE(y.size() == P.R);
            const double lp = sc::lagrangian(P, all_columns(P), 1, far, &y).bound;
            const sc::Lagrange V = sc::volume_ascent(P, start, 1000, far);
            INFO("problem " << t << ": volume " << V.bound << ", LP " << lp);
            CHECK(V.bound <= lp + 1e-7);
            CHECK(V.bound >= 0.97 * lp);
            CHECK(sc::covers_problem(P, V.best));
        }
    }
}

TEST_CASE("set cover: the bound at the LP duals equals the LP optimum and bounds the brute-force minimum") {
    const Deadline far = Deadline::after(3600);
    SUBCASE("odd cycle: LP 5/2, integer optimum 3") {
        Coverage c;
        c.n_samples = 5;
        c.n_balls = 5;
        c.ball_ptr = {0, 2, 4, 6, 8, 10};
        c.ball_samples = {0, 1, 1, 2, 2, 3, 3, 4, 0, 4};
        c.build_transpose();
        const sc::Problem P = to_problem(c);
        const std::vector<double> y = sc::lp_duals(P, 0);
        REQUIRE(y.size() == 5);
        const sc::Lagrange L = sc::lagrangian(P, {0, 1, 2, 3, 4}, 1, far, &y);
        CHECK(L.bound == doctest::Approx(2.5).epsilon(1e-7));
        CHECK(brute_min(c) == 3);
    }
    SUBCASE("random instances") {
        const auto insts = small_instances(777, 200);
        int fractional = 0;
        for (size_t t = 0; t < insts.size(); ++t) {
            const Coverage& c = insts[t].cov;
            const sc::Problem P = to_problem(c);
            std::vector<uint32_t> all(P.C);
            for (uint32_t i = 0; i < P.C; ++i) all[i] = i;
            const std::vector<double> y = sc::lp_duals(P, 0);
            INFO("instance " << t);
            REQUIRE(y.size() == P.R);
            const sc::Lagrange at_lp = sc::lagrangian(P, all, 1, far, &y);
            const sc::Lagrange subgradient = sc::lagrangian(P, all, 1000, far);
            const int best = brute_min(c);
            CHECK(at_lp.bound <= best + 1e-9);                    // a valid lower bound
            CHECK(at_lp.bound >= subgradient.bound - 1e-6);       // the LP is the best Lagrangian bound
            if (at_lp.bound < best - 1e-6) ++fractional;
        }
        CHECK(fractional > 5);  // instances with an integrality gap are among them
    }
}

TEST_CASE("set cover: a kernel too large for one CBC solve keeps a valid cover and bound under a time limit") {
    // More kernel rows than CBC may take as a whole (its root LP ignores time limits): the
    // component goes to row generation with the whole budget.
    Rng rng(31337);
    Coverage c = random_cover(rng, 6000, 2000, 0.003);
    CoverOptions opt;
    opt.time_limit_s = 0.5;
    CoverResult res;
    REQUIRE(solve_set_cover(c, opt, false, Monitor{}, res).ok());
    CHECK(res.rows_after > 4000);  // the path under test
    CHECK(valid_cover(c, res.selected));
    CHECK(res.lower_bound <= res.objective);
    CHECK(res.lower_bound >= 1);
    CoverOptions g;
    g.solver = Solver::greedy;
    CoverResult gr;
    REQUIRE(solve_set_cover(c, g, false, Monitor{}, gr).ok());
    CHECK(res.objective <= gr.objective);
    CHECK(gr.lower_bound <= res.objective);
}

TEST_CASE("set cover: the local search returns valid covers, never worse than its start, mostly optimal") {
    // Random instances with a brute-force optimum: the local search from the greedy cover must
    // return a cover of the instance, no larger than the start and no smaller than the optimum,
    // the same one for the same seed, and (these are easy for it) the optimum on nearly all.
    const Deadline far = Deadline::after(3600);
    Rng rng(2024);
    int optimal = 0, improved = 0, total = 0;
    for (int t = 0; t < 80; ++t) {
        const Coverage c = random_cover(rng, 22 + t % 7, 18 + t % 5, t % 2 ? 0.15 : 0.25);
        const int best = brute_min(c);
        REQUIRE(best >= 0);
        const sc::Problem P = to_problem(c);
        std::vector<uint32_t> g = sc::greedy_cover(P);
        sc::remove_redundant(P.cptr, P.crow, P.R, nullptr, nullptr, g);
        const std::vector<uint32_t> a = sc::local_search(P, g, {0, 20000, 7, far}).cover;
        const std::vector<uint32_t> b = sc::local_search(P, g, {0, 20000, 7, far}).cover;
        INFO("instance " << t << " greedy " << g.size() << " optimum " << best << " local " << a.size());
        CHECK(valid_cover(c, a));
        CHECK(std::is_sorted(a.begin(), a.end()));
        CHECK(a.size() <= g.size());
        CHECK(int(a.size()) >= best);
        CHECK(a == b);
        // stops at the lower bound: given the optimum as bound, it returns a cover of that size
        const std::vector<uint32_t> s = sc::local_search(P, g, {size_t(best), 20000, 7, far}).cover;
        CHECK(int(s.size()) == best);
        CHECK(valid_cover(c, s));
        optimal += int(a.size()) == best;
        improved += a.size() < g.size();
        ++total;
    }
    CHECK(optimal >= total - 2);
    CHECK(improved >= 5);  // the greedy start is not already optimal everywhere
}

// The greedy cover without redundant columns: the local search's start.
std::vector<uint32_t> greedy_start(const sc::Problem& P) {
    std::vector<uint32_t> g = sc::greedy_cover(P);
    sc::remove_redundant(P.cptr, P.crow, P.R, nullptr, nullptr, g);
    return g;
}

// The runs of SearchRuns on a fixed set of threads: one per run, or all on the calling thread
// with `threads` 1.
std::vector<uint32_t> local_search_multi(const sc::Problem& P, const std::vector<uint32_t>& start, size_t lower_bound,
                                         uint64_t max_steps, uint64_t seed, int starts, int threads,
                                         const Deadline& deadline) {
    sc::SearchRuns runs(P, start, {lower_bound, max_steps, seed, deadline}, starts);
    run_workers(threads > 1 ? size_t(starts) : 1, [&](size_t) { runs.work(); });
    return runs.best();
}

// The run SearchRuns must return: the smallest of the single runs, ties to the earliest
// swap at which it was found, then to the lowest seed.
std::vector<uint32_t> best_single_run(const sc::Problem& P, const std::vector<uint32_t>& g, size_t lower_bound,
                                      uint64_t steps, uint64_t seed, int starts, std::set<size_t>* sizes = nullptr,
                                      std::set<uint64_t>* found_steps = nullptr) {
    const Deadline far = Deadline::after(3600);
    std::vector<uint32_t> expect;
    uint64_t expect_at = 0;
    for (int k = 0; k < starts; ++k) {
        const sc::SearchResult run = sc::local_search(P, g, {lower_bound, steps, seed + uint64_t(k), far});
        const std::vector<uint32_t>& one = run.cover;
        const uint64_t at = run.found_step;
        if (sizes) sizes->insert(one.size());
        if (found_steps) found_steps->insert(at);
        if (k == 0 || one.size() < expect.size() || (one.size() == expect.size() && at < expect_at)) {
            expect = one;
            expect_at = at;
        }
    }
    return expect;
}

TEST_CASE("set cover: independent local-search runs give the best run, whatever the thread count") {
    // Larger random instances and short runs (where seeds differ): the multi-start result is the smallest of the
    // single runs (ties to the earliest found, then the lowest seed) for 1, 2 and 3 threads.
    const Deadline far = Deadline::after(3600);
    Rng rng(31337);
    int differ = 0;
    for (int t = 0; t < 12; ++t) {
        const sc::Problem P = to_problem(random_cover(rng, 300, 200, 0.02));
        const std::vector<uint32_t> g = greedy_start(P);
        std::set<size_t> sizes;
        const std::vector<uint32_t> expect = best_single_run(P, g, 0, 300, 40, 4, &sizes);
        if (sizes.size() > 1) ++differ;
        for (int threads : {1, 2, 3}) {
            INFO("instance " << t << " threads " << threads);
            CHECK(local_search_multi(P, g, 0, 300, 40, 4, threads, far) == expect);
        }
    }
    CHECK(differ > 0);  // the seeds matter on some of these
}

TEST_CASE("set cover: runs that stop each other at a known bound still give the best single run") {
    // With a lower bound the runs can reach, the first to reach it makes the others stop (SearchRace); the result
    // is still the single runs' best by (size, swap found, seed), for 1, 2 and 3 threads and repeated runs.
    const Deadline far = Deadline::after(3600);
    Rng rng(4242);
    int raced = 0;
    for (int t = 0; t < 10; ++t) {
        const sc::Problem P = to_problem(random_cover(rng, 300, 200, 0.02));
        const std::vector<uint32_t> g = greedy_start(P);
        // the bound: the best size long runs reach
        const size_t bound = best_single_run(P, g, 0, 20000, 7, 4).size();
        if (bound >= g.size()) continue;
        std::set<uint64_t> found_steps;
        const std::vector<uint32_t> expect = best_single_run(P, g, bound, 20000, 40, 4, nullptr, &found_steps);
        raced += expect.size() == bound && found_steps.size() > 1;
        for (int threads : {1, 2, 3, 3}) {
            INFO("instance " << t << " threads " << threads);
            CHECK(local_search_multi(P, g, bound, 20000, 40, 4, threads, far) == expect);
        }
    }
    CHECK(raced >= 3);  // runs that reach the bound at different swaps
}

TEST_CASE("set cover: search runs taken by threads that join late, with a bound that arrives late, give the best single run") {
    // SearchRuns as the exact solver uses it: some threads take runs at once, another joins after a delay (the LP's
    // thread, once its LP is solved), and the bound the runs may stop at is published during the search.
    const Deadline far = Deadline::after(3600);
    Rng rng(777);
    int checked = 0;
    for (int t = 0; t < 6; ++t) {
        const sc::Problem P = to_problem(random_cover(rng, 300, 200, 0.02));
        const std::vector<uint32_t> g = greedy_start(P);
        // a size no run below goes under, even before the bound arrives (runs are deterministic
        // per seed): the best of long runs with these seeds and others
        const size_t bound =
            std::min(best_single_run(P, g, 0, 20000, 7, 4).size(), best_single_run(P, g, 0, 20000, 40, 4).size());
        if (bound >= g.size()) continue;
        const std::vector<uint32_t> expect = best_single_run(P, g, bound, 20000, 40, 4);
        for (int early : {1, 2}) {
            for (int delay_ms : {0, 2, 20}) {
                INFO("instance " << t << " early threads " << early << " delay " << delay_ms << " ms");
                std::atomic<size_t> known{0};
                sc::SearchRuns runs(P, g, {0, 20000, 40, far, &known}, 4);
                std::thread late([&] {
                    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
                    known.store(bound);
                    runs.work();
                });
                std::vector<std::thread> pool;
                for (int k = 1; k < early; ++k) pool.emplace_back([&] { runs.work(); });
                runs.work();
                for (auto& th : pool) th.join();
                late.join();
                CHECK(runs.best() == expect);
                ++checked;
            }
        }
    }
    CHECK(checked >= 12);
}

TEST_CASE("set cover: the local search with no steps or an expired deadline keeps its start") {
    Rng rng(5);
    const Coverage c = random_cover(rng, 40, 30, 0.15);
    const sc::Problem P = to_problem(c);
    std::vector<uint32_t> g = sc::greedy_cover(P);
    sc::remove_redundant(P.cptr, P.crow, P.R, nullptr, nullptr, g);
    const std::vector<uint32_t> z = sc::local_search(P, g, {0, 0, 1, Deadline::after(3600)}).cover;
    CHECK(valid_cover(c, z));
    CHECK(z.size() <= g.size());
    const std::vector<uint32_t> e = sc::local_search(P, g, {0, 1000000, 1, Deadline::after(1, Clock::now() - std::chrono::seconds(2))}).cover;
    CHECK(valid_cover(c, e));
    CHECK(e.size() <= g.size());
}

TEST_CASE("set cover: the local search's patience is proportional to the problem") {
    // 200 disjoint groups of 3 rows, two identical columns per group: the start (one column per
    // group) is optimal, so the search never improves and must stop after max(2000, 5 (R + C))
    // swaps past its start, not after a fixed large count.
    Coverage c;
    c.n_samples = 600;
    c.n_balls = 400;
    c.ball_ptr = {0};
    for (uint32_t b = 0; b < 400; ++b) {
        for (uint32_t k = 0; k < 3; ++k) c.ball_samples.push_back(3 * (b / 2) + k);
        c.ball_ptr.push_back(uint32_t(c.ball_samples.size()));
    }
    c.build_transpose();
    const sc::Problem P = to_problem(c);
    std::vector<uint32_t> start;
    for (uint32_t g = 0; g < 200; ++g) start.push_back(2 * g);
    const Deadline far = Deadline::after(3600);
    const sc::SearchResult s = sc::local_search(P, start, {0, 1000000, 3, far});
    CHECK(s.cover.size() == 200);
    CHECK(valid_cover(c, s.cover));
    CHECK(s.steps == 5 * (600 + 400) + 1);
    // a small problem gets the minimum patience
    Rng rng(11);
    const Coverage small = random_cover(rng, 20, 15, 0.25);
    const int best = brute_min(small);
    REQUIRE(best >= 0);
    const sc::Problem Q = to_problem(small);
    std::vector<uint32_t> g = sc::greedy_cover(Q);
    sc::remove_redundant(Q.cptr, Q.crow, Q.R, nullptr, nullptr, g);
    const sc::SearchResult a = sc::local_search(Q, g, {0, 1000000, 3, far});
    CHECK(int(a.cover.size()) == best);
    CHECK(a.steps <= 2 * 2000 + 2000 + 1);
    CHECK(a.steps >= 2000);
}

TEST_CASE("set cover: the reduction reaches its fixpoint (incremental dominance passes miss nothing)") {
    // Larger random instances need several rounds; the kernel must have no sample with one ball,
    // no sample whose balls contain another's, no ball whose samples another ball contains, and
    // keep the optimum (brute force on the smaller ones).
    Rng rng(77);
    auto subset = [](const uint32_t* x, uint32_t nx, const uint32_t* y, uint32_t ny) {
        return std::includes(y, y + ny, x, x + nx);
    };
    int multi_round = 0;
    for (int t = 0; t < 120; ++t) {
        const bool small = t % 3 == 0;
        const size_t m = small ? 18 + t % 10 : 60 + 7 * (t % 11), n = small ? 16 + t % 9 : 80 + 13 * (t % 7);
        const Coverage c = random_cover(rng, m, n, 0.04 + 0.03 * (t % 5));
        std::vector<uint32_t> forced, kb, ks;
        Coverage ker;
        REQUIRE(detail::reduce_set_cover(c, CoverOptions{}, false, Monitor{}, forced, ker, kb, ks).ok());
        INFO("instance " << t);
        multi_round += !forced.empty() && ker.n_balls > 0;
        for (size_t j = 0; j < ker.n_samples; ++j) {
            const uint32_t dj = ker.sample_ptr[j + 1] - ker.sample_ptr[j];
            CHECK(dj >= 2);
            for (size_t k = 0; k < ker.n_samples; ++k) {
                if (k == j) continue;
                const uint32_t dk = ker.sample_ptr[k + 1] - ker.sample_ptr[k];
                CHECK_FALSE(subset(&ker.sample_balls[ker.sample_ptr[k]], dk, &ker.sample_balls[ker.sample_ptr[j]], dj));
            }
        }
        for (size_t a = 0; a < ker.n_balls; ++a) {
            const uint32_t na = ker.ball_ptr[a + 1] - ker.ball_ptr[a];
            CHECK(na >= 1);
            for (size_t b = 0; b < ker.n_balls; ++b) {
                if (b == a) continue;
                const uint32_t nb = ker.ball_ptr[b + 1] - ker.ball_ptr[b];
                CHECK_FALSE(subset(&ker.ball_samples[ker.ball_ptr[a]], na, &ker.ball_samples[ker.ball_ptr[b]], nb));
            }
        }
        if (small) {
            const int kopt = ker.n_samples == 0 ? 0 : brute_min(ker);
            REQUIRE(kopt >= 0);
            CHECK(int(forced.size()) + kopt == brute_min(c));
        }
    }
    CHECK(multi_round >= 10);
}

namespace {

// Reference reduction, written for clarity (dense sets, quadratic tests), with the rules and
// phase sequence of the library's reducer: forced_in balls first; then to a fixpoint: samples
// with one alive ball force it; ball dominance (a dropped if some other alive b has
// samples(a) ⊆ samples(b), strictly or with b < a), rerun only after forcing or a sample
// change; sample dominance (j dropped if some other alive k has balls(k) ⊆ balls(j), strictly
// or with k < j), rerun only after forcing or a ball change; balls left without samples drop.
// Each dominance phase drops what is dominated at its start.
struct RefReduction {
    std::vector<uint32_t> forced, balls, samples;  // forced (ascending), kernel balls / samples
};

RefReduction ref_reduce(const Coverage& c, const std::vector<uint8_t>& ign, const std::vector<uint8_t>& fin,
                        const std::vector<uint8_t>& fout) {
    const size_t n = c.n_balls, m = c.n_samples;
    std::vector<std::vector<uint8_t>> in(n, std::vector<uint8_t>(m, 0));
    for (size_t a = 0; a < n; ++a)
        for (uint32_t k = c.ball_ptr[a]; k < c.ball_ptr[a + 1]; ++k) in[a][c.ball_samples[k]] = 1;
    std::vector<uint8_t> s_alive(m, 1), b_alive(n, 1);
    for (size_t j = 0; j < m; ++j) {
        bool reach = false;
        for (size_t a = 0; a < n; ++a) reach = reach || (in[a][j] && !(fout.size() && fout[a]));
        if ((ign.size() && ign[j]) || !reach) s_alive[j] = 0;
    }
    RefReduction r;
    auto select = [&](size_t a) {
        r.forced.push_back(uint32_t(a));
        b_alive[a] = 0;
        for (size_t j = 0; j < m; ++j)
            if (in[a][j]) s_alive[j] = 0;
    };
    for (size_t a = 0; a < n; ++a) {
        if (fout.size() && fout[a]) b_alive[a] = 0;
        if (fin.size() && fin[a]) select(a);
    }
    auto drop_empty = [&]() {
        for (size_t a = 0; a < n; ++a) {
            bool any = false;
            for (size_t j = 0; j < m; ++j) any = any || (in[a][j] && s_alive[j]);
            if (!any) b_alive[a] = 0;
        }
    };
    auto ball_subset = [&](size_t a, size_t b, int& size_a, int& size_b) {  // samples(a) ⊆ samples(b)
        size_a = size_b = 0;
        bool sub = true;
        for (size_t j = 0; j < m; ++j) {
            if (!s_alive[j]) continue;
            size_a += in[a][j];
            size_b += in[b][j];
            if (in[a][j] && !in[b][j]) sub = false;
        }
        return sub;
    };
    auto sample_subset = [&](size_t k, size_t j, int& deg_k, int& deg_j) {  // balls(k) ⊆ balls(j)
        deg_k = deg_j = 0;
        bool sub = true;
        for (size_t a = 0; a < n; ++a) {
            if (!b_alive[a]) continue;
            deg_k += in[a][k];
            deg_j += in[a][j];
            if (in[a][k] && !in[a][j]) sub = false;
        }
        return sub;
    };
    drop_empty();
    bool need_balls = true, need_samples = true;
    for (;;) {
        bool forced_any = false;
        for (size_t j = 0; j < m; ++j) {
            if (!s_alive[j]) continue;
            int deg = 0;
            size_t last = 0;
            for (size_t a = 0; a < n; ++a)
                if (b_alive[a] && in[a][j]) { ++deg; last = a; }
            if (deg == 1) { select(last); forced_any = true; }
        }
        if (forced_any) {
            drop_empty();
            need_balls = need_samples = true;
            continue;
        }
        if (need_balls) {
            need_balls = false;
            std::vector<uint8_t> drop(n, 0);
            for (size_t a = 0; a < n; ++a)
                for (size_t b = 0; b < n && b_alive[a] && !drop[a]; ++b) {
                    int sa, sb;
                    if (b != a && b_alive[b] && ball_subset(a, b, sa, sb) && (sb > sa || b < a)) drop[a] = 1;
                }
            bool any = false;
            for (size_t a = 0; a < n; ++a)
                if (drop[a]) { b_alive[a] = 0; any = true; }
            if (any) { drop_empty(); need_samples = true; }
            continue;
        }
        if (need_samples) {
            need_samples = false;
            std::vector<uint8_t> drop(m, 0);
            for (size_t j = 0; j < m; ++j)
                for (size_t k = 0; k < m && s_alive[j] && !drop[j]; ++k) {
                    int dk, dj;
                    if (k != j && s_alive[k] && sample_subset(k, j, dk, dj) && (dj > dk || k < j)) drop[j] = 1;
                }
            bool any = false;
            for (size_t j = 0; j < m; ++j)
                if (drop[j]) { s_alive[j] = 0; any = true; }
            if (any) { drop_empty(); need_balls = true; }
            continue;
        }
        break;
    }
    std::sort(r.forced.begin(), r.forced.end());
    for (size_t a = 0; a < n; ++a)
        if (b_alive[a]) r.balls.push_back(uint32_t(a));
    for (size_t j = 0; j < m; ++j)
        if (s_alive[j]) r.samples.push_back(uint32_t(j));
    return r;
}

}  // namespace

TEST_CASE("set cover: the reduction gives the reference kernel (rules, ties, masks, several rounds)") {
    // Random instances with repeated balls and samples (ties between equal sets), with and
    // without masks and a consistent transpose: the kernel (balls, samples, their lists) and the
    // forced balls must be those of the reference reduction above.
    Rng rng(2024);
    int with_kernel = 0, multi_round = 0;
    for (int t = 0; t < 300; ++t) {
        const size_t m = 8 + rng.below(50), n = 6 + rng.below(90);
        Coverage c = random_cover(rng, m, n, 0.05 + 0.25 * rng.uniform());
        if (t % 2 == 0) {
            // copy some balls over others (equal sets) and some samples onto others (equal sets)
            std::vector<std::vector<uint32_t>> lists(n);
            for (size_t a = 0; a < n; ++a) lists[a].assign(&c.ball_samples[c.ball_ptr[a]], &c.ball_samples[c.ball_ptr[a + 1]]);
            for (int q = 0; q < int(n / 5); ++q) lists[rng.below(n)] = lists[rng.below(n)];
            for (int q = 0; q < int(m / 6); ++q) {
                const uint32_t from = uint32_t(rng.below(m)), to = uint32_t(rng.below(m));
                for (auto& l : lists) {
                    l.erase(std::remove(l.begin(), l.end(), to), l.end());
                    if (std::binary_search(l.begin(), l.end(), from)) l.insert(std::upper_bound(l.begin(), l.end(), to), to);
                }
            }
            c.ball_samples.clear();
            c.ball_ptr.assign(1, 0);
            for (auto& l : lists) {
                c.ball_samples.insert(c.ball_samples.end(), l.begin(), l.end());
                c.ball_ptr.push_back(uint32_t(c.ball_samples.size()));
            }
            c.build_transpose();
        }
        if (t % 5 == 4) c.sample_ptr.clear();  // no transpose: the reducer builds its own
        CoverOptions opt;
        if (t % 3 == 1) {
            opt.ignorable_samples.assign(m, 0);
            opt.forced_in.assign(n, 0);
            opt.forced_out.assign(n, 0);
            for (size_t j = 0; j < m; ++j) opt.ignorable_samples[j] = rng.uniform() < 0.1;
            for (size_t a = 0; a < n; ++a) {
                const double u = rng.uniform();
                opt.forced_in[a] = u < 0.03;
                opt.forced_out[a] = u > 0.9;
            }
        }
        std::vector<uint32_t> forced, kb, ks;
        Coverage ker;
        INFO("instance " << t);
        REQUIRE(detail::reduce_set_cover(c, opt, true, Monitor{}, forced, ker, kb, ks).ok());
        const RefReduction ref = ref_reduce(c, opt.ignorable_samples, opt.forced_in, opt.forced_out);
        CHECK(forced == ref.forced);
        CHECK(kb == ref.balls);
        CHECK(ks == ref.samples);
        // kernel lists: the original lists restricted to the kernel, both directions
        REQUIRE(ker.n_balls == kb.size());
        REQUIRE(ker.n_samples == ks.size());
        for (size_t a = 0; a < ker.n_balls; ++a) {
            std::vector<uint32_t> expect;
            for (uint32_t k = c.ball_ptr[kb[a]]; k < c.ball_ptr[kb[a] + 1]; ++k) {
                const auto it = std::lower_bound(ks.begin(), ks.end(), c.ball_samples[k]);
                if (it != ks.end() && *it == c.ball_samples[k]) expect.push_back(uint32_t(it - ks.begin()));
            }
            CHECK(std::vector<uint32_t>(&ker.ball_samples[ker.ball_ptr[a]], &ker.ball_samples[ker.ball_ptr[a + 1]]) == expect);
        }
        Coverage tr = ker;
        tr.build_transpose();
        CHECK(tr.sample_ptr == ker.sample_ptr);
        CHECK(tr.sample_balls == ker.sample_balls);
        with_kernel += ker.n_balls > 0;
        multi_round += ker.n_balls > 0 && forced.size() > (opt.forced_in.empty() ? 0u : 1u);
    }
    CHECK(with_kernel >= 100);
    CHECK(multi_round >= 20);
}

TEST_CASE("set cover: on components over 400 rows the fast effort branches only when the LP is close to the next integer") {
    // On one-component kernels of 400-550 rows whose cover stays at least three balls above the
    // LP (so that the fast effort does not run CBC), the bound beyond ceil(LP) can only come from
    // the branching step: it must not appear where the LP is further than kFastBranchShortfall
    // from the next integer, and it should where it is close.
    const Deadline far = Deadline::after(3600);
    Rng rng(1357);
    int close = 0, raised = 0, far_from = 0;
    for (int t = 0; t < 30; ++t) {
        const Coverage c = random_cover(rng, 450 + rng.below(100), 250 + rng.below(100), 0.015 + 0.01 * rng.uniform());
        const sc::Problem P = to_problem(c);
        const std::vector<double> y = sc::lp_duals(P, 0);
        REQUIRE(y.size() == P.R);
        // the reductions keep the LP's optimum, so this is forced + the kernel's LP
        const double lp = sc::lagrangian(P, all_columns(P), 1, far, &y).bound;
        const double ceil_lp = std::ceil(lp - 1e-6);
        CoverOptions fast;
        CoverResult a;
        REQUIRE(solve_set_cover(c, fast, false, Monitor{}, a).ok());
        CHECK(valid_cover(c, a.selected));
        if (a.rows_after <= kFastCbcMaxRows || a.components != 1 || a.objective < ceil_lp + 3) continue;
        INFO("instance " << t << ": LP " << lp << ", bound " << a.lower_bound << ", cover " << a.objective);
        CHECK(a.lower_bound >= ceil_lp);
        CHECK(a.lower_bound <= ceil_lp + 1);
        if (ceil_lp - lp <= kFastBranchShortfall) {
            ++close;
            raised += a.lower_bound == ceil_lp + 1;
        } else {
            ++far_from;
            CHECK(a.lower_bound == ceil_lp);
        }
    }
    CHECK(far_from >= 5);
    CHECK(close >= 3);
    CHECK(raised >= 3);
}

TEST_CASE("set cover: the prove effort keeps the bound of the branching step") {
    // Where the fast effort's branching step raised the bound above ceil(LP) (one-component
    // kernels of 400-550 rows, the cover at least three balls above the LP, as above), a prove
    // solve under a time limit too short for CBC to raise its own bound that far must report at
    // least that bound too: it runs the same step before CBC.
    Rng rng(1357);
    int raised = 0;
    for (int t = 0; t < 30; ++t) {
        const Coverage c = random_cover(rng, 450 + rng.below(100), 250 + rng.below(100), 0.015 + 0.01 * rng.uniform());
        const sc::Problem P = to_problem(c);
        const std::vector<double> y = sc::lp_duals(P, 0);
        REQUIRE(y.size() == P.R);
        const double lp = sc::lagrangian(P, all_columns(P), 1, Deadline::after(3600), &y).bound;
        const double ceil_lp = std::ceil(lp - 1e-6);
        CoverOptions fast;
        CoverResult a;
        REQUIRE(solve_set_cover(c, fast, false, Monitor{}, a).ok());
        if (a.rows_after <= kFastCbcMaxRows || a.components != 1 || a.objective < ceil_lp + 3) continue;
        if (a.lower_bound < ceil_lp + 1) continue;  // branching did not raise it
        ++raised;
        CoverOptions prove;
        prove.effort = Effort::prove;
        // a few times the fast solve (LP included), so that the LP also finishes on a slow machine;
        // a run whose limit ran out before the branching step ended (a loaded machine) is repeated
        // with twice the limit, at most twice, still far too short for CBC to prove the bound
        prove.time_limit_s = std::max(0.3, 5 * (a.time_reduce_s + a.time_solve_s));
        CoverResult b;
        REQUIRE(solve_set_cover(c, prove, false, Monitor{}, b).ok());
        for (int retry = 0; retry < 2 && b.lower_bound < a.lower_bound &&
                            b.time_reduce_s + b.time_solve_s >= 0.9 * prove.time_limit_s;
             ++retry) {
            prove.time_limit_s *= 2;
            REQUIRE(solve_set_cover(c, prove, false, Monitor{}, b).ok());
        }
        INFO("instance " << t << ": LP " << lp << ", fast bound " << a.lower_bound << ", prove bound " << b.lower_bound);
        CHECK(valid_cover(c, b.selected));
        CHECK(b.lower_bound <= b.objective);
        CHECK(b.lower_bound >= a.lower_bound);
    }
    CHECK(raised >= 3);
}

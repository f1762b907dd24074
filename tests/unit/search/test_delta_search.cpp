// test_delta_search.cpp: the delta search (lib/search/delta_search) driven by synthetic probes,
// HD(delta) and balls(delta) given as functions. With a non-monotone HD it finds the passing
// deltas the bracket-and-bisect phase misses (between and above failing probes, above the
// bracket); the best probe is the brute-force best of the probes run; it runs at most max_probes
// probes, deterministically; when nothing passes it returns the lowest HD, unreached.
#include <doctest/doctest.h>

#include "delta_search.h"

#include <cmath>
#include <functional>

namespace {

struct Fake {
    std::function<double(double)> hd;
    int keeps = 0;
    double kept_delta = 0;
};

// balls fall with delta, as a cover's size does
size_t balls_at(double d) { return size_t(std::lround(1.0 / d)); }

ca::DeltaSearchResult run(Fake& f, uint32_t max_probes = 14) {
    ca::DeltaSearchOptions o;
    o.start = 0.02;
    o.floor = 0.005;
    o.tolerance = 1e-4;
    o.target_error = 2;
    o.max_probes = max_probes;
    ca::DeltaSearchResult r;
    double last = 0;
    auto probe = [&](double d, ca::TargetErrorProbe& p) {
        last = d;
        p.delta = d;
        p.balls = balls_at(d);
        p.hd = f.hd(d);
        return ca::Status::success();
    };
    auto keep = [&] {
        ++f.keeps;
        f.kept_delta = last;
    };
    REQUIRE(ca::search_delta(o, probe, keep, r).ok());
    REQUIRE(!r.probes.empty());
    CHECK(r.runs <= max_probes);
    CHECK(r.runs == r.probes.size());
    // brute force over the probes run: nothing better than the returned one
    for (const ca::TargetErrorProbe& p : r.probes) {
        CHECK(p.passed == (p.hd <= 2));
        CHECK(!ca::better_probe(p, r.probes[r.best]));
    }
    CHECK(f.kept_delta == r.probes[r.best].delta);  // keep() ran for the returned probe
    return r;
}

}  // namespace

TEST_CASE("test_delta_search: every halving probe fails, a larger delta passes (cup with the fit)") {
    // fails at 0.02, 0.01, 0.005; passes only in [0.023, 0.032]
    Fake f{[](double d) { return d >= 0.023 && d <= 0.032 ? 1.5 : 2.5; }};
    const ca::DeltaSearchResult r = run(f);
    CHECK(r.probes[r.best].passed);
    CHECK(r.probes[r.best].delta >= 0.023);
}

TEST_CASE("test_delta_search: every halving probe fails, a delta between them passes (fertility with the fit)") {
    // passes only in [0.007, 0.008]
    Fake f{[](double d) { return d >= 0.007 && d <= 0.008 ? 1.0 : 2.2; }};
    const ca::DeltaSearchResult r = run(f);
    CHECK(r.probes[r.best].passed);
}

TEST_CASE("test_delta_search: a second passing interval above the bracket has fewer balls") {
    // passes up to 0.03, fails in (0.03, 0.041), passes again in [0.041, 0.06]
    Fake f{[](double d) { return d <= 0.03 || (d >= 0.041 && d <= 0.06) ? 1.8 : 2.4; }};
    const ca::DeltaSearchResult r = run(f);
    CHECK(r.probes[r.best].passed);
    CHECK(r.probes[r.best].delta >= 0.041);
}

TEST_CASE("test_delta_search: monotone HD: the best passing delta is close below the threshold") {
    Fake f{[](double d) { return 100 * d; }};  // passes for d <= 0.02
    const ca::DeltaSearchResult r = run(f);
    CHECK(r.probes[r.best].passed);
    CHECK(r.probes[r.best].delta == doctest::Approx(0.02));
}

TEST_CASE("test_delta_search: nothing passes: the lowest HD comes back unreached, within max_probes") {
    Fake f{[](double d) { return 3 + std::abs(d - 0.012); }};
    const ca::DeltaSearchResult r = run(f, 9);
    CHECK(!r.probes[r.best].passed);
    CHECK(r.runs == 9);
    // deterministic: the same probes in the same order
    Fake g{f.hd};
    const ca::DeltaSearchResult r2 = run(g, 9);
    REQUIRE(r2.probes.size() == r.probes.size());
    for (size_t i = 0; i < r.probes.size(); ++i) CHECK(r2.probes[i].delta == r.probes[i].delta);
}

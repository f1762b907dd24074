// test_steps.cpp: the C++ steps (lib/steps) and the C ABI agree on their defaults field by field
// (the C ABI's ca_*_defaults are converted from the C++ option structs); the steps' policy: the
// automatic route, the fit only where there is a mesh, a request checked before any work, and the
// cover kept by whatever runs at the defaults.
#include <doctest/doctest.h>

#include "coverage_axis.h"
#include "steps.h"
#include "support/shapes.h"
#include "support/skeleton_of.h"
#include "target_count_hd.h"
#include "target_error.h"
#include <algorithm>

TEST_CASE("defaults: every field of the C option structs is the C++ option structs' default") {
    ca_candidate_options c;
    ca_candidate_options_init(&c);
    const ca::CandidateOptions cc{};
    CHECK(c.generator == int32_t(cc.generator));
    CHECK(c.cover_samples == cc.cover_samples);
    CHECK(c.voronoi_samples == cc.voronoi_samples);
    CHECK(c.random_candidates == cc.random_candidates);
    CHECK(c.seed == cc.seed);
    CHECK(c.connect_samples == cc.connect_samples);
    CHECK((c.volumetric_only != 0) == cc.volumetric_only);

    ca_select_options s;
    ca_select_options_init(&s);
    const ca::SelectRequest sc{};
    CHECK(s.dilation == int32_t(sc.select.dilation));
    CHECK(s.delta == sc.select.delta);
    CHECK(s.scale == sc.select.scale);
    CHECK(s.solver == int32_t(sc.select.cover.solver));
    CHECK(s.time_limit_s == sc.select.cover.time_limit_s);
    CHECK((s.skip_uncoverable != 0) == sc.select.skip_uncoverable);
    CHECK((s.ignorable_samples == nullptr) == sc.select.cover.ignorable_samples.empty());
    CHECK((s.forced_in == nullptr) == sc.select.cover.forced_in.empty());
    CHECK((s.forced_out == nullptr) == sc.select.cover.forced_out.empty());
    CHECK(s.target_count == sc.select.target_count);
    CHECK(s.target_tolerance == sc.select.target_tolerance);
    CHECK(s.divide_threshold == sc.select.dc_threshold);
    CHECK(s.effort == int32_t(sc.select.cover.effort));
    CHECK(s.target_error == sc.target_error);
    CHECK(s.probe_fit == int32_t(sc.probe_fit));

    ca_connect_options k;
    ca_connect_options_init(&k);
    const ca::ConnectRequest kc{};
    CHECK(k.method == CA_CONNECT_AUTO);
    CHECK(k.method == int32_t(kc.connect.method));
    CHECK((k.remove_outside != 0) == kc.connect.remove_outside);
    CHECK((k.fill_holes != 0) == kc.connect.fill_holes);
    CHECK((k.reconnect != 0) == kc.connect.reconnect);
    CHECK(k.fit == int32_t(kc.fit));
    CHECK(k.fit_iterations == kc.fit_iterations);
    CHECK(uint32_t(kc.fit_iterations) == ca::FitOptions{}.iterations);

    ca_evaluate_options e;
    ca_evaluate_options_init(&e);
    const ca::EvaluateOptions ec{};
    CHECK(e.surface_samples == ec.surface_samples);
    CHECK(e.envelope_samples == ec.envelope_samples);
    CHECK(e.seed == ec.seed);

    ca_proxy_options px;
    ca_proxy_options_init(&px);
    const ca::ProxyOptions pc{};
    CHECK(px.shapes == int32_t(pc.shapes));
    CHECK(px.mode == int32_t(pc.mode));
    CHECK(px.count == pc.count);
    CHECK(px.surface_samples == pc.surface_samples);
    CHECK(px.evaluate_samples == pc.evaluate_samples);
    CHECK(px.volume_samples == pc.volume_samples);
    CHECK(px.seed == pc.seed);
    CHECK(px.shapes == CA_PROXY_SHAPES_CAPSULES);
    CHECK(px.mode == CA_PROXY_INSCRIBED);

    ca_surface_view v;
    ca_surface_view_init(&v);
    CHECK(v.point_normals == int32_t(ca::SurfaceInput{}.point_normals));

    // the searches' own defaults judge probes as the steps' defaults do
    CHECK(ca::TargetErrorOptions{}.connect.method == kc.connect.method);
    CHECK(ca::TargetCountHdOptions{}.connect.method == kc.connect.method);
}

TEST_CASE("steps: the automatic route, the fit on meshes only, and requests checked before any work") {
    ca::CandidateOptions co;
    co.cover_samples = 300;
    co.voronoi_samples = 800;
    ca::SurfaceInput surface;
    surface.mesh = shapes::capsule(2.0, 0.5, 32, 16);
    ca::CandidateSet set;
    REQUIRE(ca::candidates_step(surface, co, ca::Monitor{}, set).ok());
    ca::SelectRequest sr;
    sr.select.cover.time_limit_s = 0;
    ca::SelectResult sel;
    REQUIRE(ca::select_step(set, sr, ca::Monitor{}, sel).ok());
    CHECK(sel.hd_reached == -1);  // a plain cover measures nothing

    ca::ConnectRequest kr;
    ca::ConnectResult k;
    REQUIRE(ca::connect_step(set, sel.selection, kr, ca::Monitor{}, k).ok());
    CHECK(k.report.method == ca::ConnectMethod::medial);  // a mesh has its winding number
    CHECK(kr.fit == ca::FitMode::automatic);
    CHECK(!k.fitted);  // automatic: a plain cover stays unfitted, its balls cover every sample
    CHECK(!sel.selection.sized_by_count);
    {   // automatic: a selection sized by target_count is fitted thoroughly (two fits, one kept)
        ca::SelectRequest sized = sr;
        sized.select.target_count = uint32_t(std::max<size_t>(2, sel.selection.indices.size() - 1));
        ca::SelectResult small;
        REQUIRE(ca::select_step(set, sized, ca::Monitor{}, small).ok());
        CHECK(small.selection.sized_by_count);
        ca::ConnectResult f;
        REQUIRE(ca::connect_step(set, small.selection, kr, ca::Monitor{}, f).ok());
        CHECK(f.fitted);
        CHECK(f.fit.hd_first > 0);  // the thorough fit measured both of its fits
        ca::ConnectRequest off;
        off.fit = ca::FitMode::off;
        REQUIRE(ca::connect_step(set, small.selection, off, ca::Monitor{}, f).ok());
        CHECK(!f.fitted);
    }
    kr.fit = ca::FitMode::once;
    kr.fit_iterations = 2;
    REQUIRE(ca::connect_step(set, sel.selection, kr, ca::Monitor{}, k).ok());
    CHECK(k.fitted);
    CHECK(k.fit.error_after <= k.fit.error_before);
    {   // the covered fit through the step: the cover kept, the added balls after the selected ones
        ca::ConnectRequest covered = kr;
        covered.fit = ca::FitMode::covered;
        ca::ConnectResult c;
        REQUIRE(ca::connect_step(set, sel.selection, covered, ca::Monitor{}, c).ok());
        CHECK(c.fitted);
        CHECK(c.fit.uncovered == 0);
        CHECK(c.skeleton.balls.size() == sel.selection.indices.size() + c.fit.added);
    }

    // the same balls from caller arrays: no surface, so the power route and no fit
    std::vector<ca::Vec3> samples, centers;
    std::vector<double> radii;
    for (const ca::Vec3& p : set.cover_samples) samples.push_back(set.surface.norm.to_user(p));
    for (const ca::Ball& b : set.balls) {
        centers.push_back(set.surface.norm.to_user(b.center));
        radii.push_back(b.radius * set.surface.norm.scale);
    }
    ca::CandidateSet bare;
    REQUIRE(ca::candidates_from_arrays(samples, centers, radii, set.surface.norm.scale, bare).ok());
    ca::SelectResult bare_sel;
    REQUIRE(ca::select_step(bare, sr, ca::Monitor{}, bare_sel).ok());
    REQUIRE(ca::connect_step(bare, bare_sel.selection, kr, ca::Monitor{}, k).ok());
    CHECK(k.report.method == ca::ConnectMethod::power);
    CHECK(!k.fitted);

    // bad requests fail before any work, naming the field (the monitor says stop: the checks come first)
    std::atomic<int> cancel{1};
    ca::Monitor stopped;
    stopped.cancel_flag = &cancel;
    ca::ConnectRequest bad_connect;
    bad_connect.fit = static_cast<ca::FitMode>(4);
    ca::Status st = ca::connect_step(set, sel.selection, bad_connect, stopped, k);
    CHECK(st.code == ca::Code::invalid_argument);
    CHECK(st.message.find("fit") != std::string::npos);
    bad_connect = ca::ConnectRequest{};
    bad_connect.fit_iterations = -1;
    CHECK(ca::connect_step(set, sel.selection, bad_connect, stopped, k).code == ca::Code::invalid_argument);
    ca::SelectRequest bad = sr;
    bad.probe_fit = ca::FitMode::thorough;
    st = ca::select_step(set, bad, stopped, sel);
    CHECK(st.code == ca::Code::invalid_argument);
    CHECK(st.message.find("probe_fit") != std::string::npos);
    bad = sr;
    bad.select.cover.forced_in.assign(set.balls.size() + 1, 0);
    st = ca::select_step(set, bad, stopped, sel);
    CHECK(st.code == ca::Code::invalid_input);
    CHECK(st.message.find("forced_in") != std::string::npos);
    ca::CandidateOptions bad_generator = co;
    bad_generator.generator = static_cast<ca::Generator>(7);
    CHECK(ca::candidates_step(surface, bad_generator, stopped, set).code == ca::Code::invalid_argument);
}

TEST_CASE("steps: the defaults keep the cover: every cover sample lies within r + delta of a skeleton ball") {
    // Whatever runs by default after the selection (the route, its repairs, the automatic fit)
    // must leave the method's promise intact; checked by brute force over the skeleton's balls.
    for (const char* name : {"fox.obj", "cow_spot.obj"}) {
        CAPTURE(name);
        ca::SurfaceInput surface;
        surface.mesh = test_model(name);
        ca::CandidateSet set;
        ca::Status st = ca::candidates_step(surface, ca::CandidateOptions{}, ca::Monitor{}, set);
        REQUIRE_MESSAGE(st.ok(), st.message);
        ca::SelectResult sel;
        st = ca::select_step(set, ca::SelectRequest{}, ca::Monitor{}, sel);
        REQUIRE_MESSAGE(st.ok(), st.message);
        ca::ConnectResult k;
        st = ca::connect_step(set, sel.selection, ca::ConnectRequest{}, ca::Monitor{}, k);
        REQUIRE_MESSAGE(st.ok(), st.message);
        REQUIRE(k.skeleton.balls.size() >= sel.selection.indices.size());
        const double delta = sel.selection.delta;
        REQUIRE(delta > 0);
        size_t uncovered = 0;
        for (const ca::Vec3& s : set.cover_samples) {
            bool covered = false;
            for (const ca::Ball& b : k.skeleton.balls)
                if ((b.center - s).norm() <= b.radius + delta * (1 + 1e-9)) {
                    covered = true;
                    break;
                }
            uncovered += !covered;
        }
        CHECK(set.cover_samples.size() >= 1000);
        CHECK(uncovered == 0);
    }
}

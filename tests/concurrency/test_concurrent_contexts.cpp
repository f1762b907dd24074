// test_concurrent_contexts.cpp: several contexts in threads of one process run the whole pipeline
// through the C ABI at once (the exact solver at the prove effort with a small delta, so that
// Clp's LPs run in every job and CBC in most) and each gives exactly what a run alone gave: the
// same balls, the same skeleton.
// Built in the normal suite, and in a build with -DCA_TSAN=ON (`make tsan`) under ThreadSanitizer,
// which then also reports any data race between the contexts.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "coverage_axis.h"
#include "mesh_io.h"
#include "surface_view.h"

#include <atomic>
#include <string>
#include <thread>
#include <vector>

namespace {

struct Outcome {
    ca_status status = CA_OK;
    std::string message;
    std::vector<uint32_t> balls;
    std::vector<uint32_t> edges, faces;
    uint64_t cbc_components = 0;
    int32_t proven = 0;
};

bool operator==(const Outcome& a, const Outcome& b) {
    return a.status == b.status && a.balls == b.balls && a.edges == b.edges && a.faces == b.faces &&
           a.cbc_components == b.cbc_components && a.proven == b.proven;
}

// The pipeline on `mesh` in a context of its own with `threads` worker threads; the exact solver
// at the prove effort without a time limit, so the result depends on nothing but the input and
// the seed.
Outcome run(const caio::MeshData& mesh, int threads) {
    Outcome o;
    ca_context_desc desc;
    ca_context_desc_init(&desc);
    desc.threads = threads;
    ca_context* ctx = nullptr;
    if (ca_context_create(&desc, &ctx) != CA_OK) {
        o.status = CA_ERROR_OUT_OF_MEMORY;
        return o;
    }
    const ca_surface_view v = caio::surface_view(mesh);
    ca_candidate_options co;
    ca_candidate_options_init(&co);
    co.voronoi_samples = 1000;
    co.connect_samples = 1500;
    ca_select_options so;
    ca_select_options_init(&so);
    so.effort = CA_EFFORT_PROVE;
    so.time_limit_s = 0;
    so.delta = 0.01;  // a larger kernel than the default's: on these meshes CBC then has a gap to close
    ca_connect_options cop;
    ca_connect_options_init(&cop);
    ca_candidate_set* set = nullptr;
    ca_selection* sel = nullptr;
    ca_skeleton* sk = nullptr;
    o.status = ca_candidates(ctx, &v, &co, &set);
    if (o.status == CA_OK) o.status = ca_select(ctx, set, &so, &sel);
    if (o.status == CA_OK) {
        const uint32_t* idx = ca_selection_indices(sel);
        o.balls.assign(idx, idx + ca_selection_count(sel));
        ca_select_stats ss;
        ss.struct_size = sizeof ss;
        ca_selection_stats(sel, &ss);
        o.cbc_components = ss.cbc_components;
        o.proven = ss.proven_optimal;
        o.status = ca_connect(ctx, set, sel, &cop, &sk);
    }
    if (o.status == CA_OK) {
        ca_skeleton_view kv;
        ca_skeleton_view_init(&kv);
        ca_skeleton_get_view(sk, &kv);
        o.edges.assign(kv.edges, kv.edges + 2 * kv.edge_count);
        o.faces.assign(kv.faces, kv.faces + 3 * kv.face_count);
    } else {
        o.message = ca_context_last_error(ctx);
    }
    ca_skeleton_destroy(sk);
    ca_selection_destroy(sel);
    ca_candidate_set_destroy(set);
    ca_context_destroy(ctx);
    return o;
}

}  // namespace

TEST_CASE("contexts in several threads give what each gives alone, CBC and Clp included") {
    const std::string dir = CA_TEST_DATA;
    std::vector<caio::MeshData> meshes;
    for (const char* name : {"fox.obj", "fish.obj", "cow_spot.obj"}) {
        caio::MeshData m;
        std::string err;
        REQUIRE_MESSAGE(caio::read_mesh(dir + "/" + name, m, err), name, ": ", err);
        meshes.push_back(std::move(m));
    }
    // alone, one after the other, one worker thread each
    std::vector<Outcome> alone;
    uint64_t cbc = 0;
    for (const caio::MeshData& m : meshes) {
        alone.push_back(run(m, 1));
        REQUIRE_MESSAGE(alone.back().status == CA_OK, alone.back().message);
        CHECK(!alone.back().balls.empty());
        cbc += alone.back().cbc_components;
    }
    CHECK(cbc > 0);  // the inputs make CBC run: its mutex and the Clp calls beside it are exercised

    // kJobs threads, each running every mesh in its own order (so different stages and solver
    // calls overlap), half of them with two worker threads of their own
    constexpr int kJobs = 3;
    std::vector<std::vector<Outcome>> got(kJobs, std::vector<Outcome>(meshes.size()));
    std::vector<std::thread> pool;
    for (int j = 0; j < kJobs; ++j)
        pool.emplace_back([&, j] {
            for (size_t k = 0; k < meshes.size(); ++k) {
                const size_t i = (k + size_t(j)) % meshes.size();
                got[size_t(j)][i] = run(meshes[i], 1 + j % 2);
            }
        });
    for (auto& t : pool) t.join();
    for (int j = 0; j < kJobs; ++j)
        for (size_t i = 0; i < meshes.size(); ++i) {
            INFO("job ", j, ", mesh ", i);
            CHECK(got[size_t(j)][i] == alone[i]);
        }
}

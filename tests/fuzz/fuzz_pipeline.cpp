// fuzz_pipeline.cpp: libFuzzer harness for the C ABI. The input bytes become a mesh or point
// cloud (vertex count, coordinates drawn from the bytes, including NaN/Inf/huge values, triangle
// indices possibly out of range) and small option values; the whole pipeline runs with small
// sample counts. Any crash, sanitizer report or a status outside the pinned set is a bug; a
// non-OK status must leave the output NULL. Build: make fuzz (clang); run: build-fuzz/fuzz_pipeline.
#include "coverage_axis.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

struct Reader {
    const uint8_t* p;
    size_t n;
    template <class T> T get() {
        T v{};
        if (n >= sizeof(T)) { std::memcpy(&v, p, sizeof(T)); p += sizeof(T); n -= sizeof(T); }
        return v;
    }
};

void check(ca_status st, const void* out) {
    if (st < CA_OK || st > CA_ERROR_NO_CANDIDATES) std::abort();
    if (st != CA_OK && out != nullptr) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    Reader r{data, size};
    const uint8_t nv = r.get<uint8_t>(), nt = r.get<uint8_t>(), flags = r.get<uint8_t>();
    std::vector<double> pos(3 * size_t(nv)), nrm(3 * size_t(nv));
    for (double& x : pos) {
        const int8_t q = r.get<int8_t>();
        x = q == -128 ? (flags & 1 ? NAN : 1e300) : q / 16.0;
    }
    for (double& x : nrm) x = r.get<int8_t>() / 16.0;
    std::vector<uint32_t> tri(3 * size_t(nt));
    for (uint32_t& i : tri) i = r.get<uint8_t>() % (nv + 2);  // sometimes out of range

    ca_context* ctx = nullptr;
    if (ca_context_create(nullptr, &ctx) != CA_OK) return 0;
    ca_surface_view v;
    ca_surface_view_init(&v);
    v.positions = pos.data();
    v.vertex_count = nv;
    v.triangles = tri.data();
    v.triangle_count = nt;
    v.normals = flags & 2 ? nrm.data() : nullptr;
    ca_candidate_options co;
    ca_candidate_options_init(&co);
    co.cover_samples = 50 + (flags >> 2) * 10;
    co.voronoi_samples = 100;
    co.random_candidates = 200;
    co.generator = flags & 4 ? CA_CANDIDATES_RANDOM : CA_CANDIDATES_VORONOI;
    ca_candidate_set* set = nullptr;
    ca_status st = ca_candidates(ctx, &v, &co, &set);
    check(st, set);
    if (st == CA_OK) {
        ca_select_options so;
        ca_select_options_init(&so);
        so.delta = (flags & 8) ? 0.0 : 0.05;
        so.skip_uncoverable = flags & 16 ? 1 : 0;
        so.time_limit_s = 1;
        so.solver = (flags >> 5) % 3;
        ca_selection* sel = nullptr;
        st = ca_select(ctx, set, &so, &sel);
        check(st, sel);
        if (st == CA_OK) {
            ca_skeleton* sk = nullptr;
            st = ca_connect(ctx, set, sel, nullptr, &sk);
            check(st, sk);
            if (st == CA_OK) {
                ca_skeleton_view view;
                ca_skeleton_view_init(&view);
                ca_skeleton_get_view(sk, &view);
                ca_evaluate_options eo;
                ca_evaluate_options_init(&eo);
                eo.surface_samples = 200;
                eo.envelope_samples = 500;
                ca_evaluation e;
                e.struct_size = sizeof e;
                check(ca_evaluate(ctx, &v, &view, &eo, &e), nullptr);
            }
            ca_skeleton_destroy(sk);
        }
        ca_selection_destroy(sel);
    }
    ca_candidate_set_destroy(set);
    ca_context_destroy(ctx);
    return 0;
}

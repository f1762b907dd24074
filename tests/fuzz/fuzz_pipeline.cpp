// fuzz_pipeline.cpp: libFuzzer harness for the C ABI's whole pipeline. The input has a structure
// (tests/fuzz/make_seeds.py writes real small meshes in it, the seed corpus), so mutations stay
// meshes and reach the deep steps instead of dying at the first check:
//   8 option bytes   generator, point cloud, solver, dilation, sample counts, delta, target
//                    count, connect flags, coordinate scale (powers of two up to 2^±1016),
//                    padded strides, a tiny context time limit
//   u16 nv, u16 nt   vertex and triangle counts (cut to what the bytes hold)
//   nv * 3 float32   coordinates (any bit pattern: NaN, Inf, denormals)
//   nt * 3 u16       indices, taken modulo nv + 2 (sometimes out of range, sometimes == nv)
//   nv * 3 int8      normals / 64 (point clouds)
// Any crash, sanitizer report, a status outside the pinned set, or a non-NULL output after a
// failure is a bug. Build and run: make fuzz (FUZZ_SECONDS) or make fuzz-long (10 minutes).
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
    if (st < CA_OK || st > CA_ERROR_TIME_LIMIT || st == CA_ERROR_INTERNAL) std::abort();
    if (st != CA_OK && out != nullptr) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    Reader r{data, size};
    uint8_t opt[8];
    for (uint8_t& b : opt) b = r.get<uint8_t>();
    size_t nv = r.get<uint16_t>(), nt = r.get<uint16_t>();
    const bool cloud = opt[0] & 2;
    const size_t per_vertex = 12 + (cloud ? 3 : 0);
    nv = std::min(nv, r.n / per_vertex);
    nt = cloud ? 0 : std::min(nt, (r.n - nv * per_vertex) / 6);
    // Padded strides (opt[7] bit 0) exercise the strided reads: 4 doubles per vertex, 4 indices.
    const size_t pw = opt[7] & 1 ? 4 : 3, tw = opt[7] & 1 ? 4 : 3;
    const double scale = std::ldexp(1.0, int(int8_t(opt[6])) * 8);
    std::vector<double> pos(pw * nv + 1), nrm(3 * nv + 1);
    std::vector<uint32_t> tri(tw * nt + 1);
    for (size_t i = 0; i < nv; ++i)
        for (int k = 0; k < 3; ++k) pos[pw * i + k] = double(r.get<float>()) * scale;
    for (size_t i = 0; i < nt; ++i)
        for (int k = 0; k < 3; ++k) tri[tw * i + k] = uint32_t(r.get<uint16_t>() % (nv + 2));
    for (size_t i = 0; i < 3 * nv && cloud; ++i) nrm[i] = r.get<int8_t>() / 64.0;

    ca_context_desc cd;
    ca_context_desc_init(&cd);
    cd.threads = 1;
    cd.time_limit_s = opt[7] & 2 ? 1e-3 : 5;
    ca_context* ctx = nullptr;
    if (ca_context_create(&cd, &ctx) != CA_OK) return 0;
    ca_surface_view v;
    ca_surface_view_init(&v);
    v.positions = pos.data();
    v.vertex_count = nv;
    v.position_stride = pw * sizeof(double);
    v.triangles = tri.data();
    v.triangle_count = nt;
    v.triangle_stride = tw * sizeof(uint32_t);
    v.normals = cloud ? nrm.data() : nullptr;
    v.normal_count = cloud ? nv : 0;
    ca_candidate_options co;
    ca_candidate_options_init(&co);
    co.generator = opt[0] & 1 ? CA_CANDIDATES_RANDOM : CA_CANDIDATES_VORONOI;
    co.cover_samples = 20 + opt[1] % 128;
    co.voronoi_samples = 40 + opt[2] % 256;
    co.random_candidates = 100 + opt[2];
    co.connect_samples = 200 + opt[1];
    co.seed = opt[3];
    ca_candidate_set* set = nullptr;
    ca_status st = ca_candidates(ctx, &v, &co, &set);
    check(st, set);
    if (st == CA_OK) {
        ca_select_options so;
        ca_select_options_init(&so);
        so.dilation = opt[0] & 8 ? CA_DILATE_SCALE : CA_DILATE_OFFSET;
        so.delta = opt[3] / 1000.0;
        so.scale = 1.0 + opt[3] / 256.0;
        so.skip_uncoverable = opt[0] & 4 ? 1 : 0;
        so.time_limit_s = 1;
        so.solver = (opt[0] >> 4) % 3;
        so.effort = opt[0] & 64 ? CA_EFFORT_PROVE : CA_EFFORT_FAST;
        so.target_count = opt[4] & 0x80 ? opt[4] % 16 : 0;
        so.divide_threshold = opt[4] & 0x40 ? 10 + opt[4] % 32 : 100000;
        ca_selection* sel = nullptr;
        st = ca_select(ctx, set, &so, &sel);
        check(st, sel);
        if (st == CA_OK) {
            ca_connect_options cn;
            ca_connect_options_init(&cn);
            cn.method = opt[5] % 3;
            cn.remove_outside = (opt[5] >> 2) & 1;
            cn.fill_holes = (opt[5] >> 3) & 1;
            cn.reconnect = (opt[5] >> 4) & 1;
            ca_skeleton* sk = nullptr;
            st = ca_connect(ctx, set, sel, &cn, &sk);
            check(st, sk);
            if (st == CA_OK) {
                ca_skeleton_view view;
                ca_skeleton_view_init(&view);
                check(ca_skeleton_get_view(sk, &view), nullptr);
                ca_evaluate_options eo;
                ca_evaluate_options_init(&eo);
                eo.surface_samples = 100 + opt[5];
                eo.envelope_samples = 200 + opt[5];
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

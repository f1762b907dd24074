// ca_proxies.cpp: engine proxies at the C boundary: the options and the skeleton view converted for
// the core's step (lib/steps/proxies_step.cpp), the primitives' arrays and stats in the caller's
// units, and their getters. A proxy set copies what it needs (results.h): it outlives its set and
// skeleton.
#include "conversions.h"
#include "results.h"

using ca::Status;
using namespace capi;

namespace {

void publish(ca_proxy_set& r, const ca::ProxyResult& p) {
    const size_t n = p.proxies.size();
    r.kinds.assign(r.allocator, n);
    r.centers.assign(r.allocator, 6 * n);
    r.radii.assign(r.allocator, 2 * n);
    r.frames.assign(r.allocator, 12 * n);
    for (size_t i = 0; i < n; ++i) {
        const ca::Proxy& q = p.proxies[i];
        r.kinds.data[i] = static_cast<int32_t>(q.kind);
        for (int k = 0; k < 9; ++k) r.frames.data[12 * i + size_t(k)] = q.axes(k % 3, k / 3);
        for (int k = 0; k < 3; ++k) r.frames.data[12 * i + 9 + size_t(k)] = q.half[k];
        for (int k = 0; k < 3; ++k) {
            r.centers.data[6 * i + size_t(k)] = q.a.center[k];
            r.centers.data[6 * i + 3 + size_t(k)] = q.b.center[k];
        }
        r.radii.data[2 * i] = q.a.radius;
        r.radii.data[2 * i + 1] = q.b.radius;
    }
    const ca::ProxyStats& s = p.stats;
    ca_proxy_stats& o = r.stats;
    o = zeroed<ca_proxy_stats>();
    o.hd_surface_to_proxies = s.hd_surface_to_proxies;
    o.mean_surface_to_proxies = s.mean_surface_to_proxies;
    o.hd_proxies_to_surface = s.hd_proxies_to_surface;
    o.mean_proxies_to_surface = s.mean_proxies_to_surface;
    o.hd_two_sided = s.hd_two_sided;
    o.outside_bound = s.outside_bound;
    o.skeleton_outside = s.skeleton_outside;
    o.union_volume = s.union_volume;
    o.outside_volume = s.outside_volume;
    o.radius_change = s.radius_change;
    o.diagonal = s.diagonal;
    o.candidates = s.candidates;
    o.surface_cells = s.surface_cells;
    o.time_s = s.time_s;
}

// Primitive i of a set, as the core holds it.
ca::Proxy proxy_at(const ca_proxy_set& r, size_t i) {
    ca::Proxy q;
    q.kind = static_cast<ca::ProxyKind>(r.kinds.data[i]);
    for (int k = 0; k < 3; ++k) {
        q.a.center[k] = r.centers.data[6 * i + size_t(k)];
        q.b.center[k] = r.centers.data[6 * i + 3 + size_t(k)];
    }
    q.a.radius = r.radii.data[2 * i];
    q.b.radius = r.radii.data[2 * i + 1];
    for (int k = 0; k < 9; ++k) q.axes(k % 3, k / 3) = r.frames.data[12 * i + size_t(k)];
    for (int k = 0; k < 3; ++k) q.half[k] = r.frames.data[12 * i + 9 + size_t(k)];
    return q;
}

}  // namespace

extern "C" {

ca_status ca_proxies(ca_context* ctx, const ca_candidate_set* set, const ca_skeleton_view* skeleton,
                     const ca_proxy_options* options, ca_proxy_set** out) {
    if (out) *out = nullptr;
    return capi::guarded(ctx, [&]() -> Status {
        ca_proxy_options o;
        Status st = read_arguments({{out, "out"}, {set, "set"}, {skeleton, "skeleton"}}, options, o);
        if (!st.ok()) return st;
        ca::Skeleton sk;
        st = read_skeleton(skeleton, sk);
        if (!st.ok()) return st;
        ca::ProxyResult result;
        st = ca::proxies_step(set->core, sk, to_core(o, ctx->desc.threads), ctx->monitor(), result);
        if (!st.ok()) return st;
        capi::Pending<ca_proxy_set> res(capi::make_result<ca_proxy_set>(ctx));
        publish(*res.obj, result);
        *out = res.release();
        return Status::success();
    });
}

void ca_proxy_set_destroy(ca_proxy_set* p) { destroy_result(p); }
size_t ca_proxy_set_count(const ca_proxy_set* p) { return p ? p->kinds.size : 0; }
const int32_t* ca_proxy_set_kinds(const ca_proxy_set* p) { return p ? p->kinds.data : nullptr; }
const double* ca_proxy_set_centers(const ca_proxy_set* p) { return p ? p->centers.data : nullptr; }
const double* ca_proxy_set_radii(const ca_proxy_set* p) { return p ? p->radii.data : nullptr; }

ca_status ca_proxy_set_stats(const ca_proxy_set* p, ca_proxy_stats* stats) {
    if (!p || !stats) return CA_ERROR_NULL_POINTER;
    return guarded_status([&] { return write_output(p->stats, stats); });
}

ca_status ca_proxy_set_placement(const ca_proxy_set* p, size_t index, ca_proxy_placement* placement) {
    if (!p || !placement) return CA_ERROR_NULL_POINTER;
    return guarded_status([&]() -> Status {
        if (index >= p->kinds.size)
            return ca::fail(ca::Code::invalid_argument, "proxy index " + std::to_string(index) + " out of range (" +
                                                            std::to_string(p->kinds.size) + " primitives)");
        const ca_proxy_placement o = to_c(ca::proxy_placement(proxy_at(*p, index)));
        return write_output(o, placement);
    });
}

}  // extern "C"

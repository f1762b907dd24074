// ca_evaluate.cpp: the evaluation at the C boundary: a skeleton view (from ca_skeleton_get_view
// or the caller's own arrays) measured against the input surface.
#include "conversions.h"
#include "results.h"
#include "struct_size.h"

#include "evaluate.h"

#include <algorithm>
#include <chrono>
#include <cmath>

using ca::Code;
using ca::Status;
using ca::Vec3;
using namespace capi;

extern "C" {

ca_status ca_evaluate(ca_context* ctx, const ca_surface_view* surface, const ca_skeleton_view* skeleton_in,
                      const ca_evaluate_options* options, ca_evaluation* result) {
    return capi::guarded(ctx, [&]() -> Status {
        Status st = check_pointers({{surface, "surface"}, {skeleton_in, "skeleton"}, {result, "result"}});
        if (!st.ok()) return st;
        st = check_struct_size<ca_evaluation>(result->struct_size);
        if (!st.ok()) return st;
        ca_skeleton_view view;
        st = read_input(skeleton_in, view);
        if (!st.ok()) return st;
        const ca_skeleton_view* skeleton = &view;
        ca_evaluate_options o;
        st = read_input(options, o);
        if (!st.ok()) return st;
        if (o.surface_samples == 0 || o.envelope_samples == 0)
            return ca::fail(Code::invalid_argument, "surface_samples and envelope_samples must be at least 1");
        const ca::Monitor monitor = ctx->monitor();  // one budget for the whole call
        ca::Mesh raw;
        std::vector<Vec3> normals;
        st = read_surface(surface, false, raw, normals);
        if (!st.ok()) return st;
        ca::Surface surf;
        st = ca::prepare_surface(std::move(raw), {}, surf, false);
        if (!st.ok()) return st;
        if (monitor.stopped()) return monitor.stop_status("surface");

        const size_t nv = skeleton->vertex_count;
        if (nv == 0) return ca::fail(Code::degenerate_input, "the skeleton has no vertices");
        if (!skeleton->centers) return null_pointer("skeleton->centers");
        if (!skeleton->radii) return null_pointer("skeleton->radii");
        if (skeleton->edge_count && !skeleton->edges) return null_pointer("skeleton->edges");
        if (skeleton->face_count && !skeleton->faces) return null_pointer("skeleton->faces");
        if (nv > UINT32_MAX || skeleton->edge_count > UINT32_MAX || skeleton->face_count > UINT32_MAX)
            return ca::fail(Code::invalid_argument, "skeleton: more than 2^32 - 1 vertices, edges or faces");
        ca::Skeleton sk;
        const ca::Normalization& n = surf.norm;
        for (size_t i = 0; i < nv; ++i) {
            const Vec3 c(skeleton->centers[3 * i], skeleton->centers[3 * i + 1], skeleton->centers[3 * i + 2]);
            const double r = skeleton->radii[i];
            if (!c.allFinite() || !(std::isfinite(r) && r >= 0))
                return ca::fail(Code::invalid_input, "skeleton ball " + std::to_string(i) + " has a NaN, infinite or negative value");
            sk.balls.push_back({n.to_internal(c), r / n.scale});
        }
        for (size_t e = 0; e < skeleton->edge_count; ++e) {
            const uint32_t a = skeleton->edges[2 * e], b = skeleton->edges[2 * e + 1];
            if (a >= nv || b >= nv)
                return ca::fail(Code::invalid_input, "skeleton edge " + std::to_string(e) + " references vertex " +
                                                         std::to_string(std::max(a, b)) + " of " + std::to_string(nv));
            sk.edges.push_back({a, b});
        }
        for (size_t f = 0; f < skeleton->face_count; ++f) {
            ca::Tri t{skeleton->faces[3 * f], skeleton->faces[3 * f + 1], skeleton->faces[3 * f + 2]};
            for (uint32_t v : t)
                if (v >= nv)
                    return ca::fail(Code::invalid_input, "skeleton face " + std::to_string(f) + " references vertex " +
                                                             std::to_string(v) + " of " + std::to_string(nv));
            sk.faces.push_back(t);
        }
        ca::EvaluateOptions eo;
        eo.surface_samples = o.surface_samples;
        eo.envelope_samples = o.envelope_samples;
        eo.seed = o.seed;
        eo.threads = ctx->desc.threads;
        const auto t0 = std::chrono::steady_clock::now();
        ca::EvaluateResult er;
        st = ca::evaluate(surf.mesh, sk, eo, monitor, er);
        if (!st.ok()) return st;
        ca_evaluation out{};
        out.struct_size = sizeof out;
        out.hd_surface_to_recon = er.hd_surface_to_recon;
        out.mean_surface_to_recon = er.mean_surface_to_recon;
        out.hd_recon_to_surface = er.hd_recon_to_surface;
        out.mean_recon_to_surface = er.mean_recon_to_surface;
        out.hd_two_sided = er.hd_two_sided;
        out.diagonal = er.diagonal * n.scale;
        out.surface_samples_used = er.surface_samples_used;
        out.envelope_samples_used = er.envelope_samples_used;
        out.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return write_output(out, result);
    });
}

}  // extern "C"

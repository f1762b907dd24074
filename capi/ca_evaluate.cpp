// ca_evaluate.cpp: the evaluation at the C boundary: the surface view and a skeleton view (from
// ca_skeleton_get_view or the caller's own arrays) converted for the core's step
// (lib/steps/evaluate_step.cpp), and its result written to the caller's struct.
#include "conversions.h"

using ca::Status;
using ca::Vec3;
using namespace capi;

extern "C" {

ca_status ca_evaluate(ca_context* ctx, const ca_surface_view* surface, const ca_skeleton_view* skeleton,
                      const ca_evaluate_options* options, ca_evaluation* result) {
    return capi::guarded(ctx, [&]() -> Status {
        ca_evaluate_options o;
        Status st = read_arguments({{surface, "surface"}, {skeleton, "skeleton"}, {result, "result"}}, options, o);
        if (!st.ok()) return st;
        st = check_struct_size<ca_evaluation>(result->struct_size);
        if (!st.ok()) return st;
        const ca::Monitor monitor = ctx->monitor();  // one budget for the whole call
        ca::SurfaceInput input;
        ca::Skeleton sk;
        st = read_surface_and_skeleton(surface, skeleton, input, sk);
        if (!st.ok()) return st;
        ca::EvaluateResult er;
        st = ca::evaluate_step(std::move(input), sk, to_core(o, ctx->desc.threads), monitor, er);
        if (!st.ok()) return st;
        ca_evaluation e = zeroed<ca_evaluation>();
        e.hd_surface_to_recon = er.hd_surface_to_recon;
        e.mean_surface_to_recon = er.mean_surface_to_recon;
        e.hd_recon_to_surface = er.hd_recon_to_surface;
        e.mean_recon_to_surface = er.mean_recon_to_surface;
        e.hd_two_sided = er.hd_two_sided;
        e.diagonal = er.diagonal;
        e.surface_samples_used = er.surface_samples_used;
        e.envelope_samples_used = er.envelope_samples_used;
        e.time_s = er.time_s;
        return write_output(e, result);
    });
}

}  // extern "C"

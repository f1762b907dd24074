// candidates.cpp: the candidate step's entry (generate_candidates): checks the options, samples the
// surface, builds the surface structures beside the chosen generator (voronoi.cpp,
// random_candidates.cpp, point_cloud.cpp), then clamps to hole caps and adds fallback balls and
// surface balls.
#include "candidates_internal.h"

#include "sampling.h"
#include "timing.h"

#include <chrono>
#include <memory>

namespace ca {

using namespace cand;


Status generate_candidates(Surface surface, const CandidateOptions& opt, const Monitor& monitor, CandidateSet& out) {
    out = CandidateSet{};
    out.surface = std::move(surface);
    const SurfaceKind kind = out.surface.kind();
    if (opt.cover_samples == 0 && !kind.is_cloud())
        return fail(Code::invalid_argument, "cover_samples must be at least 1");
    if (opt.generator == Generator::voronoi && opt.voronoi_samples < 5 && !kind.is_cloud())
        return fail(Code::invalid_argument, "voronoi_samples must be at least 5");
    if (opt.generator == Generator::random && opt.random_candidates == 0)
        return fail(Code::invalid_argument, "random_candidates must be at least 1");
    const int threads = resolve_threads(opt.threads);

    auto t0 = Clock::now();
    if (!monitor.report("sampling", 0)) return monitor.stop_status("sampling");
    Status st;
    if (kind.is_cloud()) {
        out.report.time_sampling_s = seconds_since(t0);
        st = point_cloud_candidates(opt, monitor, threads, out);
    } else {
        // The surface trees are built on a second thread while this one builds the hole caps' tree,
        // samples and runs the Delaunay step (the same structures either way); they only read the mesh.
        SurfaceStructures built;
        const Mesh& mesh = out.surface.mesh;
        const std::function<bool()> stop = [&built, &monitor] {
            return built.abandon.load(std::memory_order_relaxed) || monitor.stopped();
        };
        Beside structures(
            [&built, &mesh, &stop, threads] {
                if (!build_mesh_queries(mesh, threads, stop, built.queries) || stop()) built.stopped = true;
            },
            threads > 1);
        // open meshes: no ball reaches out through a hole (hole_caps.cpp); the caps' tree is built
        // on this thread while the surface's are built (its own member of `built`)
        if (kind.is_open_mesh()) build_cap_queries(out.surface.caps, built.queries);
        if (!sample_surface(mesh, opt.cover_samples, stream_seed(opt.seed, 1), out.cover_samples, monitor))
            st = monitor.stop_status("sampling");
        out.report.time_sampling_s = seconds_since(t0);
        // A flat mesh bounds no volume: no inner candidates and no 3-D Delaunay step; its cover is
        // made of surface balls. A Delaunay step Qhull cannot build (its retries included) leaves
        // the fallback and surface balls to cover the shape.
        if (st.ok() && !out.surface.flat) {
            st = opt.generator == Generator::voronoi ? mesh_voronoi_candidates(opt, monitor, structures, built, threads, out)
                                                     : mesh_random_candidates(opt, monitor, structures, built, threads, out);
            if (st.code == Code::geometry_failure || st.code == Code::degenerate_input) {
                out.report.delaunay_failed = true;
                out.balls.clear();
                out.voronoi_tets.clear();
                out.voronoi_inner.clear();
                st = Status::success();
            }
        }
        if (!st.ok()) built.abandon = true;
        structures.wait();
        if (st.ok()) st = structures_status(built, monitor);
        const MeshDistance* cap_distance = built.queries.cap_distance.get();
        if (st.ok() && cap_distance && !clamp_to_hole_caps(out, *cap_distance, threads, monitor)) st = monitor.stop_status("hole caps");
        if (st.ok()) {
            if (!out.surface.flat)
                out.report.fallback_balls = add_fallback_balls(out, *built.queries.winding, *built.queries.distance, cap_distance, threads, monitor);
            if (monitor.stopped()) st = monitor.stop_status("fallback balls");
            if (st.ok() && !opt.volumetric_only) {
                add_surface_balls(out, built.queries.distance.get(), threads, monitor);
                if (monitor.stopped()) st = monitor.stop_status("surface balls");
            }
            out.queries = std::move(built.queries);
        }
        if (st.ok() && opt.connect_samples > 0)
            out.connect_samples = sample_surface(out.surface.mesh, opt.connect_samples, stream_seed(opt.seed, 4));
    }
    if (!st.ok()) return st;
    out.report.time_candidates_s = seconds_since(t0) - out.report.time_sampling_s;
    if (out.balls.empty())
        return fail(Code::no_candidates, "no candidate ball lies inside the shape (volumetric-only: is the surface "
                                         "closed around a volume? try more samples or the random generator)");
    return Status::success();
}

}  // namespace ca

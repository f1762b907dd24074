// evaluate.cpp: the reconstruction error of a medial skeleton (docs/evaluation.md): area-proportional
// samples of the input surface and of the boundary of E, their distances to E (envelope.h) and to
// the surface, and the one- and two-sided Hausdorff distances.
#include "evaluate.h"
#include "envelope.h"

#include "distance.h"
#include "kdtree.h"
#include "parallel.h"
#include "rng.h"
#include "sampling.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <new>

namespace ca {

using namespace eval;

// What evaluate() draws from the surface alone (evaluate.h).
struct EvaluationSurface {
    std::vector<Vec3> vertices;           // the input's (the point cloud's nearest-point tree reads them)
    bool mesh = false;                    // triangles: exact point-to-triangle distances
    std::vector<Vec3> samples;            // area-uniform samples plus the input vertices
    std::shared_ptr<const MeshDistance> distance;  // mesh
    std::unique_ptr<PointTree> input_points;     // point cloud
    std::unique_ptr<PointTree> sample_points;    // hd_only's bound on the distance to the surface
    double diag = 0, tol = 0;
    uint32_t surface_samples = 0;
    uint64_t seed = 0;
};

namespace {

// Every index writes only its own output, so the results do not depend on the thread count.
constexpr size_t kBatch = 4096;

// max(m, x), atomically (hd_only's running maximum, shared by the workers).
void raise_to(std::atomic<double>& m, double x) {
    double cur = m.load(std::memory_order_relaxed);
    while (x > cur && !m.compare_exchange_weak(cur, x, std::memory_order_relaxed)) {
    }
}

// `distance`: the surface's distance query, or null (built here for a mesh).
Status prepare_impl(const Mesh& surface, const EvaluateOptions& opt, std::shared_ptr<const MeshDistance> distance,
                    std::shared_ptr<EvaluationSurface>& out) {
    if (surface.vertices.empty()) return fail(Code::degenerate_input, "evaluate: empty surface");
    const size_t nv = surface.vertices.size();
    for (const Vec3& v : surface.vertices)
        if (!v.allFinite()) return fail(Code::invalid_input, "evaluate: non-finite surface vertex");
    for (const Tri& t : surface.triangles)
        if (t[0] >= nv || t[1] >= nv || t[2] >= nv)
            return fail(Code::invalid_input, "evaluate: triangle index out of range");
    Vec3 lo = surface.vertices[0], hi = surface.vertices[0];
    for (const Vec3& v : surface.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    const double diag = (hi - lo).norm();
    if (!(diag > 0)) return fail(Code::degenerate_input, "evaluate: surface has zero extent");
    auto s = std::make_shared<EvaluationSurface>();
    s->diag = diag;
    s->tol = 1e-9 * diag;
    s->surface_samples = opt.surface_samples;
    s->seed = opt.seed;
    s->vertices = surface.vertices;
    s->mesh = !surface.triangles.empty();
    // ---- surface samples: area-uniform points on the triangles plus the input vertices ----
    if (s->mesh) s->samples = sample_surface(surface, opt.surface_samples, opt.seed ^ 0xBB67AE8584CAA73Bull);
    s->samples.insert(s->samples.end(), s->vertices.begin(), s->vertices.end());
    if (s->mesh) s->distance = distance ? std::move(distance) : std::make_shared<const MeshDistance>(surface);
    else s->input_points = std::make_unique<PointTree>(s->vertices);
    out = std::move(s);
    return Status::success();
}

Status evaluate_impl(const EvaluationSurface& surface, const Skeleton& skeleton_in, const EvaluateOptions& opt,
                     const Monitor& monitor, EvaluateResult& out, bool hd_only) {
    // ---- validation ----
    if (skeleton_in.balls.empty()) return fail(Code::invalid_argument, "evaluate: empty skeleton");
    if (opt.envelope_samples == 0)
        return fail(Code::invalid_argument, "evaluate: envelope_samples must be positive");
    if (opt.surface_samples != surface.surface_samples || opt.seed != surface.seed)
        return fail(Code::invalid_argument, "evaluate: the surface was prepared with other samples or seed");
    for (const Ball& b : skeleton_in.balls)
        if (!b.center.allFinite() || !std::isfinite(b.radius) || b.radius < 0)
            return fail(Code::invalid_input, "evaluate: invalid ball (non-finite or negative radius)");
    Skeleton sk = skeleton_in;
    canonicalize(sk);
    const size_t nb = sk.balls.size();
    for (const auto& e : sk.edges)
        if (e[1] >= nb) return fail(Code::invalid_input, "evaluate: skeleton edge index out of range");
    for (const Tri& f : sk.faces)
        if (f[2] >= nb) return fail(Code::invalid_input, "evaluate: skeleton face index out of range");

    const double diag = surface.diag;
    const double tol = surface.tol;
    const auto& balls = sk.balls;
    const int threads = resolve_threads(opt.threads);
    auto cancelled = [&] { return monitor.stop_status("evaluate"); };
    if (!monitor.report("evaluate", 0.0)) return cancelled();

    const Envelope env(balls, envelope_primitives(sk));

    // ---- boundary samples of E ----
    const std::vector<Piece> pieces = boundary_pieces(sk);
    std::vector<Vec3> boundary;
    if (!sample_boundary(env, pieces, opt.envelope_samples, opt.seed ^ 0x6A09E667F3BCC909ull, tol, threads,
                         monitor, "evaluate", 0.0, 0.3, boundary))
        return cancelled();
    if (boundary.empty()) {   // zero-area envelope (all radii zero): use the centres
        for (const Ball& b : balls) boundary.push_back(b.center);
    }
    if (!monitor.report("evaluate", 0.3)) return cancelled();

    const std::vector<Vec3>& samples = surface.samples;
    // hd_only: the maxima so far (a sample whose value is shown to be at most this is skipped)
    std::atomic<double> max_se{0.0}, max_es{0.0};

    // ---- h(S -> E): F where F >= 0 (exact); inside E the distance to the nearest boundary
    // sample, tightened by the closest points of the nearby pieces (spheres, cone surfaces,
    // tangent triangles) that lie on the boundary of E. Both are points of the boundary, so
    // the value stays an upper bound of the true distance, and -F a lower bound. ----
    std::vector<double> d_se(hd_only ? 0 : samples.size());
    {
        const PointTree nearest_boundary(boundary);
        std::vector<Vec3> pcs;
        std::vector<double> prs;
        for (const Piece& pc : pieces) {
            const auto b = piece_bound(pc);
            pcs.push_back(b.first);
            prs.push_back(b.second);
        }
        const SphereBvh piece_bvh(std::move(pcs), std::move(prs));
        auto inside_distance = [&](const Vec3& p, double d0) {
            return piece_bvh.nearest(p, d0, [&](uint32_t k, double best) {
                const Vec3 x = closest_on_piece(pieces[k], p);
                const double d = (x - p).norm();
                if (d >= best) return best;
                return env.F(x, -tol) > -tol ? d : kInf;
            });
        };
        if (!parallel_for(samples.size(), threads, kBatch, monitor, "evaluate", 0.3, 0.5, [&](size_t b, size_t e) {
                for (size_t i = b; i < e; ++i) {
                    const Vec3& p = samples[i];
                    if (!hd_only) {
                        const double f = env.F(p);
                        // on or outside E (up to rounding): F is the exact distance
                        d_se[i] = f > -tol ? std::max(f, 0.0) : inside_distance(p, nearest_boundary.distance(p));
                        continue;
                    }
                    // hd_only: F stops at the first primitive closer than the maximum so far; a
                    // value at or above it is the exact F
                    const double m = max_se.load(std::memory_order_relaxed);
                    const double f = env.F(p, std::max(m, -tol));
                    if (f >= m && f > -tol) {
                        raise_to(max_se, f);
                        continue;
                    }
                    // below the maximum: only a point inside E (F <= -tol) can still raise it,
                    // by at most the distance to the nearest boundary sample
                    if (f > -tol && env.F(p, -tol) > -tol) continue;
                    const double d0 = nearest_boundary.distance(p);
                    if (d0 <= max_se.load(std::memory_order_relaxed)) continue;
                    raise_to(max_se, inside_distance(p, d0));
                }
            }))
            return cancelled();
    }

    // ---- h(E -> S) ----
    std::vector<double> d_es(hd_only ? 0 : boundary.size());
    if (surface.mesh) {
        const MeshDistance& md = *surface.distance;
        if (!parallel_for(boundary.size(), threads, kBatch, monitor, "evaluate", 0.5, 1.0, [&](size_t b, size_t e) {
                for (size_t i = b; i < e; ++i) {
                    if (!hd_only) {
                        d_es[i] = md.distance(boundary[i]);
                        continue;
                    }
                    // the nearest surface sample lies on the surface: its distance bounds the
                    // distance to the surface from above (widened for rounding)
                    const double ub = surface.sample_points->distance(boundary[i]) * (1 + 1e-12) + tol;
                    if (ub <= max_es.load(std::memory_order_relaxed)) continue;
                    raise_to(max_es, md.distance_below(boundary[i], ub));
                }
            }))
            return cancelled();
    } else {
        const PointTree& nearest_input = *surface.input_points;
        if (!parallel_for(boundary.size(), threads, kBatch, monitor, "evaluate", 0.5, 1.0, [&](size_t b, size_t e) {
                for (size_t i = b; i < e; ++i) {
                    const double d = nearest_input.distance(boundary[i]);
                    if (hd_only) raise_to(max_es, d);
                    else d_es[i] = d;
                }
            }))
            return cancelled();
    }

    // ---- results (serial reductions: deterministic) ----
    auto max_mean = [](const std::vector<double>& d, double& mx, double& mean) {
        mx = 0;
        double sum = 0;
        for (double x : d) {
            mx = std::max(mx, x);
            sum += x;
        }
        mean = d.empty() ? 0 : sum / double(d.size());
    };
    EvaluateResult r;
    double mx = max_se.load(), mean = 0;
    if (!hd_only) max_mean(d_se, mx, mean);
    r.hd_surface_to_recon = 100 * mx / diag;
    r.mean_surface_to_recon = 100 * mean / diag;
    mx = max_es.load();
    mean = 0;
    if (!hd_only) max_mean(d_es, mx, mean);
    r.hd_recon_to_surface = 100 * mx / diag;
    r.mean_recon_to_surface = 100 * mean / diag;
    r.hd_two_sided = std::max(r.hd_surface_to_recon, r.hd_recon_to_surface);
    r.diagonal = diag;
    r.surface_samples_used = samples.size();
    r.envelope_samples_used = boundary.size();
    out = r;
    monitor.report("evaluate", 1.0);
    return Status::success();
}

}  // namespace

Status prepare_evaluation(const Mesh& surface, const EvaluateOptions& opt, std::shared_ptr<const EvaluationSurface>& out,
                          const ShapeQueries* queries) {
    std::shared_ptr<EvaluationSurface> s;
    const Status st = prepare_impl(surface, opt, queries ? queries->distance : nullptr, s);
    if (!st.ok()) return st;
    if (s->mesh) s->sample_points = std::make_unique<PointTree>(s->samples);
    out = std::move(s);
    return st;
}

Status evaluate(const EvaluationSurface& surface, const Skeleton& skeleton, const EvaluateOptions& opt,
                const Monitor& monitor, EvaluateResult& out, bool hd_only) {
    const auto t0 = Clock::now();
    const Status st = evaluate_impl(surface, skeleton, opt, monitor, out, hd_only);
    out.time_s = seconds_since(t0);
    return st;
}

namespace {

// evaluate() on an unprepared surface, with its distance query or null
Status evaluate_unprepared(const Mesh& surface, std::shared_ptr<const MeshDistance> distance, const Skeleton& skeleton,
                           const EvaluateOptions& opt, const Monitor& monitor, EvaluateResult& out) {
    const auto t0 = Clock::now();
    Status st;
    std::shared_ptr<EvaluationSurface> prepared;
    if (skeleton.balls.empty()) st = fail(Code::invalid_argument, "evaluate: empty skeleton");
    else if (opt.envelope_samples == 0 && !surface.vertices.empty())
        st = fail(Code::invalid_argument, "evaluate: envelope_samples must be positive");
    else st = prepare_impl(surface, opt, std::move(distance), prepared);
    if (st.ok()) st = evaluate_impl(*prepared, skeleton, opt, monitor, out, false);
    out.time_s = seconds_since(t0);
    return st;
}

}  // namespace

Status evaluate(const Mesh& surface, const Skeleton& skeleton, const EvaluateOptions& opt,
                const Monitor& monitor, EvaluateResult& out) {
    return evaluate_unprepared(surface, nullptr, skeleton, opt, monitor, out);
}

Status evaluate(const Mesh& surface, const ShapeQueries& queries, const Skeleton& skeleton,
                const EvaluateOptions& opt, const Monitor& monitor, EvaluateResult& out) {
    return evaluate_unprepared(surface, queries.distance, skeleton, opt, monitor, out);
}

}  // namespace ca

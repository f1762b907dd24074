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
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <new>

namespace ca {

using namespace eval;

namespace {

// Every index writes only its own output, so the results do not depend on the thread count.
constexpr size_t kBatch = 4096;

// `distance`: the surface's distance query, or null (built here for a mesh).
Status evaluate_impl(const Mesh& surface, const MeshDistance* distance, const Skeleton& skeleton_in,
                     const EvaluateOptions& opt, const Monitor& monitor, EvaluateResult& out) {
    // ---- validation ----
    if (skeleton_in.balls.empty()) return fail(Code::invalid_argument, "evaluate: empty skeleton");
    if (surface.vertices.empty()) return fail(Code::degenerate_input, "evaluate: empty surface");
    if (opt.envelope_samples == 0)
        return fail(Code::invalid_argument, "evaluate: envelope_samples must be positive");
    const size_t nv = surface.vertices.size();
    for (const Vec3& v : surface.vertices)
        if (!v.allFinite()) return fail(Code::invalid_input, "evaluate: non-finite surface vertex");
    for (const Tri& t : surface.triangles)
        if (t[0] >= nv || t[1] >= nv || t[2] >= nv)
            return fail(Code::invalid_input, "evaluate: triangle index out of range");
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

    Vec3 lo = surface.vertices[0], hi = surface.vertices[0];
    for (const Vec3& v : surface.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    const double diag = (hi - lo).norm();
    if (!(diag > 0)) return fail(Code::degenerate_input, "evaluate: surface has zero extent");
    const double tol = 1e-9 * diag;
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

    // ---- surface samples: area-uniform points on the triangles plus the input vertices ----
    std::vector<Vec3> samples;
    const auto& V = surface.vertices;
    if (!surface.triangles.empty()) samples = sample_surface(surface, opt.surface_samples, opt.seed ^ 0xBB67AE8584CAA73Bull);
    samples.insert(samples.end(), V.begin(), V.end());

    // ---- h(S -> E): F where F >= 0 (exact); inside E the distance to the nearest boundary
    // sample, tightened by the closest points of the nearby pieces (spheres, cone surfaces,
    // tangent triangles) that lie on the boundary of E. Both are points of the boundary, so
    // the value stays an upper bound of the true distance, and -F a lower bound. ----
    std::vector<double> d_se(samples.size());
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
        auto inside_distance = [&](const Vec3& p) {
            const double d0 = nearest_boundary.distance(p);
            return piece_bvh.nearest(p, d0, [&](uint32_t k, double best) {
                const Vec3 x = closest_on_piece(pieces[k], p);
                const double d = (x - p).norm();
                if (d >= best) return best;
                return env.F(x, -tol) > -tol ? d : kInf;
            });
        };
        if (!parallel_for(samples.size(), threads, kBatch, monitor, "evaluate", 0.3, 0.5, [&](size_t b, size_t e) {
                for (size_t i = b; i < e; ++i) {
                    const double f = env.F(samples[i]);
                    // on or outside E (up to rounding): F is the exact distance
                    d_se[i] = f > -tol ? std::max(f, 0.0) : inside_distance(samples[i]);
                }
            }))
            return cancelled();
    }

    // ---- h(E -> S) ----
    std::vector<double> d_es(boundary.size());
    if (!surface.triangles.empty()) {
        std::unique_ptr<const MeshDistance> own;
        if (!distance) own = std::make_unique<const MeshDistance>(surface);
        const MeshDistance& md = distance ? *distance : *own;
        if (!parallel_for(boundary.size(), threads, kBatch, monitor, "evaluate", 0.5, 1.0, [&](size_t b, size_t e) {
                for (size_t i = b; i < e; ++i) d_es[i] = md.distance(boundary[i]);
            }))
            return cancelled();
    } else {
        const PointTree nearest_input(V);
        if (!parallel_for(boundary.size(), threads, kBatch, monitor, "evaluate", 0.5, 1.0, [&](size_t b, size_t e) {
                for (size_t i = b; i < e; ++i) d_es[i] = nearest_input.distance(boundary[i]);
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
    double mx, mean;
    max_mean(d_se, mx, mean);
    r.hd_surface_to_recon = 100 * mx / diag;
    r.mean_surface_to_recon = 100 * mean / diag;
    max_mean(d_es, mx, mean);
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

Status evaluate(const Mesh& surface, const Skeleton& skeleton, const EvaluateOptions& opt,
                const Monitor& monitor, EvaluateResult& out) {
    const auto t0 = Clock::now();
    const Status st = evaluate_impl(surface, nullptr, skeleton, opt, monitor, out);
    out.time_s = seconds_since(t0);
    return st;
}

Status evaluate(const Mesh& surface, const ShapeQueries& queries, const Skeleton& skeleton,
                const EvaluateOptions& opt, const Monitor& monitor, EvaluateResult& out) {
    const auto t0 = Clock::now();
    const Status st = evaluate_impl(surface, queries.distance.get(), skeleton, opt, monitor, out);
    out.time_s = seconds_since(t0);
    return st;
}

}  // namespace ca

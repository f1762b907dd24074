// fit.cpp: the post-connection fit of the balls (fit.h): residuals on surface samples and on
// boundary samples of E, their Jacobians through the closest primitive, damped and weighted
// Gauss-Newton steps with step acceptance, projection of every ball into the shape, and the
// coverage re-check.
#include "fit.h"

#include "coverage.h"
#include "distance.h"
#include "envelope.h"
#include "parallel.h"
#include "sampling.h"
#include "timing.h"
#include "winding.h"

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <exception>
#include <memory>
#include <new>

namespace ca {

using namespace eval;

namespace {

constexpr size_t kBatch = 1024;

// One residual point: its residual F(p) - g(p), the balls of its closest primitive and the
// derivatives of F(p) with respect to their (centre, radius), 4 per ball.
struct Row {
    double r = 0;
    uint32_t ball[3] = {0, 0, 0};
    int nballs = 0;
    double d[12] = {};
};

double sd_of(Kind kind, const Ball* b, const Vec3& p) {
    switch (kind) {
        case Kind::sphere: return sd_sphere(p, b[0].center, b[0].radius);
        case Kind::cone: return sd_cone(p, b[0].center, b[0].radius, b[1].center, b[1].radius);
        case Kind::slab:
            return sd_slab(p, b[0].center, b[0].radius, b[1].center, b[1].radius, b[2].center, b[2].radius);
    }
    return kInf;
}

// F(p) and its gradient with respect to the closest primitive's balls: exact for a sphere,
// forward differences for cones and slabs (their distances are piecewise smooth).
Row residual_row(const Envelope& env, const std::vector<Ball>& balls, const Vec3& p, double g) {
    Row row;
    uint32_t which = 0;
    const double f = env.F(p, which);
    row.r = f - g;
    const Primitive& q = env.primitives()[which];
    row.nballs = q.kind == Kind::sphere ? 1 : q.kind == Kind::cone ? 2 : 3;
    Ball b[3];
    for (int t = 0; t < row.nballs; ++t) {
        row.ball[t] = q.v[t];
        b[t] = balls[q.v[t]];
    }
    if (q.kind == Kind::sphere) {
        const Vec3 w = p - b[0].center;
        const double n = w.norm();
        const Vec3 u = n > 0 ? Vec3(w / n) : Vec3::Zero();
        for (int k = 0; k < 3; ++k) row.d[k] = -u[k];
        row.d[3] = -1;
        return row;
    }
    constexpr double h = 1e-7;
    const double f0 = sd_of(q.kind, b, p);
    for (int t = 0; t < row.nballs; ++t) {
        for (int k = 0; k < 4; ++k) {
            Ball saved = b[t];
            if (k < 3) b[t].center[k] += h; else b[t].radius += h;
            row.d[4 * t + k] = (sd_of(q.kind, b, p) - f0) / h;
            b[t] = saved;
        }
    }
    return row;
}

class Fitter {
public:
    Fitter(const CandidateSet& set, const FitOptions& opt, const Monitor& monitor, int threads)
        : set_(set), opt_(opt), monitor_(monitor), threads_(threads) {
        const Mesh& mesh = set.surface.mesh;
        if (set.winding) winding_ = set.winding;
        else winding_ = std::make_shared<WindingNumber>(mesh);
        if (set.distance) distance_ = set.distance;
        else distance_ = std::make_shared<MeshDistance>(mesh);
        surface_ = sample_surface(mesh, opt.surface_samples, opt.seed ^ 0x3C6EF372FE94F82Bull);
    }

    // The residual rows of the skeleton with these balls, and their maximum |r|. False if cancelled.
    bool rows(const Skeleton& sk, std::vector<Row>& out, double& max_abs) const {
        const Envelope env(sk.balls, envelope_primitives(sk));
        std::vector<Vec3> boundary;
        const double tol = 1e-9;
        if (!sample_boundary(env, boundary_pieces(sk), opt_.envelope_samples, opt_.seed ^ 0xA54FF53A5F1D36F1ull,
                             tol, threads_, Monitor{}, "fit", 0, 1, boundary))
            return false;
        const size_t ns = surface_.size();
        out.assign(ns + boundary.size(), Row{});
        if (!parallel_for(out.size(), threads_, kBatch, Monitor{}, "fit", [&](size_t b, size_t e) {
                for (size_t i = b; i < e; ++i) {
                    if (i < ns) {
                        out[i] = residual_row(env, sk.balls, surface_[i], 0);
                    } else {
                        const Vec3& x = boundary[i - ns];
                        out[i] = residual_row(env, sk.balls, x, signed_distance(x));
                    }
                }
            }))
            return false;
        max_abs = 0;
        for (const Row& r : out) max_abs = std::max(max_abs, std::abs(r.r));
        return !monitor_.cancelled();
    }

    // Distance to the surface, negative inside. The side is that of the closest triangle's plane
    // when x lies along its normal (the closest point is inside the triangle, where that is exact),
    // else the winding number's.
    double signed_distance(const Vec3& x) const {
        Vec3 y;
        uint32_t t = 0;
        const double d = distance_->distance(x, &y, &t);
        if (d > 0) {
            const Tri& tri = set_.surface.mesh.triangles[t];
            const auto& V = set_.surface.mesh.vertices;
            const Vec3 n = (V[tri[1]] - V[tri[0]]).cross(V[tri[2]] - V[tri[0]]);
            const double nn = n.norm();
            if (nn > 0) {
                const double c = (x - y).dot(n) / (nn * d);
                if (std::abs(c) > 1 - 1e-6) return c > 0 ? d : -d;
            }
        }
        return winding_->inside(x) ? -d : d;
    }

    // The damped, weighted Gauss-Newton step (to subtract from the parameters), 4 per ball.
    Eigen::VectorXd step(const std::vector<Row>& rows, double max_abs, size_t nb, double damping) const {
        const size_t n = 4 * nb;
        std::vector<Eigen::Triplet<double>> trip;
        trip.reserve(rows.size() * 16);
        Eigen::VectorXd grad = Eigen::VectorXd::Zero(Eigen::Index(n));
        const double scale = max_abs > 0 ? max_abs : 1;
        for (const Row& r : rows) {
            const double w = std::pow(std::max(std::abs(r.r) / scale, 1e-3), opt_.power - 2);
            const int m = 4 * r.nballs;
            Eigen::Index idx[12];
            for (int t = 0; t < r.nballs; ++t)
                for (int k = 0; k < 4; ++k) idx[4 * t + k] = Eigen::Index(4 * r.ball[t] + uint32_t(k));
            for (int a = 0; a < m; ++a) {
                if (r.d[a] == 0) continue;
                grad[idx[a]] += w * r.d[a] * r.r;
                for (int c = 0; c < m; ++c)
                    if (r.d[c] != 0) trip.emplace_back(idx[a], idx[c], w * r.d[a] * r.d[c]);
            }
        }
        const Eigen::Index N = Eigen::Index(n);
        Eigen::SparseMatrix<double> H(N, N);
        H.setFromTriplets(trip.begin(), trip.end());
        double mean_diag = 0;
        for (Eigen::Index i = 0; i < H.rows(); ++i) mean_diag += H.coeff(i, i);
        mean_diag = std::max(mean_diag / double(n), 1e-12);
        Eigen::SparseMatrix<double> D(N, N);
        std::vector<Eigen::Triplet<double>> diag;
        for (Eigen::Index i = 0; i < H.rows(); ++i)
            diag.emplace_back(i, i, damping * H.coeff(i, i) + opt_.regularization * mean_diag);
        D.setFromTriplets(diag.begin(), diag.end());
        Eigen::SparseMatrix<double> A = H + D;
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(A);
        if (ldlt.info() != Eigen::Success) return Eigen::VectorXd::Zero(Eigen::Index(n));
        Eigen::VectorXd x = ldlt.solve(grad);
        if (!x.allFinite()) return Eigen::VectorXd::Zero(Eigen::Index(n));
        return x;
    }

    // balls - alpha * dx, each ball projected into the shape.
    std::vector<Ball> moved(const std::vector<Ball>& balls, const Eigen::VectorXd& dx, double alpha) const {
        std::vector<Ball> out = balls;
        for (size_t i = 0; i < balls.size(); ++i) {
            Ball b = balls[i];
            const Eigen::Index o = Eigen::Index(4 * i);
            const Vec3 c = b.center - alpha * Vec3(dx[o], dx[o + 1], dx[o + 2]);
            if (winding_->inside(c)) b.center = c;
            const double dist = distance_->distance(b.center);
            const double r = b.radius - alpha * dx[o + 3];
            b.radius = std::clamp(r, 0.25 * balls[i].radius, dist + opt_.radius_tolerance);
            out[i] = b;
        }
        return out;
    }

private:
    const CandidateSet& set_;
    const FitOptions& opt_;
    const Monitor& monitor_;
    int threads_;
    std::shared_ptr<const WindingNumber> winding_;
    std::shared_ptr<const MeshDistance> distance_;
    std::vector<Vec3> surface_;
};

// Cover samples that no ball covers with its dilated radius (offset delta or scale).
size_t count_uncovered(const CandidateSet& set, const Selection& sel, const std::vector<Ball>& balls) {
    size_t n = 0;
    for (const Vec3& s : set.cover_samples) {
        bool ok = false;
        for (const Ball& b : balls) {
            const double rd = sel.delta > 0 ? b.radius + sel.delta : b.radius * sel.scale;
            if (covers(b.center, rd, s)) { ok = true; break; }
        }
        n += !ok;
    }
    return n;
}

Status fit_impl(const CandidateSet& set, const Selection& sel, const FitOptions& opt, const Monitor& monitor,
                Skeleton& sk, FitStats& stats) {
    const auto t0 = Clock::now();
    stats = FitStats{};
    if (set.surface.point_cloud || set.surface.mesh.triangles.empty() || sk.balls.empty() ||
        opt.iterations == 0)
        return Status::success();
    if (!(opt.power >= 2) || !(opt.regularization >= 0) || !(opt.radius_tolerance >= 0))
        return fail(Code::invalid_argument, "fit: power must be >= 2, regularization and radius_tolerance >= 0");
    canonicalize(sk);
    auto cancelled = [] { return fail(Code::cancelled, "fit: cancelled"); };
    const Fitter fitter(set, opt, monitor, resolve_threads(opt.threads));
    std::vector<Row> rows;
    double err = 0;
    if (!fitter.rows(sk, rows, err)) return cancelled();
    stats.error_before = err;
    std::vector<Ball> best = sk.balls;
    double best_err = err, damping = 1e-3;
    Skeleton trial = sk;
    for (uint32_t it = 0; it < opt.iterations; ++it) {
        if (!monitor.report("fit", double(it) / opt.iterations)) return cancelled();
        ++stats.iterations;
        const Eigen::VectorXd dx = fitter.step(rows, err, sk.balls.size(), damping);
        bool taken = false;
        for (double alpha : {1.0, 0.5, 0.25}) {
            trial.balls = fitter.moved(sk.balls, dx, alpha);
            std::vector<Row> trial_rows;
            double trial_err = 0;
            if (!fitter.rows(trial, trial_rows, trial_err)) return cancelled();
            if (trial_err < err) {
                sk.balls = trial.balls;
                rows = std::move(trial_rows);
                err = trial_err;
                taken = true;
                break;
            }
        }
        if (!taken) {
            damping *= 10;
            continue;
        }
        ++stats.accepted;
        damping = std::max(damping / 3, 1e-6);
        if (err < best_err) {
            best_err = err;
            best = sk.balls;
        }
    }
    sk.balls = best;
    stats.error_after = best_err;
    stats.uncovered = count_uncovered(set, sel, sk.balls);
    stats.time_s = seconds_since(t0);
    monitor.report("fit", 1.0);
    return Status::success();
}

}  // namespace

Status fit_skeleton(const CandidateSet& set, const Selection& sel, const FitOptions& opt, const Monitor& monitor,
                    Skeleton& sk, FitStats& stats) {
    return fit_impl(set, sel, opt, monitor, sk, stats);
}

}  // namespace ca

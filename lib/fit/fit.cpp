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

// The residuals of one iterate: at each point F(p) - g(p) and the primitive of E closest to p.
// The surface samples come first (the Fitter's own), then the boundary samples of E.
struct Residuals {
    std::vector<Primitive> prims;
    std::vector<Vec3> boundary;
    std::vector<double> r;
    std::vector<uint32_t> which;
    double max_abs = 0;
    size_t drawn = 0;   // boundary points drawn (kept or not)
    double lp = 0;   // (mean |r|^power)^(1/power): the objective that the steps decrease
};

// Signed distance of primitive q of these balls at p and the sphere of q that attains it.
double sd_nearest(const Primitive& q, const std::vector<Ball>& balls, const Vec3& p, NearestSphere& at) {
    const Ball& a = balls[q.v[0]];
    switch (q.kind) {
        case Kind::sphere: {
            at = NearestSphere{};
            at.w[0] = 1;
            const Vec3 w = p - a.center;
            const double n = w.norm();
            if (n > 0) at.u = w / n;
            return n - a.radius;
        }
        case Kind::cone: {
            const Ball& b = balls[q.v[1]];
            return sd_cone(p, a.center, a.radius, b.center, b.radius, &at);
        }
        case Kind::slab: {
            const Ball& b = balls[q.v[1]];
            const Ball& c = balls[q.v[2]];
            return sd_slab(p, a.center, a.radius, b.center, b.radius, c.center, c.radius, &at);
        }
    }
    return kInf;
}

// Whether ball b covers s with its dilated radius (offset delta or scale); whether some ball does.
bool reaches(const Selection& sel, const Ball& b, const Vec3& s) {
    return covers(b.center, sel.delta > 0 ? b.radius + sel.delta : b.radius * sel.scale, s);
}
bool covered(const Selection& sel, const std::vector<Ball>& balls, const Vec3& s) {
    for (const Ball& b : balls)
        if (reaches(sel, b, s)) return true;
    return false;
}

class Fitter {
public:
    Fitter(const CandidateSet& set, const FitOptions& opt, const Monitor& monitor, int threads)
        : set_(set), opt_(opt), monitor_(monitor), threads_(threads) {
        winding_ = set.queries.winding;
        distance_ = set.queries.distance;
        surface_ = sample_surface(set.surface.mesh, opt.surface_samples, opt.seed ^ 0x3C6EF372FE94F82Bull);
    }

    // The residuals of the skeleton with these balls and their maximum |r|, drawing `drawn`
    // points on the primitives' boundary pieces. False if cancelled.
    bool residuals(const Skeleton& sk, double drawn, Residuals& out) const {
        const Envelope env(sk.balls, envelope_primitives(sk));
        if (!boundary_samples(env, boundary_pieces(sk), drawn, out)) return false;
        out.prims = env.primitives();
        const size_t ns = surface_.size();
        out.r.assign(ns + out.boundary.size(), 0);
        out.which.assign(out.r.size(), 0);
        if (!parallel_for(out.r.size(), threads_, kBatch, Monitor{}, "fit", [&](size_t b, size_t e) {
                for (size_t i = b; i < e; ++i) {
                    const Vec3& x = i < ns ? surface_[i] : out.boundary[i - ns];
                    const double g = i < ns ? 0 : signed_distance(x);
                    out.r[i] = env.F(x, out.which[i]) - g;
                }
            }))
            return false;
        out.max_abs = 0;
        for (double r : out.r) out.max_abs = std::max(out.max_abs, std::abs(r));
        double sum = 0;
        if (out.max_abs > 0)
            for (double r : out.r) sum += std::pow(std::abs(r) / out.max_abs, opt_.power);
        out.lp = out.r.empty() ? 0 : out.max_abs * std::pow(sum / double(out.r.size()), 1 / opt_.power);
        return !monitor_.cancelled();
    }

    // Points of the boundary of E: `drawn` points spread over the pieces by area, those strictly
    // inside another primitive dropped. Each piece draws from a random stream of its own (seeded
    // by its index), so from one iterate to the next its samples move with it instead of being
    // redrawn: the residuals of a trial and of the iterate it starts from are comparable.
    bool boundary_samples(const Envelope& env, const std::vector<Piece>& pieces, double drawn, Residuals& out) const {
        double total = 0;
        for (const Piece& pc : pieces) total += pc.area;
        std::vector<Vec3> cand;
        if (total > 0) {
            cand.reserve(size_t(drawn) + pieces.size());
            for (size_t k = 0; k < pieces.size(); ++k) {
                Rng rng(opt_.seed ^ (0xA54FF53A5F1D36F1ull + 0x9E3779B97F4A7C15ull * (k + 1)));
                const size_t cnt = size_t(std::floor(drawn * pieces[k].area / total + rng.uniform()));
                for (size_t j = 0; j < cnt; ++j) cand.push_back(sample_piece(pieces[k], rng));
            }
        }
        std::vector<char> keep(cand.size(), 0);
        constexpr double tol = 1e-9;
        if (!parallel_for(cand.size(), threads_, kBatch, Monitor{}, "fit", [&](size_t b, size_t e) {
                for (size_t i = b; i < e; ++i) keep[i] = env.F(cand[i], -tol) > -tol;
            }))
            return false;
        out.boundary.clear();
        for (size_t i = 0; i < cand.size(); ++i)
            if (keep[i]) out.boundary.push_back(cand[i]);
        out.drawn = cand.size();
        return true;
    }

    // How many boundary points to draw at every iterate: as many as give envelope_samples kept
    // points on the connected skeleton (the share kept varies little while the balls move).
    bool boundary_draw(const Skeleton& sk, double& drawn) const {
        const Envelope env(sk.balls, envelope_primitives(sk));
        Residuals probe;
        if (!boundary_samples(env, boundary_pieces(sk), opt_.envelope_samples, probe)) return false;
        const double kept = probe.drawn ? double(probe.boundary.size()) / double(probe.drawn) : 1.0;
        drawn = double(opt_.envelope_samples) / std::max(kept, 0.05);
        return true;
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
    // Each residual's gradient is that of its closest primitive (NearestSphere), so the normal
    // equations are summed per primitive in dense 12 x 12 blocks, then scattered.
    Eigen::VectorXd step(const Residuals& res, const std::vector<Ball>& balls, double damping,
                         const std::vector<uint8_t>& fixed) const {
        const size_t n = 4 * balls.size();
        const Eigen::Index N = Eigen::Index(n);
        const size_t np = res.prims.size();
        std::vector<double> block(np * 144, 0.0);
        Eigen::VectorXd grad = Eigen::VectorXd::Zero(N);
        const double scale = res.max_abs > 0 ? res.max_abs : 1;
        const size_t ns = surface_.size();
        for (size_t i = 0; i < res.r.size(); ++i) {
            const Primitive& q = res.prims[res.which[i]];
            const int nb = q.kind == Kind::sphere ? 1 : q.kind == Kind::cone ? 2 : 3;
            NearestSphere at;
            sd_nearest(q, balls, i < ns ? surface_[i] : res.boundary[i - ns], at);
            double d[12];
            for (int t = 0; t < nb; ++t) {
                for (int k = 0; k < 3; ++k) d[4 * t + k] = -at.w[t] * at.u[k];
                d[4 * t + 3] = -at.w[t];
            }
            const double r = res.r[i];
            const double w = std::pow(std::max(std::abs(r) / scale, 1e-3), opt_.power - 2);
            const int m = 4 * nb;
            double* B = &block[144 * size_t(res.which[i])];
            for (int a = 0; a < m; ++a) {
                if (d[a] == 0) continue;
                grad[Eigen::Index(4 * q.v[a / 4] + uint32_t(a % 4))] += w * d[a] * r;
                const double wa = w * d[a];
                for (int c = 0; c < m; ++c) B[12 * a + c] += wa * d[c];
            }
        }
        std::vector<Eigen::Triplet<double>> trip;
        trip.reserve(np * 144);
        for (size_t j = 0; j < np; ++j) {
            const Primitive& q = res.prims[j];
            const int m = q.kind == Kind::sphere ? 4 : q.kind == Kind::cone ? 8 : 12;
            const double* B = &block[144 * j];
            for (int a = 0; a < m; ++a)
                for (int c = 0; c < m; ++c)
                    if (B[12 * a + c] != 0)
                        trip.emplace_back(Eigen::Index(4 * q.v[a / 4] + uint32_t(a % 4)),
                                          Eigen::Index(4 * q.v[c / 4] + uint32_t(c % 4)), B[12 * a + c]);
        }
        // every diagonal entry is present (damping and Tikhonov terms), also for unseen parameters
        for (Eigen::Index i = 0; i < N; ++i) trip.emplace_back(i, i, 0.0);
        Eigen::SparseMatrix<double> H(N, N);
        H.setFromTriplets(trip.begin(), trip.end());
        const Eigen::VectorXd hd = H.diagonal();
        const double mean_diag = std::max(hd.sum() / double(n), 1e-12);
        for (Eigen::Index i = 0; i < N; ++i) H.coeffRef(i, i) += damping * hd[i] + opt_.regularization * mean_diag;
        // a held ball's parameters are taken out of the system (its rows and columns replaced by
        // the identity with a zero right-hand side), so the others are solved with it in place
        if (!fixed.empty()) {
            for (int k = 0; k < H.outerSize(); ++k)
                for (Eigen::SparseMatrix<double>::InnerIterator it(H, k); it; ++it)
                    if (fixed[size_t(it.row()) / 4] || fixed[size_t(it.col()) / 4])
                        it.valueRef() = it.row() == it.col() ? 1.0 : 0.0;
            for (Eigen::Index i = 0; i < N; ++i)
                if (fixed[size_t(i) / 4]) grad[i] = 0;
        }
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(H);
        if (ldlt.info() != Eigen::Success) return Eigen::VectorXd::Zero(N);
        Eigen::VectorXd x = ldlt.solve(grad);
        if (!x.allFinite()) return Eigen::VectorXd::Zero(N);
        if (!fixed.empty())
            for (Eigen::Index i = 0; i < N; ++i)
                if (fixed[size_t(i) / 4]) x[i] = 0;
        return x;
    }

    // balls - alpha * dx, each ball projected into the shape: a centre that would leave it stays,
    // a radius is at most the centre's distance to the surface plus the ball's allowance.
    // Each ball's allowance over its centre's distance to the surface: radius_tolerance, or the
    // excess the connected ball already had if larger (the connection's balls touch samples, not
    // the surface between them; forcing them in at once would open gaps the fit then has to close).
    std::vector<double> allowance(const std::vector<Ball>& balls) const {
        std::vector<double> out(balls.size(), opt_.radius_tolerance);
        for (size_t i = 0; i < balls.size(); ++i)
            out[i] = std::max(opt_.radius_tolerance, balls[i].radius - distance_->distance(balls[i].center));
        return out;
    }

    std::vector<Ball> moved(const std::vector<Ball>& balls, const Eigen::VectorXd& dx, double alpha,
                            const std::vector<double>& allow) const {
        std::vector<Ball> out = balls;
        for (size_t i = 0; i < balls.size(); ++i) {
            Ball b = balls[i];
            const Eigen::Index o = Eigen::Index(4 * i);
            const Vec3 c = b.center - alpha * Vec3(dx[o], dx[o + 1], dx[o + 2]);
            if (winding_->inside(c)) b.center = c;
            const double dist = distance_->distance(b.center);
            const double r = b.radius - alpha * dx[o + 3];
            // the surface bound wins over the lower one (a quarter of the radius before the step)
            b.radius = std::min(std::max(r, 0.25 * balls[i].radius), dist + allow[i]);
            out[i] = b;
        }
        return out;
    }

    // `to` moved back towards `from` (whose balls cover every sample of `keep`) until every such
    // sample is covered again: each ball that covered a sample now lost, in `from`, has its share
    // t of the move (centre and radius along the straight path) halved, up to 8 times, then 0; a
    // centre the path takes out of the shape stays at `from`'s.
    std::vector<Ball> pull_back(const std::vector<Ball>& from, const std::vector<Ball>& to, const Selection& sel,
                                const std::vector<uint32_t>& keep) const {
        std::vector<double> t(from.size(), 1.0);
        std::vector<uint8_t> halved(from.size(), 0);
        auto blend = [&](size_t i) {
            Ball b;
            b.center = from[i].center + t[i] * (to[i].center - from[i].center);
            b.radius = from[i].radius + t[i] * (to[i].radius - from[i].radius);
            return b;
        };
        std::vector<Ball> out = to;
        for (int pass = 0; pass < 10; ++pass) {
            bool lost_any = false;
            std::vector<uint8_t> shrink(from.size(), 0);
            for (uint32_t k : keep) {
                const Vec3& x = set_.cover_samples[k];
                if (covered(sel, out, x)) continue;
                lost_any = true;
                for (size_t i = 0; i < from.size(); ++i)
                    if (t[i] > 0 && reaches(sel, from[i], x)) shrink[i] = 1;
            }
            if (!lost_any) break;
            for (size_t i = 0; i < from.size(); ++i)
                if (shrink[i]) {
                    t[i] = ++halved[i] > 8 || pass == 9 ? 0.0 : t[i] / 2;
                    out[i] = blend(i);
                }
        }
        for (size_t i = 0; i < from.size(); ++i)
            if (t[i] > 0 && t[i] < 1 && !winding_->inside(out[i].center)) out[i] = from[i];
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

// Whether these balls cover every sample of `keep` (indices into set.cover_samples).
bool keeps_cover(const CandidateSet& set, const Selection& sel, const std::vector<Ball>& balls,
                 const std::vector<uint32_t>& keep) {
    for (uint32_t i : keep)
        if (!covered(sel, balls, set.cover_samples[i])) return false;
    return true;
}

Status fit_impl(const CandidateSet& set, const Selection& sel, const FitOptions& opt, const Monitor& monitor,
                Skeleton& sk, FitStats& stats, const FitHold* hold) {
    const auto t0 = Clock::now();
    stats = FitStats{};
    if (!set.surface.kind().is_mesh() || sk.balls.empty() || opt.iterations == 0)
        return Status::success();
    if (!(opt.power >= 2) || !(opt.regularization >= 0) || !(opt.radius_tolerance >= 0))
        return fail(Code::invalid_argument, "fit: power must be >= 2, regularization and radius_tolerance >= 0");
    if (hold && !hold->fixed.empty() && hold->fixed.size() != sk.balls.size())
        return fail(Code::invalid_argument, "fit: one held flag per ball");
    canonicalize(sk);
    const std::vector<uint8_t> no_fixed;
    const std::vector<uint8_t>& fixed = hold ? hold->fixed : no_fixed;
    // with keep_cover: the cover samples the starting balls cover, which every iterate that is
    // taken or returned must still cover
    std::vector<uint32_t> keep;
    const bool keep_cover = hold && hold->keep_cover;
    if (keep_cover)
        for (uint32_t i = 0; i < set.cover_samples.size(); ++i)
            if (covered(sel, sk.balls, set.cover_samples[i])) keep.push_back(i);
    auto admissible = [&](const std::vector<Ball>& balls) { return !keep_cover || keeps_cover(set, sel, balls, keep); };
    auto cancelled = [] { return fail(Code::cancelled, "fit: cancelled"); };
    const Fitter fitter(set, opt, monitor, resolve_threads(opt.threads));
    double drawn = 0;
    if (!fitter.boundary_draw(sk, drawn)) return cancelled();
    // The connected skeleton: its largest residual is the error before, and it is the best so far.
    Residuals res;
    if (!fitter.residuals(sk, drawn, res)) return cancelled();
    stats.error_before = res.max_abs;
    std::vector<Ball> best = sk.balls;
    double best_err = res.max_abs;
    // The iterates start from its projection (radius bound; the identity unless a ball's centre is
    // outside): a trial is compared with a feasible iterate, so that a step is not refused for the
    // projection's change alone.
    const std::vector<double> allow = fitter.allowance(sk.balls);
    sk.balls = fitter.moved(sk.balls, Eigen::VectorXd::Zero(Eigen::Index(4 * sk.balls.size())), 0, allow);
    // a projection that uncovers a kept sample leaves nothing to start from that keeps the cover
    if (!admissible(sk.balls)) {
        sk.balls = best;
        stats.error_after = best_err;
        stats.uncovered = uncovered_samples(set, sel, sk.balls).size();
        stats.time_s = seconds_since(t0);
        return Status::success();
    }
    if (!fitter.residuals(sk, drawn, res)) return cancelled();
    if (res.max_abs < best_err) {
        best_err = res.max_abs;
        best = sk.balls;
    }
    double damping = 1e-3;
    Skeleton trial = sk;
    Residuals trial_res;
    for (uint32_t it = 0; it < opt.iterations; ++it) {
        if (!monitor.report("fit", double(it) / opt.iterations)) return cancelled();
        ++stats.iterations;
        const Eigen::VectorXd dx = fitter.step(res, sk.balls, damping, fixed);
        bool taken = false;
        for (double alpha : {1.0, 0.5, 0.25}) {
            trial.balls = fitter.moved(sk.balls, dx, alpha, allow);
            // with keep_cover a trial that uncovers a kept sample is pulled back towards the
            // iterate it starts from (which keeps the cover), ball by ball, as far as needed
            if (keep_cover) trial.balls = fitter.pull_back(sk.balls, trial.balls, sel, keep);
            if (!admissible(trial.balls)) continue;
            if (!fitter.residuals(trial, drawn, trial_res)) return cancelled();
            // every trial is a projected iterate: one refused on the L^p mean may still have the
            // lowest maximum residual, the measure the kept skeleton is chosen by
            if (trial_res.max_abs < best_err) {
                best_err = trial_res.max_abs;
                best = trial.balls;
            }
            if (trial_res.lp < res.lp) {
                sk.balls = trial.balls;
                std::swap(res, trial_res);
                taken = true;
                break;
            }
        }
        // The trials are drawn like the iterate (boundary_samples), so a refusal is no sampling
        // accident. A more damped retry (another direction) is sometimes taken, but the further
        // iterates it opens cost more residual evaluations than the fit is allowed (docs/fidelity.md).
        if (!taken) break;
        ++stats.accepted;
        damping = std::max(damping / 3, 1e-6);
    }
    sk.balls = best;
    stats.error_after = best_err;
    stats.uncovered = uncovered_samples(set, sel, sk.balls).size();
    stats.time_s = seconds_since(t0);
    monitor.report("fit", 1.0);
    return Status::success();
}

}  // namespace

std::vector<uint32_t> uncovered_samples(const CandidateSet& set, const Selection& sel, const std::vector<Ball>& balls) {
    std::vector<uint32_t> out;
    for (uint32_t i = 0; i < set.cover_samples.size(); ++i)
        if (!covered(sel, balls, set.cover_samples[i])) out.push_back(i);
    return out;
}

Status fit_once(const CandidateSet& set, const Selection& sel, const FitOptions& opt, const Monitor& monitor,
                Skeleton& sk, FitStats& stats, const FitHold* hold) {
    return fit_impl(set, sel, opt, monitor, sk, stats, hold);
}

}  // namespace ca

// fit_bone.cpp: one collider per part (bones.h).
//  - conservative: starts from the part's medial balls (the line through their centres, the balls
//    near its ends giving the end radii, so the shape follows the limb's own thickness and taper)
//    and from the capsule around the part's points (fit_capsule); each start grown to hold the
//    part's sample points, then its two balls moved and resized (Nelder-Mead) to the least volume
//    that still holds them: with every sample of the part held, less volume is less reach outside
//    the shape and into the neighbours' parts, where the overlap that makes ragdolls jitter lies.
//    Last, the shape grows to hold every corner of the part's polygons (exact: it is convex);
//  - inscribed: the pair of the part's medial balls (the largest ones and those at the ends of
//    their line) whose hull, shrunk by its proven outside bound (proxy_outside.cpp), has the most
//    volume; a single ball when no pair beats it.
#include "bones.h"

#include "rng.h"
#include "winding.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

namespace ca {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Growth added beyond the points' need: signed distances are computed to about 1e-16 of the
// model's size, and the joint's frame is applied after (internal units: the model's longest side is 1).
constexpr double kHoldMargin = 1e-9;
// The search: evaluations per start, and the first simplex's steps (fractions of the part's extent
// for the centres, of the start's larger radius for the radii).
constexpr int kSearchEvaluations = 400;
constexpr double kCentreStep = 0.1, kRadiusStep = 0.2;
// The search holds a spread subset of the part's samples (the cost of each trial is linear in
// it), then the part's corners the found shape misses most are added and the search resumed, a
// few rounds, so the last growth to every corner adds little: at most this many samples, this
// many corners added per round, and rounds.
constexpr size_t kSearchPoints = 256;
constexpr size_t kAddedCorners = 32;
constexpr int kRefineRounds = 3;
constexpr double kRefineTolerance = 1e-3;   // of the part's extent
// Apart from the neighbours: points inside each neighbour the overlap is measured on, and the
// softness of their inside test (a fraction of the part's extent; it keeps the objective smooth).
constexpr size_t kApartPoints = 200;
// Apart from the neighbours, the volume outside the body counts in full and the collider's own
// volume (mostly inside the body, where it costs nothing unless it reaches a neighbour, which the
// overlap term counts) only lightly: the outside volume is measured on fixed seeded points of the
// start's box, grown by a quarter each side, that lie outside the body (winding number).
constexpr size_t kOutsidePoints = 3000;
constexpr double kOwnVolumeWeight = 0.25, kOutsideBoxGrowth = 0.25;
constexpr double kApartSoftness = 0.01;
// Inscribed: the medial balls paired (the largest, and those at the ends of their line).
constexpr size_t kInscribedLargest = 12, kInscribedEnds = 4;

double cap_volume(double r, double h) { return kPi * h * h * (3 * r - h) / 3; }

// The line through weighted points: (mean, unit direction of largest spread).
std::pair<Vec3, Vec3> principal_line(const std::vector<Vec3>& pts, const std::vector<double>& weight) {
    Vec3 mean = Vec3::Zero();
    double total = 0;
    for (size_t i = 0; i < pts.size(); ++i) mean += weight[i] * pts[i], total += weight[i];
    mean /= std::max(total, 1e-300);
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (size_t i = 0; i < pts.size(); ++i) cov += weight[i] * (pts[i] - mean) * (pts[i] - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    Vec3 dir = eig.eigenvectors().col(2);
    if (!dir.allFinite() || dir.norm() < 0.5) dir = Vec3::UnitX();
    return {mean, dir.normalized()};
}

// The capsule through the medial balls: the line of their centres (weighted by radius), its ends
// at the extreme centres, each end's radius the largest of the balls within a tenth of the length.
Proxy medial_start(const std::vector<Ball>& balls) {
    std::vector<Vec3> c;
    std::vector<double> w;
    for (const Ball& b : balls) c.push_back(b.center), w.push_back(std::max(b.radius, 1e-12));
    const auto [mean, dir] = principal_line(c, w);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Vec3& x : c) lo = std::min(lo, dir.dot(x - mean)), hi = std::max(hi, dir.dot(x - mean));
    const double near = 0.1 * (hi - lo);
    double ra = 0, rb = 0;
    for (const Ball& b : balls) {
        const double t = dir.dot(b.center - mean);
        if (t <= lo + near) ra = std::max(ra, b.radius);
        if (t >= hi - near) rb = std::max(rb, b.radius);
    }
    return Proxy{ProxyKind::capsule, Ball{mean + lo * dir, ra}, Ball{mean + hi * dir, rb}};
}

// Parameters of a capsule: both centres and radii (8), or a sphere's centre (3).
using Params = Eigen::Matrix<double, Eigen::Dynamic, 1>;
Params to_params(const Proxy& p, bool sphere) {
    Params x(sphere ? 3 : 8);
    x.head<3>() = p.a.center;
    if (!sphere) x.segment<3>(3) = p.b.center, x[6] = p.a.radius, x[7] = p.b.radius;
    return x;
}
Proxy from_params(const Params& x) {
    if (x.size() == 3) return Proxy{ProxyKind::sphere, Ball{x.head<3>(), 0.0}, Ball{x.head<3>(), 0.0}};
    return Proxy{ProxyKind::capsule, Ball{x.head<3>(), std::abs(x[6])}, Ball{x.segment<3>(3), std::abs(x[7])}};
}

// Nelder-Mead on f from x0 with the first simplex's steps; deterministic.
template <class F>
Params nelder_mead(F&& f, const Params& x0, const Params& step, int evaluations) {
    const int n = int(x0.size());
    std::vector<Params> s(size_t(n + 1), x0);
    std::vector<double> v(size_t(n + 1));
    for (int i = 0; i < n; ++i) s[size_t(i + 1)][i] += step[i];
    for (size_t i = 0; i < s.size(); ++i) v[i] = f(s[i]);
    int used = n + 1;
    std::vector<size_t> order(s.size());
    while (used < evaluations) {
        for (size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return v[a] < v[b]; });
        const size_t best = order.front(), worst = order.back(), second = order[order.size() - 2];
        if (v[worst] - v[best] <= 1e-12 * std::abs(v[best])) break;
        Params centroid = Params::Zero(n);
        for (size_t i = 0; i + 1 < order.size(); ++i) centroid += s[order[i]];
        centroid /= double(n);
        const Params xr = centroid + (centroid - s[worst]);
        const double fr = f(xr);
        ++used;
        if (fr < v[best]) {
            const Params xe = centroid + 2 * (centroid - s[worst]);
            const double fe = f(xe);
            ++used;
            if (fe < fr) s[worst] = xe, v[worst] = fe;
            else s[worst] = xr, v[worst] = fr;
        } else if (fr < v[second]) {
            s[worst] = xr, v[worst] = fr;
        } else {
            const Params xc = centroid + 0.5 * (s[worst] - centroid);
            const double fc = f(xc);
            ++used;
            if (fc < v[worst]) {
                s[worst] = xc, v[worst] = fc;
            } else {
                for (size_t i = 0; i < s.size(); ++i)
                    if (i != best) s[i] = s[best] + 0.5 * (s[i] - s[best]), v[i] = f(s[i]), ++used;
            }
        }
    }
    size_t best = 0;
    for (size_t i = 1; i < v.size(); ++i)
        if (v[i] < v[best]) best = i;
    return s[best];
}

// At most kSearchPoints of the samples, evenly strided (they are seeded and area-uniform, so any
// stride of them is spread over the part).
std::vector<Vec3> search_points(const std::vector<Vec3>& points) {
    if (points.size() <= kSearchPoints) return points;
    std::vector<Vec3> out;
    out.reserve(kSearchPoints);
    for (size_t i = 0; i < kSearchPoints; ++i) out.push_back(points[i * points.size() / kSearchPoints]);
    return out;
}

// Nelder-Mead on cost (which holds `pts`) from x, then rounds of adding the part's corners the
// result misses most (by more than `tolerance`) to `pts` and resuming with smaller steps.
// Deterministic: ties between corners go to the lower index.
template <class F>
Params search_held(F&& cost, Params x, const Params& step, std::vector<Vec3>& pts, const SurfacePart& part,
                   double tolerance) {
    std::vector<std::pair<double, uint32_t>> miss;
    for (int round = 0;; ++round) {
        x = nelder_mead(cost, x, round == 0 ? step : Params(0.25 * step), round == 0 ? kSearchEvaluations : kSearchEvaluations / 2);
        if (round == kRefineRounds) break;
        const Proxy p = hold_points(from_params(x), pts, 0);
        miss.clear();
        for (size_t i = 0; i < part.corners.size(); ++i) {
            const double d = proxy_distance(p, part.corners[i]);
            if (d > tolerance) miss.emplace_back(-d, uint32_t(i));
        }
        if (miss.empty()) break;
        const size_t k = std::min(miss.size(), kAddedCorners);
        std::partial_sort(miss.begin(), miss.begin() + long(k), miss.end());
        for (size_t i = 0; i < k; ++i) pts.push_back(part.corners[miss[i].second]);
    }
    return x;
}

Proxy fit_conservative(const SurfacePart& part, const std::vector<Ball>& balls, const std::vector<Vec3>& points,
                       bool spheres_only) {
    std::vector<uint32_t> all(points.size());
    for (size_t i = 0; i < all.size(); ++i) all[i] = uint32_t(i);
    std::vector<Proxy> starts;
    starts.push_back(fit_capsule(points, all));
    if (balls.size() >= 2) starts.push_back(medial_start(balls));
    Vec3 lo = points.front(), hi = lo;
    for (const Vec3& x : points) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    const double extent = (hi - lo).norm();
    starts.push_back(Proxy{ProxyKind::sphere, Ball{0.5 * (lo + hi), 0.0}, Ball{0.5 * (lo + hi), 0.0}});
    std::vector<Vec3> pts;
    const auto cost = [&](const Params& x) { return proxy_volume(hold_points(from_params(x), pts, 0)); };
    Proxy best;
    double best_volume = std::numeric_limits<double>::infinity();
    for (const Proxy& start : starts) {
        const bool sphere = spheres_only || start.kind == ProxyKind::sphere;
        Proxy s = start;
        if (sphere) s.b = s.a;
        pts = search_points(points);
        s = hold_points(s, pts, 0);
        Params step(sphere ? 3 : 8);
        step.setConstant(kCentreStep * extent);
        if (!sphere) step[6] = step[7] = kRadiusStep * std::max({s.a.radius, s.b.radius, 1e-3 * extent});
        const Params x = search_held(cost, to_params(s, sphere), step, pts, part, kRefineTolerance * extent);
        const Proxy p = hold_points(hold_points(from_params(x), pts, 0), part.corners, kHoldMargin);
        const double v = proxy_volume(p);
        if (v < best_volume) best_volume = v, best = p;
        if (spheres_only) break;   // every start gives the same sphere search
    }
    if (spheres_only) best.b = best.a, best.kind = ProxyKind::sphere;
    return best;
}

Proxy fit_inscribed(const std::vector<Ball>& balls, const ShapeQueries& shape, bool spheres_only) {
    if (balls.empty()) return Proxy{ProxyKind::sphere, Ball{Vec3::Zero(), 0.0}, Ball{Vec3::Zero(), 0.0}};
    std::vector<uint32_t> pick(balls.size());
    for (size_t i = 0; i < pick.size(); ++i) pick[i] = uint32_t(i);
    std::stable_sort(pick.begin(), pick.end(), [&](uint32_t a, uint32_t b) { return balls[a].radius > balls[b].radius; });
    std::vector<uint32_t> chosen(pick.begin(), pick.begin() + long(std::min(pick.size(), kInscribedLargest)));
    if (!spheres_only && balls.size() >= 2) {
        std::vector<Vec3> c;
        std::vector<double> w;
        for (const Ball& b : balls) c.push_back(b.center), w.push_back(std::max(b.radius, 1e-12));
        const auto [mean, dir] = principal_line(c, w);
        std::vector<uint32_t> by_t(balls.size());
        for (size_t i = 0; i < by_t.size(); ++i) by_t[i] = uint32_t(i);
        std::stable_sort(by_t.begin(), by_t.end(),
                         [&](uint32_t a, uint32_t b) { return dir.dot(c[a] - mean) < dir.dot(c[b] - mean); });
        for (size_t k = 0; k < std::min(kInscribedEnds, by_t.size()); ++k) {
            chosen.push_back(by_t[k]);
            chosen.push_back(by_t[by_t.size() - 1 - k]);
        }
        std::sort(chosen.begin(), chosen.end());
        chosen.erase(std::unique(chosen.begin(), chosen.end()), chosen.end());
    }
    Proxy best;
    double best_volume = -1;
    const auto consider = [&](const Proxy& p) {
        const double bound = outside_bound(p, shape);
        const Proxy q = bound > 0 ? shrunk(p, bound) : p;
        const double v = proxy_volume(q);
        if (v > best_volume) best_volume = v, best = q;
    };
    for (uint32_t i : chosen) consider(Proxy{ProxyKind::sphere, balls[i], balls[i]});
    if (!spheres_only)
        for (size_t i = 0; i < chosen.size(); ++i)
            for (size_t j = i + 1; j < chosen.size(); ++j)
                consider(Proxy{ProxyKind::capsule, balls[chosen[i]], balls[chosen[j]]});
    return best;
}

}  // namespace

double proxy_volume(const Proxy& p) {
    double r1 = p.a.radius, r2 = p.b.radius;
    const double len = p.kind == ProxyKind::sphere ? 0.0 : (p.a.center - p.b.center).norm();
    if (r1 < r2) std::swap(r1, r2);
    if (len <= r1 - r2) return 4 * kPi * r1 * r1 * r1 / 3;   // the larger ball holds the other
    // the hull: the frustum of the cone tangent to both balls, and the caps of each ball beyond
    // its tangent circle (axial coordinate from ball 1, the larger, towards ball 2)
    const double s = (r1 - r2) / len, c = std::sqrt(std::max(0.0, 1 - s * s));
    const double rho1 = r1 * c, rho2 = r2 * c, h = len - (r1 - r2) * s;
    return kPi * h * (rho1 * rho1 + rho1 * rho2 + rho2 * rho2) / 3 + cap_volume(r1, r1 * (1 + s)) +
           cap_volume(r2, r2 * (1 - s));
}

Proxy hold_points(const Proxy& p, const std::vector<Vec3>& points, double margin) {
    // growing both radii by g lowers every signed distance by exactly g (the hull of the grown
    // balls is the primitive's Minkowski sum with a ball); a shrink stops at radius 0, which the
    // next round measures and grows back from
    Proxy q = p;
    for (int round = 0; round < 4; ++round) {
        double need = -std::numeric_limits<double>::infinity();
        for (const Vec3& x : points) need = std::max(need, proxy_distance(q, x));
        if (!std::isfinite(need)) return q;
        if (round > 0 && need <= 0) break;
        q = shrunk(q, -(need + margin));
    }
    return q;
}

Proxy fit_apart(const SurfacePart& part, const std::vector<Vec3>& points, const Proxy& start,
                const std::vector<Proxy>& neighbours, double weight, const ShapeQueries& shape, uint64_t seed) {
    const bool sphere = start.kind == ProxyKind::sphere;
    std::vector<Vec3> pts = search_points(points.empty() ? part.corners : points);
    // fixed points inside each neighbour (common to every trial, so the objective is a function of
    // the shape alone), and the softness of the inside test: a hundredth of the part's extent
    std::vector<std::vector<Vec3>> inside(neighbours.size());
    std::vector<double> volume(neighbours.size());
    Rng rng(seed);
    for (size_t n = 0; n < neighbours.size(); ++n) {
        const auto box = proxy_box(neighbours[n]);
        volume[n] = proxy_volume(neighbours[n]);
        for (size_t tries = 0; tries < 40 * kApartPoints && inside[n].size() < kApartPoints; ++tries) {
            Vec3 x;
            for (int k = 0; k < 3; ++k) x[k] = box.first[k] + (box.second[k] - box.first[k]) * rng.uniform();
            if (proxy_distance(neighbours[n], x) <= 0) inside[n].push_back(x);
        }
    }
    std::vector<Vec3> outside;
    double cell = 0;
    if (shape.winding) {
        auto box = proxy_box(start);
        const Vec3 grow = kOutsideBoxGrowth * (box.second - box.first);
        box.first -= grow, box.second += grow;
        const Vec3 e = box.second - box.first;
        cell = e.x() * e.y() * e.z() / double(kOutsidePoints);
        for (size_t i = 0; i < kOutsidePoints; ++i) {
            Vec3 x;
            for (int k = 0; k < 3; ++k) x[k] = box.first[k] + e[k] * rng.uniform();
            if (!shape.winding->inside(x)) outside.push_back(x);
        }
    }
    Vec3 lo = pts.front(), hi = lo;
    for (const Vec3& x : pts) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    const double extent = (hi - lo).norm(), soft = kApartSoftness * extent;
    const auto cost = [&](const Params& x) {
        const Proxy p = hold_points(from_params(x), pts, 0);
        double out = 0;
        for (const Vec3& y : outside) out += 1 / (1 + std::exp(std::min(proxy_distance(p, y) / soft, 50.0)));
        double lap = 0;
        for (size_t n = 0; n < inside.size(); ++n) {
            if (inside[n].empty()) continue;
            double in = 0;
            for (const Vec3& y : inside[n]) in += 1 / (1 + std::exp(std::min(proxy_distance(p, y) / soft, 50.0)));
            lap += volume[n] * in / double(inside[n].size());
        }
        return (shape.winding ? kOwnVolumeWeight : 1.0) * proxy_volume(p) + cell * out + weight * lap;
    };
    Params step(sphere ? 3 : 8);
    step.setConstant(0.5 * kCentreStep * extent);
    if (!sphere) step[6] = step[7] = kRadiusStep * std::max({start.a.radius, start.b.radius, 1e-3 * extent});
    const Params x = search_held(cost, to_params(start, sphere), step, pts, part, kRefineTolerance * extent);
    Proxy p = hold_points(from_params(x), pts, 0);
    if (sphere) p.b = p.a, p.kind = ProxyKind::sphere;
    return hold_points(p, part.corners, kHoldMargin);
}

Proxy fit_bone(const SurfacePart& part, const std::vector<Ball>& balls, const std::vector<Vec3>& points,
               const ShapeQueries& shape, const BoneColliderOptions& opt) {
    const bool spheres = opt.shapes == ProxyShapes::spheres;
    if (opt.mode == ProxyMode::inscribed) return fit_inscribed(balls, shape, spheres);
    return fit_conservative(part, balls, points.empty() ? part.corners : points, spheres);
}

}  // namespace ca

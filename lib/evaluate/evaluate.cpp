// evaluate.cpp: the reconstruction error of a medial skeleton (EVALUATION.md). Exact signed
// distances to spheres, medial cones and medial slabs; the envelope function F = min over the
// primitives through a BVH over primitive bounding spheres; area-proportional samples of the
// boundary of E; one- and two-sided Hausdorff distances between the input surface and E.
#include "evaluate.h"

#include "distance.h"

#include <Eigen/Geometry>
#include <nanoflann.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <new>
#include <thread>

namespace ca {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

// ---------------------------------------------------------------------------------------------
// Signed distances to one primitive
// ---------------------------------------------------------------------------------------------

double sd_sphere(const Vec3& p, const Vec3& c, double r) { return (p - c).norm() - r; }

double sd_cone(const Vec3& p, const Vec3& c1, double r1, const Vec3& c2, double r2) {
    const Vec3 e = c2 - c1;
    const double L = e.norm();
    const double dr = r2 - r1;
    if (L <= std::abs(dr)) return r1 >= r2 ? sd_sphere(p, c1, r1) : sd_sphere(p, c2, r2);
    const Vec3 a = e / L;
    const Vec3 w = p - c1;
    const double u = w.dot(a);
    const double h = (w - u * a).norm();
    const double t = std::clamp((u + h * dr / std::sqrt(L * L - dr * dr)) / L, 0.0, 1.0);
    return (p - (c1 + t * e)).norm() - (r1 + t * dr);
}

double sd_slab(const Vec3& p, const Vec3& c1, double r1, const Vec3& c2, double r2,
               const Vec3& c3, double r3) {
    auto edges = [&] {
        return std::min({sd_cone(p, c1, r1, c2, r2), sd_cone(p, c1, r1, c3, r3),
                         sd_cone(p, c2, r2, c3, r3)});
    };
    const Vec3 e1 = c1 - c3, e2 = c2 - c3;
    const double l1 = e1.norm(), l2 = e2.norm();
    const Vec3 cr = e1.cross(e2);
    const double crn = cr.norm();
    if (!(crn > 1e-12 * l1 * l2) || l1 == 0 || l2 == 0) return edges();   // collinear centres

    // Orthonormal frame of the centres' plane: u1 along e1, u2 in-plane, m the normal. In it,
    // e1 = (l1, 0) and e2 = (g, hgt); the Gram system a.e1 = -d1, a.e2 = -d2 is triangular.
    const Vec3 m = cr / crn;
    const Vec3 u1 = e1 / l1;
    const Vec3 u2 = m.cross(u1);
    const double g = e2.dot(u1), hgt = e2.dot(u2);
    const double d1 = r1 - r3, d2 = r2 - r3;
    const double a1 = -d1 / l1;
    const double a2 = (-d2 - a1 * g) / hgt;
    const double aa = a1 * a1 + a2 * a2;
    if (!(aa < 1)) return edges();   // no tangent plane touches all three balls
    const double s = std::sqrt(1 - aa);
    if (s == 0) return edges();

    // The tangent plane on p's side of the centres' plane: n = a +- s m, rho >= 0.
    const Vec3 pc = p - c3;
    const double hz = pc.dot(m);
    const double sign = hz >= 0 ? 1.0 : -1.0;
    const Vec3 n = a1 * u1 + a2 * u2 + (sign * s) * m;
    const double rho = hz / (sign * s);
    const Vec3 x = pc - rho * n;   // foot point, relative to c3, in the centres' plane
    const double b2 = x.dot(u2) / hgt;
    const double b1 = (x.dot(u1) - b2 * g) / l1;
    if (b1 >= 0 && b2 >= 0 && b1 + b2 <= 1) return n.dot(pc) - r3;
    return edges();
}

namespace {

// ---------------------------------------------------------------------------------------------
// Deterministic parallel loop: chunks are handed out dynamically, but every index writes only
// its own output, so results do not depend on the scheduling. The caller's thread reports
// progress between its chunks (Monitor::report must run on the caller's thread).
// ---------------------------------------------------------------------------------------------

template <class Fn>
bool parallel_for(size_t n, int32_t threads, const Monitor& monitor, double f0, double f1, Fn&& fn,
                  bool& failed) {
    const size_t chunk = 512;
    const size_t nchunks = (n + chunk - 1) / chunk;
    std::atomic<size_t> next{0}, done{0};
    std::atomic<bool> stop{false}, error{false};
    auto run_chunk = [&](size_t c) {
        const size_t b = c * chunk, e = std::min(n, b + chunk);
        try {
            for (size_t i = b; i < e; ++i) fn(i);
        } catch (...) {
            error = true;
            stop = true;
        }
        ++done;
    };
    auto worker = [&] {
        while (!stop.load(std::memory_order_relaxed)) {
            if (monitor.cancelled()) { stop = true; break; }
            const size_t c = next++;
            if (c >= nchunks) break;
            run_chunk(c);
        }
    };
    unsigned hw = std::thread::hardware_concurrency();
    size_t nthreads = threads > 0 ? size_t(threads) : std::min<size_t>(hw == 0 ? 1 : hw, 8);
    nthreads = std::min(nthreads, std::max<size_t>(nchunks, 1));
    std::vector<std::thread> pool;
    for (size_t t = 1; t < nthreads; ++t) {
        try {
            pool.emplace_back(worker);
        } catch (...) {
            break;   // fewer threads: still correct
        }
    }
    bool cancelled = false;
    while (!stop.load(std::memory_order_relaxed)) {
        const size_t c = next++;
        if (c >= nchunks) break;
        run_chunk(c);
        const double frac = nchunks ? double(done.load()) / double(nchunks) : 1.0;
        if (!monitor.report("evaluate", f0 + (f1 - f0) * frac)) {
            cancelled = true;
            stop = true;
        }
    }
    for (auto& t : pool) t.join();
    if (error) failed = true;
    if (monitor.cancelled()) cancelled = true;
    return !cancelled && !error;
}

// ---------------------------------------------------------------------------------------------
// The envelope: primitives and a BVH over their bounding spheres
// ---------------------------------------------------------------------------------------------

enum class Kind : uint8_t { sphere, cone, slab };

struct Primitive {
    Kind kind;
    uint32_t v[3];
    Vec3 bc;         // bounding sphere of the primitive
    double br;
};

// A binary hierarchy of bounding spheres over items given by their own bounding spheres
// (median split along the longest axis of the centres). `nearest` visits the items whose bound
// |p - b| - rho is below the current best value, nearer subtrees first.
class SphereBvh {
public:
    SphereBvh(std::vector<Vec3> centers, std::vector<double> radii)
        : c_(std::move(centers)), r_(std::move(radii)) {
        order_.resize(c_.size());
        for (uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
        if (!c_.empty()) {
            nodes_.reserve(2 * c_.size());
            nodes_.push_back({});
            build(0, 0, uint32_t(c_.size()));
        }
    }

    // item(i, best) returns the item's value (it may return early once it is >= best);
    // the result is the minimum, or `best` if nothing is below it. With stop_below set, the
    // search ends as soon as a value below it is found.
    template <class Item>
    double nearest(const Vec3& p, double best, Item&& item, double stop_below = -kInf) const {
        if (nodes_.empty()) return best;
        uint32_t stack[128];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& nd = nodes_[stack[--top]];
            if ((p - nd.c).norm() - nd.r >= best) continue;
            if (nd.count > 0) {
                for (uint32_t k = nd.first; k < nd.first + nd.count; ++k) {
                    const uint32_t i = order_[k];
                    if ((p - c_[i]).norm() - r_[i] >= best) continue;
                    best = std::min(best, item(i, best));
                    if (best < stop_below) return best;
                }
                continue;
            }
            const uint32_t l = nd.first, r = nd.first + 1;
            const double dl = (p - nodes_[l].c).norm() - nodes_[l].r;
            const double dr = (p - nodes_[r].c).norm() - nodes_[r].r;
            // push the farther child first so the nearer one is visited first
            if (dl <= dr) {
                if (dr < best) stack[top++] = r;
                if (dl < best) stack[top++] = l;
            } else {
                if (dl < best) stack[top++] = l;
                if (dr < best) stack[top++] = r;
            }
        }
        return best;
    }

private:
    struct Node {
        Vec3 c;
        double r;
        uint32_t first, count;   // leaf: range of order_; inner: count 0, children first, first+1
    };

    void bound(uint32_t node, uint32_t b, uint32_t e) {
        Vec3 lo = Vec3::Constant(kInf), hi = Vec3::Constant(-kInf);
        for (uint32_t k = b; k < e; ++k) {
            const uint32_t i = order_[k];
            lo = lo.cwiseMin(c_[i] - Vec3::Constant(r_[i]));
            hi = hi.cwiseMax(c_[i] + Vec3::Constant(r_[i]));
        }
        const Vec3 c = 0.5 * (lo + hi);
        double r = 0;
        for (uint32_t k = b; k < e; ++k) r = std::max(r, (c_[order_[k]] - c).norm() + r_[order_[k]]);
        nodes_[node].c = c;
        nodes_[node].r = r * (1 + 1e-12);
    }

    void build(uint32_t node, uint32_t b, uint32_t e) {
        bound(node, b, e);
        if (e - b <= 4) {
            nodes_[node].first = b;
            nodes_[node].count = e - b;
            return;
        }
        Vec3 lo = Vec3::Constant(kInf), hi = Vec3::Constant(-kInf);
        for (uint32_t k = b; k < e; ++k) {
            lo = lo.cwiseMin(c_[order_[k]]);
            hi = hi.cwiseMax(c_[order_[k]]);
        }
        int axis = 0;
        (hi - lo).maxCoeff(&axis);
        const uint32_t mid = b + (e - b) / 2;
        std::nth_element(order_.begin() + b, order_.begin() + mid, order_.begin() + e,
                         [&](uint32_t x, uint32_t y) {
                             const double px = c_[x][axis], py = c_[y][axis];
                             return px < py || (px == py && x < y);
                         });
        const uint32_t left = uint32_t(nodes_.size());
        nodes_.push_back({});
        nodes_.push_back({});
        nodes_[node].first = left;
        nodes_[node].count = 0;
        build(left, b, mid);
        build(left + 1, mid, e);
    }

    std::vector<Vec3> c_;
    std::vector<double> r_;
    std::vector<uint32_t> order_;
    std::vector<Node> nodes_;
};

std::vector<Vec3> centers_of(const std::vector<Primitive>& prims) {
    std::vector<Vec3> out;
    for (const Primitive& q : prims) out.push_back(q.bc);
    return out;
}
std::vector<double> radii_of(const std::vector<Primitive>& prims) {
    std::vector<double> out;
    for (const Primitive& q : prims) out.push_back(q.br);
    return out;
}

class Envelope {
public:
    Envelope(const std::vector<Ball>& balls, std::vector<Primitive> prims)
        : balls_(balls), prims_(std::move(prims)), bvh_(centers_of(prims_), radii_of(prims_)) {}

    double sd(const Primitive& q, const Vec3& p) const {
        const Ball& a = balls_[q.v[0]];
        switch (q.kind) {
            case Kind::sphere: return sd_sphere(p, a.center, a.radius);
            case Kind::cone: {
                const Ball& b = balls_[q.v[1]];
                return sd_cone(p, a.center, a.radius, b.center, b.radius);
            }
            case Kind::slab: {
                const Ball& b = balls_[q.v[1]];
                const Ball& c = balls_[q.v[2]];
                return sd_slab(p, a.center, a.radius, b.center, b.radius, c.center, c.radius);
            }
        }
        return kInf;
    }

    // F(p) = min over primitives of sd(p) (primitives are inside their bounding spheres, so
    // sd >= |p - b| - rho, also inside). With stop_below set, returns as soon as a value below
    // it is found (enough to decide F(p) < stop_below).
    double F(const Vec3& p, double stop_below = -kInf) const {
        return bvh_.nearest(p, kInf, [&](uint32_t i, double) { return sd(prims_[i], p); },
                            stop_below);
    }

private:
    const std::vector<Ball>& balls_;
    std::vector<Primitive> prims_;
    SphereBvh bvh_;
};

Primitive make_primitive(const std::vector<Ball>& balls, Kind kind, uint32_t i, uint32_t j,
                         uint32_t k) {
    Primitive q{kind, {i, j, k}, Vec3::Zero(), 0};
    const int nv = kind == Kind::sphere ? 1 : kind == Kind::cone ? 2 : 3;
    Vec3 lo = Vec3::Constant(kInf), hi = Vec3::Constant(-kInf);
    for (int t = 0; t < nv; ++t) {
        const Ball& bl = balls[q.v[t]];
        lo = lo.cwiseMin(bl.center - Vec3::Constant(bl.radius));
        hi = hi.cwiseMax(bl.center + Vec3::Constant(bl.radius));
    }
    q.bc = 0.5 * (lo + hi);
    for (int t = 0; t < nv; ++t) {
        const Ball& bl = balls[q.v[t]];
        q.br = std::max(q.br, (bl.center - q.bc).norm() + bl.radius);
    }
    q.br *= 1 + 1e-12;
    return q;
}

// ---------------------------------------------------------------------------------------------
// Boundary pieces of the primitives, for sampling
// ---------------------------------------------------------------------------------------------

struct Piece {
    Kind kind;       // sphere: whole sphere; cone: lateral surface; slab: one tangent triangle
    Vec3 p[3];       // sphere: centre; cone: axis frame; slab: triangle corners
    double r[2];     // sphere: radius; cone: radii
    double area;
};

void orthonormal_frame(const Vec3& a, Vec3& w1, Vec3& w2) {
    const Vec3 helper = std::abs(a.x()) < 0.6 ? Vec3::UnitX()
                        : std::abs(a.y()) < 0.6 ? Vec3::UnitY() : Vec3::UnitZ();
    w1 = a.cross(helper).normalized();
    w2 = a.cross(w1);
}

void sphere_piece(const Ball& b, std::vector<Piece>& out) {
    const double area = 4 * kPi * b.radius * b.radius;
    if (area > 0) out.push_back({Kind::sphere, {b.center, Vec3::Zero(), Vec3::Zero()},
                                 {b.radius, 0}, area});
}

// Lateral surface of the cone: the tangent segments c_i + r_i n, n = -s a + sqrt(1-s^2) w.
void cone_piece(const Ball& b1, const Ball& b2, std::vector<Piece>& out) {
    const Vec3 e = b2.center - b1.center;
    const double L = e.norm(), dr = b2.radius - b1.radius;
    if (!(L > std::abs(dr))) return;
    const double slant = std::sqrt(L * L - dr * dr);
    const double k = slant / L;   // sqrt(1 - s^2)
    const double area = kPi * (b1.radius + b2.radius) * k * slant;
    if (!(area > 0)) return;
    Piece pc{Kind::cone, {b1.center, b2.center, Vec3::Zero()}, {b1.radius, b2.radius}, area};
    out.push_back(pc);
}

// The two tangent triangles of a slab (none if the tangent planes do not exist).
void slab_pieces(const Ball& b1, const Ball& b2, const Ball& b3, std::vector<Piece>& out) {
    const Vec3 e1 = b1.center - b3.center, e2 = b2.center - b3.center;
    const double l1 = e1.norm(), l2 = e2.norm();
    const Vec3 cr = e1.cross(e2);
    const double crn = cr.norm();
    if (!(crn > 1e-12 * l1 * l2) || l1 == 0 || l2 == 0) return;
    const Vec3 m = cr / crn, u1 = e1 / l1, u2 = m.cross(u1);
    const double g = e2.dot(u1), hgt = e2.dot(u2);
    const double a1 = -(b1.radius - b3.radius) / l1;
    const double a2 = (-(b2.radius - b3.radius) - a1 * g) / hgt;
    const double aa = a1 * a1 + a2 * a2;
    if (!(aa < 1)) return;
    const double s = std::sqrt(1 - aa);
    for (double sign : {1.0, -1.0}) {
        const Vec3 n = a1 * u1 + a2 * u2 + sign * s * m;
        Piece pc{Kind::slab,
                 {b1.center + b1.radius * n, b2.center + b2.radius * n, b3.center + b3.radius * n},
                 {0, 0}, 0};
        pc.area = 0.5 * (pc.p[1] - pc.p[0]).cross(pc.p[2] - pc.p[0]).norm();
        if (pc.area > 0) out.push_back(pc);
    }
}

Vec3 sample_piece(const Piece& pc, Rng& rng) {
    switch (pc.kind) {
        case Kind::sphere: {
            const double z = 2 * rng.uniform() - 1, phi = 2 * kPi * rng.uniform();
            const double q = std::sqrt(std::max(0.0, 1 - z * z));
            return pc.p[0] + pc.r[0] * Vec3(q * std::cos(phi), q * std::sin(phi), z);
        }
        case Kind::cone: {
            const Vec3 e = pc.p[1] - pc.p[0];
            const double L = e.norm(), dr = pc.r[1] - pc.r[0];
            const Vec3 a = e / L;
            const double s = dr / L, k = std::sqrt(std::max(0.0, 1 - s * s));
            Vec3 w1, w2;
            orthonormal_frame(a, w1, w2);
            const double th = 2 * kPi * rng.uniform();
            const Vec3 n = -s * a + k * (std::cos(th) * w1 + std::sin(th) * w2);
            // position along the segment with density proportional to the circle radius,
            // (1-t) r1 + t r2: a mixture of densities 2(1-t) and 2t
            const double pick = rng.uniform() * (pc.r[0] + pc.r[1]);
            const double u = rng.uniform();
            const double t = pick < pc.r[0] ? 1 - std::sqrt(u) : std::sqrt(u);
            const Vec3 q1 = pc.p[0] + pc.r[0] * n, q2 = pc.p[1] + pc.r[1] * n;
            return q1 + t * (q2 - q1);
        }
        case Kind::slab: {
            const double su = std::sqrt(rng.uniform()), v = rng.uniform();
            return (1 - su) * pc.p[0] + su * (1 - v) * pc.p[1] + su * v * pc.p[2];
        }
    }
    return pc.p[0];
}

// Closest point of a boundary piece to p (for a cone: on the tangent segment in p's meridian
// half-plane, since the lateral surface is a surface of revolution).
Vec3 closest_on_piece(const Piece& pc, const Vec3& p) {
    switch (pc.kind) {
        case Kind::sphere: {
            const Vec3 d = p - pc.p[0];
            const double n = d.norm();
            return pc.p[0] + pc.r[0] * (n > 0 ? Vec3(d / n) : Vec3(Vec3::UnitX()));
        }
        case Kind::cone: {
            const Vec3 e = pc.p[1] - pc.p[0];
            const double L = e.norm(), s = (pc.r[1] - pc.r[0]) / L;
            const Vec3 a = e / L;
            const Vec3 rel = p - pc.p[0];
            Vec3 w = rel - rel.dot(a) * a;
            const double wn = w.norm();
            if (wn > 0) {
                w /= wn;
            } else {
                Vec3 w2;
                orthonormal_frame(a, w, w2);
            }
            const Vec3 n = -s * a + std::sqrt(std::max(0.0, 1 - s * s)) * w;
            const Vec3 q1 = pc.p[0] + pc.r[0] * n, q2 = pc.p[1] + pc.r[1] * n;
            const Vec3 d = q2 - q1;
            const double l2 = d.squaredNorm();
            const double t = l2 > 0 ? std::clamp((p - q1).dot(d) / l2, 0.0, 1.0) : 0.0;
            return q1 + t * d;
        }
        case Kind::slab: return closest_point_on_triangle(p, pc.p[0], pc.p[1], pc.p[2]);
    }
    return pc.p[0];
}

// Bounding sphere of a piece.
std::pair<Vec3, double> piece_bound(const Piece& pc) {
    switch (pc.kind) {
        case Kind::sphere: return {pc.p[0], pc.r[0] * (1 + 1e-12)};
        case Kind::cone: {
            const Vec3 c = 0.5 * (pc.p[0] + pc.p[1]);
            return {c, (0.5 * (pc.p[1] - pc.p[0]).norm() + std::max(pc.r[0], pc.r[1])) * (1 + 1e-12)};
        }
        case Kind::slab: {
            const Vec3 c = (pc.p[0] + pc.p[1] + pc.p[2]) / 3.0;
            const double r = std::max({(pc.p[0] - c).norm(), (pc.p[1] - c).norm(), (pc.p[2] - c).norm()});
            return {c, r * (1 + 1e-12)};
        }
    }
    return {pc.p[0], 0};
}

// ---------------------------------------------------------------------------------------------
// Nearest point queries (nanoflann)
// ---------------------------------------------------------------------------------------------

struct PointsAdaptor {
    const std::vector<Vec3>* pts;
    size_t kdtree_get_point_count() const { return pts->size(); }
    double kdtree_get_pt(size_t i, size_t d) const { return (*pts)[i][int(d)]; }
    template <class BBox>
    bool kdtree_get_bbox(BBox&) const { return false; }
};

class NearestPoint {
public:
    explicit NearestPoint(const std::vector<Vec3>& pts)
        : adaptor_{&pts}, tree_(3, adaptor_, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {}
    double distance(const Vec3& p) const {
        uint32_t idx = 0;
        double d2 = kInf;
        const double q[3] = {p.x(), p.y(), p.z()};
        tree_.knnSearch(q, 1, &idx, &d2);
        return std::sqrt(d2);
    }

private:
    using Tree = nanoflann::KDTreeSingleIndexAdaptor<
        nanoflann::L2_Simple_Adaptor<double, PointsAdaptor>, PointsAdaptor, 3, uint32_t>;
    PointsAdaptor adaptor_;
    Tree tree_;
};

bool finite(const Vec3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

Status evaluate_impl(const Mesh& surface, const Skeleton& skeleton_in, const EvaluateOptions& opt,
                     const Monitor& monitor, EvaluateResult& out) {
    // ---- validation ----
    if (skeleton_in.balls.empty()) return fail(Code::invalid_argument, "evaluate: empty skeleton");
    if (surface.vertices.empty()) return fail(Code::degenerate_input, "evaluate: empty surface");
    if (opt.envelope_samples == 0)
        return fail(Code::invalid_argument, "evaluate: envelope_samples must be positive");
    const size_t nv = surface.vertices.size();
    for (const Vec3& v : surface.vertices)
        if (!finite(v)) return fail(Code::invalid_input, "evaluate: non-finite surface vertex");
    for (const Tri& t : surface.triangles)
        if (t[0] >= nv || t[1] >= nv || t[2] >= nv)
            return fail(Code::invalid_input, "evaluate: triangle index out of range");
    for (const Ball& b : skeleton_in.balls)
        if (!finite(b.center) || !std::isfinite(b.radius) || b.radius < 0)
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
    bool failed = false;
    auto cancelled_or_failed = [&] {
        return failed ? fail(Code::internal, "evaluate: a worker failed")
                      : fail(Code::cancelled, "evaluate: cancelled");
    };
    if (!monitor.report("evaluate", 0.0)) return cancelled_or_failed();

    // ---- primitives of F: every face as a slab, every edge in no face as a cone, every ball
    // on no edge as a sphere (a slab's distance already is the minimum over its edge cones and
    // balls, so adding those would not change F) ----
    std::vector<Primitive> prims;
    std::vector<char> edge_in_face(sk.edges.size(), 0), ball_on_edge(nb, 0);
    auto edge_index = [&](uint32_t a, uint32_t b) {
        const std::array<uint32_t, 2> key{a, b};
        return size_t(std::lower_bound(sk.edges.begin(), sk.edges.end(), key) - sk.edges.begin());
    };
    for (const Tri& f : sk.faces) {
        prims.push_back(make_primitive(balls, Kind::slab, f[0], f[1], f[2]));
        edge_in_face[edge_index(f[0], f[1])] = 1;
        edge_in_face[edge_index(f[0], f[2])] = 1;
        edge_in_face[edge_index(f[1], f[2])] = 1;
    }
    for (size_t i = 0; i < sk.edges.size(); ++i) {
        const auto& e = sk.edges[i];
        ball_on_edge[e[0]] = ball_on_edge[e[1]] = 1;
        if (!edge_in_face[i]) prims.push_back(make_primitive(balls, Kind::cone, e[0], e[1], 0));
    }
    for (uint32_t i = 0; i < nb; ++i)
        if (!ball_on_edge[i]) prims.push_back(make_primitive(balls, Kind::sphere, i, 0, 0));
    const Envelope env(balls, std::move(prims));

    // ---- boundary samples of E: sample every sphere, cone lateral surface and slab tangent
    // triangle area-proportionally; keep those not strictly inside another primitive ----
    std::vector<Piece> pieces;
    for (const Ball& b : balls) sphere_piece(b, pieces);
    for (const auto& e : sk.edges) cone_piece(balls[e[0]], balls[e[1]], pieces);
    for (const Tri& f : sk.faces) slab_pieces(balls[f[0]], balls[f[1]], balls[f[2]], pieces);
    double total_area = 0;
    for (const Piece& pc : pieces) total_area += pc.area;

    std::vector<Vec3> boundary;
    const size_t target = opt.envelope_samples;
    if (total_area > 0) {
        Rng rng(opt.seed ^ 0x6A09E667F3BCC909ull);
        size_t generated = 0;
        for (int round = 0; round < 8 && boundary.size() < target; ++round) {
            // expected fraction kept so far (start optimistic), with a margin
            const double frac = generated ? std::max(double(boundary.size()) / double(generated), 1e-3) : 1.0;
            double want = double(target - boundary.size()) / frac * (round ? 1.1 : 1.0);
            want = std::min(want, 20.0 * double(target));
            std::vector<Vec3> cand;
            cand.reserve(size_t(want) + pieces.size());
            for (const Piece& pc : pieces) {
                const size_t cnt = size_t(std::floor(want * pc.area / total_area + rng.uniform()));
                for (size_t k = 0; k < cnt; ++k) cand.push_back(sample_piece(pc, rng));
            }
            generated += cand.size();
            std::vector<char> keep(cand.size(), 0);
            const double f0 = 0.3 * round / 8.0, f1 = 0.3 * (round + 1) / 8.0;
            if (!parallel_for(cand.size(), opt.threads, monitor, f0, f1,
                              [&](size_t i) { keep[i] = env.F(cand[i], -tol) > -tol; }, failed))
                return cancelled_or_failed();
            for (size_t i = 0; i < cand.size(); ++i)
                if (keep[i]) boundary.push_back(cand[i]);
        }
    }
    if (boundary.empty()) {   // zero-area envelope (all radii zero): use the centres
        for (const Ball& b : balls) boundary.push_back(b.center);
    }
    if (!monitor.report("evaluate", 0.3)) return cancelled_or_failed();

    // ---- surface samples: area-uniform points on the triangles plus the input vertices ----
    std::vector<Vec3> samples;
    const auto& V = surface.vertices;
    if (!surface.triangles.empty()) {
        std::vector<double> cdf(surface.triangles.size());
        double acc = 0;
        for (size_t t = 0; t < surface.triangles.size(); ++t) {
            const Tri& tr = surface.triangles[t];
            acc += 0.5 * (V[tr[1]] - V[tr[0]]).cross(V[tr[2]] - V[tr[0]]).norm();
            cdf[t] = acc;
        }
        if (acc > 0) {
            Rng rng(opt.seed ^ 0xBB67AE8584CAA73Bull);
            samples.reserve(opt.surface_samples + nv);
            for (uint32_t k = 0; k < opt.surface_samples; ++k) {
                const double x = rng.uniform() * acc;
                size_t t = size_t(std::upper_bound(cdf.begin(), cdf.end(), x) - cdf.begin());
                t = std::min(t, cdf.size() - 1);
                const Tri& tr = surface.triangles[t];
                const double su = std::sqrt(rng.uniform()), v = rng.uniform();
                samples.push_back((1 - su) * V[tr[0]] + su * (1 - v) * V[tr[1]] + su * v * V[tr[2]]);
            }
        }
    }
    samples.insert(samples.end(), V.begin(), V.end());

    // ---- h(S -> E): F where F >= 0 (exact); inside E the distance to the nearest boundary
    // sample, tightened by the closest points of the nearby pieces (spheres, cone surfaces,
    // tangent triangles) that lie on the boundary of E. Both are points of the boundary, so
    // the value stays an upper bound of the true distance, and -F a lower bound. ----
    std::vector<double> d_se(samples.size());
    {
        const NearestPoint nearest_boundary(boundary);
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
        if (!parallel_for(samples.size(), opt.threads, monitor, 0.3, 0.5,
                          [&](size_t i) {
                              const double f = env.F(samples[i]);
                              // on or outside E (up to rounding): F is the exact distance
                              d_se[i] = f > -tol ? std::max(f, 0.0) : inside_distance(samples[i]);
                          },
                          failed))
            return cancelled_or_failed();
    }

    // ---- h(E -> S) ----
    std::vector<double> d_es(boundary.size());
    if (!surface.triangles.empty()) {
        const MeshDistance md(surface);
        if (!parallel_for(boundary.size(), opt.threads, monitor, 0.5, 1.0,
                          [&](size_t i) { d_es[i] = md.distance(boundary[i]); }, failed))
            return cancelled_or_failed();
    } else {
        const NearestPoint nearest_input(V);
        if (!parallel_for(boundary.size(), opt.threads, monitor, 0.5, 1.0,
                          [&](size_t i) { d_es[i] = nearest_input.distance(boundary[i]); }, failed))
            return cancelled_or_failed();
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
    try {
        return evaluate_impl(surface, skeleton, opt, monitor, out);
    } catch (const std::bad_alloc&) {
        return fail(Code::out_of_memory, "evaluate: out of memory");
    } catch (const std::exception& e) {
        return fail(Code::internal, std::string("evaluate: ") + e.what());
    } catch (...) {
        return fail(Code::internal, "evaluate: unknown error");
    }
}

}  // namespace ca

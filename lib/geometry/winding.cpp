// winding.cpp: generalised winding numbers. Exact per-triangle solid angles (Van Oosterom-
// Strackee, atan2 form), and the hierarchical approximation of Barill et al. 2018: every BVH
// node stores a Taylor expansion (dipole, first- and second-order moments) of its triangles'
// solid-angle field about its area-weighted centroid; a query uses it when it is farther than
// beta * radius from that centre and recurses otherwise (leaves are summed exactly). The inside
// decision takes the same walk with a cheaper atan2 and a proven rounding bound (see inside()).
#include "winding.h"
#include "bvh.h"
#include "far_field.h"
#include "parallel.h"
#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <cmath>

namespace ca {
using detail::Expansion;
namespace {

constexpr double kFourPi = 4.0 * 3.14159265358979323846;

constexpr double kPi = 3.14159265358979323846;

// Signed solid angle of triangle (a, b, c) seen from q; positive when q is behind the triangle
// (on the side opposite to its right-handed normal). Degenerate triangles give 0, never NaN.
// `arc(y, x)` is atan2 or atan2_approx, on the same num and den.
template <class Arc>
double solid_angle_by(const Vec3& q, const Vec3& a0, const Vec3& b0, const Vec3& c0, Arc arc) {
    const Vec3 a = a0 - q, b = b0 - q, c = c0 - q;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double num = a.dot(b.cross(c));
    if (num == 0) return 0.0;   // coplanar with q (or zero area): atan2(0, den < 0) would give 2 pi
    const double den = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    return 2.0 * arc(num, den);
}

double solid_angle(const Vec3& q, const Vec3& a0, const Vec3& b0, const Vec3& c0) {
    return solid_angle_by(q, a0, b0, c0, [](double y, double x) { return std::atan2(y, x); });
}

// atan2(y, x) for y != 0 within kArcError of the true value (NaN in, NaN out). The octant
// reduction t = min(|x|, |y|) / max(|x|, |y|) in [0, 1], then for t > tan(pi/12) the identity
// atan t = pi/6 + atan s, s = (sqrt3 t - 1) / (sqrt3 + t), leaves |s| <= tan(pi/12) = 0.26795;
// atan s = s - s^3/3 + s^5/5 - ... is alternating with falling terms there, so cutting it after
// s^17/17 errs by at most |s|^19/19 < 7.3e-13. Rounding adds < 1e-14 (every quantity is O(1) and
// about 30 operations touch it; atan' <= 1 carries s's error unchanged), hence 1e-12.
constexpr double kArcError = 1e-12;
double atan2_approx(double y, double x) {
    constexpr double kTan15 = 0.26794919243112270, kSqrt3 = 1.7320508075688772;
    const double ax = std::fabs(x), ay = std::fabs(y);
    const bool steep = ay > ax;
    const double t = steep ? ax / ay : ay / ax;
    double s = t, base = 0;
    if (t > kTan15) {
        s = (kSqrt3 * t - 1.0) / (kSqrt3 + t);
        base = kPi / 6;
    }
    const double s2 = s * s;
    double p = 1.0 / 17;
    for (const double k : {-1.0 / 15, 1.0 / 13, -1.0 / 11, 1.0 / 9, -1.0 / 7, 1.0 / 5, -1.0 / 3, 1.0}) p = k + s2 * p;
    double a = base + s * p;
    if (steep) a = 0.5 * kPi - a;
    if (x < 0) a = kPi - a;
    return y < 0 ? -a : a;
}

// The largest squared distance from c to a triangle corner under node `root`: the maximum over
// all of them, with a subtree skipped when even its box's farthest corner is no farther than
// the best so far (a box corner bounds every point in the box; the factor 1 + 1e-12 covers
// rounding, so no skipped corner could have raised the maximum: the value is the full walk's).
double farthest_corner(const std::vector<detail::BvhNode>& nodes, const std::vector<std::array<Vec3, 3>>& tris,
                       uint32_t root, const Vec3& c) {
    auto bound = [&](uint32_t n) {
        const detail::BvhNode& b = nodes[n];
        return Vec3((c - b.lo).cwiseMax(b.hi - c)).squaredNorm();
    };
    double r2 = 0;
    uint32_t stack[128];   // median-split tree: depth + 1 entries at most
    int top = 0;
    stack[top++] = root;
    while (top > 0) {
        const uint32_t n = stack[--top];
        if (bound(n) * (1 + 1e-12) <= r2) continue;
        const detail::BvhNode& node = nodes[n];
        if (node.leaf()) {
            for (uint32_t i = node.begin; i < node.end; ++i)
                for (const Vec3& p : tris[i]) r2 = std::max(r2, (p - c).squaredNorm());
        } else if (bound(node.left) > bound(node.right)) {   // the farther child first
            stack[top++] = node.right;
            stack[top++] = node.left;
        } else {
            stack[top++] = node.left;
            stack[top++] = node.right;
        }
    }
    return r2;
}

// A node's area sums and its expansion about its centre, returned to its parent (the radius is
// unused there).
struct Sums {
    double weight = 0;               // total area
    Vec3 weighted = Vec3::Zero();    // area-weighted centroid sum
    Expansion expansion;
};

// The far field of every node of a tree, bottom-up: a leaf sums its triangles' moments about its
// centre, a parent shifts its children's moments to its own centre, so the build is O(F) apart
// from the radius (the farthest corner from the centre, over the node's triangles: farthest_corner
// prunes that walk by the node boxes). A node's moments are returned to its parent through the
// recursion (its depth is the tree's, about log2(F / 8)), so only the queries' far fields are
// stored. With threads > 1 the subtrees below the top levels are done at once.
class FarFieldBuilder {
public:
    FarFieldBuilder(const detail::TriangleTree& tree, double beta, std::vector<detail::FarField>& out,
                    const std::function<bool()>& stop)
        : nodes_(tree.bvh.nodes), tris_(tree.tris), beta_(beta), out_(out), stop_(stop) {}

    // false when stopped
    bool run(int threads) {
        if (threads > 1 && !nodes_[0].leaf()) expand_parallel(threads);
        else expand(0);
        return !halted_.load(std::memory_order_relaxed);
    }

private:
    // the node's radius and far field from its expansion about its centre
    void finish(uint32_t n, Expansion& e, Sums& out) {
        e.radius = std::sqrt(farthest_corner(nodes_, tris_, n, e.centre));
        out.expansion = e;
        out_[n] = detail::FarField(e, beta_);
    }

    Vec3 centre(uint32_t n, const Sums& s) const {
        const detail::BvhNode& node = nodes_[n];
        return s.weight > 0 ? Vec3(s.weighted / s.weight) : Vec3(0.5 * (node.lo + node.hi));
    }

    Sums leaf(uint32_t n) {
        const detail::BvhNode& node = nodes_[n];
        Sums out;
        for (uint32_t i = node.begin; i < node.end; ++i) {
            const auto& v = tris_[i];
            const Vec3 a = 0.5 * (v[1] - v[0]).cross(v[2] - v[0]);
            const Vec3 c = (v[0] + v[1] + v[2]) / 3.0;
            out.weight += a.norm();
            out.weighted += a.norm() * c;
        }
        Expansion e;
        e.centre = centre(n, out);
        for (uint32_t i = node.begin; i < node.end; ++i) {
            const auto& v = tris_[i];
            const Vec3 a = 0.5 * (v[1] - v[0]).cross(v[2] - v[0]);
            const Vec3 c = (v[0] + v[1] + v[2]) / 3.0;
            Eigen::Matrix3d S = Eigen::Matrix3d::Zero();   // E[(x - centre)(x - centre)^T] over the triangle
            for (const Vec3& p : v) S += (p - c) * (p - c).transpose();
            const Vec3 d = c - e.centre;
            S = S / 12.0 + d * d.transpose();
            e.N += a;
            e.M += a * d.transpose();
            for (int k = 0; k < 3; ++k) e.Q[k] += a[k] * S;
        }
        finish(n, e, out);
        return out;
    }

    Sums parent(uint32_t n, const Sums& left, const Sums& right) {
        Sums out;
        out.weight = left.weight + right.weight;
        out.weighted = left.weighted + right.weighted;
        Expansion e;
        e.centre = centre(n, out);
        for (const Sums* child : {&left, &right}) {
            const Expansion& ch = child->expansion;
            const Vec3 s = ch.centre - e.centre;   // d about the parent = d about the child + s
            e.N += ch.N;
            e.M += ch.M + ch.N * s.transpose();
            for (int k = 0; k < 3; ++k) {
                const Vec3 row = ch.M.row(k).transpose();
                e.Q[k] += ch.Q[k] + row * s.transpose() + s * row.transpose() + ch.N[k] * (s * s.transpose());
            }
        }
        finish(n, e, out);
        return out;
    }

    Sums expand(uint32_t n) {
        // a node's radius pass reads all its triangles: near the root a test every node, below
        // every kStopCheckItems nodes (the recursion visits the ids in order: parents first)
        if (halted_.load(std::memory_order_relaxed)) return Sums{};
        const detail::BvhNode& node = nodes_[n];
        if (stop_ && (n % detail::kStopCheckItems == 0 || node.end - node.begin > detail::kStopCheckItems) &&
            stop_()) {
            halted_.store(true, std::memory_order_relaxed);
            return Sums{};
        }
        if (node.leaf()) return leaf(n);
        const Sums left = expand(node.left), right = expand(node.right);
        if (halted_.load(std::memory_order_relaxed)) return Sums{};
        return parent(n, left, right);
    }

    // The roots of the subtrees below the top `levels` levels, in preorder.
    void collect(uint32_t n, int depth, int levels, std::vector<uint32_t>& below) const {
        const detail::BvhNode& node = nodes_[n];
        if (depth < levels && !node.leaf()) {
            collect(node.left, depth + 1, levels, below);
            collect(node.right, depth + 1, levels, below);
        } else {
            below.push_back(n);
        }
    }

    // The top nodes from the subtrees' sums (taken in preorder from `at`), each from its
    // children's sums by the same expressions as on one thread.
    Sums combine(uint32_t n, int depth, int levels, const std::vector<Sums>& sums, size_t& at) {
        const detail::BvhNode& node = nodes_[n];
        if (depth < levels && !node.leaf()) {
            const Sums left = combine(node.left, depth + 1, levels, sums, at);
            const Sums right = combine(node.right, depth + 1, levels, sums, at);
            return parent(n, left, right);
        }
        return sums[at++];
    }

    // The subtrees below the top levels (as many as threads, like the tree's build) expanded at
    // once, then the top nodes combined here.
    void expand_parallel(int threads) {
        const int levels = detail::parallel_top_levels(threads);
        std::vector<uint32_t> below;
        collect(0, 0, levels, below);
        std::vector<Sums> sums(below.size());
        const size_t workers = std::min(below.size(), size_t(threads));
        run_workers(workers, [&](size_t w) {
            for (size_t i = w; i < below.size(); i += workers) sums[i] = expand(below[i]);
        });
        size_t at = 0;
        if (!halted_.load(std::memory_order_relaxed)) combine(0, 0, levels, sums, at);
    }

    const std::vector<detail::BvhNode>& nodes_;
    const std::vector<std::array<Vec3, 3>>& tris_;
    const double beta_;
    std::vector<detail::FarField>& out_;
    const std::function<bool()>& stop_;
    std::atomic<bool> halted_{false};
};

// `count` zero far fields, reserved (address space only) and then filled kStopCheckItems at a
// time with a stop test before each chunk: filling them touches every page, which a stop request
// should not have to wait for (nor free afterwards). false when stopped.
bool zero_far_fields(std::vector<detail::FarField>& exp, size_t count, const std::function<bool()>& stop) {
    reserve_large(exp, count);
    for (size_t filled = 0; filled < count;) {
        if (stop && stop()) return false;
        filled = std::min<size_t>(count, filled + detail::kStopCheckItems);
        exp.resize(filled);
    }
    return true;
}

}  // namespace

struct WindingNumber::Impl {
    double beta = 2.0;
    std::shared_ptr<const detail::TriangleTree> tree;
    const detail::Bvh& bvh;
    const std::vector<std::array<Vec3, 3>>& tris;   // triangle corners, in bvh.order
    std::vector<detail::FarField> exp;              // one per BVH node
    explicit Impl(std::shared_ptr<const detail::TriangleTree> t) : tree(std::move(t)), bvh(tree->bvh), tris(tree->tris) {}
};

WindingNumber::WindingNumber(const Mesh& mesh, double beta) : WindingNumber(detail::build_triangle_tree(mesh), beta) {}

WindingNumber::WindingNumber(std::shared_ptr<const detail::TriangleTree> tree, double beta, int threads,
                             const std::function<bool()>& stop)
    : impl_(std::make_unique<Impl>(std::move(tree))) {
    Impl& m = *impl_;
    m.beta = (beta >= 0 && std::isfinite(beta)) ? beta : 2.0;
    const size_t count = m.bvh.nodes.size();
    if (count == 0) return;
    if (!zero_far_fields(m.exp, count, stop) || !FarFieldBuilder(*m.tree, m.beta, m.exp, stop).run(threads))
        impl_.reset();   // a stopped build answers 0 everywhere
}

WindingNumber::~WindingNumber() = default;
WindingNumber::WindingNumber(WindingNumber&&) noexcept = default;
WindingNumber& WindingNumber::operator=(WindingNumber&&) noexcept = default;

double WindingNumber::operator()(const Vec3& q) const {
    if (!impl_ || impl_->bvh.nodes.empty()) return 0.0;
    const Impl& m = *impl_;
    return detail::far_field_sum(m.bvh.nodes, m.exp, q, [&](const Vec3& p, uint32_t i) {
               return solid_angle(p, m.tris[i][0], m.tris[i][1], m.tris[i][2]);
           }) / kFourPi;
}

// The decision of operator() at q (fl(omega / 4pi) > 1/2) from the same walk with atan2_approx
// for the leaves' atan2 (a libm call is most of a leaf term's cost), and the accurate walk only
// when that decision is not certain. Why it always equals operator()'s: both sum the same n
// terms in the same order (the same far/near tests; the far terms are the same expression on the
// same arguments, so equal: this file is built with -ffp-contract=off, no fused multiply-adds
// placed differently in the two walks); a leaf term is 2 atan2(num, den) on the same num and den, so the
// two differ by at most D = 2 (kArcError + 1 ulp of libm's atan2) < 4e-12 per term. Recursive
// summation errs by at most gamma_(n-1) sum |t_i| (Higham, Accuracy and Stability, 4.2), so
// |omega - omega~| <= n D + gamma_(n-1) (2 sum |t~_i| + n D), with gamma_(n-1) < 1e-15 n taken
// (a factor 9 above n u, which also covers this bound's own rounding). fl(omega / 4pi) > 1/2 when
// omega > 2pi (1 + 1e-15) and not when omega < 2pi (1 - 1e-15) (one division, relative error u).
bool WindingNumber::inside(const Vec3& q) const {
    if (!impl_ || impl_->bvh.nodes.empty()) return false;
    const Impl& m = *impl_;
    double terms = 0, magnitude = 0;
    const double omega = detail::far_field_sum(
        m.bvh.nodes, m.exp, q,
        [&](const Vec3& p, uint32_t i) { return solid_angle_by(p, m.tris[i][0], m.tris[i][1], m.tris[i][2], atan2_approx); },
        [&](double t) {
            terms += 1;
            magnitude += std::fabs(t);
        });
    constexpr double kTermBound = 4e-12;
    static_assert(2 * (kArcError + 1e-15) <= kTermBound, "D = 2 (kArcError + 1 ulp) per term");
    const double slack = terms * kTermBound + 1e-15 * terms * (2 * magnitude + terms * kTermBound);
    const double half = 0.5 * kFourPi;
    if (omega - slack > half * (1 + 1e-15)) return true;
    if (omega + slack < half * (1 - 1e-15)) return false;
    return (*this)(q) > 0.5;   // also a NaN omega~ (non-finite input)
}

double winding_number_brute_force(const Mesh& mesh, const Vec3& q) {
    double omega = 0;
    for (const Tri& f : mesh.triangles) {
        if (!detail::triangle_ok(mesh, f)) continue;
        omega += solid_angle(q, mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]]);
    }
    return omega / kFourPi;
}

double signed_volume(const Mesh& mesh) {
    double v = 0;
    for (const Tri& f : mesh.triangles) {
        if (!detail::triangle_ok(mesh, f)) continue;
        v += mesh.vertices[f[0]].dot(mesh.vertices[f[1]].cross(mesh.vertices[f[2]]));
    }
    return v / 6.0;
}

}  // namespace ca

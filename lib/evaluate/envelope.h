// envelope.h: the envelope function F = min over the skeleton's primitives through a BVH over
// their bounding spheres, and the boundary pieces of the primitives that the envelope samples are
// drawn from (envelope.cpp); shared by the evaluation files, not part of the library's interface.
#pragma once
#include "evaluate.h"
#include "rng.h"

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace ca {
namespace eval {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();

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

std::vector<Vec3> centers_of(const std::vector<Primitive>& prims);
std::vector<double> radii_of(const std::vector<Primitive>& prims);

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
    // F(p) and the primitive that attains it (index into primitives()).
    double F(const Vec3& p, uint32_t& which) const {
        which = 0;
        return bvh_.nearest(p, kInf, [&](uint32_t i, double best) {
            const double d = sd(prims_[i], p);
            if (d < best) which = i;
            return d;
        });
    }
    const std::vector<Primitive>& primitives() const { return prims_; }

private:
    const std::vector<Ball>& balls_;
    std::vector<Primitive> prims_;
    SphereBvh bvh_;
};

// The primitive of balls i (sphere), i-j (cone) or i-j-k (slab) with its bounding sphere.
Primitive make_primitive(const std::vector<Ball>& balls, Kind kind, uint32_t i, uint32_t j, uint32_t k);

// The primitives of F for a canonical skeleton: every face as a slab, every edge in no face as a
// cone, every ball on no edge as a sphere (a slab's distance already is the minimum over its edge
// cones and balls, so adding those would not change F).
std::vector<Primitive> envelope_primitives(const Skeleton& sk);

// ---------------------------------------------------------------------------------------------
// Boundary pieces of the primitives, for sampling
// ---------------------------------------------------------------------------------------------

struct Piece {
    Kind kind;       // sphere: whole sphere; cone: lateral surface; slab: one tangent triangle
    Vec3 p[3];       // sphere: centre; cone: axis frame; slab: triangle corners
    double r[2];     // sphere: radius; cone: radii
    double area;
};

// The boundary pieces of a sphere, of a cone's lateral surface, and of a slab's two tangent triangles.
void sphere_piece(const Ball& b, std::vector<Piece>& out);
void cone_piece(const Ball& b1, const Ball& b2, std::vector<Piece>& out);
void slab_pieces(const Ball& b1, const Ball& b2, const Ball& b3, std::vector<Piece>& out);
// A point drawn area-uniformly on the piece.
Vec3 sample_piece(const Piece& pc, Rng& rng);
// Closest point of the piece to p.
Vec3 closest_on_piece(const Piece& pc, const Vec3& p);
// Bounding sphere of the piece.
std::pair<Vec3, double> piece_bound(const Piece& pc);
// Every sphere, cone lateral surface and slab tangent triangle of a canonical skeleton.
std::vector<Piece> boundary_pieces(const Skeleton& sk);
// Samples of the boundary of E: at least `target` points drawn area-proportionally on the pieces
// (in up to 8 rounds), keeping those not strictly inside another primitive (F > -tol); the
// result is empty if the envelope has zero area. Progress from..to of `stage`; false if cancelled.
bool sample_boundary(const Envelope& env, const std::vector<Piece>& pieces, size_t target, uint64_t seed,
                     double tol, int threads, const Monitor& monitor, const char* stage, double from,
                     double to, std::vector<Vec3>& out);

}  // namespace eval
}  // namespace ca

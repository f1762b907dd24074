// correspondence.h: which part of a skeleton each surface point belongs to: the nearest skeleton
// primitive (ball, edge or face) and up to four ball weights that sum to 1 and vary continuously
// over the surface (skin weights, segmentation). Everything in the caller's units.
#pragma once
#include "common.h"
#include "skeleton.h"

#include <array>
#include <limits>
#include <memory>
#include <vector>

namespace ca {

constexpr int kInfluences = 4;   // ball (joint) weights kept per point, as glTF skins take

struct CorrespondOptions {
    // The blend's width: primitives whose distance exceeds the nearest one's by about
    // smoothing x the median ball radius weigh e^-1 of it. Larger: softer, wider blends. > 0.
    double smoothing = 0.5;
    int32_t threads = 0;   // 0 = all cores
};

enum class NearestKind : int32_t { ball = 0, edge = 1, face = 2 };

struct Correspondence {
    // Per point, by decreasing weight: kInfluences balls and weights (sum 1); an unused slot has
    // weight 0 and repeats the first ball.
    std::vector<std::array<uint32_t, kInfluences>> balls;
    std::vector<std::array<double, kInfluences>> weights;
    // The primitive whose envelope (ball, medial cone of an edge, medial slab of a face) is
    // nearest; an edge attained at one end counts as that end's ball. Index into the skeleton's
    // balls, edges or faces.
    std::vector<NearestKind> nearest_kind;
    std::vector<uint32_t> nearest_index;
};

// A sparse weight vector over balls (ball, weight), or over joints.
using SparseWeights = std::vector<std::pair<uint32_t, double>>;

// The options in range; the points finite and at least one.
Status check_options(const CorrespondOptions& opt);
Status check_points(const std::vector<Vec3>& points);

// The skeleton's values finite, radii >= 0, edge and face indices in range, at least one ball
// (every step that takes the caller's skeleton checks it so).
Status check_skeleton(const Skeleton& s);

// The blend at any point: every primitive near p weighs exp(-(d - d_min) / sigma) (less a cut so
// that far ones weigh exactly 0), d its signed distance to p, and contributes the weights of its
// balls at the sphere that attains d (an edge's two ends linearly, a face's three
// barycentrically). Every primitive's distance and attaining sphere move continuously with p, and a
// face's interior weight fades to 0 at its border where its edges take over, so the blend is
// continuous. The skeleton must pass check_skeleton and outlive the object.
class BallBlend {
public:
    BallBlend(const Skeleton& s, const CorrespondOptions& opt);
    ~BallBlend();
    BallBlend(const BallBlend&) = delete;
    BallBlend& operator=(const BallBlend&) = delete;
    // The full blend at p (sum 1, sorted by ball) and the nearest primitive.
    void blend(const Vec3& p, SparseWeights& out, NearestKind& kind, uint32_t& index) const;
    double sigma() const { return sigma_; }

private:
    struct Term {
        double d = std::numeric_limits<double>::infinity();  // signed distance to the envelope
        double fade = 1;          // a face's weight factor, 0 at its border
        uint32_t ball[3] = {0, 0, 0};
        double w[3] = {0, 0, 0};  // the attaining sphere's weights on ball[]
        int count = 0;            // balls used
    };
    struct Impl;
    Term term(uint32_t item, const Vec3& p) const;

    const Skeleton& s_;
    double sigma_ = 1;
    std::unique_ptr<Impl> impl_;
};

// The largest kInfluences entries of w (ties: lower index first), each less the next entry's
// value so that an entry leaving the top kInfluences does so at weight 0, normalised to sum 1.
// Unused slots: weight 0 and the first index. w must not be empty.
void top_weights(SparseWeights w, std::array<uint32_t, kInfluences>& index, std::array<double, kInfluences>& weight);

// The correspondence of every point (opt.threads; the result does not depend on them).
Status correspond(const std::vector<Vec3>& points, const Skeleton& s, const CorrespondOptions& opt,
                  const Monitor& monitor, Correspondence& out);

}  // namespace ca

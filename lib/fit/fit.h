// fit.h: step 3b of the pipeline (after connecting): moves each ball's centre and radius so that
// the reconstruction E (union of spheres, cones and slabs, lib/evaluate) fits the surface, with
// the skeleton's edges and faces unchanged (docs/fidelity.md).
//
// The residual at a point p is F(p) - g(p): F the signed distance to E, g the signed distance to
// the surface (negative inside). It is taken at surface samples (g = 0: the surface is missed or
// overshot) and at samples of the boundary of E (F = 0: a bulge out of the shape or a crevice of
// the union deep inside it), so both one-sided Hausdorff distances are seen. Each boundary piece
// draws its samples from a random stream of its own, so they move with the balls and the
// residuals of successive iterates are comparable. Levenberg-Marquardt on these residuals,
// weighted |r|^(p-2) (an L^p fit leaning towards the maximum), with a Tikhonov term on the step
// and analytic gradients (the sphere of the closest primitive that attains F). A step is tried at
// full, half and quarter length and taken if the L^p mean of the residuals falls; the fit stops at
// the first step refused at all three; of the connected skeleton and every trial (taken or
// refused) the one of lowest maximum residual is kept. Every iterate is projected: each centre stays inside the shape
// (winding number > 1/2; a centre that would leave keeps its old position) and each radius is at
// most the centre's distance to the surface plus an allowance: radius_tolerance, or the excess the
// connected ball had over its centre's distance if larger.
// The thorough fit (FitOptions::thorough, off by default; choose.cpp) runs this fit and a second
// one and keeps the one the evaluator measures closer. The covered fit (cover.cpp) repairs the
// cover the fit breaks with added balls and refits keeping it.
#pragma once
#include "candidates.h"
#include "connect.h"
#include "selection.h"
#include "skeleton.h"

namespace ca {

struct FitOptions {
    uint32_t iterations = 10;          // at most this many Levenberg-Marquardt steps (each tries up to 3 lengths)
    uint32_t surface_samples = 4000;   // surface residual points
    uint32_t envelope_samples = 4000;  // boundary-of-E residual points (about; moved with the balls)
    double power = 6;                  // weights |r|^(power-2)
    double regularization = 0.1;       // Tikhonov weight on the step, relative to the mean curvature
    double radius_tolerance = 0.002;   // internal units: radius <= distance to surface + this (or + the connected excess)
    uint64_t seed = 1;
    int32_t threads = 0;               // 0 = all cores
    // Off by default. On: the fit above and a second fit (second_fit_options), both from the
    // connected skeleton; of the two, the one of lower two-sided Hausdorff distance as evaluate()
    // measures it at its default options is kept (the first on a tie). 4-6x the fit's CPU time.
    bool thorough = false;
    // Off by default. On: the covered fit (fit_covered, called by the connection step): this fit
    // (thorough or not), then the cover it breaks repaired with added balls and a refit that keeps it.
    bool keep_cover = false;
};

struct FitStats {
    double error_before = 0, error_after = 0;   // max residual (internal units) at the start / kept
    uint32_t iterations = 0, accepted = 0;      // steps computed / steps taken
    size_t uncovered = 0;     // cover samples that no fitted ball covers with its dilated radius
    double time_s = 0;
    // thorough only: the evaluator's two-sided HD (% of the bbox diagonal) of the first and the
    // second fit, and which was kept (0 the first, 1 the second)
    double hd_first = 0, hd_second = 0;
    uint32_t kept = 0;
    // covered fit only (cover.cpp): cover samples the first fit left uncovered, balls added to
    // cover them again, and the balls' count after the repair
    size_t uncovered_first = 0;
    uint32_t added = 0;
};

// What a fit must keep (cover.cpp's refit): balls it may not move, and the cover. With keep_cover
// every trial is pulled back towards the iterate it starts from (each ball that covered a sample
// the trial loses has its share of the move halved, up to 8 times, then 0) until every cover
// sample that the starting balls cover is within the dilated radius of some ball again, so every
// iterate, and the returned balls, keep that cover.
struct FitHold {
    std::vector<uint8_t> fixed;   // per ball of the skeleton, non-zero = held where it is (empty: none)
    bool keep_cover = false;
};

// The second fit of the thorough one: these options with twice the boundary samples of E (the
// bulges between the regular samples are those the evaluator's denser draw finds).
FitOptions second_fit_options(const FitOptions& opt);

// One fit (fit.cpp), the thorough option ignored; `hold` (may be null) what it must keep.
Status fit_once(const CandidateSet& set, const Selection& sel, const FitOptions& opt, const Monitor& monitor,
                Skeleton& sk, FitStats& stats, const FitHold* hold = nullptr);

// Cover samples that none of these balls covers within its dilated radius under sel's dilation
// (offset delta or scale), as indices into set.cover_samples.
std::vector<uint32_t> uncovered_samples(const CandidateSet& set, const Selection& sel, const std::vector<Ball>& balls);

// Fits sk's balls (internal units; sk as made by connect_balls from set and sel) in place: one fit,
// or with opt.thorough the better of two (choose.cpp).
// Needs a triangle mesh: for point clouds and caller arrays it leaves sk unchanged.
Status fit_skeleton(const CandidateSet& set, const Selection& sel, const FitOptions& opt,
                    const Monitor& monitor, Skeleton& sk, FitStats& stats);

// The covered fit (cover.cpp): fit_skeleton with opt, then the cover samples it uncovered (of
// those the selected balls covered) are covered again by candidate balls in their original place,
// the grown selection is connected again (copt; `report`, may be null, gets that connection's),
// and a second fit (one, opt.thorough ignored) moves the fitted balls further with the added ones
// held and the cover kept. sk's balls are then sel's, in order, followed by the added ones; every
// cover sample the selected balls covered is covered by them within the dilated radius.
Status fit_covered(const CandidateSet& set, const Selection& sel, const FitOptions& opt, const ConnectOptions& copt,
                   const Monitor& monitor, Skeleton& sk, FitStats& stats, ConnectReport* report);

}  // namespace ca

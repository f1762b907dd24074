// bone_colliders.cpp: the bone-collider step (bones.h, docs/bone_colliders.md), in order:
//  - the skin checked and each vertex's weights normalised (skin.cpp);
//  - the surface cut into the parts each joint dominates (surface_parts.cpp); a joint gets a
//    collider when its part holds at least min_share of the surface's area and it is not skipped;
//  - the medial balls of each part (part_balls.cpp) and the fit of each collider on samples of
//    its part (fit_bone.cpp), one part per task; conservative: then rounds of refitting each
//    against its parent's and children's colliders, to keep their overlap small (fit_apart);
//    colliders smaller than min_size are dropped;
//  - each collider taken to the caller's units and then to its joint's frame by the joint's
//    inverse bind (a rotation with a uniform scale: anything else is refused, since a capsule
//    under shear is no capsule);
//  - the stats (bone_stats.cpp).
#include "bones.h"

#include "parallel.h"
#include "timing.h"

#include <cmath>

namespace ca {

namespace {
// Conservative: rounds of refitting against the neighbours, and how much a unit of overlap volume
// costs against a unit of the collider's own volume (overlap is what makes ragdolls jitter; the
// volume beyond the part is mostly outside the shape or in a neighbour's part).
constexpr int kApartRounds = 2;
constexpr double kOverlapWeight = 3.0;
}  // namespace

Status make_bone_colliders(const Mesh& mesh, const ShapeQueries& shape, const Normalization& norm,
                           const std::vector<Ball>& balls, size_t inner, const Skin& skin,
                           const BoneColliderOptions& opt, const Monitor& monitor, BoneColliderResult& out) {
    const auto t0 = Clock::now();
    out = BoneColliderResult{};
    if (mesh.triangles.empty())
        return fail(Code::invalid_argument, "bone colliders need a triangle mesh surface (not a point cloud or caller arrays)");
    if (opt.mode != ProxyMode::inscribed && opt.mode != ProxyMode::conservative)
        return fail(Code::invalid_argument, "bone collider mode must be inscribed (0) or conservative (1)");
    if (opt.shapes != ProxyShapes::spheres && opt.shapes != ProxyShapes::capsules)
        return fail(Code::invalid_argument, "bone collider shapes must be spheres (0) or capsules (1)");
    if (!(std::isfinite(opt.min_share) && opt.min_share >= 0 && opt.min_share <= 1))
        return fail(Code::invalid_argument, "bone collider min_share must be a fraction from 0 to 1");
    if (!(std::isfinite(opt.min_size) && opt.min_size >= 0))
        return fail(Code::invalid_argument, "bone collider min_size must be finite and >= 0 (percent of the diagonal)");
    if (opt.surface_samples == 0 || opt.evaluate_samples == 0)
        return fail(Code::invalid_argument, "bone collider surface_samples and evaluate_samples must be at least 1");
    PreparedSkin ps;
    Status st = prepare_skin(skin, mesh.vertices.size(), opt, ps);
    if (!st.ok()) return st;
    const int threads = resolve_threads(opt.threads);
    if (!monitor.report("bone colliders", 0.0)) return monitor.stop_status("bone colliders");

    // ---- the parts and which joints get a collider ----
    const std::vector<SurfacePart> parts = surface_parts(mesh, ps);
    double total_area = 0;
    for (const SurfacePart& p : parts) total_area += p.area;
    const size_t nj = ps.parents.size();
    std::vector<uint8_t> skip(nj, 0);
    for (uint32_t j : opt.skip_joints) skip[j] = 1;
    std::vector<uint32_t> fitted;
    size_t driving = 0;
    for (size_t j = 0; j < nj; ++j) {
        if (!(parts[j].area > 0)) continue;
        ++driving;
        if (!skip[j] && parts[j].area >= opt.min_share * total_area) fitted.push_back(uint32_t(j));
    }
    if (!monitor.report("bone colliders", 0.1)) return monitor.stop_status("bone colliders");

    // ---- medial balls and the fit, one part per task ----
    const std::vector<std::vector<Ball>> medial = part_balls(mesh, shape, balls, inner, ps, threads, monitor);
    if (monitor.stopped()) return monitor.stop_status("bone colliders");
    std::vector<Proxy> fits(fitted.size());
    std::vector<std::vector<Vec3>> part_points(fitted.size());
    if (!parallel_for(fitted.size(), threads, 1, monitor, "bone colliders", 0.2, 0.45, [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i) {
                const uint32_t j = fitted[i];
                part_points[i] = sample_part(parts[j], opt.surface_samples, opt.seed + 0x9E3779B97F4A7C15ull * (j + 1));
                fits[i] = fit_bone(parts[j], medial[j], part_points[i], shape, opt);
            }
        }))
        return monitor.stop_status("bone colliders");
    // ---- conservative: neighbours apart. Each collider refitted against its parent's and
    // children's colliders of the previous round (all at once, so the result does not depend on
    // the order or the threads): the least volume plus the overlap, still holding its part ----
    if (opt.mode == ProxyMode::conservative) {
        std::vector<int32_t> fit_of(nj, -1);
        for (size_t i = 0; i < fitted.size(); ++i) fit_of[fitted[i]] = int32_t(i);
        const auto ancestor_fit = [&](uint32_t j) {
            int32_t k = ps.parents[j];
            while (k >= 0 && fit_of[size_t(k)] < 0) k = ps.parents[size_t(k)];
            return k >= 0 ? fit_of[size_t(k)] : -1;
        };
        std::vector<std::vector<uint32_t>> neighbours(fitted.size());
        for (size_t i = 0; i < fitted.size(); ++i) {
            const int32_t p = ancestor_fit(fitted[i]);
            if (p < 0) continue;
            neighbours[i].push_back(uint32_t(p));
            neighbours[size_t(p)].push_back(uint32_t(i));
        }
        for (int round = 0; round < kApartRounds; ++round) {
            const std::vector<Proxy> previous = fits;
            if (!parallel_for(fitted.size(), threads, 1, monitor, "bone colliders", 0.45 + 0.1 * round, 0.55 + 0.1 * round,
                              [&](size_t b, size_t e) {
                                  for (size_t i = b; i < e; ++i) {
                                      if (neighbours[i].empty()) continue;
                                      std::vector<Proxy> near;
                                      for (uint32_t n : neighbours[i]) near.push_back(previous[n]);
                                      fits[i] = fit_apart(parts[fitted[i]], part_points[i], previous[i], near, kOverlapWeight, shape,
                                                          opt.seed ^ (0xA54FF53A5F1D36F1ull * (fitted[i] + 1)));
                                  }
                              }))
                return monitor.stop_status("bone colliders");
        }
    }

    // ---- sizes, the joints' frames ----
    Vec3 lo = mesh.vertices.front(), hi = lo;
    for (const Vec3& v : mesh.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    const double diagonal = (hi - lo).norm();
    const bool grow = opt.mode == ProxyMode::conservative;
    std::vector<int32_t> collider_of(nj, -1);
    for (size_t i = 0; i < fitted.size(); ++i) {
        const Proxy& p = fits[i];
        if (!(std::max(p.a.radius, p.b.radius) >= 0.01 * opt.min_size * diagonal) || !(p.a.radius + p.b.radius > 0)) continue;
        const uint32_t j = fitted[i];
        Proxy user = p;
        for (Ball* b : {&user.a, &user.b}) {
            b->center = norm.to_user(b->center);
            b->radius *= norm.scale;
        }
        BoneCollider c;
        c.joint = j;
        c.surface_shape = p;
        if (!map_proxy(ps.inverse_bind[j], user, grow, c.shape))
            return fail(Code::invalid_input, "inverse bind matrix of joint " + std::to_string(j) +
                                                 " is not a rotation with a uniform scale (shear or non-uniform "
                                                 "scale): a collider cannot be placed exactly in its frame");
        collider_of[j] = int32_t(out.colliders.size());
        out.colliders.push_back(c);
    }
    // the parent collider: that of the nearest ancestor joint that has one
    for (BoneCollider& c : out.colliders) {
        int32_t k = ps.parents[c.joint];
        while (k >= 0 && collider_of[size_t(k)] < 0) k = ps.parents[size_t(k)];
        c.parent = k >= 0 ? collider_of[size_t(k)] : -1;
    }

    // ---- the stats ----
    st = bone_stats(mesh, shape, ps, out.colliders, opt, monitor, out.stats);
    if (!st.ok()) return st;
    out.stats.joints_with_collider = out.colliders.size();
    out.stats.joints_skipped = driving - out.colliders.size();
    const double cube = norm.scale * norm.scale * norm.scale;
    out.stats.union_volume *= cube;
    out.stats.outside_volume *= cube;
    out.stats.neighbour_overlap *= cube;
    for (BoneCollider& c : out.colliders) c.overlap *= cube;
    out.stats.time_s = seconds_since(t0);
    monitor.note(0, "bone colliders: " + std::to_string(out.colliders.size()) + " of " + std::to_string(driving) +
                        " driving joints; seconds " + std::to_string(out.stats.time_s));
    monitor.report("bone colliders", 1.0);
    return Status::success();
}

}  // namespace ca

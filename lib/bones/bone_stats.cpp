// bone_stats.cpp: what the bone colliders achieve (bones.h): each part's fresh surface samples
// (seeded, area-uniform over the whole surface, each given to the joint that dominates it)
// held by that joint's collider; the Monte Carlo volume of the colliders' union and of its part
// outside the shape (proxy_stats.cpp's union_volumes); and the overlap of each collider with its
// parent's, Monte Carlo over the intersection of their bounding boxes.
#include "bones.h"

#include "parallel.h"
#include "rng.h"
#include "sampling.h"

namespace ca {

namespace {
// Monte Carlo points for the union's volumes and for each parent/child overlap.
constexpr size_t kVolumeSamples = 200000;
constexpr size_t kOverlapSamples = 50000;
}  // namespace

double overlap_volume(const Proxy& a, const Proxy& b, size_t samples, uint64_t seed) {
    const auto ba = proxy_box(a), bb = proxy_box(b);
    const Vec3 lo = ba.first.cwiseMax(bb.first), hi = ba.second.cwiseMin(bb.second);
    if ((hi.array() <= lo.array()).any() || samples == 0) return 0;
    Rng rng(seed);
    size_t in = 0;
    for (size_t i = 0; i < samples; ++i) {
        Vec3 x;
        for (int k = 0; k < 3; ++k) x[k] = lo[k] + (hi[k] - lo[k]) * rng.uniform();
        in += proxy_distance(a, x) <= 0 && proxy_distance(b, x) <= 0;
    }
    const Vec3 e = hi - lo;
    return e.x() * e.y() * e.z() * double(in) / double(samples);
}

Status bone_stats(const Mesh& mesh, const ShapeQueries& shape, const PreparedSkin& skin,
                  std::vector<BoneCollider>& colliders, const BoneColliderOptions& opt, const Monitor& monitor,
                  BoneColliderStats& out) {
    const int threads = resolve_threads(opt.threads);
    std::vector<int32_t> collider_of(skin.parents.size(), -1);
    for (size_t c = 0; c < colliders.size(); ++c) collider_of[colliders[c].joint] = int32_t(c);
    // ---- containment of fresh samples ----
    std::vector<Vec3> samples;
    std::vector<uint32_t> tri;
    if (!sample_surface(mesh, opt.evaluate_samples, opt.seed ^ 0x6A09E667F3BCC909ull, samples, monitor, &tri))
        return monitor.stop_status("bone colliders");
    std::vector<int32_t> owner(samples.size(), -1);
    std::vector<uint8_t> held(samples.size(), 0);
    if (!parallel_for(samples.size(), threads, 4096, monitor, "bone colliders", 0.7, 0.8, [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i) {
                const Tri& t = mesh.triangles[tri[i]];
                const Vec3 bary = barycentric(samples[i], mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
                const int32_t j = dominant_joint(mesh, skin, tri[i], bary);
                if (j < 0 || collider_of[size_t(j)] < 0) continue;
                owner[i] = collider_of[size_t(j)];
                held[i] = proxy_distance(colliders[size_t(owner[i])].surface_shape, samples[i]) <= 0;
            }
        }))
        return monitor.stop_status("bone colliders");
    std::vector<size_t> total(colliders.size(), 0), in(colliders.size(), 0);
    for (size_t i = 0; i < samples.size(); ++i)
        if (owner[i] >= 0) ++total[size_t(owner[i])], in[size_t(owner[i])] += held[i];
    size_t all = 0, all_in = 0;
    for (size_t c = 0; c < colliders.size(); ++c) {
        colliders[c].contained = total[c] ? double(in[c]) / double(total[c]) : 1.0;
        all += total[c];
        all_in += in[c];
    }
    out.contained_fraction = all ? double(all_in) / double(all) : 1.0;
    // ---- volumes ----
    std::vector<Proxy> shapes;
    for (const BoneCollider& c : colliders) shapes.push_back(c.surface_shape);
    if (!union_volumes(shapes, shape, kVolumeSamples, opt.seed ^ 0x3C6EF372FE94F82Bull, threads, monitor,
                       "bone colliders", out.union_volume, out.outside_volume))
        return monitor.stop_status("bone colliders");
    // ---- overlap with the parent's collider ----
    if (!parallel_for(colliders.size(), threads, 1, monitor, "bone colliders", 0.9, 1.0, [&](size_t b, size_t e) {
            for (size_t c = b; c < e; ++c) {
                const int32_t p = colliders[c].parent;
                colliders[c].overlap = p < 0 ? 0.0
                                             : overlap_volume(colliders[c].surface_shape, colliders[size_t(p)].surface_shape,
                                                              kOverlapSamples, opt.seed ^ (0xBB67AE8584CAA73Bull + c));
            }
        }))
        return monitor.stop_status("bone colliders");
    out.neighbour_overlap = 0;
    for (const BoneCollider& c : colliders) out.neighbour_overlap += c.overlap;
    return Status::success();
}

}  // namespace ca

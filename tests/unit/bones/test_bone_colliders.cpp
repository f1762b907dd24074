// test_bone_colliders.cpp: bone colliders (lib/bones) on synthetic skinned characters
// (support/rigged_shapes.h: a bent arm, a Y body). Checked independently of the library: the
// parts by this file's own interpolation of the corner weights on its own surface samples, the
// colliders by a brute-force distance to a tapered capsule, the inside by the brute-force winding
// number. One collider per joint that drives the surface; conservative colliders hold 100 000
// fresh samples of each part (in the joint's frame); inscribed ones stay inside; a posed joint
// carries its collider (skinned points stay inside the collider placed by the posed matrix);
// skip lists, min_share and min_size are honoured; 1 and 4 threads and repeated seeds agree; and
// against the engine-style baseline (a capsule along each bone, from the bounds of the vertices it
// dominates), both as fitted and grown until it holds its part, the colliders leave less volume
// outside the shape, and they overlap their parents less than the grown baseline.
#include <doctest/doctest.h>

#include "steps.h"
#include "support/brute_distance.h"
#include "support/rigged_shapes.h"
#include "winding.h"

#include <map>
#include <random>
#include <set>

namespace {

using rigged::RiggedShape;

ca::CandidateSet candidates(const ca::Mesh& mesh) {
    ca::CandidateSet set;
    ca::CandidateOptions co;
    co.cover_samples = 600;
    co.voronoi_samples = 3000;
    ca::SurfaceInput surface;
    surface.mesh = mesh;
    REQUIRE(ca::candidates_step(surface, co, ca::Monitor{}, set).ok());
    return set;
}

ca::BoneColliderResult colliders(const ca::CandidateSet& set, const RiggedShape& s, const ca::BoneColliderOptions& opt) {
    ca::BoneColliderResult r;
    const ca::Status st = ca::bone_colliders_step(set, s.skin(), opt, ca::Monitor{}, r);
    REQUIRE_MESSAGE(st.ok(), st.message);
    return r;
}

// A primitive moved by an affine map with a uniform scale (the column length).
ca::Proxy moved(const Eigen::Matrix4d& m, const ca::Proxy& p) {
    ca::Proxy q = p;
    const double scale = m.topLeftCorner<3, 3>().col(0).norm();
    for (ca::Ball* b : {&q.a, &q.b}) b->center = rigged::apply(m, b->center), b->radius *= scale;
    return q;
}

// Area-uniform samples of the surface (this file's generator), each with the joint whose
// interpolated weight is the heaviest there (the lowest index among equal ones; -1: none).
struct Sample {
    ca::Vec3 x;
    int32_t joint;
};
std::vector<Sample> samples(const RiggedShape& s, size_t n, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<double> cumulative;
    double total = 0;
    const ca::Mesh& m = s.mesh;
    for (const ca::Tri& t : m.triangles) {
        total += 0.5 * (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]).norm();
        cumulative.push_back(total);
    }
    std::vector<Sample> out;
    for (size_t i = 0; i < n; ++i) {
        const size_t k = std::min(size_t(std::lower_bound(cumulative.begin(), cumulative.end(), u(rng) * total) - cumulative.begin()),
                                  m.triangles.size() - 1);
        const ca::Tri& t = m.triangles[k];
        double a = u(rng), b = u(rng);
        if (a + b > 1) a = 1 - a, b = 1 - b;
        const double l[3] = {1 - a - b, a, b};
        int32_t best = -1;
        double best_w = 0;
        for (uint32_t j = 0; j < s.parents.size(); ++j) {
            double w = 0;
            for (int c = 0; c < 3; ++c) w += l[c] * s.weight(t[size_t(c)], j);
            if (w > best_w) best_w = w, best = int32_t(j);
        }
        out.push_back({m.vertices[t[0]] + a * (m.vertices[t[1]] - m.vertices[t[0]]) + b * (m.vertices[t[2]] - m.vertices[t[0]]), best});
    }
    return out;
}

// At least `per_part` samples of every joint in `joints` (drawn in rounds, this file's generator).
std::map<int32_t, std::vector<ca::Vec3>> part_samples(const RiggedShape& s, const std::set<int32_t>& joints, size_t per_part) {
    std::map<int32_t, std::vector<ca::Vec3>> out;
    for (uint64_t round = 0; round < 40; ++round) {
        for (const Sample& x : samples(s, 100000, 1000 + round))
            if (joints.count(x.joint) && out[x.joint].size() < per_part) out[x.joint].push_back(x.x);
        bool done = true;
        for (int32_t j : joints) done = done && out[j].size() >= per_part;
        if (done) break;
    }
    return out;
}

double diagonal(const ca::Mesh& m) {
    ca::Vec3 lo = m.vertices[0], hi = lo;
    for (const ca::Vec3& v : m.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    return (hi - lo).norm();
}

// The engine-style baseline (as Unreal's physics-asset tool fits a bone): a capsule along the
// bone's axis (its segment; a bone of no length: its joint's x axis), its length and radius from
// the bounds of the vertices the bone dominates (heaviest weight) along and around that axis.
ca::Proxy engine_capsule(const RiggedShape& s, uint32_t j) {
    ca::Vec3 origin = s.bones[j].first, dir = s.bones[j].second - s.bones[j].first;
    if (dir.norm() < 1e-12) dir = s.joint_world[j].topLeftCorner<3, 3>().col(0);
    dir.normalize();
    double lo = 1e300, hi = -1e300, r = 0;
    for (uint32_t v = 0; v < s.mesh.vertices.size(); ++v) {
        uint32_t best = 0;
        for (uint32_t k = 1; k < s.parents.size(); ++k)
            if (s.weight(v, k) > s.weight(v, best)) best = k;
        if (best != j) continue;
        const ca::Vec3 d = s.mesh.vertices[v] - origin;
        const double t = d.dot(dir);
        lo = std::min(lo, t), hi = std::max(hi, t), r = std::max(r, (d - t * dir).norm());
    }
    const double inset = std::min(r, 0.5 * (hi - lo));
    return ca::Proxy{ca::ProxyKind::capsule, ca::Ball{origin + (lo + inset) * dir, r}, ca::Ball{origin + (hi - inset) * dir, r}};
}

// Monte Carlo (this file's points, the library's winding number) of the volume of the union of
// `shapes` outside the mesh, and of each pair's overlap.
// The volume of the points x of the box around `shapes`' balls for which held(x), by `count`
// uniform points of a generator seeded with `seed`.
template <class Held>
double box_volume(const std::vector<ca::Proxy>& shapes, size_t count, uint64_t seed, Held held) {
    ca::Vec3 lo = ca::Vec3::Constant(1e300), hi = -lo;
    for (const ca::Proxy& p : shapes)
        for (const ca::Ball& b : {p.a, p.b})
            lo = lo.cwiseMin(b.center - ca::Vec3::Constant(b.radius)), hi = hi.cwiseMax(b.center + ca::Vec3::Constant(b.radius));
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    size_t n = 0;
    for (size_t i = 0; i < count; ++i) {
        ca::Vec3 x;
        for (int k = 0; k < 3; ++k) x[k] = lo[k] + (hi[k] - lo[k]) * u(rng);
        n += held(x);
    }
    const ca::Vec3 e = hi - lo;
    return e.x() * e.y() * e.z() * double(n) / double(count);
}
double outside_volume(const std::vector<ca::Proxy>& shapes, const ca::WindingNumber& inside, const ca::Normalization& n,
                      size_t count) {
    return box_volume(shapes, count, 7, [&](const ca::Vec3& x) {
        bool in = false;
        for (const ca::Proxy& p : shapes) in = in || brute_distance(p, x) <= 0;
        return in && !inside.inside(n.to_internal(x));
    });
}
double overlap(const ca::Proxy& a, const ca::Proxy& b, size_t count) {
    return box_volume({a}, count, 11, [&](const ca::Vec3& x) { return brute_distance(a, x) <= 0 && brute_distance(b, x) <= 0; });
}

}  // namespace

TEST_CASE("bone colliders: one per driving joint, and conservative ones hold 100000 fresh samples of each part") {
    for (const RiggedShape& s : {rigged::bent_arm(), rigged::y_body()}) {
        const ca::CandidateSet set = candidates(s.mesh);
        const ca::BoneColliderResult r = colliders(set, s, ca::BoneColliderOptions{});
        // the joints that drive the surface, by this file's own samples
        std::set<int32_t> driving;
        for (const Sample& x : samples(s, 20000, 5))
            if (x.joint >= 0) driving.insert(x.joint);
        std::set<int32_t> got;
        for (const ca::BoneCollider& c : r.colliders) got.insert(int32_t(c.joint));
        CHECK(got == driving);
        CHECK(r.stats.contained_fraction == 1.0);
        const auto parts = part_samples(s, driving, 100000);
        for (const ca::BoneCollider& c : r.colliders) {
            const Eigen::Matrix4d to_joint = s.joint_world[c.joint].inverse();   // this file's own inverse bind
            size_t outside = 0;
            double worst = -1e300;
            REQUIRE(parts.at(int32_t(c.joint)).size() == 100000);
            for (const ca::Vec3& x : parts.at(int32_t(c.joint))) {
                const double d = brute_distance(c.shape, rigged::apply(to_joint, x));
                worst = std::max(worst, d);
                outside += d > 0;
            }
            INFO("joint " << c.joint << ": largest distance outside " << worst);
            CHECK(outside == 0);
        }
    }
}

TEST_CASE("bone colliders: spheres only, conservative ones hold their parts and inscribed ones stay inside") {
    const RiggedShape s = rigged::y_body();
    const ca::CandidateSet set = candidates(s.mesh);
    ca::BoneColliderOptions opt;
    opt.shapes = ca::ProxyShapes::spheres;
    const ca::BoneColliderResult r = colliders(set, s, opt);
    REQUIRE(r.colliders.size() == 4);
    const auto parts = part_samples(s, {0, 1, 2, 3}, 20000);
    for (const ca::BoneCollider& c : r.colliders) {
        CHECK(c.shape.kind == ca::ProxyKind::sphere);
        CHECK(c.shape.a.center == c.shape.b.center);
        size_t outside = 0;
        for (const ca::Vec3& x : parts.at(int32_t(c.joint)))
            outside += brute_distance(c.shape, rigged::apply(s.joint_world[c.joint].inverse(), x)) > 0;
        CHECK(outside == 0);
    }
    opt.mode = ca::ProxyMode::inscribed;
    opt.min_size = 0;
    std::mt19937_64 rng(5);
    std::normal_distribution<double> g(0, 1);
    for (const ca::BoneCollider& c : colliders(set, s, opt).colliders) {
        const ca::Proxy world = moved(s.joint_world[c.joint], c.shape);
        CHECK(world.kind == ca::ProxyKind::sphere);
        size_t outside = 0;
        for (int i = 0; i < 100; ++i) {   // points of the sphere's boundary
            ca::Vec3 d(g(rng), g(rng), g(rng));
            outside += ca::winding_number_brute_force(s.mesh, world.a.center + world.a.radius * d.normalized()) <= 0.5;
        }
        CHECK(outside == 0);
    }
}

TEST_CASE("bone colliders: a posed joint carries its collider (skinned points stay inside the placed collider)") {
    const RiggedShape s = rigged::bent_arm();
    const ca::CandidateSet set = candidates(s.mesh);
    const ca::BoneColliderResult r = colliders(set, s, ca::BoneColliderOptions{});
    const auto parts = part_samples(s, {0, 1, 2}, 2000);
    for (const ca::BoneCollider& c : r.colliders) {
        const Eigen::Matrix4d& bind = s.joint_world[c.joint];
        const Eigen::Matrix4d posed = bind * rigged::affine(rigged::turn(70, {0.3, -1, 0.5}), ca::Vec3(0.1, 0.2, -0.3));
        // the collider as an engine places it: a node at the placement, under the posed joint
        const ca::ProxyPlacement pl = ca::proxy_placement(c.shape);
        Eigen::Matrix4d node = Eigen::Matrix4d::Identity();
        node.topLeftCorner<3, 3>() = pl.rotation.toRotationMatrix();
        node.block<3, 1>(0, 3) = pl.translation;
        const Eigen::Matrix4d world_to_node = (posed * node).inverse();
        ca::Proxy local{ca::ProxyKind::capsule, ca::Ball{ca::Vec3(0, -pl.height / 2, 0), pl.radius_bottom},
                        ca::Ball{ca::Vec3(0, pl.height / 2, 0), pl.radius_top}};
        // points of the part and the collider's own centre, skinned by this joint alone
        std::vector<ca::Vec3> points = parts.at(int32_t(c.joint));
        points.push_back(rigged::apply(bind, 0.5 * (c.shape.a.center + c.shape.b.center)));
        size_t outside = 0;
        for (const ca::Vec3& x : points) {
            const ca::Vec3 skinned = rigged::apply(posed * bind.inverse(), x);
            outside += brute_distance(local, rigged::apply(world_to_node, skinned)) > 1e-9;
        }
        CHECK(outside == 0);
        // and a point just outside the collider stays outside it (the check can fail)
        const ca::Vec3 beyond = c.shape.b.center + (c.shape.b.radius * 1.01 + 1e-3) * ca::Vec3::UnitX();
        if (brute_distance(c.shape, beyond) > 1e-6)
            CHECK(brute_distance(local, rigged::apply(world_to_node, rigged::apply(posed, beyond))) > 0);
    }
}

TEST_CASE("bone colliders: inscribed ones stay inside the shape") {
    for (const RiggedShape& s : {rigged::bent_arm(), rigged::y_body()}) {
        const ca::CandidateSet set = candidates(s.mesh);
        ca::BoneColliderOptions opt;
        opt.mode = ca::ProxyMode::inscribed;
        opt.min_size = 0;
        const ca::BoneColliderResult r = colliders(set, s, opt);
        CHECK(r.colliders.size() >= s.parents.size() - 1);
        std::mt19937_64 rng(3);
        std::uniform_real_distribution<double> u(0, 1);
        for (const ca::BoneCollider& c : r.colliders) {
            const ca::Proxy world = moved(s.joint_world[c.joint], c.shape);
            ca::Vec3 lo = world.a.center.cwiseMin(world.b.center) - ca::Vec3::Constant(std::max(world.a.radius, world.b.radius));
            ca::Vec3 hi = world.a.center.cwiseMax(world.b.center) + ca::Vec3::Constant(std::max(world.a.radius, world.b.radius));
            size_t tried = 0, outside = 0, in = 0;
            while (in < 150 && tried < 100000) {
                ++tried;
                ca::Vec3 x;
                for (int k = 0; k < 3; ++k) x[k] = lo[k] + (hi[k] - lo[k]) * u(rng);
                if (brute_distance(world, x) > 0) continue;
                ++in;
                outside += ca::winding_number_brute_force(s.mesh, x) <= 0.5;
            }
            CHECK(in == 150);
            CHECK(outside == 0);
        }
    }
}

TEST_CASE("bone colliders: skip list, min_share and min_size are honoured") {
    const RiggedShape s = rigged::y_body();
    const ca::CandidateSet set = candidates(s.mesh);
    const ca::BoneColliderResult all = colliders(set, s, ca::BoneColliderOptions{});
    REQUIRE(all.colliders.size() == 4);
    CHECK(all.stats.joints_skipped == 0);
    ca::BoneColliderOptions opt;
    opt.skip_joints = {2};
    const ca::BoneColliderResult skipped = colliders(set, s, opt);
    CHECK(skipped.colliders.size() == 3);
    CHECK(skipped.stats.joints_skipped == 1);
    for (const ca::BoneCollider& c : skipped.colliders) CHECK(c.joint != 2);
    // the parts' shares of the area, by this file's samples; a threshold between two of them
    std::map<int32_t, double> share;
    const auto xs = samples(s, 200000, 9);
    for (const Sample& x : xs) share[x.joint] += 1.0 / double(xs.size());
    std::vector<double> sorted;
    for (auto& [j, f] : share) sorted.push_back(f);
    std::sort(sorted.begin(), sorted.end());
    opt = ca::BoneColliderOptions{};
    opt.min_share = 0.5 * (sorted[1] + sorted[2]);
    REQUIRE(sorted[2] - sorted[1] > 0.02);   // far apart for the Monte Carlo shares
    const ca::BoneColliderResult big = colliders(set, s, opt);
    std::set<uint32_t> want, got;
    for (auto& [j, f] : share)
        if (f >= opt.min_share) want.insert(uint32_t(j));
    for (const ca::BoneCollider& c : big.colliders) got.insert(c.joint);
    CHECK(got == want);
    // min_size: between the smallest and the largest collider's larger radius (percent of the
    // diagonal, the surface's frame)
    std::vector<double> size;
    for (const ca::BoneCollider& c : all.colliders)
        size.push_back(100 * std::max(c.surface_shape.a.radius, c.surface_shape.b.radius) * set.surface.norm.scale / diagonal(s.mesh));
    std::vector<double> by_size = size;
    std::sort(by_size.begin(), by_size.end());
    opt = ca::BoneColliderOptions{};
    opt.min_size = 0.5 * (by_size[0] + by_size[1]);
    const ca::BoneColliderResult sized = colliders(set, s, opt);
    got.clear();
    want.clear();
    for (size_t i = 0; i < all.colliders.size(); ++i)
        if (size[i] >= opt.min_size) want.insert(all.colliders[i].joint);
    for (const ca::BoneCollider& c : sized.colliders) got.insert(c.joint);
    CHECK(got == want);
    CHECK(got.size() == 3);
}

TEST_CASE("bone colliders: the same on 1 and 4 threads and for a repeated seed") {
    const RiggedShape s = rigged::y_body();
    const ca::CandidateSet set = candidates(s.mesh);
    ca::BoneColliderOptions opt;
    opt.threads = 1;
    const ca::BoneColliderResult one = colliders(set, s, opt);
    opt.threads = 4;
    const ca::BoneColliderResult four = colliders(set, s, opt);
    const ca::BoneColliderResult again = colliders(set, s, opt);
    REQUIRE(one.colliders.size() == four.colliders.size());
    REQUIRE(again.colliders.size() == four.colliders.size());
    for (size_t i = 0; i < one.colliders.size(); ++i)
        for (const ca::BoneColliderResult* r : {&four, &again}) {
            const ca::Proxy &p = one.colliders[i].shape, &q = r->colliders[i].shape;
            CHECK(p.a.center == q.a.center);
            CHECK(p.b.center == q.b.center);
            CHECK(p.a.radius == q.a.radius);
            CHECK(p.b.radius == q.b.radius);
            CHECK(one.colliders[i].overlap == r->colliders[i].overlap);
        }
    CHECK(one.stats.outside_volume == four.stats.outside_volume);
}
TEST_CASE("bone colliders: less outside volume and parent overlap than the engine-style baseline held to 100 percent") {
    for (const RiggedShape& s : {rigged::bent_arm(), rigged::y_body()}) {
        const ca::CandidateSet set = candidates(s.mesh);
        const ca::BoneColliderResult r = colliders(set, s, ca::BoneColliderOptions{});
        std::set<int32_t> joints;
        for (const ca::BoneCollider& c : r.colliders) joints.insert(int32_t(c.joint));
        const auto parts = part_samples(s, joints, 100000);
        // ours in the surface's frame; the baseline as fitted, and grown until it holds its part's
        // fresh samples (the engine's idea made conservative)
        std::vector<ca::Proxy> ours, engine, grown;
        std::map<uint32_t, size_t> index;
        size_t held = 0, total = 0;
        for (const ca::BoneCollider& c : r.colliders) {
            index[c.joint] = ours.size();
            ours.push_back(moved(s.joint_world[c.joint], c.shape));
            engine.push_back(engine_capsule(s, c.joint));
            double need = -1e300;
            for (const ca::Vec3& x : parts.at(int32_t(c.joint))) {
                const double d = brute_distance(engine.back(), x);
                need = std::max(need, d);
                held += d <= 0, ++total;
            }
            grown.push_back(engine.back());
            grown.back().a.radius += std::max(need, 0.0);
            grown.back().b.radius += std::max(need, 0.0);
        }
        const ca::WindingNumber& inside = *set.queries.winding;
        const double out_ours = outside_volume(ours, inside, set.surface.norm, 200000);
        const double out_engine = outside_volume(engine, inside, set.surface.norm, 200000);
        const double out_grown = outside_volume(grown, inside, set.surface.norm, 200000);
        double lap_ours = 0, lap_engine = 0, lap_grown = 0;
        for (const ca::BoneCollider& c : r.colliders) {
            int32_t p = s.parents[c.joint];
            while (p >= 0 && !index.count(uint32_t(p))) p = s.parents[size_t(p)];
            if (p < 0) continue;
            const size_t a = index[c.joint], b = index[uint32_t(p)];
            lap_ours += overlap(ours[a], ours[b], 100000);
            lap_engine += overlap(engine[a], engine[b], 100000);
            lap_grown += overlap(grown[a], grown[b], 100000);
        }
        MESSAGE("joints " << s.parents.size() << ": outside volume ours " << out_ours << ", engine " << out_engine
                          << " (holds " << double(held) / double(total) << " of its parts' samples), engine held "
                          << out_grown << "; parent overlap ours " << lap_ours << ", engine " << lap_engine
                          << ", engine held " << lap_grown << "; library stats: outside " << r.stats.outside_volume
                          << " overlap " << r.stats.neighbour_overlap << "; seconds " << r.stats.time_s);
        CHECK(out_ours < out_engine);
        CHECK(out_ours < out_grown);
        CHECK(lap_ours < lap_grown);
    }
}

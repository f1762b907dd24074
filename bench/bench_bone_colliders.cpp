// bench_bone_colliders.cpp: a collider per bone (ca_bone_colliders_build, conservative, at the
// library's defaults; docs/bone_colliders.md) against the colliders engines generate
// (bone_baseline.h: per bone a capsule along the bone's axis sized by the bounding box of the
// vertices it dominates, as Unreal's physics-asset tool does by default).
// Characters: the rigged test characters (tests/data/rigged: glb and fbx) and every skinned
// .glb/.gltf/.fbx in <data>/rigged when present. One measure for both methods, in the mesh's bind
// pose (each collider placed by its joint's inverse bind matrix):
//  - held: the share of 100 000 fresh area-uniform surface samples (drawn here, not the library's)
//    inside the collider of their part (the joint with the heaviest interpolated weight there),
//    over the samples of parts that have a collider; "all": over every sample (a part without a
//    collider holds none of its samples);
//  - outside: the volume of the colliders' union outside the body (Monte Carlo in the union's box,
//    the library's winding-number inside test), % of the body's volume;
//  - overlap: the volume shared by each collider and its parent's (the nearest ancestor joint
//    with one), summed (Monte Carlo in the child's box), % of the body's volume;
//  - time: ours, the candidate balls (ca_candidates at the defaults) and the fit; the engine's, its
//    fit. Reading the file is not counted for either.
// usage: bench_bone_colliders [DATA_ROOT] [--only NAME[,NAME...]]
#include "bench_common.h"
#include "bone_baseline.h"
#include "proxies.h"
#include "skin_view.h"
#include "support/fresh_samples.h"
#include "support/mesh_convert.h"
#include "winding.h"

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace {

constexpr size_t kFreshSamples = 100000;
constexpr size_t kVolumePoints = 400000;
constexpr size_t kOverlapPoints = 40000;

struct Result {
    bool ok = false;
    std::string note;
    size_t count = 0;
    double held = 0, held_all = 0, outside_pct = 0, overlap_pct = 0, seconds = 0;
    // ours only: the library's own stats
    double lib_contained = 0, lib_outside_pct = 0, lib_overlap_pct = 0;
};

// One collider in the mesh frame: its joint's inverse bind (to test points in the joint frame),
// the shape there, and a box holding it in the mesh frame.
struct Placed {
    uint32_t joint;
    ca::Proxy shape;
    ca::Vec3 lo, hi;
};

std::vector<Placed> place(const std::vector<bench::BoneShape>& shapes, const caio::SkinData& skin) {
    std::vector<Placed> out;
    for (const bench::BoneShape& s : shapes) {
        const Eigen::Map<const Eigen::Matrix4d> ibm(&skin.inverse_bind[16 * s.joint]);
        const Eigen::Matrix4d inv = ibm.inverse();
        const double scale = std::cbrt(std::abs(inv.topLeftCorner<3, 3>().determinant()));
        Placed p{s.joint, s.shape, ca::Vec3::Constant(1e300), ca::Vec3::Constant(-1e300)};
        for (const ca::Ball& b : {s.shape.a, s.shape.b}) {
            const ca::Vec3 c = (inv * b.center.homogeneous()).head<3>();
            p.lo = p.lo.cwiseMin(c - ca::Vec3::Constant(b.radius * scale));
            p.hi = p.hi.cwiseMax(c + ca::Vec3::Constant(b.radius * scale));
        }
        out.push_back(p);
    }
    return out;
}

bool inside(const Placed& p, const caio::SkinData& skin, const ca::Vec3& x) {
    if ((x.array() < p.lo.array()).any() || (x.array() > p.hi.array()).any()) return false;
    return ca::proxy_distance(p.shape, bench::to_joint(skin.inverse_bind.data(), p.joint, x)) <= 0;
}

double box_volume(const ca::Vec3& lo, const ca::Vec3& hi) {
    const ca::Vec3 e = (hi - lo).cwiseMax(ca::Vec3::Zero());
    return e.x() * e.y() * e.z();
}

// The measures of one set of colliders (see the header).
void measure(const std::vector<Placed>& colliders, const caio::SkinData& skin, const std::vector<ca::Vec3>& fresh,
             const std::vector<int32_t>& part, const ca::WindingNumber& winding, double volume, Result& r) {
    std::vector<int32_t> collider_of(skin.joint_names.size(), -1);
    for (size_t i = 0; i < colliders.size(); ++i) collider_of[colliders[i].joint] = int32_t(i);
    size_t held = 0, with = 0;
    for (size_t i = 0; i < fresh.size(); ++i) {
        if (part[i] < 0 || collider_of[size_t(part[i])] < 0) continue;
        ++with;
        held += inside(colliders[size_t(collider_of[size_t(part[i])])], skin, fresh[i]);
    }
    r.count = colliders.size();
    r.held = with ? 100.0 * double(held) / double(with) : 0;
    r.held_all = 100.0 * double(held) / double(fresh.size());
    ca::Vec3 lo = ca::Vec3::Constant(1e300), hi = -lo;
    for (const Placed& p : colliders) lo = lo.cwiseMin(p.lo), hi = hi.cwiseMax(p.hi);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    size_t outside = 0;
    for (size_t i = 0; i < kVolumePoints && !colliders.empty(); ++i) {
        const ca::Vec3 x(lo.x() + (hi.x() - lo.x()) * u(rng), lo.y() + (hi.y() - lo.y()) * u(rng), lo.z() + (hi.z() - lo.z()) * u(rng));
        bool in = false;
        for (const Placed& p : colliders) in = in || inside(p, skin, x);
        if (in && !winding.inside(x)) ++outside;
    }
    r.outside_pct = 100.0 * box_volume(lo, hi) * double(outside) / double(kVolumePoints) / volume;
    double overlap = 0;
    for (const Placed& c : colliders) {
        int32_t a = skin.parents[c.joint];
        while (a >= 0 && collider_of[size_t(a)] < 0) a = skin.parents[size_t(a)];
        if (a < 0) continue;
        const Placed& p = colliders[size_t(collider_of[size_t(a)])];
        const ca::Vec3 blo = c.lo.cwiseMax(p.lo), bhi = c.hi.cwiseMin(p.hi);
        if (box_volume(blo, bhi) <= 0) continue;
        size_t both = 0;
        for (size_t i = 0; i < kOverlapPoints; ++i) {
            const ca::Vec3 x(blo.x() + (bhi.x() - blo.x()) * u(rng), blo.y() + (bhi.y() - blo.y()) * u(rng),
                             blo.z() + (bhi.z() - blo.z()) * u(rng));
            both += inside(c, skin, x) && inside(p, skin, x);
        }
        overlap += box_volume(blo, bhi) * double(both) / double(kOverlapPoints);
    }
    r.overlap_pct = 100.0 * overlap / volume;
}

// Our colliders through the C ABI, as the tool makes them.
std::vector<bench::BoneShape> ours(const caio::MeshData& md, Result& r) {
    std::vector<bench::BoneShape> out;
    const auto t0 = std::chrono::steady_clock::now();
    ca_context* ctx = nullptr;
    ca_context_desc desc;
    ca_context_desc_init(&desc);
    if (ca_context_create(&desc, &ctx) != CA_OK) return r.note = "no context", out;
    const ca_surface_view surface = caio::surface_view(md);
    ca_candidate_options co;
    ca_candidate_options_init(&co);
    ca_candidate_set* set = nullptr;
    ca_status st = ca_candidates(ctx, &surface, &co, &set);
    const ca_skin_view view = caio::skin_view(md);
    ca_bone_collider_options bo;
    ca_bone_collider_options_defaults(&bo, sizeof bo);
    bo.mode = CA_PROXY_CONSERVATIVE;
    ca_bone_colliders* bones = nullptr;
    if (st == CA_OK) st = ca_bone_colliders_build(ctx, set, nullptr, &view, &bo, &bones);
    r.seconds = bench::seconds_since(t0);
    if (st != CA_OK) {
        r.note = std::string(ca_status_string(st)) + ": " + ca_context_last_error(ctx);
    } else {
        for (size_t i = 0; i < ca_bone_colliders_count(bones); ++i) {
            ca_proxy_placement pl;
            pl.struct_size = sizeof pl;
            ca_bone_colliders_placement(bones, i, &pl);
            const ca::Vec3 c(pl.center[0], pl.center[1], pl.center[2]), axis(pl.axis[0], pl.axis[1], pl.axis[2]);
            bench::BoneShape b;
            b.joint = ca_bone_colliders_joints(bones)[i];
            b.shape.kind = pl.kind == CA_PROXY_CAPSULE ? ca::ProxyKind::capsule : ca::ProxyKind::sphere;
            b.shape.a = {pl.kind == CA_PROXY_CAPSULE ? ca::Vec3(c - 0.5 * pl.height * axis) : c, pl.radius_bottom};
            b.shape.b = {pl.kind == CA_PROXY_CAPSULE ? ca::Vec3(c + 0.5 * pl.height * axis) : c, pl.radius_top};
            if (pl.kind != CA_PROXY_CAPSULE) b.shape.a.radius = b.shape.b.radius = pl.radius_top;
            out.push_back(b);
        }
        ca_bone_collider_stats bs;
        bs.struct_size = sizeof bs;
        ca_bone_colliders_stats(bones, &bs);
        r.lib_contained = 100 * bs.contained_fraction;
        r.lib_outside_pct = bs.outside_volume;   // absolute; turned into % by the caller
        r.lib_overlap_pct = bs.neighbour_overlap;
        r.ok = true;
    }
    ca_bone_colliders_destroy(bones);
    ca_candidate_set_destroy(set);
    ca_context_destroy(ctx);
    return out;
}

std::string cells(const Result& r) {
    if (!r.ok) return "  failed: " + r.note;
    char b[160];
    std::snprintf(b, sizeof b, "%4zu %8.3f %8.3f %9.2f %9.2f %8.3f", r.count, r.held, r.held_all, r.outside_pct, r.overlap_pct,
                  r.seconds);
    return b;
}

}  // namespace

int main(int argc, char** argv) {
    std::string root, only;
    bench::root_and_only(argc, argv, root, only);
    std::vector<std::string> files;
    for (const std::string& dir : {std::string(CA_TEST_DATA) + "/rigged", root + "/rigged"})
        for (const char* ext : {".glb", ".gltf", ".fbx"})
            for (const std::string& f : bench::list_files(dir, ext)) files.push_back(f);
    std::printf("Bone colliders: ours (conservative, library defaults) against the engine-style capsules (per bone, along\n"
                "its axis, sized by the box of the vertices it dominates). held: %% of %zu fresh surface samples inside\n"
                "their part's collider, over parts with a collider; all: over every sample. outside and overlap (parent/child\n"
                "pairs): %% of the body's volume (Monte Carlo). time: s (ours: candidates + fit; reading excluded).\n\n",
                kFreshSamples);
    std::printf("%-16s %6s | %-4s %8s %8s %9s %9s %8s | %-4s %8s %8s %9s %9s %8s\n", "character", "joints", "ours", "held%",
                "all%", "outside%", "overlap%", "time", "eng.", "held%", "all%", "outside%", "overlap%", "time");
    size_t n = 0, less_outside = 0, less_overlap = 0, all_held = 0;
    std::string library_lines;
    for (const std::string& path : files) {
        const std::string name = bench::stem(path) + path.substr(path.find_last_of('.'));
        if (!bench::selected(only, name)) continue;
        caio::MeshData md;
        std::string err;
        if (!caio::read_mesh(path, md, err) || md.skin.empty() || md.triangles.empty()) {
            std::printf("%-16s skipped: %s\n", name.c_str(), err.empty() ? "no skin" : err.c_str());
            continue;
        }
        const ca::Mesh mesh = to_core_mesh(md);
        const double volume = std::abs(ca::signed_volume(mesh));
        const ca::WindingNumber winding(mesh);
        std::vector<FreshSampleSite> where;
        const std::vector<ca::Vec3> fresh = fresh_surface_samples(mesh, kFreshSamples, 2024, &where);
        // each sample's part: the heaviest of the corners' weights interpolated
        const caio::SkinData& s = md.skin;
        std::vector<int32_t> part(fresh.size(), -1);
        std::vector<double> w(s.joint_names.size());
        for (size_t i = 0; i < fresh.size(); ++i) {
            std::fill(w.begin(), w.end(), 0.0);
            for (int c = 0; c < 3; ++c) {
                const size_t v = mesh.triangles[where[i].triangle][size_t(c)];
                for (size_t k = 0; k < s.influences; ++k)
                    w[s.vertex_joints[v * s.influences + k]] += where[i].corner[c] * s.vertex_weights[v * s.influences + k];
            }
            double best = 0;
            for (size_t j = 0; j < w.size(); ++j)
                if (w[j] > best) best = w[j], part[i] = int32_t(j);
        }
        Result a, b;
        const std::vector<bench::BoneShape> mine = ours(md, a);
        if (a.ok) {
            measure(place(mine, s), s, fresh, part, winding, volume, a);
            a.lib_outside_pct = 100 * a.lib_outside_pct / volume;
            a.lib_overlap_pct = 100 * a.lib_overlap_pct / volume;
        }
        const auto t0 = std::chrono::steady_clock::now();
        const std::vector<bench::BoneShape> engine = bench::engine_capsules(
            md.positions, s.joint_names.size(), s.influences, s.vertex_joints.data(), s.vertex_weights.data(), s.inverse_bind.data());
        b.seconds = bench::seconds_since(t0);
        b.ok = true;
        measure(place(engine, s), s, fresh, part, winding, volume, b);
        std::printf("%-16s %6zu | %s | %s\n", name.c_str(), s.joint_names.size(), cells(a).c_str(), cells(b).c_str());
        char line[200];
        std::snprintf(line, sizeof line, "  %-16s held %.3f %%, outside %.2f %%, overlap %.2f %% of the body's volume\n", name.c_str(),
                      a.lib_contained, a.lib_outside_pct, a.lib_overlap_pct);
        library_lines += line;
        ++n;
        less_outside += a.ok && a.outside_pct < b.outside_pct;
        less_overlap += a.ok && a.overlap_pct < b.overlap_pct;
        all_held += a.ok && a.held >= 100.0;
    }
    std::printf("\nOurs against the engine-style capsules on %zu characters: less volume outside the body on %zu, less neighbour\n"
                "overlap on %zu; every sample of a part with a collider held on %zu.\n",
                n, less_outside, less_overlap, all_held);
    std::printf("\nThe library's own stats of ours (ca_bone_colliders_stats: its fresh samples and Monte Carlo):\n%s",
                library_lines.c_str());
    return 0;
}

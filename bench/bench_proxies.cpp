// bench_proxies.cpp: engine proxies (ca_proxies, docs/proxies.md) on every mesh of
// <data>/meshes/paper, against the proxies a user would write by hand: K-means spheres on surface
// samples with each radius grown to hold its cluster. Per model, for K = 8, 16, 32 and both modes
// (tapered capsules and spheres): the primitives made, the two-sided Hausdorff distance (% of the
// bbox diagonal, as ca_evaluate measures a skeleton whose balls and edges are the primitives), the
// volume of the union outside the shape (Monte Carlo with the library's winding-number inside
// test, % of the model's volume) and, conservative, the share of 100 000 fresh surface samples
// (drawn here, not the library's) that the union contains. The baseline gets the same measures.
// Summary per mode and K: on how many models the proxies have the lower error than the baseline,
// the smaller outside volume (conservative), and contain every fresh sample.
// usage: bench_proxies [DATA_ROOT] [--only NAME[,NAME...]]   (default ../shared/data; skipped when missing)
#include "bench_common.h"
#include "evaluate.h"
#include "proxies.h"
#include "support/fresh_samples.h"
#include "support/mesh_convert.h"
#include "winding.h"

#include <cmath>
#include <random>
#include <vector>

namespace {

const uint32_t kCounts[] = {8, 16, 32};
constexpr size_t kFreshSamples = 100000;
constexpr size_t kVolumePoints = 20000;
constexpr size_t kClusterSamples = 20000;

struct Measure {
    ca_status status = CA_OK;
    size_t count = 0;
    double hd = 0, outside_pct = 0, contained = 0, seconds = 0;
};

// K-means (k-means++ start, 20 Lloyd steps, fixed seed) spheres on the points, each radius the
// farthest of its cluster from its centroid.
std::vector<ca::Proxy> kmeans_spheres(const std::vector<ca::Vec3>& pts, size_t k, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<ca::Vec3> centers{pts[size_t(u(rng) * double(pts.size())) % pts.size()]};
    std::vector<double> d2(pts.size(), 1e300);
    while (centers.size() < k) {
        double sum = 0;
        for (size_t i = 0; i < pts.size(); ++i) {
            d2[i] = std::min(d2[i], (pts[i] - centers.back()).squaredNorm());
            sum += d2[i];
        }
        double pick = u(rng) * sum;
        size_t i = 0;
        while (i + 1 < pts.size() && (pick -= d2[i]) > 0) ++i;
        centers.push_back(pts[i]);
    }
    std::vector<size_t> label(pts.size(), 0);
    for (int step = 0; step < 20; ++step) {
        for (size_t i = 0; i < pts.size(); ++i) {
            double best = 1e300;
            for (size_t c = 0; c < k; ++c) {
                const double d = (pts[i] - centers[c]).squaredNorm();
                if (d < best) { best = d; label[i] = c; }
            }
        }
        std::vector<ca::Vec3> sum(k, ca::Vec3::Zero());
        std::vector<size_t> n(k, 0);
        for (size_t i = 0; i < pts.size(); ++i) { sum[label[i]] += pts[i]; ++n[label[i]]; }
        for (size_t c = 0; c < k; ++c)
            if (n[c]) centers[c] = sum[c] / double(n[c]);
    }
    std::vector<double> radius(k, 0);
    for (size_t i = 0; i < pts.size(); ++i) radius[label[i]] = std::max(radius[label[i]], (pts[i] - centers[label[i]]).norm());
    std::vector<ca::Proxy> out;
    for (size_t c = 0; c < k; ++c)
        if (radius[c] > 0) out.push_back({ca::ProxyKind::sphere, {centers[c], radius[c]}, {centers[c], radius[c]}});
    return out;
}

double union_distance(const std::vector<ca::Proxy>& ps, const ca::Vec3& x) {
    double best = 1e300;
    for (const ca::Proxy& p : ps) best = std::min(best, ca::proxy_distance(p, x));
    return best;
}

// The two-sided HD through ca_evaluate, the outside volume (% of the model's) and the share of
// `fresh` inside the union.
void measure(ca_context* ctx, const ca_surface_view& v, const ca::WindingNumber& winding, double volume,
             const std::vector<ca::Vec3>& fresh, const std::vector<ca::Proxy>& ps, Measure& m) {
    m.count = ps.size();
    std::vector<double> centers, radii;
    std::vector<uint32_t> edges;
    for (const ca::Proxy& p : ps) {
        centers.insert(centers.end(), {p.a.center.x(), p.a.center.y(), p.a.center.z()});
        radii.push_back(p.a.radius);
        if (p.kind == ca::ProxyKind::capsule) {
            centers.insert(centers.end(), {p.b.center.x(), p.b.center.y(), p.b.center.z()});
            radii.push_back(p.b.radius);
            edges.insert(edges.end(), {uint32_t(radii.size() - 2), uint32_t(radii.size() - 1)});
        }
    }
    ca_skeleton_view view;
    ca_skeleton_view_init(&view);
    view.centers = centers.data();
    view.radii = radii.data();
    view.vertex_count = radii.size();
    view.edges = edges.empty() ? nullptr : edges.data();
    view.edge_count = edges.size() / 2;
    ca_evaluate_options eo;
    ca_evaluate_options_init(&eo);
    eo.surface_samples = 10000;
    eo.envelope_samples = 10000;
    ca_evaluation ev;
    ev.struct_size = sizeof ev;
    m.status = ca_evaluate(ctx, &v, &view, &eo, &ev);
    m.hd = ev.hd_two_sided;
    ca::Vec3 lo = ca::Vec3::Constant(1e300), hi = -lo;
    for (const ca::Proxy& p : ps)
        for (const ca::Ball& b : {p.a, p.b}) {
            lo = lo.cwiseMin(b.center - ca::Vec3::Constant(b.radius));
            hi = hi.cwiseMax(b.center + ca::Vec3::Constant(b.radius));
        }
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> u(0, 1);
    size_t outside = 0;
    for (size_t i = 0; i < kVolumePoints; ++i) {
        const ca::Vec3 x(lo.x() + (hi.x() - lo.x()) * u(rng), lo.y() + (hi.y() - lo.y()) * u(rng), lo.z() + (hi.z() - lo.z()) * u(rng));
        if (union_distance(ps, x) <= 0 && !winding.inside(x)) ++outside;
    }
    const ca::Vec3 e = hi - lo;
    m.outside_pct = 100 * e.x() * e.y() * e.z() * double(outside) / double(kVolumePoints) / volume;
    size_t in = 0;
    for (const ca::Vec3& x : fresh) in += union_distance(ps, x) <= 0;
    m.contained = 100 * double(in) / double(fresh.size());
}

}  // namespace

int main(int argc, char** argv) {
    std::string root, only;
    bench::root_and_only(argc, argv, root, only);
    const auto models = bench::list_files(root + "/meshes/paper", ".obj");
    if (models.empty()) {
        std::printf("bench_proxies: no models under %s/meshes/paper, skipped\n", root.c_str());
        return 0;
    }
    std::printf("\n## Engine proxies against K-means spheres\n\n");
    std::printf("Skeleton at the defaults; proxies: capsules (tapered capsules and spheres), K = 8, 16, 32, both modes. "
                "Baseline: K-means spheres on %zu surface samples, radii grown to hold their clusters. HD: two-sided, %% of the "
                "bbox diagonal (ca_evaluate with 10000 + 10000 samples). out: volume of the union outside the shape, %% of the "
                "model's volume (%zu Monte Carlo points, winding-number inside test). in: %% of %zu fresh surface samples "
                "inside the union. n: primitives made. s: wall time of ca_proxies.\n\n",
                kClusterSamples, kVolumePoints, kFreshSamples);
    std::printf("| model | K | inscribed n | HD %% | out %% | s | conservative n | HD %% | out %% | in %% | s | K-means HD %% | out %% | in %% |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    const size_t nk = sizeof kCounts / sizeof kCounts[0];
    std::vector<int> ins_lower(nk, 0), con_lower(nk, 0), con_smaller_out(nk, 0), con_all_in(nk, 0), base_all_in(nk, 0), ins_out_zero(nk, 0);
    int measured = 0;
    const auto t_all = std::chrono::steady_clock::now();
    for (const std::string& path : models) {
        const std::string name = bench::stem(path);
        if (!bench::selected(only, name)) continue;
        caio::MeshData mesh;
        std::string err;
        if (!caio::read_mesh(path, mesh, err)) {
            std::printf("| %s | read failed: %s |\n", name.c_str(), err.c_str());
            continue;
        }
        const ca::Mesh core = to_core_mesh(mesh);
        const ca::WindingNumber winding(core);
        const double volume = std::abs(ca::signed_volume(core));
        const std::vector<ca::Vec3> fresh = fresh_surface_samples(core, kFreshSamples, 2024);
        const std::vector<ca::Vec3> cluster_pts = fresh_surface_samples(core, kClusterSamples, 7);
        ca_context* ctx = nullptr;
        ca_context_create(nullptr, &ctx);
        const ca_surface_view v = bench::surface_view(mesh);
        const bench::DefaultOptions d;
        ca_candidate_set* set = nullptr;
        ca_selection* sel = nullptr;
        ca_skeleton* sk = nullptr;
        ca_status st = ca_candidates(ctx, &v, &d.candidates, &set);
        if (st == CA_OK) st = ca_select(ctx, set, &d.select, &sel);
        if (st == CA_OK) st = ca_connect(ctx, set, sel, &d.connect, &sk);
        if (st != CA_OK) {
            std::printf("| %s | pipeline failed: %s |\n", name.c_str(), ca_context_last_error(ctx));
            ca_skeleton_destroy(sk);
            ca_selection_destroy(sel);
            ca_candidate_set_destroy(set);
            ca_context_destroy(ctx);
            continue;
        }
        ++measured;
        ca_skeleton_view skv;
        ca_skeleton_view_init(&skv);
        ca_skeleton_get_view(sk, &skv);
        for (size_t ki = 0; ki < nk; ++ki) {
            Measure m[2], base;
            for (int mode = 0; mode < 2; ++mode) {
                ca_proxy_options po;
                ca_proxy_options_init(&po);
                po.count = kCounts[ki];
                po.mode = mode == 0 ? CA_PROXY_INSCRIBED : CA_PROXY_CONSERVATIVE;
                po.evaluate_samples = 1;   // the bench measures both sides alike below
                po.volume_samples = 1;
                ca_proxy_set* px = nullptr;
                const auto t0 = std::chrono::steady_clock::now();
                m[mode].status = ca_proxies(ctx, set, &skv, &po, &px);
                m[mode].seconds = bench::seconds_since(t0);
                if (m[mode].status != CA_OK) continue;
                std::vector<ca::Proxy> ps(ca_proxy_set_count(px));
                const int32_t* kinds = ca_proxy_set_kinds(px);
                const double *c = ca_proxy_set_centers(px), *r = ca_proxy_set_radii(px);
                for (size_t i = 0; i < ps.size(); ++i) {
                    ps[i].kind = kinds[i] == CA_PROXY_CAPSULE ? ca::ProxyKind::capsule : ca::ProxyKind::sphere;
                    ps[i].a = {ca::Vec3(c[6 * i], c[6 * i + 1], c[6 * i + 2]), r[2 * i]};
                    ps[i].b = {ca::Vec3(c[6 * i + 3], c[6 * i + 4], c[6 * i + 5]), r[2 * i + 1]};
                }
                ca_proxy_set_destroy(px);
                measure(ctx, v, winding, volume, fresh, ps, m[mode]);
            }
            measure(ctx, v, winding, volume, fresh, kmeans_spheres(cluster_pts, kCounts[ki], 5), base);
            std::printf("| %s | %u |", name.c_str(), kCounts[ki]);
            if (m[0].status != CA_OK) std::printf(" failed (%d) | | | |", m[0].status);
            else std::printf(" %zu | %.2f | %.2f | %.1f |", m[0].count, m[0].hd, m[0].outside_pct, m[0].seconds);
            if (m[1].status != CA_OK) std::printf(" failed (%d) | | | | |", m[1].status);
            else std::printf(" %zu | %.2f | %.2f | %.3f | %.1f |", m[1].count, m[1].hd, m[1].outside_pct, m[1].contained, m[1].seconds);
            std::printf(" %.2f | %.2f | %.3f |\n", base.hd, base.outside_pct, base.contained);
            std::fflush(stdout);
            ins_lower[ki] += m[0].status == CA_OK && m[0].hd < base.hd;
            ins_out_zero[ki] += m[0].status == CA_OK && m[0].outside_pct < base.outside_pct;
            con_lower[ki] += m[1].status == CA_OK && m[1].hd < base.hd;
            con_smaller_out[ki] += m[1].status == CA_OK && m[1].outside_pct < base.outside_pct;
            con_all_in[ki] += m[1].status == CA_OK && m[1].contained == 100;
            base_all_in[ki] += base.contained == 100;
        }
        ca_skeleton_destroy(sk);
        ca_selection_destroy(sel);
        ca_candidate_set_destroy(set);
        ca_context_destroy(ctx);
    }
    std::printf("\n");
    for (size_t ki = 0; ki < nk; ++ki) {
        std::printf("K = %u: inscribed proxies have the lower HD than K-means spheres on %d of %d models (the smaller outside "
                    "volume on %d); conservative proxies the lower HD on %d, the smaller outside volume on %d, and hold all "
                    "%zu fresh samples on %d of %d (K-means spheres: %d).\n",
                    kCounts[ki], ins_lower[ki], measured, ins_out_zero[ki], con_lower[ki], con_smaller_out[ki], kFreshSamples,
                    con_all_in[ki], measured, base_all_in[ki]);
    }
    std::printf("Total wall time: %.0f s.\n", bench::seconds_since(t_all));
    return 0;
}

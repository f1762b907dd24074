// bench_proxies.cpp: engine proxies (ca_proxies, docs/proxies.md) against the proxies a user would
// write by hand and against V-HACD 4.1, the convex decomposition engines ship.
// 1. On every mesh of <data>/meshes/paper, against K-means spheres on surface samples with each
//    radius grown to hold its cluster. Per model, for K = 8, 16, 32 and both modes (tapered
//    capsules and spheres): the primitives made, the two-sided Hausdorff distance (% of the bbox
//    diagonal, as ca_evaluate measures a skeleton whose balls and edges are the primitives), the
//    volume of the union outside the shape (Monte Carlo with the library's winding-number inside
//    test, % of the model's volume) and, conservative, the share of 100 000 fresh surface samples
//    (drawn here, not the library's) that the union contains. Summary per mode and K: on how many
//    models the proxies have the lower error, the smaller outside volume, and hold every sample.
// 2. Conservative proxies (capsules, and `all`: spheres, capsules and boxes)
//    at K = 16, 32, 64 against V-HACD's hulls at 16 and 64 (bench/vhacd/vhacd_driver, built by
//    bench/vhacd/setup.sh; without it the table says so and the rest runs), on the paper models
//    and, at K = 16, the game files of <data>/real. One measure for both (bench_proxies_peer.h):
//    fresh surface samples inside, volume outside and missed, stick-out, bytes, wall time (ours:
//    reading the file, the skeleton and the proxies at the defaults, as the tool runs them;
//    V-HACD: its Compute call). Open meshes: surface inside and time only.
// usage: bench_proxies [DATA_ROOT] [--only NAME[,NAME...]]   (default ../shared/data; skipped when missing)
#include "bench_common.h"
#include "bench_proxies_peer.h"
#include "evaluate.h"
#include "mesh_topology.h"
#include "proxies.h"
#include "support/fresh_samples.h"
#include "support/mesh_convert.h"
#include "winding.h"

#include <cmath>
#include <limits.h>
#include <random>
#include <sys/stat.h>
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


// The K-means table's rows of one model (its skeleton made) and its tallies.
struct KmeansTally {
    size_t nk = sizeof kCounts / sizeof kCounts[0];
    std::vector<int> ins_lower = std::vector<int>(nk), con_lower = std::vector<int>(nk), con_smaller_out = std::vector<int>(nk),
                     con_all_in = std::vector<int>(nk), base_all_in = std::vector<int>(nk), ins_out_zero = std::vector<int>(nk);
    int measured = 0;
};

std::string kmeans_rows(const std::string& name, ca_context* ctx, const ca_candidate_set* set, const ca_skeleton_view& skv,
                        const ca_surface_view& v, const ca::Mesh& core, const ca::WindingNumber& winding, double volume,
                        const std::vector<ca::Vec3>& fresh, KmeansTally& tally);

// ---- the peer: V-HACD ----

const uint32_t kPeerCounts[] = {16, 32, 64};   // ours at each; V-HACD at those in kVhacdCounts
const uint32_t kVhacdCounts[] = {16, 64};
constexpr size_t kPeerVolumePoints = 400000;
constexpr size_t kBoundarySamples = 40000;
constexpr double kVhacdLimitS = 300;
constexpr size_t kRealEvery = 5;   // a subset of the game files keeps the run under an hour on 2 cores

// Fields of ca_proxy_stats printed beside each run of ours, from the stats and the model's
// volume: one line per field the library reports (a solver's lower bound of the outside volume,
// once ca_proxy_stats has one, is one more line).
struct StatColumn {
    const char* header;
    double (*value)(const ca_proxy_stats& s, double model_volume);
};
const StatColumn kStatColumns[] = {
    {"lib out %", [](const ca_proxy_stats& s, double vol) { return 100 * s.outside_volume / vol; }},
};

// The shapes our proxies are run with: capsules (and spheres), and all shapes (boxes too).
struct OurShapes {
    const char* name;
    int32_t shapes;
};
const OurShapes kOurShapes[] = {
    {"capsules", CA_PROXY_SHAPES_CAPSULES},
    {"all", CA_PROXY_SHAPES_ALL},
};
constexpr size_t kShapeCount = sizeof kOurShapes / sizeof kOurShapes[0];

// The primitives of a proxy set as the core's; false when one has a kind this bench cannot place.
bool read_proxies(const ca_proxy_set* px, std::vector<ca::Proxy>& ps) {
    ps.assign(ca_proxy_set_count(px), ca::Proxy{});
    const int32_t* kinds = ca_proxy_set_kinds(px);
    const double *c = ca_proxy_set_centers(px), *r = ca_proxy_set_radii(px);
    for (size_t i = 0; i < ps.size(); ++i) {
        if (kinds[i] == CA_PROXY_BOX) {
            // a box as an engine places it: the node's rotation turns the box's x y z axes
            ca_proxy_placement pl;
            pl.struct_size = sizeof pl;
            if (ca_proxy_set_placement(px, i, &pl) != CA_OK) return false;
            const Eigen::Quaterniond q(pl.rotation[3], pl.rotation[0], pl.rotation[1], pl.rotation[2]);
            ps[i] = ca::make_box(ca::Vec3(pl.center[0], pl.center[1], pl.center[2]), q.toRotationMatrix(),
                                 ca::Vec3(pl.half_extents[0], pl.half_extents[1], pl.half_extents[2]));
            continue;
        }
        if (kinds[i] != CA_PROXY_SPHERE && kinds[i] != CA_PROXY_CAPSULE) return false;
        ps[i].kind = kinds[i] == CA_PROXY_CAPSULE ? ca::ProxyKind::capsule : ca::ProxyKind::sphere;
        ps[i].a = {ca::Vec3(c[6 * i], c[6 * i + 1], c[6 * i + 2]), r[2 * i]};
        ps[i].b = {ca::Vec3(c[6 * i + 3], c[6 * i + 4], c[6 * i + 5]), r[2 * i + 1]};
    }
    return true;
}

// One method's result at one count.
struct PeerResult {
    bool ran = false;
    std::string note;          // why it did not run
    size_t count = 0;          // primitives or hulls
    double seconds = NAN;
    bench::UnionMeasure m;
    std::vector<double> stats; // ours: kStatColumns
    bench::ConvexUnion u;
};

// A model's results: ours[shape][count index], V-HACD per kPeerCounts index (not run at 32).
struct PeerRow {
    std::string name;
    bool read = false, closed = false;
    std::vector<std::vector<PeerResult>> ours;
    std::vector<PeerResult> vhacd;
};

// The path of a program beside this one.
std::string beside_self(const std::string& program) {
    char buf[PATH_MAX];
    const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
    if (n <= 0) return program;
    const std::string self(buf, size_t(n));
    return self.substr(0, self.find_last_of('/') + 1) + program;
}

// Whether reading the file survives (some assimp formats crash on a few files): read in a child.
bool read_survives(const std::string& path) {
    const pid_t pid = fork();
    if (pid < 0) return true;
    if (pid == 0) {
        caio::MeshData mesh;
        std::string err;
        caio::read_mesh(path, mesh, err);
        _exit(0);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

std::string fmt(double x, const char* f = "%.2f") {
    if (std::isnan(x)) return "-";
    char b[48];
    std::snprintf(b, sizeof b, f, x);
    return b;
}

// One model through both methods at `counts` (ours) and the V-HACD counts among them; with `kmeans`,
// also the K-means table's rows.
PeerRow peer_model(const std::string& path, const std::vector<uint32_t>& counts, const std::string& driver,
                   const std::string& driver_note, const std::string& dir, std::string* kmeans, KmeansTally* tally) {
    PeerRow row;
    row.name = bench::stem(path);
    row.ours.assign(kShapeCount, std::vector<PeerResult>(counts.size()));
    row.vhacd.assign(counts.size(), PeerResult{});
    auto fail_all = [&](const std::string& why) {
        for (auto& s : row.ours)
            for (PeerResult& r : s) r.note = why;
        for (PeerResult& r : row.vhacd) r.note = why;
        return row;
    };
    if (!read_survives(path)) return fail_all("reading crashed");
    const auto t_read0 = std::chrono::steady_clock::now();
    caio::MeshData mesh;
    std::string err;
    if (!caio::read_mesh(path, mesh, err)) return fail_all("read failed: " + err);
    const double t_read = bench::seconds_since(t_read0);
    bench::PeerModel pm;
    pm.mesh = to_core_mesh(mesh);
    if (pm.mesh.triangles.empty()) return fail_all("no triangles");
    row.read = true;
    pm.closed = ca::mesh_topology(pm.mesh).closed;
    row.closed = pm.closed;
    pm.lo = ca::Vec3::Constant(1e300);
    pm.hi = -pm.lo;
    for (const ca::Vec3& x : pm.mesh.vertices) {
        pm.lo = pm.lo.cwiseMin(x);
        pm.hi = pm.hi.cwiseMax(x);
    }
    pm.diagonal = (pm.hi - pm.lo).norm();
    pm.volume = std::abs(ca::signed_volume(pm.mesh));
    pm.winding = std::make_shared<ca::WindingNumber>(pm.mesh);
    pm.distance = std::make_shared<ca::MeshDistance>(pm.mesh);
    pm.fresh = fresh_surface_samples(pm.mesh, kFreshSamples, 2024);
    if (!(pm.volume > 0)) pm.closed = row.closed = false;

    // ours: the skeleton at the defaults, then the proxies at the defaults but mode and count
    ca_context* ctx = nullptr;
    ca_context_create(nullptr, &ctx);
    const ca_surface_view v = bench::surface_view(mesh);
    const bench::DefaultOptions d;
    ca_candidate_set* set = nullptr;
    ca_selection* sel = nullptr;
    ca_skeleton* sk = nullptr;
    const auto t_skel0 = std::chrono::steady_clock::now();
    ca_status st = ca_candidates(ctx, &v, &d.candidates, &set);
    if (st == CA_OK) st = ca_select(ctx, set, &d.select, &sel);
    if (st == CA_OK) st = ca_connect(ctx, set, sel, &d.connect, &sk);
    const double t_skeleton = t_read + bench::seconds_since(t_skel0);
    ca_skeleton_view skv;
    ca_skeleton_view_init(&skv);
    if (st == CA_OK) ca_skeleton_get_view(sk, &skv);
    const std::string skeleton_error = st == CA_OK ? "" : std::string("skeleton: ") + ca_context_last_error(ctx);
    for (size_t s = 0; s < kShapeCount; ++s)
        for (size_t k = 0; k < counts.size(); ++k) {
            PeerResult& r = row.ours[s][k];
            if (st != CA_OK) { r.note = skeleton_error; continue; }
            ca_proxy_options po;
            ca_proxy_options_init(&po);
            po.count = counts[k];
            po.mode = CA_PROXY_CONSERVATIVE;
            po.shapes = kOurShapes[s].shapes;
            ca_proxy_set* px = nullptr;
            const auto t0 = std::chrono::steady_clock::now();
            const ca_status ps = ca_proxies(ctx, set, &skv, &po, &px);
            r.seconds = t_skeleton + bench::seconds_since(t0);
            std::vector<ca::Proxy> prims;
            if (ps != CA_OK) {
                r.note = std::string("proxies: ") + ca_context_last_error(ctx);
            } else if (!read_proxies(px, prims)) {
                r.note = "a primitive of a kind this bench cannot place";
            } else {
                ca_proxy_stats stats;
                stats.struct_size = sizeof stats;
                ca_proxy_set_stats(px, &stats);
                for (const StatColumn& c : kStatColumns) r.stats.push_back(pm.closed ? c.value(stats, pm.volume) : NAN);
                r.ran = true;
                r.count = prims.size();
                r.u = bench::ConvexUnion::of(std::move(prims));
            }
            ca_proxy_set_destroy(px);
        }
    if (kmeans && st == CA_OK)
        *kmeans += kmeans_rows(row.name, ctx, set, skv, v, pm.mesh, *pm.winding, pm.volume, pm.fresh, *tally);
    else if (kmeans)
        *kmeans += "| " + row.name + " | pipeline failed: " + skeleton_error + " |\n";
    ca_skeleton_destroy(sk);
    ca_selection_destroy(sel);
    ca_candidate_set_destroy(set);
    ca_context_destroy(ctx);

    // V-HACD
    for (size_t k = 0; k < counts.size(); ++k) {
        PeerResult& r = row.vhacd[k];
        const uint32_t* end = kVhacdCounts + sizeof kVhacdCounts / sizeof kVhacdCounts[0];
        if (std::find(kVhacdCounts, end, counts[k]) == end) continue;
        if (driver.empty()) { r.note = driver_note; continue; }
        bench::VhacdRun run = bench::run_vhacd(driver, dir, pm.mesh, counts[k], kVhacdLimitS);
        if (!run.ok) { r.note = run.note; continue; }
        r.ran = true;
        r.seconds = run.seconds;
        r.count = run.hulls.size();
        r.u = bench::ConvexUnion::of(std::move(run.hulls));
    }

    // the measures, on one set of volume points holding every union
    std::vector<const bench::ConvexUnion*> unions;
    for (auto& s : row.ours)
        for (PeerResult& r : s)
            if (r.ran) unions.push_back(&r.u);
    for (PeerResult& r : row.vhacd)
        if (r.ran) unions.push_back(&r.u);
    if (pm.closed) bench::volume_points(pm, unions, kPeerVolumePoints, 77);
    for (auto& s : row.ours)
        for (PeerResult& r : s)
            if (r.ran) r.m = bench::measure_union(pm, r.u, kBoundarySamples);
    for (PeerResult& r : row.vhacd)
        if (r.ran) r.m = bench::measure_union(pm, r.u, kBoundarySamples);
    return row;
}

std::string result_cells(const PeerResult& r, bool ours) {
    const size_t extra = ours ? sizeof kStatColumns / sizeof kStatColumns[0] : 0;
    if (!r.ran) {
        std::string s = " " + (r.note.empty() ? std::string("-") : r.note) + " |";
        for (size_t i = 0; i < 6 + extra; ++i) s += " |";
        return s;
    }
    std::string s = " " + std::to_string(r.count) + " | " + fmt(r.m.inside_pct, "%.3f") + " | " + fmt(r.m.outside_pct) + " | " +
                    fmt(r.m.missed_pct) + " | " + fmt(r.m.stick_out_pct) + " | " + std::to_string(r.m.bytes) + " | " +
                    fmt(r.seconds) + " |";
    if (ours)
        for (double x : r.stats) s += " " + fmt(x) + " |";
    return s;
}

void print_peer_header() {
    std::printf("| model | K | ours | n | in %% | out %% | missed %% | stick %% | bytes | s |");
    for (const StatColumn& c : kStatColumns) std::printf(" %s |", c.header);
    std::printf(" V-HACD n | in %% | out %% | missed %% | stick %% | bytes | s | out ours/V-HACD | s ours/V-HACD |\n|");
    for (size_t i = 0; i < 19 + sizeof kStatColumns / sizeof kStatColumns[0]; ++i) std::printf("---|");
    std::printf("\n");
}

void print_peer_rows(const PeerRow& row, const std::vector<uint32_t>& counts) {
    for (size_t s = 0; s < kShapeCount; ++s)
        for (size_t k = 0; k < counts.size(); ++k) {
            const PeerResult &o = row.ours[s][k], &h = row.vhacd[k];
            const bool peer = s == 0 && (h.ran || !h.note.empty());
            std::printf("| %s%s | %u | %s |%s", row.name.c_str(), row.read && !row.closed ? " (open)" : "", counts[k], kOurShapes[s].name,
                        result_cells(o, true).c_str());
            if (peer) {
                std::printf("%s", result_cells(h, false).c_str());
                const bool both = o.ran && h.ran;
                std::printf(" %s | %s |\n", both ? fmt(o.m.outside_pct / h.m.outside_pct).c_str() : "-",
                            both ? fmt(o.seconds / h.seconds).c_str() : "-");
            } else {
                std::printf(" |  |  |  |  |  |  |  |  |\n");
            }
        }
    std::fflush(stdout);
}

// The result of `rows` at count index k (ours with shape s; s < 0: V-HACD) where `keep` holds.
template <class F>
std::vector<double> column(const std::vector<PeerRow>& rows, int s, size_t k, F value) {
    std::vector<double> out;
    for (const PeerRow& r : rows) {
        const PeerResult& x = s < 0 ? r.vhacd[k] : r.ours[size_t(s)][k];
        if (x.ran) out.push_back(value(r, x));
    }
    return out;
}

// The summary of the paper models against V-HACD (counts {16, 32, 64}: index 0 is 16).
void peer_summary(const std::vector<PeerRow>& rows) {
    const size_t n = rows.size();
    size_t vh_all_in = 0, vh_ran = 0;
    for (const PeerRow& r : rows) {
        vh_ran += r.vhacd[0].ran;
        vh_all_in += r.vhacd[0].ran && r.vhacd[0].m.inside_pct == 100;
    }
    for (size_t s = 0; s < kShapeCount; ++s) {
        const char* sh = kOurShapes[s].name;
        for (size_t k = 0; k < 3; ++k) {
            size_t ran = 0, all_in = 0;
            for (const PeerRow& r : rows) {
                ran += r.ours[s][k].ran;
                all_in += r.ours[s][k].ran && r.ours[s][k].m.inside_pct == 100;
            }
            std::printf("Ours (%s) at K = %u hold all %zu fresh samples on %zu of %zu models (made on %zu).\n", sh, kPeerCounts[k],
                        kFreshSamples, all_in, n, ran);
        }
        if (vh_ran == 0) continue;
        // ours at K against V-HACD at `vk` (count index) on the models where both ran
        auto compare = [&](size_t k, size_t vk) {
            std::vector<double> ratio, time_ratio, stick_o, stick_v, out_o, out_v, missed_o, missed_v, bytes_o, bytes_v;
            size_t within2 = 0, at_most = 0, time_fifth = 0;
            for (const PeerRow& r : rows) {
                const PeerResult &o = r.ours[s][k], &h = r.vhacd[vk];
                if (!o.ran || !h.ran || !r.closed) continue;
                const double q = o.m.outside_pct / h.m.outside_pct;
                ratio.push_back(q);
                within2 += q <= 2;
                at_most += o.m.outside_pct <= h.m.outside_pct;
                time_ratio.push_back(o.seconds / h.seconds);
                time_fifth += o.seconds <= h.seconds / 5;
                stick_o.push_back(o.m.stick_out_pct);
                stick_v.push_back(h.m.stick_out_pct);
                out_o.push_back(o.m.outside_pct);
                out_v.push_back(h.m.outside_pct);
                missed_o.push_back(o.m.missed_pct);
                missed_v.push_back(h.m.missed_pct);
                bytes_o.push_back(double(o.m.bytes));
                bytes_v.push_back(double(h.m.bytes));
            }
            std::printf("Ours (%s) at K = %u against V-HACD at %u hulls, %zu models: outside volume <= 2x V-HACD's on %zu, <= V-HACD's "
                        "on %zu; ratio ours/V-HACD median %.2f; outside volume median %.2f %% vs %.2f %% of the model's; missed "
                        "inside volume median %.2f %% vs %.2f %%; stick-out median %.2f %% vs %.2f %% of the diagonal; bytes median "
                        "%.0f vs %.0f; time ratio ours/V-HACD median %.3f (target <= 0.2), <= 1/5 on %zu.\n",
                        sh, kPeerCounts[k], kPeerCounts[vk], ratio.size(), within2, at_most, bench::median(ratio), bench::median(out_o),
                        bench::median(out_v), bench::median(missed_o), bench::median(missed_v), bench::median(stick_o),
                        bench::median(stick_v), bench::median(bytes_o), bench::median(bytes_v), bench::median(time_ratio), time_fifth);
        };
        compare(0, 0);
        compare(1, 0);
        compare(2, 2);
    }
    std::printf("V-HACD at 16 hulls holds all %zu fresh samples on %zu of %zu models (ran on %zu); at 64 hulls on %zu.\n", kFreshSamples,
                vh_all_in, n, vh_ran, size_t(std::count_if(rows.begin(), rows.end(), [](const PeerRow& r) {
                    return r.vhacd[2].ran && r.vhacd[2].m.inside_pct == 100;
                })));
}

}  // namespace

int main(int argc, char** argv) {
    std::string root, only;
    bench::root_and_only(argc, argv, root, only);
    const auto models = bench::paper_models("bench_proxies", root);
    if (models.empty()) return 0;
    std::vector<std::string> real;
    // the game files: every kRealEvery-th of each folder in name order (all of them with --only)
    for (const auto& [folder, ext] : {std::pair<const char*, const char*>{"0ad", ".obj"}, {"flightgear", ".ac"}, {"openarena", ".md3"}}) {
        const std::vector<std::string> files = bench::list_files(root + "/real/" + folder, ext);
        for (size_t i = 0; i < files.size(); ++i)
            if (!only.empty() || i % kRealEvery == 0) real.push_back(files[i]);
    }
    std::string driver = beside_self("vhacd_driver"), driver_note;
    if (access(driver.c_str(), X_OK) != 0) {
        driver_note = "V-HACD not built (bench/vhacd/setup.sh BUILD_DIR; needs npm)";
        driver.clear();
    }
    char dir_template[] = "/tmp/bench_proxies.XXXXXX";
    const char* dir_c = mkdtemp(dir_template);
    if (!dir_c) { std::printf("bench_proxies: no temporary folder\n"); return 1; }
    const std::string dir = dir_c;
    const auto t_all = std::chrono::steady_clock::now();

    std::string kmeans;
    KmeansTally tally;
    std::vector<PeerRow> paper, games;
    const std::vector<uint32_t> paper_counts(std::begin(kPeerCounts), std::end(kPeerCounts)), game_counts = {16};
    for (const std::string& path : models) {
        if (!bench::selected(only, bench::stem(path))) continue;
        std::fprintf(stderr, "bench_proxies: %s\n", bench::stem(path).c_str());
        paper.push_back(peer_model(path, paper_counts, driver, driver_note, dir, &kmeans, &tally));
    }
    for (const std::string& path : real) {
        if (!bench::selected(only, bench::stem(path))) continue;
        std::fprintf(stderr, "bench_proxies: %s\n", bench::stem(path).c_str());
        games.push_back(peer_model(path, game_counts, driver, driver_note, dir, nullptr, nullptr));
    }
    rmdir(dir.c_str());

    std::printf("\n## Engine proxies against K-means spheres\n\n");
    std::printf("Skeleton at the defaults; proxies: capsules (tapered capsules and spheres), K = 8, 16, 32, both modes. "
                "Baseline: K-means spheres on %zu surface samples, radii grown to hold their clusters. HD: two-sided, %% of the "
                "bbox diagonal (ca_evaluate with 10000 + 10000 samples). out: volume of the union outside the shape, %% of the "
                "model's volume (%zu Monte Carlo points, winding-number inside test). in: %% of %zu fresh surface samples "
                "inside the union. n: primitives made. s: wall time of ca_proxies.\n\n",
                kClusterSamples, kVolumePoints, kFreshSamples);
    std::printf("| model | K | inscribed n | HD %% | out %% | s | conservative n | HD %% | out %% | in %% | s | K-means HD %% | out %% | in %% |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n%s\n", kmeans.c_str());
    for (size_t ki = 0; ki < tally.nk; ++ki) {
        std::printf("K = %u: inscribed proxies have the lower HD than K-means spheres on %d of %d models (the smaller outside "
                    "volume on %d); conservative proxies the lower HD on %d, the smaller outside volume on %d, and hold all "
                    "%zu fresh samples on %d of %d (K-means spheres: %d).\n",
                    kCounts[ki], tally.ins_lower[ki], tally.measured, tally.ins_out_zero[ki], tally.con_lower[ki],
                    tally.con_smaller_out[ki], kFreshSamples, tally.con_all_in[ki], tally.measured, tally.base_all_in[ki]);
    }

    std::printf("\n## Conservative proxies against V-HACD 4.1\n\n");
    std::printf("Ours: conservative proxies (%s) at K = 16, 32, 64 at the defaults otherwise; s: reading the file, the skeleton and "
                "the proxies (with their stats, as the tool runs them), in one context on all cores. V-HACD 4.1 (npm vhacd-js, "
                "bench/vhacd/vhacd_driver) at its default parameters but the hull count, 16 and 64; s: its Compute call (the "
                "blocking interface, which runs its work on 8 threads of its own). Both measured alike: in: %% of %zu fresh "
                "surface samples inside the union (hulls: by their planes); out: volume of the union outside the model and "
                "missed: volume of the model outside the union, %% of the model's volume (%zu Monte Carlo points in a box "
                "holding the model and every union, the library's winding-number inside test); stick: the farthest of about "
                "%zu samples on the pieces' boundaries outside the model, %% of the bbox diagonal; bytes: float32 primitives "
                "(sphere 16, capsule 32, box 40) or hull vertices and triangles (12 bytes each).",
                kShapeCount > 1 ? "capsules, then all shapes" : "capsules", kFreshSamples, kPeerVolumePoints, kBoundarySamples);
    for (const StatColumn& c : kStatColumns) std::printf(" %s: from ca_proxy_stats.", c.header);
    if (!driver_note.empty()) std::printf(" %s.", driver_note.c_str());
    std::printf(" Open meshes: in and s only.\n\n### The %zu paper models\n\n", paper.size());
    print_peer_header();
    for (const PeerRow& r : paper) print_peer_rows(r, paper_counts);
    std::printf("\n");
    peer_summary(paper);
    std::printf("\n### Game files of %s/real (0 A.D., FlightGear, OpenArena), K = 16\n\n"
                "%s: %zu files.\n\n", root.c_str(),
                only.empty() ? ("Every " + std::to_string(kRealEvery) + "th file of each folder in name order").c_str() : "Those named by --only",
                games.size());
    print_peer_header();
    for (const PeerRow& r : games) print_peer_rows(r, game_counts);
    size_t ours_ran = 0, ours_in = 0, vh_ran = 0, vh_in = 0;
    std::vector<double> time_ratio;
    for (const PeerRow& r : games) {
        const PeerResult &o = r.ours[0][0], &h = r.vhacd[0];
        ours_ran += o.ran;
        ours_in += o.ran && o.m.inside_pct == 100;
        vh_ran += h.ran;
        vh_in += h.ran && h.m.inside_pct == 100;
        if (o.ran && h.ran) time_ratio.push_back(o.seconds / h.seconds);
    }
    std::printf("\nGame files: %zu; ours (capsules, K = 16) made on %zu, holding all fresh samples on %zu; V-HACD (16 hulls) ran on "
                "%zu, holding all on %zu; time ratio ours/V-HACD median %.3f over %zu.\n",
                games.size(), ours_ran, ours_in, vh_ran, vh_in, bench::median(time_ratio), time_ratio.size());
    std::printf("Total wall time: %.0f s.\n", bench::seconds_since(t_all));
    return 0;
}

namespace {

std::string kmeans_rows(const std::string& name, ca_context* ctx, const ca_candidate_set* set, const ca_skeleton_view& skv,
                        const ca_surface_view& v, const ca::Mesh& core, const ca::WindingNumber& winding, double volume,
                        const std::vector<ca::Vec3>& fresh, KmeansTally& t) {
    const std::vector<ca::Vec3> cluster_pts = fresh_surface_samples(core, kClusterSamples, 7);
    std::string out;
    ++t.measured;
    for (size_t ki = 0; ki < t.nk; ++ki) {
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
            std::vector<ca::Proxy> ps;
            const bool placed = read_proxies(px, ps);
            ca_proxy_set_destroy(px);
            if (!placed) { m[mode].status = CA_ERROR_INVALID_ARGUMENT; continue; }
            measure(ctx, v, winding, volume, fresh, ps, m[mode]);
        }
        measure(ctx, v, winding, volume, fresh, kmeans_spheres(cluster_pts, kCounts[ki], 5), base);
        char line[512];
        int w = std::snprintf(line, sizeof line, "| %s | %u |", name.c_str(), kCounts[ki]);
        if (m[0].status != CA_OK) w += std::snprintf(line + w, sizeof line - size_t(w), " failed (%d) | | | |", m[0].status);
        else w += std::snprintf(line + w, sizeof line - size_t(w), " %zu | %.2f | %.2f | %.1f |", m[0].count, m[0].hd, m[0].outside_pct, m[0].seconds);
        if (m[1].status != CA_OK) w += std::snprintf(line + w, sizeof line - size_t(w), " failed (%d) | | | | |", m[1].status);
        else w += std::snprintf(line + w, sizeof line - size_t(w), " %zu | %.2f | %.2f | %.3f | %.1f |", m[1].count, m[1].hd, m[1].outside_pct, m[1].contained, m[1].seconds);
        std::snprintf(line + w, sizeof line - size_t(w), " %.2f | %.2f | %.3f |\n", base.hd, base.outside_pct, base.contained);
        out += line;
        t.ins_lower[ki] += m[0].status == CA_OK && m[0].hd < base.hd;
        t.ins_out_zero[ki] += m[0].status == CA_OK && m[0].outside_pct < base.outside_pct;
        t.con_lower[ki] += m[1].status == CA_OK && m[1].hd < base.hd;
        t.con_smaller_out[ki] += m[1].status == CA_OK && m[1].outside_pct < base.outside_pct;
        t.con_all_in[ki] += m[1].status == CA_OK && m[1].contained == 100;
        t.base_all_in[ki] += base.contained == 100;
    }
    return out;
}

}  // namespace

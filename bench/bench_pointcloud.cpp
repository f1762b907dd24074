// bench_pointcloud.cpp: point clouds through the public C ABI at the defaults, against the
// targets of docs/pointclouds.md. Rows: every cloud under <data>/pointclouds, and clouds sampled
// area-uniformly (fixed seed) from every mesh under <data>/meshes/paper at 5000 and 30 000 points,
// in four variants: (a) the exact normals of the sampled triangles, (b) PCA normals with random
// signs, (c) no normals, (d) Gaussian noise of 0.5 % of the bbox diagonal per coordinate with the
// exact normals; and, only when --variants names it, (o): (b)'s PCA directions with the signs of
// the exact normals, passed as trusted, a diagnostic that tells what wrong signs cost (b, c) from
// what PCA's directions cost (it counts in no summary line). Each row: whether it succeeded, |V|,
// the samples left uncovered (an uncoverable cloud is run again with skip_uncoverable to count
// them and measure the rest), the Hausdorff distances against the source mesh (ca_evaluate at its defaults) and the pipeline's time
// (candidates + select + connect, not the evaluation). Then the mesh route's distance per shape
// and one summary line per target. The scans under <data>/pointclouds/scans (as stored, and with
// their normals ignored and estimated) are measured against the cloud itself: h(recon -> cloud)
// at most 5 % of the bbox diagonal is their target, and the sampled clouds' (c) rows are measured
// against their own cloud for the same target (one summary line).
// The evaluation uses 10 000 surface and 30 000 envelope samples (the mesh route's too), so that
// the whole table stays within minutes; clouds above 5000 points are sampled only from the
// shapes named by --large (bunny, fish, horse) unless --full.
// usage: bench_pointcloud [DATA_ROOT] [--only NAME[,NAME...]] [--sizes N[,N...]] [--variants abcdo]
//                         [--large NAME[,NAME...] | --full]
//   --only keeps the meshes and clouds whose file stem starts with one of the names.
#include "bench_common.h"
#include "support/clouds.h"
#include "support/mesh_convert.h"
#include "normals.h"
#include "rng.h"

#include <cmath>
#include <ctime>
#include <cstdlib>
#include <cstring>
#include <map>

namespace {

struct Options {
    std::string root = "../shared/data";
    std::vector<std::string> only;
    std::vector<size_t> sizes = {5000, 30000};
    std::string variants = "abcd";
    std::vector<std::string> large = {"bunny", "fish", "horse"};  // empty: every shape
};

std::vector<std::string> split(const std::string& s) {
    std::vector<std::string> out;
    size_t i = 0;
    while (i <= s.size()) {
        size_t j = s.find(',', i);
        if (j == std::string::npos) j = s.size();
        if (j > i) out.push_back(s.substr(i, j - i));
        i = j + 1;
    }
    return out;
}

bool parse(int argc, char** argv, Options& o) {
    bool root_seen = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool has_value = i + 1 < argc;
        if (a == "--only" && has_value) o.only = split(argv[++i]);
        else if (a == "--sizes" && has_value) {
            o.sizes.clear();
            for (const std::string& s : split(argv[++i])) o.sizes.push_back(size_t(std::strtoull(s.c_str(), nullptr, 10)));
        } else if (a == "--variants" && has_value) o.variants = argv[++i];
        else if (a == "--large" && has_value) o.large = split(argv[++i]);
        else if (a == "--full") o.large.clear();
        else if (!root_seen && a.rfind("--", 0) != 0) o.root = a, root_seen = true;
        else return false;
    }
    return true;
}

// Whether `name` starts with one of `prefixes` (an empty list takes every name).
bool selected(const std::vector<std::string>& prefixes, const std::string& name) {
    if (prefixes.empty()) return true;
    for (const std::string& s : prefixes)
        if (name.rfind(s, 0) == 0) return true;
    return false;
}

ca_evaluate_options evaluate_options() {
    ca_evaluate_options eo;
    ca_evaluate_options_init(&eo);
    eo.surface_samples = 10000;
    eo.envelope_samples = 30000;
    return eo;
}

bool evaluate(ca_context* ctx, const ca_surface_view& reference, const ca_skeleton* sk, ca_evaluation& out) {
    ca_skeleton_view view;
    ca_skeleton_view_init(&view);
    ca_skeleton_get_view(sk, &view);
    const ca_evaluate_options eo = evaluate_options();
    out.struct_size = sizeof out;
    return ca_evaluate(ctx, &reference, &view, &eo, &out) == CA_OK;
}

// One run of the pipeline on a cloud, evaluated against `reference`.
struct CloudRun {
    ca_status status = CA_OK;
    std::string message;
    size_t balls = 0, uncovered = 0;
    int32_t normals = CA_NORMALS_NONE;
    bool evaluated = false;
    ca_evaluation eval{};
    bool cloud_evaluated = false;   // against the input cloud itself (run_surface's cloud_reference)
    ca_evaluation cloud_eval{};
    double seconds = 0, cpu_seconds = 0;
};

double cpu_now() { return double(std::clock()) / CLOCKS_PER_SEC; }

// The pipeline at the defaults on `input` (a cloud, or the mesh for the mesh route); the skeleton
// is evaluated against `reference` and, if given, against `cloud_reference` too.
CloudRun run_surface(const ca_surface_view& input, const ca_surface_view& reference,
                     const ca_surface_view* cloud_reference = nullptr) {
    CloudRun r;
    ca_context* ctx = nullptr;
    ca_context_create(nullptr, &ctx);
    bench::DefaultOptions options;
    ca_select_options& so = options.select;
    ca_candidate_set* set = nullptr;
    ca_selection* sel = nullptr;
    ca_skeleton* sk = nullptr;
    const auto t = std::chrono::steady_clock::now();
    const double c0 = cpu_now();
    r.status = ca_candidates(ctx, &input, &options.candidates, &set);
    if (r.status == CA_OK) {
        r.normals = ca_candidate_set_normals(set);
        r.status = ca_select(ctx, set, &so, &sel);
        if (r.status == CA_ERROR_UNCOVERABLE) {
            // Count the uncovered samples and build the skeleton of the rest: the row stays failed.
            r.message = ca_context_last_error(ctx);
            so.skip_uncoverable = 1;
            if (ca_select(ctx, set, &so, &sel) == CA_OK) r.uncovered = ca_selection_uncovered_count(sel);
        }
    }
    if (sel) {
        const ca_status connected = ca_connect(ctx, set, sel, &options.connect, &sk);
        if (r.status == CA_OK) r.status = connected;
    }
    r.seconds = bench::seconds_since(t);
    r.cpu_seconds = cpu_now() - c0;
    if (r.status != CA_OK && r.message.empty()) r.message = ca_context_last_error(ctx);
    if (sk) {
        r.balls = ca_skeleton_vertex_count(sk);
        r.evaluated = evaluate(ctx, reference, sk, r.eval);
        if (cloud_reference) r.cloud_evaluated = evaluate(ctx, *cloud_reference, sk, r.cloud_eval);
    }
    ca_skeleton_destroy(sk);
    ca_selection_destroy(sel);
    ca_candidate_set_destroy(set);
    ca_context_destroy(ctx);
    return r;
}

// "CA_ERROR_UNCOVERABLE" without the description.
std::string status_name(ca_status st) {
    const std::string s = ca_status_string(st);
    return s.substr(0, s.find(':'));
}


void print_row(const std::string& name, const char* variant, const CloudRun& r) {
    const std::string ok = r.status == CA_OK ? "yes" : "no: " + status_name(r.status);
    if (r.evaluated)
        std::printf("| %s | %s | %s | %s | %zu | %zu | %.3f | %.3f | %.3f | %.2f | %.2f |\n", name.c_str(), variant, ok.c_str(),
                    bench::normals_name(r.normals), r.balls, r.uncovered, r.eval.hd_surface_to_recon, r.eval.hd_recon_to_surface,
                    r.eval.hd_two_sided, r.seconds, r.cpu_seconds);
    else
        std::printf("| %s | %s | %s | %s | %zu | %zu | | | | %.2f | %.2f |\n", name.c_str(), variant, ok.c_str(), bench::normals_name(r.normals),
                    r.balls, r.uncovered, r.seconds, r.cpu_seconds);
    std::fflush(stdout);
}

std::vector<double> flatten(const std::vector<ca::Vec3>& v) {
    std::vector<double> out;
    out.reserve(3 * v.size());
    for (const ca::Vec3& p : v) out.insert(out.end(), {p.x(), p.y(), p.z()});
    return out;
}

struct Box {
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    explicit Box(const std::vector<double>& xyz) {
        for (size_t i = 0; i + 2 < xyz.size(); i += 3)
            for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], xyz[i + k]), hi[k] = std::max(hi[k], xyz[i + k]);
    }
    double diagonal() const { return std::sqrt(sq(hi[0] - lo[0]) + sq(hi[1] - lo[1]) + sq(hi[2] - lo[2])); }
    // Whether both boxes' corners agree within 2 % of this box's diagonal (same shape, same frame).
    bool matches(const Box& b) const {
        const double tol = 0.02 * diagonal();
        for (int k = 0; k < 3; ++k)
            if (std::fabs(lo[k] - b.lo[k]) > tol || std::fabs(hi[k] - b.hi[k]) > tol) return false;
        return true;
    }
    static double sq(double x) { return x * x; }
};

// A standard normal deviate (Box-Muller on the library's portable generator).
double gaussian(ca::Rng& rng) {
    const double u = 1.0 - rng.uniform(), v = rng.uniform();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(6.283185307179586 * v);
}

struct Variant {
    char key;
    const char* label;
};
const Variant kVariants[] = {{'a', "(a) exact normals"}, {'b', "(b) PCA, random signs"}, {'c', "(c) no normals"},
                             {'d', "(d) 0.5 % noise"}, {'o', "(o) PCA, exact signs"}};

// The cloud of variant `key` sampled from `mesh` with `n` points: positions and normals (empty: none).
void make_variant(const ca::Mesh& mesh, size_t n, char key, double diagonal, std::vector<double>& xyz,
                  std::vector<double>& normals) {
    const shapes::Cloud c = shapes::sample_cloud(mesh, n, 20260 + n);
    xyz = flatten(c.points);
    normals.clear();
    if (key == 'a') normals = flatten(c.normals);
    if (key == 'b') {
        // Passed as CA_POINT_NORMALS_UNORIENTED (main).
        std::vector<ca::Vec3> pca = ca::estimate_normals(c.points);
        ca::Rng rng(99 + n);
        for (ca::Vec3& v : pca)
            if (rng.next() & 1) v = -v;
        normals = flatten(pca);
    }
    if (key == 'o') {
        // diagnostic: (b)'s directions with the signs of the exact normals, passed as trusted
        std::vector<ca::Vec3> pca = ca::estimate_normals(c.points);
        for (size_t i = 0; i < pca.size(); ++i)
            if (pca[i].dot(c.normals[i]) < 0) pca[i] = -pca[i];
        normals = flatten(pca);
    }
    if (key == 'd') {
        ca::Rng rng(77 + n);
        const double sigma = 0.005 * diagonal;
        for (double& x : xyz) x += sigma * gaussian(rng);
        normals = flatten(c.normals);
    }
}

struct ShapeResult {
    double mesh_hd = 0;
    bool mesh_ok = false;
    std::map<std::pair<size_t, char>, CloudRun> runs;
};

double median(std::vector<double> v) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// "k of n within LIMIT (median M, worst W)" for ratios; n counts every comparable pair.
void print_ratio_line(const char* what, const std::vector<double>& ratios, double limit, size_t failed) {
    size_t within = 0;
    double worst = 0;
    for (double r : ratios) within += r <= limit, worst = std::max(worst, r);
    std::printf("- %s: %zu of %zu within %.2fx", what, within, ratios.size(), limit);
    if (!ratios.empty()) std::printf(" (median %.2fx, worst %.2fx)", median(ratios), worst);
    if (failed) std::printf("; %zu pair(s) not comparable (a run failed)", failed);
    std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    if (!parse(argc, argv, o)) {
        std::fprintf(stderr, "usage: bench_pointcloud [DATA_ROOT] [--only NAME[,NAME...]] [--sizes N[,N...]] [--variants abcdo]\n");
        return 2;
    }
    std::vector<std::string> meshes, clouds;
    for (const std::string& f : bench::list_files(o.root + "/meshes/paper", ".obj"))
        if (selected(o.only, bench::stem(f))) meshes.push_back(f);
    for (const char* ext : {".xyz", ".ply", ".obj", ".pts"})
        for (const std::string& f : bench::list_files(o.root + "/pointclouds", ext))
            if (selected(o.only, bench::stem(f))) clouds.push_back(f);
    if (meshes.empty() && clouds.empty()) {
        std::printf("bench_pointcloud: no meshes under %s/meshes/paper and no clouds under %s/pointclouds, skipped\n",
                    o.root.c_str(), o.root.c_str());
        return 0;
    }
    const char* header = "| cloud | variant | ok? | normals used | V | uncovered | HD surf->recon % | HD recon->surf % | "
                         "HD two-sided % | s | cpu s |\n|---|---|---|---|---|---|---|---|---|---|---|\n";

    // The stored clouds, evaluated against the paper mesh of the same name when it lies in the
    // same frame, else against the cloud itself.
    std::printf("## Clouds under pointclouds/ (defaults; HD against the mesh named by the file's first word)\n\n%s", header);
    size_t stored_ok = 0;
    for (const std::string& path : clouds) {
        caio::MeshData cloud, mesh;
        std::string err;
        if (!caio::read_mesh(path, cloud, err)) { std::printf("| %s | | read error: %s |\n", bench::stem(path).c_str(), err.c_str()); continue; }
        const std::string name = bench::stem(path);
        const std::string mesh_path = o.root + "/meshes/paper/" + name.substr(0, name.find('_')) + ".obj";
        const bool against_mesh = caio::read_mesh(mesh_path, mesh, err) && Box(mesh.positions).matches(Box(cloud.positions));
        const CloudRun r = run_surface(bench::view_of(cloud.positions, {}, cloud.normals),
                                       against_mesh ? bench::view_of(mesh.positions, mesh.triangles, {}) : bench::view_of(cloud.positions, {}, {}));
        stored_ok += r.status == CA_OK;
        print_row(name + (against_mesh ? "" : " (HD vs the cloud)"), cloud.normals.empty() ? "as stored, no normals" : "as stored",
                  r);
    }

    // The scans: h(recon -> cloud) is the target (no reconstruction reaches far outside the cloud).
    std::vector<std::string> scans;
    for (const char* ext : {".xyz", ".ply"})
        for (const std::string& f : bench::list_files(o.root + "/pointclouds/scans", ext))
            if (selected(o.only, bench::stem(f))) scans.push_back(f);
    size_t scans_within = 0, scans_rows = 0;
    if (!scans.empty()) {
        std::printf("\n## Scans under pointclouds/scans (defaults; HD against the cloud itself)\n\n"
                    "| scan | normals | ok? | normals used | V | uncovered | h(cloud->recon) %% | h(recon->cloud) %% | "
                    "two-sided %% | s |\n|---|---|---|---|---|---|---|---|---|---|\n");
        for (const std::string& path : scans) {
            caio::MeshData cloud;
            std::string err;
            const std::string name = bench::stem(path);
            if (!caio::read_mesh(path, cloud, err)) { std::printf("| %s | | read error: %s |\n", name.c_str(), err.c_str()); continue; }
            const ca_surface_view reference = bench::view_of(cloud.positions, {}, {});
            for (int estimated = 0; estimated < 2; ++estimated) {
                if (estimated && cloud.normals.empty()) continue;   // as stored is estimated already
                ca_surface_view input = bench::view_of(cloud.positions, {}, cloud.normals);
                if (estimated) input.point_normals = CA_POINT_NORMALS_ESTIMATE;
                const CloudRun r = run_surface(input, reference);
                const bool within = r.status == CA_OK && r.evaluated && r.eval.hd_recon_to_surface <= 5.0;
                scans_within += within, ++scans_rows;
                const char* variant = estimated ? "estimate" : cloud.normals.empty() ? "as stored (none)" : "as stored";
                const std::string ok = r.status == CA_OK ? "yes" : "no: " + status_name(r.status);
                if (r.evaluated)
                    std::printf("| %s | %s | %s | %s | %zu | %zu | %.3f | %.3f | %.3f | %.2f |\n", name.c_str(), variant, ok.c_str(),
                                bench::normals_name(r.normals), r.balls, r.uncovered, r.eval.hd_surface_to_recon,
                                r.eval.hd_recon_to_surface, r.eval.hd_two_sided, r.seconds);
                else
                    std::printf("| %s | %s | %s | %s | %zu | %zu | | | | %.2f |\n", name.c_str(), variant, ok.c_str(),
                                bench::normals_name(r.normals), r.balls, r.uncovered, r.seconds);
                std::fflush(stdout);
            }
        }
    }

    std::printf("\n## Clouds sampled from meshes/paper (area-uniform, fixed seed; HD against the source mesh)\n\n%s", header);
    std::map<std::string, ShapeResult> shapes_seen;
    for (const std::string& path : meshes) {
        const std::string name = bench::stem(path);
        caio::MeshData md;
        std::string err;
        if (!caio::read_mesh(path, md, err)) { std::printf("| %s | | read error: %s |\n", name.c_str(), err.c_str()); continue; }
        ShapeResult& sr = shapes_seen[name];
        const ca_surface_view reference = bench::view_of(md.positions, md.triangles, {});
        {
            const CloudRun m = run_surface(reference, reference);
            sr.mesh_ok = m.status == CA_OK && m.evaluated;
            sr.mesh_hd = m.eval.hd_two_sided;
            print_row(name, "mesh route", m);
        }
        const ca::Mesh core = to_core_mesh(md);
        const double diagonal = Box(md.positions).diagonal();
        for (size_t n : o.sizes) {
            if (n > 5000 && !selected(o.large, name)) continue;
            for (const Variant& v : kVariants) {
                if (o.variants.find(v.key) == std::string::npos) continue;
                std::vector<double> xyz, normals;
                make_variant(core, n, v.key, diagonal, xyz, normals);
                ca_surface_view input = bench::view_of(xyz, {}, normals);
                // (b)'s normals are right up to sign, and a caller who made them by PCA knows it
                if (v.key == 'b') input.point_normals = CA_POINT_NORMALS_UNORIENTED;
                // (c) is also measured against its own cloud: the scans' target (h(recon -> cloud))
                const ca_surface_view own = bench::view_of(xyz, {}, {});
                const CloudRun r = run_surface(input, reference, v.key == 'c' ? &own : nullptr);
                print_row(name + " " + std::to_string(n), v.label, r);
                sr.runs[{n, v.key}] = r;
            }
        }
    }

    // One line per target.
    std::printf("\n## Targets\n\n");
    std::printf("- stored clouds: %zu of %zu succeed at the defaults\n", stored_ok, clouds.size());
    size_t clean = 0, covered = 0;
    std::vector<double> vs_mesh, b_vs_a, c_vs_a, noisy;
    size_t vs_mesh_failed = 0, b_failed = 0, c_failed = 0, noisy_failed = 0;
    std::map<size_t, std::vector<double>> times, cpu_times;
    for (const auto& [name, sr] : shapes_seen)
        for (const auto& [key, r] : sr.runs) {
            const size_t n = key.first;
            const char variant = key.second;
            if (r.status == CA_OK) times[n].push_back(r.seconds), cpu_times[n].push_back(r.cpu_seconds);
            if (variant != 'd' && variant != 'o') clean += 1, covered += r.status == CA_OK && r.uncovered == 0;
            auto a = sr.runs.find({n, 'a'});
            const bool a_ok = a != sr.runs.end() && a->second.status == CA_OK && a->second.evaluated;
            const bool r_ok = r.status == CA_OK && r.evaluated;
            if (variant == 'a') {
                if (r_ok && sr.mesh_ok && sr.mesh_hd > 0) vs_mesh.push_back(r.eval.hd_two_sided / sr.mesh_hd);
                else ++vs_mesh_failed;
            } else if (variant == 'b' || variant == 'c') {
                if (r_ok && a_ok && a->second.eval.hd_two_sided > 0)
                    (variant == 'b' ? b_vs_a : c_vs_a).push_back(r.eval.hd_two_sided / a->second.eval.hd_two_sided);
                else ++(variant == 'b' ? b_failed : c_failed);
            } else if (variant == 'd') {
                if (r.evaluated && a_ok && a->second.eval.hd_recon_to_surface > 0)
                    noisy.push_back(r.eval.hd_recon_to_surface / a->second.eval.hd_recon_to_surface);
                else ++noisy_failed;
            }
        }
    std::printf("- clean sampled clouds (a-c) covering all their samples: %zu of %zu\n", covered, clean);
    if (scans_rows) std::printf("- scans: h(recon->cloud) <= 5 %%: %zu of %zu\n", scans_within, scans_rows);
    {
        size_t within = 0, rows = 0;
        double worst = 0;
        std::string worst_name;
        for (const auto& [name, sr] : shapes_seen)
            for (const auto& [key, r] : sr.runs) {
                if (key.second != 'c') continue;
                ++rows;
                if (r.status != CA_OK || !r.cloud_evaluated) continue;
                within += r.cloud_eval.hd_recon_to_surface <= 5.0;
                if (r.cloud_eval.hd_recon_to_surface > worst)
                    worst = r.cloud_eval.hd_recon_to_surface, worst_name = name + " " + std::to_string(key.first);
            }
        if (rows)
            std::printf("- sampled clouds with estimated normals (c): h(recon->cloud) <= 5 %%: %zu of %zu (worst %.2f %%, %s)\n",
                        within, rows, worst, worst_name.c_str());
    }
    print_ratio_line("two-sided HD of (a) / the mesh route's", vs_mesh, 1.25, vs_mesh_failed);
    print_ratio_line("two-sided HD of (b) / (a)", b_vs_a, 1.1, b_failed);
    print_ratio_line("two-sided HD of (c) / (a)", c_vs_a, 1.1, c_failed);
    print_ratio_line("noisy (d) h(recon->surface) / clean (a)'s", noisy, 2.0, noisy_failed);
    for (size_t n : o.sizes) {
        const std::vector<double>& t = times[n];
        const double limit = n <= 5000 ? 1.0 : 5.0;
        size_t within = 0;
        double worst = 0;
        for (double s : t) within += s <= limit, worst = std::max(worst, s);
        std::printf("- time per %zu-point cloud (successful runs): %zu of %zu within %.0f s", n, within, t.size(), limit);
        if (!t.empty()) std::printf(" (median %.2f s, worst %.2f s; cpu median %.2f s)", median(t), worst, median(cpu_times[n]));
        std::printf("\n");
    }
    return 0;
}

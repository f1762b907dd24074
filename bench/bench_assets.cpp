// bench_assets.cpp: every asset under the data folder through the command-line tool at its
// defaults, each in its own process as an asset pipeline runs it: the game meshes of <data>/real
// (foliage cards, open cloth, decals, flat planes, many-part buildings, files that break readers)
// and the other meshes of <data>. Per asset: the outcome, the medial and surface balls, the open
// parts, the two-sided Hausdorff distance and the time; each skeleton's exported cover samples are
// checked, independently of the tool, to lie within the dilated radius of one of its balls.
// Summary: "N of M assets: a skeleton covering every sample", and the time per asset of <data>/real.
// usage: bench_assets [DATA_ROOT] [--only PREFIX[,PREFIX...]]
#include "bench_common.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

namespace {

using Json = nlohmann::json;

// Cover samples (v x y z) farther than the dilated radius r + delta from every ball of the .ma,
// with a relative tolerance for the files' 9 printed digits.
size_t uncovered_samples(const std::string& samples_path, const std::string& ma_path, double delta, double diag) {
    std::vector<double> xyz, radii;
    std::string err;
    caio::SkeletonData sk;
    if (!caio::read_points(samples_path, xyz, radii, err) || !caio::read_ma(ma_path, sk, err)) return size_t(-1);
    const double tol = 1e-7 * diag;
    size_t bad = 0;
    for (size_t j = 0; j + 2 < xyz.size(); j += 3) {
        bool hit = false;
        for (size_t i = 0; i < sk.radii.size() && !hit; ++i) {
            const double dx = xyz[j] - sk.centers[3 * i], dy = xyz[j + 1] - sk.centers[3 * i + 1], dz = xyz[j + 2] - sk.centers[3 * i + 2];
            hit = std::sqrt(dx * dx + dy * dy + dz * dz) <= sk.radii[i] + delta + tol;
        }
        bad += !hit;
    }
    return bad;
}

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

}  // namespace

int main(int argc, char** argv) {
    std::string root, only;
    bench::root_and_only(argc, argv, root, only);
    std::string self = argv[0];
    const std::string tool = self.substr(0, self.find_last_of('/') + 1) + "coverage-axis";
    const std::vector<std::string> folders = {"real/0ad",     "real/flightgear", "real/openarena", "meshes/paper",
                                              "meshes/extra", "meshes/poor",     "meshes/thin",    "noisy"};
    std::vector<std::string> assets;
    for (const std::string& f : folders) {
        DIR* d = opendir((root + "/" + f).c_str());
        if (!d) continue;
        std::vector<std::string> names;
        while (dirent* e = readdir(d))
            if (e->d_name[0] != '.' && std::string(e->d_name) != "README.md") names.push_back(e->d_name);
        closedir(d);
        std::sort(names.begin(), names.end());
        for (const std::string& n : names)
            if (bench::selected(only, f + "/" + n)) assets.push_back(f + "/" + n);
    }
    if (assets.empty()) {
        std::printf("bench_assets: no assets under %s/real or %s/meshes, skipped\n", root.c_str(), root.c_str());
        return 0;
    }
    char dir_template[] = "/tmp/bench_assets.XXXXXX";
    const char* dir_c = mkdtemp(dir_template);
    if (!dir_c) { std::printf("bench_assets: no temporary folder\n"); return 1; }
    const std::string dir = dir_c;
    // the tool's own run bound; the process is killed a little after it
    const double limit_s = 60;
    std::printf("Every asset through `coverage-axis ASSET -o OUT.ma --export-samples S.xyz --evaluate --json --time-limit %.0f`\n"
                "at the defaults, one process each. time: the run (read, candidates, selection, connection; not the\n"
                "evaluation); wall: the whole process. covered: the exported cover samples within r + delta of a ball of\n"
                "the .ma (checked here, not by the tool).\n\n",
                limit_s);
    std::printf("%-58s %-26s %6s %6s %4s %8s %7s %7s %s\n", "asset", "outcome", "medial", "surf", "open", "HD %", "time s",
                "wall s", "covered");
    size_t good = 0, failed_clean = 0, crashed = 0;
    std::vector<double> real_times, sheet_hd, all_hd;
    double real_max = 0, worst_hd = 0;
    std::string worst_name, slowest;
    for (const std::string& a : assets) {
        const std::string in = root + "/" + a, ma = dir + "/out.ma", samples = dir + "/samples.xyz", out = dir + "/out.json";
        std::remove(ma.c_str());
        std::remove(samples.c_str());
        const bench::ProcessRun o = bench::run_process({tool, in, "-o", ma, "--export-samples", samples, "--evaluate", "--json", "--time-limit",
                                    std::to_string(int(limit_s))},
                                   out, limit_s + 30);
        std::string outcome;
        unsigned long long medial = 0, surface = 0, open = 0;
        double hd = -1, t = 0;
        std::string covered = "-";
        Json j;
        bool parsed = false;
        try {
            j = Json::parse(o.out);
            parsed = true;
        } catch (const std::exception&) {
        }
        if (!o.ran) {
            outcome = "HUNG (killed)";
            ++crashed;
        } else if (o.signal) {
            outcome = "CRASHED (signal " + std::to_string(o.signal) + ")";
            ++crashed;
        } else if (!parsed) {
            outcome = "no JSON (exit " + std::to_string(o.exit_code) + ")";
            ++crashed;
        } else if (j.contains("error")) {
            const Json& e = j["error"];
            outcome = e.is_object() && e.contains("status") ? e["status"].get<std::string>() : std::string("error");
            if (outcome.rfind("CA_ERROR_", 0) == 0) outcome = outcome.substr(9);
            ++failed_clean;
        } else {
            medial = j.value("medial_balls", 0ull);
            surface = j.value("surface_balls", 0ull);
            open = j.value("open_parts", 0ull);
            hd = j.value("hd_two_sided", -1.0);
            t = j["time_s"].value("total", 0.0) - j["time_s"].value("evaluate", 0.0);
            const double diag = j.value("diagonal", 0.0) > 0 ? j["diagonal"].get<double>() : j.value("reference_length", 1.0);
            const size_t bad = uncovered_samples(samples, ma, j.value("delta", 0.0), diag);
            covered = bad == 0 ? "all" : bad == size_t(-1) ? "unread" : std::to_string(bad) + " not";
            outcome = "skeleton";
            if (bad == 0) ++good;
            all_hd.push_back(hd);
            if (surface > 0) sheet_hd.push_back(hd);
            if (hd > worst_hd) worst_hd = hd, worst_name = a;
            if (a.rfind("real/", 0) == 0) {
                real_times.push_back(t);
                if (t > real_max) real_max = t, slowest = a;
            }
        }
        std::printf("%-58s %-26s %6llu %6llu %4llu %8.3f %7.3f %7.3f %s\n", a.c_str(), outcome.c_str(), medial, surface, open, hd, t,
                    o.wall_s, covered.c_str());
        std::fflush(stdout);
    }
    std::remove((dir + "/out.ma").c_str());
    std::remove((dir + "/samples.xyz").c_str());
    std::remove((dir + "/out.json").c_str());
    rmdir(dir.c_str());
    std::printf("\n%zu of %zu assets: a skeleton covering every sample; %zu refused with a clear error, %zu crashed or hung\n", good,
                assets.size(), failed_clean, crashed);
    std::printf("two-sided HD: median %.3f %% over all skeletons, median %.3f %% over the %zu with surface balls, worst %.3f %% (%s)\n",
                median(all_hd), median(sheet_hd), sheet_hd.size(), worst_hd, worst_name.c_str());
    if (!real_times.empty())
        std::printf("time per asset of real/ (%zu skeletons): median %.3f s, max %.3f s (%s)\n", real_times.size(), median(real_times),
                    real_max, slowest.c_str());
    return crashed ? 1 : 0;
}

// bench_connect.cpp: both connection routes (power diagram, medial axis) on the same selection
// for every mesh of <data>/meshes/paper and <data>/meshes/extra, at the default options (exact
// solver, 5 s limit). One row per model and route: |V|, |E|, |F|, components, b1, the input's
// genus (-1 unknown) and the handles without a loop (thin), the share of edges leaving the shape,
// and the connection time.
// An edge "leaves" when one of its points at spacing delta/8 lies outside the shape: generalised
// winding number <= 1/2, not inside 0.95 x the undilated ball of either end, and farther than
// delta/4 from the surface.
// Usage: bench_connect [data root, default ../shared/data] [connect samples] [model substring]
#include "candidates.h"
#include "connect.h"
#include "distance.h"
#include "mesh_io.h"
#include "support/mesh_convert.h"
#include "selection.h"
#include "winding.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <dirent.h>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace {

bool is_dir(const std::string& p) {
    struct stat st;
    return stat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

std::vector<std::string> meshes_in(const std::string& dir) {
    std::vector<std::string> out;
    if (DIR* d = opendir(dir.c_str())) {
        while (dirent* e = readdir(d)) {
            const std::string name = e->d_name;
            if (name.size() > 4 && name.substr(name.size() - 4) == ".obj") out.push_back(dir + "/" + name);
        }
        closedir(d);
    }
    std::sort(out.begin(), out.end());
    return out;
}

// Edges of `sk` that leave the shape (rule in the header comment).
size_t leaving_edges(const ca::Skeleton& sk, const ca::Mesh& mesh, const ca::WindingNumber& w,
                     const ca::MeshDistance& dist, double delta) {
    size_t bad = 0;
    const double h = delta / 8, tol = delta / 4;
    for (const auto& e : sk.edges) {
        const ca::Ball &a = sk.balls[e[0]], &b = sk.balls[e[1]];
        const int n = std::max(1, int(std::ceil((b.center - a.center).norm() / h)));
        for (int i = 1; i < n; ++i) {
            const ca::Vec3 p = a.center + (b.center - a.center) * (double(i) / n);
            if ((p - a.center).norm() < 0.95 * a.radius || (p - b.center).norm() < 0.95 * b.radius) continue;
            if (w(p) > 0.5 || dist.distance_below(p, 2 * tol) <= tol) continue;
            ++bad;
            break;
        }
    }
    (void)mesh;
    return bad;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string root = argc > 1 ? argv[1] : "../shared/data";
    const long connect_samples = argc > 2 ? std::atol(argv[2]) : -1;
    const std::string filter = argc > 3 ? argv[3] : "";
    if (!is_dir(root + "/meshes/paper") && !is_dir(root + "/meshes/extra")) {
        std::printf("bench_connect: no meshes under %s/meshes/{paper,extra}; nothing to do\n", root.c_str());
        return 0;
    }
    std::vector<std::string> files = meshes_in(root + "/meshes/paper");
    for (const std::string& f : meshes_in(root + "/meshes/extra")) files.push_back(f);

    std::printf("%-22s %-6s %5s %6s %6s %5s %4s %5s %4s %8s %9s\n", "model", "route", "|V|", "|E|", "|F|", "comp", "b1",
                "genus", "thin", "leave%", "time_s");
    double total[2] = {0, 0}, worst[2] = {0, 0};
    size_t total_leave[2] = {0, 0};
    for (const std::string& file : files) {
        std::string name = file.substr(file.find_last_of('/') + 1);
        name = name.substr(0, name.size() - 4);
        if (!filter.empty() && name.find(filter) == std::string::npos) continue;
        caio::MeshData data;
        std::string error;
        if (!caio::read_mesh(file, data, error)) {
            std::printf("%-22s read error: %s\n", name.c_str(), error.c_str());
            continue;
        }
        ca::Surface surface;
        ca::Status st = ca::prepare_surface(to_core_mesh(data), {}, surface);
        ca::Monitor monitor;
        ca::CandidateOptions copt;
        if (connect_samples >= 0) copt.connect_samples = uint32_t(connect_samples);
        ca::CandidateSet set;
        if (st.ok()) st = ca::generate_candidates(std::move(surface), copt, monitor, set);
        ca::SelectOptions sopt;
        sopt.cover.time_limit_s = 5;
        ca::Selection sel;
        if (st.ok()) st = ca::select_balls(set, sopt, monitor, sel);
        if (!st.ok()) {
            std::printf("%-22s pipeline error: %s\n", name.c_str(), st.message.c_str());
            continue;
        }
        const ca::WindingNumber winding(set.surface.mesh);
        const ca::MeshDistance distance(set.surface.mesh);
        for (int route = 0; route < 2; ++route) {
            ca::ConnectOptions opt;
            opt.method = route == 0 ? ca::ConnectMethod::power : ca::ConnectMethod::medial;
            ca::Skeleton sk;
            const auto t0 = std::chrono::steady_clock::now();
            ca::ConnectReport report;
            st = ca::connect_balls(set, sel, opt, monitor, sk, &report);
            const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            if (!st.ok()) {
                std::printf("%-22s %-6s error: %s\n", name.c_str(), route ? "medial" : "power", st.message.c_str());
                continue;
            }
            const ca::TopologyStats topo = ca::topology(sk);
            const size_t leave = leaving_edges(sk, set.surface.mesh, winding, distance, sel.delta);
            total[route] += t;
            worst[route] = std::max(worst[route], t);
            total_leave[route] += leave;
            std::printf("%-22s %-6s %5zu %6zu %6zu %5zu %4ld %5ld %4zu %8.2f %9.3f\n", name.c_str(), route ? "medial" : "power",
                        sk.balls.size(), sk.edges.size(), sk.faces.size(), topo.components, topo.betti1, report.genus,
                        report.thin_handles,
                        sk.edges.empty() ? 0.0 : 100.0 * double(leave) / double(sk.edges.size()), t);
            std::fflush(stdout);
        }
    }
    for (int route = 0; route < 2; ++route)
        std::printf("%-6s total connection %.3f s, worst %.3f s, leaving edges %zu\n", route ? "medial" : "power",
                    total[route], worst[route], total_leave[route]);
    return 0;
}

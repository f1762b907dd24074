// bench_rig.cpp: the correspondence and the rig (docs/rig.md) on tests/data/fox.obj and every mesh
// of <data>/meshes/paper, each skeletonized at the default options (exact solver, proven or 5 s).
// One row per model: input vertices, balls, the rig's joints, branches and leaves, the largest
// change of a vertex's ball weights (L1) across a mesh edge, and the times of ca_correspond's step
// and ca_rig_build's step (curve skeleton, joints and vertex weights).
// Usage: bench_rig [data root, default ../shared/data] [model substring]
#include "bench_common.h"
#include "mesh_io.h"
#include "steps.h"
#include "support/mesh_convert.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <dirent.h>
#include <map>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

bool skeleton_of(const ca::Mesh& mesh, ca::Skeleton& out) {
    ca::SurfaceInput surface;
    surface.mesh = mesh;
    ca::CandidateSet set;
    ca::SelectResult sel;
    ca::ConnectResult k;
    ca::SelectRequest sr;
    sr.select.cover.time_limit_s = 5;
    if (!ca::candidates_step(surface, ca::CandidateOptions{}, ca::Monitor{}, set).ok() ||
        !ca::select_step(set, sr, ca::Monitor{}, sel).ok() ||
        !ca::connect_step(set, sel.selection, ca::ConnectRequest{}, ca::Monitor{}, k).ok())
        return false;
    out = k.skeleton;
    for (ca::Ball& b : out.balls) {
        b.center = set.surface.norm.to_user(b.center);
        b.radius *= set.surface.norm.scale;
    }
    return true;
}

void row(const std::string& path) {
    ca::Mesh mesh;
    std::string error;
    if (!read_core_mesh(path, mesh, error)) {
        std::printf("| %s | read failed: %s |\n", path.c_str(), error.c_str());
        return;
    }
    ca::Skeleton sk;
    if (!skeleton_of(mesh, sk)) {
        std::printf("| %s | no skeleton |\n", path.c_str());
        return;
    }
    ca::SurfaceInput surface;
    surface.mesh = mesh;
    auto t = Clock::now();
    ca::Correspondence c;
    const ca::Status sc = ca::correspondence_step(surface, sk, {}, ca::Monitor{}, c);
    const double t_correspond = since(t);
    t = Clock::now();
    ca::Rig rig;
    const ca::Status sr = ca::rig_step(surface, sk, {}, ca::Monitor{}, rig);
    const double t_rig = since(t);
    if (!sc.ok() || !sr.ok()) {
        std::printf("| %s | failed: %s %s |\n", path.c_str(), sc.message.c_str(), sr.message.c_str());
        return;
    }
    std::vector<int> degree(rig.joints.size(), 0);
    for (size_t j = 1; j < rig.joints.size(); ++j) {
        ++degree[j];
        ++degree[size_t(rig.parent[j])];
    }
    const long leaves = std::count(degree.begin(), degree.end(), 1);
    double worst = 0;
    for (const ca::Tri& f : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = f[k], b = f[(k + 1) % 3];
            std::map<uint32_t, double> d;
            for (int s = 0; s < ca::kInfluences; ++s) {
                d[c.balls[a][s]] += c.weights[a][s];
                d[c.balls[b][s]] -= c.weights[b][s];
            }
            double change = 0;
            for (const auto& [ball, w] : d) change += std::abs(w);
            worst = std::max(worst, change);
        }
    std::string name = path.substr(path.find_last_of('/') + 1);
    std::printf("| %s | %zu | %zu | %zu | %zu | %ld | %.3f | %.3f | %.3f |\n", name.c_str(), mesh.vertices.size(),
                sk.balls.size(), rig.joints.size(), rig.branch_count, leaves, worst, t_correspond, t_rig);
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    const std::string data = argc > 1 ? argv[1] : "../shared/data";
    const std::string filter = argc > 2 ? argv[2] : "";
    std::printf("Correspondence and rig at the defaults (docs/rig.md); edge change: the largest L1 change of a\n"
                "vertex's ball weights across a mesh edge (nearest-ball labels: 2).\n\n");
    std::printf("| model | vertices | balls | joints | branches | leaves | edge change | correspond s | rig s |\n");
    std::printf("| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
    std::vector<std::string> models{std::string(CA_TEST_DATA) + "/fox.obj"};
    for (const std::string& m : bench::list_files(data + "/meshes/paper", ".obj")) models.push_back(m);
    for (const std::string& m : models)
        if (filter.empty() || m.find(filter) != std::string::npos) row(m);
    return 0;
}

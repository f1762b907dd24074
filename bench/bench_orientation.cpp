// bench_orientation.cpp: how well point-cloud normals are oriented, without the rest of the
// pipeline. Each cloud goes through prepare_surface (surface.h: the sign check, orientation and
// refusal) in four variants: (r) exact normals with random per-point signs, passed as trusted;
// (b) PCA normals with random signs, passed as unoriented; (c) no normals (estimated);
// (d) 0.5 % Gaussian noise of the bbox diagonal with the exact normals, trusted. Per row: the
// status, the normals used, and "wrong": the share of points whose sign differs from the exact
// normal's, up to one global sign (the winding number fixes that later), with the CPU time.
// Clouds: tests/data/fish_points.xyz, every .xyz under <data>/pointclouds (their stored normals
// as the exact ones) and 5000 points sampled from each mesh under <data>/meshes/paper (the seed
// of bench_pointcloud).
// usage: bench_orientation [DATA_ROOT] [--only NAME[,NAME...]]
#include "bench_common.h"
#include "normals.h"
#include "rng.h"
#include "surface.h"
#include "support/clouds.h"
#include "support/mesh_convert.h"

#include <cmath>
#include <cstdio>

namespace {


double gaussian(ca::Rng& rng) {
    const double u = 1.0 - rng.uniform(), v = rng.uniform();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(6.283185307179586 * v);
}

const char* source_name(ca::NormalSource s) {
    switch (s) {
        case ca::NormalSource::given: return "given";
        case ca::NormalSource::oriented: return "oriented";
        case ca::NormalSource::estimated: return "estimated";
        default: return "none";
    }
}

void run_cloud(const std::string& name, const shapes::Cloud& c) {
    auto [lo, hi] = ca::bounding_box(c.points);
    const double diagonal = (hi - lo).norm();
    for (char key : {'r', 'b', 'c', 'd'}) {
        std::vector<ca::Vec3> pts = c.points, nrm = c.normals;
        ca::PointNormals trust = ca::PointNormals::trusted;
        ca::Rng rng(99 + pts.size());
        if (key == 'r')
            for (ca::Vec3& v : nrm)
                if (rng.next() & 1) v = -v;
        if (key == 'b') {
            nrm = ca::estimate_normals(pts);
            for (ca::Vec3& v : nrm)
                if (rng.next() & 1) v = -v;
            trust = ca::PointNormals::unoriented;
        }
        if (key == 'c') nrm.clear(), trust = ca::PointNormals::estimate;
        if (key == 'd')
            for (ca::Vec3& p : pts)
                for (int k = 0; k < 3; ++k) p[k] += 0.005 * diagonal * gaussian(rng);
        ca::Mesh m;
        m.vertices = pts;
        ca::Surface s;
        const double t = bench::cpu_seconds();
        const ca::Status st = ca::prepare_surface(m, nrm, s, true, trust);
        const double cpu = bench::cpu_seconds() - t;
        if (!st.ok()) {
            std::printf("| %s | %c | refused: %s | | | %.2f |\n", name.c_str(), key, st.message.c_str(), cpu);
            continue;
        }
        size_t same = 0;
        for (size_t i = 0; i < pts.size(); ++i) same += s.normals[i].dot(c.normals[i]) > 0;
        const double f = double(same) / double(pts.size());
        std::printf("| %s | %c | ok | %s | %.2f %% | %.2f |\n", name.c_str(), key, source_name(s.normals_source),
                    100.0 * std::min(f, 1 - f), cpu);
    }
}

}  // namespace

int main(int argc, char** argv) {
    std::string root, only;
    bench::root_and_only(argc, argv, root, only);
    std::printf("%s\n\n", bench::kCpuClock);
    std::printf("| cloud | variant | status | normals used | wrong | cpu s |\n|---|---|---|---|---|---|\n");
    std::vector<std::string> files = {std::string(CA_TEST_DATA) + "/fish_points.xyz"};
    for (const std::string& f : bench::list_files(root + "/pointclouds", ".xyz")) files.push_back(f);
    for (const std::string& f : files) {
        if (!bench::selected(only, bench::stem(f))) continue;
        caio::MeshData m;
        std::string err;
        if (!caio::read_mesh(f, m, err) || m.normals.empty()) continue;
        shapes::Cloud c;
        for (size_t i = 0; 3 * i + 2 < m.positions.size(); ++i) {
            c.points.emplace_back(m.positions[3 * i], m.positions[3 * i + 1], m.positions[3 * i + 2]);
            c.normals.push_back(ca::Vec3(m.normals[3 * i], m.normals[3 * i + 1], m.normals[3 * i + 2]).normalized());
        }
        run_cloud(bench::stem(f), c);
    }
    for (const std::string& f : bench::list_files(root + "/meshes/paper", ".obj")) {
        if (!bench::selected(only, bench::stem(f))) continue;
        ca::Mesh mesh;
        std::string err;
        if (!read_core_mesh(f, mesh, err)) continue;
        run_cloud(bench::stem(f) + " (5000)", shapes::sample_cloud(mesh, 5000, 20260 + 5000));
    }
    return 0;
}

// bench_normals.cpp: point clouds under five kinds of normals: exact (as sampled or as in the
// file), all flipped, random per-point signs passed as trusted (the sign check must catch them)
// and as unoriented, and none (estimated). Per row: the sign disagreement of the normals passed
// (normals.h), the normals the library used, the skeleton's size and topology. Clouds: a sampled
// sphere and torus, tests/data/fish_points.xyz and every .xyz under <data>/pointclouds.
// usage: bench_normals [DATA_ROOT [NAME_PART]]   (NAME_PART: only the files whose path contains it)
#include "bench_common.h"
#include "normals.h"
#include "rng.h"
#include "support/clouds.h"
#include "support/shapes.h"

#include <cstdio>

namespace {

struct Variant {
    const char* name;
    int32_t trust;
    int flip;   // 0 as given, 1 all flipped, 2 random per-point signs, 3 no normals
};

const char* used_name(int32_t n) {
    switch (n) {
        case CA_NORMALS_GIVEN: return "given";
        case CA_NORMALS_ORIENTED: return "oriented";
        case CA_NORMALS_ESTIMATED: return "estimated";
        default: return "none";
    }
}

caio::MeshData from_cloud(const shapes::Cloud& c) {
    caio::MeshData m;
    for (size_t i = 0; i < c.points.size(); ++i)
        for (int k = 0; k < 3; ++k) m.positions.push_back(c.points[i][k]), m.normals.push_back(c.normals[i][k]);
    return m;
}

void run_cloud(const std::string& name, const caio::MeshData& cloud) {
    static const Variant variants[] = {{"exact", CA_POINT_NORMALS_TRUSTED, 0},
                                       {"flipped", CA_POINT_NORMALS_TRUSTED, 1},
                                       {"random signs, trusted", CA_POINT_NORMALS_TRUSTED, 2},
                                       {"random signs, unoriented", CA_POINT_NORMALS_UNORIENTED, 2},
                                       {"none", CA_POINT_NORMALS_TRUSTED, 3}};
    const bench::DefaultOptions d;
    const size_t n = cloud.positions.size() / 3;
    std::vector<ca::Vec3> pts(n);
    for (size_t i = 0; i < n; ++i) pts[i] = ca::Vec3(cloud.positions[3 * i], cloud.positions[3 * i + 1], cloud.positions[3 * i + 2]);
    for (const Variant& v : variants) {
        caio::MeshData m = cloud;
        ca::Rng rng(11);
        for (size_t i = 0; i < n; ++i) {
            const bool negate = v.flip == 1 || (v.flip == 2 && rng.uniform() < 0.5);
            if (negate)
                for (int k = 0; k < 3; ++k) m.normals[3 * i + k] = -m.normals[3 * i + k];
        }
        if (v.flip == 3) m.normals.clear();
        double disagreement = -1;
        if (!m.normals.empty()) {
            std::vector<ca::Vec3> nrm(n);
            for (size_t i = 0; i < n; ++i) nrm[i] = ca::Vec3(m.normals[3 * i], m.normals[3 * i + 1], m.normals[3 * i + 2]).normalized();
            disagreement = ca::sign_disagreement(pts, nrm);
        }
        const auto t = std::chrono::steady_clock::now();
        const bench::PipelineRun r = bench::run_pipeline(m, d.candidates, d.select, d.connect, false, nullptr, nullptr, v.trust);
        const double secs = bench::seconds_since(t);
        char dis[16] = "-";
        if (disagreement >= 0) std::snprintf(dis, sizeof dis, "%.3f", disagreement);
        if (r.status == CA_OK)
            std::printf("%-22s %-26s %9s %-10s %6zu %5zu %4ld %7.2f\n", name.c_str(), v.name, dis, used_name(r.normals),
                        r.balls, r.components, r.betti1, secs);
        else
            std::printf("%-22s %-26s %9s %s: %s\n", name.c_str(), v.name, dis, ca_status_string(r.status), r.message.c_str());
    }
}

}  // namespace

int main(int argc, char** argv) {
    const std::string root = argc > 1 ? argv[1] : "../shared/data";
    std::printf("%-22s %-26s %9s %-10s %6s %5s %4s %7s\n", "cloud", "normals passed", "disagree", "used", "|V|", "comp",
                "b1", "time s");
    run_cloud("sphere R=2 (5000)", from_cloud(shapes::sample_cloud(shapes::sphere(2.0, 96, 192), 5000)));
    run_cloud("torus 1/0.3 (8000)", from_cloud(shapes::sample_cloud(shapes::torus(1.0, 0.3, 128, 48), 8000)));
    std::vector<std::string> files = {std::string(CA_TEST_DATA) + "/fish_points.xyz"};
    for (const std::string& f : bench::list_files(root + "/pointclouds", ".xyz")) files.push_back(f);
    const std::string only = argc > 2 ? argv[2] : "";
    for (const std::string& f : files) {
        if (f.find(only) == std::string::npos) continue;
        caio::MeshData m;
        std::string err;
        if (!caio::read_mesh(f, m, err) || m.normals.empty()) {
            std::printf("%-22s skipped (%s)\n", bench::stem(f).c_str(), err.empty() ? "no normals" : err.c_str());
            continue;
        }
        run_cloud(bench::stem(f), m);
    }
    return 0;
}

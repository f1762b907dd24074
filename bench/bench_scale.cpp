// bench_scale.cpp: a 2 000 000-triangle torus (generated, written as binary PLY) at the defaults:
// the whole run (read + pipeline) in its own process with its peak RSS, then where the time goes,
// each step timed alone on the same input: reading, validation and merging, the winding-number
// tree, the distance tree, hole caps, surface sampling, the Delaunay step, the inside decisions
// and the distances at the Voronoi vertices.
// usage: bench_scale [DATA_ROOT]   (the data root is not used: the input is generated)
#include "bench_common.h"
#include "bench_inputs.h"

#include "candidates.h"
#include "delaunay.h"
#include "distance.h"
#include "sampling.h"
#include "surface.h"
#include "winding.h"

#include <cstdlib>

namespace {

template <class F>
double timed(F&& f) {
    const auto t = std::chrono::steady_clock::now();
    f();
    return bench::seconds_since(t);
}

}  // namespace

int main() {
    char dir_template[] = "/tmp/bench_scale.XXXXXX";
    const char* dir = mkdtemp(dir_template);
    if (!dir) { std::printf("bench_scale: no temporary folder, skipped\n"); return 0; }
    const std::string path = std::string(dir) + "/torus.ply";
    if (!bench::write_binary_ply(path, bench::torus(2000, 500))) { std::printf("bench_scale: cannot write %s\n", path.c_str()); return 0; }

    ca_candidate_options co;
    ca_candidate_options_init(&co);
    ca_select_options so;
    ca_select_options_init(&so);
    ca_connect_options cop;
    ca_connect_options_init(&cop);
    double peak = 0;
    const bench::Outcome o = bench::run_isolated(path, co, so, cop, peak);
    std::printf("\n## A 2 000 000-triangle torus (binary PLY) at the defaults\n\n");
    std::printf("whole run (read + candidates + select + connect, own process): %s, %zu balls, %.2f s, peak RSS %.0f MB\n",
                o.status == CA_OK && o.read_ok ? "skeleton" : o.message, o.balls, o.seconds, peak);

    std::printf("\n| step (timed alone) | s |\n|---|---|\n");
    caio::MeshData md;
    std::string err;
    std::printf("| read binary PLY | %.3f |\n", timed([&] { caio::read_mesh(path, md, err); }));
    std::remove(path.c_str());
    rmdir(dir);
    ca::Surface surf;
    const double t_prepare = timed([&] {
        ca::Mesh m;
        m.vertices.reserve(md.positions.size() / 3);
        for (size_t i = 0; i + 2 < md.positions.size(); i += 3)
            m.vertices.emplace_back(md.positions[i], md.positions[i + 1], md.positions[i + 2]);
        m.triangles.reserve(md.triangles.size() / 3);
        for (size_t i = 0; i + 2 < md.triangles.size(); i += 3)
            m.triangles.push_back({md.triangles[i], md.triangles[i + 1], md.triangles[i + 2]});
        ca::prepare_surface(std::move(m), {}, surf);
    });
    std::printf("| copy in, validate, weld and merge, normalise, orient | %.3f |\n", t_prepare);
    const ca::Mesh& mesh = surf.mesh;
    std::unique_ptr<ca::WindingNumber> winding;
    std::unique_ptr<ca::MeshDistance> distance;
    std::printf("| winding-number tree (BVH + expansions) | %.3f |\n", timed([&] { winding = std::make_unique<ca::WindingNumber>(mesh); }));
    std::printf("| distance tree (BVH) | %.3f |\n", timed([&] { distance = std::make_unique<ca::MeshDistance>(mesh); }));
    std::printf("| hole caps (boundary loops) | %.3f |\n", timed([&] { ca::hole_caps(mesh); }));
    std::vector<ca::Vec3> samples;
    std::printf("| surface sampling (1 500 + 4 000 + 4 000) | %.3f |\n", timed([&] {
        ca::sample_surface(mesh, co.cover_samples, 1);
        ca::sample_surface(mesh, co.connect_samples, 4);
        samples = ca::sample_surface(mesh, co.voronoi_samples, 2);
    }));
    std::vector<ca::Tet> tets;
    std::printf("| Delaunay of the 4 000 samples (Qhull) | %.3f |\n", timed([&] { ca::delaunay_tetrahedra(samples, tets); }));
    // the circumcentres the candidate step tests: those within the samples' box
    std::vector<ca::Vec3> centres;
    const auto [lo, hi] = ca::bounding_box(samples);
    for (const ca::Tet& t : tets) {
        ca::Vec3 c;
        if (ca::circumcenter(samples[t[0]], samples[t[1]], samples[t[2]], samples[t[3]], c) &&
            (c.array() >= lo.array()).all() && (c.array() <= hi.array()).all())
            centres.push_back(c);
    }
    std::vector<ca::Vec3> inner;
    std::printf("| inside decisions (winding number) at %zu circumcentres | %.3f |\n", centres.size(), timed([&] {
        for (const ca::Vec3& c : centres)
            if (winding->inside(c)) inner.push_back(c);
    }));
    // inner points only: outer ones near the torus's axis are equidistant from a whole circle of
    // triangles, which no box can prune, and the pipeline never measures them
    std::printf("| distances at the %zu inner circumcentres | %.3f |\n", inner.size(), timed([&] {
        for (const ca::Vec3& c : inner) distance->distance(c);
    }));
    return 0;
}

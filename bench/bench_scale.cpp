// bench_scale.cpp: a 2 000 000-triangle torus (generated, written as binary PLY) at the defaults:
// the whole run (read + pipeline) in its own process with its peak RSS and its phases (read,
// candidates, select, connect), at 1 and 2 worker threads and at all cores, with the speed-ups
// over 1 thread; then where the candidate step's time goes, each step timed alone on the same
// input: reading, the surface preparation (validation, merging, the half-edges'
// caps and topology), the triangle tree the winding number and the distances share, the
// winding number's far fields, surface sampling, the Delaunay step and the inside decisions.
// usage: bench_scale [DATA_ROOT]   (the data root is not used: the input is generated)
#include "bench_common.h"
#include "bench_inputs.h"

#include "bvh.h"
#include "candidates.h"
#include "delaunay.h"
#include "hole_caps.h"
#include "mesh_topology.h"
#include "parallel.h"
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

    const bench::DefaultOptions d;
    // the whole run at 1 and 2 worker threads and at the defaults (all cores), each in its own process
    const int cores = ca::resolve_threads(0);
    std::vector<int> counts = {1, 2};
    if (cores > 2) counts.push_back(cores);
    std::vector<bench::Outcome> runs;
    std::vector<double> peaks;
    for (int t : counts) {
        double peak = 0;
        runs.push_back(bench::run_isolated(path, d.candidates, d.select, d.connect, peak, t == cores ? 0 : t));
        peaks.push_back(peak);
    }
    const bench::Outcome& o = runs.back();
    std::printf("\n## A 2 000 000-triangle torus (binary PLY) at the defaults\n\n");
    std::printf("whole run (read + candidates + select + connect, own process, %d threads = all cores): %s, %zu balls, %.2f s, peak RSS %.0f MB\n",
                cores, o.status == CA_OK && o.read_ok ? "skeleton" : o.message, o.balls, o.seconds, peaks.back());
    std::printf("\n| phase of the whole run (s) |");
    for (int t : counts) std::printf(" %d thread%s |", t, t == 1 ? "" : "s");
    std::printf("\n|---|");
    for (size_t i = 0; i < counts.size(); ++i) std::printf("---|");
    std::printf("\n");
    auto row = [&](const char* name, double bench::Outcome::*field) {
        std::printf("| %s |", name);
        for (const bench::Outcome& r : runs) std::printf(" %.3f |", r.*field);
        std::printf("\n");
    };
    row("read binary PLY", &bench::Outcome::t_read);
    row("candidates", &bench::Outcome::t_candidates);
    row("select", &bench::Outcome::t_select);
    row("connect", &bench::Outcome::t_connect);
    row("whole run", &bench::Outcome::seconds);
    std::printf("| speed-up of the whole run over 1 thread |");
    for (const bench::Outcome& r : runs) std::printf(" %.2f |", r.seconds > 0 ? runs[0].seconds / r.seconds : 0.0);
    std::printf("\n| same skeleton (balls) as 1 thread |");
    for (const bench::Outcome& r : runs) std::printf(" %s |", r.status == runs[0].status && r.balls == runs[0].balls ? "yes" : "NO");
    std::printf("\n");

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
    std::printf("| copy in, validate, weld and merge, normalise, half-edges (caps, topology), orient | %.3f |\n", t_prepare);
    const ca::Mesh& mesh = surf.mesh;
    std::printf("| of which the half-edges, caps and topology | %.3f |\n", timed([&] {
        const ca::HalfEdgeBuckets edges = ca::half_edge_buckets(mesh);
        ca::hole_caps(mesh, edges);
        ca::mesh_topology(mesh, {}, edges);
    }));
    std::unique_ptr<ca::WindingNumber> winding;
    const int threads = cores;   // all cores, as the pipeline builds it by default
    std::shared_ptr<const ca::detail::TriangleTree> tree;
    std::printf("| triangle tree (BVH + corners, shared by the winding number and the distances, %d threads) | %.3f |\n",
                threads, timed([&] { tree = ca::detail::build_triangle_tree(mesh, threads); }));
    std::printf("| winding-number far fields (%d threads) | %.3f |\n", threads,
                timed([&] { winding = std::make_unique<ca::WindingNumber>(tree, 2.0, threads); }));
    std::vector<ca::Vec3> samples;
    std::printf("| surface sampling (1 500 + 4 000 + 4 000) | %.3f |\n", timed([&] {
        ca::sample_surface(mesh, d.candidates.cover_samples, 1);
        ca::sample_surface(mesh, d.candidates.connect_samples, 4);
        samples = ca::sample_surface(mesh, d.candidates.voronoi_samples, 2);
    }));
    std::vector<ca::Tet> tets;
    std::printf("| Delaunay of the 4 000 samples (Qhull) | %.3f |\n", timed([&] { ca::delaunay_tetrahedra(samples, tets, ca::Monitor{}, "delaunay"); }));
    // the circumcentres the candidate step tests: those within the samples' box
    std::vector<ca::Vec3> centres;
    const auto [lo, hi] = ca::bounding_box(samples);
    for (const ca::Tet& t : tets) {
        ca::Vec3 c;
        if (ca::circumcenter(samples[t[0]], samples[t[1]], samples[t[2]], samples[t[3]], c) &&
            (c.array() >= lo.array()).all() && (c.array() <= hi.array()).all())
            centres.push_back(c);
    }
    size_t inner = 0;
    const double t_inside = timed([&] {
        for (const ca::Vec3& c : centres) inner += winding->inside(c);
    });
    std::printf("| inside decisions (winding number) at %zu circumcentres (%zu inside) | %.3f |\n", centres.size(), inner, t_inside);
    return 0;
}

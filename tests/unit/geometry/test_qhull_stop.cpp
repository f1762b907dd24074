// test_qhull_stop.cpp: Qhull's build stops when the monitor says so: a run through QhullStream
// with a stop request ends after the first points instead of adding all of them, and the
// Delaunay and power-diagram wrappers then return the stop status with no cells; unasked they
// give what they give without a monitor.
#include "delaunay.h"
#include "qhull_stream.h"
#include "sampling.h"
#include "support/shapes.h"

#include <doctest/doctest.h>

extern "C" {
#include <libqhull_r/libqhull_r.h>
#include <libqhull_r/mem_r.h>
}

#include <atomic>
#include <memory>

using namespace ca;

namespace {

std::vector<Vec3> torus_samples(size_t n) {
    const std::vector<Vec3> raw = sample_surface(shapes::torus(1.0, 0.3, 96, 32), n, 11);
    std::vector<Vec3> pts;
    for (uint32_t i : remove_near_duplicates(raw, 1e-7)) pts.push_back(raw[i]);
    return pts;
}

// How many input points Qhull made vertices of, and whether the stream saw a stop.
std::pair<int, bool> vertices_built(const std::vector<Vec3>& pts, const Monitor& monitor) {
    std::vector<double> coords;
    for (const Vec3& p : pts) coords.insert(coords.end(), {p.x(), p.y(), p.z()});
    auto qh = std::make_unique<qhT>();
    QhullStream sink(qh.get(), monitor);
    qh_zero(qh.get(), sink.file());
    std::string cmd = std::string("qhull d QJ Qbb") + (sink.can_stop() ? QhullStream::option() : "");
    const int code = qh_new_qhull(qh.get(), 3, int(pts.size()), coords.data(), False, cmd.data(), nullptr, sink.file());
    const int vertices = code == 0 ? qh->num_vertices : -1;
    qh_freeqhull(qh.get(), !qh_ALL);
    int curlong = 0, totlong = 0;
    qh_memfreeshort(qh.get(), &curlong, &totlong);
    return {vertices, sink.stopped()};
}

}  // namespace

TEST_CASE("stop requests: Qhull's build stops at its next point") {
    const std::vector<Vec3> pts = torus_samples(20000);
    REQUIRE(pts.size() > 19000);
    std::atomic<int> flag{0};
    Monitor watched;
    watched.cancel_flag = &flag;
    const auto [all, seen] = vertices_built(pts, watched);
    CHECK(all == int(pts.size()));   // every sample is a Delaunay vertex
    CHECK_FALSE(seen);
    flag = 1;
    const auto [few, stopped] = vertices_built(pts, watched);
    CHECK(stopped);
    CHECK(few > 0);
    CHECK(few < 200);   // stopped at the first build report, not at the end
}

TEST_CASE("stop requests: the Delaunay and power-diagram wrappers return the stop status") {
    const std::vector<Vec3> pts = torus_samples(5000);
    std::atomic<int> flag{0};
    Monitor watched;
    watched.cancel_flag = &flag;
    std::vector<Tet> plain, tets;
    REQUIRE(delaunay_tetrahedra(pts, plain, Monitor{}, "delaunay").ok());
    REQUIRE(delaunay_tetrahedra(pts, tets, watched, "delaunay").ok());
    CHECK(tets == plain);   // the build reports change nothing
    flag = 1;
    const Status c = delaunay_tetrahedra(pts, tets, watched, "delaunay");
    CHECK(c.code == Code::cancelled);
    CHECK(c.message == "delaunay: cancelled");
    CHECK(tets.empty());
    Monitor spent;
    spent.deadline = Deadline::after(1e-12);
    const Status t = delaunay_tetrahedra(pts, tets, spent, "delaunay");
    CHECK(t.code == Code::time_limit);
    CHECK(t.message == "time limit reached in delaunay");

    std::vector<double> weights(pts.size(), 1e-4);
    std::vector<Tet> cells_plain, cells;
    flag = 0;
    REQUIRE(regular_triangulation(pts, weights, cells_plain, Monitor{}, "connect").ok());
    REQUIRE(regular_triangulation(pts, weights, cells, watched, "connect").ok());
    CHECK(cells == cells_plain);
    flag = 1;
    const Status p = regular_triangulation(pts, weights, cells, watched, "connect");
    CHECK(p.code == Code::cancelled);
    CHECK(p.message == "connect: cancelled");
    CHECK(cells.empty());
}

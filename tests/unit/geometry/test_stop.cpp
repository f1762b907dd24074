// test_stop.cpp: the surface structure builds and the sampling stop when asked (a cancel or the
// time limit during the candidate step): a stopped BVH is empty, a stopped winding tree answers
// 0, a stopped sampling says so; unasked, each gives what it gives without a stop request. The
// surface preparation (welding, duplicate merge) stops the same way.
#include "bvh.h"
#include "duplicates.h"
#include "surface.h"
#include "sampling.h"
#include "support/shapes.h"
#include "winding.h"

#include <doctest/doctest.h>

#include <atomic>

using namespace ca;

TEST_CASE("stop requests: BVH, winding tree and sampling stop within a few thousand items") {
    const Mesh m = shapes::torus(1.0, 0.3, 200, 100);   // 40 000 triangles
    REQUIRE(m.triangles.size() == 40000);
    int calls = 0;
    const std::function<bool()> never = [&] { return ++calls, false; };
    const auto full = detail::build_triangle_tree(m, 1, never);
    const auto plain = detail::build_triangle_tree(m);
    CHECK(calls >= 10);   // tested along the way
    CHECK(full->bvh.order == plain->bvh.order);
    CHECK(full->bvh.nodes.size() == plain->bvh.nodes.size());
    // stopped in the centroid pass, at the start of the recursion, and at its last test
    for (int after : {0, 12, calls / 2, calls - 1}) {
        int n = 0;
        const std::function<bool()> stop_after = [&] { return ++n > after; };
        const auto stopped = detail::build_triangle_tree(m, 1, stop_after);
        CHECK(stopped->bvh.nodes.empty());
        CHECK(stopped->tris.empty());
        CHECK(n == after + 1);   // no test after the one that said stop
    }
    // the corner copy after the BVH tests the stop too: stopped right after the BVH's last test
    int bvh_calls = 0;
    const std::function<bool()> count_bvh = [&] { return ++bvh_calls, false; };
    CHECK(detail::build_bvh(m, detail::valid_triangles(m), 8, 1, count_bvh).order == plain->bvh.order);
    CHECK(bvh_calls < calls);
    {
        int n = 0;
        const std::function<bool()> after_bvh = [&] { return ++n > bvh_calls; };
        const auto stopped = detail::build_triangle_tree(m, 1, after_bvh);
        CHECK(stopped->bvh.nodes.empty());
        CHECK(stopped->tris.empty());
        CHECK(n == bvh_calls + 1);
    }
    const Vec3 inside_tube(1.0, 0.0, 0.0);
    // the winding tree tests the stop before each kStopCheckItems-node chunk of its zero-filled
    // arrays, then along the expansion pass (every kStopCheckItems nodes and at every larger node)
    const auto& nodes = full->bvh.nodes;
    size_t expected = (nodes.size() + detail::kStopCheckItems - 1) / detail::kStopCheckItems;
    for (size_t i = 0; i < nodes.size(); ++i)
        expected += i % detail::kStopCheckItems == 0 || nodes[i].end - nodes[i].begin > detail::kStopCheckItems;
    calls = 0;
    CHECK(WindingNumber(full, 2.0, 1, never).inside(inside_tube));
    CHECK(size_t(calls) == expected);
    CHECK(WindingNumber(full, 2.0, 1, [] { return true; })(inside_tube) == 0.0);

    std::vector<Vec3> s;
    CHECK(sample_surface(m, 5000, 7, s, Monitor{}));
    CHECK(s == sample_surface(m, 5000, 7));
    std::atomic<int> flag{1};
    Monitor cancelled;
    cancelled.cancel_flag = &flag;
    CHECK_FALSE(sample_surface(m, 5000, 7, s, cancelled));
    Monitor spent;
    spent.deadline = Deadline::after(1e-12);
    CHECK_FALSE(sample_surface(m, 5000, 7, s, spent));
}

TEST_CASE("stop requests: welding, duplicate merge and surface preparation stop when asked") {
    Mesh m = shapes::torus(1.0, 0.3, 200, 100);
    m.triangles.push_back(m.triangles[0]);   // one repeat for the merge to drop
    std::atomic<int> flag{1};
    Monitor cancelled;
    cancelled.cancel_flag = &flag;
    Monitor spent;
    spent.deadline = Deadline::after(1e-12);

    CHECK(weld_map(m.vertices, Monitor{}).size() == m.vertices.size());
    CHECK(weld_map(m.vertices, cancelled).empty());
    CHECK(weld_map(m.vertices, spent).empty());

    Mesh merged = m, stopped = m;
    const MergeCounts full = merge_duplicate_geometry(merged, Monitor{});
    CHECK_FALSE(full.stopped);
    CHECK(full.duplicate == 1);
    CHECK(merged.triangles.size() == m.triangles.size() - 1);
    const MergeCounts none = merge_duplicate_geometry(stopped, cancelled);
    CHECK(none.stopped);
    CHECK(stopped.triangles == m.triangles);   // left as it was

    Surface s;
    CHECK(prepare_surface(m, {}, s, true, PointNormals::trusted, Monitor{}).ok());
    CHECK(s.duplicate_triangles == 1);
    const Status c = prepare_surface(m, {}, s, true, PointNormals::trusted, cancelled);
    CHECK(c.code == Code::cancelled);
    CHECK(c.message == "surface: cancelled");
    const Status t = prepare_surface(m, {}, s, true, PointNormals::trusted, spent);
    CHECK(t.code == Code::time_limit);
    CHECK(t.message == "time limit reached in surface");
}

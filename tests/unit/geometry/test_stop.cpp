// test_stop.cpp: the surface structure builds and the sampling stop when asked (a cancel or the
// time limit during the candidate step): a stopped BVH is empty, a stopped winding tree answers
// 0, a stopped sampling says so; unasked, each gives what it gives without a stop request.
#include "bvh.h"
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
    const Vec3 inside_tube(1.0, 0.0, 0.0);
    CHECK(WindingNumber(full, 2.0, 1, never).inside(inside_tube));
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

// test_correspondence.cpp: the per-vertex correspondence (lib/correspond): weights that sum to 1
// over at most four balls, a nearest primitive that a brute-force scan of every primitive agrees
// with, weights that change continuously along every mesh edge (where nearest-ball labels jump),
// the same result on any number of threads, and bad input refused.
#include <doctest/doctest.h>

#include "correspondence.h"
#include "evaluate.h"
#include "support/skeleton_of.h"

#include <cmath>
#include <limits>

namespace {

const ca::Skeleton& fox_skeleton() {
    static const ca::Skeleton s = skeleton_of(test_model("fox.obj"));
    return s;
}

// The points along every mesh edge, `steps` + 1 per edge (ends included), edge after edge.
std::vector<ca::Vec3> edge_walks(const ca::Mesh& m, int steps) {
    std::vector<ca::Vec3> out;
    for (const ca::Tri& t : m.triangles)
        for (int k = 0; k < 3; ++k) {
            const ca::Vec3 a = m.vertices[t[k]], b = m.vertices[t[(k + 1) % 3]];
            for (int i = 0; i <= steps; ++i) out.push_back(a + (b - a) * (double(i) / steps));
        }
    return out;
}

// The L1 distance between two points' weight vectors (as sparse maps over balls).
double l1(const std::array<uint32_t, 4>& ba, const std::array<double, 4>& wa, const std::array<uint32_t, 4>& bb,
          const std::array<double, 4>& wb) {
    std::vector<std::pair<uint32_t, double>> d;
    for (int k = 0; k < 4; ++k) {
        d.emplace_back(ba[k], wa[k]);
        d.emplace_back(bb[k], -wb[k]);
    }
    std::sort(d.begin(), d.end());
    double total = 0, run = 0;
    for (size_t i = 0; i < d.size(); ++i) {
        run += d[i].second;
        if (i + 1 == d.size() || d[i + 1].first != d[i].first) {
            total += std::abs(run);
            run = 0;
        }
    }
    return total;
}

}  // namespace

TEST_CASE("correspondence: the fox's vertices get at most four balls, weights summing to 1, and the nearest primitive") {
    const ca::Mesh fox = test_model("fox.obj");
    const ca::Skeleton& s = fox_skeleton();
    ca::Correspondence c;
    REQUIRE(ca::correspond(fox.vertices, s, {}, ca::Monitor{}, c).ok());
    REQUIRE(c.balls.size() == fox.vertices.size());
    for (size_t i = 0; i < fox.vertices.size(); ++i) {
        double sum = 0;
        for (int k = 0; k < ca::kInfluences; ++k) {
            CHECK(c.balls[i][k] < s.balls.size());
            CHECK(c.weights[i][k] >= 0);
            if (k > 0) CHECK(c.weights[i][k] <= c.weights[i][k - 1]);
            sum += c.weights[i][k];
        }
        CHECK(std::abs(sum - 1) < 1e-12);
        // brute force: the distance to every edge's cone, every face's slab, every ball
        const ca::Vec3& p = fox.vertices[i];
        double best = std::numeric_limits<double>::infinity();
        for (const ca::Ball& b : s.balls) best = std::min(best, ca::sd_sphere(p, b.center, b.radius));
        for (const auto& e : s.edges)
            best = std::min(best, ca::sd_cone(p, s.balls[e[0]].center, s.balls[e[0]].radius, s.balls[e[1]].center,
                                              s.balls[e[1]].radius));
        for (const ca::Tri& f : s.faces)
            best = std::min(best, ca::sd_slab(p, s.balls[f[0]].center, s.balls[f[0]].radius, s.balls[f[1]].center,
                                              s.balls[f[1]].radius, s.balls[f[2]].center, s.balls[f[2]].radius));
        double found = 0;
        const uint32_t j = c.nearest_index[i];
        switch (c.nearest_kind[i]) {
            case ca::NearestKind::ball: found = ca::sd_sphere(p, s.balls[j].center, s.balls[j].radius); break;
            case ca::NearestKind::edge:
                found = ca::sd_cone(p, s.balls[s.edges[j][0]].center, s.balls[s.edges[j][0]].radius,
                                    s.balls[s.edges[j][1]].center, s.balls[s.edges[j][1]].radius);
                break;
            case ca::NearestKind::face: {
                const ca::Tri& f = s.faces[j];
                found = ca::sd_slab(p, s.balls[f[0]].center, s.balls[f[0]].radius, s.balls[f[1]].center,
                                    s.balls[f[1]].radius, s.balls[f[2]].center, s.balls[f[2]].radius);
                break;
            }
        }
        CHECK(found <= best + 1e-9 * (1 + std::abs(best)));
    }
}

TEST_CASE("correspondence: weights change continuously along every mesh edge, where nearest-ball labels jump") {
    const ca::Mesh fox = test_model("fox.obj");
    const ca::Skeleton& s = fox_skeleton();
    const int steps = 64;
    const std::vector<ca::Vec3> walk = edge_walks(fox, steps);
    ca::Correspondence c;
    REQUIRE(ca::correspond(walk, s, {}, ca::Monitor{}, c).ok());
    // the largest change between neighbouring points of a walk, of the weights and of a hard label
    // (all weight on the nearest ball by |p - c| - r)
    double soft = 0, hard = 0;
    auto nearest_ball = [&](const ca::Vec3& p) {
        uint32_t best = 0;
        for (uint32_t b = 1; b < s.balls.size(); ++b)
            if ((p - s.balls[b].center).norm() - s.balls[b].radius <
                (p - s.balls[best].center).norm() - s.balls[best].radius)
                best = b;
        return best;
    };
    for (size_t e = 0; e < walk.size(); e += steps + 1) {
        uint32_t label = nearest_ball(walk[e]);
        for (int i = 1; i <= steps; ++i) {
            const size_t a = e + size_t(i) - 1, b = e + size_t(i);
            soft = std::max(soft, l1(c.balls[a], c.weights[a], c.balls[b], c.weights[b]));
            const uint32_t next = nearest_ball(walk[b]);
            if (next != label) hard = 2;
            label = next;
        }
    }
    // a step is 1/64 of an edge: continuous weights move less than a quarter of a jump; hard labels jump by 2
    MESSAGE("largest weight change over 1/64 of a fox edge: " << soft);
    CHECK(hard == 2);
    CHECK(soft < 0.5);

    // twice as fine a walk: the largest step shrinks (continuity), unlike a jump
    const std::vector<ca::Vec3> fine = edge_walks(fox, 2 * steps);
    ca::Correspondence f;
    REQUIRE(ca::correspond(fine, s, {}, ca::Monitor{}, f).ok());
    double soft_fine = 0;
    for (size_t e = 0; e < fine.size(); e += 2 * steps + 1)
        for (int i = 1; i <= 2 * steps; ++i)
            soft_fine = std::max(soft_fine, l1(f.balls[e + i - 1], f.weights[e + i - 1], f.balls[e + i], f.weights[e + i]));
    CHECK(soft_fine < 0.75 * soft);
}

TEST_CASE("correspondence: the same weights on one thread and on several") {
    const ca::Mesh fox = test_model("fox.obj");
    ca::CorrespondOptions one, many;
    one.threads = 1;
    many.threads = 3;
    ca::Correspondence a, b;
    REQUIRE(ca::correspond(fox.vertices, fox_skeleton(), one, ca::Monitor{}, a).ok());
    REQUIRE(ca::correspond(fox.vertices, fox_skeleton(), many, ca::Monitor{}, b).ok());
    CHECK(a.balls == b.balls);
    CHECK(a.weights == b.weights);
    CHECK(a.nearest_index == b.nearest_index);
}

TEST_CASE("correspondence: top_weights leaves the top four at weight 0 when a fifth overtakes") {
    std::array<uint32_t, 4> idx;
    std::array<double, 4> w;
    ca::top_weights({{0, 0.3}, {1, 0.25}, {2, 0.2}, {3, 0.15}, {4, 0.1}}, idx, w);
    CHECK(idx == std::array<uint32_t, 4>{0, 1, 2, 3});
    CHECK(w[3] == doctest::Approx(0.05 / 0.5));   // (0.15 - 0.1) / (0.2 + 0.15 + 0.1 + 0.05)
    ca::top_weights({{0, 0.3}, {1, 0.25}, {2, 0.2}, {3, 0.125}, {4, 0.125}}, idx, w);
    CHECK(w[3] == 0);
    ca::top_weights({{7, 1.0}}, idx, w);
    CHECK(idx == std::array<uint32_t, 4>{7, 7, 7, 7});
    CHECK(w == std::array<double, 4>{1, 0, 0, 0});
}

TEST_CASE("correspondence: bad points, skeletons and options are refused with a status") {
    ca::Skeleton s;
    s.balls = {{ca::Vec3(0, 0, 0), 1.0}, {ca::Vec3(2, 0, 0), 1.0}};
    s.edges = {{0, 1}};
    const std::vector<ca::Vec3> pts{{0, 1, 0}, {1, 1, 0}};
    ca::Correspondence c;
    REQUIRE(ca::correspond(pts, s, {}, ca::Monitor{}, c).ok());
    // halfway along the edge: half each end
    CHECK(c.weights[1][0] == doctest::Approx(0.5));
    CHECK(c.nearest_kind[1] == ca::NearestKind::edge);
    CHECK(ca::correspond({{std::nan(""), 0, 0}}, s, {}, ca::Monitor{}, c).code == ca::Code::invalid_input);
    CHECK(c.balls.empty());
    CHECK(ca::correspond({}, s, {}, ca::Monitor{}, c).code == ca::Code::degenerate_input);
    ca::Skeleton bad = s;
    bad.edges = {{0, 2}};
    CHECK(ca::correspond(pts, bad, {}, ca::Monitor{}, c).code == ca::Code::invalid_input);
    bad = s;
    bad.balls[1].radius = -1;
    CHECK(ca::correspond(pts, bad, {}, ca::Monitor{}, c).code == ca::Code::invalid_input);
    CHECK(ca::correspond(pts, ca::Skeleton{}, {}, ca::Monitor{}, c).code == ca::Code::degenerate_input);
    ca::CorrespondOptions o;
    o.smoothing = 0;
    CHECK(ca::correspond(pts, s, o, ca::Monitor{}, c).code == ca::Code::invalid_argument);
}

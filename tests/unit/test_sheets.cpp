// test_sheets.cpp: surfaces with no inside get skeletons (candidates/surface_balls.cpp,
// connect/sheet_route.cpp). Known answers: the medial surface of a zero-thickness sheet is the
// sheet itself, so a single-sided square's balls lie on it, cover it, and span it with a patch
// of triangles; a flat disc and a nearly flat box give skeletons; a card glued to a box and a
// closed body with a single-sided ear are covered, in one component.
#include <doctest/doctest.h>

#include "candidates.h"
#include "connect.h"
#include "coverage.h"
#include "selection.h"
#include "support/shapes.h"

#include <cmath>

namespace {

struct Run {
    ca::CandidateSet set;
    ca::Selection sel;
    ca::Skeleton skeleton;   // internal (unit-cube) units
    ca::ConnectReport report;
};

ca::Status run(ca::Mesh mesh, Run& r, ca::CandidateOptions copt = {}) {
    ca::SelectOptions sopt;
    sopt.cover.time_limit_s = 0;
    ca::Surface surface;
    ca::Status st = ca::prepare_surface(std::move(mesh), {}, surface);
    if (!st.ok()) return st;
    const ca::Monitor monitor;
    st = ca::generate_candidates(std::move(surface), copt, monitor, r.set);
    if (!st.ok()) return st;
    st = ca::select_balls(r.set, sopt, monitor, r.sel);
    if (!st.ok()) return st;
    ca::ConnectOptions power;   // the route these checks measure
    power.method = ca::ConnectMethod::power;
    return ca::connect_balls(r.set, r.sel, power, monitor, r.skeleton, &r.report);
}

// Every cover sample lies within the dilated radius of a selected ball (brute force).
size_t uncovered(const Run& r) {
    size_t n = 0;
    for (const ca::Vec3& s : r.set.cover_samples) {
        bool hit = false;
        for (size_t i = 0; i < r.sel.indices.size() && !hit; ++i)
            hit = ca::covers(r.set.balls[r.sel.indices[i]].center, r.sel.dilated_radii[i], s);
        n += !hit;
    }
    return n;
}

// A grid sheet over [0, 1]^2 (n x n quads) lifted by z(x, y), single-sided: one triangle layer.
ca::Mesh sheet(int n, double (*z)(double, double)) {
    ca::Mesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const double x = double(i) / n, y = double(j) / n;
            m.vertices.push_back({x, y, z(x, y)});
        }
    auto v = [n](int i, int j) { return uint32_t(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            m.triangles.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
            m.triangles.push_back({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
        }
    return m;
}

double bowed(double x, double) { return 0.15 * (x - 0.5) * (x - 0.5); }
double level(double, double) { return 0; }

// Distance from p to triangle abc (closest point by region tests; independent of the library).
double point_triangle(const ca::Vec3& p, const ca::Vec3& a, const ca::Vec3& b, const ca::Vec3& c) {
    const ca::Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return (p - a).norm();
    const ca::Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return (p - b).norm();
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + ab * (d1 / (d1 - d3)))).norm();
    const ca::Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return (p - c).norm();
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + ac * (d2 / (d2 - d6)))).norm();
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return (p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))))).norm();
    const double denom = 1 / (va + vb + vc);
    return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

// The largest distance from the points of an inner grid of the sheet to the skeleton's triangles.
double patch_gap(const Run& r, double (*z)(double, double), double margin) {
    double worst = 0;
    for (int j = 0; j <= 20; ++j)
        for (int i = 0; i <= 20; ++i) {
            const double x = margin + (1 - 2 * margin) * i / 20, y = margin + (1 - 2 * margin) * j / 20;
            const ca::Vec3 p = r.set.surface.norm.to_internal({x, y, z(x, y)});
            double best = 1e9;
            for (const ca::Tri& f : r.skeleton.faces)
                best = std::min(best, point_triangle(p, r.skeleton.balls[f[0]].center, r.skeleton.balls[f[1]].center,
                                                     r.skeleton.balls[f[2]].center));
            worst = std::max(worst, best);
        }
    return worst;
}

}  // namespace

TEST_CASE("single-sided sheet: surface balls on the sheet cover it and a triangle patch spans it") {
    // flat: nothing but surface balls, points of the sheet. Bowed: the sheet and its hole cap
    // enclose a thin lens, so inner balls may serve too, but every ball stays at the sheet.
    for (auto z : {level, bowed}) {
        Run r;
        const ca::Status st = run(sheet(12, z), r);
        REQUIRE_MESSAGE(st.ok(), st.message);
        const bool flat = z == level;
        CHECK(r.set.surface.flat == flat);
        CHECK(uncovered(r) == 0);
        REQUIRE(r.skeleton.balls.size() > 3);
        if (flat) CHECK(r.report.surface_balls == r.skeleton.balls.size());
        CHECK(r.report.open_parts == 1);
        for (const ca::Ball& b : r.skeleton.balls) {
            const ca::Vec3 p = r.set.surface.norm.to_user(b.center);
            CHECK(std::abs(p.z() - z(p.x(), p.y())) <= (flat ? 1e-9 : 0.02));   // on the sheet
            CHECK(b.radius <= (flat ? 0.0 : 0.02));                            // single-sided: no thickness
        }
        const ca::TopologyStats topo = ca::topology(r.skeleton);
        CHECK(topo.components == 1);
        CHECK(r.skeleton.faces.size() >= r.skeleton.balls.size());
        // every point of the sheet away from its border is near the patch (delta = 0.02: the balls
        // are about that far apart)
        CHECK(patch_gap(r, z, 0.05) < 0.03);
    }
}

TEST_CASE("volumetric-only: a sheet has no candidates, as the paper's method has it") {
    Run r;
    ca::CandidateOptions copt;
    copt.volumetric_only = true;
    const ca::Status st = run(sheet(8, level), r, copt);
    CHECK(!st.ok());
    CHECK((st.code == ca::Code::no_candidates || st.code == ca::Code::uncoverable));
}

TEST_CASE("flat disc: a skeleton of surface balls, no Delaunay step") {
    ca::Mesh disc;
    disc.vertices.push_back({0, 0, 0});
    const int n = 64;
    for (int k = 0; k < n; ++k) disc.vertices.push_back({2 * std::cos(2 * M_PI * k / n), 2 * std::sin(2 * M_PI * k / n), 0});
    for (int k = 0; k < n; ++k) disc.triangles.push_back({0, uint32_t(1 + k), uint32_t(1 + (k + 1) % n)});
    Run r;
    const ca::Status st = run(disc, r);
    REQUIRE_MESSAGE(st.ok(), st.message);
    CHECK(r.set.surface.flat);
    CHECK(r.set.voronoi_tets.empty());
    CHECK(r.set.surface_balls == r.set.balls.size());
    CHECK(uncovered(r) == 0);
    CHECK(r.skeleton.faces.size() > 0);
    CHECK(ca::topology(r.skeleton).components == 1);
}

TEST_CASE("nearly flat box: a skeleton, whatever Qhull makes of its samples") {
    Run r;
    const ca::Status st = run(shapes::box(1, 1, 1e-9), r);
    REQUIRE_MESSAGE(st.ok(), st.message);
    CHECK(uncovered(r) == 0);
    CHECK(r.skeleton.balls.size() > 0);
}

TEST_CASE("a card glued to a closed box: covered, one component") {
    // the card: a vertical quad standing on the box's top face (z = 1), single-sided
    ca::Mesh card;
    card.vertices = {{0.5, 0.2, 1.0}, {0.5, 0.8, 1.0}, {0.5, 0.8, 1.6}, {0.5, 0.2, 1.6}};
    card.triangles = {{0, 1, 2}, {0, 2, 3}};
    Run r;
    const ca::Status st = run(shapes::merged(shapes::box(1, 1, 1), card), r);
    REQUIRE_MESSAGE(st.ok(), st.message);
    CHECK(r.set.surface_balls > 0);
    CHECK(uncovered(r) == 0);
    CHECK(r.report.surface_balls > 0);
    CHECK(r.report.surface_balls < r.skeleton.balls.size());   // the box keeps its medial balls
    CHECK(r.report.open_parts == 1);
    CHECK(ca::topology(r.skeleton).components == 1);
}

TEST_CASE("a closed body with a single-sided ear: every sample covered") {
    // the ear: a fan of triangles leaving the sphere's surface, one layer thick
    ca::Mesh ear;
    ear.vertices = {{0, -0.3, 0.95}, {0, 0.3, 0.95}, {0, 0.0, 1.9}, {0, -0.25, 1.6}, {0, 0.25, 1.6}};
    ear.triangles = {{0, 1, 4}, {0, 4, 3}, {3, 4, 2}};
    Run r;
    const ca::Status st = run(shapes::merged(shapes::sphere(1.0, 24, 48), ear), r);
    REQUIRE_MESSAGE(st.ok(), st.message);
    CHECK(uncovered(r) == 0);
    CHECK(ca::topology(r.skeleton).components == 1);
}

TEST_CASE("a closed shape gets no surface balls") {
    Run r;
    const ca::Status st = run(shapes::capsule(1.0, 0.4, 32, 32), r);
    REQUIRE_MESSAGE(st.ok(), st.message);
    CHECK(r.set.surface_balls == 0);
    CHECK(r.report.surface_balls == 0);
    CHECK(r.report.open_parts == 0);
}

TEST_CASE("a card modelled as two sheets a hair apart: surface balls midway, half the gap as radius") {
    // both layers face the same way, so the winding number calls the gap outside (the half-space on
    // one side of the stack counts as inside and gets inner balls): the samples of the gap's sides
    // get surface balls by the thin-part rule, which finds the opposite layer along the normal line
    const double gap = 0.004;   // 0.4 % of the longest side, under the thin-part limit of 1 %
    ca::Mesh upper = sheet(6, level);
    for (ca::Vec3& v : upper.vertices) v.z() = gap;
    Run r;
    const ca::Status st = run(shapes::merged(sheet(6, level), upper), r);
    REQUIRE_MESSAGE(st.ok(), st.message);
    CHECK(!r.set.surface.flat);
    CHECK(uncovered(r) == 0);
    REQUIRE(r.set.surface_balls > 0);
    size_t midway = 0;
    for (size_t i = r.set.balls.size() - r.set.surface_balls; i < r.set.balls.size(); ++i) {
        const ca::Ball& b = r.set.balls[i];
        const ca::Vec3 p = r.set.surface.norm.to_user(b.center);
        const double radius = b.radius * r.set.surface.norm.scale;
        midway += std::abs(p.z() - gap / 2) < 1e-3 * gap && std::abs(radius - gap / 2) < 0.05 * gap;
    }
    // interior samples see the other layer straight across; near the border the distance may
    // reach round the edge
    CHECK(midway >= 0.8 * double(r.set.surface_balls));
}

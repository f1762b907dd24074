// test_evaluate.cpp: exact primitive distances (sphere, medial cone, medial slab) against a
// brute-force minimisation over the simplex, and Hausdorff distances with known answers.
#include <doctest/doctest.h>

#include "evaluate.h"
#include "rng.h"
#include "support/shapes.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

using namespace ca;

namespace {

Vec3 random_vec(Rng& rng, double s) {
    return Vec3(2 * rng.uniform() - 1, 2 * rng.uniform() - 1, 2 * rng.uniform() - 1) * s;
}

// min over a grid of t in [0,1] of |p - c(t)| - r(t)
double brute_cone(const Vec3& p, const Vec3& c1, double r1, const Vec3& c2, double r2, int n) {
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= n; ++i) {
        const double t = double(i) / n;
        best = std::min(best, (p - ((1 - t) * c1 + t * c2)).norm() - ((1 - t) * r1 + t * r2));
    }
    return best;
}

// min over a barycentric grid of the triangle
double brute_slab(const Vec3& p, const Vec3& c1, double r1, const Vec3& c2, double r2,
                  const Vec3& c3, double r3, int n) {
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
            const double a = double(i) / n, b = double(j) / n, c = 1 - a - b;
            const Vec3 cc = a * c1 + b * c2 + c * c3;
            best = std::min(best, (p - cc).norm() - (a * r1 + b * r2 + c * r3));
        }
    return best;
}

Skeleton one_ball(double r) {
    Skeleton s;
    s.balls.push_back({Vec3::Zero(), r});
    return s;
}

// largest distance between the icosphere's faces and the sphere it approximates
double sagitta(const Mesh& m, double R) {
    double worst = 0;
    for (const Tri& t : m.triangles) {
        const Vec3 c = (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3.0;
        worst = std::max(worst, R - c.norm());
    }
    return worst;
}

}  // namespace

TEST_CASE("sd_sphere") {
    CHECK(sd_sphere(Vec3(3, 0, 0), Vec3::Zero(), 1) == doctest::Approx(2));
    CHECK(sd_sphere(Vec3(0.5, 0, 0), Vec3::Zero(), 1) == doctest::Approx(-0.5));
}

TEST_CASE("sd_cone matches brute force over t") {
    Rng rng(7);
    const int n = 4000;
    for (int k = 0; k < 400; ++k) {
        Vec3 c1 = random_vec(rng, 1), c2 = random_vec(rng, 1);
        double r1 = 0.6 * rng.uniform(), r2 = 0.6 * rng.uniform();
        const int kind = k % 4;
        if (kind == 1) {   // one ball contains the other
            r1 = 0.5 + 0.5 * rng.uniform();
            c2 = c1 + random_vec(rng, 0.2);
            r2 = 0.1 * rng.uniform();
        }
        if (kind == 3) c2 = c1;   // coincident centres
        Vec3 p = random_vec(rng, 2);
        if (kind == 2) {   // inside the cone
            const double t = rng.uniform();
            p = (1 - t) * c1 + t * c2 + random_vec(rng, 0.3 * ((1 - t) * r1 + t * r2));
        }
        const double exact = sd_cone(p, c1, r1, c2, r2);
        const double brute = brute_cone(p, c1, r1, c2, r2, n);
        const double step = ((c2 - c1).norm() + std::abs(r2 - r1)) / n;
        INFO("case " << k);
        CHECK(exact <= brute + 1e-12);
        CHECK(exact >= brute - step - 1e-12);
    }
}

TEST_CASE("sd_slab matches brute force over barycentric coordinates") {
    Rng rng(11);
    const int n = 150;
    for (int k = 0; k < 300; ++k) {
        Vec3 c1 = random_vec(rng, 1), c2 = random_vec(rng, 1), c3 = random_vec(rng, 1);
        double r1 = 0.5 * rng.uniform(), r2 = 0.5 * rng.uniform(), r3 = 0.5 * rng.uniform();
        const int kind = k % 5;
        if (kind == 1) {   // near-collinear centres
            c3 = c1 + rng.uniform() * (c2 - c1) + random_vec(rng, 1e-7);
        } else if (kind == 2) {   // one ball swallows the others (no tangent plane)
            r1 = 1.5 + rng.uniform();
            c2 = c1 + random_vec(rng, 0.3);
            c3 = c1 + random_vec(rng, 0.3);
        } else if (kind == 4) {   // exactly collinear
            c3 = 0.5 * (c1 + c2);
        }
        Vec3 p = random_vec(rng, 2);
        if (kind == 3) {   // inside the slab
            double a = rng.uniform(), b = rng.uniform();
            if (a + b > 1) { a = 1 - a; b = 1 - b; }
            const double c = 1 - a - b;
            p = a * c1 + b * c2 + c * c3 + random_vec(rng, 0.3 * (a * r1 + b * r2 + c * r3));
        }
        const double exact = sd_slab(p, c1, r1, c2, r2, c3, r3);
        const double brute = brute_slab(p, c1, r1, c2, r2, c3, r3, n);
        const double lip = std::max({(c1 - c3).norm() + std::abs(r1 - r3),
                                     (c2 - c3).norm() + std::abs(r2 - r3),
                                     (c1 - c2).norm() + std::abs(r1 - r2)});
        const double step = 2 * lip / n;
        INFO("case " << k << " kind " << kind);
        CHECK(exact <= brute + 1e-9);
        CHECK(exact >= brute - step - 1e-12);
        // the slab contains its edge cones
        CHECK(exact <= sd_cone(p, c1, r1, c2, r2) + 1e-12);
        CHECK(exact <= sd_cone(p, c2, r2, c3, r3) + 1e-12);
    }
}

TEST_CASE("the attaining sphere gives the same distance and its derivatives") {
    // The value with NearestSphere is the one without; -w[i] u and -w[i] are the derivatives
    // with respect to ball i's centre and radius (checked by central differences where smooth).
    Rng rng(19);
    int compared = 0;
    for (int k = 0; k < 400; ++k) {
        Vec3 c[3] = {random_vec(rng, 1), random_vec(rng, 1), random_vec(rng, 1)};
        double r[3] = {0.5 * rng.uniform(), 0.5 * rng.uniform(), 0.5 * rng.uniform()};
        const bool slab = k % 2 == 0;
        if (k % 8 == 1) {   // one ball swallows the other: the cone is a sphere
            r[0] = 1.5;
            c[1] = c[0] + random_vec(rng, 0.3);
        }
        const int nb = slab ? 3 : 2;
        const Vec3 p = random_vec(rng, 2);
        auto sd = [&](NearestSphere* at) {
            return slab ? sd_slab(p, c[0], r[0], c[1], r[1], c[2], r[2], at) : sd_cone(p, c[0], r[0], c[1], r[1], at);
        };
        NearestSphere at;
        const double d = sd(&at);
        INFO("case " << k);
        CHECK(d == sd(nullptr));
        double wsum = 0;
        for (int i = 0; i < nb; ++i) wsum += at.w[i];
        CHECK(wsum == doctest::Approx(1));
        CHECK(at.u.norm() == doctest::Approx(1));
        const double h = 1e-6;
        for (int i = 0; i < nb; ++i) {
            for (int j = 0; j < 4; ++j) {
                double* x = j < 3 ? &c[i][j] : &r[i];
                const double x0 = *x;
                *x = x0 + h;
                const double up = sd(nullptr);
                *x = x0 - h;
                const double down = sd(nullptr);
                *x = x0;
                const double fd = (up - down) / (2 * h);
                if (std::abs((up - d) - (d - down)) > 1e-9) continue;   // a kink: not smooth here
                const double analytic = j < 3 ? -at.w[i] * at.u[j] : -at.w[i];
                CHECK(std::abs(analytic - fd) < 1e-5);
                ++compared;
            }
        }
    }
    CHECK(compared > 2000);
}

TEST_CASE("sd_slab of equal radii is the distance to a thick triangle") {
    const Vec3 c1(0, 0, 0), c2(1, 0, 0), c3(0, 1, 0);
    CHECK(sd_slab(Vec3(0.2, 0.2, 1), c1, 0.1, c2, 0.1, c3, 0.1) == doctest::Approx(0.9));
    CHECK(sd_slab(Vec3(0.2, 0.2, -1), c1, 0.1, c2, 0.1, c3, 0.1) == doctest::Approx(0.9));
    CHECK(sd_slab(Vec3(0.2, 0.2, 0.05), c1, 0.1, c2, 0.1, c3, 0.1) == doctest::Approx(-0.05));
    CHECK(sd_slab(Vec3(-1, 0, 0), c1, 0.1, c2, 0.1, c3, 0.1) == doctest::Approx(0.9));
}

TEST_CASE("evaluate: one ball against a sphere mesh of the same radius") {
    const Mesh sphere = shapes::icosphere(1.0, 3);
    const double sag = sagitta(sphere, 1.0);
    EvaluateOptions opt;
    opt.surface_samples = 5000;
    opt.envelope_samples = 30000;
    EvaluateResult r;
    REQUIRE(evaluate(sphere, one_ball(1.0), opt, Monitor{}, r).ok());
    const double diag = r.diagonal;
    CHECK(r.envelope_samples_used >= 30000);
    CHECK(r.surface_samples_used == 5000 + sphere.vertices.size());
    // E -> S is exact per sample: at most the triangulation error
    CHECK(r.hd_recon_to_surface * diag / 100 <= sag * 1.01 + 1e-12);
    // S -> E: the mesh is inside the ball; the nearest boundary point is the radial projection
    // (found exactly through the closest point on the sphere piece), at most the sagitta
    CHECK(r.hd_surface_to_recon * diag / 100 <= sag + 1e-9);
    CHECK(r.hd_two_sided == std::max(r.hd_surface_to_recon, r.hd_recon_to_surface));
    CHECK(r.mean_surface_to_recon <= r.hd_surface_to_recon);
}

TEST_CASE("evaluate: ball of radius r against a sphere mesh of radius R") {
    const double R = 1.0;
    const Mesh sphere = shapes::icosphere(R, 3);
    const double sag = sagitta(sphere, R);
    EvaluateOptions opt;
    opt.surface_samples = 5000;
    opt.envelope_samples = 20000;
    for (double r : {0.7, 1.25}) {
        EvaluateResult res;
        REQUIRE(evaluate(sphere, one_ball(r), opt, Monitor{}, res).ok());
        const double d = res.diagonal / 100;
        INFO("r = " << r);
        CHECK(std::abs(res.hd_recon_to_surface * d - std::abs(R - r)) <= sag + 1e-9);
        if (r < R) {   // surface outside the ball: F is exact
            CHECK(res.hd_surface_to_recon * d == doctest::Approx(R - r).epsilon(1e-9));
            CHECK(res.mean_surface_to_recon * d <= R - r + 1e-9);
            CHECK(res.mean_surface_to_recon * d >= R - r - sag);
        } else {       // surface inside: distance to the sphere, r - |p|
            CHECK(res.hd_surface_to_recon * d >= r - R - 1e-9);
            CHECK(res.hd_surface_to_recon * d <= r - R + sag + 1e-9);
        }
    }
}

TEST_CASE("evaluate: capsule skeleton, point cloud input, determinism") {
    // the surface of a capsule of radius 0.5 around the segment (0,0,0)-(2,0,0), as points
    Mesh cloud;
    Rng rng(3);
    for (int i = 0; i < 4000; ++i) {
        const Vec3 d = random_vec(rng, 1).normalized();
        const double t = 2 * rng.uniform();
        const Vec3 radial = Vec3(0, d.y(), d.z()).normalized();
        cloud.vertices.push_back(i % 2 ? Vec3(t, 0, 0) + 0.5 * radial
                                       : (d.x() < 0 ? Vec3::Zero() : Vec3(2, 0, 0)) + 0.5 * d);
    }
    Skeleton s;
    s.balls = {{Vec3(0, 0, 0), 0.5}, {Vec3(1, 0, 0), 0.5}, {Vec3(2, 0, 0), 0.5}};
    s.edges = {{0, 1}, {1, 2}};
    EvaluateOptions opt;
    opt.envelope_samples = 20000;
    EvaluateResult a, b;
    REQUIRE(evaluate(cloud, s, opt, Monitor{}, a).ok());
    CHECK(a.surface_samples_used == cloud.vertices.size());
    CHECK(a.hd_surface_to_recon < 1e-6);   // every point is on the capsule
    CHECK(a.hd_recon_to_surface < 5.0);    // the capsule is near some input point
    REQUIRE(evaluate(cloud, s, opt, Monitor{}, b).ok());
    CHECK(a.hd_surface_to_recon == b.hd_surface_to_recon);
    CHECK(a.hd_recon_to_surface == b.hd_recon_to_surface);
    CHECK(a.mean_recon_to_surface == b.mean_recon_to_surface);
    CHECK(a.envelope_samples_used == b.envelope_samples_used);
}

TEST_CASE("evaluate: a slab skeleton agrees with itself as a mesh of its tangent triangles") {
    // a thin slab of equal radii: its envelope boundary contains the two offset triangles
    Skeleton s;
    s.balls = {{Vec3(0, 0, 0), 0.1}, {Vec3(1, 0, 0), 0.1}, {Vec3(0, 1, 0), 0.1}};
    s.faces = {{0, 1, 2}};
    Mesh m;
    m.vertices = {{0, 0, 0.1}, {1, 0, 0.1}, {0, 1, 0.1}, {0, 0, -0.1}, {1, 0, -0.1}, {0, 1, -0.1}};
    m.triangles = {{0, 1, 2}, {3, 5, 4}};
    EvaluateOptions opt;
    opt.envelope_samples = 20000;
    opt.surface_samples = 5000;
    EvaluateResult r;
    REQUIRE(evaluate(m, s, opt, Monitor{}, r).ok());
    CHECK(r.hd_surface_to_recon * r.diagonal / 100 < 1e-9);   // on the boundary: F = 0
    // the farthest boundary point is on a corner cap, e.g. (-0.1, 0, 0) -> corner (0, 0, 0.1)
    CHECK(r.hd_recon_to_surface * r.diagonal / 100 == doctest::Approx(0.1 * std::sqrt(2.0)).epsilon(0.01));
}

TEST_CASE("evaluate: a mesh inside a capsule (distances from inside points)") {
    Mesh inner = shapes::icosphere(0.3, 3);
    const double sag = sagitta(inner, 0.3);
    for (auto& v : inner.vertices) v += Vec3(1, 0, 0);
    Skeleton s;
    s.balls = {{Vec3(0, 0, 0), 0.5}, {Vec3(2, 0, 0), 0.5}};
    s.edges = {{0, 1}};
    EvaluateOptions opt;
    opt.surface_samples = 3000;
    opt.envelope_samples = 20000;
    EvaluateResult r;
    REQUIRE(evaluate(inner, s, opt, Monitor{}, r).ok());
    const double d = r.diagonal / 100;
    // every input point is inside the cylinder part: its distance to the boundary is
    // 0.5 - radial distance; the vertices are among the samples
    double worst_vertex = 0;
    for (const Vec3& v : inner.vertices)
        worst_vertex = std::max(worst_vertex, 0.5 - std::hypot(v.y(), v.z()));
    CHECK(r.hd_surface_to_recon * d >= worst_vertex - 1e-9);
    CHECK(r.hd_surface_to_recon * d <= 0.5 + 1e-9);
    // the farthest boundary points are the cap tips, 1.2 from the inner sphere's poles
    CHECK(r.hd_recon_to_surface * d <= 1.2 + sag + 1e-9);
    CHECK(r.hd_recon_to_surface * d >= 1.2 - 0.01);
}

TEST_CASE("evaluate: errors and cancellation") {
    const Mesh sphere = shapes::icosphere(1.0, 1);
    EvaluateResult r;
    CHECK(evaluate(sphere, Skeleton{}, EvaluateOptions{}, Monitor{}, r).code == Code::invalid_argument);
    CHECK(evaluate(Mesh{}, one_ball(1), EvaluateOptions{}, Monitor{}, r).code == Code::degenerate_input);
    Skeleton bad = one_ball(1);
    bad.edges = {{0, 5}};
    CHECK(evaluate(sphere, bad, EvaluateOptions{}, Monitor{}, r).code == Code::invalid_input);
    Skeleton neg = one_ball(-1);
    CHECK(evaluate(sphere, neg, EvaluateOptions{}, Monitor{}, r).code == Code::invalid_input);

    std::atomic<int> flag{1};
    Monitor cancel;
    cancel.cancel_flag = &flag;
    CHECK(evaluate(sphere, one_ball(1), EvaluateOptions{}, cancel, r).code == Code::cancelled);

    int calls = 0;
    Monitor stop_later;
    stop_later.progress = [&](const char* stage, double f) {
        CHECK(std::string(stage) == "evaluate");
        CHECK(f >= 0);
        CHECK(f <= 1);
        return ++calls < 3;
    };
    CHECK(evaluate(sphere, one_ball(1), EvaluateOptions{}, stop_later, r).code == Code::cancelled);
}

TEST_CASE("evaluate on a prepared surface: the full result is evaluate()'s, hd_only its maxima") {
    // skeletons inside, across and outside a sphere mesh: points of S inside and outside E, and
    // boundary points of E near and far from S, so that every pruning branch is taken
    const Mesh sphere = shapes::icosphere(1.0, 3);
    EvaluateOptions opt;
    opt.surface_samples = 4000;
    opt.envelope_samples = 20000;
    std::shared_ptr<const EvaluationSurface> prepared;
    REQUIRE(prepare_evaluation(sphere, opt, prepared).ok());
    std::vector<Skeleton> skeletons(4);
    skeletons[0].balls = {{Vec3(0, 0, 0), 0.9}};
    skeletons[1].balls = {{Vec3(-0.5, 0, 0), 0.6}, {Vec3(0.5, 0, 0), 0.6}, {Vec3(0, 0.5, 0), 0.5}};
    skeletons[1].faces = {{0, 1, 2}};
    skeletons[2].balls = {{Vec3(-0.8, 0, 0), 0.5}, {Vec3(0.9, 0.2, 0), 0.4}};
    skeletons[2].edges = {{0, 1}};
    skeletons[3].balls = {{Vec3(0.3, 0.1, 0), 1.2}};
    for (int threads : {1, 3}) {
        opt.threads = threads;
        for (const Skeleton& s : skeletons) {
            EvaluateResult full, same, fast;
            REQUIRE(evaluate(sphere, s, opt, Monitor{}, full).ok());
            REQUIRE(evaluate(*prepared, s, opt, Monitor{}, same).ok());
            REQUIRE(evaluate(*prepared, s, opt, Monitor{}, fast, true).ok());
            CHECK(same.hd_two_sided == full.hd_two_sided);
            CHECK(same.mean_surface_to_recon == full.mean_surface_to_recon);
            CHECK(same.mean_recon_to_surface == full.mean_recon_to_surface);
            CHECK(fast.hd_surface_to_recon == full.hd_surface_to_recon);
            CHECK(fast.hd_recon_to_surface == full.hd_recon_to_surface);
            CHECK(fast.hd_two_sided == full.hd_two_sided);
        }
    }
    // other samples or seed than those prepared are refused
    EvaluateOptions other = opt;
    other.seed = 2;
    EvaluateResult r;
    CHECK(evaluate(*prepared, skeletons[0], other, Monitor{}, r).code == Code::invalid_argument);
}

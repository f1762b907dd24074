// test_normals.cpp: point-cloud normals against the exact normals of sampled shapes: PCA
// estimation, orientation of random per-point signs (a sphere, a torus, a flattened sphere whose
// two sides are closer than the sample spacing, the fish cloud of tests/data), and the sign
// disagreement measure (low for consistent normals, about 1/2 for random signs, pairs across a
// thin part not counted); the winding-number vote over patches propagation flipped, the winding
// residual, and noisy exact normals kept as given.
#include "normals.h"
#include "patch_signs.h"
#include "rng.h"
#include "surface.h"
#include "mesh_io.h"
#include "support/clouds.h"
#include "support/shapes.h"
#include <doctest/doctest.h>
#include <cmath>

using namespace ca;

namespace {

std::vector<Vec3> random_signs(const std::vector<Vec3>& n, uint64_t seed) {
    Rng rng(seed);
    std::vector<Vec3> out = n;
    for (Vec3& v : out)
        if (rng.uniform() < 0.5) v = -v;
    return out;
}

// The fraction of points whose normal agrees with the exact one, up to one global sign.
double agreement(const std::vector<Vec3>& got, const std::vector<Vec3>& exact) {
    size_t same = 0;
    for (size_t i = 0; i < got.size(); ++i) same += got[i].dot(exact[i]) > 0;
    const double f = double(same) / double(got.size());
    return std::max(f, 1 - f);
}

shapes::Cloud fish_cloud() {
    caio::MeshData m;
    std::string err;
    REQUIRE_MESSAGE(caio::read_mesh(std::string(CA_TEST_DATA) + "/fish_points.xyz", m, err), err);
    shapes::Cloud c;
    for (size_t i = 0; 3 * i + 2 < m.positions.size(); ++i) {
        c.points.emplace_back(m.positions[3 * i], m.positions[3 * i + 1], m.positions[3 * i + 2]);
        c.normals.push_back(Vec3(m.normals[3 * i], m.normals[3 * i + 1], m.normals[3 * i + 2]).normalized());
    }
    return c;
}

// A sphere of radius 1 flattened to a thickness of 0.04: its sides are closer than the samples
// are to each other (about 0.03), so every neighbourhood reaches across.
shapes::Cloud slab_cloud() {
    Mesh m = shapes::sphere(1.0, 96, 192);
    for (Vec3& v : m.vertices) v.z() *= 0.02;
    return shapes::sample_cloud(m, 4000);
}

}  // namespace

TEST_CASE("normals: PCA estimates the sphere's radial directions") {
    const shapes::Cloud c = shapes::sample_cloud(shapes::sphere(1.0, 96, 192), 4000);
    const std::vector<Vec3> n = estimate_normals(c.points);
    double worst = 1;
    for (size_t i = 0; i < n.size(); ++i) worst = std::min(worst, std::abs(n[i].dot(c.normals[i])));
    CHECK(worst > 0.98);
}

TEST_CASE("normals: orientation repairs random per-point signs (sphere, torus, thin slab)") {
    struct Case { const char* name; shapes::Cloud cloud; };
    const Case cases[] = {{"sphere", shapes::sample_cloud(shapes::sphere(1.0, 96, 192), 4000)},
                          {"torus", shapes::sample_cloud(shapes::torus(1.0, 0.3, 128, 48), 6000)},
                          {"slab", slab_cloud()}};
    for (const Case& k : cases) {
        CAPTURE(k.name);
        std::vector<Vec3> n = random_signs(k.cloud.normals, 5);
        CHECK(agreement(n, k.cloud.normals) < 0.6);
        orient_normals(k.cloud.points, n);
        CHECK(agreement(n, k.cloud.normals) > 0.99);
    }
}

TEST_CASE("normals: sign disagreement separates consistent from random signs") {
    const shapes::Cloud sphere = shapes::sample_cloud(shapes::sphere(1.0, 96, 192), 4000);
    const shapes::Cloud slab = slab_cloud();
    for (const shapes::Cloud* c : {&sphere, &slab}) {
        // the slab: pairs facing across it agree; some side by side across its knife-edge rim do
        // not, too few to distrust the normals
        const double bound = c == &sphere ? 0.02 : kMaxSignDisagreement;
        CHECK(sign_disagreement(c->points, c->normals) < bound);
        std::vector<Vec3> flipped = c->normals;
        for (Vec3& v : flipped) v = -v;
        CHECK(sign_disagreement(c->points, flipped) < bound);
        const double r = sign_disagreement(c->points, random_signs(c->normals, 9));
        CHECK(r > 0.3);
        CHECK(r < 0.6);
    }
    CHECK(sign_disagreement({}, {}) == 0);
}

TEST_CASE("normals: the fish cloud with random signs is detected and re-oriented") {
    const shapes::Cloud fish = fish_cloud();
    CHECK(sign_disagreement(fish.points, fish.normals) < kMaxSignDisagreement);
    Surface s;
    REQUIRE(prepare_surface(Mesh{fish.points, {}}, fish.normals, s).ok());
    CHECK(s.normals_source == NormalSource::given);
    const std::vector<Vec3> shuffled = random_signs(fish.normals, 13);
    REQUIRE(prepare_surface(Mesh{fish.points, {}}, shuffled, s).ok());
    CHECK(s.disagreement_given > kMaxSignDisagreement);
    CHECK(s.normals_source == NormalSource::oriented);
    CHECK(s.disagreement < kMaxSignDisagreement);
    // thin fins: most points, not all, get their sign back
    CHECK(agreement(s.normals, fish.normals) > 0.9);
}

TEST_CASE("normals: the caller's trust level") {
    const shapes::Cloud c = shapes::sample_cloud(shapes::sphere(1.0, 96, 192), 3000);
    Surface s;
    REQUIRE(prepare_surface(Mesh{c.points, {}}, c.normals, s, true, PointNormals::unoriented).ok());
    CHECK(s.normals_source == NormalSource::oriented);
    CHECK(agreement(s.normals, c.normals) > 0.99);
    // random directions: nothing to orient; ignored when estimating, refused otherwise
    Rng rng(2);
    std::vector<Vec3> junk(c.points.size());
    for (Vec3& v : junk) v = Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
    REQUIRE(prepare_surface(Mesh{c.points, {}}, junk, s, true, PointNormals::estimate).ok());
    CHECK(s.normals_source == NormalSource::estimated);
    CHECK(agreement(s.normals, c.normals) > 0.99);
    const Status st = prepare_surface(Mesh{c.points, {}}, junk, s);
    CHECK(st.code == Code::invalid_input);
    CHECK(st.message.find("could not be oriented") != std::string::npos);
}

// A flat box 1 x 1 x 0.02: its two faces closer than PCA's neighbourhoods, so pairs across the
// thin part still disagree after orientation although the signs are mostly right. Directions that
// follow the surface, passed as unoriented, are left to the winding-number probes.
TEST_CASE("normals: PCA normals with random signs of a thin flat box, passed as unoriented, are accepted") {
    const shapes::Cloud c = shapes::sample_cloud(shapes::box(1.0, 1.0, 0.02), 5000, 3);
    const std::vector<Vec3> pca = random_signs(estimate_normals(c.points), 4);
    Surface s;
    const Status st = prepare_surface(Mesh{c.points, {}}, pca, s, true, PointNormals::unoriented);
    REQUIRE_MESSAGE(st.ok(), st.message);
    CHECK(s.normals_source == NormalSource::oriented);
    CHECK(s.disagreement > kMaxSignDisagreement);   // the pair rule alone would refuse it
    CHECK(agreement(s.normals, c.normals) > 0.75);   // most signs right, up to one global sign
}

// Shapes where propagation alone joins patches the wrong way round (across a thin part, a crease
// or a gap narrower than the neighbourhoods): each patch is signed by the winding-number vote.
TEST_CASE("normals: the winding-number vote signs whole patches that propagation flipped") {
    const shapes::Cloud bar = shapes::sample_cloud(shapes::box(1.0, 0.2, 0.03), 4000, 3);
    const shapes::Cloud plate = shapes::sample_cloud(
        shapes::merged(shapes::box(1.0, 1.0, 0.03), shapes::capsule(0.6, 0.12), Vec3(0.5, 0.5, 0.15)), 5000, 3);
    const shapes::Cloud caps = shapes::sample_cloud(
        shapes::merged(shapes::capsule(0.5, 0.1), shapes::capsule(0.5, 0.1), Vec3(0, 0.215, 0)), 5000, 3);
    struct Case { const char* name; const shapes::Cloud* cloud; bool estimated; double min_agreement; };
    const Case cases[] = {{"bar, exact normals", &bar, false, 0.99},
                          // its 0.03-wide side faces, narrower than PCA's neighbourhoods, get directions
                          // averaged with the top and bottom, whose signs the facing rule splits
                          // (the skeleton does not change: test_pointcloud.cpp's thin sheets)
                          {"bar, PCA normals", &bar, true, 0.93},
                          {"plate and capsule, exact normals", &plate, false, 0.95},
                          {"two capsules 0.015 apart, PCA normals", &caps, true, 0.95}};
    for (const Case& k : cases) {
        CAPTURE(k.name);
        std::vector<Vec3> n = random_signs(k.estimated ? estimate_normals(k.cloud->points) : k.cloud->normals, 5);
        orient_normals(k.cloud->points, n, 16, k.estimated);
        CHECK(agreement(n, k.cloud->normals) > k.min_agreement);
    }
}

TEST_CASE("normals: the winding residual separates consistent from cancelling signs, either global sign") {
    const shapes::Cloud torus = shapes::sample_cloud(shapes::torus(1.0, 0.3, 128, 48), 5000);
    const shapes::Cloud bar = shapes::sample_cloud(shapes::box(1.0, 0.2, 0.03), 4000, 3);
    for (const shapes::Cloud* c : {&torus, &bar}) {
        std::vector<Vec3> inward = c->normals;
        for (Vec3& v : inward) v = -v;
        CHECK(winding_residual(c->points, c->normals) < 0.05);
        CHECK(winding_residual(c->points, inward) < 0.05);
        CHECK(winding_residual(c->points, random_signs(c->normals, 3)) > 0.2);
    }
}

// Noise of 0.5 % of the diagonal on a thin box: neighbours' offsets then say little about signs
// (the pair rule disagrees, and orientation does not halve it) and PCA averages across the thin
// part (the directions do not follow it), but the winding number finds the exact normals
// consistent: they are kept as given.
TEST_CASE("normals: exact normals of a noisy thin box are kept as given") {
    const shapes::Cloud c = shapes::noisy_cloud(shapes::sample_cloud(shapes::box(1.0, 1.0, 0.04), 5000, 3), 0.005, 0.0);
    Surface s;
    const Status st = prepare_surface(Mesh{c.points, {}}, c.normals, s);
    REQUIRE_MESSAGE(st.ok(), st.message);
    CHECK(s.disagreement_given > kMaxSignDisagreement);
    CHECK(s.normals_source == NormalSource::given);
    CHECK(s.sign_check_inconclusive);
}

// The surface stage splits its per-point loops (searches, PCA, the sign checks, the vote's probes
// and patch pairs) across threads: every count gives bit-identical normals and measures, so no
// loop may write another point's (or probe's) slot, nor sum in an order that depends on the split.
TEST_CASE("normals: the surface stage gives the same result on any number of threads") {
    const shapes::Cloud plate = shapes::sample_cloud(
        shapes::merged(shapes::box(1.0, 1.0, 0.03), shapes::capsule(0.6, 0.12), Vec3(0.5, 0.5, 0.15)), 3000, 3);
    const shapes::Cloud caps = shapes::sample_cloud(
        shapes::merged(shapes::capsule(0.5, 0.1), shapes::capsule(0.5, 0.1), Vec3(0, 0.215, 0)), 3000, 3);
    const shapes::Cloud noisy = shapes::noisy_cloud(shapes::sample_cloud(shapes::box(1.0, 1.0, 0.04), 5000, 3), 0.005, 0.0);
    struct Case { const char* name; const shapes::Cloud* cloud; std::vector<Vec3> normals; PointNormals trust; };
    const Case cases[] = {{"plate, random signs, trusted", &plate, random_signs(plate.normals, 5), PointNormals::trusted},
                          {"plate, random signs, unoriented", &plate, random_signs(plate.normals, 6), PointNormals::unoriented},
                          {"two capsules, no normals", &caps, {}, PointNormals::estimate},
                          {"noisy thin box, exact normals", &noisy, noisy.normals, PointNormals::trusted}};
    for (const Case& k : cases) {
        CAPTURE(std::string(k.name));
        Surface one;
        const Status st = prepare_surface(Mesh{k.cloud->points, {}}, k.normals, one, true, k.trust, Monitor{}, 1);
        REQUIRE_MESSAGE(st.ok(), st.message);
        for (int threads : {2, 3, 7}) {
            CAPTURE(threads);
            Surface many;
            REQUIRE(prepare_surface(Mesh{k.cloud->points, {}}, k.normals, many, true, k.trust, Monitor{}, threads).ok());
            CHECK(many.normals_source == one.normals_source);
            CHECK(many.disagreement_given == one.disagreement_given);
            CHECK(many.disagreement == one.disagreement);
            CHECK(many.normals == one.normals);
        }
    }
    // the steps on their own, with patches for the vote to sign
    const std::vector<Vec3> pca = estimate_normals(caps.points);
    std::vector<Vec3> oriented = random_signs(plate.normals, 7);
    orient_normals(plate.points, oriented);
    const double given = sign_disagreement(plate.points, random_signs(plate.normals, 8));
    const double residual = winding_residual(plate.points, random_signs(plate.normals, 8));
    std::vector<uint32_t> halves(plate.points.size());
    for (size_t i = 0; i < halves.size(); ++i) halves[i] = uint32_t(plate.points[i].x() > 0.5) + 2 * (i % 2);
    std::vector<Vec3> voted = random_signs(plate.normals, 9);
    const std::vector<Vec3> unvoted = voted;
    const size_t negated = vote_patch_signs(plate.points, voted, halves, 4);
    for (int threads : {2, 3, 7}) {
        CAPTURE(threads);
        CHECK(estimate_normals(caps.points, 16, threads) == pca);
        std::vector<Vec3> o = random_signs(plate.normals, 7);
        orient_normals(plate.points, o, 16, false, threads);
        CHECK(o == oriented);
        CHECK(sign_disagreement(plate.points, random_signs(plate.normals, 8), 8, threads) == given);
        CHECK(winding_residual(plate.points, random_signs(plate.normals, 8), threads) == residual);
        std::vector<Vec3> v = unvoted;
        CHECK(vote_patch_signs(plate.points, v, halves, 4, threads) == negated);
        CHECK(v == voted);
    }
}

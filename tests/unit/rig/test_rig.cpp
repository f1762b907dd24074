// test_rig.cpp: the rig (lib/rig) on shapes whose curve skeleton is known: a cylinder gives one
// chain, a Y of three tubes three branches at one junction, the fox a leaf at each foot, the tail
// and the head; joint weights sum to 1 and change continuously; the options hold (joint cap, root);
// the C defaults are the C++ ones.
#include <doctest/doctest.h>

#include "coverage_axis.h"
#include "rig.h"
#include "steps.h"
#include "support/shapes.h"
#include "support/skeleton_of.h"

#include <cmath>
#include <map>
#include <string>

namespace {

// A cylinder along x, flat caps: length 2 h, radius r.
ca::Mesh cylinder(double h, double r) {
    const double total = 2 * r + 2 * h;
    return shapes::revolve([&](double t) {
        const double s = t * total;
        if (s < r) return std::pair<double, double>{-h, s};
        if (s < r + 2 * h) return std::pair<double, double>{-h + (s - r), r};
        return std::pair<double, double>{h, total - s};
    }, 64, 48);
}

// Three capsules from the origin in the xy plane, 120 degrees apart, as one soup: a Y.
ca::Mesh y_tubes(double arm, double r) {
    ca::Mesh out;
    for (int k = 0; k < 3; ++k) {
        ca::Mesh c = shapes::capsule(arm / 2, r, 48, 32);
        const double a = 2 * 3.14159265358979323846 * k / 3;
        const Eigen::Matrix3d rot = Eigen::AngleAxisd(a, ca::Vec3::UnitZ()).toRotationMatrix();
        for (ca::Vec3& v : c.vertices) v = rot * (v + ca::Vec3(arm / 2, 0, 0));
        out = shapes::merged(out, c);
    }
    return out;
}

struct Shape {
    ca::Mesh mesh;
    ca::Skeleton skeleton;
    ca::Rig rig;
};

Shape rigged(ca::Mesh mesh, ca::RigOptions opt = {}) {
    Shape s{std::move(mesh), {}, {}};
    s.skeleton = skeleton_of(s.mesh);
    ca::SurfaceInput surface;
    surface.mesh = s.mesh;
    const ca::Status st = ca::rig_step(surface, s.skeleton, opt, ca::Monitor{}, s.rig);
    REQUIRE_MESSAGE(st.ok(), st.message);
    return s;
}

// Joints' degrees in the undirected tree.
std::vector<int> degrees(const ca::Rig& rig) {
    std::vector<int> d(rig.joints.size(), 0);
    for (size_t j = 1; j < rig.joints.size(); ++j) {
        REQUIRE(rig.parent[j] >= 0);
        REQUIRE(size_t(rig.parent[j]) < j);
        ++d[j];
        ++d[size_t(rig.parent[j])];
    }
    return d;
}

std::vector<ca::Vec3> leaves(const ca::Rig& rig) {
    std::vector<ca::Vec3> out;
    const std::vector<int> d = degrees(rig);
    for (size_t j = 0; j < d.size(); ++j)
        if (d[j] == 1) out.push_back(rig.joints[j]);
    return out;
}

void check_weights(const Shape& s) {
    REQUIRE(s.rig.vertex_joints.size() == s.mesh.vertices.size());
    for (size_t i = 0; i < s.mesh.vertices.size(); ++i) {
        double sum = 0;
        for (int k = 0; k < ca::kInfluences; ++k) {
            CHECK(s.rig.vertex_joints[i][k] < s.rig.joints.size());
            CHECK(s.rig.vertex_weights[i][k] >= 0);
            sum += s.rig.vertex_weights[i][k];
        }
        CHECK(std::abs(sum - 1) < 1e-12);
    }
}

}  // namespace

TEST_CASE("rig: a cylinder gives one chain of joints from cap to cap") {
    const double h = 3, r = 0.5;
    const Shape s = rigged(cylinder(h, r));
    const std::vector<int> d = degrees(s.rig);
    REQUIRE(s.rig.joints.size() >= 3);
    for (int x : d) CHECK(x <= 2);   // no junction
    const std::vector<ca::Vec3> ends = leaves(s.rig);
    REQUIRE(ends.size() == 2);
    // one end near each cap (within two radii: a ball and the cap's medial cone), on the axis
    CHECK(std::min(ends[0].x(), ends[1].x()) < -h + 2 * r);
    CHECK(std::max(ends[0].x(), ends[1].x()) > h - 2 * r);
    // joints on the axis; an end may sit on its cap's medial cone, inside the tube
    for (size_t j = 0; j < d.size(); ++j)
        CHECK(std::hypot(s.rig.joints[j].y(), s.rig.joints[j].z()) < (d[j] == 1 ? 0.8 : 0.3) * r);
    check_weights(s);
}

TEST_CASE("rig: a Y of three tubes gives three branches at one junction") {
    const double arm = 3, r = 0.4;
    const Shape s = rigged(y_tubes(arm, r));
    const std::vector<int> d = degrees(s.rig);
    int junctions = 0;
    size_t junction = 0;
    for (size_t j = 0; j < d.size(); ++j)
        if (d[j] >= 3) {
            ++junctions;
            junction = j;
            CHECK(d[j] == 3);
        }
    REQUIRE(junctions == 1);
    CHECK(s.rig.joints[junction].norm() < 2 * r);
    const std::vector<ca::Vec3> ends = leaves(s.rig);
    REQUIRE(ends.size() == 3);
    // one tip near the end of each arm
    for (int k = 0; k < 3; ++k) {
        const double a = 2 * 3.14159265358979323846 * k / 3;
        const ca::Vec3 tip = arm * ca::Vec3(std::cos(a), std::sin(a), 0);
        int near = 0;
        for (const ca::Vec3& e : ends) near += (e - tip).norm() < 1.5 * r;
        CHECK(near == 1);
    }
    check_weights(s);
}

TEST_CASE("rig: the fox has leaves at its four feet, its tail and its head, and nowhere else") {
    const ca::Mesh fox = test_model("fox.obj");
    ca::Vec3 lo = fox.vertices[0], hi = lo;
    for (const ca::Vec3& v : fox.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    const Shape s = rigged(fox);
    // the fox stands on z = lo.z facing -y, its tail towards +y
    const double height = hi.z() - lo.z(), length = hi.y() - lo.y();
    std::vector<ca::Vec3> feet;
    int tail = 0, head = 0;
    for (const ca::Vec3& e : leaves(s.rig)) {
        const bool foot = e.z() < lo.z() + 0.1 * height;
        const bool is_tail = e.y() > hi.y() - 0.2 * length;
        const bool is_head = e.y() < lo.y() + 0.25 * length && e.z() > lo.z() + 0.4 * height;
        CHECK_MESSAGE(int(foot) + int(is_tail) + int(is_head) == 1, "a leaf off the extremities at ", e.transpose());
        if (foot) feet.push_back(e);
        tail += is_tail;
        head += is_head;
    }
    REQUIRE(feet.size() == 4);
    for (size_t a = 0; a < 4; ++a)
        for (size_t b = a + 1; b < 4; ++b) CHECK((feet[a] - feet[b]).norm() > 0.1 * length);
    CHECK(tail == 1);
    CHECK(head >= 1);
    check_weights(s);
}

TEST_CASE("rig: joint weights change continuously along the fox's edges") {
    const ca::Mesh fox = test_model("fox.obj");
    const ca::Skeleton skeleton = skeleton_of(fox);
    std::vector<ca::Vec3> walk;
    const int steps = 64;
    for (const ca::Tri& t : fox.triangles)
        for (int k = 0; k < 3; ++k)
            for (int i = 0; i <= steps; ++i)
                walk.push_back(fox.vertices[t[k]] + (fox.vertices[t[(k + 1) % 3]] - fox.vertices[t[k]]) * (double(i) / steps));
    ca::SurfaceInput points;
    points.mesh.vertices = walk;
    ca::Rig rig;
    REQUIRE(ca::rig_step(points, skeleton, {}, ca::Monitor{}, rig).ok());
    double worst = 0;
    for (size_t e = 0; e < walk.size(); e += steps + 1)
        for (int i = 1; i <= steps; ++i) {
            std::map<uint32_t, double> d;
            for (int k = 0; k < ca::kInfluences; ++k) {
                d[rig.vertex_joints[e + i - 1][k]] += rig.vertex_weights[e + i - 1][k];
                d[rig.vertex_joints[e + i][k]] -= rig.vertex_weights[e + i][k];
            }
            double change = 0;
            for (const auto& [j, w] : d) change += std::abs(w);
            worst = std::max(worst, change);
        }
    MESSAGE("largest joint weight change over 1/64 of a fox edge: " << worst);
    CHECK(worst < 0.6);   // nearest-joint labels would jump by 2
}

TEST_CASE("rig: the joint cap, the root option, threads, and bad options") {
    const ca::Mesh fox = test_model("fox.obj");
    const ca::Skeleton skeleton = skeleton_of(fox);
    ca::SurfaceInput surface;
    surface.mesh = fox;
    ca::RigOptions o;
    o.max_joints = 8;
    ca::Rig rig;
    REQUIRE(ca::rig_step(surface, skeleton, o, ca::Monitor{}, rig).ok());
    CHECK(rig.joints.size() <= 8);
    CHECK(rig.joints.size() >= 2);
    o = ca::RigOptions{};
    o.root = 3;
    REQUIRE(ca::rig_step(surface, skeleton, o, ca::Monitor{}, rig).ok());
    CHECK(rig.joint_ball[0] == 3);
    // the default root is the largest ball
    REQUIRE(ca::rig_step(surface, skeleton, {}, ca::Monitor{}, rig).ok());
    for (const ca::Ball& b : skeleton.balls) CHECK(b.radius <= skeleton.balls[rig.joint_ball[0]].radius);
    ca::Rig other;
    o = ca::RigOptions{};
    o.correspond.threads = 1;
    REQUIRE(ca::rig_step(surface, skeleton, o, ca::Monitor{}, other).ok());
    CHECK(other.joints == rig.joints);
    CHECK(other.vertex_weights == rig.vertex_weights);
    CHECK(other.vertex_joints == rig.vertex_joints);

    o = ca::RigOptions{};
    o.root = int64_t(skeleton.balls.size());
    CHECK(ca::rig_step(surface, skeleton, o, ca::Monitor{}, rig).code == ca::Code::invalid_argument);
    CHECK(rig.joints.empty());
    o = ca::RigOptions{};
    o.max_joints = 0;
    CHECK(ca::rig_step(surface, skeleton, o, ca::Monitor{}, rig).code == ca::Code::invalid_argument);
    o = ca::RigOptions{};
    o.joint_spacing = std::nan("");
    CHECK(ca::rig_step(surface, skeleton, o, ca::Monitor{}, rig).code == ca::Code::invalid_argument);
    o = ca::RigOptions{};
    o.min_branch = -1;
    CHECK(ca::rig_step(surface, skeleton, o, ca::Monitor{}, rig).code == ca::Code::invalid_argument);
}

TEST_CASE("rig: the C options' defaults are the C++ ones") {
    ca_rig_options r;
    ca_rig_options_init(&r);
    const ca::RigOptions rr;
    CHECK(r.root == rr.root);
    CHECK(r.max_joints == rr.max_joints);
    CHECK(r.joint_spacing == rr.joint_spacing);
    CHECK(r.min_branch == rr.min_branch);
    CHECK(r.smoothing == rr.correspond.smoothing);
    ca_correspondence_options c;
    ca_correspondence_options_init(&c);
    CHECK(c.smoothing == ca::CorrespondOptions{}.smoothing);
    CHECK(ca_rig_options_defaults(&r, 3) == CA_ERROR_STRUCT_SIZE);
    CHECK(ca_correspondence_options_defaults(nullptr, sizeof c) == CA_ERROR_NULL_POINTER);
}

TEST_CASE("rig: the C ABI checks its arguments and gives the core's arrays") {
    ca::Skeleton s;
    s.balls = {{ca::Vec3(0, 0, 0), 1.0}, {ca::Vec3(3, 0, 0), 0.8}, {ca::Vec3(6, 0, 0), 0.6}};
    s.edges = {{0, 1}, {1, 2}};
    const std::vector<double> xyz = {0, 1, 0, 1.5, 0.9, 0, 3, 0.8, 0, 4.5, 0.7, 0, 6, 0.6, 0, 6.6, 0, 0};
    const std::vector<double> centers = {0, 0, 0, 3, 0, 0, 6, 0, 0}, radii = {1.0, 0.8, 0.6};
    const std::vector<uint32_t> edges = {0, 1, 1, 2};
    ca_context* ctx = nullptr;
    REQUIRE(ca_context_create(nullptr, &ctx) == CA_OK);
    ca_surface_view surface;
    ca_surface_view_init(&surface);
    surface.positions = xyz.data();
    surface.vertex_count = xyz.size() / 3;
    ca_skeleton_view view;
    ca_skeleton_view_init(&view);
    view.centers = centers.data();
    view.radii = radii.data();
    view.vertex_count = 3;
    view.edges = edges.data();
    view.edge_count = 2;

    ca_correspondence* c = reinterpret_cast<ca_correspondence*>(1);
    CHECK(ca_correspond(ctx, nullptr, &view, nullptr, &c) == CA_ERROR_NULL_POINTER);
    CHECK(c == nullptr);
    ca_correspondence_options co;
    ca_correspondence_options_init(&co);
    co.struct_size = 4;
    CHECK(ca_correspond(ctx, &surface, &view, &co, &c) == CA_ERROR_STRUCT_SIZE);
    CHECK(std::string(ca_context_last_error(ctx)).find("ca_correspondence_options") != std::string::npos);
    co.struct_size = sizeof co;
    co.smoothing = -1;
    CHECK(ca_correspond(ctx, &surface, &view, &co, &c) == CA_ERROR_INVALID_ARGUMENT);
    ca_skeleton_view bad = view;
    bad.edge_count = 1;
    const uint32_t far_edge[2] = {0, 3};
    bad.edges = far_edge;
    CHECK(ca_correspond(ctx, &surface, &bad, nullptr, &c) == CA_ERROR_INVALID_INPUT);
    REQUIRE(ca_correspond(ctx, &surface, &view, nullptr, &c) == CA_OK);
    ca::SurfaceInput in;
    for (size_t i = 0; i < xyz.size(); i += 3) in.mesh.vertices.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
    ca::Correspondence core;
    REQUIRE(ca::correspondence_step(in, s, {}, ca::Monitor{}, core).ok());
    REQUIRE(ca_correspondence_vertex_count(c) == 6);
    for (size_t i = 0; i < 6; ++i) {
        for (int k = 0; k < 4; ++k) {
            CHECK(ca_correspondence_balls(c)[4 * i + k] == core.balls[i][k]);
            CHECK(ca_correspondence_weights(c)[4 * i + k] == core.weights[i][k]);
        }
        CHECK(ca_correspondence_nearest_kinds(c)[i] == int32_t(core.nearest_kind[i]));
        CHECK(ca_correspondence_nearest_indices(c)[i] == core.nearest_index[i]);
    }
    ca_correspondence_destroy(c);
    ca_correspondence_destroy(nullptr);

    ca_rig* r = nullptr;
    ca_rig_options ro;
    ca_rig_options_init(&ro);
    ro.root = 3;
    CHECK(ca_rig_build(ctx, &surface, &view, &ro, &r) == CA_ERROR_INVALID_ARGUMENT);
    CHECK(r == nullptr);
    ro.root = -1;
    REQUIRE(ca_rig_build(ctx, &surface, &view, &ro, &r) == CA_OK);
    ca::Rig rig;
    REQUIRE(ca::rig_step(in, s, ca::RigOptions{}, ca::Monitor{}, rig).ok());
    REQUIRE(ca_rig_joint_count(r) == rig.joints.size());
    CHECK(ca_rig_joint_parents(r)[0] == -1);
    CHECK(ca_rig_joint_balls(r)[0] == 0);   // the largest ball
    CHECK(ca_rig_branch_count(r) == rig.branch_count);
    REQUIRE(ca_rig_vertex_count(r) == 6);
    for (size_t i = 0; i < 6; ++i)
        for (int k = 0; k < 4; ++k) {
            CHECK(ca_rig_vertex_joints(r)[4 * i + k] == rig.vertex_joints[i][k]);
            CHECK(ca_rig_vertex_weights(r)[4 * i + k] == rig.vertex_weights[i][k]);
        }
    ca_rig_destroy(r);
    ca_rig_destroy(nullptr);
    CHECK(ca_rig_joint_count(nullptr) == 0);
    CHECK(ca_correspondence_balls(nullptr) == nullptr);
    ca_context_destroy(ctx);
}

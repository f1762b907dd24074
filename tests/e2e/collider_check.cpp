// collider_check.cpp: the library's side of the colliders tests (tests/e2e/colliders.sh).
//   collider_check hits PROXIES.json < RAYS    for each ray "ox oy oz dx dy dz" (d a unit vector),
//                                              the distance along it to the first point of the union
//                                              of the primitives, or -1 if it misses them
//   collider_check distance PROXIES.json < POINTS   for each point "x y z", its signed distance to
//                                              the union (negative inside)
//   collider_check write OUT.glb MESH PROXIES.json   a colliders file (as --colliders writes it) from
//                                              given primitives, placed by the library
//   collider_check bones OUT.glb BONES.json INPUT   a --bone-colliders file read back through the
//                                              project's reader (caio::read_mesh) beside its JSON:
//                                              the skin as the input's (joints, parents, inverse
//                                              binds, weights, bind-pose positions, to float
//                                              precision) and, per collider of BONES.json (the
//                                              tool's --bone-colliders-json), a node that is a child
//                                              of its joint's node with the collider's shape and
//                                              local placement (KHR_implicit_shapes,
//                                              KHR_physics_rigid_bodies)
// PROXIES.json is the tool's --proxies-json ({"proxies": [{"kind": "sphere", "center", "radius"},
// {"kind": "capsule", "a", "radius_a", "b", "radius_b"}, {"kind": "box", "center", "rotation"
// (x y z w), "half_extents"}]}). Hits come from sphere tracing the exact signed distance of the
// union (proxy_distance): the march stops within 1e-9 of the primitives' size of the surface, so a
// hit is exact to that over the sine of the ray's angle with the surface.
#include "gltf_physics.h"
#include "mesh_io.h"
#include "proxies.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

namespace {

using nlohmann::json;

ca::Vec3 vec(const json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

std::vector<ca::Proxy> read_proxies(const std::string& path) {
    std::ifstream in(path);
    const json doc = json::parse(in);
    std::vector<ca::Proxy> out;
    for (const json& p : doc.at("proxies")) {
        const std::string kind = p.at("kind");
        if (kind == "sphere") {
            const ca::Ball b{vec(p.at("center")), p.at("radius").get<double>()};
            out.push_back({ca::ProxyKind::sphere, b, b});
        } else if (kind == "capsule") {
            out.push_back({ca::ProxyKind::capsule, {vec(p.at("a")), p.at("radius_a").get<double>()},
                           {vec(p.at("b")), p.at("radius_b").get<double>()}});
        } else if (kind == "box") {
            const json& r = p.at("rotation");
            const Eigen::Quaterniond q(r[3].get<double>(), r[0].get<double>(), r[1].get<double>(), r[2].get<double>());
            out.push_back(ca::make_box(vec(p.at("center")), q.normalized().toRotationMatrix(), vec(p.at("half_extents"))));
        } else {
            throw std::runtime_error(path + ": unknown proxy kind " + kind);
        }
    }
    return out;
}

// A ball holding every primitive.
void bounding_ball(const std::vector<ca::Proxy>& proxies, ca::Vec3& centre, double& radius) {
    centre.setZero();
    for (const ca::Proxy& p : proxies) centre += 0.5 * (p.a.center + p.b.center);
    centre /= double(proxies.size());
    radius = 0;
    for (const ca::Proxy& p : proxies) {
        const double reach = p.kind == ca::ProxyKind::box ? p.half.norm() : 0.0;
        radius = std::max({radius, (p.a.center - centre).norm() + p.a.radius + reach, (p.b.center - centre).norm() + p.b.radius + reach});
    }
}

int hits(const std::string& proxies_path) {
    const std::vector<ca::Proxy> proxies = read_proxies(proxies_path);
    if (proxies.empty()) throw std::runtime_error(proxies_path + ": no proxies");
    ca::Vec3 centre;
    double radius;
    bounding_ball(proxies, centre, radius);
    const double eps = 1e-9 * radius;
    auto distance = [&](const ca::Vec3& x) {
        double d = INFINITY;
        for (const ca::Proxy& p : proxies) d = std::min(d, ca::proxy_distance(p, x));
        return d;
    };
    double ox, oy, oz, dx, dy, dz;
    while (std::cin >> ox >> oy >> oz >> dx >> dy >> dz) {
        const ca::Vec3 o(ox, oy, oz), d = ca::Vec3(dx, dy, dz).normalized();
        // past t_far the ray has left the bounding ball for good
        const double t_far = (centre - o).dot(d) + radius;
        double t = 0, hit = -1;
        for (long step = 0; step < 10000000 && t <= t_far; ++step) {
            const double s = distance(o + t * d);
            if (s < eps) {
                hit = t;
                break;
            }
            t += s;
        }
        std::printf("%.17g\n", hit);
    }
    return 0;
}

int distances(const std::string& proxies_path) {
    const std::vector<ca::Proxy> proxies = read_proxies(proxies_path);
    double x, y, z;
    while (std::cin >> x >> y >> z) {
        double d = INFINITY;
        for (const ca::Proxy& p : proxies) d = std::min(d, ca::proxy_distance(p, ca::Vec3(x, y, z)));
        std::printf("%.17g\n", d);
    }
    return 0;
}

int write(const std::string& out, const std::string& mesh_path, const std::string& proxies_path) {
    caio::MeshData mesh;
    std::string err;
    if (!caio::read_mesh(mesh_path, mesh, err)) throw std::runtime_error(err);
    std::vector<caio::ProxyData> data;
    for (const ca::Proxy& p : read_proxies(proxies_path)) {
        caio::ProxyData d;
        d.kind = int(p.kind);
        for (int k = 0; k < 3; ++k) d.a[k] = p.a.center[k], d.b[k] = p.b.center[k];
        d.radius_a = p.a.radius;
        d.radius_b = p.b.radius;
        const ca::ProxyPlacement pl = ca::proxy_placement(p);
        d.placed.kind = int(pl.kind);
        for (int k = 0; k < 3; ++k) d.placed.translation[k] = pl.translation[k], d.placed.size[k] = pl.size[k];
        d.placed.rotation[0] = pl.rotation.x(), d.placed.rotation[1] = pl.rotation.y();
        d.placed.rotation[2] = pl.rotation.z(), d.placed.rotation[3] = pl.rotation.w();
        d.placed.radius_top = pl.radius_top;
        d.placed.radius_bottom = pl.radius_bottom;
        d.placed.height = pl.height;
        data.push_back(d);
    }
    if (!caio::write_colliders(out, mesh, data, err)) throw std::runtime_error(err);
    return 0;
}

}  // namespace

// The JSON chunk of a .glb.
json glb_json(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    uint32_t length = 0;
    if (bytes.size() < 20) throw std::runtime_error(path + ": not a .glb");
    std::memcpy(&length, bytes.data() + 12, 4);
    return json::parse(bytes.substr(20, length));
}

int bones(const std::string& out, const std::string& bones_json, const std::string& input) {
    caio::MeshData written, given;
    std::string err;
    if (!caio::read_mesh(out, written, err) || !caio::read_mesh(input, given, err)) throw std::runtime_error(err);
    std::vector<std::string> failures;
    const caio::SkinData &a = written.skin, &b = given.skin;
    auto close = [](const std::vector<double>& x, const std::vector<double>& y, double tol) {
        if (x.size() != y.size()) return false;
        for (size_t i = 0; i < x.size(); ++i)
            if (!(std::abs(x[i] - y[i]) <= tol * std::max(1.0, std::abs(y[i])))) return false;
        return true;
    };
    if (a.joint_names != b.joint_names || a.parents != b.parents) failures.push_back("the joints or their hierarchy differ");
    if (!close(a.inverse_bind, b.inverse_bind, 1e-6)) failures.push_back("the inverse bind matrices differ");
    if (!close(written.positions, given.positions, 1e-6)) failures.push_back("the bind-pose positions differ");
    // weights per vertex and joint (slots may be ordered differently)
    auto weights = [](const caio::SkinData& s, size_t nv) {
        std::vector<double> w(nv * s.joint_names.size(), 0.0);
        for (size_t i = 0; i < nv; ++i)
            for (size_t k = 0; k < s.influences; ++k) w[i * s.joint_names.size() + s.vertex_joints[i * s.influences + k]] += s.vertex_weights[i * s.influences + k];
        return w;
    };
    if (a.joint_names.size() == b.joint_names.size() && written.positions.size() == given.positions.size() &&
        !close(weights(a, written.positions.size() / 3), weights(b, given.positions.size() / 3), 1e-6))
        failures.push_back("the weights differ");

    const json doc = glb_json(out);
    std::ifstream in(bones_json);
    const json list = json::parse(in).at("colliders");
    const json& shapes = doc.at("extensions").at("KHR_implicit_shapes").at("shapes");
    for (size_t i = 0; i < list.size(); ++i) {
        const json& c = list[i];
        const std::string what = "collider " + std::to_string(i) + ": ";
        const size_t joint = c.at("joint"), node = c.at("node");
        if (joint >= a.gltf_nodes.size()) { failures.push_back(what + "joint out of range"); continue; }
        const json& parent = doc.at("nodes").at(size_t(a.gltf_nodes[joint]));
        bool child = false;
        for (const json& k : parent.value("children", json::array())) child = child || k == node;
        if (!child) failures.push_back(what + "its node is not a child of the joint's node");
        const json& n = doc.at("nodes").at(node);
        const json& shape = shapes.at(size_t(n.at("extensions").at("KHR_physics_rigid_bodies").at("collider").at("geometry").at("shape")));
        const double scale = std::max(1e-12, std::max(c.at("radius_top").get<double>(), c.at("radius_bottom").get<double>()));
        auto near = [&](double x, double y) { return std::abs(x - y) <= 1e-9 * scale; };
        const std::string kind = c.at("kind");
        bool same = shape.at("type") == kind;
        if (same && kind == "sphere") same = near(shape["sphere"]["radius"], c["radius_top"]);
        if (same && kind == "capsule")
            same = near(shape["capsule"]["radiusTop"], c["radius_top"]) && near(shape["capsule"]["radiusBottom"], c["radius_bottom"]) &&
                   near(shape["capsule"]["height"], c["height"]);
        if (!same) failures.push_back(what + "its shape differs");
        for (int k = 0; k < 3; ++k)
            if (!near(n.at("translation")[k], c.at("translation")[k])) same = false;
        const json r = n.value("rotation", json{0.0, 0.0, 0.0, 1.0});
        double dot = 0;
        for (int k = 0; k < 4; ++k) dot += r[k].get<double>() * c.at("rotation")[k].get<double>();
        if (!same || std::abs(std::abs(dot) - 1) > 1e-9) failures.push_back(what + "its placement differs");
    }
    std::printf("project reader: %s: %zu joints as the input's, %zu colliders on their joints' nodes\n", out.c_str(),
                a.joint_names.size(), list.size());
    for (const std::string& f : failures) std::printf("  FAILED %s\n", f.c_str());
    return failures.empty() ? 0 : 1;
}

int main(int argc, char** argv) {
    try {
        const std::string mode = argc > 1 ? argv[1] : "";
        if (mode == "hits" && argc == 3) return hits(argv[2]);
        if (mode == "distance" && argc == 3) return distances(argv[2]);
        if (mode == "write" && argc == 5) return write(argv[2], argv[3], argv[4]);
        if (mode == "bones" && argc == 5) return bones(argv[2], argv[3], argv[4]);
        std::fprintf(stderr, "usage: collider_check hits|distance PROXIES.json < RAYS|POINTS, write OUT.glb MESH PROXIES.json, "
                             "or bones OUT.glb BONES.json INPUT\n");
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "collider_check: %s\n", e.what());
        return 1;
    }
}

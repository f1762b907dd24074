// collider_check.cpp: the library's side of the colliders tests (tests/e2e/colliders.sh).
//   collider_check hits PROXIES.json < RAYS    for each ray "ox oy oz dx dy dz" (d a unit vector),
//                                              the distance along it to the first point of the union
//                                              of the primitives, or -1 if it misses them
//   collider_check distance PROXIES.json < POINTS   for each point "x y z", its signed distance to
//                                              the union (negative inside)
//   collider_check write OUT.glb MESH PROXIES.json   a colliders file (as --colliders writes it) from
//                                              given primitives, placed by the library
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
#include <cstdio>
#include <fstream>
#include <iostream>
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

int main(int argc, char** argv) {
    try {
        const std::string mode = argc > 1 ? argv[1] : "";
        if (mode == "hits" && argc == 3) return hits(argv[2]);
        if (mode == "distance" && argc == 3) return distances(argv[2]);
        if (mode == "write" && argc == 5) return write(argv[2], argv[3], argv[4]);
        std::fprintf(stderr, "usage: collider_check hits|distance PROXIES.json < RAYS|POINTS, or write OUT.glb MESH PROXIES.json\n");
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "collider_check: %s\n", e.what());
        return 1;
    }
}

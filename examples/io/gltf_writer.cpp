// gltf_writer.cpp: the skeleton as glTF 2.0 (see gltf_writer.h). The JSON is built with
// nlohmann-json; the binary buffer holds, in order, the unit sphere (positions, normals,
// indices), the skeleton's vertex positions and radii, its edge and its face indices.
#include "gltf_writer.h"

#include "gltf_builder.h"
#include "gltf_physics.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <limits>
#include <vector>

namespace caio {
namespace {

using nlohmann::json;
using gltf::Builder;
using gltf::kFloat;
using gltf::kUnsignedShort;
using gltf::kUnsignedInt;

constexpr int kModeLines = 1, kModeTriangles = 4;

// A UV sphere of radius 1 around the origin (its normals equal its positions).
void unit_sphere(std::vector<float>& positions, std::vector<uint16_t>& triangles) {
    const int segments = 24, rings = 12;
    const double pi = 3.14159265358979323846;
    for (int r = 0; r <= rings; ++r) {
        const double theta = pi * r / rings;
        for (int s = 0; s <= segments; ++s) {
            const double phi = 2 * pi * s / segments;
            positions.push_back(float(std::sin(theta) * std::cos(phi)));
            positions.push_back(float(std::cos(theta)));
            positions.push_back(float(std::sin(theta) * std::sin(phi)));
        }
    }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const uint16_t a = uint16_t(r * (segments + 1) + s), b = uint16_t(a + segments + 1);
            if (r > 0) triangles.insert(triangles.end(), {a, uint16_t(a + 1), b});
            if (r + 1 < rings) triangles.insert(triangles.end(), {uint16_t(a + 1), uint16_t(b + 1), b});
        }
}

json material(const char* name, std::initializer_list<double> rgba, bool blend) {
    json m = {{"name", name}, {"doubleSided", true},
              {"pbrMetallicRoughness", {{"baseColorFactor", rgba}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.8}}}};
    if (blend) m["alphaMode"] = "BLEND";
    return m;
}

// The glTF document (without its buffer's uri) and the binary buffer.
json build(const SkeletonData& s, const std::vector<ProxyData>& proxies, std::string& bin) {
    Builder b;
    std::vector<float> sphere;
    std::vector<uint16_t> sphere_triangles;
    unit_sphere(sphere, sphere_triangles);
    const int sphere_pos = b.floats(sphere, 3);
    const int sphere_nrm = b.floats(sphere, 3);
    const int sphere_idx = b.indices(sphere_triangles, kUnsignedShort);

    json meshes = json::array();
    meshes.push_back({{"name", "ball"},
                      {"primitives", {{{"attributes", {{"POSITION", sphere_pos}, {"NORMAL", sphere_nrm}}},
                                       {"indices", sphere_idx}, {"mode", kModeTriangles}, {"material", 0}}}}});
    json skeleton = {{"name", "skeleton"}};
    json balls = json::array();
    const size_t nv = s.radii.size();
    if (nv > 0) {
        const std::vector<float> pos(s.centers.begin(), s.centers.end());
        const std::vector<float> rad(s.radii.begin(), s.radii.end());
        const json attributes = {{"POSITION", b.floats(pos, 3)}, {"_RADIUS", b.floats(rad, 1)}};
        json primitives = json::array();
        if (!s.edges.empty())
            primitives.push_back({{"attributes", attributes}, {"indices", b.indices(s.edges, kUnsignedInt)},
                                  {"mode", kModeLines}, {"material", 1}});
        if (!s.faces.empty())
            primitives.push_back({{"attributes", attributes}, {"indices", b.indices(s.faces, kUnsignedInt)},
                                  {"mode", kModeTriangles}, {"material", 2}});
        if (!primitives.empty()) {
            meshes.push_back({{"name", "skeleton"}, {"primitives", primitives}});
            skeleton["mesh"] = 1;
        }
        for (size_t i = 0; i < nv; ++i) {
            const double r = s.radii[i];
            balls.push_back({{"name", "ball_" + std::to_string(i)}, {"mesh", 0},
                             {"translation", {s.centers[3 * i], s.centers[3 * i + 1], s.centers[3 * i + 2]}},
                             {"scale", {r, r, r}}});
        }
    }
    json nodes = json::array({skeleton});
    json children = json::array();
    for (auto& n : balls) {
        children.push_back(nodes.size());
        nodes.push_back(std::move(n));
    }
    if (!children.empty()) nodes[0]["children"] = children;
    const json scene_nodes = json::array({0});
    bin = std::move(b.bin);
    while (bin.size() % 4) bin.push_back('\0');
    json doc = {{"asset", {{"version", "2.0"}, {"generator", "coverage-axis"}}},
                {"scene", 0},
                {"scenes", {{{"name", "coverage axis skeleton"}, {"nodes", scene_nodes}}}},
                {"nodes", nodes},
                {"meshes", meshes},
                {"materials", {material("ball", {0.25, 0.45, 0.9, 0.3}, true), material("edge", {0.1, 0.1, 0.1, 1.0}, false),
                               material("face", {0.9, 0.35, 0.2, 0.6}, true)}},
                {"accessors", b.accessors},
                {"bufferViews", b.views},
                {"buffers", {{{"byteLength", bin.size()}}}}};
    if (!proxies.empty()) {
        // the proxies as static colliders (gltf_physics.h) under "proxies", their parameters also
        // in `extras`; a sphere shows the ball mesh on a child node (a collider's node is not scaled)
        std::vector<ColliderShape> shapes;
        for (const ProxyData& p : proxies) shapes.push_back(p.placed);
        gltf::ColliderOptions options;
        options.group = "proxies";
        options.name = "proxy";
        const std::vector<size_t> placed = gltf::add_colliders(doc, shapes, options);
        json& all = doc["nodes"];
        for (size_t i = 0; i < proxies.size(); ++i) {
            const ProxyData& p = proxies[i];
            const json a = {p.a[0], p.a[1], p.a[2]}, b = {p.b[0], p.b[1], p.b[2]};
            json& node = all[placed[i]];
            if (p.kind == 1) {
                node["extras"] = {{"kind", "capsule"}, {"a", a}, {"radius_a", p.radius_a}, {"b", b}, {"radius_b", p.radius_b}};
            } else if (p.kind == 2) {
                const ColliderShape& c = p.placed;
                node["extras"] = {{"kind", "box"}, {"center", a}, {"rotation", {c.rotation[0], c.rotation[1], c.rotation[2], c.rotation[3]}},
                                  {"half_extents", {c.size[0] / 2, c.size[1] / 2, c.size[2] / 2}}};
            } else {
                node["extras"] = {{"kind", "sphere"}, {"center", a}, {"radius", p.radius_a}};
                node["children"] = {all.size()};
                all.push_back({{"name", "ball_mesh_" + std::to_string(i)}, {"mesh", 0},
                               {"scale", {p.radius_a, p.radius_a, p.radius_a}}});
            }
        }
    }
    return doc;
}

}  // namespace

bool write_gltf(const std::string& path, const SkeletonData& s, std::string& error,
                const std::vector<ProxyData>& proxies) {
    try {
        const size_t nv = s.radii.size();
        if (s.centers.size() != 3 * nv || s.edges.size() % 2 || s.faces.size() % 3) {
            error = path + ": inconsistent skeleton arrays";
            return false;
        }
        for (uint32_t i : s.edges)
            if (i >= nv) { error = path + ": edge index out of range"; return false; }
        for (uint32_t i : s.faces)
            if (i >= nv) { error = path + ": face index out of range"; return false; }
        if (!gltf::ends_with(path, ".glb") && !gltf::ends_with(path, ".gltf")) {
            error = path + ": a glTF file ends in .glb or .gltf";
            return false;
        }
        const std::string what = proxies_finite(proxies);
        if (!what.empty()) {
            error = path + ": " + what;
            return false;
        }
        std::string bin;
        const json doc = build(s, proxies, bin);
        return gltf::write_document(path, doc, bin, error);
    } catch (const std::exception& e) {
        error = path + ": " + e.what();
        return false;
    }
}

}  // namespace caio

// gltf_physics.cpp: engine proxies as glTF physics (see gltf_physics.h). A collider node's local
// transform is its world placement expressed in the parent's frame: t = R_p^-1 (t_w - t_p),
// q = q_p^-1 q_w.
#include "gltf_physics.h"

#include <cmath>
#include <exception>

namespace caio {
namespace gltf {
namespace {

constexpr int kSphere = 0, kCapsule = 1, kBox = 2;

// Quaternions as x y z w.
void multiply(const double* a, const double* b, double* out) {
    const double x = a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1];
    const double y = a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0];
    const double z = a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3];
    const double w = a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2];
    out[0] = x, out[1] = y, out[2] = z, out[3] = w;
}
void rotate(const double* q, const double* v, double* out) {
    const double p[4] = {v[0], v[1], v[2], 0}, c[4] = {-q[0], -q[1], -q[2], q[3]};
    double t[4], r[4];
    multiply(q, p, t);
    multiply(t, c, r);
    out[0] = r[0], out[1] = r[1], out[2] = r[2];
}

json implicit_shape(const ColliderShape& c) {
    switch (c.kind) {
    case kCapsule:
        return {{"type", "capsule"},
                {"capsule", {{"height", c.height}, {"radiusTop", c.radius_top}, {"radiusBottom", c.radius_bottom}}}};
    case kBox: return {{"type", "box"}, {"box", {{"size", {c.size[0], c.size[1], c.size[2]}}}}};
    default: return {{"type", "sphere"}, {"sphere", {{"radius", c.radius_top}}}};
    }
}

// OMI_physics_shape has no tapered capsule; its capsule height is the whole length, caps included.
bool omi_expressible(const ColliderShape& c) { return c.kind != kCapsule || c.radius_top == c.radius_bottom; }
json omi_shape(const ColliderShape& c) {
    if (c.kind == kCapsule)
        return {{"type", "capsule"}, {"capsule", {{"radius", c.radius_top}, {"height", c.height + 2 * c.radius_top}}}};
    return implicit_shape(c);
}

// doc.extensions[extension].shapes, created if absent.
json& shapes_of(json& doc, const char* extension) {
    json& list = doc["extensions"][extension]["shapes"];
    if (!list.is_array()) list = json::array();
    return list;
}

}  // namespace

void use_extension(json& doc, const char* name) {
    json& used = doc["extensionsUsed"];
    if (!used.is_array()) used = json::array();
    for (const auto& u : used)
        if (u == name) return;
    used.push_back(name);
}

bool collider_has_volume(const ColliderShape& c) {
    switch (c.kind) {
    case kSphere: return c.radius_top > 0;
    case kCapsule: return c.height > 0 && (c.radius_top > 0 || c.radius_bottom > 0);
    case kBox: return c.size[0] > 0 && c.size[1] > 0 && c.size[2] > 0;
    }
    return false;
}

std::vector<size_t> add_colliders(json& doc, const std::vector<ColliderShape>& shapes, const ColliderOptions& o) {
    json& nodes = doc["nodes"];
    size_t parent;
    if (o.parent >= 0) {
        parent = size_t(o.parent);
    } else {
        parent = nodes.size();
        nodes.push_back({{"name", o.group}});
        doc["scenes"][0]["nodes"].push_back(parent);
    }
    bool omi = o.omi;
    for (const ColliderShape& c : shapes) omi = omi && (!collider_has_volume(c) || omi_expressible(c));
    const double* qp = o.parent_rotation;
    const double qp_inverse[4] = {-qp[0], -qp[1], -qp[2], qp[3]};
    std::vector<size_t> out;
    bool any = false;
    for (size_t i = 0; i < shapes.size(); ++i) {
        const ColliderShape& c = shapes[i];
        double d[3], t[3], q[4];
        for (int k = 0; k < 3; ++k) d[k] = c.translation[k] - o.parent_translation[k];
        rotate(qp_inverse, d, t);
        multiply(qp_inverse, c.rotation, q);
        json node = {{"name", o.name + "_" + std::to_string(i)}, {"translation", {t[0], t[1], t[2]}}};
        if (!(q[0] == 0 && q[1] == 0 && q[2] == 0)) {
            const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            node["rotation"] = {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
        }
        if (collider_has_volume(c)) {
            json& khr = shapes_of(doc, "KHR_implicit_shapes");
            json body = {{"collider", {{"geometry", {{"shape", khr.size()}}}}}};
            khr.push_back(implicit_shape(c));
            if (o.kinematic) body["motion"] = {{"isKinematic", true}};
            node["extensions"]["KHR_physics_rigid_bodies"] = body;
            if (omi) {
                json& list = shapes_of(doc, "OMI_physics_shape");
                json omi_body = {{"collider", {{"shape", list.size()}}}};
                list.push_back(omi_shape(c));
                if (o.kinematic) omi_body["motion"] = {{"type", "kinematic"}};
                node["extensions"]["OMI_physics_body"] = omi_body;
            }
            any = true;
        }
        out.push_back(nodes.size());
        nodes[parent]["children"].push_back(nodes.size());
        nodes.push_back(std::move(node));
    }
    if (any) {
        use_extension(doc, "KHR_implicit_shapes");
        use_extension(doc, "KHR_physics_rigid_bodies");
        if (omi) {
            use_extension(doc, "OMI_physics_shape");
            use_extension(doc, "OMI_physics_body");
        }
    }
    return out;
}

}  // namespace gltf

std::string proxies_finite(const std::vector<ProxyData>& proxies) {
    for (const ProxyData& p : proxies) {
        const ColliderShape& c = p.placed;
        for (double v : {p.a[0], p.a[1], p.a[2], p.b[0], p.b[1], p.b[2], p.radius_a, p.radius_b, c.translation[0],
                         c.translation[1], c.translation[2], c.rotation[0], c.rotation[1], c.rotation[2], c.rotation[3],
                         c.radius_top, c.radius_bottom, c.height, c.size[0], c.size[1], c.size[2]})
            if (!std::isfinite(v)) return "a proxy has a NaN or infinite value";
    }
    return "";
}

bool write_colliders(const std::string& path, const MeshData& mesh, const std::vector<ProxyData>& proxies,
                     std::string& error) {
    try {
        const size_t nv = mesh.positions.size() / 3;
        if (mesh.positions.size() % 3 || mesh.triangles.size() % 3 || mesh.triangles.empty()) {
            error = path + ": the colliders file needs a triangle mesh";
            return false;
        }
        for (uint32_t i : mesh.triangles)
            if (i >= nv) {
                error = path + ": a triangle index is out of range";
                return false;
            }
        const std::string what = proxies_finite(proxies);
        if (!what.empty()) {
            error = path + ": " + what;
            return false;
        }
        gltf::Builder b;
        const std::vector<float> pos(mesh.positions.begin(), mesh.positions.end());
        const gltf::json primitive = {{"attributes", {{"POSITION", b.floats(pos, 3)}}},
                                      {"indices", b.indices(mesh.triangles, gltf::kUnsignedInt)},
                                      {"mode", 4}};   // triangles
        std::string bin = std::move(b.bin);
        while (bin.size() % 4) bin.push_back('\0');
        gltf::json doc = {{"asset", {{"version", "2.0"}, {"generator", "coverage-axis"}}},
                          {"scene", 0},
                          {"scenes", {{{"name", "coverage axis colliders"}, {"nodes", {0}}}}},
                          {"nodes", {{{"name", "mesh"}, {"mesh", 0}}}},
                          {"meshes", {{{"name", "mesh"}, {"primitives", {primitive}}}}},
                          {"accessors", b.accessors},
                          {"bufferViews", b.views},
                          {"buffers", {{{"byteLength", bin.size()}}}}};
        std::vector<ColliderShape> shapes;
        for (const ProxyData& p : proxies) shapes.push_back(p.placed);
        gltf::add_colliders(doc, shapes, gltf::ColliderOptions{});
        return gltf::write_document(path, doc, bin, error);
    } catch (const std::exception& e) {
        error = path + ": " + e.what();
        return false;
    }
}

}  // namespace caio

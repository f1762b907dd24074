// rig_writer.cpp: the skinned mesh as glTF 2.0 (see rig_writer.h). The binary buffer holds, in
// order, the mesh's positions, its triangle indices, JOINTS_0 (unsigned bytes up to 256 joints,
// else shorts), WEIGHTS_0 (floats, renormalised after rounding) and the inverse bind matrices.
// A weight-0 slot names joint 0, as the validator expects of unused slots.
#include "rig_writer.h"

#include "gltf_builder.h"
#include "gltf_physics.h"

#include <cmath>
#include <exception>

namespace caio {
namespace {

using gltf::json;

constexpr int kModePoints = 0, kModeTriangles = 4;

bool check(const MeshData& mesh, const RigData& rig, std::string& what) {
    const size_t nv = mesh.positions.size() / 3, nj = rig.parents.size();
    if (mesh.positions.size() % 3 || mesh.triangles.size() % 3 || nv == 0) return what = "inconsistent mesh arrays", false;
    if (nj == 0 || rig.joints.size() != 3 * nj || rig.parents[0] != -1) return what = "no joints, or joint 0 is not the root", false;
    if (nj > 65536) return what = "more than 65536 joints", false;
    for (size_t j = 1; j < nj; ++j)
        if (rig.parents[j] < 0 || size_t(rig.parents[j]) >= j) return what = "a joint's parent does not come before it", false;
    if (rig.vertex_joints.size() != 4 * nv || rig.vertex_weights.size() != 4 * nv)
        return what = "not 4 joint weights per mesh vertex", false;
    for (uint32_t j : rig.vertex_joints)
        if (j >= nj) return what = "a vertex's joint index is out of range", false;
    for (uint32_t i : mesh.triangles)
        if (i >= nv) return what = "a triangle index is out of range", false;
    return true;
}

json build(const MeshData& mesh, const RigData& rig, std::string& bin) {
    gltf::Builder b;
    const size_t nj = rig.parents.size();
    const std::vector<float> pos(mesh.positions.begin(), mesh.positions.end());
    json attributes = {{"POSITION", b.floats(pos, 3)}};
    json primitive = {{"mode", mesh.triangles.empty() ? kModePoints : kModeTriangles}};
    if (!mesh.triangles.empty()) primitive["indices"] = b.indices(mesh.triangles, gltf::kUnsignedInt);

    // the rig's weights are normalised, so a vertex always has one (the fallback is never used)
    b.skin_weights(rig.vertex_joints, rig.vertex_weights, 4, nj, 0, attributes);
    primitive["attributes"] = attributes;

    // inverse bind matrices (column-major): a translation by minus the joint's position
    std::vector<float> ibm(16 * nj, 0.0f);
    for (size_t j = 0; j < nj; ++j) {
        float* m = &ibm[16 * j];
        m[0] = m[5] = m[10] = m[15] = 1.0f;
        for (int c = 0; c < 3; ++c) m[12 + c] = float(-rig.joints[3 * j + c]);
    }
    const int ibm_accessor = b.matrices(ibm);

    // nodes: 0 the mesh, then joint j as node 1 + j, translated from its parent
    json nodes = json::array();
    nodes.push_back({{"name", "mesh"}, {"mesh", 0}, {"skin", 0}});
    std::vector<json> children(nj, json::array());
    for (size_t j = 1; j < nj; ++j) children[size_t(rig.parents[j])].push_back(1 + j);
    json joint_nodes = json::array();
    for (size_t j = 0; j < nj; ++j) {
        const int32_t p = rig.parents[j];
        json t = json::array();
        for (int c = 0; c < 3; ++c) {
            // the translation is from the float positions the bind matrices undo
            const float here = float(rig.joints[3 * j + c]), there = p < 0 ? 0.0f : float(rig.joints[3 * size_t(p) + c]);
            t.push_back(double(here) - double(there));
        }
        json node = {{"name", "joint_" + std::to_string(j)}, {"translation", t}};
        if (!children[j].empty()) node["children"] = children[j];
        nodes.push_back(node);
        joint_nodes.push_back(1 + j);
    }

    bin = std::move(b.bin);
    while (bin.size() % 4) bin.push_back('\0');
    return {{"asset", {{"version", "2.0"}, {"generator", "coverage-axis"}}},
            {"scene", 0},
            {"scenes", {{{"name", "coverage axis rig"}, {"nodes", {0, 1}}}}},
            {"nodes", nodes},
            {"meshes", {{{"name", "mesh"}, {"primitives", {primitive}}}}},
            {"skins", {{{"name", "rig"}, {"inverseBindMatrices", ibm_accessor}, {"skeleton", 1}, {"joints", joint_nodes}}}},
            {"accessors", b.accessors},
            {"bufferViews", b.views},
            {"buffers", {{{"byteLength", bin.size()}}}}};
}

}  // namespace

bool write_rig_glb(const std::string& path, const MeshData& mesh, const RigData& rig, std::string& error,
                   const std::vector<ProxyData>& proxies) {
    try {
        std::string what;
        if (!check(mesh, rig, what)) {
            error = path + ": " + what;
            return false;
        }
        const size_t n = path.size();
        if (n < 4 || path.compare(n - 4, 4, ".glb") != 0) {
            error = path + ": the rig is written as .glb";
            return false;
        }
        what = proxies_finite(proxies);
        if (!what.empty()) {
            error = path + ": " + what;
            return false;
        }
        std::string bin;
        json doc = build(mesh, rig, bin);
        if (!proxies.empty()) {
            std::vector<ColliderShape> shapes;
            for (const ProxyData& p : proxies) shapes.push_back(p.placed);
            gltf::add_colliders(doc, shapes, gltf::ColliderOptions{});
        }
        return write_bytes(path, gltf::glb(doc, bin), error);
    } catch (const std::exception& e) {
        error = path + ": " + e.what();
        return false;
    }
}

}  // namespace caio

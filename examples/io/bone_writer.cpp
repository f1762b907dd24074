// bone_writer.cpp: colliders per bone on a skinned glTF's joint nodes (see bone_writer.h): the
// input glTF rewritten (its JSON and buffers, merged into one binary buffer), or a new skinned
// .glb from the mesh and its skin; glTF physics through gltf_physics.h; VRMC_springBone for VRM.
#include "bone_writer.h"

#include "gltf_builder.h"
#include "gltf_physics.h"

#include <Eigen/Geometry>

#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace caio {
namespace {

using gltf::json;
using Mat4 = Eigen::Matrix4d;

constexpr int kCapsule = 1;

bool read_file(const std::string& path, std::string& bytes) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream s;
    s << in.rdbuf();
    bytes = s.str();
    return bool(in) || in.eof();
}

uint32_t u32(const std::string& b, size_t at) {
    uint32_t v;
    std::memcpy(&v, b.data() + at, 4);
    return v;
}

bool base64_decode(const std::string& in, std::string& out) {
    auto value = [](char c) -> int {
        if (c >= 'A' && c <= 'Z') return c - 'A';
        if (c >= 'a' && c <= 'z') return c - 'a' + 26;
        if (c >= '0' && c <= '9') return c - '0' + 52;
        if (c == '+') return 62;
        if (c == '/') return 63;
        return -1;
    };
    out.clear();
    uint32_t acc = 0;
    int bits = 0;
    for (char c : in) {
        if (c == '=') break;
        const int v = value(c);
        if (v < 0) return false;
        acc = (acc << 6) | uint32_t(v);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out.push_back(char((acc >> bits) & 0xFF));
        }
    }
    return true;
}

// The input's document and its buffers merged into one: every bufferView then points into `bin`
// (buffer 0), each old buffer starting at a multiple of 4 so accessor alignments hold.
bool load_document(const std::string& input, json& doc, std::string& bin, std::string& what) {
    std::string bytes;
    if (!read_file(input, bytes)) return what = "cannot read the input " + input, false;
    std::string glb_bin;
    bool has_glb_bin = false;
    if (bytes.size() >= 12 && u32(bytes, 0) == 0x46546C67u) {
        size_t at = 12;
        std::string text;
        while (at + 8 <= bytes.size()) {
            const uint32_t length = u32(bytes, at), type = u32(bytes, at + 4);
            if (length > bytes.size() - at - 8) return what = "the input's .glb chunks overrun the file", false;
            if (type == 0x4E4F534Au && text.empty()) text = bytes.substr(at + 8, length);
            else if (type == 0x004E4942u && !has_glb_bin) glb_bin = bytes.substr(at + 8, length), has_glb_bin = true;
            at += 8 + size_t(length);
        }
        doc = json::parse(text);
    } else {
        doc = json::parse(bytes);
    }
    const std::filesystem::path folder = std::filesystem::path(input).parent_path();
    std::vector<size_t> base;
    json& buffers = doc["buffers"];
    if (!buffers.is_array()) buffers = json::array();
    for (size_t i = 0; i < buffers.size(); ++i) {
        std::string data;
        const json& b = buffers[i];
        if (!b.contains("uri")) {
            if (i != 0 || !has_glb_bin) return what = "buffer " + std::to_string(i) + " has no data", false;
            data = glb_bin;
        } else {
            const std::string uri = b["uri"].get<std::string>();
            if (uri.rfind("data:", 0) == 0) {
                const size_t comma = uri.find(',');
                if (comma == std::string::npos || uri.compare(comma - 7, 7, ";base64") != 0 ||
                    !base64_decode(uri.substr(comma + 1), data))
                    return what = "buffer " + std::to_string(i) + ": a data URI that is not base64", false;
            } else {
                // a plain relative file name inside the input's folder: no scheme, no absolute
                // path, no '..' (the rule the glTF reader applies)
                const std::filesystem::path p(uri);
                bool ok = uri.find(':') == std::string::npos && uri.find('%') == std::string::npos && p.is_relative();
                for (const auto& part : p) ok = ok && part != "..";
                if (!ok || !read_file((folder / p).string(), data))
                    return what = "buffer " + std::to_string(i) + ": cannot read '" + uri + "' beside the input", false;
            }
        }
        const size_t length = b.value("byteLength", size_t(0));
        if (data.size() < length) return what = "buffer " + std::to_string(i) + " is shorter than its byteLength", false;
        while (bin.size() % 4) bin.push_back('\0');
        base.push_back(bin.size());
        bin.append(data, 0, length);
    }
    while (bin.size() % 4) bin.push_back('\0');
    if (doc.contains("bufferViews"))
        for (json& v : doc["bufferViews"]) {
            const size_t buffer = v.value("buffer", size_t(0));
            if (buffer >= base.size()) return what = "a bufferView names a missing buffer", false;
            v["buffer"] = 0;
            v["byteOffset"] = base[buffer] + v.value("byteOffset", size_t(0));
        }
    buffers = json::array({{{"byteLength", bin.size()}}});
    return true;
}

Mat4 matrix(const std::vector<double>& m, size_t j) { return Eigen::Map<const Mat4>(&m[16 * j]); }

// A matrix as glTF's translation / rotation / scale (no shear: the columns' lengths are the scale;
// a mirroring matrix mirrors through its x scale).
json trs(const Mat4& m) {
    Eigen::Matrix3d r = m.topLeftCorner<3, 3>();
    Eigen::Vector3d s(r.col(0).norm(), r.col(1).norm(), r.col(2).norm());
    if (r.determinant() < 0) s.x() = -s.x();
    for (int k = 0; k < 3; ++k)
        if (s[k] != 0) r.col(k) /= s[k];
    Eigen::Quaterniond q(r);
    q.normalize();
    json node = {{"translation", {m(0, 3), m(1, 3), m(2, 3)}}};
    if (q.vec().norm() > 1e-12) node["rotation"] = {q.x(), q.y(), q.z(), q.w()};
    if ((s - Eigen::Vector3d::Ones()).norm() > 1e-12) node["scale"] = {s.x(), s.y(), s.z()};
    return node;
}

// Consistency of the mesh, its skin and the colliders ("" when fine).
std::string check(const MeshData& mesh, const std::vector<BoneCollider>& colliders) {
    const SkinData& s = mesh.skin;
    const size_t nv = mesh.positions.size() / 3, nj = s.joint_names.size();
    if (mesh.positions.size() % 3 || mesh.triangles.size() % 3 || nv == 0) return "inconsistent mesh arrays";
    for (uint32_t i : mesh.triangles)
        if (i >= nv) return "a triangle index is out of range";
    if (nj == 0) return "the mesh has no skin";
    if (nj > 65536) return "more than 65536 joints";
    if (s.parents.size() != nj || s.inverse_bind.size() != 16 * nj ||
        !(s.joint_world.empty() || s.joint_world.size() == 16 * nj) || (s.influences != 4 && s.influences != 8) ||
        s.vertex_joints.size() != s.influences * nv || s.vertex_weights.size() != s.influences * nv)
        return "inconsistent skin arrays";
    for (int32_t p : s.parents)
        if (p < -1 || p >= int32_t(nj)) return "a joint's parent is out of range";
    for (uint32_t j : s.vertex_joints)
        if (j >= nj) return "a vertex's joint index is out of range";
    for (double v : s.inverse_bind)
        if (!std::isfinite(v)) return "an inverse bind matrix is not finite";
    for (double v : s.joint_world)
        if (!std::isfinite(v)) return "a joint's matrix is not finite";
    for (const BoneCollider& c : colliders) {
        if (c.joint >= nj) return "a collider's joint is out of range";
        ProxyData p;
        p.placed = c.placed;
        if (!proxies_finite({p}).empty()) return "a collider has a NaN or infinite value";
    }
    return "";
}

// A new document: the mesh, its skin and one node per joint (in the skin's hierarchy), `joint_node`
// filled with each joint's node.
json skinned_document(const MeshData& mesh, std::string& bin, std::vector<int>& joint_node) {
    const SkinData& s = mesh.skin;
    const size_t nj = s.joint_names.size();
    gltf::Builder b;
    const std::vector<float> pos(mesh.positions.begin(), mesh.positions.end());
    json attributes = {{"POSITION", b.floats(pos, 3)}};
    json primitive = {{"mode", 4}, {"indices", b.indices(mesh.triangles, gltf::kUnsignedInt)}};
    uint32_t root = 0;
    while (root + 1 < nj && s.parents[root] >= 0) ++root;
    b.skin_weights(s.vertex_joints, s.vertex_weights, s.influences, nj, root, attributes);
    primitive["attributes"] = attributes;
    const std::vector<float> ibm(s.inverse_bind.begin(), s.inverse_bind.end());
    const int ibm_accessor = b.matrices(ibm);

    // the joints' world matrices (the rest pose), each node's local one from its parent's
    std::vector<Mat4> world(nj);
    for (size_t j = 0; j < nj; ++j) world[j] = s.joint_world.empty() ? Mat4(matrix(s.inverse_bind, j).inverse()) : matrix(s.joint_world, j);
    json nodes = json::array({{{"name", "mesh"}, {"mesh", 0}, {"skin", 0}}});
    json roots = json::array({0}), joints = json::array();
    joint_node.assign(nj, 0);
    for (size_t j = 0; j < nj; ++j) joint_node[j] = int(1 + j);
    for (size_t j = 0; j < nj; ++j) {
        const int32_t p = s.parents[j];
        json node = trs(p < 0 ? world[j] : Mat4(world[size_t(p)].inverse() * world[j]));
        node["name"] = s.joint_names[j];
        nodes.push_back(node);
        joints.push_back(joint_node[j]);
        if (p < 0) roots.push_back(joint_node[j]);
        else nodes[size_t(joint_node[size_t(p)])]["children"].push_back(joint_node[j]);
    }
    bin = std::move(b.bin);
    while (bin.size() % 4) bin.push_back('\0');
    return {{"asset", {{"version", "2.0"}, {"generator", "coverage-axis"}}},
            {"scene", 0},
            {"scenes", {{{"name", "coverage axis bone colliders"}, {"nodes", roots}}}},
            {"nodes", nodes},
            {"meshes", {{{"name", "mesh"}, {"primitives", {primitive}}}}},
            {"skins", {{{"name", "skin"}, {"inverseBindMatrices", ibm_accessor}, {"joints", joints}}}},
            {"accessors", b.accessors},
            {"bufferViews", b.views},
            {"buffers", {{{"byteLength", bin.size()}}}}};
}

// VRMC_springBone colliders on the joints' nodes, one group per joint (see bone_writer.h).
void add_spring_bone_colliders(json& doc, const std::vector<BoneCollider>& colliders, const std::vector<int>& joint_node,
                               bool conservative) {
    json& spring = doc["extensions"]["VRMC_springBone"];
    if (!spring.is_object()) spring = json::object();
    spring["specVersion"] = "1.0";
    json& list = spring["colliders"];
    if (!list.is_array()) list = json::array();
    json& groups = spring["colliderGroups"];
    if (!groups.is_array()) groups = json::array();
    std::vector<int> group_of(joint_node.size(), -1);
    for (const BoneCollider& c : colliders) {
        const ColliderShape& s = c.placed;
        const Eigen::Quaterniond q(s.rotation[3], s.rotation[0], s.rotation[1], s.rotation[2]);
        const Eigen::Vector3d t(s.translation[0], s.translation[1], s.translation[2]);
        json shape;
        if (s.kind == kCapsule) {
            // ColliderShape's capsule: radius_bottom at -height/2, radius_top at +height/2 on +Y
            const Eigen::Vector3d bottom = t + q * Eigen::Vector3d(0, -s.height / 2, 0);
            const Eigen::Vector3d top = t + q * Eigen::Vector3d(0, s.height / 2, 0);
            const double r = conservative ? std::max(s.radius_top, s.radius_bottom) : std::min(s.radius_top, s.radius_bottom);
            shape = {{"capsule", {{"offset", {bottom.x(), bottom.y(), bottom.z()}}, {"radius", r},
                                  {"tail", {top.x(), top.y(), top.z()}}}}};
        } else {
            shape = {{"sphere", {{"offset", {t.x(), t.y(), t.z()}}, {"radius", s.radius_top}}}};
        }
        const size_t index = list.size();
        list.push_back({{"node", joint_node[c.joint]}, {"shape", shape}});
        int& g = group_of[c.joint];
        if (g < 0) {
            g = int(groups.size());
            json name = doc["nodes"][size_t(joint_node[c.joint])].value("name", std::string("joint"));
            groups.push_back({{"name", name}, {"colliders", json::array()}});
        }
        groups[size_t(g)]["colliders"].push_back(index);
    }
    gltf::use_extension(doc, "VRMC_springBone");
}

}  // namespace

bool rewrites_input(const std::string& input, const MeshData& mesh) {
    return (gltf::ends_with(input, ".glb") || gltf::ends_with(input, ".gltf")) && !mesh.skin.gltf_nodes.empty();
}

bool write_bone_colliders(const std::string& path, const std::string& input, const MeshData& mesh,
                          const std::vector<BoneCollider>& colliders, bool conservative, BoneCollidersWritten& written,
                          std::string& error) {
    written = BoneCollidersWritten{};
    try {
        std::string what = check(mesh, colliders);
        if (!what.empty()) return error = path + ": " + what, false;
        if (!gltf::ends_with(path, ".glb") && !gltf::ends_with(path, ".gltf"))
            return error = path + ": a glTF file ends in .glb or .gltf", false;
        json doc;
        std::string bin;
        std::vector<int> joint_node;
        if (rewrites_input(input, mesh)) {
            if (!load_document(input, doc, bin, what)) return error = path + ": " + what, false;
            joint_node.assign(mesh.skin.gltf_nodes.begin(), mesh.skin.gltf_nodes.end());
            const size_t node_count = doc["nodes"].is_array() ? doc["nodes"].size() : 0;
            if (joint_node.size() != mesh.skin.joint_names.size()) return error = path + ": the skin has no node per joint", false;
            for (int n : joint_node)
                if (n < 0 || size_t(n) >= node_count) return error = path + ": a joint's node is out of range", false;
            if (!doc["scenes"].is_array() || doc["scenes"].empty()) doc["scenes"] = json::array({json::object()});
            written.rewritten = true;
        } else {
            doc = skinned_document(mesh, bin, joint_node);
        }
        for (const BoneCollider& c : colliders) {
            gltf::ColliderOptions o;
            o.parent = joint_node[c.joint];
            o.kinematic = true;
            o.name = mesh.skin.joint_names[c.joint] + "_collider";
            const std::vector<size_t> made = gltf::add_colliders(doc, {c.placed}, o);
            written.collider_nodes.push_back(int(made.front()));
            written.joint_nodes.push_back(o.parent);
        }
        if (doc.contains("extensions") && doc["extensions"].contains("VRMC_vrm")) {
            add_spring_bone_colliders(doc, colliders, joint_node, conservative);
            written.vrm = true;
        }
        return gltf::write_document(path, doc, bin, error);
    } catch (const std::exception& e) {
        error = path + ": " + e.what();
        written = BoneCollidersWritten{};
        return false;
    }
}

}  // namespace caio

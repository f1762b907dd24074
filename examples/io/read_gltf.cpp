// read_gltf.cpp: glTF 2.0 meshes (.gltf JSON with external or data-URI buffers, .glb) through
// tinygltf. Every triangle primitive (TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN; points and lines
// are skipped) reachable from the default scene's root nodes (all scenes' roots when there is no
// default scene; every parentless node when there are no scenes) is placed in world coordinates
// by its node's transform (matrix or T*R*S, composed down the hierarchy); a mesh used by several
// nodes appears once per node. POSITION must be float VEC3; indices unsigned byte, short or int.
// Normals are not read (MeshData normals stay empty). When drawn meshes are skinned, the skin is
// read too and the meshes are placed in the skinned mesh's own space instead (see "skins" below).
//
// Assets come from outside, so before tinygltf sees the asset every buffer and image URI is
// checked: data: URIs must not declare more bytes than the file holds; any other URI must be a
// relative path (no scheme, no leading '/', no '..' component, percent-escapes decoded first)
// naming an existing file whose real path (symbolic links resolved) lies inside the asset's own
// folder. The file-system callbacks handed to tinygltf enforce the same folder rule again. Images
// are never decoded. Every accessor read is bounds-checked against its buffer view and buffer.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_NO_FS
#include <fstream>  // tiny_gltf.h uses it without including it
#include <tiny_gltf.h>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "readers.h"

namespace caio {
namespace detail {
namespace {

namespace fs = std::filesystem;

// ---- URI checks ----

std::string percent_decode(const std::string& s) {
    auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return -1;
    };
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '%' && i + 2 < s.size() && hex(s[i + 1]) >= 0 && hex(s[i + 2]) >= 0) {
            out += static_cast<char>(hex(s[i + 1]) * 16 + hex(s[i + 2]));
            i += 2;
        } else {
            out += s[i];
        }
    }
    return out;
}

bool inside(const std::string& dir, const std::string& p) {
    return p.size() > dir.size() + 1 && p.compare(0, dir.size(), dir) == 0 && p[dir.size()] == '/';
}

// Why the external URI `uri` may not be read from `asset_dir`, or "" if it may.
std::string refuse_external_uri(const std::string& asset_dir, const std::string& uri) {
    const std::string d = percent_decode(uri);
    if (d.empty()) return "empty URI";
    if (d.find('\0') != std::string::npos) return "NUL byte in URI";
    if (d[0] == '/' || d[0] == '\\') return "absolute paths are not allowed";
    const size_t colon = d.find(':');
    if (colon != std::string::npos && d.find_first_of("/\\") > colon)
        return "URI schemes other than data: are not allowed";
    size_t start = 0;
    for (;;) {
        const size_t end = d.find_first_of("/\\", start);
        const std::string part = d.substr(start, end == std::string::npos ? std::string::npos : end - start);
        if (part == "..") return "'..' leaves the asset folder";
        if (end == std::string::npos) break;
        start = end + 1;
    }
    if (asset_dir.empty()) return "external files cannot be resolved when reading standard input";
    std::error_code ec;
    const fs::path real = fs::canonical(fs::path(asset_dir) / d, ec);
    if (ec) return "file not found in the asset folder";
    if (!inside(asset_dir, real.string())) return "it resolves outside the asset folder (symbolic link)";
    if (!fs::is_regular_file(real, ec)) return "not a regular file";
    return "";
}

bool is_data_uri(const std::string& uri) { return uri.compare(0, 5, "data:") == 0; }

// The JSON chunk of a GLB, or "" if the header is malformed (tinygltf then reports it).
std::string glb_json(const std::string& buf) {
    if (buf.size() < 20) return "";
    uint32_t len, type;
    std::memcpy(&len, buf.data() + 12, 4);
    std::memcpy(&type, buf.data() + 16, 4);
    if (type != 0x4E4F534Au || len > buf.size() - 20) return "";
    return buf.substr(20, len);
}

// Checks every buffer and image URI of the asset's JSON before anything is loaded.
bool check_uris(const std::string& name, const std::string& json_text, size_t file_bytes,
                const std::string& asset_dir, std::string& error) {
    const nlohmann::json j = nlohmann::json::parse(json_text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) return true;  // tinygltf reports the parse error
    for (const char* kind : {"buffers", "images"}) {
        const auto it = j.find(kind);
        if (it == j.end() || !it->is_array()) continue;
        for (size_t i = 0; i < it->size(); ++i) {
            const auto& item = (*it)[i];
            if (!item.is_object()) continue;
            const auto u = item.find("uri");
            if (u == item.end() || !u->is_string()) continue;
            const std::string uri = u->get<std::string>();
            const std::string what = std::string(kind).substr(0, std::strlen(kind) - 1) + " " + std::to_string(i);
            if (is_data_uri(uri)) {
                const auto bl = item.find("byteLength");
                if (bl != item.end() && bl->is_number() && bl->get<double>() > static_cast<double>(file_bytes))
                    return fail(error, name, 0,
                                what + ": data URI declares " + std::to_string(bl->get<double>()) +
                                    " bytes, more than the file's " + std::to_string(file_bytes));
                continue;
            }
            const std::string why = refuse_external_uri(asset_dir, uri);
            if (!why.empty()) return fail(error, name, 0, what + ": URI " + quote_token(uri.data(), uri.data() + uri.size()) + " refused: " + why);
        }
    }
    return true;
}

// ---- file-system callbacks for tinygltf: only files inside the asset folder ----

struct FolderJail {
    std::string dir;      // canonical asset folder, or "" (nothing may be read)
    size_t bytes_read = 0;
};

bool jail_allows(const FolderJail& jail, const std::string& path) {
    if (jail.dir.empty() || !inside(jail.dir, path)) return false;
    std::error_code ec;
    const fs::path real = fs::canonical(path, ec);
    return !ec && inside(jail.dir, real.string()) && fs::is_regular_file(real, ec);
}

bool jail_exists(const std::string& path, void* user) { return jail_allows(*static_cast<FolderJail*>(user), path); }

std::string jail_expand(const std::string& path, void*) { return path; }

bool jail_read(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    FolderJail& jail = *static_cast<FolderJail*>(user);
    if (!jail_allows(jail, path)) {
        if (err) *err += "outside the asset folder";
        return false;
    }
    std::string buf, e;
    if (!load_file(path, buf, e)) {
        if (err) *err += e;
        return false;
    }
    jail.bytes_read += buf.size();
    out->assign(buf.begin(), buf.end());
    return true;
}

bool jail_write(std::string*, const std::string&, const std::vector<unsigned char>&, void*) { return false; }

bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
    return true;  // images are not needed and never decoded
}

// ---- transforms ----

// The node's local matrix: `matrix` if given, else T * R * S.
Mat4 local_matrix(const tinygltf::Node& n) {
    if (n.matrix.size() == 16) {
        Mat4 m;
        for (int i = 0; i < 16; ++i) m[i] = n.matrix[i];
        return m;
    }
    Mat4 t = identity4(), r = identity4(), s = identity4();
    if (n.translation.size() == 3)
        for (int i = 0; i < 3; ++i) t[12 + i] = n.translation[i];
    if (n.rotation.size() == 4) {
        const double x = n.rotation[0], y = n.rotation[1], z = n.rotation[2], w = n.rotation[3];
        r = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w), 0,
             2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w), 0,
             2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y), 0,
             0, 0, 0, 1};
    }
    if (n.scale.size() == 3)
        for (int i = 0; i < 3; ++i) s[i * 5] = n.scale[i];
    return mul4(t, mul4(r, s));
}

// ---- accessors ----

struct AccessorView {
    const unsigned char* data = nullptr;
    size_t count = 0, stride = 0;
};

// Locates accessor `index` with the expected type; every element must lie inside its view and
// buffer.
bool view_accessor(const std::string& name, const tinygltf::Model& m, int index, int type, size_t comp_size,
                   const char* what, AccessorView& v, std::string& error) {
    const std::string where = std::string(what) + " accessor " + std::to_string(index);
    if (index < 0 || static_cast<size_t>(index) >= m.accessors.size())
        return fail(error, name, 0, where + " does not exist");
    const tinygltf::Accessor& a = m.accessors[static_cast<size_t>(index)];
    if (a.type != type) return fail(error, name, 0, where + " has the wrong element type");
    if (a.sparse.isSparse) return fail(error, name, 0, where + " is sparse (not supported)");
    if (a.bufferView < 0 || static_cast<size_t>(a.bufferView) >= m.bufferViews.size())
        return fail(error, name, 0, where + " has no buffer view");
    const tinygltf::BufferView& bv = m.bufferViews[static_cast<size_t>(a.bufferView)];
    if (bv.buffer < 0 || static_cast<size_t>(bv.buffer) >= m.buffers.size())
        return fail(error, name, 0, where + ": buffer view without a buffer");
    const size_t buf_size = m.buffers[static_cast<size_t>(bv.buffer)].data.size();
    const size_t elem = comp_size * static_cast<size_t>(tinygltf::GetNumComponentsInType(static_cast<uint32_t>(type)));
    const size_t stride = bv.byteStride ? bv.byteStride : elem;
    if (stride < elem) return fail(error, name, 0, where + ": byteStride smaller than an element");
    if (bv.byteOffset > buf_size || bv.byteLength > buf_size - bv.byteOffset)
        return fail(error, name, 0, where + ": buffer view exceeds its buffer");
    if (a.count > 0 &&
        (a.byteOffset > bv.byteLength || (a.count - 1) > (bv.byteLength - a.byteOffset) / stride ||
         (a.count - 1) * stride + elem > bv.byteLength - a.byteOffset))
        return fail(error, name, 0, where + ": " + std::to_string(a.count) + " elements exceed its buffer view");
    v.data = m.buffers[static_cast<size_t>(bv.buffer)].data.data() + bv.byteOffset + a.byteOffset;
    v.count = a.count;
    v.stride = stride;
    return true;
}

// Appends one primitive, transformed by `world`, to `out`.
bool add_primitive(const std::string& name, const tinygltf::Model& m, const tinygltf::Primitive& p,
                   const Mat4& world, size_t budget, MeshData& out, std::string& error) {
    const auto pos = p.attributes.find("POSITION");
    if (pos == p.attributes.end()) return fail(error, name, 0, "triangle primitive without POSITION");
    if (pos->second < 0 || static_cast<size_t>(pos->second) >= m.accessors.size() ||
        m.accessors[static_cast<size_t>(pos->second)].componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
        return fail(error, name, 0, "POSITION must be a float VEC3 accessor");
    AccessorView pv;
    if (!view_accessor(name, m, pos->second, TINYGLTF_TYPE_VEC3, 4, "POSITION", pv, error)) return false;
    std::vector<uint32_t> idx;
    if (p.indices >= 0) {
        if (static_cast<size_t>(p.indices) >= m.accessors.size())
            return fail(error, name, 0, "index accessor " + std::to_string(p.indices) + " does not exist");
        const int ct = m.accessors[static_cast<size_t>(p.indices)].componentType;
        const size_t cs = ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ? 1
                          : ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                          : ct == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT ? 4 : 0;
        if (cs == 0) return fail(error, name, 0, "indices must be unsigned byte, short or int");
        AccessorView iv;
        if (!view_accessor(name, m, p.indices, TINYGLTF_TYPE_SCALAR, cs, "index", iv, error)) return false;
        if (iv.count > budget) return check_budget(name, budget, 0, iv.count, error);
        idx.resize(iv.count);
        for (size_t i = 0; i < iv.count; ++i) {
            const unsigned char* e = iv.data + i * iv.stride;
            uint32_t v = 0;
            if (cs == 1) v = e[0];
            else if (cs == 2) { uint16_t s; std::memcpy(&s, e, 2); v = s; }
            else std::memcpy(&v, e, 4);
            if (v >= pv.count)
                return fail(error, name, 0, "index " + std::to_string(v) + " out of range (" + vcount_msg(pv.count));
            idx[i] = v;
        }
    } else {
        if (pv.count > budget) return check_budget(name, budget, pv.count, 0, error);
        idx.resize(pv.count);
        for (size_t i = 0; i < pv.count; ++i) idx[i] = static_cast<uint32_t>(i);
    }
    // Triangles of this primitive, as corners into idx.
    std::vector<uint32_t> tris;
    const size_t n = idx.size();
    if (p.mode == TINYGLTF_MODE_TRIANGLES) {
        for (size_t i = 0; i + 2 < n; i += 3) tris.insert(tris.end(), {idx[i], idx[i + 1], idx[i + 2]});
    } else if (p.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (size_t i = 0; i + 2 < n; ++i)
            if (i % 2 == 0) tris.insert(tris.end(), {idx[i], idx[i + 1], idx[i + 2]});
            else tris.insert(tris.end(), {idx[i + 1], idx[i], idx[i + 2]});
    } else {  // TRIANGLE_FAN
        for (size_t i = 1; i + 1 < n; ++i) tris.insert(tris.end(), {idx[0], idx[i], idx[i + 1]});
    }
    const size_t nv0 = out.positions.size() / 3;
    if (!check_budget(name, budget, nv0 + pv.count, out.triangles.size() / 3 + tris.size() / 3, error)) return false;
    if (nv0 + pv.count > std::numeric_limits<uint32_t>::max()) return fail(error, name, 0, "too many vertices");
    out.positions.reserve(out.positions.size() + 3 * pv.count);
    for (size_t i = 0; i < pv.count; ++i) {
        float q[3];
        std::memcpy(q, pv.data + i * pv.stride, 12);
        for (int r = 0; r < 3; ++r)
            out.positions.push_back(world[r] * q[0] + world[4 + r] * q[1] + world[8 + r] * q[2] + world[12 + r]);
    }
    for (uint32_t t : tris) out.triangles.push_back(static_cast<uint32_t>(nv0) + t);
    return true;
}

bool is_triangles(int mode) {
    return mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

// The root nodes to draw: the default scene's, else every scene's, else every parentless node.
std::vector<int> root_nodes(const tinygltf::Model& m) {
    std::vector<int> roots;
    if (m.defaultScene >= 0 && static_cast<size_t>(m.defaultScene) < m.scenes.size())
        return m.scenes[static_cast<size_t>(m.defaultScene)].nodes;
    if (!m.scenes.empty()) {
        for (const auto& s : m.scenes) roots.insert(roots.end(), s.nodes.begin(), s.nodes.end());
        return roots;
    }
    std::vector<char> child(m.nodes.size(), 0);
    for (const auto& n : m.nodes)
        for (int c : n.children)
            if (c >= 0 && static_cast<size_t>(c) < child.size()) child[static_cast<size_t>(c)] = 1;
    for (size_t i = 0; i < m.nodes.size(); ++i)
        if (!child[i]) roots.push_back(static_cast<int>(i));
    return roots;
}

// One visit of a node instance during the walk: its node, its world matrix, and the nearest joint
// at or above it (an index into the scene's joints, -1 for none; see SceneSkin).
struct Visit {
    int node;
    Mat4 world;
    int32_t joint;
};

// Walks the node hierarchy from the roots depth first, in file order, calling `visit` for every
// node instance (a node under several parents once per path). `joint_of_node` (may be empty)
// maps a node to its joint index, -1 for none.
template <class F>
bool walk_scene(const std::string& name, const tinygltf::Model& m, size_t budget,
                const std::vector<int32_t>& joint_of_node, std::string& error, F&& visit) {
    struct Item { int node; Mat4 parent; size_t depth; int32_t joint; };
    std::vector<Item> stack;
    // Depth first, in file order: roots and children are pushed last to first.
    const std::vector<int> roots = root_nodes(m);
    for (auto r = roots.rbegin(); r != roots.rend(); ++r) stack.push_back({*r, identity4(), 0, -1});
    size_t visits = 0;
    while (!stack.empty()) {
        const Item it = stack.back();
        stack.pop_back();
        if (it.node < 0 || static_cast<size_t>(it.node) >= m.nodes.size())
            return fail(error, name, 0, "node " + std::to_string(it.node) + " does not exist");
        // A hierarchy deeper than the node count has a cycle; visits past the budget would
        // instance more geometry than the input justifies.
        if (it.depth > m.nodes.size()) return fail(error, name, 0, "node hierarchy has a cycle");
        if (++visits > budget) return fail(error, name, 0, "more node instances than input bytes");
        const tinygltf::Node& n = m.nodes[static_cast<size_t>(it.node)];
        const Mat4 world = mul4(it.parent, local_matrix(n));
        const int32_t joint = joint_of_node.empty() || joint_of_node[static_cast<size_t>(it.node)] < 0
                                  ? it.joint : joint_of_node[static_cast<size_t>(it.node)];
        if (!visit(Visit{it.node, world, joint})) return false;
        for (auto c = n.children.rbegin(); c != n.children.rend(); ++c)
            stack.push_back({*c, world, it.depth + 1, joint});
    }
    return true;
}

// The node's mesh, checked; null when it has none.
bool node_mesh(const std::string& name, const tinygltf::Model& m, const tinygltf::Node& n, const tinygltf::Mesh*& mesh,
               std::string& error) {
    mesh = nullptr;
    if (n.mesh < 0) return true;
    if (static_cast<size_t>(n.mesh) >= m.meshes.size())
        return fail(error, name, 0, "mesh " + std::to_string(n.mesh) + " does not exist");
    mesh = &m.meshes[static_cast<size_t>(n.mesh)];
    return true;
}

// ---- skins ----
// The skins of the drawn meshes become one SkinData. Its joints are the union of those skins'
// joint nodes (first skin first); its frame is the first skin's mesh space, whose meshes keep
// their positions as stored (the bind pose). The other meshes are brought into that frame through
// the rest pose: M0 = world(j) * inverseBind(j) for the first skin's first joint j takes the frame
// to world coordinates at rest, so an unskinned mesh is placed at M0^-1 * its node's world, and a
// mesh of another skin at M0^-1 * its own skin's blend at rest. A joint only other skins name gets
// inverse bind world(j)^-1 * M0 (the frame to the joint's frame at rest). An unskinned mesh under
// a joint node follows that joint (weight 1; a prop in a hand); elsewhere it gets zero weights.

struct SceneSkin {
    std::vector<int> skins;                      // skins drawn, in order of first use
    std::vector<std::vector<uint32_t>> joints;   // per drawn skin: its joints' indices in the union
    std::vector<std::vector<Mat4>> inverse_bind; // per drawn skin: its own inverse bind matrices
    std::vector<int32_t> joint_of_node;          // per node: its index in the union, -1 if not a joint
    std::vector<int> node_parent;                // per node: the node listing it as a child, -1 if none
    std::vector<int> joint_nodes;                // per joint of the union: its node
    std::vector<Mat4> union_inverse_bind, joint_world;
    Mat4 frame_to_world = identity4();           // M0: the first skin's mesh space -> world at rest
    Mat4 to_frame = identity4();                 // M0^-1
    // per output vertex, kMaxInfluences slots, filled while the primitives are added
    std::vector<uint32_t> vertex_joints;
    std::vector<double> vertex_weights;
    bool second_set = false;                     // some primitive had JOINTS_1
};

// World matrices of the nodes at rest, from the parent links (every node, drawn or not: joints
// need not be in the scene). A node listed as a child twice, or a cycle, is refused when a joint
// depends on it; `need` lists the nodes whose matrices are wanted.
bool joint_worlds(const std::string& name, const tinygltf::Model& m, const std::vector<int>& need,
                  std::vector<int>& parent, std::vector<Mat4>& world, std::string& error) {
    const size_t nn = m.nodes.size();
    parent.assign(nn, -1);
    std::vector<char> twice(nn, 0);
    for (size_t i = 0; i < nn; ++i)
        for (int c : m.nodes[i].children) {
            if (c < 0 || static_cast<size_t>(c) >= nn)
                return fail(error, name, 0, "node " + std::to_string(i) + ": child " + std::to_string(c) + " does not exist");
            if (parent[static_cast<size_t>(c)] != -1) twice[static_cast<size_t>(c)] = 1;
            parent[static_cast<size_t>(c)] = static_cast<int>(i);
        }
    world.assign(nn, identity4());
    std::vector<char> done(nn, 0);
    std::vector<int> chain;
    for (int start : need) {
        chain.clear();
        for (int at = start; at != -1 && !done[static_cast<size_t>(at)]; at = parent[static_cast<size_t>(at)]) {
            if (twice[static_cast<size_t>(at)])
                return fail(error, name, 0, "skin: node " + std::to_string(at) + " above joint node " + std::to_string(start) +
                                                " has more than one parent");
            if (chain.size() > nn)
                return fail(error, name, 0, "skin: the nodes above joint node " + std::to_string(start) + " form a cycle");
            chain.push_back(at);
        }
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            const size_t i = static_cast<size_t>(*it);
            const int p = parent[i];
            world[i] = p == -1 ? local_matrix(m.nodes[i]) : mul4(world[static_cast<size_t>(p)], local_matrix(m.nodes[i]));
            done[i] = 1;
        }
    }
    return true;
}

// Reads the used skins' joints and matrices into `sk` (the skins are those of drawn mesh nodes).
bool gather_skins(const std::string& name, const tinygltf::Model& m, size_t budget, SceneSkin& sk, std::string& error) {
    std::vector<char> used(m.skins.size(), 0);
    const bool walked = walk_scene(name, m, budget, {}, error, [&](const Visit& v) {
        const tinygltf::Node& n = m.nodes[static_cast<size_t>(v.node)];
        const tinygltf::Mesh* mesh = nullptr;
        if (!node_mesh(name, m, n, mesh, error)) return false;
        if (!mesh || n.skin < 0) return true;
        if (static_cast<size_t>(n.skin) >= m.skins.size())
            return fail(error, name, 0, "node " + std::to_string(v.node) + ": skin " + std::to_string(n.skin) + " does not exist");
        if (!used[static_cast<size_t>(n.skin)]) sk.skins.push_back(n.skin);
        used[static_cast<size_t>(n.skin)] = 1;
        return true;
    });
    if (!walked) return false;
    if (sk.skins.empty()) return true;
    sk.joint_of_node.assign(m.nodes.size(), -1);
    std::vector<int> need;
    for (int s : sk.skins) {
        const tinygltf::Skin& skin = m.skins[static_cast<size_t>(s)];
        const std::string where = "skin " + std::to_string(s);
        if (skin.joints.empty()) return fail(error, name, 0, where + " has no joints");
        std::vector<char> seen(m.nodes.size(), 0);
        for (int j : skin.joints) {
            if (j < 0 || static_cast<size_t>(j) >= m.nodes.size())
                return fail(error, name, 0, where + ": joint node " + std::to_string(j) + " does not exist");
            if (seen[static_cast<size_t>(j)]) return fail(error, name, 0, where + ": joint node " + std::to_string(j) + " listed twice");
            seen[static_cast<size_t>(j)] = 1;
            need.push_back(j);
        }
    }
    std::vector<Mat4> world;
    if (!joint_worlds(name, m, need, sk.node_parent, world, error)) return false;
    for (size_t si = 0; si < sk.skins.size(); ++si) {
        const tinygltf::Skin& skin = m.skins[static_cast<size_t>(sk.skins[si])];
        const std::string where = "skin " + std::to_string(sk.skins[si]);
        std::vector<Mat4> ibm(skin.joints.size(), identity4());
        if (skin.inverseBindMatrices >= 0) {
            if (static_cast<size_t>(skin.inverseBindMatrices) >= m.accessors.size() ||
                m.accessors[static_cast<size_t>(skin.inverseBindMatrices)].componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
                return fail(error, name, 0, where + ": inverseBindMatrices must be a float MAT4 accessor");
            AccessorView av;
            if (!view_accessor(name, m, skin.inverseBindMatrices, TINYGLTF_TYPE_MAT4, 4, "inverseBindMatrices", av, error))
                return false;
            if (av.count != skin.joints.size())
                return fail(error, name, 0, where + ": " + std::to_string(av.count) + " inverse bind matrices for " +
                                                std::to_string(skin.joints.size()) + " joints");
            for (size_t j = 0; j < av.count; ++j) {
                float f[16];
                std::memcpy(f, av.data + j * av.stride, sizeof f);
                for (int k = 0; k < 16; ++k) {
                    if (!std::isfinite(f[k]))
                        return fail(error, name, 0, where + ": inverse bind matrix " + std::to_string(j) + " holds NaN or infinity");
                    ibm[j][static_cast<size_t>(k)] = f[k];
                }
            }
        }
        if (si == 0) {
            sk.frame_to_world = mul4(world[static_cast<size_t>(skin.joints[0])], ibm[0]);
            if (!invert4(sk.frame_to_world, sk.to_frame))
                return fail(error, name, 0, where + ": joint 0's world matrix times its inverse bind matrix is singular");
        }
        std::vector<uint32_t> local;
        for (size_t j = 0; j < skin.joints.size(); ++j) {
            const size_t node = static_cast<size_t>(skin.joints[j]);
            if (sk.joint_of_node[node] < 0) {
                Mat4 inverse_bind = ibm[j];
                if (si > 0) {
                    Mat4 world_inverse;
                    if (!invert4(world[node], world_inverse))
                        return fail(error, name, 0, where + ": joint node " + std::to_string(node) + " has a singular world matrix");
                    inverse_bind = mul4(world_inverse, sk.frame_to_world);
                }
                sk.joint_of_node[node] = static_cast<int32_t>(sk.joint_nodes.size());
                sk.joint_nodes.push_back(static_cast<int>(node));
                sk.union_inverse_bind.push_back(inverse_bind);
                sk.joint_world.push_back(world[node]);
            }
            local.push_back(static_cast<uint32_t>(sk.joint_of_node[node]));
        }
        sk.joints.push_back(std::move(local));
        sk.inverse_bind.push_back(std::move(ibm));
    }
    return true;
}

// Reads a skinned primitive's JOINTS_n/WEIGHTS_n (n = 0, and 1 when present) for its `nv`
// vertices: kMaxInfluences slots per vertex, joints as indices into the skin's own joint list
// (`skin_joints` of them), weights normalised per vertex.
bool read_influences(const std::string& name, const tinygltf::Model& m, const tinygltf::Primitive& p, size_t nv,
                     size_t skin_joints, std::vector<uint32_t>& joints, std::vector<double>& weights, bool& second_set,
                     std::string& error) {
    joints.assign(nv * kMaxInfluences, 0);
    weights.assign(nv * kMaxInfluences, 0.0);
    for (int set = 0; set < 2; ++set) {
        const std::string jn = "JOINTS_" + std::to_string(set), wn = "WEIGHTS_" + std::to_string(set);
        const auto ja = p.attributes.find(jn), wa = p.attributes.find(wn);
        const bool has_j = ja != p.attributes.end(), has_w = wa != p.attributes.end();
        if (set == 0 && (!has_j || !has_w)) return fail(error, name, 0, "skinned primitive without JOINTS_0 and WEIGHTS_0");
        if (has_j != has_w) return fail(error, name, 0, "skinned primitive has " + (has_j ? jn : wn) + " without " + (has_j ? wn : jn));
        if (!has_j) continue;
        if (set == 1) second_set = true;
        auto component = [&](int index) {
            return index >= 0 && static_cast<size_t>(index) < m.accessors.size()
                       ? m.accessors[static_cast<size_t>(index)].componentType : -1;
        };
        const int jt = component(ja->second), wt = component(wa->second);
        const size_t js = jt == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ? 1 : jt == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2 : 0;
        const size_t ws = wt == TINYGLTF_COMPONENT_TYPE_FLOAT ? 4 : wt == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ? 1
                          : wt == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2 : 0;
        if (js == 0) return fail(error, name, 0, jn + " must be an unsigned byte or short VEC4 accessor");
        if (ws == 0) return fail(error, name, 0, wn + " must be a float or normalized unsigned byte or short VEC4 accessor");
        AccessorView jv, wv;
        if (!view_accessor(name, m, ja->second, TINYGLTF_TYPE_VEC4, js, jn.c_str(), jv, error)) return false;
        if (!view_accessor(name, m, wa->second, TINYGLTF_TYPE_VEC4, ws, wn.c_str(), wv, error)) return false;
        if (jv.count != nv || wv.count != nv)
            return fail(error, name, 0, jn + " and " + wn + " have " + std::to_string(jv.count) + " and " + std::to_string(wv.count) +
                                            " elements for " + std::to_string(nv) + " vertices");
        for (size_t v = 0; v < nv; ++v)
            for (size_t k = 0; k < 4; ++k) {
                const unsigned char* je = jv.data + v * jv.stride + k * js;
                const unsigned char* we = wv.data + v * wv.stride + k * ws;
                uint32_t j = 0;
                if (js == 1) j = je[0];
                else { uint16_t u; std::memcpy(&u, je, 2); j = u; }
                double w = 0;
                if (ws == 4) { float f; std::memcpy(&f, we, 4); w = f; }
                else if (ws == 1) w = we[0] / 255.0;
                else { uint16_t u; std::memcpy(&u, we, 2); w = u / 65535.0; }
                if (!std::isfinite(w) || w < 0)
                    return fail(error, name, 0, wn + ": vertex " + std::to_string(v) + " has a weight that is negative, NaN or infinite");
                if (j >= skin_joints)
                    return fail(error, name, 0, jn + ": vertex " + std::to_string(v) + " names joint " + std::to_string(j) +
                                                    ", out of range (the skin has " + std::to_string(skin_joints) + " joints)");
                joints[v * kMaxInfluences + set * 4 + k] = j;
                weights[v * kMaxInfluences + set * 4 + k] = w;
            }
    }
    for (size_t v = 0; v < nv; ++v)
        if (!normalise_row(&weights[v * kMaxInfluences], &joints[v * kMaxInfluences], kMaxInfluences))
            return fail(error, name, 0, "vertex " + std::to_string(v) + ": weights do not sum to a finite number");
    return true;
}

// Adds the instance's triangle primitives to `out`: placed in world coordinates when the scene has
// no skin, else in the first skin's mesh space with their weights (see SceneSkin above).
bool add_instance(const std::string& name, const tinygltf::Model& m, const Visit& v, size_t budget, SceneSkin* sk,
                  MeshData& out, std::string& error) {
    const tinygltf::Node& n = m.nodes[static_cast<size_t>(v.node)];
    const tinygltf::Mesh* mesh = nullptr;
    if (!node_mesh(name, m, n, mesh, error)) return false;
    if (!mesh) return true;
    size_t si = 0;  // the node's skin among the drawn ones
    if (sk && n.skin >= 0)
        while (sk->skins[si] != n.skin) ++si;  // gather_skins found every drawn skin
    const bool skinned = sk && n.skin >= 0;
    const Mat4 place = !sk ? v.world : !skinned ? mul4(sk->to_frame, v.world) : identity4();
    for (const auto& p : mesh->primitives) {
        if (!is_triangles(p.mode)) continue;
        const size_t nv0 = out.positions.size() / 3;
        if (!add_primitive(name, m, p, place, budget, out, error)) return false;
        if (!sk) continue;
        const size_t nv = out.positions.size() / 3 - nv0;
        std::vector<uint32_t> joints;
        std::vector<double> weights;
        if (skinned) {
            const std::vector<uint32_t>& local = sk->joints[si];
            if (!read_influences(name, m, p, nv, local.size(), joints, weights, sk->second_set, error)) return false;
            if (si > 0) {  // another skin: its blend at rest, into the first skin's mesh space
                const std::vector<Mat4>& ibm = sk->inverse_bind[si];
                for (size_t i = 0; i < nv; ++i) {
                    Mat4 blend{};
                    double* q = &out.positions[3 * (nv0 + i)];
                    for (size_t k = 0; k < kMaxInfluences; ++k) {
                        const double w = weights[i * kMaxInfluences + k];
                        if (w == 0) continue;
                        const uint32_t j = joints[i * kMaxInfluences + k];
                        const Mat4 jm = mul4(sk->joint_world[local[j]], ibm[j]);
                        for (size_t e = 0; e < 16; ++e) blend[e] += w * jm[e];
                    }
                    if (blend[15] == 0) continue;  // no weight: the vertex stays as stored
                    const double stored[3] = {q[0], q[1], q[2]};
                    double world[3];
                    transform_point(blend, stored, world);
                    transform_point(sk->to_frame, world, q);
                }
            }
            for (size_t i = 0; i < joints.size(); ++i)
                joints[i] = weights[i] == 0 ? 0 : local[joints[i]];
        } else {
            joints.assign(nv * kMaxInfluences, 0);
            weights.assign(nv * kMaxInfluences, 0.0);
            if (v.joint >= 0)  // under a joint node: the mesh follows that joint
                for (size_t i = 0; i < nv; ++i) {
                    joints[i * kMaxInfluences] = static_cast<uint32_t>(v.joint);
                    weights[i * kMaxInfluences] = 1;
                }
        }
        sk->vertex_joints.insert(sk->vertex_joints.end(), joints.begin(), joints.end());
        sk->vertex_weights.insert(sk->vertex_weights.end(), weights.begin(), weights.end());
    }
    return true;
}

// Every triangle primitive of the scene (see the file comment), and the skin when drawn meshes
// have one.
bool add_scene(const std::string& name, const tinygltf::Model& m, size_t budget, MeshData& out, std::string& error) {
    SceneSkin sk;
    if (!gather_skins(name, m, budget, sk, error)) return false;
    SceneSkin* skin = sk.skins.empty() ? nullptr : &sk;
    const bool ok = walk_scene(name, m, budget, sk.joint_of_node, error,
                               [&](const Visit& v) { return add_instance(name, m, v, budget, skin, out, error); });
    if (!ok || !skin) return ok;
    SkinData& s = out.skin;
    const size_t nj = sk.joint_nodes.size();
    s.influences = sk.second_set ? kMaxInfluences : 4;
    for (size_t j = 0; j < nj; ++j) {
        const int node = sk.joint_nodes[j];
        const std::string& jname = m.nodes[static_cast<size_t>(node)].name;
        s.joint_names.push_back(jname.empty() ? "node_" + std::to_string(node) : jname);
        s.gltf_nodes.push_back(node);
        s.inverse_bind.insert(s.inverse_bind.end(), sk.union_inverse_bind[j].begin(), sk.union_inverse_bind[j].end());
        s.joint_world.insert(s.joint_world.end(), sk.joint_world[j].begin(), sk.joint_world[j].end());
        // the joint's own hierarchy: its nearest ancestor node that is a joint (gather_skins
        // checked that the nodes above every joint form a chain)
        int32_t parent = -1;
        for (int at = sk.node_parent[static_cast<size_t>(node)]; at != -1 && parent < 0; at = sk.node_parent[static_cast<size_t>(at)])
            parent = sk.joint_of_node[static_cast<size_t>(at)];
        s.parents.push_back(parent);
    }
    const size_t nv = out.positions.size() / 3;
    for (size_t v = 0; v < nv; ++v)
        for (size_t k = 0; k < s.influences; ++k) {
            s.vertex_joints.push_back(sk.vertex_joints[v * kMaxInfluences + k]);
            s.vertex_weights.push_back(sk.vertex_weights[v * kMaxInfluences + k]);
        }
    return true;
}

}  // namespace

bool read_gltf(const std::string& name, const std::string& buf, bool binary, const std::string& asset_dir,
               MeshData& out, std::string& error) {
    if (buf.size() > std::numeric_limits<unsigned int>::max()) return fail(error, name, 0, "file too large for glTF");
    if (!check_uris(name, binary ? glb_json(buf) : buf, buf.size(), asset_dir, error)) return false;
    FolderJail jail{asset_dir};
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&jail_exists, &jail_expand, &jail_read, &jail_write, &jail});
    loader.SetImageLoader(&skip_image, nullptr);
    tinygltf::Model model;
    std::string err, warn;
    const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(buf.data()),
                                                        static_cast<unsigned int>(buf.size()), asset_dir)
                           : loader.LoadASCIIFromString(&model, &err, &warn, buf.data(),
                                                        static_cast<unsigned int>(buf.size()), asset_dir);
    if (!ok) {
        while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
        for (char& c : err)
            if (c == '\n') c = ';';
        return fail(error, name, 0, "glTF: " + (err.empty() ? std::string("cannot parse") : err));
    }
    // External buffers count towards the input size that bounds the output.
    if (!add_scene(name, model, buf.size() + jail.bytes_read, out, error)) return false;
    if (out.triangles.empty()) return fail(error, name, 0, "no triangle primitives in the scene");
    const std::string skin = skin_problem(out);
    if (!skin.empty()) return fail(error, name, 0, "skin: " + skin);
    return true;
}

}  // namespace detail
}  // namespace caio

// read_gltf.cpp: glTF 2.0 meshes (.gltf JSON with external or data-URI buffers, .glb) through
// tinygltf. Every triangle primitive (TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN; points and lines
// are skipped) reachable from the default scene's root nodes (all scenes' roots when there is no
// default scene; every parentless node when there are no scenes) is placed in world coordinates
// by its node's transform (matrix or T*R*S, composed down the hierarchy); a mesh used by several
// nodes appears once per node. POSITION must be float VEC3; indices unsigned byte, short or int.
// Normals are not read (MeshData normals stay empty).
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
using Mat4 = std::array<double, 16>;  // column-major, as glTF stores matrices

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

Mat4 identity() { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; }

Mat4 mul(const Mat4& a, const Mat4& b) {
    Mat4 c{};
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row) {
            double s = 0;
            for (int k = 0; k < 4; ++k) s += a[k * 4 + row] * b[col * 4 + k];
            c[col * 4 + row] = s;
        }
    return c;
}

// The node's local matrix: `matrix` if given, else T * R * S.
Mat4 local_matrix(const tinygltf::Node& n) {
    if (n.matrix.size() == 16) {
        Mat4 m;
        for (int i = 0; i < 16; ++i) m[i] = n.matrix[i];
        return m;
    }
    Mat4 t = identity(), r = identity(), s = identity();
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
    return mul(t, mul(r, s));
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
    const size_t elem = comp_size * static_cast<size_t>(type == TINYGLTF_TYPE_VEC3 ? 3 : 1);
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

// Walks the node hierarchy from the roots, adding every triangle primitive in world space.
bool add_scene(const std::string& name, const tinygltf::Model& m, size_t budget, MeshData& out, std::string& error) {
    struct Item { int node; Mat4 parent; size_t depth; };
    std::vector<Item> stack;
    // Depth first, in file order: roots and children are pushed last to first.
    const std::vector<int> roots = root_nodes(m);
    for (auto r = roots.rbegin(); r != roots.rend(); ++r) stack.push_back({*r, identity(), 0});
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
        const Mat4 world = mul(it.parent, local_matrix(n));
        if (n.mesh >= 0) {
            if (static_cast<size_t>(n.mesh) >= m.meshes.size())
                return fail(error, name, 0, "mesh " + std::to_string(n.mesh) + " does not exist");
            for (const auto& p : m.meshes[static_cast<size_t>(n.mesh)].primitives)
                if (is_triangles(p.mode) && !add_primitive(name, m, p, world, budget, out, error)) return false;
        }
        for (auto c = n.children.rbegin(); c != n.children.rend(); ++c) stack.push_back({*c, world, it.depth + 1});
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
    return true;
}

}  // namespace detail
}  // namespace caio

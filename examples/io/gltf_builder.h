// gltf_builder.h: what the glTF 2.0 writers share (the skeleton's, gltf_writer.cpp, the rig's,
// rig_writer.cpp, and the colliders', gltf_physics.cpp): a binary buffer with its bufferViews and
// accessors, the .glb container around a document and its buffer, and the choice between .glb and
// a self-contained .gltf by the path's extension.
#pragma once
#include "output_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace caio {
namespace gltf {

using nlohmann::json;

constexpr int kFloat = 5126, kUnsignedByte = 5121, kUnsignedShort = 5123, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

// The binary buffer and the bufferViews/accessors that describe it.
struct Builder {
    std::string bin;
    json views = json::array(), accessors = json::array();

    // Appends raw bytes as a new bufferView (4-byte aligned) and returns its index.
    int view(const void* data, size_t bytes, int target) {
        while (bin.size() % 4) bin.push_back('\0');
        json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}};
        if (target) v["target"] = target;
        bin.append(static_cast<const char*>(data), bytes);
        views.push_back(v);
        return int(views.size()) - 1;
    }
    // float32 VEC3 / SCALAR data with min/max per component.
    int floats(const std::vector<float>& data, int components) {
        const size_t count = data.size() / size_t(components);
        json lo = json::array(), hi = json::array();
        for (int c = 0; c < components; ++c) {
            float a = std::numeric_limits<float>::infinity(), b = -a;
            for (size_t i = 0; i < count; ++i) {
                a = std::min(a, data[i * components + c]);
                b = std::max(b, data[i * components + c]);
            }
            lo.push_back(a);
            hi.push_back(b);
        }
        const int v = view(data.data(), data.size() * sizeof(float), kArrayBuffer);
        accessors.push_back({{"bufferView", v}, {"componentType", kFloat}, {"count", count},
                             {"type", components == 3 ? "VEC3" : "SCALAR"}, {"min", lo}, {"max", hi}});
        return int(accessors.size()) - 1;
    }
    template <class Index>
    int indices(const std::vector<Index>& data, int component_type) {
        const int v = view(data.data(), data.size() * sizeof(Index), kElementArrayBuffer);
        const Index hi = data.empty() ? 0 : *std::max_element(data.begin(), data.end());
        const Index lo = data.empty() ? 0 : *std::min_element(data.begin(), data.end());
        accessors.push_back({{"bufferView", v}, {"componentType", component_type}, {"count", data.size()},
                             {"type", "SCALAR"}, {"min", {lo}}, {"max", {hi}}});
        return int(accessors.size()) - 1;
    }
};

// The .glb bytes: the 12-byte header, the JSON chunk (padded with spaces) and the BIN chunk
// (padded with zeros, as `bin` must already be to 4 bytes).
inline std::string glb(const json& doc, const std::string& bin) {
    auto append_u32 = [](std::string& s, uint32_t v) {
        char b[4];
        std::memcpy(b, &v, 4);  // glTF is little-endian, as is every platform this tool builds on
        s.append(b, 4);
    };
    std::string text = doc.dump();
    while (text.size() % 4) text.push_back(' ');
    std::string out;
    append_u32(out, 0x46546C67u);  // "glTF"
    append_u32(out, 2);
    append_u32(out, uint32_t(12 + 8 + text.size() + 8 + bin.size()));
    append_u32(out, uint32_t(text.size()));
    append_u32(out, 0x4E4F534Au);  // "JSON"
    out += text;
    append_u32(out, uint32_t(bin.size()));
    append_u32(out, 0x004E4942u);  // "BIN\0"
    out += bin;
    return out;
}

// Whether `path` ends in `suffix` (lower case), in any case.
inline bool ends_with(const std::string& path, const char* suffix) {
    const size_t n = std::strlen(suffix);
    if (path.size() < n) return false;
    for (size_t i = 0; i < n; ++i)
        if (std::tolower(static_cast<unsigned char>(path[path.size() - n + i])) != suffix[i]) return false;
    return true;
}

inline std::string base64(const std::string& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const uint32_t b0 = uint8_t(bytes[i]), b1 = i + 1 < bytes.size() ? uint8_t(bytes[i + 1]) : 0,
                       b2 = i + 2 < bytes.size() ? uint8_t(bytes[i + 2]) : 0;
        const uint32_t v = (b0 << 16) | (b1 << 8) | b2;
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? table[v & 63] : '=';
    }
    return out;
}

// Writes `doc` (its one buffer without a uri) and `bin` (padded to 4 bytes): .glb as the binary
// container, .gltf as JSON with the buffer embedded as a base64 data URI (one self-contained file).
// False with "path: what" for another extension or a write error.
inline bool write_document(const std::string& path, json doc, const std::string& bin, std::string& error) {
    if (ends_with(path, ".glb")) return write_bytes(path, glb(doc, bin), error);
    if (!ends_with(path, ".gltf")) {
        error = path + ": a glTF file ends in .glb or .gltf";
        return false;
    }
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(bin);
    return write_bytes(path, doc.dump(1) + "\n", error);
}

}  // namespace gltf
}  // namespace caio

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
    // JOINTS_n / WEIGHTS_n of a skinned primitive, `influences` (a multiple of 4, at most 8) slots
    // per vertex, added to `attributes`. Weights are written as floats that sum to 1 as floats (the
    // rounding goes to the vertex's heaviest slot); an unused slot names joint 0 with weight 0, as
    // the validator expects; a vertex with no weight at all is bound wholly to `fallback_joint`
    // (glTF has no unskinned vertex in a skinned primitive). Joints as unsigned bytes up to 256
    // joints, else unsigned shorts.
    void skin_weights(const std::vector<uint32_t>& vertex_joints, const std::vector<double>& vertex_weights,
                      size_t influences, size_t joint_count, uint32_t fallback_joint, json& attributes) {
        const size_t nv = influences ? vertex_weights.size() / influences : 0;
        std::vector<uint16_t> joints(influences * nv, 0);
        std::vector<float> weights(influences * nv, 0.0f);
        for (size_t i = 0; i < nv; ++i) {
            size_t heaviest = 0;
            for (size_t k = 0; k < influences; ++k) {
                const double w = vertex_weights[influences * i + k];
                if (!(w > 0)) continue;
                joints[influences * i + k] = uint16_t(vertex_joints[influences * i + k]);
                weights[influences * i + k] = float(w);
                if (w > vertex_weights[influences * i + heaviest]) heaviest = k;
            }
            if (!(vertex_weights[influences * i + heaviest] > 0)) {
                joints[influences * i] = uint16_t(fallback_joint);
                weights[influences * i] = 1.0f;
                continue;
            }
            float rest = 0;
            for (size_t k = 0; k < influences; ++k)
                if (k != heaviest) rest += weights[influences * i + k];
            weights[influences * i + heaviest] = 1.0f - rest;
        }
        for (size_t set = 0; set * 4 < influences; ++set) {
            std::vector<uint16_t> j16(4 * nv);
            std::vector<float> w4(4 * nv);
            for (size_t i = 0; i < nv; ++i)
                for (size_t k = 0; k < 4; ++k) {
                    j16[4 * i + k] = joints[influences * i + 4 * set + k];
                    w4[4 * i + k] = weights[influences * i + 4 * set + k];
                }
            if (joint_count <= 256) {
                const std::vector<uint8_t> small(j16.begin(), j16.end());
                const int v = view(small.data(), small.size(), kArrayBuffer);
                accessors.push_back({{"bufferView", v}, {"componentType", kUnsignedByte}, {"count", nv}, {"type", "VEC4"}});
            } else {
                const int v = view(j16.data(), j16.size() * sizeof(uint16_t), kArrayBuffer);
                accessors.push_back({{"bufferView", v}, {"componentType", kUnsignedShort}, {"count", nv}, {"type", "VEC4"}});
            }
            attributes["JOINTS_" + std::to_string(set)] = int(accessors.size()) - 1;
            const int wv = view(w4.data(), w4.size() * sizeof(float), kArrayBuffer);
            accessors.push_back({{"bufferView", wv}, {"componentType", kFloat}, {"count", nv}, {"type", "VEC4"}});
            attributes["WEIGHTS_" + std::to_string(set)] = int(accessors.size()) - 1;
        }
    }
    // Column-major float MAT4s (inverse bind matrices); no target, as the spec asks of them.
    int matrices(const std::vector<float>& m) {
        const int v = view(m.data(), m.size() * sizeof(float), 0);
        accessors.push_back({{"bufferView", v}, {"componentType", kFloat}, {"count", m.size() / 16}, {"type", "MAT4"}});
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

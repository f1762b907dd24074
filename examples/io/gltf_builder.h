// gltf_builder.h: what the glTF 2.0 writers share (the skeleton's, gltf_writer.cpp, and the
// rig's, rig_writer.cpp): a binary buffer with its bufferViews and accessors, and the .glb
// container around a document and its buffer.
#pragma once
#include <nlohmann/json.hpp>

#include <algorithm>
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

}  // namespace gltf
}  // namespace caio

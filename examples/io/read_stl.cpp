// read_stl.cpp: STL meshes, binary and ASCII. A file whose size is exactly 84 + 50 * (the
// triangle count at byte 80) is binary, even if it starts with "solid" (some exporters write
// that); otherwise it must be ASCII ("solid ... facet normal ... outer loop, vertex x y z (3x),
// endloop, endfacet ... endsolid", several solids allowed). STL is single precision: ASCII
// values are rounded to float as binary ones are, so both encodings of a mesh read the same.
// STL stores a triangle soup; equal positions are merged into one vertex so that closed meshes
// come out closed. Facet normals are ignored (MeshData normals stay empty).
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>

#include "readers.h"
#include "large_pages.h"

namespace caio {
namespace detail {
namespace {

// Merges equal float positions (by bit pattern, with -0 folded into +0).
struct VertexMerger {
    struct Key {
        uint32_t b[3];
        bool operator==(const Key& o) const { return b[0] == o.b[0] && b[1] == o.b[1] && b[2] == o.b[2]; }
    };
    struct Hash {
        size_t operator()(const Key& k) const {
            uint64_t h = 1469598103934665603ull;
            for (uint32_t v : k.b) h = (h ^ v) * 1099511628211ull;
            return static_cast<size_t>(h ^ (h >> 29));
        }
    };
    std::unordered_map<Key, uint32_t, Hash> index;
    MeshData& out;
    explicit VertexMerger(MeshData& m) : out(m) {}
    uint32_t add(const float p[3]) {
        Key k;
        for (int i = 0; i < 3; ++i) {
            const float v = p[i] + 0.0f;
            std::memcpy(&k.b[i], &v, 4);
        }
        auto it = index.emplace(k, static_cast<uint32_t>(out.positions.size() / 3));
        if (it.second)
            for (int i = 0; i < 3; ++i) out.positions.push_back(static_cast<double>(p[i]));
        return it.first->second;
    }
};

bool is_binary_stl(const std::string& buf) {
    if (buf.size() < 84) return false;
    uint32_t n;
    std::memcpy(&n, buf.data() + 80, 4);  // little endian on every supported host
    return (buf.size() - 84) % 50 == 0 && (buf.size() - 84) / 50 == n;
}

bool read_binary_stl(const std::string& path, const std::string& buf, MeshData& out, std::string& error) {
    const size_t n = (buf.size() - 84) / 50;
    if (n == 0) return fail(error, path, 0, "binary STL with no triangles");
    VertexMerger merge(out);
    ca::reserve_large(out.triangles, n * 3);
    for (size_t t = 0; t < n; ++t) {
        const char* rec = buf.data() + 84 + 50 * t + 12;  // skip the facet normal
        for (int v = 0; v < 3; ++v) {
            float p[3];
            std::memcpy(p, rec + 12 * v, 12);
            out.triangles.push_back(merge.add(p));
        }
    }
    return true;
}

bool read_ascii_stl(const std::string& path, const std::string& buf, MeshData& out, std::string& error) {
    LineReader lr(buf);
    const char *lb, *le, *tb, *te;
    VertexMerger merge(out);
    uint32_t loop[3];
    int in_loop = -1;  // vertices seen in the open loop, -1 outside a loop
    bool solid = false;
    while (lr.next(lb, le)) {
        Tok t{lb, le};
        if (!t.next(tb, te)) continue;
        const std::string kw(tb, te);
        if (kw == "solid") {
            solid = true;
        } else if (!solid) {
            return fail(error, path, lr.line, "not an STL file (ASCII STL starts with 'solid')");
        } else if (kw == "vertex") {
            if (in_loop < 0) return fail(error, path, lr.line, "vertex outside 'outer loop'");
            if (in_loop == 3) return fail(error, path, lr.line, "facet with more than 3 vertices");
            float p[3];
            for (float& c : p) {
                double d;
                if (!t.next(tb, te)) return fail(error, path, lr.line, "vertex needs 3 coordinates");
                if (!parse_double_token(tb, te, d)) return fail(error, path, lr.line, "bad number " + quote_token(tb, te));
                c = static_cast<float>(d);
            }
            loop[in_loop++] = merge.add(p);
        } else if (kw == "outer") {
            if (in_loop >= 0) return fail(error, path, lr.line, "nested 'outer loop'");
            in_loop = 0;
        } else if (kw == "endloop") {
            if (in_loop != 3)
                return fail(error, path, lr.line,
                            "facet with " + std::to_string(in_loop < 0 ? 0 : in_loop) + " vertices (need 3)");
            out.triangles.insert(out.triangles.end(), loop, loop + 3);
            in_loop = -1;
        } else if (kw == "endsolid") {
            solid = false;
        } else if (kw != "facet" && kw != "endfacet") {
            return fail(error, path, lr.line, "unknown STL keyword " + quote_token(tb, te));
        }
    }
    if (in_loop >= 0) return fail(error, path, 0, "file truncated inside a facet");
    if (out.triangles.empty()) return fail(error, path, 0, "no facets");
    return true;
}

}  // namespace

bool read_stl(const std::string& path, const std::string& buf, MeshData& out, std::string& error) {
    if (is_binary_stl(buf)) return read_binary_stl(path, buf, out, error);
    return read_ascii_stl(path, buf, out, error);
}

}  // namespace detail
}  // namespace caio

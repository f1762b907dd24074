// read_off.cpp: OFF meshes ([ST][C][N]OFF headers, comments, counts on the header line or the
// next one, polygons fan-triangulated, face colours ignored). NOFF gives per-vertex normals.
#include "readers.h"
#include "large_pages.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace caio {
namespace detail {
bool read_off(const std::string& path, const std::string& buf, MeshData& out, std::string& error) {
    LineReader lr(buf);
    const char *lb = nullptr, *le = nullptr, *tb = nullptr, *te = nullptr;
    // Next non-empty line after comment stripping.
    auto next_content = [&](Tok& t) -> bool {
        while (lr.next(lb, le)) {
            t = Tok{lb, strip_comment(lb, le)};
            if (!t.at_end()) return true;
        }
        return false;
    };
    Tok t{nullptr, nullptr};
    if (!next_content(t)) return fail(error, path, 0, "empty file (expected OFF header)");
    t.next(tb, te);
    // Header keyword: [ST][C][N]OFF. 4OFF / nOFF (other dimensions) are not supported.
    bool has_normals = false;
    {
        const std::string kw(tb, te);
        bool ok = kw.size() >= 3 && kw.compare(kw.size() - 3, 3, "OFF") == 0;
        for (size_t i = 0; ok && i + 3 < kw.size(); ++i) {
            const char c = kw[i];
            if (c == 'N') has_normals = true;
            else if (c != 'S' && c != 'T' && c != 'C') ok = false;
        }
        if (!ok) {
            if (kw.find("OFF") != std::string::npos)
                return fail(error, path, lr.line, "unsupported OFF variant " + quote_token(tb, te));
            return fail(error, path, lr.line, "not an OFF file (header " + quote_token(tb, te) + ")");
        }
    }
    // Counts: on the header line or the next content line.
    long long counts[3] = {0, 0, 0};
    int have = 0;
    while (have < 2) {
        while (have < 3 && t.next(tb, te)) {
            if (!parse_int_token(tb, te, counts[have]) || counts[have] < 0)
                return fail(error, path, lr.line, "bad count " + quote_token(tb, te));
            ++have;
        }
        if (have >= 2) break;
        if (have != 0) return fail(error, path, lr.line, "expected vertex, face and edge counts");
        if (!next_content(t)) return fail(error, path, 0, "missing vertex and face counts");
    }
    const long long nv = counts[0], nf = counts[1];
    const size_t bytes = buf.size();
    // A vertex line has at least 6 bytes ("0 0 0\n"), a face line at least 8 ("3 0 0 0\n").
    if (static_cast<unsigned long long>(nv) > bytes / 6 || static_cast<unsigned long long>(nf) > bytes / 8)
        return fail(error, path, lr.line,
                    "counts " + std::to_string(nv) + " vertices / " + std::to_string(nf) +
                        " faces exceed what the file size allows (file truncated?)");
    if (nv > static_cast<long long>(std::numeric_limits<uint32_t>::max()))
        return fail(error, path, lr.line, "too many vertices");
    ca::reserve_large(out.positions, static_cast<size_t>(nv) * 3);
    if (has_normals) ca::reserve_large(out.normals, static_cast<size_t>(nv) * 3);
    for (long long i = 0; i < nv; ++i) {
        if (!next_content(t))
            return fail(error, path, 0,
                        "file truncated: expected " + std::to_string(nv) + " vertices, found " +
                            std::to_string(i));
        const int need = has_normals ? 6 : 3;
        double x[6];
        for (int k = 0; k < need; ++k) {
            if (!t.next(tb, te))
                return fail(error, path, lr.line,
                            has_normals ? "vertex needs 6 values (x y z nx ny nz)" : "vertex needs 3 coordinates");
            if (!parse_double_token(tb, te, x[k]))
                return fail(error, path, lr.line, "bad number " + quote_token(tb, te));
        }
        out.positions.insert(out.positions.end(), x, x + 3);
        if (has_normals) out.normals.insert(out.normals.end(), x + 3, x + 6);
    }
    std::vector<uint32_t> poly;
    for (long long i = 0; i < nf; ++i) {
        if (!next_content(t))
            return fail(error, path, 0,
                        "file truncated: expected " + std::to_string(nf) + " faces, found " +
                            std::to_string(i));
        long long k = 0;
        if (!t.next(tb, te) || !parse_int_token(tb, te, k) || k < 0)
            return fail(error, path, lr.line, "bad face vertex count " + quote_token(tb, te));
        if (k == 0) continue;  // empty faces are skipped
        if (k > static_cast<long long>(kMaxPolygon))
            return fail(error, path, lr.line,
                        "polygon with " + std::to_string(k) + " vertices exceeds the limit of " + std::to_string(kMaxPolygon));
        if (k < 3)
            return fail(error, path, lr.line, "face with " + std::to_string(k) + " vertices (need at least 3)");
        poly.clear();
        for (long long j = 0; j < k; ++j) {
            long long idx = 0;
            if (!t.next(tb, te))
                return fail(error, path, lr.line,
                            "face lists " + std::to_string(j) + " of " + std::to_string(k) + " indices");
            if (!parse_int_token(tb, te, idx))
                return fail(error, path, lr.line, "bad face index " + quote_token(tb, te));
            if (idx < 0 || idx >= nv)
                return fail(error, path, lr.line,
                            "face index " + std::to_string(idx) + " out of range (" +
                                vcount_msg(static_cast<size_t>(nv)));
            poly.push_back(static_cast<uint32_t>(idx));
        }
        // Remaining tokens (face colour) are ignored.
        if (!fan(path, lr.line, poly, out.triangles, error)) return false;
    }
    if (nv == 0) return fail(error, path, 0, "no vertices");
    return true;
}

}  // namespace detail
}  // namespace caio

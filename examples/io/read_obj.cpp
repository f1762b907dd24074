// read_obj.cpp: Wavefront OBJ meshes and point clouds: v, vn and f records (v, v/vt, v//vn,
// v/vt/vn forms; negative indices; polygons fan-triangulated). Other records are ignored.
// Normals are kept when there is one vn per v (per-vertex normals, as point clouds carry them).
#include "readers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace caio {
namespace detail {
bool read_obj(const std::string& path, const std::string& buf, MeshData& out, std::string& error) {
    LineReader lr(buf);
    std::vector<double> vn;
    std::vector<uint32_t> poly;
    const char *lb, *le, *tb, *te;
    // Positive indices may refer to vertices defined later; they are checked at the end.
    long long max_forward = 0;
    size_t max_forward_line = 0;
    while (lr.next(lb, le)) {
        Tok t{lb, strip_comment(lb, le)};
        if (!t.next(tb, te)) continue;
        const size_t n = static_cast<size_t>(te - tb);
        if (n == 1 && tb[0] == 'v') {
            double x[3];
            for (double& c : x) {
                if (!t.next(tb, te)) return fail(error, path, lr.line, "vertex needs 3 coordinates");
                if (!parse_double_token(tb, te, c))
                    return fail(error, path, lr.line, "bad number " + quote_token(tb, te));
            }
            out.positions.insert(out.positions.end(), x, x + 3);
        } else if (n == 2 && tb[0] == 'v' && tb[1] == 'n') {
            double x[3];
            for (double& c : x) {
                if (!t.next(tb, te)) return fail(error, path, lr.line, "normal needs 3 coordinates");
                if (!parse_double_token(tb, te, c))
                    return fail(error, path, lr.line, "bad number " + quote_token(tb, te));
            }
            vn.insert(vn.end(), x, x + 3);
        } else if (n == 1 && tb[0] == 'f') {
            poly.clear();
            const long long nv = static_cast<long long>(out.positions.size() / 3);
            while (t.next(tb, te)) {
                const char* slash = static_cast<const char*>(std::memchr(tb, '/', static_cast<size_t>(te - tb)));
                const char* ie = slash ? slash : te;
                long long idx = 0;
                if (!parse_int_token(tb, ie, idx))
                    return fail(error, path, lr.line, "bad face index " + quote_token(tb, te));
                long long zero_based;
                if (idx < 0) {
                    zero_based = nv + idx;
                    if (zero_based < 0)
                        return fail(error, path, lr.line,
                                    "face index " + std::to_string(idx) + " out of range (" +
                                        vcount_msg(static_cast<size_t>(nv)));
                } else if (idx == 0) {
                    return fail(error, path, lr.line, "face index 0 (OBJ indices start at 1)");
                } else {
                    if (idx > std::numeric_limits<uint32_t>::max())
                        return fail(error, path, lr.line,
                                    "face index " + std::to_string(idx) + " out of range (" +
                                        vcount_msg(static_cast<size_t>(nv)));
                    if (idx > nv && idx > max_forward) {
                        max_forward = idx;
                        max_forward_line = lr.line;
                    }
                    zero_based = idx - 1;
                }
                if (poly.size() == kMaxPolygon)
                    return fail(error, path, lr.line,
                                "polygon with more than " + std::to_string(kMaxPolygon) + " vertices (the limit)");
                poly.push_back(static_cast<uint32_t>(zero_based));
            }
            // An empty "f" record (written by some tools) is skipped; 1 or 2 indices is an error.
            if (!poly.empty() && poly.size() < 3)
                return fail(error, path, lr.line,
                            "face with " + std::to_string(poly.size()) + " vertices (need at least 3)");
            if (!fan(path, lr.line, poly, out.triangles, error)) return false;
        }
        // Other records (vt, l, o, g, s, usemtl, mtllib, ...) are ignored.
    }
    const size_t nv = out.positions.size() / 3;
    if (nv == 0) return fail(error, path, 0, "no vertices");
    if (max_forward > static_cast<long long>(nv))
        return fail(error, path, max_forward_line,
                    "face index " + std::to_string(max_forward) + " out of range (" + vcount_msg(nv));
    if (vn.size() == out.positions.size()) out.normals = std::move(vn);
    return true;
}

}  // namespace detail
}  // namespace caio

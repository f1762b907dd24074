// read_point_clouds.cpp: plain-text point clouds.
// .xyz: one point per line, "x y z" or "x y z nx ny nz" (further columns ignored); normals are
//   kept only when every point has them. '#' comments and blank lines are skipped.
// .pts: the Leica/laser-scanner layout: blocks, each an optional line with a single integer (the
//   number of points that follow; checked), then lines "x y z", "x y z intensity",
//   "x y z r g b" or "x y z intensity r g b". Only x y z are kept (no normals in .pts).
#include <string>
#include <vector>

#include "readers.h"

namespace caio {
namespace detail {

bool read_xyz(const std::string& path, const std::string& buf, MeshData& out, std::string& error) {
    LineReader lr(buf);
    const char *lb, *le, *tb, *te;
    bool all_normals = true;
    std::vector<double> normals;
    while (lr.next(lb, le)) {
        Tok t{lb, strip_comment(lb, le)};
        double x[6];
        int n = 0;
        while (n < 6 && t.next(tb, te)) {
            if (!parse_double_token(tb, te, x[n]))
                return fail(error, path, lr.line, "bad number " + quote_token(tb, te));
            ++n;
        }
        if (n == 0) continue;
        if (n < 3) return fail(error, path, lr.line, "point needs 3 coordinates");
        out.positions.insert(out.positions.end(), x, x + 3);
        if (n == 6 && all_normals) normals.insert(normals.end(), x + 3, x + 6);
        else all_normals = false;
    }
    if (out.positions.empty()) return fail(error, path, 0, "no points");
    if (all_normals) out.normals = std::move(normals);
    return true;
}

bool read_pts(const std::string& path, const std::string& buf, MeshData& out, std::string& error) {
    LineReader lr(buf);
    const char *lb, *le, *tb, *te;
    long long block_count = -1;  // points announced by the current block's count line, or -1
    size_t block_line = 0, block_seen = 0;
    auto close_block = [&]() {
        if (block_count >= 0 && static_cast<size_t>(block_count) != block_seen)
            return fail(error, path, block_line,
                        "count line announces " + std::to_string(block_count) + " points, " +
                            std::to_string(block_seen) + " follow");
        return true;
    };
    while (lr.next(lb, le)) {
        Tok t{lb, strip_comment(lb, le)};
        double x[7];
        int n = 0;
        const char* first_b = nullptr;
        const char* first_e = nullptr;
        while (t.next(tb, te)) {
            if (n == 7) return fail(error, path, lr.line, "more than 7 values (x y z [intensity] [r g b])");
            if (n == 0) first_b = tb, first_e = te;
            if (!parse_double_token(tb, te, x[n]))
                return fail(error, path, lr.line, "bad number " + quote_token(tb, te));
            ++n;
        }
        if (n == 0) continue;
        long long count = 0;
        if (n == 1) {
            if (!parse_int_token(first_b, first_e, count) || count < 0)
                return fail(error, path, lr.line, "expected a point count or x y z, got " + quote_token(first_b, first_e));
            if (!close_block()) return false;
            block_count = count;
            block_line = lr.line;
            block_seen = 0;
            continue;
        }
        if (n == 2 || n == 5) return fail(error, path, lr.line, std::to_string(n) + " values (expected 3, 4, 6 or 7)");
        out.positions.insert(out.positions.end(), x, x + 3);
        ++block_seen;
    }
    if (!close_block()) return false;
    if (out.positions.empty()) return fail(error, path, 0, "no points");
    return true;
}

}  // namespace detail
}  // namespace caio

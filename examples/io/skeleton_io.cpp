// skeleton_io.cpp: the non-mesh files of the tool: point/ball files (read_points, write_points),
// index files (read_indices) and skeleton files (.ma read and write; .obj and .ply written).
// Numbers are written with %.9g; every writer checks sizes and index ranges first.
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "mesh_io.h"
#include "reader_common.h"

namespace caio {
using namespace detail;
namespace {

struct Writer {
    std::string buf;
    void num(double v) {
        char tmp[40];
        const int n = std::snprintf(tmp, sizeof tmp, "%.9g", v);
        buf.append(tmp, static_cast<size_t>(n));
    }
    void uint(unsigned long long v) {
        char tmp[24];
        auto r = std::to_chars(tmp, tmp + sizeof tmp, v);
        buf.append(tmp, r.ptr);
    }
    void str(const char* s) { buf += s; }
    void ch(char c) { buf += c; }
};

bool write_file(const std::string& path, const std::string& data, std::string& error) {
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return fail(error, path, 0, std::string("cannot open for writing: ") + std::strerror(errno));
    const size_t n = std::fwrite(data.data(), 1, data.size(), f);
    int err = (n != data.size()) ? errno : 0;
    if (std::fflush(f) != 0 && err == 0) err = errno ? errno : EIO;
    if (std::fclose(f) != 0 && err == 0) err = errno ? errno : EIO;
    if (n != data.size() || err != 0)
        return fail(error, path, 0, std::string("write error: ") + std::strerror(err ? err : EIO));
    return true;
}

// Checks the skeleton's array sizes and index ranges.
bool check_skeleton(const std::string& path, const SkeletonData& s, bool need_radii, std::string& error) {
    if (s.centers.size() % 3 != 0) return fail(error, path, 0, "centers size is not a multiple of 3");
    const size_t nv = s.centers.size() / 3;
    if (need_radii ? s.radii.size() != nv : (!s.radii.empty() && s.radii.size() != nv))
        return fail(error, path, 0,
                    std::to_string(s.radii.size()) + " radii for " + std::to_string(nv) + " balls");
    if (s.edges.size() % 2 != 0) return fail(error, path, 0, "edges size is not a multiple of 2");
    if (s.faces.size() % 3 != 0) return fail(error, path, 0, "faces size is not a multiple of 3");
    for (size_t i = 0; i < s.edges.size(); ++i)
        if (s.edges[i] >= nv)
            return fail(error, path, 0,
                        "edge " + std::to_string(i / 2) + " index " + std::to_string(s.edges[i]) +
                            " out of range (" + std::to_string(nv) + " balls)");
    for (size_t i = 0; i < s.faces.size(); ++i)
        if (s.faces[i] >= nv)
            return fail(error, path, 0,
                        "face " + std::to_string(i / 3) + " index " + std::to_string(s.faces[i]) +
                            " out of range (" + std::to_string(nv) + " balls)");
    return true;
}

inline uint64_t edge_key(uint32_t a, uint32_t b) {
    if (a > b) std::swap(a, b);
    return (static_cast<uint64_t>(a) << 32) | b;
}

}  // namespace

bool read_points(const std::string& path, std::vector<double>& xyz, std::vector<double>& radii,
                 std::string& error) {
    xyz.clear();
    radii.clear();
    const bool ok = guarded(path, error, [&]() {
        std::string buf;
        if (!load_file(path, buf, error)) return false;
        LineReader lr(buf);
        const char *lb, *le, *tb, *te;
        bool all_radii = true;
        while (lr.next(lb, le)) {
            Tok t{lb, strip_comment(lb, le)};
            if (!t.next(tb, te)) continue;
            double x[8];
            int n = 0;
            const bool v_record = (te - tb == 1 && *tb == 'v');
            if (!v_record) {
                // A plain line starts with a number; any other record (vn, vt, f, l, ...) is skipped.
                if (!parse_double_token(tb, te, x[0])) {
                    const char c = *tb;
                    if ((c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.')
                        return fail(error, path, lr.line, "bad number " + quote_token(tb, te));
                    continue;
                }
                n = 1;
            }
            while (t.next(tb, te)) {
                double v;
                if (!parse_double_token(tb, te, v))
                    return fail(error, path, lr.line, "bad number " + quote_token(tb, te));
                if (n < 8) x[n] = v;
                ++n;
            }
            if (n < 3) return fail(error, path, lr.line, "point needs 3 coordinates");
            xyz.insert(xyz.end(), x, x + 3);
            // Exactly four numbers: x y z r. Other counts (e.g. x y z nx ny nz) carry no radius.
            if (n == 4 && all_radii) radii.push_back(x[3]);
            else all_radii = false;
        }
        if (xyz.empty()) return fail(error, path, 0, "no points");
        if (!all_radii) radii.clear();
        return true;
    });
    if (!ok) {
        xyz.clear();
        radii.clear();
    }
    return ok;
}

bool read_indices(const std::string& path, std::vector<uint32_t>& out, std::string& error) {
    out.clear();
    const bool ok = guarded(path, error, [&]() {
        std::string buf;
        if (!load_file(path, buf, error)) return false;
        LineReader lr(buf);
        const char *lb, *le, *tb, *te;
        while (lr.next(lb, le)) {
            Tok t{lb, strip_comment(lb, le)};
            while (t.next(tb, te)) {
                long long v = 0;
                if (!parse_int_token(tb, te, v))
                    return fail(error, path, lr.line, "bad index " + quote_token(tb, te));
                if (v < 0 || v > static_cast<long long>(std::numeric_limits<uint32_t>::max()))
                    return fail(error, path, lr.line, "index " + std::to_string(v) + " out of range");
                out.push_back(static_cast<uint32_t>(v));
            }
        }
        return true;
    });
    if (!ok) out.clear();
    return ok;
}
bool write_ma(const std::string& path, const SkeletonData& s, std::string& error) {
    return guarded(path, error, [&]() {
        if (!check_skeleton(path, s, true, error)) return false;
        // Every face edge must appear as an e line: add the missing ones after the given edges.
        std::vector<uint32_t> edges = s.edges;
        if (!s.faces.empty()) {
            std::unordered_set<uint64_t> have;
            have.reserve(s.edges.size() / 2 + s.faces.size());
            for (size_t i = 0; i + 1 < s.edges.size(); i += 2) have.insert(edge_key(s.edges[i], s.edges[i + 1]));
            for (size_t f = 0; f + 2 < s.faces.size(); f += 3)
                for (size_t k = 0; k < 3; ++k) {
                    const uint32_t a = s.faces[f + k], b = s.faces[f + (k + 1) % 3];
                    if (have.insert(edge_key(a, b)).second) {
                        edges.push_back(a);
                        edges.push_back(b);
                    }
                }
        }
        const size_t nv = s.centers.size() / 3, ne = edges.size() / 2, nf = s.faces.size() / 3;
        Writer w;
        w.buf.reserve(nv * 80 + ne * 16 + nf * 24 + 64);
        w.uint(nv); w.ch(' '); w.uint(ne); w.ch(' '); w.uint(nf); w.ch('\n');
        for (size_t i = 0; i < nv; ++i) {
            w.str("v ");
            w.num(s.centers[3 * i]); w.ch(' ');
            w.num(s.centers[3 * i + 1]); w.ch(' ');
            w.num(s.centers[3 * i + 2]); w.ch(' ');
            w.num(s.radii[i]); w.ch('\n');
        }
        for (size_t i = 0; i < ne; ++i) {
            w.str("e "); w.uint(edges[2 * i]); w.ch(' '); w.uint(edges[2 * i + 1]); w.ch('\n');
        }
        for (size_t i = 0; i < nf; ++i) {
            w.str("f "); w.uint(s.faces[3 * i]); w.ch(' ');
            w.uint(s.faces[3 * i + 1]); w.ch(' '); w.uint(s.faces[3 * i + 2]); w.ch('\n');
        }
        return write_file(path, w.buf, error);
    });
}

bool read_ma(const std::string& path, SkeletonData& s, std::string& error) {
    s = SkeletonData{};
    const bool ok = guarded(path, error, [&]() {
        std::string buf;
        if (!load_file(path, buf, error)) return false;
        LineReader lr(buf);
        const char *lb, *le, *tb, *te;
        long long counts[3] = {-1, -1, -1};
        size_t header_line = 0;
        // Header: the first non-empty, non-comment line holds "nv ne nf".
        while (lr.next(lb, le)) {
            Tok t{lb, strip_comment(lb, le)};
            if (t.at_end()) continue;
            header_line = lr.line;
            for (long long& c : counts) {
                if (!t.next(tb, te) || !parse_int_token(tb, te, c) || c < 0)
                    return fail(error, path, lr.line, "expected header 'nv ne nf'");
            }
            if (!t.at_end()) return fail(error, path, lr.line, "expected header 'nv ne nf'");
            break;
        }
        if (header_line == 0) return fail(error, path, 0, "empty file (expected header 'nv ne nf')");
        const long long nv = counts[0], ne = counts[1], nf = counts[2];
        // Each record line is at least 8 bytes ("v 0 0 0 0" is 9, "e 0 0" + newline is 6).
        const unsigned long long bytes = buf.size();
        if (static_cast<unsigned long long>(nv) > bytes / 8 || static_cast<unsigned long long>(ne) > bytes / 6 ||
            static_cast<unsigned long long>(nf) > bytes / 8)
            return fail(error, path, header_line, "header counts exceed what the file size allows (file truncated?)");
        s.centers.reserve(static_cast<size_t>(nv) * 3);
        s.radii.reserve(static_cast<size_t>(nv));
        s.edges.reserve(static_cast<size_t>(ne) * 2);
        s.faces.reserve(static_cast<size_t>(nf) * 3);
        auto read_index = [&](Tok& t, uint32_t& idx) {
            long long v = 0;
            if (!t.next(tb, te)) return fail(error, path, lr.line, "missing index");
            if (!parse_int_token(tb, te, v)) return fail(error, path, lr.line, "bad index " + quote_token(tb, te));
            if (v < 0 || v >= nv)
                return fail(error, path, lr.line,
                            "index " + std::to_string(v) + " out of range (" + vcount_msg(static_cast<size_t>(nv)));
            idx = static_cast<uint32_t>(v);
            return true;
        };
        while (lr.next(lb, le)) {
            Tok t{lb, strip_comment(lb, le)};
            if (!t.next(tb, te)) continue;
            const std::string kw(tb, te);
            if (kw == "v") {
                if (static_cast<long long>(s.radii.size()) >= nv)
                    return fail(error, path, lr.line, "more v lines than the header's " + std::to_string(nv));
                double x[4];
                for (double& c : x) {
                    if (!t.next(tb, te)) return fail(error, path, lr.line, "v line needs x y z r");
                    if (!parse_double_token(tb, te, c))
                        return fail(error, path, lr.line, "bad number " + quote_token(tb, te));
                }
                s.centers.insert(s.centers.end(), x, x + 3);
                s.radii.push_back(x[3]);
            } else if (kw == "e") {
                if (static_cast<long long>(s.edges.size() / 2) >= ne)
                    return fail(error, path, lr.line, "more e lines than the header's " + std::to_string(ne));
                uint32_t a, b;
                if (!read_index(t, a) || !read_index(t, b)) return false;
                s.edges.push_back(a);
                s.edges.push_back(b);
            } else if (kw == "f") {
                if (static_cast<long long>(s.faces.size() / 3) >= nf)
                    return fail(error, path, lr.line, "more f lines than the header's " + std::to_string(nf));
                uint32_t a, b, c;
                if (!read_index(t, a) || !read_index(t, b) || !read_index(t, c)) return false;
                s.faces.push_back(a);
                s.faces.push_back(b);
                s.faces.push_back(c);
            } else {
                return fail(error, path, lr.line, "unknown record " + quote_token(tb, te) + " (expected v, e or f)");
            }
        }
        if (static_cast<long long>(s.radii.size()) != nv || static_cast<long long>(s.edges.size() / 2) != ne ||
            static_cast<long long>(s.faces.size() / 3) != nf)
            return fail(error, path, 0,
                        "file truncated: header says " + std::to_string(nv) + " " + std::to_string(ne) + " " +
                            std::to_string(nf) + ", found " + std::to_string(s.radii.size()) + " " +
                            std::to_string(s.edges.size() / 2) + " " + std::to_string(s.faces.size() / 3));
        return true;
    });
    if (!ok) s = SkeletonData{};
    return ok;
}

// Writes "v x y z" lines, then every edge as "l i j", then every face as "f i j k" (1-based).
// Radii are not stored.
bool write_obj(const std::string& path, const SkeletonData& s, std::string& error) {
    return guarded(path, error, [&]() {
        if (!check_skeleton(path, s, false, error)) return false;
        const size_t nv = s.centers.size() / 3, ne = s.edges.size() / 2, nf = s.faces.size() / 3;
        Writer w;
        w.buf.reserve(nv * 64 + ne * 16 + nf * 24 + 64);
        for (size_t i = 0; i < nv; ++i) {
            w.str("v ");
            w.num(s.centers[3 * i]); w.ch(' ');
            w.num(s.centers[3 * i + 1]); w.ch(' ');
            w.num(s.centers[3 * i + 2]); w.ch('\n');
        }
        for (size_t i = 0; i < ne; ++i) {
            w.str("l "); w.uint(s.edges[2 * i] + 1ull); w.ch(' '); w.uint(s.edges[2 * i + 1] + 1ull); w.ch('\n');
        }
        for (size_t i = 0; i < nf; ++i) {
            w.str("f "); w.uint(s.faces[3 * i] + 1ull); w.ch(' ');
            w.uint(s.faces[3 * i + 1] + 1ull); w.ch(' '); w.uint(s.faces[3 * i + 2] + 1ull); w.ch('\n');
        }
        return write_file(path, w.buf, error);
    });
}

bool write_ply(const std::string& path, const SkeletonData& s, std::string& error) {
    return guarded(path, error, [&]() {
        if (!check_skeleton(path, s, false, error)) return false;
        const size_t nv = s.centers.size() / 3, ne = s.edges.size() / 2, nf = s.faces.size() / 3;
        const bool radii = !s.radii.empty();
        Writer w;
        w.buf.reserve(nv * 80 + ne * 16 + nf * 24 + 256);
        w.str("ply\nformat ascii 1.0\ncomment coverage-axis skeleton\nelement vertex ");
        w.uint(nv);
        w.str("\nproperty double x\nproperty double y\nproperty double z\n");
        if (radii) w.str("property double radius\n");
        w.str("element face ");
        w.uint(nf);
        w.str("\nproperty list uchar int vertex_indices\nelement edge ");
        w.uint(ne);
        w.str("\nproperty int vertex1\nproperty int vertex2\nend_header\n");
        for (size_t i = 0; i < nv; ++i) {
            w.num(s.centers[3 * i]); w.ch(' ');
            w.num(s.centers[3 * i + 1]); w.ch(' ');
            w.num(s.centers[3 * i + 2]);
            if (radii) { w.ch(' '); w.num(s.radii[i]); }
            w.ch('\n');
        }
        for (size_t i = 0; i < nf; ++i) {
            w.str("3 "); w.uint(s.faces[3 * i]); w.ch(' ');
            w.uint(s.faces[3 * i + 1]); w.ch(' '); w.uint(s.faces[3 * i + 2]); w.ch('\n');
        }
        for (size_t i = 0; i < ne; ++i) {
            w.uint(s.edges[2 * i]); w.ch(' '); w.uint(s.edges[2 * i + 1]); w.ch('\n');
        }
        return write_file(path, w.buf, error);
    });
}

bool write_points(const std::string& path, const std::vector<double>& xyz,
                  const std::vector<double>& radii, std::string& error) {
    return guarded(path, error, [&]() {
        if (xyz.size() % 3 != 0) return fail(error, path, 0, "point array size is not a multiple of 3");
        const size_t n = xyz.size() / 3;
        if (!radii.empty() && radii.size() != n)
            return fail(error, path, 0, std::to_string(radii.size()) + " radii for " + std::to_string(n) + " points");
        Writer w;
        w.buf.reserve(n * 80 + 16);
        for (size_t i = 0; i < n; ++i) {
            w.str("v ");
            w.num(xyz[3 * i]); w.ch(' ');
            w.num(xyz[3 * i + 1]); w.ch(' ');
            w.num(xyz[3 * i + 2]);
            if (!radii.empty()) { w.ch(' '); w.num(radii[i]); }
            w.ch('\n');
        }
        return write_file(path, w.buf, error);
    });
}
}  // namespace caio

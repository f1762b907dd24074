// read_ply.cpp: PLY meshes and point clouds (ascii, binary_little_endian, binary_big_endian;
// any scalar types; vertex x y z [nx ny nz]; face vertex_indices / vertex_index lists; other
// elements and properties skipped). Every element count is checked against the bytes left.
#include "readers.h"
#include "large_pages.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace caio {
namespace detail {
namespace {

enum class PType { I8, U8, I16, U16, I32, U32, F32, F64, Invalid };

PType ptype_from(const std::string& s) {
    if (s == "char" || s == "int8") return PType::I8;
    if (s == "uchar" || s == "uint8") return PType::U8;
    if (s == "short" || s == "int16") return PType::I16;
    if (s == "ushort" || s == "uint16") return PType::U16;
    if (s == "int" || s == "int32") return PType::I32;
    if (s == "uint" || s == "uint32") return PType::U32;
    if (s == "float" || s == "float32") return PType::F32;
    if (s == "double" || s == "float64") return PType::F64;
    return PType::Invalid;
}

size_t ptype_size(PType t) {
    switch (t) {
        case PType::I8: case PType::U8: return 1;
        case PType::I16: case PType::U16: return 2;
        case PType::I32: case PType::U32: case PType::F32: return 4;
        case PType::F64: return 8;
        default: return 0;
    }
}

bool ptype_integral(PType t) { return t != PType::F32 && t != PType::F64; }

struct PlyProp {
    std::string name;
    bool is_list = false;
    PType type = PType::Invalid;        // scalar type, or list item type
    PType count_type = PType::Invalid;  // list count type
};

struct PlyElement {
    std::string name;
    unsigned long long count = 0;
    std::vector<PlyProp> props;
    size_t line = 0;
};

inline bool host_little_endian() {
    const uint16_t x = 1;
    unsigned char c;
    std::memcpy(&c, &x, 1);
    return c == 1;
}

// Reads one binary scalar at p (caller has checked the bounds).
inline double read_binary(const unsigned char* p, PType t, bool swap) {
    unsigned char b[8];
    const size_t n = ptype_size(t);
    if (swap) {
        for (size_t i = 0; i < n; ++i) b[i] = p[n - 1 - i];
    } else {
        std::memcpy(b, p, n);
    }
    switch (t) {
        case PType::I8: { int8_t v; std::memcpy(&v, b, 1); return v; }
        case PType::U8: { uint8_t v; std::memcpy(&v, b, 1); return v; }
        case PType::I16: { int16_t v; std::memcpy(&v, b, 2); return v; }
        case PType::U16: { uint16_t v; std::memcpy(&v, b, 2); return v; }
        case PType::I32: { int32_t v; std::memcpy(&v, b, 4); return v; }
        case PType::U32: { uint32_t v; std::memcpy(&v, b, 4); return v; }
        case PType::F32: { float v; std::memcpy(&v, b, 4); return v; }
        case PType::F64: { double v; std::memcpy(&v, b, 8); return v; }
        default: return 0;
    }
}

// A source of PLY values: binary (with bounds checks) or ASCII (token stream with lines).
struct PlyBody {
    bool ascii = true;
    bool swap = false;
    const char* p = nullptr;
    const char* end = nullptr;
    size_t line = 0;  // ascii only
    // On failure: `truncated` set if the data ended, otherwise a bad ascii token in bad_tok.
    bool truncated = false;
    std::string bad_tok;

    bool value(PType t, double& v) {
        if (ascii) {
            while (p < end && is_space(*p)) {
                if (*p == '\n') ++line;
                ++p;
            }
            if (p >= end) {
                truncated = true;
                return false;
            }
            const char* tb = p;
            p = token_end(p, end);
            if (!parse_double_token(tb, p, v)) {
                bad_tok = quote_token(tb, p);
                return false;
            }
            if (ptype_integral(t) && v != std::floor(v)) {
                bad_tok = quote_token(tb, p) + " (expected an integer)";
                return false;
            }
            return true;
        }
        const size_t n = ptype_size(t);
        if (static_cast<size_t>(end - p) < n) {
            truncated = true;
            return false;
        }
        v = read_binary(reinterpret_cast<const unsigned char*>(p), t, swap);
        p += n;
        return true;
    }
    // Skips `count` values of type t.
    bool skip(PType t, unsigned long long count) {
        if (!ascii) {
            const size_t n = ptype_size(t);
            if (count > static_cast<size_t>(end - p) / n) {
                truncated = true;
                return false;
            }
            p += count * n;
            return true;
        }
        double v;
        for (unsigned long long i = 0; i < count; ++i)
            if (!value(t, v)) return false;
        return true;
    }
    size_t remaining() const { return static_cast<size_t>(end - p); }
};

}  // namespace

bool read_ply(const std::string& path, const std::string& buf, MeshData& out, std::string& error) {
    LineReader lr(buf);
    const char *lb, *le, *tb, *te;
    if (!lr.next(lb, le)) return fail(error, path, 0, "empty file (expected 'ply')");
    {
        Tok t{lb, le};
        if (!t.next(tb, te) || std::string(tb, te) != "ply" || !t.at_end())
            return fail(error, path, 1, "not a PLY file (first line is not 'ply')");
    }
    std::vector<PlyElement> elems;
    int format = -1;  // 0 ascii, 1 little endian, 2 big endian
    bool ended = false;
    while (!ended && lr.next(lb, le)) {
        Tok t{lb, le};
        if (!t.next(tb, te)) continue;
        const std::string kw(tb, te);
        if (kw == "comment" || kw == "obj_info") continue;
        std::vector<std::string> w;
        while (t.next(tb, te)) w.emplace_back(tb, te);
        if (kw == "end_header") {
            ended = true;
        } else if (kw == "format") {
            if (w.size() < 1) return fail(error, path, lr.line, "format line without a format");
            if (w[0] == "ascii") format = 0;
            else if (w[0] == "binary_little_endian") format = 1;
            else if (w[0] == "binary_big_endian") format = 2;
            else return fail(error, path, lr.line, "unknown format '" + w[0] + "'");
        } else if (kw == "element") {
            if (w.size() != 2) return fail(error, path, lr.line, "element line needs a name and a count");
            PlyElement el;
            el.name = w[0];
            el.line = lr.line;
            const char* cb = w[1].data();
            auto r = std::from_chars(cb, cb + w[1].size(), el.count);
            if (r.ec != std::errc() || r.ptr != cb + w[1].size())
                return fail(error, path, lr.line, "bad element count '" + w[1] + "'");
            elems.push_back(std::move(el));
        } else if (kw == "property") {
            if (elems.empty()) return fail(error, path, lr.line, "property before any element");
            PlyProp pr;
            if (!w.empty() && w[0] == "list") {
                if (w.size() != 4) return fail(error, path, lr.line, "list property needs count type, item type and name");
                pr.is_list = true;
                pr.count_type = ptype_from(w[1]);
                pr.type = ptype_from(w[2]);
                pr.name = w[3];
                if (pr.count_type == PType::Invalid) return fail(error, path, lr.line, "unknown property type '" + w[1] + "'");
                if (pr.type == PType::Invalid) return fail(error, path, lr.line, "unknown property type '" + w[2] + "'");
                if (!ptype_integral(pr.count_type)) return fail(error, path, lr.line, "list count type must be an integer type");
            } else {
                if (w.size() != 2) return fail(error, path, lr.line, "property needs a type and a name");
                pr.type = ptype_from(w[0]);
                pr.name = w[1];
                if (pr.type == PType::Invalid) return fail(error, path, lr.line, "unknown property type '" + w[0] + "'");
            }
            elems.back().props.push_back(std::move(pr));
        } else {
            return fail(error, path, lr.line, "unknown header line starting with " + quote_token(lb, le));
        }
    }
    if (!ended) return fail(error, path, 0, "header has no end_header line");
    if (format < 0) return fail(error, path, 0, "header has no format line");

    // Locate the vertex and face elements.
    int vi = -1, fi = -1;
    for (size_t i = 0; i < elems.size(); ++i) {
        if (elems[i].name == "vertex") {
            if (vi >= 0) return fail(error, path, elems[i].line, "more than one vertex element");
            vi = static_cast<int>(i);
        } else if (elems[i].name == "face") {
            if (fi >= 0) return fail(error, path, elems[i].line, "more than one face element");
            fi = static_cast<int>(i);
        }
    }
    if (vi < 0) return fail(error, path, 0, "no vertex element");
    const PlyElement& ve = elems[static_cast<size_t>(vi)];
    int px = -1, py = -1, pz = -1, pnx = -1, pny = -1, pnz = -1;
    for (size_t k = 0; k < ve.props.size(); ++k) {
        const PlyProp& pr = ve.props[k];
        int* slot = nullptr;
        if (pr.name == "x") slot = &px;
        else if (pr.name == "y") slot = &py;
        else if (pr.name == "z") slot = &pz;
        else if (pr.name == "nx") slot = &pnx;
        else if (pr.name == "ny") slot = &pny;
        else if (pr.name == "nz") slot = &pnz;
        if (slot) {
            if (pr.is_list) return fail(error, path, ve.line, "vertex property '" + pr.name + "' is a list");
            *slot = static_cast<int>(k);
        }
    }
    if (px < 0 || py < 0 || pz < 0) return fail(error, path, ve.line, "vertex element lacks x, y or z");
    const bool want_normals = pnx >= 0 && pny >= 0 && pnz >= 0;
    int pidx = -1;
    if (fi >= 0) {
        const PlyElement& fe = elems[static_cast<size_t>(fi)];
        for (size_t k = 0; k < fe.props.size(); ++k)
            if (fe.props[k].is_list && (fe.props[k].name == "vertex_indices" || fe.props[k].name == "vertex_index"))
                pidx = static_cast<int>(k);
        if (pidx < 0 && fe.count > 0)
            return fail(error, path, fe.line, "face element has no vertex_indices list");
    }
    if (ve.count > std::numeric_limits<uint32_t>::max()) return fail(error, path, ve.line, "too many vertices");
    const unsigned long long nv = ve.count;

    PlyBody body;
    body.ascii = format == 0;
    body.swap = format != 0 && ((format == 1) != host_little_endian());
    body.p = lr.p;
    body.end = lr.end;
    body.line = lr.line + 1;

    std::vector<double> row;
    std::vector<uint32_t> poly;
    for (size_t ei = 0; ei < elems.size(); ++ei) {
        const PlyElement& el = elems[ei];
        if (el.props.empty() || el.count == 0) continue;
        auto truncated = [&]() {
            return fail(error, path, body.ascii ? body.line : 0, "file truncated in element '" + el.name + "'");
        };
        auto bad_value = [&]() {
            if (body.truncated) return truncated();
            return fail(error, path, body.line, "bad value " + body.bad_tok + " in element '" + el.name + "'");
        };
        // Minimal size per instance, to reject impossible counts before reserving memory.
        size_t min_size = 0;
        for (const PlyProp& pr : el.props)
            min_size += body.ascii ? 1 : ptype_size(pr.is_list ? pr.count_type : pr.type);
        if (el.count > (body.remaining() + 1) / min_size) return truncated();
        const bool is_vertex = static_cast<int>(ei) == vi;
        const bool is_face = static_cast<int>(ei) == fi;
        if (is_vertex) {
            ca::reserve_large(out.positions, static_cast<size_t>(el.count) * 3);
            if (want_normals) ca::reserve_large(out.normals, static_cast<size_t>(el.count) * 3);
            row.assign(el.props.size(), 0.0);
        } else if (is_face) {
            ca::reserve_large(out.triangles, static_cast<size_t>(el.count) * 3);
        }
        for (unsigned long long n = 0; n < el.count; ++n) {
            for (size_t k = 0; k < el.props.size(); ++k) {
                const PlyProp& pr = el.props[k];
                if (!pr.is_list) {
                    if (is_vertex) {
                        if (!body.value(pr.type, row[k])) return bad_value();
                    } else if (!body.skip(pr.type, 1)) {
                        return bad_value();
                    }
                    continue;
                }
                double cnt_d = 0;
                if (!body.value(pr.count_type, cnt_d)) return bad_value();
                if (cnt_d < 0)
                    return fail(error, path, body.ascii ? body.line : 0,
                                "negative list length in element '" + el.name + "'");
                if (cnt_d > 4294967295.0)
                    return fail(error, path, body.ascii ? body.line : 0,
                                "list length too large in element '" + el.name + "'");
                const auto cnt = static_cast<unsigned long long>(cnt_d);
                if (is_face && static_cast<int>(k) == pidx) {
                    if (!body.ascii && cnt > body.remaining() / ptype_size(pr.type)) return truncated();
                    if (cnt > kMaxPolygon)
                        return fail(error, path, body.ascii ? body.line : 0,
                                    "face " + std::to_string(n) + " has " + std::to_string(cnt) +
                                        " vertices, more than the limit of " + std::to_string(kMaxPolygon));
                    if (cnt == 1 || cnt == 2)  // empty faces are skipped
                        return fail(error, path, body.ascii ? body.line : 0,
                                    "face " + std::to_string(n) + " has " + std::to_string(cnt) +
                                        " vertices (need at least 3)");
                    poly.clear();
                    for (unsigned long long j = 0; j < cnt; ++j) {
                        double d = 0;
                        if (!body.value(pr.type, d)) return bad_value();
                        if (!(d >= 0 && d < static_cast<double>(nv) && d == std::floor(d))) {
                            char num[64];
                            std::snprintf(num, sizeof num, "%.17g", d);
                            return fail(error, path, body.ascii ? body.line : 0,
                                        "face " + std::to_string(n) + ": index " + num +
                                            " out of range (" + vcount_msg(static_cast<size_t>(nv)));
                        }
                        poly.push_back(static_cast<uint32_t>(d));
                    }
                    if (!fan(path, body.ascii ? body.line : 0, poly, out.triangles, error)) return false;
                } else if (!body.skip(pr.type, cnt)) {
                    return bad_value();
                }
            }
            if (is_vertex) {
                out.positions.push_back(row[static_cast<size_t>(px)]);
                out.positions.push_back(row[static_cast<size_t>(py)]);
                out.positions.push_back(row[static_cast<size_t>(pz)]);
                if (want_normals) {
                    out.normals.push_back(row[static_cast<size_t>(pnx)]);
                    out.normals.push_back(row[static_cast<size_t>(pny)]);
                    out.normals.push_back(row[static_cast<size_t>(pnz)]);
                }
            }
        }
    }
    if (nv == 0) return fail(error, path, 0, "no vertices");
    return true;
}

}  // namespace detail
}  // namespace caio

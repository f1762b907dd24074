// mesh_io.cpp: readers and writers for .obj/.off/.ply/.xyz meshes and point clouds, point/ball
// files, index files and skeleton files (.ma/.obj/.ply). Files are loaded whole into memory and
// parsed with std::from_chars (locale-independent, no iostreams). Every count read from a header
// is checked against the file size before memory is reserved. No exception escapes: every public
// function catches and returns false with a one-line "file[:line]: what" message.
#include "mesh_io.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <limits>
#include <new>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

namespace caio {
namespace {

// ---------------------------------------------------------------------------------------------
// Errors

bool fail(std::string& error, const std::string& path, size_t line, const std::string& what) {
    error = path;
    if (line > 0) error += ":" + std::to_string(line);
    error += ": " + what;
    return false;
}

std::string quote_token(const char* b, const char* e) {
    const size_t n = static_cast<size_t>(e - b);
    std::string s(b, std::min<size_t>(n, 40));
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
    if (n > 40) s += "...";
    return "'" + s + "'";
}

// Runs `body`, converting any exception into a false return with a message.
template <class F>
bool guarded(const std::string& path, std::string& error, F&& body) {
    try {
        return body();
    } catch (const std::bad_alloc&) {
        return fail(error, path, 0, "out of memory");
    } catch (const std::exception& e) {
        return fail(error, path, 0, std::string("internal error: ") + e.what());
    } catch (...) {
        return fail(error, path, 0, "internal error");
    }
}

// ---------------------------------------------------------------------------------------------
// File loading

bool load_file(const std::string& path, std::string& buf, std::string& error) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return fail(error, path, 0, "is a directory");
    FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return fail(error, path, 0, std::string("cannot open: ") + std::strerror(errno));
    buf.clear();
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > 0 && size < (uint64_t(1) << 40)) buf.reserve(static_cast<size_t>(size));
    char chunk[1 << 16];
    for (;;) {
        const size_t n = std::fread(chunk, 1, sizeof chunk, f);
        buf.append(chunk, n);
        if (n < sizeof chunk) break;
    }
    const bool bad = std::ferror(f) != 0;
    std::fclose(f);
    if (bad) return fail(error, path, 0, "read error");
    return true;
}

// ---------------------------------------------------------------------------------------------
// Tokenising helpers (all bounded by an end pointer; the buffer need not be NUL-terminated)

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
inline bool is_space(char c) { return is_blank(c) || c == '\n'; }

inline const char* skip_blank(const char* p, const char* e) {
    while (p < e && is_blank(*p)) ++p;
    return p;
}
inline const char* token_end(const char* p, const char* e) {
    while (p < e && !is_space(*p)) ++p;
    return p;
}

// Parses one double token [b, e) exactly. Accepts a leading '+', inf/nan, and maps overflow to
// +-inf and underflow to 0 (via strtod).
bool parse_double_token(const char* b, const char* e, double& v) {
    if (b < e && *b == '+') ++b;
    if (b >= e) return false;
    auto r = std::from_chars(b, e, v);
    if (r.ec == std::errc::result_out_of_range) {
        if (e - b > 400) return false;
        std::string tmp(b, e);
        char* endp = nullptr;
        v = std::strtod(tmp.c_str(), &endp);
        return endp == tmp.c_str() + tmp.size();
    }
    return r.ec == std::errc() && r.ptr == e;
}

// Parses one integer token exactly (optional sign).
bool parse_int_token(const char* b, const char* e, long long& v) {
    if (b < e && *b == '+') ++b;
    if (b >= e) return false;
    auto r = std::from_chars(b, e, v);
    return r.ec == std::errc() && r.ptr == e;
}

// Iterates the lines of a buffer, counting them (1-based).
struct LineReader {
    const char* p;
    const char* end;
    size_t line = 0;
    LineReader(const std::string& buf) : p(buf.data()), end(buf.data() + buf.size()) {}
    // Returns the next line [b, e) without its '\n'.
    bool next(const char*& b, const char*& e) {
        if (p >= end) return false;
        b = p;
        const void* nl = std::memchr(p, '\n', static_cast<size_t>(end - p));
        e = nl ? static_cast<const char*>(nl) : end;
        p = nl ? e + 1 : end;
        ++line;
        return true;
    }
};

// Token cursor within one line.
struct Tok {
    const char* p;
    const char* e;
    // Next token, or false at end of line.
    bool next(const char*& tb, const char*& te) {
        p = skip_blank(p, e);
        if (p >= e) return false;
        tb = p;
        p = te = token_end(p, e);
        return true;
    }
    bool at_end() {
        p = skip_blank(p, e);
        return p >= e;
    }
};

// Strips a '#' comment from a line.
inline const char* strip_comment(const char* b, const char* e) {
    const void* h = std::memchr(b, '#', static_cast<size_t>(e - b));
    return h ? static_cast<const char*>(h) : e;
}

std::string lower_ext(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

std::string vcount_msg(size_t nv) { return std::to_string(nv) + (nv == 1 ? " vertex)" : " vertices)"); }

// Fan-triangulates polygon `poly` into `tris`.
void fan(const std::vector<uint32_t>& poly, std::vector<uint32_t>& tris) {
    for (size_t k = 1; k + 1 < poly.size(); ++k) {
        tris.push_back(poly[0]);
        tris.push_back(poly[k]);
        tris.push_back(poly[k + 1]);
    }
}

// ---------------------------------------------------------------------------------------------
// OBJ

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
                poly.push_back(static_cast<uint32_t>(zero_based));
            }
            // An empty "f" record (written by some tools) is skipped; 1 or 2 indices is an error.
            if (!poly.empty() && poly.size() < 3)
                return fail(error, path, lr.line,
                            "face with " + std::to_string(poly.size()) + " vertices (need at least 3)");
            fan(poly, out.triangles);
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

// ---------------------------------------------------------------------------------------------
// OFF

bool read_off(const std::string& path, const std::string& buf, MeshData& out, std::string& error) {
    LineReader lr(buf);
    const char *lb, *le, *tb, *te;
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
    out.positions.reserve(static_cast<size_t>(nv) * 3);
    if (has_normals) out.normals.reserve(static_cast<size_t>(nv) * 3);
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
        fan(poly, out.triangles);
    }
    if (nv == 0) return fail(error, path, 0, "no vertices");
    return true;
}

// ---------------------------------------------------------------------------------------------
// PLY

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
            out.positions.reserve(static_cast<size_t>(el.count) * 3);
            if (want_normals) out.normals.reserve(static_cast<size_t>(el.count) * 3);
            row.assign(el.props.size(), 0.0);
        } else if (is_face) {
            out.triangles.reserve(static_cast<size_t>(el.count) * 3);
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
                    fan(poly, out.triangles);
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

// ---------------------------------------------------------------------------------------------
// XYZ

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

// ---------------------------------------------------------------------------------------------
// Writing

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

// =============================================================================================
// Public functions

bool read_mesh(const std::string& path, MeshData& out, std::string& error) {
    out = MeshData{};
    const bool ok = guarded(path, error, [&]() {
        const std::string ext = lower_ext(path);
        if (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".xyz")
            return fail(error, path, 0,
                        "unknown mesh format '" + ext + "' (expected .obj, .off, .ply or .xyz)");
        std::string buf;
        if (!load_file(path, buf, error)) return false;
        if (ext == ".obj") return read_obj(path, buf, out, error);
        if (ext == ".off") return read_off(path, buf, out, error);
        if (ext == ".ply") return read_ply(path, buf, out, error);
        return read_xyz(path, buf, out, error);
    });
    if (!ok) out = MeshData{};
    return ok;
}

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

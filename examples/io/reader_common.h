// reader_common.h: helpers shared by the file readers in examples/io (internal, not installed):
// error messages, exception guard, whole-file loading, bounded tokenising of text buffers, the
// size limits every reader applies, and fan triangulation. Readers work on a buffer already in
// memory, so the same code serves files, standard input and the fuzz harnesses.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "mesh_io.h"

namespace caio {
namespace detail {

// ---- errors ----
// Sets error to "name[:line]: what" and returns false.
bool fail(std::string& error, const std::string& name, size_t line, const std::string& what);
// `text` fit for a one-line message: at most `max_chars` characters (then "..."), bytes outside
// printable ASCII as '?'.
std::string printable(const std::string& text, size_t max_chars);
// A token quoted for a message: at most 40 characters, non-printable bytes as '?'.
std::string quote_token(const char* b, const char* e);
std::string vcount_msg(size_t nv);

// Runs `body`, converting any exception into a false return with a message.
template <class F>
bool guarded(const std::string& name, std::string& error, F&& body) {
    try {
        return body();
    } catch (const std::bad_alloc&) {
        return fail(error, name, 0, "out of memory");
    } catch (const std::exception& e) {
        return fail(error, name, 0, std::string("internal error: ") + e.what());
    } catch (...) {
        return fail(error, name, 0, "internal error");
    }
}

// ---- loading ----
bool load_file(const std::string& path, std::string& buf, std::string& error);
bool load_stdin(std::string& buf, std::string& error);
// Lower-case extension with its dot (".obj"), or "".
std::string lower_ext(const std::string& path);

// ---- size limits (documented in mesh_io.h) ----
// Every supported encoding spends at least one input byte per vertex and per triangle, so a
// reader refuses output beyond one vertex and one triangle per input byte: memory stays
// proportional to the input even for instanced glTF nodes, accessors without data, or what
// assimp builds. A polygon has at most kMaxPolygon vertices.
constexpr size_t kMaxPolygon = 65536;
bool check_budget(const std::string& name, size_t input_bytes, size_t vertices, size_t triangles,
                  std::string& error);
// Fan-triangulates `poly` into `tris`; false with a message past kMaxPolygon.
bool fan(const std::string& name, size_t line, const std::vector<uint32_t>& poly,
         std::vector<uint32_t>& tris, std::string& error);

// ---- tokenising (all bounded by an end pointer; buffers need not be NUL-terminated) ----
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
// One double token [b, e) exactly: a leading '+', inf/nan accepted; overflow maps to +-inf and
// underflow to 0.
bool parse_double_token(const char* b, const char* e, double& v);
// One integer token exactly (optional sign).
bool parse_int_token(const char* b, const char* e, long long& v);

// Iterates the lines of a buffer, counting them (1-based).
struct LineReader {
    const char* p;
    const char* end;
    size_t line = 0;
    explicit LineReader(const std::string& buf) : p(buf.data()), end(buf.data() + buf.size()) {}
    // The next line [b, e) without its '\n'.
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

}  // namespace detail
}  // namespace caio

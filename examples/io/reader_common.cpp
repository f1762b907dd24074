// reader_common.cpp: the shared reader helpers declared in reader_common.h (messages, loading,
// number parsing, size limits, fan triangulation).
#include "reader_common.h"
#include "large_pages.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace caio {
namespace detail {

bool fail(std::string& error, const std::string& name, size_t line, const std::string& what) {
    error = name;
    if (line > 0) error += ":" + std::to_string(line);
    error += ": " + what;
    return false;
}

std::string printable(const std::string& text, size_t max_chars) {
    std::string s = text.substr(0, max_chars);
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
    if (text.size() > max_chars) s += "...";
    return s;
}

std::string quote_token(const char* b, const char* e) { return "'" + printable(std::string(b, e), 40) + "'"; }

std::string vcount_msg(size_t nv) { return std::to_string(nv) + (nv == 1 ? " vertex)" : " vertices)"); }

namespace {
bool read_stream(FILE* f, std::string& buf) {
    char chunk[1 << 16];
    for (;;) {
        const size_t n = std::fread(chunk, 1, sizeof chunk, f);
        buf.append(chunk, n);
        if (n < sizeof chunk) break;
    }
    return std::ferror(f) == 0;
}
}  // namespace

bool load_file(const std::string& path, std::string& buf, std::string& error) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return fail(error, path, 0, "is a directory");
    FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return fail(error, path, 0, std::string("cannot open: ") + std::strerror(errno));
    buf.clear();
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > 0 && size < (uint64_t(1) << 40)) {
        buf.reserve(static_cast<size_t>(size));
        ca::advise_huge_pages(buf.data(), static_cast<size_t>(size));
    }
    const bool ok = read_stream(f, buf);
    std::fclose(f);
    if (!ok) return fail(error, path, 0, "read error");
    return true;
}

bool load_stdin(std::string& buf, std::string& error) {
    buf.clear();
    if (!read_stream(stdin, buf)) return fail(error, "-", 0, "read error on standard input");
    return true;
}

std::string lower_ext(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

bool check_budget(const std::string& name, size_t input_bytes, size_t vertices, size_t triangles,
                  std::string& error) {
    if (vertices > input_bytes)
        return fail(error, name, 0,
                    std::to_string(vertices) + " vertices exceed the limit of one per input byte (" +
                        std::to_string(input_bytes) + " bytes)");
    if (triangles > input_bytes)
        return fail(error, name, 0,
                    std::to_string(triangles) + " triangles exceed the limit of one per input byte (" +
                        std::to_string(input_bytes) + " bytes)");
    return true;
}

bool fan(const std::string& name, size_t line, const std::vector<uint32_t>& poly,
         std::vector<uint32_t>& tris, std::string& error) {
    if (poly.size() > kMaxPolygon)
        return fail(error, name, line,
                    "polygon with " + std::to_string(poly.size()) + " vertices exceeds the limit of " +
                        std::to_string(kMaxPolygon));
    for (size_t k = 1; k + 1 < poly.size(); ++k) {
        tris.push_back(poly[0]);
        tris.push_back(poly[k]);
        tris.push_back(poly[k + 1]);
    }
    return true;
}

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

bool parse_int_token(const char* b, const char* e, long long& v) {
    if (b < e && *b == '+') ++b;
    if (b >= e) return false;
    auto r = std::from_chars(b, e, v);
    return r.ec == std::errc() && r.ptr == e;
}

}  // namespace detail
}  // namespace caio

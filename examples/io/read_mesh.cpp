// read_mesh.cpp: the entry points read_mesh and readable_formats: picks the reader by format
// name or extension, loads the file or standard input whole, runs the reader and applies the
// common size limit. Formats with a reader of their own (obj off ply xyz pts stl gltf glb) never
// go to assimp (is_assimp_input says which inputs do).
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

#include "mesh_io.h"
#include "readers.h"

namespace caio {
using namespace detail;
namespace {

const char* const kOwnFormats[] = {"obj", "off", "ply", "xyz", "pts", "stl", "gltf", "glb"};

bool own_format(const std::string& f) {
    return std::find(std::begin(kOwnFormats), std::end(kOwnFormats), f) != std::end(kOwnFormats);
}

std::string normalise_format(std::string f) {
    if (!f.empty() && f[0] == '.') f.erase(0, 1);
    for (char& c : f) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return f;
}

// The canonical folder of the file at `path` (external glTF URIs resolve only in it), or "".
std::string asset_folder(const std::string& path) {
    std::error_code ec;
    const auto real = std::filesystem::canonical(path, ec);
    return ec ? std::string() : real.parent_path().string();
}

bool parse_buffer(const std::string& name, const std::string& buf, const std::string& format,
                  const std::string& asset_dir, MeshData& out, std::string& error) {
    if (format == "obj") return read_obj(name, buf, out, error);
    if (format == "off") return read_off(name, buf, out, error);
    if (format == "ply") return read_ply(name, buf, out, error);
    if (format == "xyz") return read_xyz(name, buf, out, error);
    if (format == "pts") return read_pts(name, buf, out, error);
    if (format == "stl") return read_stl(name, buf, out, error);
    if (format == "gltf" || format == "glb") return read_gltf(name, buf, format == "glb", asset_dir, out, error);
    return read_assimp(name, buf, format, out, error);
}

// The format read_mesh uses: `format_name`, or if "" the extension of `path`.
std::string input_format(const std::string& path, const std::string& format_name) {
    return normalise_format(format_name.empty() ? lower_ext(path) : format_name);
}

}  // namespace

bool read_mesh(const std::string& path, const std::string& format_name, MeshData& out, std::string& error,
               const std::function<void(size_t)>& loaded) {
    out = MeshData{};
    const bool from_stdin = path == "-";
    const std::string name = from_stdin ? "<stdin>" : path;
    const bool ok = guarded(name, error, [&]() {
        const std::string format = input_format(path, format_name);
        if (format.empty())
            return fail(error, name, 0,
                        from_stdin ? "reading standard input needs a format name"
                                   : "no extension: give the format (" + readable_formats() + ")");
        if (!own_format(format) && !assimp_can_read(format))
            return fail(error, name, 0, "unknown mesh format '" + format + "' (readable: " + readable_formats() + ")");
        std::string buf;
        if (!(from_stdin ? load_stdin(buf, error) : load_file(path, buf, error))) return false;
        if (loaded) loaded(buf.size());
        if (!parse_buffer(name, buf, format, from_stdin ? std::string() : asset_folder(path), out, error)) return false;
        // glTF may add external buffers' bytes; its reader applied the limit with them included.
        if (format != "gltf" && format != "glb" &&
            !check_budget(name, buf.size(), out.positions.size() / 3, out.triangles.size() / 3, error))
            return false;
        return true;
    });
    if (!ok) out = MeshData{};
    return ok;
}

bool read_mesh(const std::string& path, MeshData& out, std::string& error) {
    return read_mesh(path, std::string(), out, error);
}

bool read_mesh_buffer(const std::string& buf, const std::string& format_name, MeshData& out, std::string& error) {
    out = MeshData{};
    const std::string format = normalise_format(format_name);
    const bool ok = guarded("<buffer>", error, [&]() {
        if (!own_format(format) && !assimp_can_read(format))
            return fail(error, "<buffer>", 0, "unknown mesh format '" + format + "'");
        return parse_buffer("<buffer>", buf, format, std::string(), out, error) &&
               check_budget("<buffer>", buf.size(), out.positions.size() / 3, out.triangles.size() / 3, error);
    });
    if (!ok) out = MeshData{};
    return ok;
}

bool is_assimp_input(const std::string& path, const std::string& format_name) {
    const std::string format = input_format(path, format_name);
    return !format.empty() && !own_format(format) && assimp_can_read(format);
}

bool is_readable_format(const std::string& format_name) {
    const std::string format = normalise_format(format_name);
    return !format.empty() && (own_format(format) || assimp_can_read(format));
}

std::string readable_formats() {
    std::string s;
    for (const char* f : kOwnFormats) s += (s.empty() ? "" : " ") + std::string(f);
    std::string extra;
    const std::string all = assimp_formats();
    size_t i = 0;
    while (i < all.size()) {
        size_t j = all.find(' ', i);
        if (j == std::string::npos) j = all.size();
        const std::string f = all.substr(i, j - i);
        if (!own_format(f)) extra += " " + f;
        i = j + 1;
    }
    if (!extra.empty()) s += "; through assimp:" + extra;
    return s;
}

}  // namespace caio

// readers.h: the per-format mesh and point-cloud readers behind read_mesh (internal). Each parses
// a buffer already in memory (`name` is used in messages only), so files, standard input and the
// fuzz harnesses share one code path. On failure `out` may be partly filled; read_mesh clears it.
#pragma once
#include <string>
#include <vector>

#include "mesh_io.h"
#include "reader_common.h"

struct aiScene;

namespace caio {
namespace detail {

bool read_obj(const std::string& name, const std::string& buf, MeshData& out, std::string& error);
bool read_off(const std::string& name, const std::string& buf, MeshData& out, std::string& error);
bool read_ply(const std::string& name, const std::string& buf, MeshData& out, std::string& error);
bool read_xyz(const std::string& name, const std::string& buf, MeshData& out, std::string& error);
bool read_pts(const std::string& name, const std::string& buf, MeshData& out, std::string& error);
bool read_stl(const std::string& name, const std::string& buf, MeshData& out, std::string& error);
// glTF 2.0, JSON (`binary` false) or GLB. External buffer and image URIs resolve only inside
// `asset_dir`; an empty asset_dir (standard input, fuzzing) refuses every external URI.
bool read_gltf(const std::string& name, const std::string& buf, bool binary, const std::string& asset_dir,
               MeshData& out, std::string& error);
// Any format assimp imports; `format` is the extension without its dot (a hint for assimp).
bool read_assimp(const std::string& name, const std::string& buf, const std::string& format, MeshData& out,
                 std::string& error);
bool assimp_can_read(const std::string& format);
// Whether an imported assimp scene is safe to post-process (check_assimp_scene.cpp); false with
// a message naming the first problem. `input_bytes` sets the size limit.
bool check_assimp_scene(const std::string& name, const aiScene* scene, size_t input_bytes, std::string& error);
// Takes out of an imported scene the parts the readers never use (animations, cameras, lights,
// embedded textures) that would fail assimp's validation, and the meshes without faces
// (drop_invalid_unused.cpp); one line per part dropped, "animation 'Take 001': keys past its
// duration", at most 1000 and then one counting the rest.
std::vector<std::string> drop_invalid_unused(aiScene& scene);
// The extensions assimp imports, without dots, space-separated.
std::string assimp_formats();

}  // namespace detail
}  // namespace caio

// readers.h: the per-format mesh and point-cloud readers behind read_mesh (internal). Each parses
// a buffer already in memory (`name` is used in messages only), so files, standard input and the
// fuzz harnesses share one code path. On failure `out` may be partly filled; read_mesh clears it.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "mesh_io.h"
#include "reader_common.h"

struct aiScene;

namespace caio {
namespace detail {

// ---- skins (skin_data.cpp) ----
using Mat4 = std::array<double, 16>;  // column-major, as glTF and ca_skin_view store matrices
Mat4 identity4();
Mat4 mul4(const Mat4& a, const Mat4& b);
// False when `m` is singular (or not finite); `out` is then undefined.
bool invert4(const Mat4& m, Mat4& out);
void transform_point(const Mat4& m, const double p[3], double out[3]);
// One vertex's `n` weights divided by their sum (a zero row stays zero, its joints set to 0);
// false on a weight that is negative, NaN or infinite.
bool normalise_row(double* weights, uint32_t* joints, size_t n);
// A vertex's (weight, joint) pairs, heaviest first (ties by joint), cut to `keep`.
void keep_heaviest(std::vector<std::pair<double, uint32_t>>& row, size_t keep);

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
// The triangles of a checked, post-processed scene, each node's meshes in world coordinates, and
// the bones as out.skin (place_assimp_meshes.cpp); false past the size limit or on a bad bone.
bool place_assimp_meshes(const std::string& name, const aiScene& scene, size_t input_bytes, MeshData& out,
                         std::string& error);
// Takes out of an imported scene the parts the readers never use (animations, cameras, lights,
// embedded textures) that would fail assimp's validation, and the meshes without faces
// (drop_invalid_unused.cpp); one line per part dropped, "animation 'Take 001': keys past its
// duration", at most 1000 and then one counting the rest.
std::vector<std::string> drop_invalid_unused(aiScene& scene);
// The extensions assimp imports, without dots, space-separated.
std::string assimp_formats();

}  // namespace detail
}  // namespace caio

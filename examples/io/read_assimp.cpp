// read_assimp.cpp: every other mesh format assimp imports (FBX, DAE, 3DS, ...). The file is
// handed to assimp from memory with an I/O system that opens nothing else, so files an asset
// references (materials, textures, external geometry) are never read. Assimp imports the scene
// with only its own structure validation; the scene then passes check_assimp_scene
// (check_assimp_scene.cpp) before any post-processing step runs, because those steps trust the
// importer's output and crash or abort on a malformed scene. Post-processing then drops the
// vertex attributes other than positions, triangulates and merges vertices at one position;
// place_assimp_meshes.cpp places every node's meshes in world units, with the bones as the skin.
// Point and line primitives are dropped. The output obeys the same one-per-input-byte limit as
// the other readers. Normals are not read (MeshData normals stay empty).
// Geometry first: assimp's validation refuses a whole scene for a fault in a part the readers
// never use (an animation key past its animation's end, an empty object, a camera's clip planes).
// When it refuses one, the file is imported again without validation, those parts are dropped
// (drop_invalid_unused.cpp, named in MeshData::dropped) and the validation runs on what is kept,
// then the scene checks as above. Validating first keeps assimp's own preparation of the scene
// (which runs between import and post-processing) away from scenes the validation refuses, for
// every file but these; where nothing is dropped the file is refused with the first message.
// Assimp's Collada reader does not advance past a non-digit in an index list (<p>, <v>,
// <vcount>, <h>) and fills memory until it runs out; such files are refused before assimp sees
// them. A crash or hang inside an importer itself cannot be caught here: the command-line tool
// runs this reader in a child process (examples/cli/isolated_read.cpp).
#include <assimp/IOStream.hpp>
#include <assimp/IOSystem.hpp>
#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <cctype>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "readers.h"

namespace caio {
namespace detail {
namespace {

// An I/O system with no files: assimp's readers can open only the buffer they were given.
class NoFiles : public Assimp::IOSystem {
public:
    bool Exists(const char*) const override { return false; }
    char getOsSeparator() const override { return '/'; }
    Assimp::IOStream* Open(const char*, const char*) override { return nullptr; }
    void Close(Assimp::IOStream* s) override { delete s; }
};

// True if some Collada index list holds a character other than digits and white space.
bool bad_collada_index_list(const std::string& buf) {
    for (const char* tag : {"<p>", "<v>", "<vcount>", "<h>"}) {
        for (size_t at = buf.find(tag); at != std::string::npos; at = buf.find(tag, at + 1)) {
            for (size_t i = at + std::strlen(tag); i < buf.size() && buf[i] != '<'; ++i) {
                const unsigned char c = static_cast<unsigned char>(buf[i]);
                if (!std::isdigit(c) && !std::isspace(c)) return true;
            }
        }
    }
    return false;
}

}  // namespace

bool assimp_can_read(const std::string& format) {
    if (format.empty()) return false;
    Assimp::Importer importer;
    return importer.IsExtensionSupported("." + format);
}

std::string assimp_formats() {
    Assimp::Importer importer;
    std::string list;
    importer.GetExtensionList(list);  // "*.3ds;*.obj;..."
    std::string out;
    size_t i = 0;
    while (i < list.size()) {
        size_t j = list.find(';', i);
        if (j == std::string::npos) j = list.size();
        std::string ext = list.substr(i, j - i);
        if (ext.compare(0, 2, "*.") == 0) ext = ext.substr(2);
        if (!ext.empty()) out += (out.empty() ? "" : " ") + ext;
        i = j + 1;
    }
    return out;
}

bool read_assimp(const std::string& name, const std::string& buf, const std::string& format, MeshData& out,
                 std::string& error) {
    if (buf.empty()) return fail(error, name, 0, "empty file");
    if ((format == "dae" || format == "zae" || buf.find("<COLLADA") != std::string::npos) && bad_collada_index_list(buf))
        return fail(error, name, 0, "Collada index list (<p>, <v>, <vcount> or <h>) holds a character other than digits");
    Assimp::Importer importer;
    importer.SetIOHandler(new NoFiles);  // owned by the importer
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const aiScene* scene =
        importer.ReadFileFromMemory(buf.data(), buf.size(), aiProcess_ValidateDataStructure, format.c_str());
    // assimp's messages may quote a long stretch of the file: one short line of it is kept
    constexpr size_t kMessageChars = 200;
    std::vector<std::string> dropped;
    if (!scene) {
        const std::string refused = importer.GetErrorString();
        if (refused.rfind("Validation failed", 0) != 0) return fail(error, name, 0, "assimp: " + printable(refused, kMessageChars));
        // geometry first: import again unvalidated, drop the unused parts at fault, validate the rest
        scene = importer.ReadFileFromMemory(buf.data(), buf.size(), 0, format.c_str());
        if (scene) dropped = drop_invalid_unused(*const_cast<aiScene*>(scene));  // the importer's own scene
        if (!scene || dropped.empty()) return fail(error, name, 0, "assimp: " + printable(refused, kMessageChars));
        const std::string after = " (after dropping " + std::to_string(dropped.size()) + " unused part" +
                                  (dropped.size() == 1 ? "" : "s") + " at fault: " + printable(dropped[0], 100) +
                                  (dropped.size() == 1 ? ")" : ", ...)");
        if (scene->mNumMeshes == 0) return fail(error, name, 0, "no meshes with faces" + after);
        scene = importer.ApplyPostProcessing(aiProcess_ValidateDataStructure);
        if (!scene) return fail(error, name, 0, "assimp: " + printable(importer.GetErrorString(), kMessageChars) + after);
    }
    if (!check_assimp_scene(name, scene, buf.size(), error)) return false;
    // Normals, tangents, colours and texture coordinates are removed first (the readers use none
    // of them), so the join merges every corner at one position and the surface comes out
    // connected, not split at each crease or UV seam. No PreTransformVertices: it deletes the
    // bones; place_assimp_meshes places the instances.
    importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS | aiComponent_TANGENTS_AND_BITANGENTS |
                                                            aiComponent_COLORS | aiComponent_TEXCOORDS);
    scene = importer.ApplyPostProcessing(aiProcess_RemoveComponent | aiProcess_Triangulate |
                                         aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
    if (!scene)
        return fail(error, name, 0, "assimp post-processing: " + printable(importer.GetErrorString(), kMessageChars));
    if (!place_assimp_meshes(name, *scene, buf.size(), out, error)) return false;
    if (out.triangles.empty()) return fail(error, name, 0, "no triangles");
    const std::string skin = skin_problem(out);
    if (!skin.empty()) return fail(error, name, 0, "skin: " + skin);
    out.dropped = std::move(dropped);
    return true;
}

}  // namespace detail
}  // namespace caio

// drop_invalid_unused.cpp: takes out of an imported assimp scene the parts the readers never use
// that would make assimp's validation refuse the whole file: animations, cameras, lights and
// embedded textures that break the validation's rules, and meshes without faces (they add no
// triangle). Assimp's validation (aiProcess_ValidateDataStructure) refuses a scene for any fault,
// so files with sound geometry were refused for an animation key one frame past its animation's
// end, or for one empty object among thousands. The rules below are assimp 5.2's for these parts;
// a fault they miss still makes the validation, which runs on what is kept, refuse the file, and
// so does any fault of the geometry, materials, bones or node tree, which are never dropped.
// This runs before any validation, on a scene nothing has checked: every pointer is tested
// before it is followed, and the node tree is walked without recursion, each node once. A part
// that is itself a null pointer is dropped as missing; a null mesh is left for the checks to
// refuse. The scene is edited in place, as assimp's own post-processing steps edit it.
#include <assimp/scene.h>

#include <cstring>
#include <string>
#include <unordered_set>
#include <vector>

#include "readers.h"

namespace caio {
namespace detail {
namespace {

// A part's name is quoted in messages up to this many characters.
constexpr size_t kNameChars = 60;
// Parts named one by one; past it one line counts the rest (a file can hold millions of parts).
constexpr size_t kMaxNamed = 1000;
// Assimp accepts a key this far past its animation's duration (its validation's tolerance).
constexpr double kKeyTimeSlack = 0.001;

// A well-formed aiString as assimp's validation wants it: its terminating zero where its length
// says, within its buffer.
bool valid_string(const aiString& s) {
    const void* zero = std::memchr(s.data, 0, MAXLEN);
    return zero && size_t(static_cast<const char*>(zero) - s.data) == s.length;
}

std::string label(const char* kind, const aiString& name, unsigned index) {
    if (valid_string(name) && name.length > 0) return std::string(kind) + " '" + printable(name.C_Str(), kNameChars) + "'";
    return std::string(kind) + " " + std::to_string(index);
}

// Every node reachable from the root, each once, without recursion (the tree is not checked yet).
std::vector<aiNode*> scene_nodes(const aiScene& scene) {
    std::vector<aiNode*> nodes, stack;
    std::unordered_set<const aiNode*> seen;
    if (scene.mRootNode) stack.push_back(scene.mRootNode);
    while (!stack.empty()) {
        aiNode* node = stack.back();
        stack.pop_back();
        if (!seen.insert(node).second) continue;
        nodes.push_back(node);
        if (node->mNumChildren > 0 && node->mChildren)
            for (unsigned c = node->mNumChildren; c-- > 0;)
                if (node->mChildren[c]) stack.push_back(node->mChildren[c]);
    }
    return nodes;
}

class Dropper {
public:
    explicit Dropper(aiScene& scene) : scene_(scene), nodes_(scene_nodes(scene)) {}

    std::vector<std::string> run() {
        drop_from(scene_.mAnimations, scene_.mNumAnimations, "animation",
                  [&](const aiAnimation& a, unsigned) { return animation_fault(a); });
        std::vector<const aiString*> names;
        drop_from(scene_.mCameras, scene_.mNumCameras, "camera", [&](const aiCamera& c, unsigned) {
            if (c.mClipPlaneFar <= c.mClipPlaneNear) return std::string("its far clip plane is not beyond its near one");
            return name_fault(c.mName, names, "camera");
        });
        names.clear();
        drop_from(scene_.mLights, scene_.mNumLights, "light", [&](const aiLight& l, unsigned) {
            if (l.mAngleInnerCone > l.mAngleOuterCone) return std::string("its inner cone is wider than its outer one");
            return name_fault(l.mName, names, "light");
        });
        drop_from(scene_.mTextures, scene_.mNumTextures, "texture",
                  [&](const aiTexture& t, unsigned) { return texture_fault(t); });
        drop_empty_meshes();
        if (dropped_.size() > kMaxNamed) {
            const size_t more = dropped_.size() - kMaxNamed;
            dropped_.resize(kMaxNamed);
            dropped_.push_back("and " + std::to_string(more) + " more");
        }
        return std::move(dropped_);
    }

private:
    static const aiString& name_of(const aiAnimation& a) { return a.mName; }
    static const aiString& name_of(const aiCamera& c) { return c.mName; }
    static const aiString& name_of(const aiLight& l) { return l.mName; }
    static const aiString& name_of(const aiTexture& t) { return t.mFilename; }

    // Drops the entries of `array` for which `fault` names a fault (a null entry is "missing"),
    // keeping the others in order. A list that is missing as a whole is left to the validation.
    template <class T, class Fault>
    void drop_from(T**& array, unsigned& count, const char* kind, Fault fault) {
        if (count == 0 || !array) return;
        unsigned kept = 0;
        for (unsigned i = 0; i < count; ++i) {
            T* part = array[i];
            const std::string why = part ? fault(*part, i) : "missing";
            if (why.empty()) {
                array[kept++] = part;
                continue;
            }
            dropped_.push_back((part ? label(kind, name_of(*part), i) : std::string(kind) + " " + std::to_string(i)) + ": " + why);
            delete part;
        }
        count = kept;
        if (kept == 0) {
            delete[] array;
            array = nullptr;
        }
    }

    // Keys of one track: a missing list, or a key past the animation's duration.
    template <class Key>
    static std::string keys_fault(const aiAnimation& a, const Key* keys, unsigned n) {
        if (n > 0 && !keys) return "a missing key list";
        for (unsigned k = 0; k < n; ++k)
            if (a.mDuration > 0 && keys[k].mTime > a.mDuration + kKeyTimeSlack) return "keys past its duration";
        return "";
    }

    static std::string animation_fault(const aiAnimation& a) {
        if (!valid_string(a.mName)) return "a malformed name";
        if (a.mNumChannels == 0 && a.mNumMorphMeshChannels == 0) return "no channels";
        if ((a.mNumChannels > 0 && !a.mChannels) || (a.mNumMorphMeshChannels > 0 && !a.mMorphMeshChannels))
            return "a missing channel list";
        for (unsigned c = 0; c < a.mNumChannels; ++c) {
            const aiNodeAnim* ch = a.mChannels[c];
            if (!ch) return "a missing channel";
            if (!valid_string(ch->mNodeName)) return "a channel with a malformed name";
            if (ch->mNumPositionKeys == 0 && ch->mNumRotationKeys == 0 && (ch->mNumScalingKeys == 0 || !ch->mScalingKeys))
                return "an empty channel";
            for (const std::string& why : {keys_fault(a, ch->mPositionKeys, ch->mNumPositionKeys),
                                           keys_fault(a, ch->mRotationKeys, ch->mNumRotationKeys),
                                           keys_fault(a, ch->mScalingKeys, ch->mNumScalingKeys)})
                if (!why.empty()) return why;
        }
        for (unsigned c = 0; c < a.mNumMorphMeshChannels; ++c) {
            const aiMeshMorphAnim* ch = a.mMorphMeshChannels[c];
            if (!ch) return "a missing channel";
            if (!valid_string(ch->mName)) return "a channel with a malformed name";
            const std::string why = keys_fault(a, ch->mKeys, ch->mNumKeys);
            if (!why.empty()) return why;
        }
        return "";
    }

    static std::string texture_fault(const aiTexture& t) {
        if (!t.pcData) return "no data";
        if (t.mWidth == 0) return "no width";
        for (int k = 0; k < 4; ++k)
            if (t.achFormatHint[k] >= 'A' && t.achFormatHint[k] <= 'Z') return "a format hint in capitals";
        return "";
    }

    // A camera or light is tied to the one node of its name, and no two share a name; `kept`
    // holds the names of those kept so far.
    std::string name_fault(const aiString& name, std::vector<const aiString*>& kept, const char* kind) const {
        if (!valid_string(name)) return "a malformed name";
        for (const aiString* other : kept)
            if (*other == name) return std::string("the name of another ") + kind;
        size_t nodes = 0;
        for (const aiNode* node : nodes_) nodes += node->mName == name;
        if (nodes == 0) return "no node of its name";
        if (nodes > 1) return "more than one node of its name";
        kept.push_back(&name);
        return "";
    }

    // Meshes without faces add nothing: they go, and the nodes' mesh lists are renumbered (an
    // index out of range stays out of range, for the checks to refuse).
    void drop_empty_meshes() {
        const unsigned count = scene_.mNumMeshes;
        if (count == 0 || !scene_.mMeshes) return;
        std::vector<long long> new_index(count, -1);
        unsigned kept = 0;
        for (unsigned m = 0; m < count; ++m) {
            aiMesh* mesh = scene_.mMeshes[m];
            if (!mesh || mesh->mNumFaces > 0) {
                new_index[m] = kept;
                scene_.mMeshes[kept++] = mesh;
                continue;
            }
            dropped_.push_back(mesh_label(*mesh, m) + (mesh->mNumVertices == 0 ? ": no vertices" : ": no faces"));
            delete mesh;
        }
        if (kept == count) return;
        scene_.mNumMeshes = kept;
        if (kept == 0) {
            delete[] scene_.mMeshes;
            scene_.mMeshes = nullptr;
        }
        for (aiNode* node : nodes_) {
            if (node->mNumMeshes == 0 || !node->mMeshes) continue;
            unsigned n = 0;
            for (unsigned k = 0; k < node->mNumMeshes; ++k) {
                const unsigned m = node->mMeshes[k];
                if (m >= count) node->mMeshes[n++] = m;
                else if (new_index[m] >= 0) node->mMeshes[n++] = unsigned(new_index[m]);
            }
            node->mNumMeshes = n;
            if (n == 0) {
                delete[] node->mMeshes;
                node->mMeshes = nullptr;
            }
        }
    }

    // A mesh by its name, else by the name of the first node that instances it (formats such as
    // Blitz3D name only nodes), else by its index.
    std::string mesh_label(const aiMesh& mesh, unsigned m) const {
        if (valid_string(mesh.mName) && mesh.mName.length > 0) return label("mesh", mesh.mName, m);
        for (const aiNode* node : nodes_)
            if (node->mNumMeshes > 0 && node->mMeshes)
                for (unsigned k = 0; k < node->mNumMeshes; ++k)
                    if (node->mMeshes[k] == m) return label("mesh", node->mName, m);
        return "mesh " + std::to_string(m);
    }

    aiScene& scene_;
    std::vector<aiNode*> nodes_;
    std::vector<std::string> dropped_;
};

}  // namespace

std::vector<std::string> drop_invalid_unused(aiScene& scene) { return Dropper(scene).run(); }

}  // namespace detail
}  // namespace caio

// test_drop_invalid_unused.cpp: tests of the step that takes out of an imported assimp scene the
// unused parts assimp's validation would refuse (examples/io/drop_invalid_unused.cpp), on scenes
// built by hand with sound and faulty parts side by side, and of the assimp reader on the files
// of tests/data/dropped, which assimp's validation refuses whole.
#include <doctest/doctest.h>

#include <assimp/material.h>
#include <assimp/scene.h>
#include <assimp/texture.h>

#include <memory>
#include <string>
#include <vector>

#include "assimp_shapes.h"
#include "mesh_io.h"
#include "readers.h"

namespace {

const std::string kDropped = std::string(CA_TEST_DATA) + "/dropped/";

// A scene of `meshes` (owned), a material, and a root node instancing every mesh, with one child
// node per name in `node_names`.
std::unique_ptr<aiScene> scene_of(const std::vector<aiMesh*>& meshes, const std::vector<std::string>& node_names = {}) {
    auto scene = std::make_unique<aiScene>();
    scene->mNumMeshes = unsigned(meshes.size());
    scene->mMeshes = new aiMesh*[meshes.size()];
    for (size_t m = 0; m < meshes.size(); ++m) scene->mMeshes[m] = meshes[m];
    scene->mNumMaterials = 1;
    scene->mMaterials = new aiMaterial*[1]{new aiMaterial};
    scene->mRootNode = new aiNode("root");
    scene->mRootNode->mNumMeshes = unsigned(meshes.size());
    scene->mRootNode->mMeshes = new unsigned[meshes.size()];
    for (size_t m = 0; m < meshes.size(); ++m) scene->mRootNode->mMeshes[m] = unsigned(m);
    if (!node_names.empty()) {
        scene->mRootNode->mNumChildren = unsigned(node_names.size());
        scene->mRootNode->mChildren = new aiNode*[node_names.size()];
        for (size_t c = 0; c < node_names.size(); ++c) {
            scene->mRootNode->mChildren[c] = new aiNode(node_names[c]);
            scene->mRootNode->mChildren[c]->mParent = scene->mRootNode;
        }
    }
    return scene;
}

// An animation of `duration` ticks with one channel on node `node`, its position keys at `times`.
aiAnimation* animation(const char* name, double duration, const char* node, const std::vector<double>& times) {
    aiAnimation* a = new aiAnimation;
    a->mName = aiString(name);
    a->mDuration = duration;
    a->mNumChannels = 1;
    a->mChannels = new aiNodeAnim*[1]{new aiNodeAnim};
    aiNodeAnim* ch = a->mChannels[0];
    ch->mNodeName = aiString(node);
    ch->mNumPositionKeys = unsigned(times.size());
    ch->mPositionKeys = new aiVectorKey[times.size()];
    for (size_t k = 0; k < times.size(); ++k) ch->mPositionKeys[k] = aiVectorKey(times[k], aiVector3D(0, 0, 0));
    return a;
}

aiCamera* camera(const char* name, float near_plane, float far_plane) {
    aiCamera* c = new aiCamera;
    c->mName = aiString(name);
    c->mClipPlaneNear = near_plane;
    c->mClipPlaneFar = far_plane;
    return c;
}

aiLight* light(const char* name, float inner, float outer) {
    aiLight* l = new aiLight;
    l->mName = aiString(name);
    l->mType = aiLightSource_SPOT;
    l->mAngleInnerCone = inner;
    l->mAngleOuterCone = outer;
    return l;
}

template <class T>
void set_parts(T**& array, unsigned& count, const std::vector<T*>& parts) {
    count = unsigned(parts.size());
    array = new T*[parts.size()];
    for (size_t i = 0; i < parts.size(); ++i) array[i] = parts[i];
}

using Lines = std::vector<std::string>;

}  // namespace

TEST_CASE("drop invalid unused: a sound scene keeps every part") {
    auto s = scene_of({tetrahedron_mesh()}, {"arm", "Camera", "Spot"});
    set_parts(s->mAnimations, s->mNumAnimations, {animation("walk", 20, "arm", {0, 10, 20})});
    set_parts(s->mCameras, s->mNumCameras, {camera("Camera", 0.1f, 100)});
    set_parts(s->mLights, s->mNumLights, {light("Spot", 0.3f, 0.5f)});
    CHECK(caio::detail::drop_invalid_unused(*s) == Lines{});
    CHECK(s->mNumMeshes == 1);
    CHECK(s->mNumAnimations == 1);
    CHECK(s->mNumCameras == 1);
    CHECK(s->mNumLights == 1);
}

TEST_CASE("drop invalid unused: animations with keys past their duration go, the others stay") {
    auto s = scene_of({tetrahedron_mesh()}, {"arm"});
    set_parts(s->mAnimations, s->mNumAnimations,
              {animation("Take 001", 220, "arm", {1, 110, 221}),  // one key a frame past the end
               animation("walk", 20, "arm", {0, 20.0005}),         // within assimp's tolerance
               animation("", 5, "arm", {6}), nullptr});
    const Lines dropped = caio::detail::drop_invalid_unused(*s);
    CHECK(dropped == Lines{"animation 'Take 001': keys past its duration", "animation 2: keys past its duration",
                           "animation 3: missing"});
    REQUIRE(s->mNumAnimations == 1);
    CHECK(std::string(s->mAnimations[0]->mName.C_Str()) == "walk");
    // an animation without channels, or whose only channel has no keys
    auto t = scene_of({tetrahedron_mesh()}, {"arm"});
    set_parts(t->mAnimations, t->mNumAnimations, {new aiAnimation, animation("idle", 10, "arm", {})});
    CHECK(caio::detail::drop_invalid_unused(*t) == Lines{"animation 0: no channels", "animation 'idle': an empty channel"});
    CHECK(t->mNumAnimations == 0);
    CHECK(t->mAnimations == nullptr);
}

TEST_CASE("drop invalid unused: cameras and lights at fault go, each named with its fault") {
    auto s = scene_of({tetrahedron_mesh()}, {"Camera", "Camera.001", "Spot", "Twice", "Twice"});
    set_parts(s->mCameras, s->mNumCameras,
              {camera("Camera", 100, 0.1f), camera("Camera.001", 0.1f, 100), camera("Camera.001", 0.1f, 50),
               camera("Nowhere", 0.1f, 100), camera("Twice", 0.1f, 100)});
    set_parts(s->mLights, s->mNumLights, {light("Spot", 1.0f, 0.3f), light("Camera", 0.2f, 0.3f)});
    const Lines dropped = caio::detail::drop_invalid_unused(*s);
    CHECK(dropped == Lines{"camera 'Camera': its far clip plane is not beyond its near one",
                           "camera 'Camera.001': the name of another camera", "camera 'Nowhere': no node of its name",
                           "camera 'Twice': more than one node of its name",
                           "light 'Spot': its inner cone is wider than its outer one"});
    REQUIRE(s->mNumCameras == 1);
    CHECK(s->mCameras[0]->mClipPlaneFar == 100);
    REQUIRE(s->mNumLights == 1);  // a light may share a camera's name
    CHECK(std::string(s->mLights[0]->mName.C_Str()) == "Camera");
}

TEST_CASE("drop invalid unused: embedded textures without data go") {
    auto s = scene_of({tetrahedron_mesh()});
    aiTexture* good = new aiTexture;
    good->mWidth = 4;
    good->pcData = new aiTexel[4];
    aiTexture* empty = new aiTexture;
    empty->mFilename = aiString("skin.png");
    set_parts(s->mTextures, s->mNumTextures, {good, empty});
    CHECK(caio::detail::drop_invalid_unused(*s) == Lines{"texture 'skin.png': no data"});
    REQUIRE(s->mNumTextures == 1);
    CHECK(s->mTextures[0] == good);
}

TEST_CASE("drop invalid unused: meshes without faces go and the nodes' mesh lists are renumbered") {
    aiMesh* empty = new aiMesh;  // named by the node that instances it
    aiMesh* points_only = new aiMesh;
    points_only->mName = aiString("Box.003");
    points_only->mNumVertices = 2;
    points_only->mVertices = new aiVector3D[2];
    aiMesh* a = tetrahedron_mesh();
    aiMesh* b = tetrahedron_mesh();
    auto s = scene_of({empty, a, points_only, b}, {"Empty"});
    s->mRootNode->mNumMeshes = 1;
    s->mRootNode->mMeshes[0] = 3;  // the root instances b
    aiNode* child = s->mRootNode->mChildren[0];
    child->mNumMeshes = 4;
    child->mMeshes = new unsigned[4]{1, 0, 2, 9};  // a, the two empty meshes, an index out of range
    const Lines dropped = caio::detail::drop_invalid_unused(*s);
    // "Empty" is the first node instancing mesh 0 in the walk (the root instances only b)
    CHECK(dropped == Lines{"mesh 'Empty': no vertices", "mesh 'Box.003': no faces"});
    REQUIRE(s->mNumMeshes == 2);
    CHECK(s->mMeshes[0] == a);
    CHECK(s->mMeshes[1] == b);
    REQUIRE(s->mRootNode->mNumMeshes == 1);
    CHECK(s->mRootNode->mMeshes[0] == 1);
    REQUIRE(child->mNumMeshes == 2);
    CHECK(child->mMeshes[0] == 0);
    CHECK(child->mMeshes[1] >= s->mNumMeshes);  // still out of range, for the checks to refuse
}

TEST_CASE("drop invalid unused: a null mesh is left for the checks, and every part named past 1000 is counted") {
    auto s = scene_of({nullptr, tetrahedron_mesh()});
    CHECK(caio::detail::drop_invalid_unused(*s) == Lines{});
    CHECK(s->mNumMeshes == 2);
    std::string error;
    CHECK_FALSE(caio::detail::check_assimp_scene("s", s.get(), 1000, error));

    std::vector<aiMesh*> meshes(1005, nullptr);
    for (aiMesh*& m : meshes) m = new aiMesh;
    meshes.push_back(tetrahedron_mesh());
    auto many = scene_of(meshes);
    const Lines dropped = caio::detail::drop_invalid_unused(*many);
    REQUIRE(dropped.size() == 1001);
    CHECK(dropped[0] == "mesh 'root': no vertices");
    CHECK(dropped[1000] == "and 5 more");
    REQUIRE(many->mNumMeshes == 1);
    CHECK(many->mRootNode->mNumMeshes == 1);
    CHECK(many->mRootNode->mMeshes[0] == 0);
}

TEST_CASE("assimp reader: files refused whole by assimp's validation give their geometry and name what was dropped") {
    struct Case {
        const char* file;
        Lines dropped;
        size_t vertices, triangles;
    };
    // ellipsoids of 12 slices and 8 stacks (make_dropped.py): 86 vertices and 168 triangles each
    const Case cases[] = {
        {"keys_past_duration.b3d", {"animation 0: keys past its duration"}, 86, 168},
        {"empty_mesh.b3d", {"mesh 'Box.003': no vertices"}, 3 * 86, 3 * 168},
        {"camera_light.dae",
         {"camera 'Camera-node': its far clip plane is not beyond its near one",
          "light 'Spot-node': its inner cone is wider than its outer one"},
         3 * 86,
         3 * 168},
    };
    for (const Case& c : cases) {
        INFO(c.file);
        caio::MeshData m;
        std::string error;
        CHECK(caio::read_mesh(kDropped + c.file, m, error));
        INFO(error);
        CHECK(m.dropped == c.dropped);
        CHECK(m.positions.size() == 3 * c.vertices);
        CHECK(m.triangles.size() == 3 * c.triangles);
    }
}

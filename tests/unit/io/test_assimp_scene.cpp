// test_assimp_scene.cpp: tests of the checks an assimp scene passes before post-processing
// (examples/io/check_assimp_scene.cpp), on scenes built by hand with one flaw each, and of the
// assimp reader on the bundled files whose scenes assimp's post-processing crashed or aborted on
// and on a file whose message from assimp quotes the rest of the file.
#include <doctest/doctest.h>

#include <assimp/material.h>
#include <assimp/scene.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "assimp_shapes.h"
#include "io_test_util.h"
#include "mesh_io.h"
#include "readers.h"

namespace {

const std::string kHostile = std::string(CA_TEST_DATA) + "/hostile/";

// A tetrahedron: one mesh of four triangles, one material, instanced by the root node.
std::unique_ptr<aiScene> tetrahedron() {
    auto scene = std::make_unique<aiScene>();
    aiMesh* mesh = tetrahedron_mesh();
    scene->mNumMeshes = 1;
    scene->mMeshes = new aiMesh*[1]{mesh};
    scene->mNumMaterials = 1;
    scene->mMaterials = new aiMaterial*[1]{new aiMaterial};
    scene->mRootNode = new aiNode("root");
    scene->mRootNode->mNumMeshes = 1;
    scene->mRootNode->mMeshes = new unsigned[1]{0};
    return scene;
}

// Adds `count` children to `parent`, each instancing mesh 0 unless `empty`.
void add_children(aiNode* parent, unsigned count, bool empty = false) {
    aiNode** children = new aiNode*[count];
    for (unsigned c = 0; c < count; ++c) {
        children[c] = new aiNode;
        children[c]->mParent = parent;
        if (!empty) {
            children[c]->mNumMeshes = 1;
            children[c]->mMeshes = new unsigned[1]{0};
        }
    }
    parent->mChildren = children;
    parent->mNumChildren = count;
}

// The check's message, "" if the scene passes.
std::string problem(const aiScene* scene, size_t input_bytes = 1000) {
    std::string error;
    const bool ok = caio::detail::check_assimp_scene("s", scene, input_bytes, error);
    CHECK(ok == error.empty());
    return error;
}

bool says(const std::string& error, const char* what) {
    INFO(error);
    return error.find(what) != std::string::npos;
}

}  // namespace

TEST_CASE("assimp scene check: a sound scene passes") {
    CHECK(problem(tetrahedron().get()) == "");
}

TEST_CASE("assimp scene check: missing arrays and null pointers are refused") {
    CHECK(says(problem(nullptr), "none"));
    auto s = tetrahedron();
    aiMesh* mesh = s->mMeshes[0];
    s->mMeshes[0] = nullptr;
    CHECK(says(problem(s.get()), "mesh 0 is missing"));
    s->mMeshes[0] = mesh;

    aiFace& face = mesh->mFaces[2];
    unsigned* indices = face.mIndices;
    face.mIndices = nullptr;
    CHECK(says(problem(s.get()), "mesh 0 face 2 has no indices"));
    face.mIndices = indices;
    face.mNumIndices = 0;
    CHECK(says(problem(s.get()), "mesh 0 face 2 has no indices"));
    face.mNumIndices = 3;

    aiNode* root = s->mRootNode;
    s->mRootNode = nullptr;
    CHECK(says(problem(s.get()), "no root node"));
    s->mRootNode = root;
    CHECK(problem(s.get()) == "");
}

TEST_CASE("assimp scene check: indices, material indices and bone weights out of range are refused") {
    auto s = tetrahedron();
    aiMesh* mesh = s->mMeshes[0];
    mesh->mFaces[3].mIndices[1] = 4;
    CHECK(says(problem(s.get()), "mesh 0 face 3 has an index out of range (4 vertices)"));
    mesh->mFaces[3].mIndices[1] = 2;
    mesh->mMaterialIndex = 1;
    CHECK(says(problem(s.get()), "material that does not exist"));
    mesh->mMaterialIndex = 0;
    s->mRootNode->mMeshes[0] = 1;
    CHECK(says(problem(s.get()), "names a mesh that does not exist"));
    s->mRootNode->mMeshes[0] = 0;
    mesh->mNumBones = 1;
    mesh->mBones = new aiBone*[1]{new aiBone};
    mesh->mBones[0]->mNumWeights = 1;
    mesh->mBones[0]->mWeights = new aiVertexWeight[1]{{7, 1.0f}};
    CHECK(says(problem(s.get()), "weighs a vertex out of range"));
    mesh->mBones[0]->mWeights[0].mVertexId = 3;
    CHECK(problem(s.get()) == "");
}

TEST_CASE("assimp scene check: non-finite positions and node transforms are refused") {
    auto s = tetrahedron();
    s->mMeshes[0]->mVertices[3].y = std::numeric_limits<float>::quiet_NaN();
    CHECK(says(problem(s.get()), "mesh 0 vertex 3 is not finite"));
    s->mMeshes[0]->mVertices[3].y = 0;
    s->mRootNode->mTransformation.a4 = std::numeric_limits<float>::infinity();
    CHECK(says(problem(s.get()), "transform is not finite"));
}

TEST_CASE("assimp scene check: a node twice in the tree, a wrong parent and a too deep tree are refused") {
    auto s = tetrahedron();
    add_children(s->mRootNode, 2, true);
    aiNode* second = s->mRootNode->mChildren[1];
    s->mRootNode->mChildren[1] = s->mRootNode->mChildren[0];  // the first child twice
    CHECK(says(problem(s.get()), "appears twice"));
    s->mRootNode->mChildren[1] = second;
    second->mParent = nullptr;
    CHECK(says(problem(s.get()), "names another parent"));
    second->mParent = s->mRootNode;
    CHECK(problem(s.get()) == "");

    // a chain down to level 1024 (the root is level 1) passes; one level more is refused
    aiNode* node = s->mRootNode->mChildren[0];
    for (int level = 3; level <= 1024; ++level) {
        add_children(node, 1, true);
        node = node->mChildren[0];
    }
    CHECK(problem(s.get(), 2000) == "");
    CHECK(says(problem(s.get(), 1000), "more nodes than input bytes"));
    add_children(node, 1, true);
    CHECK(says(problem(s.get(), 2000), "deeper than 1024 levels"));
}

TEST_CASE("assimp scene check: meshes are counted once per node that instances them") {
    // the root and 30 children instance the tetrahedron: 31 x 4 = 124 triangles, 124 vertices
    // and 372 corners
    auto s = tetrahedron();
    add_children(s->mRootNode, 30);
    CHECK(problem(s.get(), 124) == "");
    CHECK(says(problem(s.get(), 123), "124 triangles exceed the limit of one per input byte (123 bytes)"));
    // a mesh of lines makes no triangles: its corners (8 per instance) meet their limit of three
    // per input byte
    for (unsigned f = 0; f < 4; ++f) s->mMeshes[0]->mFaces[f].mNumIndices = 2;
    CHECK(problem(s.get(), 83) == "");
    CHECK(says(problem(s.get(), 82), "more than 3 vertices or face corners per input byte (82 bytes)"));
}

TEST_CASE("assimp reader: scenes its post-processing crashed or aborted on are refused before it") {
    // assimp's MD3 importer leaves a null mesh in misc_telep.md3; in assimp_ac_abort.ac the AC3D
    // importer makes a face without indices, on which triangulation's assertion aborts
    for (const char* file : {"misc_telep.md3", "assimp_ac_abort.ac"}) {
        caio::MeshData m;
        std::string error;
        INFO(file);
        CHECK_FALSE(caio::read_mesh(kHostile + file, m, error));
        INFO(error);
        CHECK(error.find(file) != std::string::npos);
        CHECK(m.positions.empty());
    }
}

TEST_CASE("assimp reader: assimp's message is cut to one short printable line") {
    // AC3D's number parser quotes everything after the bad number, here over 7000 bytes
    std::string ac = "AC3Db\nOBJECT world\nkids 1\nOBJECT poly\nnumvert 3\n0 0 0\n1 0 0\n0 1 0\nnumsurf 1\n"
                     "SURF 0x10\nmat 0\nrefs 3\n0 0 0\n1 0 0\n2 0{0\n";
    for (int k = 0; k < 1000; ++k) ac += "kids 0\n";
    iotest::TempDir td;
    caio::MeshData m;
    std::string error;
    CHECK_FALSE(caio::read_mesh(td.write("long.ac", ac), m, error));
    INFO(error);
    CHECK(error.find("assimp: ") != std::string::npos);
    CHECK(error.size() < td.path("long.ac").size() + 250);
    CHECK(error.find('\n') == std::string::npos);
}

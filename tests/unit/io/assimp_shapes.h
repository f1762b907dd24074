// assimp_shapes.h: assimp meshes built by hand for the reader's scene tests (the caller's scene
// owns what it is given).
#pragma once
#include <assimp/scene.h>

// A tetrahedron: four vertices, four outward triangles.
inline aiMesh* tetrahedron_mesh() {
    aiMesh* mesh = new aiMesh;
    mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    mesh->mNumVertices = 4;
    mesh->mVertices = new aiVector3D[4]{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const unsigned corners[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    mesh->mNumFaces = 4;
    mesh->mFaces = new aiFace[4];
    for (unsigned f = 0; f < 4; ++f) {
        mesh->mFaces[f].mNumIndices = 3;
        mesh->mFaces[f].mIndices = new unsigned[3]{corners[f][0], corners[f][1], corners[f][2]};
    }
    return mesh;
}

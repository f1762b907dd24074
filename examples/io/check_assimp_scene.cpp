// check_assimp_scene.cpp: the checks an assimp scene passes between import and post-processing.
// Assimp's post-processing steps (triangulation, pre-transformed vertices, vertex joining, sorting
// by primitive type) trust the scene an importer built: a null mesh, a face without indices, an
// index past the vertex array, a node naming a mesh that does not exist or a non-finite value
// make them crash, abort on an assertion or loop. So every pointer they follow is checked for
// null, every count against the array it sizes, every index against its range, positions, node
// transforms and bone offset matrices for finite values, and the node tree for cycles, depth and size. The meshes
// pre-transformed vertices will copy once per node that instances them are counted per instance,
// so a small file cannot make post-processing build more than the readers' size limit allows.
#include <assimp/scene.h>

#include <cmath>
#include <unordered_set>
#include <utility>
#include <vector>

#include "readers.h"

namespace caio {
namespace detail {
namespace {

// The post-processing steps recurse once per node level: a deeper tree could exhaust the stack.
constexpr size_t kMaxNodeDepth = 1024;
// Every output triangle has three corners and every vertex a joined one stands for is a corner:
// before the join, at most three corners and three vertices per input byte can be within the
// output's limit of one triangle per input byte.
constexpr size_t kCornersPerByte = 3;

bool finite(const aiVector3D& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool finite(const aiMatrix4x4& m) {
    for (unsigned r = 0; r < 4; ++r)
        for (unsigned c = 0; c < 4; ++c)
            if (!std::isfinite(m[r][c])) return false;
    return true;
}

std::string mesh_label(unsigned m) { return "assimp scene: mesh " + std::to_string(m); }

bool check_mesh(const std::string& name, const aiScene& scene, unsigned m, std::string& error) {
    const aiMesh* mesh = scene.mMeshes[m];
    if (!mesh) return fail(error, name, 0, mesh_label(m) + " is missing");
    const unsigned nv = mesh->mNumVertices;
    if (nv > 0 && !mesh->mVertices) return fail(error, name, 0, mesh_label(m) + " has no vertex array");
    for (unsigned v = 0; v < nv; ++v)
        if (!finite(mesh->mVertices[v]))
            return fail(error, name, 0, mesh_label(m) + " vertex " + std::to_string(v) + " is not finite");
    if (mesh->mNumFaces > 0 && !mesh->mFaces) return fail(error, name, 0, mesh_label(m) + " has no face array");
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
        const aiFace& face = mesh->mFaces[f];
        const std::string label = mesh_label(m) + " face " + std::to_string(f);
        if (face.mNumIndices == 0 || !face.mIndices) return fail(error, name, 0, label + " has no indices");
        if (face.mNumIndices > kMaxPolygon)
            return fail(error, name, 0, label + " has " + std::to_string(face.mNumIndices) +
                                            " vertices, beyond the limit of " + std::to_string(kMaxPolygon));
        for (unsigned k = 0; k < face.mNumIndices; ++k)
            if (face.mIndices[k] >= nv)
                return fail(error, name, 0, label + " has an index out of range (" + vcount_msg(nv));
    }
    if (mesh->mMaterialIndex >= scene.mNumMaterials || !scene.mMaterials || !scene.mMaterials[mesh->mMaterialIndex])
        return fail(error, name, 0, mesh_label(m) + " names a material that does not exist");
    for (unsigned c = 0; c < AI_MAX_NUMBER_OF_TEXTURECOORDS; ++c)
        if (mesh->mNumUVComponents[c] > 3)
            return fail(error, name, 0, mesh_label(m) + " has texture coordinates of more than 3 components");
    if (mesh->mNumBones > 0 && !mesh->mBones) return fail(error, name, 0, mesh_label(m) + " has no bone array");
    for (unsigned b = 0; b < mesh->mNumBones; ++b) {
        const aiBone* bone = mesh->mBones[b];
        if (!bone || (bone->mNumWeights > 0 && !bone->mWeights))
            return fail(error, name, 0, mesh_label(m) + " bone " + std::to_string(b) + " is missing or has no weights");
        if (!finite(bone->mOffsetMatrix))
            return fail(error, name, 0, mesh_label(m) + " bone " + std::to_string(b) + ": offset matrix holds NaN or infinity");
        for (unsigned w = 0; w < bone->mNumWeights; ++w)
            if (bone->mWeights[w].mVertexId >= nv)
                return fail(error, name, 0, mesh_label(m) + " bone " + std::to_string(b) + " weighs a vertex out of range");
    }
    if (mesh->mNumAnimMeshes > 0 && !mesh->mAnimMeshes)
        return fail(error, name, 0, mesh_label(m) + " has no animation mesh array");
    for (unsigned a = 0; a < mesh->mNumAnimMeshes; ++a) {
        const aiAnimMesh* anim = mesh->mAnimMeshes[a];
        if (!anim || anim->mNumVertices != nv)
            return fail(error, name, 0, mesh_label(m) + " animation mesh " + std::to_string(a) +
                                            " is missing or has another vertex count");
    }
    return true;
}

// Walks the node tree without recursion, checking it and counting what post-processing will build
// from the meshes its nodes instance; false as soon as something is wrong or a count passes its
// limit.
bool check_nodes(const std::string& name, const aiScene& scene, size_t input_bytes, std::string& error) {
    if (!scene.mRootNode) return fail(error, name, 0, "assimp scene: no root node");
    // per mesh: its corners and the triangles its faces become
    std::vector<std::pair<size_t, size_t>> mesh_size(scene.mNumMeshes);
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh& mesh = *scene.mMeshes[m];
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const unsigned n = mesh.mFaces[f].mNumIndices;
            mesh_size[m].first += n;
            if (n >= 3) mesh_size[m].second += n - 2;
        }
    }
    const size_t corner_limit = kCornersPerByte * input_bytes;
    size_t vertices = 0, corners = 0, triangles = 0;
    std::unordered_set<const aiNode*> seen;
    std::vector<std::pair<const aiNode*, size_t>> stack = {{scene.mRootNode, 1}};
    while (!stack.empty()) {
        const auto [node, depth] = stack.back();
        stack.pop_back();
        if (!seen.insert(node).second) return fail(error, name, 0, "assimp scene: a node appears twice in the node tree");
        if (seen.size() > input_bytes) return fail(error, name, 0, "assimp scene: more nodes than input bytes");
        if (depth > kMaxNodeDepth)
            return fail(error, name, 0, "assimp scene: the node tree is deeper than " + std::to_string(kMaxNodeDepth) + " levels");
        if (!finite(node->mTransformation)) return fail(error, name, 0, "assimp scene: a node transform is not finite");
        if (node->mNumMeshes > 0 && !node->mMeshes) return fail(error, name, 0, "assimp scene: a node has no mesh list");
        for (unsigned k = 0; k < node->mNumMeshes; ++k) {
            const unsigned m = node->mMeshes[k];
            if (m >= scene.mNumMeshes) return fail(error, name, 0, "assimp scene: a node names a mesh that does not exist");
            vertices += scene.mMeshes[m]->mNumVertices;
            corners += mesh_size[m].first;
            triangles += mesh_size[m].second;
            if (!check_budget(name, input_bytes, 0, triangles, error)) return false;
            if (vertices > corner_limit || corners > corner_limit)
                return fail(error, name, 0, "assimp scene: the node tree instances more than " +
                                                std::to_string(kCornersPerByte) + " vertices or face corners per input byte (" +
                                                std::to_string(input_bytes) + " bytes)");
        }
        if (node->mNumChildren > 0 && !node->mChildren) return fail(error, name, 0, "assimp scene: a node has no child list");
        for (unsigned c = 0; c < node->mNumChildren; ++c) {
            const aiNode* child = node->mChildren[c];
            if (!child || child->mParent != node)
                return fail(error, name, 0, "assimp scene: a node's child is missing or names another parent");
            stack.emplace_back(child, depth + 1);
        }
    }
    return true;
}

}  // namespace

bool check_assimp_scene(const std::string& name, const aiScene* scene, size_t input_bytes, std::string& error) {
    if (!scene) return fail(error, name, 0, "assimp scene: none");
    if (scene->mNumMeshes == 0) return fail(error, name, 0, "no meshes");
    if (!scene->mMeshes) return fail(error, name, 0, "assimp scene: no mesh array");
    if (scene->mNumMeshes > input_bytes) return fail(error, name, 0, "assimp scene: more meshes than input bytes");
    for (unsigned m = 0; m < scene->mNumMeshes; ++m)
        if (!check_mesh(name, *scene, m, error)) return false;
    return check_nodes(name, *scene, input_bytes, error);
}

}  // namespace detail
}  // namespace caio

// place_assimp_meshes.cpp: the triangles of a checked, post-processed assimp scene in world
// coordinates, one copy per node that instances a mesh (what assimp's PreTransformVertices step
// did, done here because that step deletes the bones), and the meshes' bones as the skin
// (MeshData::skin). A bone is a joint, named by its node; bones of the same name in several meshes
// are one joint. Its inverse bind matrix is the bone's offset matrix (mesh space -> bone space at
// bind) composed with the inverse of the first instancing node's world matrix, since the vertices
// are moved into world coordinates: offset * world^-1 * (world * v) = offset * v, so the bind pose
// is unchanged. Where another instance's bone gives a different inverse bind, its vertices are
// moved to the pose the kept matrices bind (each vertex by its weights' blend of
// kept^-1 * its own), so every vertex agrees with the joints' matrices. A joint's world matrix is
// its node's in the file's node tree (its rest pose); its parent is the nearest node above it that
// is a joint. Each vertex keeps its 8 heaviest weights (summed per joint, ties to the lower
// joint), renormalised. A mesh without bones in a skinned scene follows the nearest joint node at
// or above its node (weight 1), or no joint (zero weights). The scene passed check_assimp_scene
// (finite offset matrices, weights naming vertices in range) before post-processing.
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "large_pages.h"
#include "readers.h"

namespace caio {
namespace detail {
namespace {

Mat4 to_mat4(const aiMatrix4x4& a) {
    Mat4 m;
    for (unsigned r = 0; r < 4; ++r)
        for (unsigned c = 0; c < 4; ++c) m[c * 4 + r] = a[r][c];
    return m;
}

bool same_matrix(const Mat4& a, const Mat4& b) {
    double scale = 1;
    for (size_t i = 0; i < 16; ++i) scale = std::max(scale, std::fabs(a[i]));
    for (size_t i = 0; i < 16; ++i)
        if (std::fabs(a[i] - b[i]) > 1e-5 * scale) return false;
    return true;
}

std::string bone_name(const aiString& s) {
    const void* zero = std::memchr(s.data, 0, MAXLEN);
    const size_t n = zero ? size_t(static_cast<const char*>(zero) - s.data) : 0;
    return std::string(s.data, std::min<size_t>(n, s.length));
}

struct Instance {
    const aiNode* node;
    unsigned mesh;
    Mat4 world;
};

struct Joints {
    std::vector<std::string> names;
    std::vector<const aiNode*> nodes;                 // null when no node has the bone's name
    std::vector<Mat4> inverse_bind, inverse_bind_inverse;
    std::vector<char> inverted;                       // inverse_bind_inverse computed
    std::unordered_map<std::string, uint32_t> by_name;
    std::unordered_map<const aiNode*, uint32_t> by_node;
};

// The nearest joint at or above `node`, or -1 (the tree was checked: finite depth, no cycle).
int32_t joint_at_or_above(const Joints& j, const aiNode* node) {
    for (; node; node = node->mParent) {
        const auto it = j.by_node.find(node);
        if (it != j.by_node.end()) return int32_t(it->second);
    }
    return -1;
}

}  // namespace

bool place_assimp_meshes(const std::string& name, const aiScene& scene, size_t input_bytes, MeshData& out,
                         std::string& error) {
    // node instances of meshes, in depth-first order, and every node by name (the first one)
    std::vector<Instance> instances;
    std::unordered_map<std::string, const aiNode*> node_by_name;
    std::unordered_map<const aiNode*, Mat4> node_world;
    std::vector<std::pair<const aiNode*, Mat4>> stack = {{scene.mRootNode, identity4()}};
    while (!stack.empty()) {
        const auto [node, parent] = stack.back();
        stack.pop_back();
        const Mat4 world = mul4(parent, to_mat4(node->mTransformation));
        node_world[node] = world;
        node_by_name.emplace(bone_name(node->mName), node);
        for (unsigned k = 0; k < node->mNumMeshes; ++k)
            if (node->mMeshes[k] < scene.mNumMeshes && scene.mMeshes[node->mMeshes[k]])
                instances.push_back({node, node->mMeshes[k], world});
        for (unsigned c = node->mNumChildren; c-- > 0;) stack.emplace_back(node->mChildren[c], world);
    }
    size_t nv = 0, nt = 0;
    bool bones = false;
    for (const Instance& in : instances) {
        const aiMesh& mesh = *scene.mMeshes[in.mesh];
        nv += mesh.mNumVertices;
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) nt += mesh.mFaces[f].mNumIndices == 3;
        bones = bones || mesh.mNumBones > 0;
        if (!check_budget(name, input_bytes, nv, nt, error)) return false;
    }
    if (nv > std::numeric_limits<uint32_t>::max()) return fail(error, name, 0, "too many vertices");

    // the joints: every bone, by name, in order of first use
    Joints joints;
    if (bones)
        for (const Instance& in : instances) {
            const aiMesh& mesh = *scene.mMeshes[in.mesh];
            if (mesh.mNumBones == 0) continue;
            Mat4 world_inverse;
            if (!invert4(in.world, world_inverse))
                return fail(error, name, 0, "skinned mesh " + std::to_string(in.mesh) + " has a singular node transform");
            for (unsigned b = 0; b < mesh.mNumBones; ++b) {
                const aiBone& bone = *mesh.mBones[b];
                const std::string bname = bone_name(bone.mName);
                if (joints.by_name.count(bname)) continue;
                joints.by_name.emplace(bname, uint32_t(joints.names.size()));
                joints.names.push_back(bname);
                const auto node = node_by_name.find(bname);
                joints.nodes.push_back(node == node_by_name.end() ? nullptr : node->second);
                if (joints.nodes.back()) joints.by_node.emplace(joints.nodes.back(), uint32_t(joints.names.size() - 1));
                joints.inverse_bind.push_back(mul4(to_mat4(bone.mOffsetMatrix), world_inverse));
                joints.inverse_bind_inverse.push_back(identity4());
                joints.inverted.push_back(0);
            }
        }
    const size_t nj = joints.names.size();

    ca::reserve_large(out.positions, 3 * nv);
    ca::reserve_large(out.triangles, 3 * nt);
    SkinData& skin = out.skin;
    // kMaxInfluences slots per vertex while reading, cut to the influences used at the end
    if (nj > 0) {
        ca::reserve_large(skin.vertex_joints, kMaxInfluences * nv);
        ca::reserve_large(skin.vertex_weights, kMaxInfluences * nv);
    }
    size_t widest = 1;
    for (const Instance& in : instances) {
        const aiMesh& mesh = *scene.mMeshes[in.mesh];
        const uint32_t base = uint32_t(out.positions.size() / 3);
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            const double p[3] = {mesh.mVertices[v].x, mesh.mVertices[v].y, mesh.mVertices[v].z};
            double q[3];
            transform_point(in.world, p, q);
            out.positions.insert(out.positions.end(), {q[0], q[1], q[2]});
        }
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3) continue;
            for (unsigned k = 0; k < 3; ++k) {
                if (face.mIndices[k] >= mesh.mNumVertices) return fail(error, name, 0, "assimp returned an index out of range");
                out.triangles.push_back(base + face.mIndices[k]);
            }
        }
        if (nj == 0) continue;
        // this instance's weights per vertex, summed per joint; and whether its binds differ
        std::vector<std::vector<std::pair<double, uint32_t>>> vertex(mesh.mNumVertices);
        std::vector<Mat4> own(mesh.mNumBones);
        std::unordered_map<uint32_t, unsigned> bone_of_joint;
        bool moved = false;
        Mat4 world_inverse = identity4();
        if (mesh.mNumBones > 0) invert4(in.world, world_inverse);  // not singular: checked above
        for (unsigned b = 0; b < mesh.mNumBones; ++b) {
            const aiBone& bone = *mesh.mBones[b];
            const std::string bname = bone_name(bone.mName);
            const uint32_t j = joints.by_name.at(bname);
            bone_of_joint.emplace(j, b);
            own[b] = mul4(to_mat4(bone.mOffsetMatrix), world_inverse);
            if (!same_matrix(own[b], joints.inverse_bind[j])) {
                moved = true;
                if (!joints.inverted[j] && !invert4(joints.inverse_bind[j], joints.inverse_bind_inverse[j]))
                    return fail(error, name, 0, "bone '" + printable(bname, 60) + "': singular offset matrix");
                joints.inverted[j] = 1;
            }
            for (unsigned w = 0; w < bone.mNumWeights; ++w) {
                const aiVertexWeight& vw = bone.mWeights[w];
                if (vw.mVertexId >= mesh.mNumVertices)
                    return fail(error, name, 0, "bone '" + printable(bname, 60) + "' weighs a vertex out of range");
                if (!std::isfinite(vw.mWeight) || vw.mWeight < 0)
                    return fail(error, name, 0, "bone '" + printable(bname, 60) + "': weight of vertex " +
                                                    std::to_string(vw.mVertexId) + " is negative, NaN or infinite");
                if (vw.mWeight == 0) continue;
                auto& row = vertex[vw.mVertexId];
                auto same = std::find_if(row.begin(), row.end(), [&](const auto& e) { return e.second == j; });
                if (same != row.end()) same->first += vw.mWeight;
                else row.emplace_back(vw.mWeight, j);
            }
        }
        const int32_t follow = mesh.mNumBones == 0 ? joint_at_or_above(joints, in.node) : -1;
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            auto& row = vertex[v];
            if (follow >= 0) row.emplace_back(1.0, uint32_t(follow));
            keep_heaviest(row, kMaxInfluences);
            double sum = 0;
            for (const auto& e : row) sum += e.first;
            if (!std::isfinite(sum)) return fail(error, name, 0, "vertex weights do not sum to a finite number");
            widest = std::max(widest, row.size());
            if (moved && sum > 0) {
                // the vertex in the pose the kept inverse binds describe: the blend of
                // kept^-1 * own over its joints
                Mat4 blend{};
                for (const auto& e : row) {
                    const Mat4 m = joints.inverted[e.second]
                                       ? mul4(joints.inverse_bind_inverse[e.second], own[bone_of_joint.at(e.second)])
                                       : identity4();
                    for (size_t k = 0; k < 16; ++k) blend[k] += e.first / sum * m[k];
                }
                double* q = &out.positions[3 * (base + v)];
                const double p[3] = {q[0], q[1], q[2]};
                transform_point(blend, p, q);
            }
            for (size_t k = 0; k < kMaxInfluences; ++k) {
                skin.vertex_weights.push_back(k < row.size() && sum > 0 ? row[k].first / sum : 0.0);
                skin.vertex_joints.push_back(k < row.size() ? row[k].second : 0u);
            }
        }
    }
    if (nj == 0) return true;

    skin.influences = widest > 4 ? kMaxInfluences : 4;
    if (skin.influences < kMaxInfluences) {  // in place: row v moves to v * influences
        for (size_t v = 0; v < nv; ++v)
            for (size_t k = 0; k < skin.influences; ++k) {
                skin.vertex_weights[v * skin.influences + k] = skin.vertex_weights[v * kMaxInfluences + k];
                skin.vertex_joints[v * skin.influences + k] = skin.vertex_joints[v * kMaxInfluences + k];
            }
        skin.vertex_weights.resize(nv * skin.influences);
        skin.vertex_joints.resize(nv * skin.influences);
    }
    for (size_t j = 0; j < nj; ++j) {
        skin.joint_names.push_back(joints.names[j]);
        const aiNode* node = joints.nodes[j];
        skin.parents.push_back(node ? joint_at_or_above(joints, node->mParent) : -1);
        skin.inverse_bind.insert(skin.inverse_bind.end(), joints.inverse_bind[j].begin(), joints.inverse_bind[j].end());
        // a bone without a node: its world matrix at rest taken as its bind
        Mat4 world;
        if (node) world = node_world.at(node);
        else if (!invert4(joints.inverse_bind[j], world))
            return fail(error, name, 0, "bone '" + printable(joints.names[j], 60) + "': singular offset matrix");
        skin.joint_world.insert(skin.joint_world.end(), world.begin(), world.end());
    }
    return true;
}

}  // namespace detail
}  // namespace caio

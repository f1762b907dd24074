// part_balls.cpp: the medial balls of each part (bones.h): an inner ball of the candidate set
// touches the surface at its nearest surface point (its radius is that distance), and it
// belongs to the joint that dominates the surface there, so each part gets the balls that
// measure its own thickness.
#include "bones.h"

#include "distance.h"
#include "parallel.h"

namespace ca {

std::vector<std::vector<Ball>> part_balls(const Mesh& mesh, const ShapeQueries& shape, const std::vector<Ball>& balls,
                                          size_t inner, const PreparedSkin& skin, int threads, const Monitor& monitor) {
    std::vector<std::vector<Ball>> out(skin.parents.size());
    inner = std::min(inner, balls.size());
    if (!shape.distance) return out;
    std::vector<int32_t> owner(inner, -1);
    if (!parallel_for(inner, threads, 1024, monitor, "bone colliders", 0.1, 0.2, [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i) {
                Vec3 closest;
                uint32_t t = 0;
                shape.distance->distance(balls[i].center, &closest, &t);
                if (t >= mesh.triangles.size()) continue;
                const Tri& tri = mesh.triangles[t];
                const Vec3 bary = barycentric(closest, mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]);
                owner[i] = dominant_joint(mesh, skin, t, bary);
            }
        }))
        return {};
    for (size_t i = 0; i < inner; ++i)
        if (owner[i] >= 0) out[size_t(owner[i])].push_back(balls[i]);
    return out;
}

}  // namespace ca

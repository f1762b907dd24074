// evaluate.h: how far a medial skeleton is from the shape (docs/evaluation.md). The reconstruction
// E is the union of the skeleton's spheres, medial cones (edges) and medial slabs (faces).
// Exact signed distances to each primitive, F(x) = min over primitives (BVH over primitive
// bounding spheres), samples of the boundary of E, and one- and two-sided Hausdorff distances
// to the input surface (exact point-to-triangle distances through an AABB tree).
#pragma once
#include "common.h"
#include "shape_queries.h"
#include "skeleton.h"

#include <memory>

namespace ca {

// The sphere of a primitive's simplex that attains its distance at p: its barycentric weights on
// the primitive's balls and the unit direction from its centre to p (zero at the centre). Since the
// distance is a minimum over the simplex, its derivative with respect to ball i's centre is
// -w[i] u and with respect to its radius -w[i] (the minimiser's own motion does not count).
struct NearestSphere {
    double w[3] = {0, 0, 0};
    Vec3 u = Vec3::Zero();
};

// Exact signed distances (negative inside): min over the simplex of |p - c(t)| - r(t). With `at`
// set, also the sphere that attains it.
double sd_sphere(const Vec3& p, const Vec3& c, double r);
double sd_cone(const Vec3& p, const Vec3& c1, double r1, const Vec3& c2, double r2,
               NearestSphere* at = nullptr);
double sd_slab(const Vec3& p, const Vec3& c1, double r1, const Vec3& c2, double r2,
               const Vec3& c3, double r3, NearestSphere* at = nullptr);

struct EvaluateOptions {
    uint32_t surface_samples = 30000;    // plus the input vertices
    uint32_t envelope_samples = 100000;  // at least; boundary samples of E
    uint64_t seed = 1;
    int32_t threads = 0;                 // worker threads (0 = all cores; 1 = serial)
};

struct EvaluateResult {
    // all in percent of the input bounding-box diagonal
    double hd_surface_to_recon = 0, mean_surface_to_recon = 0;
    double hd_recon_to_surface = 0, mean_recon_to_surface = 0;
    double hd_two_sided = 0;
    double diagonal = 0;                 // the input bbox diagonal (input units)
    size_t surface_samples_used = 0, envelope_samples_used = 0;
    double time_s = 0;                   // of evaluate()
};

// Mesh input (triangles non-empty) or point cloud (triangles empty: distance to nearest point).
Status evaluate(const Mesh& surface, const Skeleton& skeleton, const EvaluateOptions& opt,
                const Monitor& monitor, EvaluateResult& out);
// The same on a candidate set's surface (the mesh `queries` were built on, shape_queries.h): its
// distance query is used, not built again (the searches evaluate every probe).
Status evaluate(const Mesh& surface, const ShapeQueries& queries, const Skeleton& skeleton,
                const EvaluateOptions& opt, const Monitor& monitor, EvaluateResult& out);

// What evaluate() draws from the surface alone (its samples at opt.surface_samples and opt.seed,
// the distance structure, the diagonal), built once to measure many skeletons against one
// surface: the delta searches (lib/search) and the thorough fit measure one skeleton per probe.
// With `queries` (built on `surface`: a candidate set's), its distance query is used, not built again.
struct EvaluationSurface;
Status prepare_evaluation(const Mesh& surface, const EvaluateOptions& opt, std::shared_ptr<const EvaluationSurface>& out,
                          const ShapeQueries* queries = nullptr);

// evaluate() on a prepared surface (opt's surface_samples and seed must be those it was prepared
// with). hd_only: only hd_two_sided (and the one-sided maxima) are computed; the means are left 0.
// A sample that cannot raise the maximum found so far is skipped (a bound shows it: the distance
// to the nearest surface sample, an early exit of the envelope's distance), so the maxima are
// those evaluate() gives, at a fraction of its time.
Status evaluate(const EvaluationSurface& surface, const Skeleton& skeleton, const EvaluateOptions& opt,
                const Monitor& monitor, EvaluateResult& out, bool hd_only = false);

}  // namespace ca

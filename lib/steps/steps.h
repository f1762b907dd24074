// steps.h: the pipeline's steps as one request each, the C++ entries the C ABI (capi/) converts to
// and from. Each takes the full options of its step and makes the step's policy choices: the
// connection route for ConnectMethod::automatic, the selection strategy (plain cover, target
// count, target error), which probes of a search are fitted, and what goes to the caller's log
// (Monitor::note). The defaults are those of the option structs; the C ABI's ca_*_defaults are
// converted from them, so they are stated once.
#pragma once
#include "bones.h"
#include "candidates.h"
#include "connect.h"
#include "correspondence.h"
#include "evaluate.h"
#include "fit.h"
#include "rig.h"
#include "proxies.h"
#include "selection.h"
#include "skeleton.h"

#include <optional>
#include <vector>

namespace ca {

// ---- step 1: candidates (candidates_step.cpp) ----

// The caller's surface in its own units: a triangle mesh, or a point cloud (no triangles) with one
// normal per point, or none (estimated), trusted as point_normals says.
struct SurfaceInput {
    Mesh mesh;
    std::vector<Vec3> normals;
    PointNormals point_normals = PointNormals::trusted;
};

// The request's own fields in range (point_normals one of PointNormals) and, for a point cloud,
// one normal per point or none; the arrays' values are checked by prepare_surface.
Status check_surface_input(const SurfaceInput& surface);

// invalid_argument unless `set` was made from a triangle mesh, which `what` (e.g. "engine
// proxies") is built on: a point cloud's or the caller's arrays' set has no surface to fit.
Status check_mesh_set(const CandidateSet& set, const char* what);

// Validates and prepares the surface (prepare_surface on opt.threads), then generates the
// candidates. Notes what the preparation changed (re-oriented normals, a flipped mesh, dropped or
// merged triangles) and the sizes reached.
Status candidates_step(SurfaceInput surface, const CandidateOptions& opt, const Monitor& monitor, CandidateSet& out);

// A candidate set from the caller's own samples and balls (caller's units; radius = undilated
// medial radius): internal units are the samples' bounding box, scaled by reference_length (0 =
// the longest side of that box). No surface: the medial route and the searches need one.
Status candidates_from_arrays(const std::vector<Vec3>& samples, const std::vector<Vec3>& centers,
                              const std::vector<double>& radii, double reference_length, CandidateSet& out);

// ---- step 3: connection (connect_step.cpp); before step 2, whose searches connect probes ----

// How the balls are fitted after connecting (fit.h): not at all, one fit, the thorough fit, or the
// covered fit (one fit, then the cover it breaks repaired: fit_covered);
// automatic: the thorough fit for a selection sized by target_count (few balls, which the fit
// brings closest to the shape), one fit for a selection a target_error search judged fitted (so
// the HD it reported is the one connected), else none: a plain selection stays unfitted, so its
// balls keep covering every sample.
enum class FitMode : int32_t { automatic = -1, off = 0, once = 1, thorough = 2, covered = 3 };

struct ConnectRequest {
    ConnectOptions connect;       // the route (automatic by default) and the repairs
    FitMode fit = FitMode::automatic;
    int32_t fit_iterations = int32_t(FitOptions{}.iterations);  // >= 0
};

// The fit options of a request on `set` for a selection (FitMode::automatic reads how it was
// made; none given: automatic is off), or none when it does not fit: the fit needs a triangle
// mesh, and fit on with 0 iterations is no fit.
std::optional<FitOptions> fit_options(const ConnectRequest& request, const CandidateSet& set,
                                      const Selection* selection = nullptr);

struct ConnectResult {
    Skeleton skeleton;            // internal units
    ConnectReport report;         // the route taken, the genus and thin handles
    TopologyStats topology;
    bool fitted = false;
    FitStats fit;
    double time_s = 0;            // connection and fit
};

// Connects the selection (made from `set`) and fits it as the request says.
Status connect_step(const CandidateSet& set, const Selection& selection, const ConnectRequest& request,
                    const Monitor& monitor, ConnectResult& out);

// ---- step 2: selection (select_step.cpp) ----

struct SelectRequest {
    SelectOptions select;         // the cover: dilation, solver, masks, target_count, ...
    // 0: off. E > 0: the fewest balls whose skeleton has a two-sided HD <= E % of the bbox diagonal
    // (target_error.h; offset dilation, not with target_count).
    double target_error = 0;
    // How the searches (target_error, and target_count with the offset dilation on a set with a
    // surface) connect each probe: the default ConnectRequest with this fit (off or once).
    FitMode probe_fit = FitMode::off;
};

struct SelectResult {
    Selection selection;
    double hd_reached = -1;       // the searches: the HD of the returned selection; -1 not measured
    bool stopped = false;         // the time limit ended a search: Code::time_limit, `selection` its best so far
};

// Checks the request and runs its strategy: target_error's search when set (on a mesh with
// unfitted probes, each probe's cover is judged unfitted and fitted once, the lower HD; when no
// probe reaches it: Code::target_not_reached with `out` holding the probe of lowest HD); target_count with the
// offset dilation on a set with a surface: the lowest HD within the count (target_count_hd.h); else
// select_balls (which handles target_count by bisection alone). Each search probe is connected as
// connect_step would with the default ConnectRequest (fit = probe_fit) and measured as
// evaluate_step would with the default EvaluateOptions. When the time limit ends either search
// after a probe: Code::time_limit with `out` holding the best selection so far (out.stopped).
Status select_step(const CandidateSet& set, const SelectRequest& request, const Monitor& monitor, SelectResult& out);

// ---- evaluation (evaluate_step.cpp) ----

// The distances between the caller's surface (its units; a point cloud has no triangles; normals
// are not used) and a skeleton in the same units; out.diagonal in those units.
Status evaluate_step(SurfaceInput surface, const Skeleton& skeleton, const EvaluateOptions& opt,
                     const Monitor& monitor, EvaluateResult& out);

// ---- correspondence and rig (correspondence_step.cpp, rig_step.cpp) ----

// The correspondence of the surface's vertices (its units; triangles and normals are not used)
// to a skeleton in the same units (correspondence.h).
Status correspondence_step(const SurfaceInput& surface, const Skeleton& skeleton, const CorrespondOptions& opt,
                           const Monitor& monitor, Correspondence& out);

// The rig of a skeleton (rig.h: curve skeleton, joints, the joint weights of the surface's vertices),
// the skeleton and the surface in the same units.
Status rig_step(const SurfaceInput& surface, const Skeleton& skeleton, const RigOptions& opt, const Monitor& monitor,
                Rig& out);

// ---- engine proxies (proxies_step.cpp) ----

// Spheres and tapered capsules from a skeleton in the caller's units (as ca_skeleton holds it) over
// the candidate set's surface, a triangle mesh (proxies.h, docs/proxies.md). The skeleton is
// checked and brought to the set's internal units; the proxies, the diagonal and the volumes of
// the result are in the caller's units (the errors are percent of the diagonal).
Status proxies_step(const CandidateSet& set, const Skeleton& skeleton, const ProxyOptions& opt,
                    const Monitor& monitor, ProxyResult& out);

// ---- bone colliders (bone_colliders_step.cpp) ----

// A collider per joint of `skin` on the set's surface (a triangle mesh, else invalid_argument),
// fitted to the set's inner balls (bones.h); the result in the caller's units, each collider in
// its joint's frame.
Status bone_colliders_step(const CandidateSet& set, const Skin& skin, const BoneColliderOptions& opt,
                           const Monitor& monitor, BoneColliderResult& out);

}  // namespace ca

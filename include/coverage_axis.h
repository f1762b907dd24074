/*
 * coverage_axis.h - the one stable C ABI of the coverage-axis library (C99; compiles as C and C++).
 *
 * Coverage Axis (Dou et al., Eurographics 2022) turns a triangle mesh or an oriented point cloud
 * into a few medial balls (centre + radius) joined by edges and triangles, in three calls:
 *   ca_candidates  surface -> surface samples + inner candidate balls        (ca_candidate_set)
 *   ca_select      fewest dilated candidate balls covering every sample      (ca_selection)
 *   ca_connect     edges and triangles between the selected balls            (ca_skeleton)
 * A skeleton then feeds ca_evaluate, ca_correspond, ca_rig_build, ca_proxies, ca_bone_colliders_build.
 *
 * Conventions of every call, stated here once (in full, with each ABI version's additions: docs/abi.md)
 * - Units: coordinates are doubles in the caller's units, as are results. Lengths given as options
 *   are fractions of the longest side of the input's bounding box; a "%" is percent of its diagonal.
 * - Inputs are borrowed views (pointer, count, byte stride; 0 = packed), read during the call only.
 *   A count that does not match its array is CA_ERROR_INVALID_INPUT; an array may be NULL when its
 *   count is 0, else CA_ERROR_NULL_POINTER. Output arrays are packed (x y z per point, i j per edge,
 *   i j k per face; 0-based indices).
 * - Status: on any but CA_OK the output pointer is NULL, nothing is allocated and no output struct
 *   is written (except ca_select's CA_ERROR_TARGET_NOT_REACHED, and its CA_ERROR_TIME_LIMIT when
 *   *out is not NULL: a search's best selection so far); ca_context_last_error() explains. No exception
 *   crosses this boundary; nothing prints, exits or aborts.
 * - Results are opaque and immutable, readable from several threads, freed by their ca_*_destroy
 *   (NULL: no-op); getters' pointers live until then (NULL object: NULL / 0). A result copies what
 *   it needs and outlives its context and inputs (a selection keeps its candidate set alive).
 * - Threads: a context serves one thread at a time; results do not depend on the thread count, and
 *   the same seed gives the same result.
 * - struct_size: every struct starts with it and grows only at its end; the sizes this library
 *   published are accepted, others are CA_ERROR_STRUCT_SIZE (nothing written). Inputs: ca_*_init(p)
 *   (C) or ca_*_defaults(p, size) (FFI); fields past the caller's size, and a NULL options pointer,
 *   take the defaults. Outputs (stats, placements): the caller sets struct_size; written up to it.
 * - Defaults live in the library: a field's comment names its default, else it is 0 / NULL
 *   (tests/abi_layout/check_defaults.py checks both). time_s fields are wall-clock seconds.
 */
#ifndef COVERAGE_AXIS_H
#define COVERAGE_AXIS_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Only the ca_* functions are exported; Windows DLL users define CA_SHARED_LIBRARY. */
#if defined(_WIN32) && defined(CA_SHARED_LIBRARY)
#  ifdef CA_BUILDING_LIBRARY
#    define CA_API __declspec(dllexport)
#  else
#    define CA_API __declspec(dllimport)
#  endif
#elif defined(__GNUC__) && defined(CA_BUILDING_LIBRARY)
#  define CA_API __attribute__((visibility("default")))
#else
#  define CA_API
#endif

/* ca_xxx_init(p): struct_size = sizeof *p as the caller's compiler sees it, then ca_xxx_defaults. */
#define CA_DEFINE_INIT_(type) static inline void type##_init(type* p) { \
    if (p) { p->struct_size = (uint32_t)sizeof *p; (void)type##_defaults(p, (uint32_t)sizeof *p); } }

/* ---- versions (what a release may change: docs/abi.md) ------------------------------------- */
#define CA_VERSION_MAJOR 0
#define CA_VERSION_MINOR 2
#define CA_VERSION_PATCH 0
#define CA_VERSION_NUMBER (CA_VERSION_MAJOR * 10000 + CA_VERSION_MINOR * 100 + CA_VERSION_PATCH)
#define CA_ABI_VERSION 3 /* the struct layouts and entry points */
#define CA_SOVERSION 3   /* the shared library's; raised only by a release that breaks callers */

CA_API uint32_t ca_version(void);     /* CA_VERSION_NUMBER of the linked library */
CA_API const char* ca_version_string(void); /* the same as "major.minor.patch" (static) */
CA_API uint32_t ca_abi_version(void); /* CA_ABI_VERSION of the linked library */

/* ---- status codes (pinned values; never renumbered) ---------------------------------------- */
typedef int32_t ca_status;
#define CA_OK                      0
#define CA_ERROR_INVALID_ARGUMENT  1  /* an option is out of range */
#define CA_ERROR_NULL_POINTER      2  /* a required pointer is NULL */
#define CA_ERROR_STRUCT_SIZE       3  /* struct_size is not one this library knows */
#define CA_ERROR_INVALID_INPUT     4  /* NaN/Inf coordinate, out-of-range index, bad normal */
#define CA_ERROR_DEGENERATE_INPUT  5  /* empty, zero area, too few distinct points, coplanar */
#define CA_ERROR_UNCOVERABLE       6  /* some samples are covered by no candidate ball */
#define CA_ERROR_GEOMETRY          7  /* the Delaunay / power diagram (Qhull) failed */
#define CA_ERROR_SOLVER            8  /* the set-cover solver (CBC) failed */
#define CA_ERROR_CANCELLED         9  /* the progress callback or a cancel request stopped it */
#define CA_ERROR_OUT_OF_MEMORY     10
#define CA_ERROR_BUFFER_TOO_SMALL  11 /* copy-out capacity too small; *count has the size needed */
#define CA_ERROR_INTERNAL          12 /* a bug: please report it with the input */
#define CA_ERROR_NO_CANDIDATES     13 /* no inner candidate ball was found */
#define CA_ERROR_TIME_LIMIT        14 /* ca_context_desc.time_limit_s ran out; the message names the stage.
                                       ca_select's target_error or target_count search stopped after a
                                       probe: *out is its best selection so far (else NULL), destroyed
                                       as on success */
#define CA_ERROR_TARGET_NOT_REACHED 15 /* ca_select: no probe reached target_error; a failure with a
                                       result: *out is the probe of lowest HD, destroyed as on success */

/* A static English name, e.g. "CA_ERROR_NULL_POINTER: a required pointer is NULL". */
CA_API const char* ca_status_string(ca_status status);

/* ---- context ------------------------------------------------------------------------------- */
typedef struct ca_context ca_context;
/* Callbacks run on the calling thread. Log level: 0 debug, 1 info, 2 warning. Progress: a stage
   ("sampling", "delaunay", "selection", ...) and its fraction in [0,1]; non-zero cancels the call. */
typedef void (*ca_log_fn)(void* user, int32_t level, const char* message);
typedef int32_t (*ca_progress_fn)(void* user, const char* stage, double fraction);
/* Allocates the result objects and their getters' arrays (working memory uses the C++ heap). */
typedef void* (*ca_alloc_fn)(void* user, size_t size);
typedef void (*ca_free_fn)(void* user, void* pointer);

typedef struct ca_context_desc {
    uint32_t struct_size;
    ca_alloc_fn alloc; ca_free_fn free; void* alloc_user; /* NULL: malloc and free; set both or neither */
    ca_log_fn log; void* log_user;                        /* NULL: no log */
    ca_progress_fn progress; void* progress_user;         /* NULL: no progress */
    int32_t threads;       /* worker threads of the parallel stages; 0 = all cores, 1 = serial */
    double progress_interval_s; /* least seconds between a stage's progress calls, but for its first
                                   and fraction 1; 0 = every update */
    double time_limit_s;   /* each long call's budget, else CA_ERROR_TIME_LIMIT (the exact solver: its
                              best cover, unproven); 0 = unlimited */
} ca_context_desc;
CA_API ca_status ca_context_desc_defaults(ca_context_desc* desc, uint32_t struct_size);
CA_DEFINE_INIT_(ca_context_desc)
CA_API ca_status ca_context_create(const ca_context_desc* desc, ca_context** out); /* desc NULL: defaults */
CA_API void ca_context_destroy(ca_context* ctx);
/* From any thread: every long call returns CA_ERROR_CANCELLED until ca_context_clear_cancel(). */
CA_API void ca_context_request_cancel(ca_context* ctx);
CA_API void ca_context_clear_cancel(ca_context* ctx);
/* The message of the last failed call on this context ("" if none), valid until the next call. */
CA_API const char* ca_context_last_error(const ca_context* ctx);

/* ---- input views --------------------------------------------------------------------------- */
/* A triangle mesh (triangle_count > 0; may be open, a soup or self-intersecting: inside comes from
   the generalised winding number) or a point cloud (triangle_count == 0; docs/pointclouds.md). */
#define CA_POINT_NORMALS_TRUSTED    0 /* consistently oriented: used as given, signs checked */
#define CA_POINT_NORMALS_UNORIENTED 1 /* directions right, signs not: re-oriented */
#define CA_POINT_NORMALS_ESTIMATE   2 /* ignored: estimated from the points by PCA and oriented */
typedef struct ca_surface_view {
    uint32_t struct_size;
    const double* positions; size_t vertex_count; size_t position_stride;     /* x y z per vertex */
    const uint32_t* triangles; size_t triangle_count; size_t triangle_stride; /* i j k per triangle */
    const double* normals; size_t normal_stride; /* clouds: per point, inward or outward; NULL: estimated */
    int32_t point_normals;      /* CA_POINT_NORMALS_*; default TRUSTED */
    size_t normal_count;        /* entries of normals: vertex_count, or 0 with normals NULL */
} ca_surface_view;
CA_API ca_status ca_surface_view_defaults(ca_surface_view* view, uint32_t struct_size);
CA_DEFINE_INIT_(ca_surface_view)

/* ---- step 1: candidates -------------------------------------------------------------------- */
#define CA_CANDIDATES_VORONOI 0 /* inner Voronoi vertices of voronoi_samples surface samples */
#define CA_CANDIDATES_RANDOM  1 /* random interior points, radius = distance to the surface */
typedef struct ca_candidate_options {
    uint32_t struct_size;
    int32_t generator;           /* CA_CANDIDATES_*; default VORONOI */
    uint32_t cover_samples;      /* |S|, samples to cover; default 1500 (clouds: at most this many points; 0 = all) */
    uint32_t voronoi_samples;    /* |C|, samples whose Voronoi vertices are candidates; default 4000 */
    uint32_t random_candidates;  /* random generator: number of interior points; default 10000 */
    uint64_t seed;               /* default 1 */
    uint32_t connect_samples;    /* meshes: power-diagram samples; default 10000; 0 = the Voronoi ones */
    uint32_t reserved_abi2_tail; /* never read */
    int32_t volumetric_only;     /* 1: inner balls only; 0: a sample no inner ball reaches gets a surface ball */
} ca_candidate_options;
CA_API ca_status ca_candidate_options_defaults(ca_candidate_options* options, uint32_t struct_size);
CA_DEFINE_INIT_(ca_candidate_options)

typedef struct ca_candidate_set ca_candidate_set;
CA_API ca_status ca_candidates(ca_context* ctx, const ca_surface_view* surface,
                               const ca_candidate_options* options, ca_candidate_set** out);
/* A set from the caller's samples and balls (undilated radii). reference_length: the length delta is
   a fraction of; 0 = the samples' longest bbox side. */
CA_API ca_status ca_candidates_from_arrays(ca_context* ctx,
                                           const double* samples, size_t sample_count, size_t sample_stride,
                                           const double* centers, size_t center_stride,
                                           const double* radii, size_t radius_stride,
                                           size_t ball_count, double reference_length,
                                           ca_candidate_set** out);
CA_API void ca_candidate_set_destroy(ca_candidate_set* set); /* the caller's handle only */
CA_API size_t ca_candidate_set_count(const ca_candidate_set* set);
CA_API const double* ca_candidate_set_centers(const ca_candidate_set* set);
CA_API const double* ca_candidate_set_radii(const ca_candidate_set* set);
CA_API size_t ca_candidate_set_sample_count(const ca_candidate_set* set);
CA_API const double* ca_candidate_set_samples(const ca_candidate_set* set);
CA_API double ca_candidate_set_reference_length(const ca_candidate_set* set);
/* 1 if the mesh faced inward (or the cloud's normals pointed inward) and was flipped, else 0. */
CA_API int32_t ca_candidate_set_flipped(const ca_candidate_set* set);
#define CA_NORMALS_NONE      0 /* a mesh: no point normals */
#define CA_NORMALS_GIVEN     1 /* the caller's normals */
#define CA_NORMALS_ORIENTED  2 /* the caller's normals, re-oriented */
#define CA_NORMALS_ESTIMATED 3 /* estimated from the points (PCA) and oriented */
CA_API int32_t ca_candidate_set_normals(const ca_candidate_set* set); /* CA_NORMALS_*: what a cloud used */
/* Point clouds (0 for meshes): points dropped as outliers; zero ("none") normals estimated. */
CA_API uint64_t ca_candidate_set_outlier_count(const ca_candidate_set* set);
CA_API uint64_t ca_candidate_set_normals_replaced(const ca_candidate_set* set);
/* Copy-out (centers: 3 * capacity doubles, radii: capacity; either may be NULL); *count: the
   number of balls; a smaller capacity is CA_ERROR_BUFFER_TOO_SMALL, nothing copied. */
CA_API ca_status ca_candidate_set_copy(const ca_candidate_set* set, double* centers, double* radii,
                                       size_t capacity, size_t* count);

/* ---- step 2: selection (minimum set cover) ------------------------------------------------- */
#define CA_DILATE_OFFSET 0 /* r' = r + delta * reference_length */
#define CA_DILATE_SCALE  1 /* r' = r * scale */
#define CA_SOLVER_EXACT  0 /* reduction, LP bound, local search, CBC branch and bound (CA_EFFORT_*) */
#define CA_SOLVER_GREEDY 1 /* classic greedy + redundancy removal */
#define CA_SOLVER_CAPP   2 /* Coverage Axis++ score greedy + redundancy removal */
#define CA_EFFORT_FAST  0 /* exact solver (docs/solver.md): LP bound + local search, CBC only on a small
                             kernel one ball from the bound; else the cover is unproven, with its gap */
#define CA_EFFORT_PROVE 1 /* CBC until the cover is proven optimal or the time limit ends it */
typedef struct ca_select_options {
    uint32_t struct_size;
    int32_t dilation;            /* CA_DILATE_*; default OFFSET */
    double delta;                /* offset, fraction of the longest bbox side; default 0.02 */
    double scale;                /* scale factor; default 1.5 */
    int32_t solver;              /* CA_SOLVER_*; default EXACT */
    double time_limit_s;         /* exact solver's wall-clock budget, a safety net; default 60; <= 0: none */
    int32_t skip_uncoverable;    /* 1: uncoverable samples are ignored and listed (ca_selection_uncovered);
                                    0: they are CA_ERROR_UNCOVERABLE */
    const uint8_t* ignorable_samples; /* per sample, non-zero: need not be covered */
    const uint8_t* forced_in;         /* per candidate ball, non-zero: must be selected */
    const uint8_t* forced_out;        /* per candidate ball, non-zero: must not be selected */
    uint32_t target_count;       /* K > 0: at most K balls, at the smallest dilation that achieves it,
                                    then the lowest HD among probed deltas (docs/fidelity.md) */
    double target_tolerance;     /* bisection tolerance on delta or scale; default 1e-4 */
    uint32_t divide_threshold;   /* more samples: divide and conquer; default 100000; 0 = never */
    int32_t effort;              /* CA_EFFORT_*; default FAST */
    double target_error;         /* E > 0: few balls whose skeleton is within two-sided HD E % (OFFSET
                                    dilation, not with target_count) */
    int32_t probe_fit;           /* 1: the searches' probes connected with fit = 1 (meshes) */
    size_t ignorable_samples_count; size_t forced_in_count; size_t forced_out_count; /* the masks' entries */
} ca_select_options;
CA_API ca_status ca_select_options_defaults(ca_select_options* options, uint32_t struct_size);
CA_DEFINE_INIT_(ca_select_options)

typedef struct ca_selection ca_selection;
CA_API ca_status ca_select(ca_context* ctx, const ca_candidate_set* set,
                           const ca_select_options* options, ca_selection** out);
CA_API void ca_selection_destroy(ca_selection* selection);
CA_API size_t ca_selection_count(const ca_selection* selection);
CA_API const uint32_t* ca_selection_indices(const ca_selection* selection); /* into the candidate set */
CA_API const double* ca_selection_centers(const ca_selection* selection);
CA_API const double* ca_selection_radii(const ca_selection* selection);     /* undilated */
CA_API const double* ca_selection_dilated_radii(const ca_selection* selection);
CA_API size_t ca_selection_uncovered_count(const ca_selection* selection);
CA_API const uint32_t* ca_selection_uncovered(const ca_selection* selection); /* sample indices */

typedef struct ca_select_stats {
    uint32_t struct_size;
    int32_t proven_optimal;      /* 1 iff the cover is a proven minimum */
    int32_t solver;              /* CA_SOLVER_* used */
    double objective;            /* number of selected balls */
    double lower_bound;          /* a valid lower bound on the minimum */
    double gap;                  /* (objective - lower_bound) / objective */
    double delta_absolute;       /* the offset in the caller's units (0 for SCALE) */
    double time_reduce_s, time_solve_s, time_total_s; /* the total includes the coverage matrix */
    uint64_t rows_before, cols_before, rows_after, cols_after, forced;
    uint64_t components;         /* independent parts of the reduced problem */
    uint64_t probes;             /* set-cover solves of the searches (target_count, target_error) */
    uint64_t parts;              /* divide and conquer: spatial parts (0 = not used) */
    double scale_used;           /* the scale factor used (CA_DILATE_SCALE), else 0 */
    double time_coverage_s;      /* building the coverage matrix (part of time_total_s) */
    uint64_t cbc_components;     /* components of the kernel that needed CBC */
    uint64_t rowgen_rounds;      /* row-generation rounds */
    double hd_reached;           /* the searches: the selection's two-sided HD, %; -1: not measured */
} ca_select_stats;
CA_API ca_status ca_selection_stats(const ca_selection* selection, ca_select_stats* stats);

/* ---- step 3: connectivity ------------------------------------------------------------------ */
#define CA_FIT_AUTO     (-1) /* THOROUGH for a target_count selection on a mesh, else OFF */
#define CA_FIT_OFF      0
#define CA_FIT_ONCE     1 /* each ball's centre and radius fitted to the surface (meshes) */
#define CA_FIT_THOROUGH 2 /* of ONCE and a fit with twice the samples, the lower evaluated HD */
#define CA_FIT_COVERED  3 /* ONCE, then added balls keep every cover sample covered */
#define CA_CONNECT_POWER  0 /* regular triangulation of selected balls and dense surface samples */
#define CA_CONNECT_MEDIAL 1 /* regions of the selected balls on the inner Voronoi medial mesh */
#define CA_CONNECT_AUTO   2 /* MEDIAL for meshes and clean point clouds, else POWER */
typedef struct ca_connect_options {
    uint32_t struct_size;
    int32_t method;              /* CA_CONNECT_*; default AUTO */
    int32_t remove_outside;      /* 1 (default): drop edges/triangles whose interior leaves the shape */
    int32_t fill_holes;          /* 1 (default): fill 3- and 4-edge holes whose triangles stay inside */
    int32_t reconnect;           /* 1 (default): join components by the shortest inside edges */
    int32_t fit;                 /* CA_FIT_*; default AUTO (docs/fidelity.md) */
    int32_t fit_iterations;      /* fitting steps; default 10 */
} ca_connect_options;
CA_API ca_status ca_connect_options_defaults(ca_connect_options* options, uint32_t struct_size);
CA_DEFINE_INIT_(ca_connect_options)

typedef struct ca_skeleton ca_skeleton;
/* `set` must be the one `selection` was made from, else CA_ERROR_INVALID_ARGUMENT. */
CA_API ca_status ca_connect(ca_context* ctx, const ca_candidate_set* set, const ca_selection* selection,
                            const ca_connect_options* options, ca_skeleton** out);
CA_API void ca_skeleton_destroy(ca_skeleton* skeleton);
CA_API size_t ca_skeleton_vertex_count(const ca_skeleton* skeleton);
CA_API const double* ca_skeleton_centers(const ca_skeleton* skeleton);
CA_API const double* ca_skeleton_radii(const ca_skeleton* skeleton);   /* undilated medial radii */
CA_API size_t ca_skeleton_edge_count(const ca_skeleton* skeleton);
CA_API const uint32_t* ca_skeleton_edges(const ca_skeleton* skeleton); /* incl. the faces' edges */
CA_API size_t ca_skeleton_face_count(const ca_skeleton* skeleton);
CA_API const uint32_t* ca_skeleton_faces(const ca_skeleton* skeleton);

typedef struct ca_skeleton_stats {
    uint32_t struct_size;
    uint64_t vertices, edges, faces;
    uint64_t components;         /* connected components (isolated vertices count) */
    uint64_t isolated;           /* vertices with no edge */
    int64_t betti1;              /* independent cycles of the complex */
    double time_s;
    int32_t method;              /* CA_CONNECT_POWER or CA_CONNECT_MEDIAL: the route used */
    double fit_time_s;           /* part of time_s */
    double fit_error_before;     /* fit's largest residual before / after, % of the longest bbox side */
    double fit_error_after;
    uint64_t fit_uncovered;      /* cover samples no fitted dilated ball covers (0: the cover holds) */
    int32_t fitted;              /* 1 if the balls were fitted */
    int64_t genus;               /* the input mesh's (sum over its parts; loops beyond it are removed);
                                    -1: unknown (clouds, open or non-manifold parts) */
    uint64_t thin_handles;       /* max(0, genus - betti1): handles too thin for a loop; 0: genus unknown */
    uint64_t medial_balls;       /* vertices that are inner (medial) balls */
    uint64_t surface_balls;      /* vertices that are surface balls (see volumetric_only) */
    uint64_t open_parts;         /* connected parts of the input mesh with a boundary; 0 for clouds */
} ca_skeleton_stats;
CA_API ca_status ca_skeleton_stats_get(const ca_skeleton* skeleton, ca_skeleton_stats* stats);

/* ---- evaluation: how far is a skeleton from the shape? (docs/evaluation.md) ----------------- */
/* A skeleton as arrays (ca_skeleton_get_view's or the caller's). Its reconstruction is the union of
   its balls, its edges' cones and its faces' slabs; distances are Hausdorff (max) and mean, in %. */
typedef struct ca_skeleton_view {
    uint32_t struct_size;
    const double* centers; const double* radii; size_t vertex_count; /* x y z and a radius per ball, packed */
    const uint32_t* edges; size_t edge_count; /* i j per edge, packed */
    const uint32_t* faces; size_t face_count; /* i j k per face, packed */
} ca_skeleton_view;
CA_API ca_status ca_skeleton_view_defaults(ca_skeleton_view* view, uint32_t struct_size);
CA_DEFINE_INIT_(ca_skeleton_view)
CA_API ca_status ca_skeleton_get_view(const ca_skeleton* skeleton, ca_skeleton_view* view);

typedef struct ca_evaluate_options {
    uint32_t struct_size;
    uint32_t surface_samples;    /* area-uniform samples of the input, plus its vertices; default 30000 */
    uint32_t envelope_samples;   /* samples of the reconstruction's boundary; default 100000 */
    uint64_t seed;               /* default 1 */
} ca_evaluate_options;
CA_API ca_status ca_evaluate_options_defaults(ca_evaluate_options* options, uint32_t struct_size);
CA_DEFINE_INIT_(ca_evaluate_options)

typedef struct ca_evaluation {
    uint32_t struct_size;
    double hd_surface_to_recon;  /* max over surface samples of the distance to the reconstruction */
    double mean_surface_to_recon;
    double hd_recon_to_surface;  /* max over the reconstruction's boundary samples of the distance to the surface */
    double mean_recon_to_surface;
    double hd_two_sided;         /* max of the two */
    double diagonal;             /* the input's bounding-box diagonal, caller's units */
    uint64_t surface_samples_used, envelope_samples_used;
    double time_s;
} ca_evaluation;

/* surface: the input mesh, or a point cloud (distances to its nearest point). */
CA_API ca_status ca_evaluate(ca_context* ctx, const ca_surface_view* surface, const ca_skeleton_view* skeleton,
                             const ca_evaluate_options* options, ca_evaluation* result);

/* ---- correspondence and rig (docs/rig.md) -------------------------------------------------- */
/* Per surface vertex, from a skeleton in the same units: the nearest primitive and CA_INFLUENCES balls
   (correspondence), or joints of a tree along a curve skeleton (rig), with weights summing to 1, by
   decreasing weight; an unused slot has weight 0 and repeats the first ball or joint. */
#define CA_INFLUENCES 4
#define CA_NEAREST_BALL 0 /* ca_correspondence_nearest_kinds: the index is a ball's */
#define CA_NEAREST_EDGE 1 /* an edge's (of ca_skeleton_view.edges) */
#define CA_NEAREST_FACE 2 /* a face's (also for an edge of a face not among the view's edges) */
typedef struct ca_correspondence_options {
    uint32_t struct_size;
    double smoothing;            /* the blend's width in median ball radii: a primitive farther than the
                                    nearest by that much weighs e^-1 of it; > 0; default 0.5 */
} ca_correspondence_options;
CA_API ca_status ca_correspondence_options_defaults(ca_correspondence_options* options, uint32_t struct_size);
CA_DEFINE_INIT_(ca_correspondence_options)

typedef struct ca_correspondence ca_correspondence;
CA_API ca_status ca_correspond(ca_context* ctx, const ca_surface_view* surface, const ca_skeleton_view* skeleton,
                               const ca_correspondence_options* options, ca_correspondence** out);
CA_API void ca_correspondence_destroy(ca_correspondence* correspondence);
CA_API size_t ca_correspondence_vertex_count(const ca_correspondence* correspondence);
CA_API const uint32_t* ca_correspondence_balls(const ca_correspondence* correspondence);  /* CA_INFLUENCES per vertex */
CA_API const double* ca_correspondence_weights(const ca_correspondence* correspondence); /* CA_INFLUENCES per vertex */
CA_API const int32_t* ca_correspondence_nearest_kinds(const ca_correspondence* correspondence);    /* CA_NEAREST_* */
CA_API const uint32_t* ca_correspondence_nearest_indices(const ca_correspondence* correspondence); /* ball, edge or face */

typedef struct ca_rig_options {
    uint32_t struct_size;
    int64_t root;                /* the root joint's ball; default -1: the largest ball */
    uint32_t max_joints;         /* at most this many joints, >= 1; default 64 */
    double joint_spacing;        /* joints about this far apart along a branch, > 0, fraction of the
                                    longest side of the balls' bounding box; default 0.1 */
    double min_branch;           /* a branch is kept when its tip ball reaches past the tree by more than
                                    this many radii and it is this many tip radii long, >= 0; default 1.5 */
    double smoothing;            /* as ca_correspondence_options; default 0.5 */
} ca_rig_options;
CA_API ca_status ca_rig_options_defaults(ca_rig_options* options, uint32_t struct_size);
CA_DEFINE_INIT_(ca_rig_options)

typedef struct ca_rig ca_rig;
CA_API ca_status ca_rig_build(ca_context* ctx, const ca_surface_view* surface, const ca_skeleton_view* skeleton,
                              const ca_rig_options* options, ca_rig** out);
CA_API void ca_rig_destroy(ca_rig* rig);
/* Joints in an order where a parent comes before its children; joint 0 is the root. */
CA_API size_t ca_rig_joint_count(const ca_rig* rig);
CA_API const double* ca_rig_joint_positions(const ca_rig* rig);  /* a ball's centre per joint */
CA_API const int32_t* ca_rig_joint_parents(const ca_rig* rig);   /* -1 for the root */
CA_API const uint32_t* ca_rig_joint_balls(const ca_rig* rig);    /* the ball each joint sits on */
CA_API const uint32_t* ca_rig_joint_branches(const ca_rig* rig); /* the branch each joint is on (root: 0) */
CA_API size_t ca_rig_branch_count(const ca_rig* rig);            /* branches between root, junctions, tips */
CA_API size_t ca_rig_vertex_count(const ca_rig* rig);
CA_API const uint32_t* ca_rig_vertex_joints(const ca_rig* rig);   /* CA_INFLUENCES per vertex */
CA_API const double* ca_rig_vertex_weights(const ca_rig* rig);    /* CA_INFLUENCES per vertex */
CA_API const uint32_t* ca_rig_vertex_branches(const ca_rig* rig); /* the branch of the vertex's heaviest ball */

/* ---- engine proxies (docs/proxies.md) ------------------------------------------------------ */
/* At most `count` spheres, tapered capsules (hulls of two balls) and oriented boxes. INSCRIBED: least
   two-sided HD, none reaching farther outside than the skeleton (a proven bound); CONSERVATIVE: least
   volume outside, holding every point of every triangle. */
#define CA_PROXY_SHAPES_SPHERES  0 /* spheres only */
#define CA_PROXY_SHAPES_CAPSULES 1 /* tapered capsules and spheres */
#define CA_PROXY_SHAPES_BOXES    2 /* oriented boxes and spheres */
#define CA_PROXY_SHAPES_ALL      3 /* spheres, tapered capsules and oriented boxes */
#define CA_PROXY_INSCRIBED       0
#define CA_PROXY_CONSERVATIVE    1
#define CA_PROXY_SPHERE          0 /* kind of one primitive */
#define CA_PROXY_CAPSULE         1
#define CA_PROXY_BOX             2
typedef struct ca_proxy_options {
    uint32_t struct_size;
    int32_t shapes;              /* CA_PROXY_SHAPES_*; default CAPSULES */
    int32_t mode;                /* CA_PROXY_INSCRIBED or CA_PROXY_CONSERVATIVE; default INSCRIBED */
    uint32_t count;              /* at most this many primitives, >= 1; default 16 */
    uint32_t surface_samples;    /* about this many corners of the surface cells; default 20000 */
    uint32_t evaluate_samples;   /* stats: surface and proxy-boundary samples each; default 20000 */
    uint32_t volume_samples;     /* stats: Monte Carlo points for the volumes; default 100000 */
    uint64_t seed;               /* default 1 */
} ca_proxy_options;
CA_API ca_status ca_proxy_options_defaults(ca_proxy_options* options, uint32_t struct_size);
CA_DEFINE_INIT_(ca_proxy_options)

typedef struct ca_proxy_set ca_proxy_set;
/* `set` must come from ca_candidates on a triangle mesh, else CA_ERROR_INVALID_ARGUMENT. */
CA_API ca_status ca_proxies(ca_context* ctx, const ca_candidate_set* set, const ca_skeleton_view* skeleton,
                            const ca_proxy_options* options, ca_proxy_set** out);
CA_API void ca_proxy_set_destroy(ca_proxy_set* proxies);
CA_API size_t ca_proxy_set_count(const ca_proxy_set* proxies);
CA_API const int32_t* ca_proxy_set_kinds(const ca_proxy_set* proxies);   /* CA_PROXY_SPHERE, CAPSULE or BOX */
/* Per primitive, balls a and b: centres (6 doubles) and radii (2); a sphere's b is its a, a box has
   its centre twice and radii 0. */
CA_API const double* ca_proxy_set_centers(const ca_proxy_set* proxies);
CA_API const double* ca_proxy_set_radii(const ca_proxy_set* proxies);

typedef struct ca_proxy_stats {
    uint32_t struct_size;
    double hd_surface_to_proxies;   /* these five as ca_evaluation, the primitives as balls and edges */
    double mean_surface_to_proxies;
    double hd_proxies_to_surface;
    double mean_proxies_to_surface;
    double hd_two_sided;
    double outside_bound;        /* proven bound of how far any primitive reaches outside the shape, % */
    double skeleton_outside;     /* how far the skeleton's balls and edges reach outside at least
                                    (measured), % (INSCRIBED: outside_bound is at most this) */
    double union_volume;         /* Monte Carlo volume of the union of the primitives, caller's units^3 */
    double outside_volume;       /* of which outside the shape (winding-number inside test) */
    double radius_change;        /* %: the most a primitive grew (CONSERVATIVE) or a candidate shrank (INSCRIBED) */
    double diagonal;             /* the surface's bbox diagonal, caller's units */
    uint64_t candidates;         /* primitives chosen from */
    uint64_t surface_cells;      /* small triangles the surface was cut into */
    double time_s;
} ca_proxy_stats;
CA_API ca_status ca_proxy_set_stats(const ca_proxy_set* proxies, ca_proxy_stats* stats);

/* A primitive as an engine places it (glTF KHR_implicit_shapes): a node at `center`, turned by the
   unit quaternion `rotation` (node frame to the caller's), holds in its own frame
   - CA_PROXY_SPHERE: a sphere of radius radius_top (= radius_bottom) at its origin;
   - CA_PROXY_CAPSULE: the hull of a ball of radius_top at (0, +height/2, 0) (the set's ball b) and
     one of radius_bottom at (0, -height/2, 0) (ball a), height > 0;
   - CA_PROXY_BOX: the box of half extents half_extents[0..2] along its x, y, z axes.
   A capsule one of whose balls holds the other is placed as that ball, a CA_PROXY_SPHERE. Unused
   fields are 0. */
typedef struct ca_proxy_placement {
    uint32_t struct_size;
    int32_t kind;                /* CA_PROXY_SPHERE, CA_PROXY_CAPSULE or CA_PROXY_BOX */
    double center[3];            /* the node's translation */
    double rotation[4];          /* the node's rotation, x y z w, w >= 0 */
    double axis[3];              /* the node's +Y axis in the caller's frame (a capsule: from a to b) */
    double radius_top, radius_bottom, height;
    double half_extents[3];
} ca_proxy_placement;
/* index < ca_proxy_set_count, else CA_ERROR_INVALID_ARGUMENT. */
CA_API ca_status ca_proxy_set_placement(const ca_proxy_set* proxies, size_t index, ca_proxy_placement* placement);

/* ---- bone colliders (docs/bone_colliders.md) ----------------------------------------------- */
/* A skin (glTF skins, assimp aiBone) of the surface in its bind pose; where the surface repeats a
   vertex position, the first vertex's weights are used. */
typedef struct ca_skin_view {
    uint32_t struct_size;
    size_t joint_count;             /* >= 1 */
    const int32_t* parents;         /* joint_count; -1 for a root; no cycles */
    const double* inverse_bind;     /* joint_count * 16, column-major 4x4: surface to joint frame at bind
                                       time; rotation (or reflection), uniform scale, translation; NULL = identity */
    size_t vertex_count;            /* must equal the surface's vertex_count */
    uint32_t influences;            /* joints per vertex, 1..8 */
    const uint32_t* vertex_joints;  /* vertex_count * influences, each < joint_count */
    const double* vertex_weights;   /* vertex_count * influences, finite, >= 0; normalised per vertex
                                       (all zero: the vertex drives no joint) */
} ca_skin_view;
CA_API ca_status ca_skin_view_defaults(ca_skin_view* view, uint32_t struct_size);
CA_DEFINE_INIT_(ca_skin_view)

typedef struct ca_bone_collider_options {
    uint32_t struct_size;
    int32_t mode;                   /* CA_PROXY_CONSERVATIVE (holds every point of its part) or
                                       CA_PROXY_INSCRIBED (stays inside the shape); default CONSERVATIVE */
    int32_t shapes;                 /* CA_PROXY_SHAPES_CAPSULES (a tapered capsule or sphere each) or
                                       CA_PROXY_SHAPES_SPHERES; default CAPSULES */
    double min_share;               /* a joint dominating less of the area than this gets none; default 0.005 */
    double min_size;                /* least larger radius of a collider, %; default 0.5 */
    const uint32_t* skip_joints; size_t skip_count; /* joints to give no collider */
    uint32_t surface_samples;       /* samples of each part the fit uses; default 2000 */
    uint32_t evaluate_samples;      /* fresh surface samples for the stats; default 100000 */
    uint64_t seed;                  /* default 1 */
} ca_bone_collider_options;
CA_API ca_status ca_bone_collider_options_defaults(ca_bone_collider_options* options, uint32_t struct_size);
CA_DEFINE_INIT_(ca_bone_collider_options)

typedef struct ca_bone_colliders ca_bone_colliders;
/* A collider per joint, fitted to the inner balls of `set` in the joint's part (the surface it
   dominates: where its weight is the heaviest), in the joint's frame. `set` as for ca_proxies;
   `skeleton` may be NULL (not used yet; a view given is checked). */
CA_API ca_status ca_bone_colliders_build(ca_context* ctx, const ca_candidate_set* set,
                                         const ca_skeleton_view* skeleton, const ca_skin_view* skin,
                                         const ca_bone_collider_options* options, ca_bone_colliders** out);
CA_API void ca_bone_colliders_destroy(ca_bone_colliders* colliders);
CA_API size_t ca_bone_colliders_count(const ca_bone_colliders* colliders);
CA_API const uint32_t* ca_bone_colliders_joints(const ca_bone_colliders* colliders); /* joint of each, ascending */
/* Collider `index` in ITS JOINT'S frame, as ca_proxy_set_placement (CA_PROXY_SPHERE or CAPSULE). */
CA_API ca_status ca_bone_colliders_placement(const ca_bone_colliders* colliders, size_t index,
                                             ca_proxy_placement* placement);

typedef struct ca_bone_collider_stats {
    uint32_t struct_size;
    double contained_fraction;      /* fresh surface samples held by their part's collider, over the
                                       parts that have one (CONSERVATIVE: 1) */
    double union_volume, outside_volume;  /* Monte Carlo: the colliders' union and its part outside the
                                             shape, in the surface's frame */
    double neighbour_overlap;       /* sum of ca_bone_colliders_overlap */
    uint64_t joints_with_collider;
    uint64_t joints_skipped;        /* joints that dominate some of the surface but got no collider */
    double time_s;
} ca_bone_collider_stats;
CA_API ca_status ca_bone_colliders_stats(const ca_bone_colliders* colliders, ca_bone_collider_stats* stats);
/* Per collider: the fraction of its part's fresh samples it holds, and its overlap volume with the
   collider of its nearest ancestor joint that has one (else 0). */
CA_API const double* ca_bone_colliders_contained(const ca_bone_colliders* colliders);
CA_API const double* ca_bone_colliders_overlap(const ca_bone_colliders* colliders);

#ifdef __cplusplus
}
#endif
#undef CA_DEFINE_INIT_
#endif /* COVERAGE_AXIS_H */

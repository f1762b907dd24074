/*
 * coverage_axis.h - the one stable C ABI of the coverage-axis library (C99; compiles as C and C++).
 *
 * Coverage Axis (Dou et al., Eurographics 2022) turns a triangle mesh or an oriented point cloud
 * into a few medial balls (centre + radius) joined by edges and triangles, in three calls:
 *   ca_candidates  surface -> surface samples + inner candidate balls        (ca_candidate_set)
 *   ca_select      fewest dilated candidate balls covering every sample      (ca_selection)
 *   ca_connect     edges and triangles between the selected balls            (ca_skeleton)
 *
 * Contracts of every call, stated once here (in full, with what each ABI version added: docs/abi.md)
 * - Coordinates are doubles in the caller's units, as are results; lengths given as options are
 *   fractions of the longest side of the input's bounding box.
 * - Inputs are borrowed views (pointer, count, byte stride; 0 = packed), read during the call only;
 *   a count that does not match its array is CA_ERROR_INVALID_INPUT. Outputs are packed.
 * - Fallible calls return a ca_status. On any but CA_OK the output pointer is NULL and nothing is
 *   allocated (except ca_select's CA_ERROR_TARGET_NOT_REACHED, and its CA_ERROR_TIME_LIMIT when *out
 *   is not NULL: a search's best selection so far); ca_context_last_error() explains. No exception
 *   crosses this boundary; nothing prints, exits or aborts.
 * - Results are opaque, immutable, readable from several threads and freed with their ca_*_destroy
 *   (NULL: no-op); getters' pointers live until then. A context serves one thread at a time.
 * - Every struct starts with uint32_t struct_size and grows only at its end; any size this library
 *   published is accepted, others are CA_ERROR_STRUCT_SIZE (nothing written). Inputs: ca_*_init(p)
 *   (C) or ca_*_defaults(p, size) (FFI); fields past the caller's size, and a NULL options pointer,
 *   take the defaults. Outputs are written up to the caller's size.
 * - Defaults live in the library: a field's comment names its default, else it is 0 / NULL
 *   (tests/abi_layout/check_defaults.py checks both).
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

/* ca_xxx_init(p): p->struct_size = sizeof *p as the caller's compiler sees it, then the library's
   defaults (never writes past the caller's struct). */
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
/* The callbacks run on the calling thread. log level: 0 debug, 1 info, 2 warning. */
typedef void (*ca_log_fn)(void* user, int32_t level, const char* message);
/* stage: "sampling", "inside", "delaunay", "candidates", "coverage", "selection", "connect", ...;
   fraction in [0,1] within the stage. Non-zero cancels the call (CA_ERROR_CANCELLED). */
typedef int32_t (*ca_progress_fn)(void* user, const char* stage, double fraction);
/* Allocates the result objects and their getters' arrays (working memory uses the C++ heap). */
typedef void* (*ca_alloc_fn)(void* user, size_t size);
typedef void (*ca_free_fn)(void* user, void* pointer);

typedef struct ca_context_desc {
    uint32_t struct_size;  /* sizeof(ca_context_desc) */
    ca_alloc_fn alloc;     /* NULL: malloc; set both alloc and free, or neither */
    ca_free_fn free;       /* NULL: free */
    void* alloc_user;
    ca_log_fn log;         /* NULL: no log */
    void* log_user;
    ca_progress_fn progress; /* NULL: no progress */
    void* progress_user;
    int32_t threads;       /* worker threads of the parallel stages; 0 = all cores, 1 = serial */
    double progress_interval_s; /* least time between two progress calls of a stage (its first call and
                                   fraction 1 always come); default 0 = every update */
    double time_limit_s;   /* wall-clock budget of each long call: CA_ERROR_TIME_LIMIT, except the exact
                              solver, which returns its best cover unproven; default 0 = unlimited */
} ca_context_desc;
CA_API ca_status ca_context_desc_defaults(ca_context_desc* desc, uint32_t struct_size);
CA_DEFINE_INIT_(ca_context_desc)
CA_API ca_status ca_context_create(const ca_context_desc* desc, ca_context** out); /* desc NULL: defaults */
CA_API void ca_context_destroy(ca_context* ctx);
/* Any thread. Every long call returns CA_ERROR_CANCELLED until ca_context_clear_cancel(). */
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
    uint32_t struct_size;       /* sizeof(ca_surface_view) */
    const double* positions;    /* x y z per vertex */
    size_t vertex_count;
    size_t position_stride;
    const uint32_t* triangles;  /* i j k per triangle, 0-based */
    size_t triangle_count;
    size_t triangle_stride;
    const double* normals;      /* point clouds: nx ny nz per point, inward or outward; NULL: estimated */
    size_t normal_stride;
    int32_t point_normals;      /* CA_POINT_NORMALS_*; default TRUSTED */
    size_t normal_count;        /* entries of normals: vertex_count, or 0 with normals NULL */
} ca_surface_view;
CA_API ca_status ca_surface_view_defaults(ca_surface_view* view, uint32_t struct_size);
CA_DEFINE_INIT_(ca_surface_view)

/* ---- step 1: candidates -------------------------------------------------------------------- */
#define CA_CANDIDATES_VORONOI 0 /* inner Voronoi vertices of voronoi_samples surface samples */
#define CA_CANDIDATES_RANDOM  1 /* random interior points, radius = distance to the surface */

typedef struct ca_candidate_options {
    uint32_t struct_size;        /* sizeof(ca_candidate_options) */
    int32_t generator;           /* CA_CANDIDATES_*; default VORONOI */
    uint32_t cover_samples;      /* |S|, samples to cover; default 1500 (point clouds: the points,
                                    subsampled to this many if there are more; 0 = all) */
    uint32_t voronoi_samples;    /* |C|, samples whose Voronoi vertices are candidates; default 4000 */
    uint32_t random_candidates;  /* random generator: number of interior points; default 10000 */
    uint64_t seed;               /* default 1; the same seed gives the same result */
    uint32_t connect_samples;    /* meshes: surface samples of the power-diagram connection;
                                    default 10000; 0 = reuse the Voronoi samples */
    uint32_t reserved_abi2_tail; /* never read (the tail padding of an older layout) */
    int32_t volumetric_only;     /* 0 (default): a cover sample no inner ball reaches (sheets, thin
                                    parts) gets a surface ball, so a cover exists. 1: inner balls only */
} ca_candidate_options;
CA_API ca_status ca_candidate_options_defaults(ca_candidate_options* options, uint32_t struct_size);
CA_DEFINE_INIT_(ca_candidate_options)

typedef struct ca_candidate_set ca_candidate_set;
CA_API ca_status ca_candidates(ca_context* ctx, const ca_surface_view* surface,
                               const ca_candidate_options* options, ca_candidate_set** out);
/* A candidate set from the caller's own samples and balls (radius = undilated medial radius).
   reference_length: the length delta is a fraction of; 0 = the samples' longest bbox side. */
CA_API ca_status ca_candidates_from_arrays(ca_context* ctx,
                                           const double* samples, size_t sample_count, size_t sample_stride,
                                           const double* centers, size_t center_stride,
                                           const double* radii, size_t radius_stride,
                                           size_t ball_count, double reference_length,
                                           ca_candidate_set** out);
/* Releases the caller's handle; selections made from the set keep it alive. */
CA_API void ca_candidate_set_destroy(ca_candidate_set* set);
CA_API size_t ca_candidate_set_count(const ca_candidate_set* set);
CA_API const double* ca_candidate_set_centers(const ca_candidate_set* set);
CA_API const double* ca_candidate_set_radii(const ca_candidate_set* set);
CA_API size_t ca_candidate_set_sample_count(const ca_candidate_set* set);
CA_API const double* ca_candidate_set_samples(const ca_candidate_set* set);
CA_API double ca_candidate_set_reference_length(const ca_candidate_set* set); /* caller's units */
/* 1 if the mesh faced inward (or the cloud's normals pointed inward) and was flipped, else 0. */
CA_API int32_t ca_candidate_set_flipped(const ca_candidate_set* set);
#define CA_NORMALS_NONE      0 /* a mesh: no point normals */
#define CA_NORMALS_GIVEN     1 /* the caller's normals */
#define CA_NORMALS_ORIENTED  2 /* the caller's normals, re-oriented */
#define CA_NORMALS_ESTIMATED 3 /* estimated from the points (PCA) and oriented */
CA_API int32_t ca_candidate_set_normals(const ca_candidate_set* set); /* CA_NORMALS_*: what a cloud used */
/* Point clouds: (de-duplicated) points dropped as outliers; 0 for meshes. */
CA_API uint64_t ca_candidate_set_outlier_count(const ca_candidate_set* set);
/* Point clouds: given normals that were zero ("none") and were estimated; 0 for meshes. */
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
/* Effort of the exact solver (docs/solver.md). */
#define CA_EFFORT_FAST  0 /* LP bound + local search; CBC only on a small kernel one ball from the
                             bound; else the cover comes back unproven with its bound and gap */
#define CA_EFFORT_PROVE 1 /* CBC until the cover is proven optimal or the time limit ends it */

typedef struct ca_select_options {
    uint32_t struct_size;        /* sizeof(ca_select_options) */
    int32_t dilation;            /* CA_DILATE_*; default OFFSET */
    double delta;                /* offset, fraction of the longest bbox side; default 0.02 */
    double scale;                /* scale factor; default 1.5 */
    int32_t solver;              /* CA_SOLVER_*; default EXACT */
    double time_limit_s;         /* exact solver's wall-clock budget, a safety net; default 60; <= 0: none */
    int32_t skip_uncoverable;    /* 0 (default): uncoverable samples are CA_ERROR_UNCOVERABLE;
                                    1: they are ignored and listed in the result */
    const uint8_t* ignorable_samples; /* per sample, non-zero: need not be covered */
    const uint8_t* forced_in;         /* per candidate ball, non-zero: must be selected */
    const uint8_t* forced_out;        /* per candidate ball, non-zero: must not be selected */
    uint32_t target_count;       /* 0 (default): off. K: at most K balls, at the smallest dilation that
                                    achieves it, then the lowest HD among probed deltas (docs/fidelity.md) */
    double target_tolerance;     /* bisection tolerance on delta or scale; default 1e-4 */
    uint32_t divide_threshold;   /* more samples: divide and conquer; default 100000; 0 = never */
    int32_t effort;              /* CA_EFFORT_*; default FAST */
    double target_error;         /* 0 (default): off. E: few balls whose skeleton is within two-sided HD
                                    E % of the bbox diagonal (offset dilation, not with target_count) */
    int32_t probe_fit;           /* 0 (default): the searches' probes connected at the defaults;
                                    1: with fit = 1 (meshes) */
    size_t ignorable_samples_count; /* the masks' entries: the set's samples or balls, 0 with NULL */
    size_t forced_in_count;
    size_t forced_out_count;
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
    uint32_t struct_size;        /* sizeof(ca_select_stats) */
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
    uint32_t struct_size;        /* sizeof(ca_connect_options) */
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
CA_API ca_status ca_connect(ca_context* ctx, const ca_candidate_set* set, const ca_selection* selection,
                            const ca_connect_options* options, ca_skeleton** out);
CA_API void ca_skeleton_destroy(ca_skeleton* skeleton);
CA_API size_t ca_skeleton_vertex_count(const ca_skeleton* skeleton);
CA_API const double* ca_skeleton_centers(const ca_skeleton* skeleton);
CA_API const double* ca_skeleton_radii(const ca_skeleton* skeleton);   /* undilated medial radii */
CA_API size_t ca_skeleton_edge_count(const ca_skeleton* skeleton);
CA_API const uint32_t* ca_skeleton_edges(const ca_skeleton* skeleton); /* i j per edge, incl. face edges */
CA_API size_t ca_skeleton_face_count(const ca_skeleton* skeleton);
CA_API const uint32_t* ca_skeleton_faces(const ca_skeleton* skeleton); /* i j k per face */

typedef struct ca_skeleton_stats {
    uint32_t struct_size;        /* sizeof(ca_skeleton_stats) */
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
    int64_t genus;               /* the input mesh's (sum over its parts); -1: unknown (clouds, open or
                                    non-manifold parts); loops beyond it are removed */
    uint64_t thin_handles;       /* max(0, genus - betti1): handles too thin for a loop; 0: genus unknown */
    uint64_t medial_balls;       /* vertices that are inner (medial) balls */
    uint64_t surface_balls;      /* vertices that are surface balls (see volumetric_only) */
    uint64_t open_parts;         /* connected parts of the input mesh with a boundary; 0 for clouds */
} ca_skeleton_stats;
CA_API ca_status ca_skeleton_stats_get(const ca_skeleton* skeleton, ca_skeleton_stats* stats);

/* ---- evaluation: how far is a skeleton from the shape? ------------------------------------- */
/* The reconstruction is the union of the skeleton's balls, edges' medial cones and faces' medial
   slabs. Hausdorff distances (max and mean), one-sided and two-sided, in % of the input's
   bounding-box diagonal (docs/evaluation.md). */
typedef struct ca_skeleton_view {
    uint32_t struct_size;        /* sizeof(ca_skeleton_view) */
    const double* centers;       /* x y z per ball, packed */
    const double* radii;         /* one per ball */
    size_t vertex_count;
    const uint32_t* edges;       /* i j per edge, packed; may be NULL if edge_count == 0 */
    size_t edge_count;
    const uint32_t* faces;       /* i j k per face, packed; may be NULL if face_count == 0 */
    size_t face_count;
} ca_skeleton_view;
CA_API ca_status ca_skeleton_view_defaults(ca_skeleton_view* view, uint32_t struct_size);
CA_DEFINE_INIT_(ca_skeleton_view)
/* A view of a skeleton result (valid while the skeleton lives). */
CA_API ca_status ca_skeleton_get_view(const ca_skeleton* skeleton, ca_skeleton_view* view);

typedef struct ca_evaluate_options {
    uint32_t struct_size;        /* sizeof(ca_evaluate_options) */
    uint32_t surface_samples;    /* area-uniform samples of the input, plus its vertices; default 30000 */
    uint32_t envelope_samples;   /* samples of the reconstruction's boundary; default 100000 */
    uint64_t seed;               /* default 1 */
} ca_evaluate_options;
CA_API ca_status ca_evaluate_options_defaults(ca_evaluate_options* options, uint32_t struct_size);
CA_DEFINE_INIT_(ca_evaluate_options)

typedef struct ca_evaluation {
    uint32_t struct_size;        /* sizeof(ca_evaluation) */
    double hd_surface_to_recon;  /* max over surface samples of the distance to the reconstruction, % */
    double mean_surface_to_recon;
    double hd_recon_to_surface;  /* max over reconstruction boundary samples of the distance to the surface, % */
    double mean_recon_to_surface;
    double hd_two_sided;         /* max of the two, % */
    double diagonal;             /* the input's bounding-box diagonal, caller's units */
    uint64_t surface_samples_used, envelope_samples_used;
    double time_s;
} ca_evaluation;

/* surface: the input mesh, or a point cloud (distances to its nearest point). Fills *result. */
CA_API ca_status ca_evaluate(ca_context* ctx, const ca_surface_view* surface, const ca_skeleton_view* skeleton,
                             const ca_evaluate_options* options, ca_evaluation* result);

/* ---- correspondence and rig (docs/rig.md) -------------------------------------------------- */
/* For every vertex of a surface and a skeleton in the same units: the correspondence (the nearest
   skeleton primitive, and up to CA_INFLUENCES balls with weights), and the rig (a tree of joints
   along a curve skeleton, and CA_INFLUENCES joints with weights). Weights sum to 1, by decreasing
   weight; an unused slot has weight 0 and repeats the first ball or joint. */
#define CA_INFLUENCES 4
#define CA_NEAREST_BALL 0 /* ca_correspondence_nearest_kinds: the index is a ball's */
#define CA_NEAREST_EDGE 1 /* an edge's (of ca_skeleton_view.edges) */
#define CA_NEAREST_FACE 2 /* a face's (also for an edge of a face not among the view's edges) */

typedef struct ca_correspondence_options {
    uint32_t struct_size;        /* sizeof(ca_correspondence_options) */
    double smoothing;            /* the blend's width, in median ball radii: a primitive farther than
                                    the nearest by that much weighs e^-1 of it; > 0; default 0.5 */
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
    uint32_t struct_size;        /* sizeof(ca_rig_options) */
    int64_t root;                /* the root joint's ball; default -1: the largest ball */
    uint32_t max_joints;         /* at most this many joints, >= 1; default 64 */
    double joint_spacing;        /* joints about this far apart along a branch, fraction of the longest
                                    side of the balls' bounding box, > 0; default 0.1 */
    double min_branch;           /* a branch is kept when its tip ball reaches past the tree by more than
                                    this many radii and it is this many tip radii long, >= 0; default 1.5 */
    double smoothing;            /* the ball weights' blend, as ca_correspondence_options; default 0.5 */
} ca_rig_options;
CA_API ca_status ca_rig_options_defaults(ca_rig_options* options, uint32_t struct_size);
CA_DEFINE_INIT_(ca_rig_options)

typedef struct ca_rig ca_rig;
CA_API ca_status ca_rig_build(ca_context* ctx, const ca_surface_view* surface, const ca_skeleton_view* skeleton,
                              const ca_rig_options* options, ca_rig** out);
CA_API void ca_rig_destroy(ca_rig* rig);

/* Joints in an order where a parent comes before its children; joint 0 is the root. */
CA_API size_t ca_rig_joint_count(const ca_rig* rig);
CA_API const double* ca_rig_joint_positions(const ca_rig* rig);  /* x y z per joint (a ball's centre) */
CA_API const int32_t* ca_rig_joint_parents(const ca_rig* rig);   /* -1 for the root */
CA_API const uint32_t* ca_rig_joint_balls(const ca_rig* rig);    /* the ball each joint sits on */
CA_API const uint32_t* ca_rig_joint_branches(const ca_rig* rig); /* the branch each joint is on (root: 0) */
CA_API size_t ca_rig_branch_count(const ca_rig* rig);            /* branches between root, junctions, tips */
CA_API size_t ca_rig_vertex_count(const ca_rig* rig);
CA_API const uint32_t* ca_rig_vertex_joints(const ca_rig* rig);   /* CA_INFLUENCES per vertex */
CA_API const double* ca_rig_vertex_weights(const ca_rig* rig);    /* CA_INFLUENCES per vertex */
CA_API const uint32_t* ca_rig_vertex_branches(const ca_rig* rig); /* the branch of the vertex's heaviest ball */

/* ---- engine proxies ------------------------------------------------------------------------ */
/* At most `count` convex colliders (docs/proxies.md): spheres, tapered capsules (the convex hull of
   two balls) and oriented boxes, from a skeleton and its surface. INSCRIBED: the least two-sided HD,
   no primitive reaching farther outside than the skeleton's balls and edges (a proven bound);
   CONSERVATIVE: the least volume outside, the union holding every point of every triangle. */
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
    uint32_t struct_size;        /* sizeof(ca_proxy_options) */
    int32_t shapes;              /* CA_PROXY_SHAPES_*; default CAPSULES */
    int32_t mode;                /* CA_PROXY_INSCRIBED or CA_PROXY_CONSERVATIVE; default INSCRIBED */
    uint32_t count;              /* at most this many primitives, >= 1; default 16 */
    uint32_t surface_samples;    /* about this many corners of the surface cells; default 20000 */
    uint32_t evaluate_samples;   /* stats: surface and proxy-boundary samples each; default 20000 */
    uint32_t volume_samples;     /* stats: Monte Carlo points for the volumes; default 100000 */
    uint64_t seed;               /* default 1; the same seed gives the same proxies */
} ca_proxy_options;
CA_API ca_status ca_proxy_options_defaults(ca_proxy_options* options, uint32_t struct_size);
CA_DEFINE_INIT_(ca_proxy_options)

typedef struct ca_proxy_set ca_proxy_set;
/* Proxies of `skeleton` (caller's units) over the surface of `set`, which must come from a triangle
   mesh (else CA_ERROR_INVALID_ARGUMENT). */
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
    uint32_t struct_size;        /* sizeof(ca_proxy_stats) */
    double hd_surface_to_proxies;   /* as ca_evaluation, the primitives as balls and edges, % */
    double mean_surface_to_proxies;
    double hd_proxies_to_surface;
    double mean_proxies_to_surface;
    double hd_two_sided;
    double outside_bound;        /* proven bound of how far any primitive reaches outside the shape, % */
    double skeleton_outside;     /* how far the skeleton's balls and edges reach outside at least
                                    (measured), % (INSCRIBED: outside_bound is at most this) */
    double union_volume;         /* Monte Carlo volume of the union of the primitives, caller's units^3 */
    double outside_volume;       /* of which outside the shape (winding-number inside test) */
    double radius_change;        /* CONSERVATIVE: the most a primitive grew; INSCRIBED: the most a
                                    candidate shrank; % of the diagonal */
    double diagonal;             /* the surface's bbox diagonal, caller's units */
    uint64_t candidates;         /* primitives chosen from */
    uint64_t surface_cells;      /* small triangles the surface was cut into */
    double time_s;
} ca_proxy_stats;
CA_API ca_status ca_proxy_set_stats(const ca_proxy_set* proxies, ca_proxy_stats* stats);

/* One primitive as an engine places it, in the caller's units: a node at `center` turned by the
   unit quaternion `rotation` (x y z w; node frame to the caller's frame) holds, in its own frame
   (glTF KHR_implicit_shapes' conventions):
   - CA_PROXY_SPHERE: a sphere of radius radius_top (= radius_bottom) at its origin;
   - CA_PROXY_CAPSULE: the convex hull of a ball of radius_top at (0, +height/2, 0) and one of
     radius_bottom at (0, -height/2, 0), height > 0 (the set's ball b on top, a at the bottom);
   - CA_PROXY_BOX: the box of half extents half_extents[0..2] along its x, y, z axes.
   A capsule one of whose balls holds the other (or whose balls coincide) is placed as that larger
   ball, kind CA_PROXY_SPHERE. `axis` is the node's +Y axis in the caller's frame (a capsule: the
   unit vector from a to b). Unused fields are 0 (height of a sphere, half_extents of a capsule). */
typedef struct ca_proxy_placement {
    uint32_t struct_size;        /* sizeof(ca_proxy_placement) */
    int32_t kind;                /* CA_PROXY_SPHERE, CA_PROXY_CAPSULE or CA_PROXY_BOX */
    double center[3];            /* the node's translation */
    double rotation[4];          /* the node's rotation, x y z w, w >= 0 */
    double axis[3];              /* the node's +Y axis */
    double radius_top, radius_bottom, height;
    double half_extents[3];
} ca_proxy_placement;

/* Fills `placement` for primitive `index` (< ca_proxy_set_count; else CA_ERROR_INVALID_ARGUMENT). */
CA_API ca_status ca_proxy_set_placement(const ca_proxy_set* proxies, size_t index, ca_proxy_placement* placement);

/* ---- Bone colliders (docs/bone_colliders.md) ----
   One collider per joint (bone) of a skin: a tapered capsule or sphere fitted to the part of the
   surface that joint dominates (the heaviest of the interpolated weights there), from the medial
   balls of that part, placed in the joint's frame so it moves with the bone. */

/* A skin: joints with a hierarchy and inverse bind matrices, and up to 8 joint weights per vertex
   of the surface it deforms (glTF skins, assimp aiBone), in its bind pose (the vertices as given).
   Where the surface repeats a vertex position, the first vertex's weights are used. */
typedef struct ca_skin_view {
    uint32_t struct_size;           /* sizeof(ca_skin_view) */
    size_t joint_count;             /* >= 1 */
    const int32_t* parents;         /* joint_count; -1 for a root; no cycles */
    const double* inverse_bind;     /* joint_count * 16, column-major 4x4 (glTF): the surface's frame to
                                       the joint's frame at bind time, a rotation (or reflection) with a
                                       uniform scale and a translation; NULL = identity */
    size_t vertex_count;            /* must equal the surface's vertex_count */
    uint32_t influences;            /* joints per vertex, 1..8 */
    const uint32_t* vertex_joints;  /* vertex_count * influences, each < joint_count */
    const double* vertex_weights;   /* vertex_count * influences, finite, >= 0; normalised per vertex by
                                       the library (all zero: the vertex drives no joint) */
} ca_skin_view;
CA_API ca_status ca_skin_view_defaults(ca_skin_view* view, uint32_t struct_size); /* all zero */
CA_DEFINE_INIT_(ca_skin_view)

typedef struct ca_bone_collider_options {
    uint32_t struct_size;           /* sizeof(ca_bone_collider_options) */
    int32_t mode;                   /* CA_PROXY_CONSERVATIVE (holds every point of its part) or
                                       CA_PROXY_INSCRIBED (stays inside the shape); default CONSERVATIVE */
    int32_t shapes;                 /* CA_PROXY_SHAPES_*: CAPSULES (a tapered capsule or sphere each) or
                                       SPHERES; default CAPSULES */
    double min_share;               /* a joint dominating less than this fraction of the surface's area
                                       gets no collider; default 0.005 */
    double min_size;                /* a collider whose larger radius is below this (percent of the
                                       surface's bounding-box diagonal) is dropped; default 0.5 */
    const uint32_t* skip_joints;    /* joints to give no collider (may be NULL when skip_count is 0) */
    size_t skip_count;
    uint32_t surface_samples;       /* samples of each part the fit uses; default 2000 */
    uint32_t evaluate_samples;      /* fresh surface samples for the stats; default 100000 */
    uint64_t seed;                  /* default 1 */
} ca_bone_collider_options;
CA_API ca_status ca_bone_collider_options_defaults(ca_bone_collider_options* options, uint32_t struct_size);
CA_DEFINE_INIT_(ca_bone_collider_options)

typedef struct ca_bone_colliders ca_bone_colliders;

/* One collider per joint that dominates at least min_share of the surface (and is not skipped),
   fitted to the inner balls of `set` (made by ca_candidates from the same triangle mesh; else
   CA_ERROR_INVALID_ARGUMENT) whose nearest surface point lies in that joint's part, and expressed
   in the joint's frame (inverse_bind applied). `skeleton` may be NULL (it is not used yet; when
   given, its view is checked). Bad skins (NULL arrays, NaN/Inf, indices out of range, a
   vertex_count that is not the surface's, influences 0 or > 8, cycles, an inverse bind with shear
   or non-uniform scale): CA_ERROR_INVALID_INPUT and nothing returned. The result copies what it
   needs: it outlives `set`. */
CA_API ca_status ca_bone_colliders_build(ca_context* ctx, const ca_candidate_set* set,
                                         const ca_skeleton_view* skeleton, const ca_skin_view* skin,
                                         const ca_bone_collider_options* options, ca_bone_colliders** out);
CA_API void ca_bone_colliders_destroy(ca_bone_colliders* colliders);
CA_API size_t ca_bone_colliders_count(const ca_bone_colliders* colliders);
CA_API const uint32_t* ca_bone_colliders_joints(const ca_bone_colliders* colliders); /* joint of each, ascending */
/* Placement of collider `index` in ITS JOINT'S frame (ca_proxy_placement's conventions; kind
   CA_PROXY_SPHERE or CA_PROXY_CAPSULE). */
CA_API ca_status ca_bone_colliders_placement(const ca_bone_colliders* colliders, size_t index,
                                             ca_proxy_placement* placement);

typedef struct ca_bone_collider_stats {
    uint32_t struct_size;           /* set by the caller: sizeof(ca_bone_collider_stats) */
    double contained_fraction;      /* fresh surface samples held by their part's collider, over all
                                       parts that have one (conservative: 1) */
    double union_volume, outside_volume;  /* Monte Carlo: the colliders' union and its part outside the
                                             shape, caller's units cubed (surface frame) */
    double neighbour_overlap;       /* sum over colliders of the overlap volume with the parent's */
    uint64_t joints_with_collider;
    uint64_t joints_skipped;        /* joints that dominate some of the surface but got no collider */
    double time_s;
} ca_bone_collider_stats;
CA_API ca_status ca_bone_colliders_stats(const ca_bone_colliders* colliders, ca_bone_collider_stats* stats);
/* Per collider (count entries): the fraction of its part's fresh samples it holds (0..1), and the
   volume of its overlap with its parent's collider (the nearest ancestor joint that has one; 0 for
   none), caller's units cubed. */
CA_API const double* ca_bone_colliders_contained(const ca_bone_colliders* colliders);
CA_API const double* ca_bone_colliders_overlap(const ca_bone_colliders* colliders);

#ifdef __cplusplus
}
#endif
#undef CA_DEFINE_INIT_
#endif /* COVERAGE_AXIS_H */

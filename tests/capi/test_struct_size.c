/* test_struct_size.c: the ABI's growth rule, compiled as C99. A caller built against the ABI 1
 * layouts (declared here as they were published) is accepted and gets the defaults for the
 * fields it does not have; output structs are written only up to the caller's struct_size (a
 * canary after a short struct stays intact); sizes the library never published are refused
 * with CA_ERROR_STRUCT_SIZE and a message; ca_*_defaults writes only the caller's size; a
 * selection keeps its candidate set alive after the set's handle is destroyed. */
#include "capi_check.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

/* ---- the layouts of ABI 1 (ca_context_desc, ca_surface_view, ca_select_options, ca_select_stats,
   ca_connect_options and ca_skeleton_stats grew in ABI 2) ---- */
typedef struct v1_context_desc {
    uint32_t struct_size;
    ca_alloc_fn alloc;
    ca_free_fn free;
    void* alloc_user;
    ca_log_fn log;
    void* log_user;
    ca_progress_fn progress;
    void* progress_user;
    int32_t threads;
} v1_context_desc;

typedef struct v1_surface_view {
    uint32_t struct_size;
    const double* positions;
    size_t vertex_count, position_stride;
    const uint32_t* triangles;
    size_t triangle_count, triangle_stride;
    const double* normals;
    size_t normal_stride;
} v1_surface_view;

typedef struct v1_select_stats {
    uint32_t struct_size;
    int32_t proven_optimal;
    int32_t solver;
    double objective, lower_bound, gap, delta_absolute, time_reduce_s, time_solve_s, time_total_s;
    uint64_t rows_before, cols_before, rows_after, cols_after, forced, components, probes, parts;
    double scale_used;
} v1_select_stats;

typedef struct v1_select_options {
    uint32_t struct_size;
    int32_t dilation;
    double delta, scale;
    int32_t solver;
    double time_limit_s;
    int32_t skip_uncoverable;
    const uint8_t *ignorable_samples, *forced_in, *forced_out;
    uint32_t target_count;
    double target_tolerance;
    uint32_t divide_threshold;
    int32_t effort;
} v1_select_options;

/* ca_select_options as first published in ABI 2, before probe_fit was appended */
typedef struct v2_first_select_options {
    v1_select_options v1;
    double target_error;
} v2_first_select_options;

/* ca_select_stats as first published in ABI 2, before hd_reached was appended */
typedef struct v2_first_select_stats {
    v1_select_stats v1;
    double time_coverage_s;
    uint64_t cbc_components, rowgen_rounds;
} v2_first_select_stats;

/* the last ABI 2 layouts of the structs that gained counts in ABI 3 */
typedef struct v2_surface_view {
    v1_surface_view v1;
    int32_t point_normals;
} v2_surface_view;

typedef struct v2_select_options {
    v2_first_select_options v2_first;
    int32_t probe_fit;
} v2_select_options;

typedef struct v1_connect_options {
    uint32_t struct_size;
    int32_t method, remove_outside, fill_holes, reconnect;
} v1_connect_options;

typedef struct v1_skeleton_stats {
    uint32_t struct_size;
    uint64_t vertices, edges, faces, components, isolated;
    int64_t betti1;
    double time_s;
    int32_t method;
} v1_skeleton_stats;

/* ca_candidate_options as last published in ABI 2 (ABI 3 appended after its tail padding) */
typedef struct v2_candidate_options {
    uint32_t struct_size;
    int32_t generator;
    uint32_t cover_samples, voronoi_samples, random_candidates;
    uint64_t seed;
    uint32_t connect_samples;
} v2_candidate_options;

/* ca_skeleton_stats as last published in ABI 2 */
typedef struct v2_skeleton_stats {
    v1_skeleton_stats v1;
    double fit_time_s, fit_error_before, fit_error_after;
    uint64_t fit_uncovered;
    int32_t fitted;
    int64_t genus;
    uint64_t thin_handles;
} v2_skeleton_stats;

#define CANARY 0xA5
static int canary_intact(const unsigned char* p, size_t n) {
    size_t i;
    for (i = 0; i < n; ++i)
        if (p[i] != CANARY) return 0;
    return 1;
}

static int progress_calls = 0, progress_rule_broken = 0;
static char last_stage[64];
/* Counts the calls and checks the throttle's rule when user is non-NULL: a call is either the
   first of its stage or has fraction 1. */
static int32_t count_progress(void* user, const char* stage, double f) {
    const int new_stage = strcmp(stage, last_stage) != 0;
    if (user && !new_stage && f < 1) progress_rule_broken = 1;
    strncpy(last_stage, stage, sizeof last_stage - 1);
    ++progress_calls;
    return 0;
}

/* Runs step 1 on the box with a context made from desc (of any layout); the progress count. */
static int box_progress_calls(const void* desc) {
    ca_context* ctx = NULL;
    ca_candidate_set* set = NULL;
    ca_surface_view v = box_view();
    ca_candidate_options o;
    ca_candidate_options_init(&o);
    o.cover_samples = 300;
    o.voronoi_samples = 600;
    progress_calls = 0;
    last_stage[0] = '\0';
    if (ca_context_create((const ca_context_desc*)desc, &ctx) != CA_OK) return -1;
    if (ca_candidates(ctx, &v, &o, &set) != CA_OK) progress_calls = -2;
    ca_candidate_set_destroy(set);
    ca_context_destroy(ctx);
    return progress_calls;
}

static void test_old_input_struct(void) {
    /* a v1 desc followed by bytes that would be an invalid progress_interval_s (NaN) if read */
    struct { v1_context_desc d; unsigned char tail[32]; } old;
    ca_context_desc now;
    int calls_v1, calls_v2;
    CHECK(sizeof(v1_context_desc) < sizeof(ca_context_desc));
    memset(&old, 0xFF, sizeof old);
    memset(&old.d, 0, sizeof old.d);
    old.d.struct_size = (uint32_t)sizeof(v1_context_desc);
    old.d.progress = count_progress;
    old.d.threads = 1;
    calls_v1 = box_progress_calls(&old);
    CHECK(calls_v1 > 0);
    /* the same with the current layout and its default interval (every update) */
    ca_context_desc_init(&now);
    CHECK(now.struct_size == sizeof now && now.progress_interval_s == 0 && now.threads == 0 && now.progress == NULL);
    now.progress = count_progress;
    now.threads = 1;
    calls_v2 = box_progress_calls(&now);
    CHECK(calls_v2 == calls_v1);
    /* a long interval: only a stage's first call and calls with fraction 1 come */
    now.progress_interval_s = 1e6;
    now.progress_user = &now;
    progress_rule_broken = 0;
    CHECK(box_progress_calls(&now) > 0 && progress_calls <= calls_v2 && !progress_rule_broken);
    now.progress_interval_s = -1;
    CHECK(box_progress_calls(&now) == -1);
}

static void test_defaults_write_only_the_callers_size(void) {
    struct { v1_context_desc d; unsigned char tail[16]; } old;
    struct { ca_select_options o; unsigned char tail[16]; } cur;
    ca_select_options ref;
    memset(&old, CANARY, sizeof old);
    CHECK(ca_context_desc_defaults((ca_context_desc*)(void*)&old, (uint32_t)sizeof old.d) == CA_OK);
    CHECK(old.d.struct_size == sizeof old.d && old.d.threads == 0 && old.d.progress == NULL);
    CHECK(canary_intact(old.tail, sizeof old.tail));
    /* unknown sizes: refused, nothing written */
    memset(&cur, CANARY, sizeof cur);
    CHECK(ca_select_options_defaults(&cur.o, 4) == CA_ERROR_STRUCT_SIZE);
    CHECK(ca_select_options_defaults(&cur.o, (uint32_t)sizeof cur.o + 8) == CA_ERROR_STRUCT_SIZE);
    CHECK(canary_intact((const unsigned char*)&cur, sizeof cur));
    CHECK(ca_select_options_defaults(NULL, (uint32_t)sizeof cur.o) == CA_ERROR_NULL_POINTER);
    /* the inline init and the exported defaults agree */
    CHECK(ca_select_options_defaults(&cur.o, (uint32_t)sizeof cur.o) == CA_OK && canary_intact(cur.tail, sizeof cur.tail));
    ca_select_options_init(&ref);
    CHECK(ref.struct_size == sizeof ref && ref.delta == 0.02 && ref.divide_threshold == 100000);
    CHECK(cur.o.delta == ref.delta && cur.o.scale == ref.scale && cur.o.time_limit_s == ref.time_limit_s &&
          cur.o.target_tolerance == ref.target_tolerance && cur.o.effort == ref.effort && cur.o.forced_in == NULL);
}

static void test_sizes_refused(void) {
    ca_context* ctx = NULL;
    ca_context_desc d;
    ca_candidate_set* set = NULL;
    ca_surface_view v = box_view();
    ca_candidate_options o;
    ca_context_desc_init(&d);
    d.struct_size = 4; /* smaller than the first published size */
    CHECK(ca_context_create(&d, &ctx) == CA_ERROR_STRUCT_SIZE && ctx == NULL);
    d.struct_size = (uint32_t)sizeof(v1_context_desc) + 4; /* between two published sizes */
    if (d.struct_size != sizeof d) CHECK(ca_context_create(&d, &ctx) == CA_ERROR_STRUCT_SIZE && ctx == NULL);
    d.struct_size = (uint32_t)sizeof d + 8; /* a later ABI than this library */
    CHECK(ca_context_create(&d, &ctx) == CA_ERROR_STRUCT_SIZE && ctx == NULL);
    CHECK(ca_context_create(NULL, &ctx) == CA_OK);
    ca_candidate_options_init(&o);
    o.struct_size = 8;
    CHECK(ca_candidates(ctx, &v, &o, &set) == CA_ERROR_STRUCT_SIZE && set == NULL);
    /* the message names the struct, the size given and the sizes accepted */
    CHECK(strstr(ca_context_last_error(ctx), "ca_candidate_options.struct_size is 8") != NULL);
    CHECK(strstr(ca_context_last_error(ctx), "accepts") != NULL);
    /* each size with the ABI version that published it */
    {
        ca_select_options so;
        ca_selection* sel = NULL;
        CHECK(ca_candidates(ctx, &v, NULL, &set) == CA_OK);
        ca_select_options_init(&so);
        so.struct_size = 8;
        CHECK(ca_select(ctx, set, &so, &sel) == CA_ERROR_STRUCT_SIZE && sel == NULL);
        CHECK(strstr(ca_context_last_error(ctx), " (ABI 1), ") != NULL);
        CHECK(strstr(ca_context_last_error(ctx), " (ABI 3)") != NULL);
        ca_candidate_set_destroy(set);
    }
    ca_context_destroy(ctx);
}

static void test_old_output_struct_and_lifetimes(void) {
    ca_context* ctx = NULL;
    ca_candidate_set* set = NULL;
    ca_selection* sel = NULL;
    ca_skeleton* sk = NULL;
    ca_select_stats full;
    struct { v1_select_stats s; unsigned char tail[32]; } old;
    struct { ca_skeleton_stats s; unsigned char tail[16]; } ks;
    const double samples[] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0};
    const double centers[] = {0.5, 0, 0, 2.5, 0, 0};
    const double radii[] = {0.6, 0.6};
    CHECK(ca_context_create(NULL, &ctx) == CA_OK);
    CHECK(ca_candidates_from_arrays(ctx, samples, 4, 0, centers, 0, radii, 0, 2, 1.0, &set) == CA_OK);
    CHECK(ca_select(ctx, set, NULL, &sel) == CA_OK);

    full.struct_size = sizeof full;
    CHECK(ca_selection_stats(sel, &full) == CA_OK && full.objective == 2 && full.struct_size == sizeof full);
    memset(&old, CANARY, sizeof old);
    old.s.struct_size = (uint32_t)sizeof old.s;
    CHECK(ca_selection_stats(sel, (ca_select_stats*)(void*)&old) == CA_OK);
    CHECK(old.s.struct_size == sizeof old.s);
    CHECK(canary_intact(old.tail, sizeof old.tail));
    CHECK(old.s.objective == full.objective && old.s.proven_optimal == full.proven_optimal &&
          old.s.components == full.components && old.s.scale_used == full.scale_used);
    old.s.struct_size = 8;
    CHECK(ca_selection_stats(sel, (ca_select_stats*)(void*)&old) == CA_ERROR_STRUCT_SIZE);
    CHECK(canary_intact(old.tail, sizeof old.tail));

    /* the set's handle goes first: the selection keeps the set alive, connect still works */
    CHECK(ca_connect(ctx, set, sel, NULL, &sk) == CA_OK);
    ca_candidate_set_destroy(set);
    CHECK(ca_selection_count(sel) == 2 && ca_selection_centers(sel)[3] == 2.5);
    ca_selection_destroy(sel); /* frees the set too (a leak checker would see it otherwise) */
    CHECK(ca_skeleton_vertex_count(sk) == 2); /* a skeleton outlives both */
    memset(&ks, CANARY, sizeof ks);
    ks.s.struct_size = (uint32_t)sizeof ks.s;
    CHECK(ca_skeleton_stats_get(sk, &ks.s) == CA_OK && ks.s.vertices == 2 && canary_intact(ks.tail, sizeof ks.tail));
    ca_skeleton_destroy(sk);
    ca_context_destroy(ctx);
}

/* An ABI 1 surface view (no point_normals field) is accepted: the field takes its default
   (a point_normals read past the caller's size would be -1 and refused). */
static void test_old_surface_view(void) {
    ca_context* ctx = NULL;
    ca_candidate_set* set = NULL;
    const ca_surface_view cur = box_view();
    struct { v1_surface_view v; unsigned char tail[16]; } old;
    memset(&old, 0xFF, sizeof old);
    old.v.struct_size = (uint32_t)sizeof old.v;
    old.v.positions = cur.positions;
    old.v.vertex_count = cur.vertex_count;
    old.v.position_stride = 0;
    old.v.triangles = cur.triangles;
    old.v.triangle_count = cur.triangle_count;
    old.v.triangle_stride = 0;
    old.v.normals = NULL;
    old.v.normal_stride = 0;
    CHECK(ca_context_create(NULL, &ctx) == CA_OK);
    CHECK(ca_candidates(ctx, (const ca_surface_view*)(void*)&old, NULL, &set) == CA_OK && set != NULL);
    ca_candidate_set_destroy(set);
    ca_context_destroy(ctx);
}

/* ABI 1 connect options (no fit field: not fitted) and skeleton stats on the box; the current
   layout with fit on fits the balls and reports it. */
static void test_connect_layouts(void) {
    ca_context* ctx = NULL;
    ca_candidate_set* set = NULL;
    ca_selection* sel = NULL;
    ca_skeleton* sk = NULL;
    ca_surface_view v = box_view();
    struct { v1_connect_options o; unsigned char tail[16]; } old;
    struct { v1_skeleton_stats s; unsigned char tail[64]; } oks;
    ca_connect_options cop;
    ca_skeleton_stats ks;
    CHECK(ca_context_create(NULL, &ctx) == CA_OK);
    CHECK(ca_candidates(ctx, &v, NULL, &set) == CA_OK);
    CHECK(ca_select(ctx, set, NULL, &sel) == CA_OK);
    memset(&old, 0xFF, sizeof old); /* a fit field read past the size would be -1: on */
    old.o.struct_size = (uint32_t)sizeof old.o;
    old.o.method = CA_CONNECT_AUTO;
    old.o.remove_outside = old.o.fill_holes = old.o.reconnect = 1;
    CHECK(ca_connect(ctx, set, sel, (const ca_connect_options*)(void*)&old, &sk) == CA_OK);
    ks.struct_size = sizeof ks;
    CHECK(ca_skeleton_stats_get(sk, &ks) == CA_OK && ks.fitted == 0 && ks.fit_time_s == 0);
    CHECK(ks.genus == 0 && ks.thin_handles == 0); /* a closed box */
    memset(&oks, CANARY, sizeof oks);
    oks.s.struct_size = (uint32_t)sizeof oks.s;
    CHECK(ca_skeleton_stats_get(sk, (ca_skeleton_stats*)(void*)&oks) == CA_OK && oks.s.vertices == ks.vertices &&
          canary_intact(oks.tail, sizeof oks.tail));
    ca_skeleton_destroy(sk);
    sk = NULL;
    ca_connect_options_init(&cop);
    CHECK(cop.fit == CA_FIT_AUTO && cop.fit_iterations == 10);
    cop.fit = 1;
    CHECK(ca_connect(ctx, set, sel, &cop, &sk) == CA_OK);
    CHECK(ca_skeleton_stats_get(sk, &ks) == CA_OK && ks.fitted == 1 && ks.fit_error_after <= ks.fit_error_before);
    ca_skeleton_destroy(sk);
    sk = NULL;
    cop.fit_iterations = -1;
    CHECK(ca_connect(ctx, set, sel, &cop, &sk) == CA_ERROR_INVALID_ARGUMENT && sk == NULL);
    ca_selection_destroy(sel);
    ca_candidate_set_destroy(set);
    ca_context_destroy(ctx);
}

/* ABI 1 select options (no target_error: off), the first ABI 2 select options (no probe_fit: off)
   and the first ABI 2 select stats are accepted; probe_fit defaults to 0 and values other than 0
   and 1 are CA_ERROR_INVALID_ARGUMENT naming it; target_error is checked: NaN, negative, with
   target_count, with the scale dilation, or on a set from caller arrays (no surface) are
   CA_ERROR_INVALID_ARGUMENT naming target_error. */
static void test_select_layouts(void) {
    ca_context* ctx = NULL;
    ca_candidate_set* set = NULL;
    ca_selection* sel = NULL;
    ca_surface_view v = box_view();
    struct { v1_select_options o; unsigned char tail[16]; } old;
    struct { v2_first_select_stats s; unsigned char tail[16]; } ss;
    struct { v2_first_select_options o; unsigned char tail[16]; } old2;
    ca_select_stats at_old2;
    ca_select_stats full;
    ca_select_options o;
    const double samples[] = {0, 0, 0, 1, 0, 0};
    const double centers[] = {0.5, 0, 0};
    const double radii[] = {0.6};
    CHECK(ca_context_create(NULL, &ctx) == CA_OK);
    CHECK(ca_candidates(ctx, &v, NULL, &set) == CA_OK);
    ca_select_options_init(&o);
    CHECK(o.target_error == 0 && sizeof(v1_select_options) < sizeof o);
    memcpy(&old.o, &o, sizeof old.o);
    memset(old.tail, 0xFF, sizeof old.tail); /* a target_error read past the size would be NaN */
    old.o.struct_size = (uint32_t)sizeof old.o;
    CHECK(ca_select(ctx, set, (const ca_select_options*)(void*)&old, &sel) == CA_OK);
    full.struct_size = sizeof full;
    CHECK(ca_selection_stats(sel, &full) == CA_OK && full.hd_reached == -1);
    memset(&ss, CANARY, sizeof ss);
    ss.s.v1.struct_size = (uint32_t)sizeof ss.s;
    CHECK(ca_selection_stats(sel, (ca_select_stats*)(void*)&ss) == CA_OK && ss.s.rowgen_rounds == full.rowgen_rounds &&
          canary_intact(ss.tail, sizeof ss.tail));
    ca_selection_destroy(sel);
    sel = NULL;
    /* the first ABI 2 layout: a probe_fit read past its size would be -1 (refused) */
    CHECK(o.probe_fit == 0 && sizeof(v2_first_select_options) < sizeof o &&
          sizeof(v1_select_options) < sizeof(v2_first_select_options));
    memcpy(&old2.o, &o, sizeof old2.o);
    memset(old2.tail, 0xFF, sizeof old2.tail);
    old2.o.v1.struct_size = (uint32_t)sizeof old2.o;
    old2.o.target_error = 50; /* reached at the first probe: the search runs, cheaply */
    CHECK(ca_select(ctx, set, (const ca_select_options*)(void*)&old2, &sel) == CA_OK);
    at_old2.struct_size = sizeof at_old2;
    CHECK(ca_selection_stats(sel, &at_old2) == CA_OK && at_old2.hd_reached >= 0 && at_old2.hd_reached <= 50);
    ca_selection_destroy(sel);
    sel = NULL;
    o.probe_fit = 2;
    CHECK(ca_select(ctx, set, &o, &sel) == CA_ERROR_INVALID_ARGUMENT && sel == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "probe_fit") != NULL);
    o.probe_fit = -1;
    CHECK(ca_select(ctx, set, &o, &sel) == CA_ERROR_INVALID_ARGUMENT && sel == NULL);
    o.probe_fit = 0;
    o.target_error = 0.0 / 0.0;
    CHECK(ca_select(ctx, set, &o, &sel) == CA_ERROR_INVALID_ARGUMENT && sel == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "target_error") != NULL);
    o.target_error = -1;
    CHECK(ca_select(ctx, set, &o, &sel) == CA_ERROR_INVALID_ARGUMENT && sel == NULL);
    o.target_error = 2;
    o.target_count = 10;
    CHECK(ca_select(ctx, set, &o, &sel) == CA_ERROR_INVALID_ARGUMENT && sel == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "target_count") != NULL);
    o.target_count = 0;
    o.dilation = CA_DILATE_SCALE;
    CHECK(ca_select(ctx, set, &o, &sel) == CA_ERROR_INVALID_ARGUMENT && sel == NULL);
    o.dilation = CA_DILATE_OFFSET;
    ca_candidate_set_destroy(set);
    set = NULL;
    CHECK(ca_candidates_from_arrays(ctx, samples, 2, 0, centers, 0, radii, 0, 1, 1.0, &set) == CA_OK);
    CHECK(ca_select(ctx, set, &o, &sel) == CA_ERROR_INVALID_ARGUMENT && sel == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "target_error") != NULL);
    ca_candidate_set_destroy(set);
    ca_context_destroy(ctx);
}

/* n points on the unit sphere (a Fibonacci spiral) with their outward normals */
#define SPHERE_POINTS 400
static void sphere_cloud(double* pts, double* nrm) {
    int i;
    for (i = 0; i < SPHERE_POINTS; ++i) {
        const double z = 1 - (2 * i + 1) / (double)SPHERE_POINTS, r = sqrt(1 - z * z), a = 2.399963229728653 * i;
        pts[3 * i] = nrm[3 * i] = r * cos(a);
        pts[3 * i + 1] = nrm[3 * i + 1] = r * sin(a);
        pts[3 * i + 2] = nrm[3 * i + 2] = z;
    }
}

/* Whether the selection holds candidate ball i. */
static int selects(const ca_selection* sel, uint32_t i) {
    size_t k;
    for (k = 0; k < ca_selection_count(sel); ++k)
        if (ca_selection_indices(sel)[k] == i) return 1;
    return 0;
}

/* ABI 3 counts: every array the library reads has one. A count that does not match is
   CA_ERROR_INVALID_INPUT naming the array; a set array with a count of 0, from a struct that has
   the count, too (it was not filled in); a count without its array is CA_ERROR_NULL_POINTER. A
   caller of ABI 2 has no counts: its normals and masks have the implied lengths, as before. */
static void test_counts(void) {
    static double pts[3 * SPHERE_POINTS], nrm[3 * SPHERE_POINTS];
    ca_context* ctx = NULL;
    ca_candidate_set* set = NULL;
    ca_selection* sel = NULL;
    ca_surface_view v;
    ca_candidate_options co;
    struct { v2_surface_view v; unsigned char tail[16]; } old;
    struct { v2_select_options o; unsigned char tail[32]; } old_select;
    ca_select_options so;
    uint8_t mask[4096];
    size_t balls, balls_old;
    sphere_cloud(pts, nrm);
    CHECK(ca_context_create(NULL, &ctx) == CA_OK);
    ca_candidate_options_init(&co);
    co.cover_samples = 100;
    co.voronoi_samples = 400;
    ca_surface_view_init(&v);
    CHECK(v.normal_count == 0 && sizeof(v2_surface_view) < sizeof v);
    v.positions = pts;
    v.vertex_count = SPHERE_POINTS;
    v.normals = nrm;
    /* the count not filled in, too short, too long */
    CHECK(ca_candidates(ctx, &v, &co, &set) == CA_ERROR_INVALID_INPUT && set == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "normal_count") != NULL);
    v.normal_count = SPHERE_POINTS - 1;
    CHECK(ca_candidates(ctx, &v, &co, &set) == CA_ERROR_INVALID_INPUT && set == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "normals") != NULL);
    v.normal_count = SPHERE_POINTS + 1;
    CHECK(ca_candidates(ctx, &v, &co, &set) == CA_ERROR_INVALID_INPUT && set == NULL);
    v.point_normals = CA_POINT_NORMALS_ESTIMATE; /* refused even where the normals are not used */
    CHECK(ca_candidates(ctx, &v, &co, &set) == CA_ERROR_INVALID_INPUT && set == NULL);
    v.point_normals = CA_POINT_NORMALS_TRUSTED;
    v.normals = NULL;
    CHECK(ca_candidates(ctx, &v, &co, &set) == CA_ERROR_NULL_POINTER && set == NULL);
    /* the right count; then an ABI 2 view, whose normals count vertex_count */
    v.normals = nrm;
    v.normal_count = SPHERE_POINTS;
    CHECK(ca_candidates(ctx, &v, &co, &set) == CA_OK && ca_candidate_set_normals(set) == CA_NORMALS_GIVEN);
    balls = ca_candidate_set_count(set);
    ca_candidate_set_destroy(set);
    set = NULL;
    memset(&old, 0xFF, sizeof old); /* a normal_count read past the size would be huge */
    memcpy(&old.v, &v, sizeof old.v);
    old.v.v1.struct_size = (uint32_t)sizeof old.v;
    CHECK(ca_candidates(ctx, (const ca_surface_view*)(void*)&old, &co, &set) == CA_OK);
    balls_old = ca_candidate_set_count(set);
    CHECK(balls_old == balls && balls > 0 && ca_candidate_set_normals(set) == CA_NORMALS_GIVEN);

    /* masks: one entry per candidate ball (forced_in, forced_out) or per sample */
    memset(mask, 0, sizeof mask);
    CHECK(balls + 1 <= sizeof mask && ca_candidate_set_sample_count(set) + 1 <= sizeof mask);
    ca_select_options_init(&so);
    CHECK(so.forced_in_count == 0 && so.forced_out_count == 0 && so.ignorable_samples_count == 0);
    so.forced_out = mask;
    CHECK(ca_select(ctx, set, &so, &sel) == CA_ERROR_INVALID_INPUT && sel == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "forced_out_count") != NULL);
    so.forced_out_count = balls - 1;
    CHECK(ca_select(ctx, set, &so, &sel) == CA_ERROR_INVALID_INPUT && sel == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "forced_out") != NULL);
    so.forced_out_count = balls + 1;
    CHECK(ca_select(ctx, set, &so, &sel) == CA_ERROR_INVALID_INPUT && sel == NULL);
    so.forced_out = NULL;
    CHECK(ca_select(ctx, set, &so, &sel) == CA_ERROR_NULL_POINTER && sel == NULL);
    so.forced_out_count = 0;
    so.ignorable_samples = mask;
    so.ignorable_samples_count = ca_candidate_set_sample_count(set) + 1;
    CHECK(ca_select(ctx, set, &so, &sel) == CA_ERROR_INVALID_INPUT && sel == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "ignorable_samples") != NULL);
    so.ignorable_samples_count = ca_candidate_set_sample_count(set);
    so.forced_in = mask;
    so.forced_in_count = balls;
    mask[0] = 1; /* ball 0 forced in; sample 0 ignorable */
    CHECK(ca_select(ctx, set, &so, &sel) == CA_OK && sel != NULL);
    CHECK(selects(sel, 0));
    ca_selection_destroy(sel);
    sel = NULL;
    /* an ABI 2 caller's masks have the set's lengths */
    memset(&old_select, 0xFF, sizeof old_select); /* counts read past the size would be huge */
    memcpy(&old_select.o, &so, sizeof old_select.o);
    old_select.o.v2_first.v1.struct_size = (uint32_t)sizeof old_select.o;
    CHECK(ca_select(ctx, set, (const ca_select_options*)(void*)&old_select, &sel) == CA_OK && sel != NULL);
    CHECK(selects(sel, 0));
    ca_selection_destroy(sel);
    ca_candidate_set_destroy(set);
    ca_context_destroy(ctx);
}

/* ABI 3 (surface balls): an ABI 2 caller's candidate options, whose tail padding holds garbage,
   get surface balls on a flat square (volumetric_only is past its size: the default, off); the
   current layout with volumetric_only finds no candidate there; ABI 2 skeleton stats are written
   up to their size only, and the ABI 3 counts say what the skeleton is made of. */
static void test_surface_ball_layouts(void) {
    static const double square[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    static const uint32_t tris[] = {0, 1, 2, 0, 2, 3};
    ca_context* ctx = NULL;
    ca_candidate_set* set = NULL;
    ca_selection* sel = NULL;
    ca_skeleton* sk = NULL;
    ca_surface_view v;
    ca_candidate_options now;
    ca_skeleton_stats ks;
    struct { v2_candidate_options o; unsigned char tail[16]; } old;
    struct { v2_skeleton_stats s; unsigned char tail[64]; } oks;
    ca_surface_view_init(&v);
    v.positions = square;
    v.vertex_count = 4;
    v.triangles = tris;
    v.triangle_count = 2;
    CHECK(sizeof(v2_candidate_options) <= offsetof(ca_candidate_options, volumetric_only));
    CHECK(ca_context_create(NULL, &ctx) == CA_OK);
    ca_candidate_options_init(&now);
    memset(&old, 0xFF, sizeof old);
    memcpy(&old.o, &now, sizeof old.o);
    old.o.struct_size = (uint32_t)sizeof old.o;
    old.o.cover_samples = 300;
    CHECK(ca_candidates(ctx, &v, (const ca_candidate_options*)(void*)&old, &set) == CA_OK);
    CHECK(ca_select(ctx, set, NULL, &sel) == CA_OK);
    CHECK(ca_connect(ctx, set, sel, NULL, &sk) == CA_OK);
    ks.struct_size = sizeof ks;
    CHECK(ca_skeleton_stats_get(sk, &ks) == CA_OK && ks.surface_balls == ks.vertices && ks.medial_balls == 0 &&
          ks.open_parts == 1 && ks.faces > 0);
    memset(&oks, CANARY, sizeof oks);
    oks.s.v1.struct_size = (uint32_t)sizeof oks.s;
    CHECK(ca_skeleton_stats_get(sk, (ca_skeleton_stats*)(void*)&oks) == CA_OK && oks.s.v1.vertices == ks.vertices &&
          oks.s.thin_handles == ks.thin_handles && canary_intact(oks.tail, sizeof oks.tail));
    ca_skeleton_destroy(sk);
    ca_selection_destroy(sel);
    ca_candidate_set_destroy(set);
    set = NULL;
    now.cover_samples = 300;
    now.volumetric_only = 1;
    CHECK(ca_candidates(ctx, &v, &now, &set) == CA_ERROR_NO_CANDIDATES && set == NULL);
    ca_context_destroy(ctx);
}

int main(void) {
    CHECK(ca_abi_version() == 3 && CA_ABI_VERSION == 3);
    test_old_input_struct();
    test_defaults_write_only_the_callers_size();
    test_sizes_refused();
    test_old_output_struct_and_lifetimes();
    test_connect_layouts();
    test_select_layouts();
    test_old_surface_view();
    test_counts();
    test_surface_ball_layouts();
    printf("test_struct_size: %d checks, %d failed\n", checks, failures);
    return failures ? 1 : 0;
}

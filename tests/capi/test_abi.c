/* test_abi.c: tests of the C ABI, compiled as C99: versions, NULL pointers, struct sizes, bad
 * input (NaN, out-of-range index, empty, flat, too few distinct points), uncoverable samples,
 * copy-out capacity, cancellation and progress, the custom allocator, determinism, and a
 * known answer (the balls of a box lie on its medial axis). */
#include "box_skeleton.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The searches' bisection tolerance in these tests: coarser than the default (1e-4), as none of
   their checks depends on how finely the delta is bisected; fewer probes, each a full solve. */
#define SEARCH_TOLERANCE 1e-2

static void test_versions(void) {
    CHECK(ca_version() == CA_VERSION_NUMBER);
    {
        char text[32];
        snprintf(text, sizeof text, "%d.%d.%d", CA_VERSION_MAJOR, CA_VERSION_MINOR, CA_VERSION_PATCH);
        CHECK(strcmp(ca_version_string(), text) == 0);
    }
    CHECK(ca_abi_version() == CA_ABI_VERSION);
    CHECK(strncmp(ca_status_string(CA_ERROR_NULL_POINTER), "CA_ERROR_NULL_POINTER", 21) == 0);
    CHECK(strcmp(ca_status_string(9999), "unknown ca_status") == 0);
    /* pinned values */
    CHECK(CA_OK == 0 && CA_ERROR_INVALID_INPUT == 4 && CA_ERROR_UNCOVERABLE == 6 && CA_ERROR_NO_CANDIDATES == 13);
}

static void test_null_and_sizes(void) {
    ca_context* ctx = NULL;
    ca_candidate_set* set = (ca_candidate_set*)1;
    ca_surface_view v = box_view();
    ca_candidate_options o = box_options(400);
    ca_context_desc d;

    CHECK(ca_context_create(NULL, NULL) == CA_ERROR_NULL_POINTER);
    ca_context_desc_init(&d);
    d.struct_size = 3;
    CHECK(ca_context_create(&d, &ctx) == CA_ERROR_STRUCT_SIZE && ctx == NULL);
    CHECK(ca_context_create(NULL, &ctx) == CA_OK && ctx != NULL);

    CHECK(ca_candidates(NULL, &v, &o, &set) == CA_ERROR_NULL_POINTER);
    CHECK(set == NULL);
    CHECK(ca_candidates(ctx, NULL, &o, &set) == CA_ERROR_NULL_POINTER && set == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "surface") != NULL);
    CHECK(ca_candidates(ctx, &v, &o, NULL) == CA_ERROR_NULL_POINTER);
    v.positions = NULL;
    CHECK(ca_candidates(ctx, &v, &o, &set) == CA_ERROR_NULL_POINTER && set == NULL);
    v = box_view();
    v.struct_size = 8;
    CHECK(ca_candidates(ctx, &v, &o, &set) == CA_ERROR_STRUCT_SIZE && set == NULL);
    v = box_view();
    o.struct_size = sizeof(o) + 8;
    CHECK(ca_candidates(ctx, &v, &o, &set) == CA_ERROR_STRUCT_SIZE && set == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "struct_size") != NULL);
    o = box_options(400);
    o.generator = 7;
    CHECK(ca_candidates(ctx, &v, &o, &set) == CA_ERROR_INVALID_ARGUMENT && set == NULL);
    v.position_stride = 8; /* smaller than a vertex */
    o = box_options(400);
    CHECK(ca_candidates(ctx, &v, &o, &set) == CA_ERROR_INVALID_ARGUMENT && set == NULL);

    CHECK(ca_select(ctx, NULL, NULL, (ca_selection**)&set) == CA_ERROR_NULL_POINTER);
    CHECK(ca_connect(ctx, NULL, NULL, NULL, NULL) == CA_ERROR_NULL_POINTER);
    /* getters and destroy accept NULL */
    CHECK(ca_candidate_set_count(NULL) == 0 && ca_skeleton_centers(NULL) == NULL);
    ca_candidate_set_destroy(NULL);
    ca_selection_destroy(NULL);
    ca_skeleton_destroy(NULL);
    ca_context_destroy(ctx);
}

static ca_status run_candidates(ca_context* ctx, const double* pos, size_t nv, const uint32_t* tri, size_t nt,
                                const double* normals, ca_candidate_set** out) {
    ca_surface_view v;
    ca_candidate_options o = box_options(400);
    ca_surface_view_init(&v);
    v.positions = pos;
    v.vertex_count = nv;
    v.triangles = tri;
    v.triangle_count = nt;
    v.normals = normals;
    v.normal_count = normals ? nv : 0;
    return ca_candidates(ctx, &v, &o, out);
}

static void test_bad_input(void) {
    ca_context* ctx = NULL;
    ca_candidate_set* set = NULL;
    double v[24];
    uint32_t f[36];
    double pts[300], nrm[300];
    int i;
    CHECK(ca_context_create(NULL, &ctx) == CA_OK);

    memcpy(v, box_v, sizeof v);
    memcpy(f, box_f, sizeof f);
    v[7] = NAN;
    CHECK(run_candidates(ctx, v, 8, f, 12, NULL, &set) == CA_ERROR_INVALID_INPUT && set == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "vertex 2") != NULL);
    v[7] = INFINITY;
    CHECK(run_candidates(ctx, v, 8, f, 12, NULL, &set) == CA_ERROR_INVALID_INPUT && set == NULL);

    memcpy(v, box_v, sizeof v);
    f[17] = 900;
    CHECK(run_candidates(ctx, v, 8, f, 12, NULL, &set) == CA_ERROR_INVALID_INPUT && set == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "triangle 5 references vertex 900 of 8") != NULL);

    /* empty mesh */
    CHECK(run_candidates(ctx, v, 0, NULL, 0, NULL, &set) == CA_ERROR_DEGENERATE_INPUT && set == NULL);
    /* every triangle degenerate */
    memset(f, 0, sizeof f);
    CHECK(run_candidates(ctx, box_v, 8, f, 12, NULL, &set) == CA_ERROR_DEGENERATE_INPUT && set == NULL);
    /* flat (the bottom face of the box only): a sheet, covered by surface balls on it */
    CHECK(run_candidates(ctx, box_v, 8, box_f, 2, NULL, &set) == CA_OK && set != NULL);
    CHECK(ca_candidate_set_count(set) > 0);
    {
        size_t i;
        for (i = 0; set && i < ca_candidate_set_count(set); ++i)
            CHECK(ca_candidate_set_radii(set)[i] == 0 && ca_candidate_set_centers(set)[3 * i + 2] == box_v[2]);
    }
    ca_candidate_set_destroy(set);
    set = NULL;
    /* a point cloud in one plane is refused: it encloses nothing and its normals name no side */
    CHECK(run_candidates(ctx, box_v, 4, NULL, 0, NULL, &set) == CA_ERROR_DEGENERATE_INPUT && set == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "plane") != NULL);

    /* point cloud without normals: estimated (8 box corners are too few for any inner ball) */
    {
    const ca_status st = run_candidates(ctx, box_v, 8, NULL, 0, NULL, &set);
    CHECK((st == CA_OK && ca_candidate_set_normals(set) == CA_NORMALS_ESTIMATED) ||
          (st != CA_OK && set == NULL && ca_context_last_error(ctx)[0] != 0));
    if (set) ca_candidate_set_destroy(set), set = NULL;
    }
    /* point_normals outside CA_POINT_NORMALS_*: refused before anything is read */
    {
    ca_surface_view sv;
    ca_candidate_options o = box_options(400);
    ca_surface_view_init(&sv);
    CHECK(sv.point_normals == CA_POINT_NORMALS_TRUSTED);
    sv.positions = box_v;
    sv.vertex_count = 8;
    sv.point_normals = 3;
    CHECK(ca_candidates(ctx, &sv, &o, &set) == CA_ERROR_INVALID_ARGUMENT && set == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "point_normals") != NULL);
    sv.point_normals = -1;
    CHECK(ca_candidates(ctx, &sv, &o, &set) == CA_ERROR_INVALID_ARGUMENT && set == NULL);
    }
    /* point cloud: 100 points that are copies of 4 distinct points (a tetrahedron) */
    for (i = 0; i < 100; ++i) {
        const int k = i % 4;
        pts[3 * i] = k == 1; pts[3 * i + 1] = k == 2; pts[3 * i + 2] = k == 3;
        nrm[3 * i] = k == 1 ? 1 : -0.5; nrm[3 * i + 1] = k == 2 ? 1 : -0.5; nrm[3 * i + 2] = k == 3 ? 1 : -0.5;
    }
    CHECK(run_candidates(ctx, pts, 100, NULL, 0, nrm, &set) == CA_ERROR_DEGENERATE_INPUT && set == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "5") != NULL);
    /* a NaN normal is refused; a zero normal means "none" (estimated): the cloud is judged on its points */
    nrm[0] = 0.0 / 0.0;
    CHECK(run_candidates(ctx, pts, 100, NULL, 0, nrm, &set) == CA_ERROR_INVALID_INPUT && set == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "normal 0") != NULL);
    nrm[0] = nrm[1] = nrm[2] = 0;
    CHECK(run_candidates(ctx, pts, 100, NULL, 0, nrm, &set) == CA_ERROR_DEGENERATE_INPUT && set == NULL);
    ca_context_destroy(ctx);
}

static void test_arrays_uncoverable_and_copy(void) {
    ca_context* ctx = NULL;
    ca_candidate_set* set = NULL;
    ca_selection* sel = NULL;
    ca_select_options so;
    ca_select_stats stats;
    /* samples on a line; two balls cover the first three, the last is far away */
    const double samples[] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 10, 0, 0};
    const double centers[] = {0.5, 0, 0, 2, 0, 0};
    const double radii[] = {0.6, 0.1};
    double out_c[6], out_r[2];
    size_t count = 0;
    CHECK(ca_context_create(NULL, &ctx) == CA_OK);
    CHECK(ca_candidates_from_arrays(ctx, samples, 4, 0, centers, 0, radii, 0, 2, 1.0, &set) == CA_OK);
    CHECK(ca_candidate_set_count(set) == 2 && ca_candidate_set_sample_count(set) == 4);
    CHECK(fabs(ca_candidate_set_reference_length(set) - 1.0) < 1e-12);
    CHECK(ca_candidate_set_outlier_count(set) == 0 && ca_candidate_set_outlier_count(NULL) == 0);
    CHECK(fabs(ca_candidate_set_centers(set)[3] - 2.0) < 1e-12 && fabs(ca_candidate_set_radii(set)[0] - 0.6) < 1e-12);

    CHECK(ca_candidate_set_copy(set, out_c, out_r, 1, &count) == CA_ERROR_BUFFER_TOO_SMALL && count == 2);
    CHECK(ca_candidate_set_copy(set, out_c, out_r, 2, &count) == CA_OK && count == 2 && fabs(out_r[1] - 0.1) < 1e-12);

    ca_select_options_init(&so);
    so.delta = 0.0;
    CHECK(ca_select(ctx, set, &so, &sel) == CA_ERROR_UNCOVERABLE && sel == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "1 of 4") != NULL);
    CHECK(strstr(ca_context_last_error(ctx), "no inside behind them") != NULL);   /* the reason, and what to do */
    CHECK(strstr(ca_context_last_error(ctx), "skip_uncoverable") != NULL);
    so.skip_uncoverable = 1;
    CHECK(ca_select(ctx, set, &so, &sel) == CA_OK && sel != NULL);
    CHECK(ca_selection_count(sel) == 2);
    CHECK(ca_selection_uncovered_count(sel) == 1 && ca_selection_uncovered(sel)[0] == 3);
    stats.struct_size = 5;
    CHECK(ca_selection_stats(sel, &stats) == CA_ERROR_STRUCT_SIZE);
    stats.struct_size = sizeof stats;
    CHECK(ca_selection_stats(sel, &stats) == CA_OK && stats.proven_optimal == 1 && stats.objective == 2);
    ca_selection_destroy(sel);
    sel = NULL;

    /* bad options */
    ca_select_options_init(&so);
    so.delta = -1;
    CHECK(ca_select(ctx, set, &so, &sel) == CA_ERROR_INVALID_ARGUMENT && sel == NULL);
    ca_select_options_init(&so);
    so.solver = 42;
    CHECK(ca_select(ctx, set, &so, &sel) == CA_ERROR_INVALID_ARGUMENT && sel == NULL);
    ca_select_options_init(&so);
    CHECK(so.effort == CA_EFFORT_FAST);
    so.effort = 9;
    CHECK(ca_select(ctx, set, &so, &sel) == CA_ERROR_INVALID_ARGUMENT && sel == NULL);
    so.effort = CA_EFFORT_PROVE;
    so.skip_uncoverable = 1; /* sample 3 is covered by no ball */
    CHECK(ca_select(ctx, set, &so, &sel) == CA_OK && sel != NULL && ca_selection_count(sel) == 2);
    ca_selection_destroy(sel);
    sel = NULL;
    /* NaN radius */
    {
        const double bad_r[] = {NAN, 0.1};
        ca_candidate_set* bad = NULL;
        CHECK(ca_candidates_from_arrays(ctx, samples, 4, 0, centers, 0, bad_r, 0, 2, 1.0, &bad) == CA_ERROR_INVALID_INPUT && bad == NULL);
    }
    ca_candidate_set_destroy(set);
    ca_context_destroy(ctx);
}

static int32_t cancel_at_second_call(void* user, const char* stage, double f) {
    int* calls = (int*)user;
    (void)stage;
    (void)f;
    return ++*calls >= 2;
}

static void test_cancel(void) {
    ca_context* ctx = NULL;
    ca_candidate_set* set = NULL;
    ca_surface_view v = box_view();
    ca_candidate_options o = box_options(400);
    ca_context_desc d;
    int calls = 0;

    CHECK(ca_context_create(NULL, &ctx) == CA_OK);
    ca_context_request_cancel(ctx);
    CHECK(ca_candidates(ctx, &v, &o, &set) == CA_ERROR_CANCELLED && set == NULL);
    ca_context_clear_cancel(ctx);
    CHECK(ca_candidates(ctx, &v, &o, &set) == CA_OK && set != NULL);
    ca_candidate_set_destroy(set);
    set = NULL;
    ca_context_destroy(ctx);

    ca_context_desc_init(&d);
    d.progress = cancel_at_second_call;
    d.progress_user = &calls;
    CHECK(ca_context_create(&d, &ctx) == CA_OK);
    CHECK(ca_candidates(ctx, &v, &o, &set) == CA_ERROR_CANCELLED && set == NULL);
    CHECK(calls >= 2);
    ca_context_destroy(ctx);
}

static long live_blocks = 0, total_blocks = 0;
static void* counting_alloc(void* user, size_t n) {
    (void)user;
    ++live_blocks;
    ++total_blocks;
    return malloc(n);
}
static void counting_free(void* user, void* p) {
    (void)user;
    if (p) --live_blocks;
    free(p);
}

/* The whole pipeline on the box: known answer and determinism. */
static void test_box_pipeline(void) {
    ca_context* ctx = NULL;
    BoxSkeleton b;
    ca_surface_view v = box_view();
    ca_candidate_options o = box_options(400);
    ca_skeleton_stats ks;
    ca_context_desc d;
    size_t i, n;
    const double* c;
    const double* r;
    double first[3 * 64];
    size_t first_n;

    ca_context_desc_init(&d);
    d.alloc = counting_alloc;
    d.free = counting_free;
    CHECK(ca_context_create(&d, &ctx) == CA_OK);
    CHECK(box_skeleton(ctx, &o, &b) == CA_OK);
    CHECK(ca_candidate_set_count(b.set) > 10);
    n = ca_skeleton_vertex_count(b.sk);
    CHECK(n >= 2 && n <= 64);
    c = ca_skeleton_centers(b.sk);
    r = ca_skeleton_radii(b.sk);
    for (i = 0; i < n; ++i) {
        /* inside the box and a medial ball: its radius is its distance to the nearest face
           (up to the sampling: Voronoi radii are distances to the nearest sample) */
        const double x = c[3 * i], y = c[3 * i + 1], z = c[3 * i + 2];
        double dmin = x;
        if (2 - x < dmin) dmin = 2 - x;
        if (y < dmin) dmin = y;
        if (1 - y < dmin) dmin = 1 - y;
        if (z < dmin) dmin = z;
        if (1 - z < dmin) dmin = 1 - z;
        CHECK(dmin > 0);
        CHECK(r[i] >= dmin - 1e-9 && r[i] <= dmin + 0.1);
    }
    ks.struct_size = sizeof ks;
    CHECK(ca_skeleton_stats_get(b.sk, &ks) == CA_OK && ks.vertices == n && ks.components >= 1);
    first_n = n;
    memcpy(first, c, 3 * n * sizeof(double));

    /* a selection from another set is refused */
    {
        ca_candidate_set* other = NULL;
        ca_skeleton* bad = NULL;
        CHECK(ca_candidates(ctx, &v, &o, &other) == CA_OK);
        CHECK(ca_connect(ctx, other, b.sel, NULL, &bad) == CA_ERROR_INVALID_ARGUMENT && bad == NULL);
        ca_candidate_set_destroy(other);
    }
    box_skeleton_destroy(&b);
    CHECK(total_blocks > 0 && live_blocks == 0);

    /* the same seed gives the same skeleton */
    CHECK(box_skeleton(ctx, &o, &b) == CA_OK);
    CHECK(ca_skeleton_vertex_count(b.sk) == first_n);
    if (ca_skeleton_vertex_count(b.sk) == first_n)
        CHECK(memcmp(first, ca_skeleton_centers(b.sk), 3 * first_n * sizeof(double)) == 0);
    box_skeleton_destroy(&b);
    CHECK(live_blocks == 0);
    ca_context_destroy(ctx);
}

/* Connection routes and the target size. */
static void test_routes_and_target(void) {
    ca_context* ctx = NULL;
    ca_candidate_set* set = NULL;
    ca_selection* sel = NULL;
    ca_selection* small = NULL;
    ca_skeleton* sk = NULL;
    ca_surface_view v = box_view();
    ca_candidate_options o = box_options(400);
    ca_connect_options cop;
    ca_select_options so;
    ca_select_stats full_stats, small_stats;
    ca_skeleton_stats ks;
    int32_t method;
    CHECK(ca_context_create(NULL, &ctx) == CA_OK);
    CHECK(ca_candidates(ctx, &v, &o, &set) == CA_OK);
    CHECK(ca_select(ctx, set, NULL, &sel) == CA_OK);
    for (method = CA_CONNECT_POWER; method <= CA_CONNECT_AUTO; ++method) {
        ca_connect_options_init(&cop);
        cop.method = method;
        sk = NULL;
        CHECK(ca_connect(ctx, set, sel, &cop, &sk) == CA_OK);
        ks.struct_size = sizeof ks;
        CHECK(ca_skeleton_stats_get(sk, &ks) == CA_OK);
        CHECK(ks.components == 1 && ks.betti1 == 0);
        CHECK(ks.method == (method == CA_CONNECT_AUTO ? CA_CONNECT_MEDIAL : method));
        ca_skeleton_destroy(sk);
    }
    ca_connect_options_init(&cop);
    cop.method = 9;
    sk = NULL;
    CHECK(ca_connect(ctx, set, sel, &cop, &sk) == CA_ERROR_INVALID_ARGUMENT && sk == NULL);

    /* target size: at most K balls, and it needs a larger delta than the default */
    full_stats.struct_size = sizeof full_stats;
    CHECK(ca_selection_stats(sel, &full_stats) == CA_OK);
    ca_select_options_init(&so);
    so.target_count = (uint32_t)(full_stats.objective > 2 ? full_stats.objective - 2 : 1);
    so.target_tolerance = SEARCH_TOLERANCE;
    CHECK(ca_select(ctx, set, &so, &small) == CA_OK);
    small_stats.struct_size = sizeof small_stats;
    CHECK(ca_selection_stats(small, &small_stats) == CA_OK);
    CHECK(ca_selection_count(small) <= so.target_count);
    CHECK(small_stats.delta_absolute > full_stats.delta_absolute && small_stats.probes > 1);
    CHECK(small_stats.hd_reached > 0); /* a mesh: the lowest-HD search measured it */
    so.target_tolerance = 0;
    ca_selection_destroy(small);
    small = NULL;
    CHECK(ca_select(ctx, set, &so, &small) == CA_ERROR_INVALID_ARGUMENT && small == NULL);
    ca_selection_destroy(sel);
    ca_candidate_set_destroy(set);

    /* the medial route needs a mesh: a set from caller arrays has none */
    {
        const double samples[] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0, 0, 1, 0, 0, 0, 1};
        const double centers[] = {0.5, 0.2, 0.2, 2.5, 0.2, 0.2};
        const double radii[] = {1.5, 1.5};
        set = NULL;
        sel = NULL;
        CHECK(ca_candidates_from_arrays(ctx, samples, 6, 0, centers, 0, radii, 0, 2, 0, &set) == CA_OK);
        CHECK(ca_select(ctx, set, NULL, &sel) == CA_OK);
        ca_connect_options_init(&cop);
        cop.method = CA_CONNECT_MEDIAL;
        sk = NULL;
        CHECK(ca_connect(ctx, set, sel, &cop, &sk) == CA_ERROR_INVALID_ARGUMENT && sk == NULL);
        cop.method = CA_CONNECT_AUTO;
        CHECK(ca_connect(ctx, set, sel, &cop, &sk) == CA_OK);
        ca_skeleton_destroy(sk);
        ca_selection_destroy(sel);
        ca_candidate_set_destroy(set);
    }
    ca_context_destroy(ctx);
}

/* Evaluation: known answer for one ball in the box, and bad input. */
static void test_evaluate(void) {
    ca_context* ctx = NULL;
    ca_surface_view v = box_view();
    ca_skeleton_view sk;
    ca_evaluate_options eo;
    ca_evaluation e;
    const double center[] = {1, 0.5, 0.5}, radius[] = {0.5};
    const uint32_t bad_edge[] = {0, 3};
    const double diag = sqrt(6.0);
    CHECK(ca_context_create(NULL, &ctx) == CA_OK);
    ca_skeleton_view_init(&sk);
    sk.centers = center;
    sk.radii = radius;
    sk.vertex_count = 1;
    ca_evaluate_options_init(&eo);
    eo.surface_samples = 20000;
    eo.envelope_samples = 50000;
    e.struct_size = sizeof e;
    CHECK(ca_evaluate(ctx, &v, &sk, &eo, &e) == CA_OK);
    /* surface -> ball: the box corners, |(1, .5, .5)| - .5; ball -> surface: the ball's tips at x = .5, 1.5 */
    CHECK(fabs(e.hd_surface_to_recon - 100 * (sqrt(1.5) - 0.5) / diag) < 0.01);
    CHECK(fabs(e.hd_recon_to_surface - 100 * 0.5 / diag) < 0.3);
    CHECK(e.hd_recon_to_surface <= 100 * 0.5 / diag + 1e-9);
    CHECK(fabs(e.hd_two_sided - e.hd_surface_to_recon) < 1e-12);
    CHECK(fabs(e.diagonal - diag) < 1e-12);
    CHECK(e.surface_samples_used >= 20000 && e.envelope_samples_used >= 50000);

    CHECK(ca_evaluate(ctx, NULL, &sk, &eo, &e) == CA_ERROR_NULL_POINTER);
    CHECK(ca_evaluate(ctx, &v, &sk, &eo, NULL) == CA_ERROR_NULL_POINTER);
    e.struct_size = 1;
    CHECK(ca_evaluate(ctx, &v, &sk, &eo, &e) == CA_ERROR_STRUCT_SIZE);
    e.struct_size = sizeof e;
    sk.edges = bad_edge;
    sk.edge_count = 1;
    CHECK(ca_evaluate(ctx, &v, &sk, &eo, &e) == CA_ERROR_INVALID_INPUT);
    CHECK(strstr(ca_context_last_error(ctx), "edge 0 references vertex 3 of 1") != NULL);
    sk.edge_count = 0;
    sk.vertex_count = 0;
    CHECK(ca_evaluate(ctx, &v, &sk, &eo, &e) == CA_ERROR_DEGENERATE_INPUT);
    ca_context_destroy(ctx);
}

/* The two-sided HD of `sel` connected at the defaults with `fit` and evaluated at the defaults. */
static double connected_hd(ca_context* ctx, const ca_candidate_set* set, const ca_selection* sel, int32_t fit) {
    ca_surface_view v = box_view();
    ca_connect_options cop;
    ca_skeleton* sk = NULL;
    ca_skeleton_view view;
    ca_evaluation e;
    ca_connect_options_init(&cop);
    cop.fit = fit;
    CHECK(ca_connect(ctx, set, sel, &cop, &sk) == CA_OK);
    ca_skeleton_view_init(&view);
    CHECK(ca_skeleton_get_view(sk, &view) == CA_OK);
    e.struct_size = sizeof e;
    CHECK(ca_evaluate(ctx, &v, &view, NULL, &e) == CA_OK);
    ca_skeleton_destroy(sk);
    return e.hd_two_sided;
}

/* probe_fit = 1: both delta searches (target_error, target_count by HD) report the HD of the
   selection as ca_connect with fit = 1 and ca_evaluate at their defaults measure it, which the
   fit changes on the box (so a search probing without the fit fails here). */
static void test_probe_fit(void) {
    ca_context* ctx = NULL;
    ca_candidate_set* set = NULL;
    ca_selection* sel = NULL;
    ca_surface_view v = box_view();
    ca_candidate_options o = box_options(400);
    ca_select_options so;
    ca_select_stats ss;
    int search;
    CHECK(ca_context_create(NULL, &ctx) == CA_OK);
    CHECK(ca_candidates(ctx, &v, &o, &set) == CA_OK);
    for (search = 0; search < 2; ++search) {
        double fitted, plain;
        ca_select_options_init(&so);
        CHECK(so.probe_fit == 0);
        so.probe_fit = 1;
        so.target_tolerance = SEARCH_TOLERANCE;
        if (search == 0) so.target_error = 8;
        else so.target_count = 12;
        sel = NULL;
        CHECK(ca_select(ctx, set, &so, &sel) == CA_OK);
        ss.struct_size = sizeof ss;
        CHECK(ca_selection_stats(sel, &ss) == CA_OK && ss.hd_reached > 0);
        fitted = connected_hd(ctx, set, sel, 1);
        plain = connected_hd(ctx, set, sel, 0);
        CHECK(fabs(ss.hd_reached - fitted) < 1e-9 * fitted);
        CHECK(fabs(fitted - plain) > 1e-6);
        /* fit = 2 (thorough): never farther than fit = 1 by ca_evaluate at its defaults */
        CHECK(connected_hd(ctx, set, sel, 2) <= fitted);
        ca_selection_destroy(sel);
    }
    {   /* fit values other than -1, 0, 1, 2, 3 are refused */
        ca_connect_options cop;
        ca_skeleton* sk = NULL;
        ca_select_options_init(&so);
        CHECK(ca_select(ctx, set, &so, &sel) == CA_OK);
        ca_connect_options_init(&cop);
        cop.fit = 4;
        CHECK(ca_connect(ctx, set, sel, &cop, &sk) == CA_ERROR_INVALID_ARGUMENT && sk == NULL);
        CHECK(strstr(ca_context_last_error(ctx), "fit") != NULL);
        ca_selection_destroy(sel);
    }
    ca_candidate_set_destroy(set);
    ca_context_destroy(ctx);
}

/* A target error no probe reaches: CA_ERROR_TARGET_NOT_REACHED with a message saying what was
   reached, and the selection of lowest HD still in *out: its stats report that HD (above the
   target), and it connects like any selection. */
static void test_target_not_reached(void) {
    ca_context* ctx = NULL;
    ca_candidate_set* set = NULL;
    ca_selection* sel = NULL;
    ca_skeleton* sk = NULL;
    ca_surface_view v = box_view();
    ca_candidate_options o = box_options(400);
    ca_select_options so;
    ca_select_stats ss;
    CHECK(ca_context_create(NULL, &ctx) == CA_OK);
    CHECK(ca_candidates(ctx, &v, &o, &set) == CA_OK);
    ca_select_options_init(&so);
    so.target_tolerance = SEARCH_TOLERANCE;
    so.target_error = 1e-4; /* a box's skeleton of a few balls is never that close */
    CHECK(ca_select(ctx, set, &so, &sel) == CA_ERROR_TARGET_NOT_REACHED);
    CHECK(strstr(ca_context_last_error(ctx), "not reached") != NULL);
    CHECK(strstr(ca_status_string(CA_ERROR_TARGET_NOT_REACHED), "CA_ERROR_TARGET_NOT_REACHED") != NULL);
    CHECK(sel != NULL);
    if (sel) {
        ss.struct_size = sizeof ss;
        CHECK(ca_selection_stats(sel, &ss) == CA_OK);
        CHECK(ss.hd_reached > so.target_error);
        CHECK(ss.probes >= 2);
        CHECK(ca_selection_count(sel) > 0);
        CHECK(ca_connect(ctx, set, sel, NULL, &sk) == CA_OK && sk != NULL);
        /* the HD the stats report is the one ca_evaluate measures on the skeleton ca_connect gives
           at its defaults (CA_FIT_AUTO fits it as the search judged it) */
        CHECK(fabs(connected_hd(ctx, set, sel, CA_FIT_AUTO) - ss.hd_reached) < 1e-9 * ss.hd_reached);
        ca_skeleton_destroy(sk);
        ca_selection_destroy(sel);
    }
    /* a reachable target is a success */
    so.target_error = 50;
    sel = NULL;
    CHECK(ca_select(ctx, set, &so, &sel) == CA_OK && sel != NULL);
    ca_selection_destroy(sel);
    ca_candidate_set_destroy(set);
    ca_context_destroy(ctx);
}

int main(void) {
    test_versions();
    test_null_and_sizes();
    test_bad_input();
    test_arrays_uncoverable_and_copy();
    test_cancel();
    test_box_pipeline();
    test_evaluate();
    test_routes_and_target();
    test_probe_fit();
    test_target_not_reached();
    printf("test_abi: %d passed, %d failed\n", checks - failures, failures);
    return failures ? 1 : 0;
}

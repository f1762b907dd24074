/* test_budget.c: the C ABI's bounds on work and its range checks, compiled as C99: the context's
 * time limit (CA_ERROR_TIME_LIMIT naming the stage, no partial result, the context usable
 * after it; inside ca_select's searches, after a probe, the best selection so far with that status), a cancel from the first progress call of every stage stops that stage at once,
 * counts past the ABI's range, strides that leave elements misaligned, boxes near the ends of
 * the double range, and indices equal to the vertex count everywhere the ABI takes indices. */
#include "box_skeleton.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static ca_context* context_with_limit(double seconds) {
    ca_context_desc d;
    ca_context* ctx = NULL;
    ca_context_desc_init(&d);
    d.time_limit_s = seconds;
    CHECK(ca_context_create(&d, &ctx) == CA_OK && ctx != NULL);
    return ctx;
}

static int names_stage(const ca_context* ctx, const char* stage) {
    const char* m = ca_context_last_error(ctx);
    return strstr(m, "time limit reached in ") != NULL && strstr(m, stage) != NULL;
}

/* Each step on a context whose budget is already spent fails with CA_ERROR_TIME_LIMIT naming
   its stage and allocates nothing; a context without a budget still runs every step, before and
   after, with the same inputs. */
static void test_time_limit(void) {
    ca_context* ok = context_with_limit(0);
    ca_context* tiny = context_with_limit(1e-12);
    ca_context* generous = context_with_limit(1e6);
    ca_surface_view v = box_view();
    ca_candidate_options o = box_options(400);
    ca_candidate_set* set = NULL;
    ca_candidate_set* failed_set = (ca_candidate_set*)1;
    ca_selection* sel = NULL;
    ca_selection* failed_sel = (ca_selection*)1;
    ca_skeleton* sk = NULL;
    ca_skeleton* failed_sk = (ca_skeleton*)1;
    ca_skeleton_view view;
    ca_evaluation e;
    ca_context_desc d;
    ca_context* c = NULL;

    ca_context_desc_init(&d);
    CHECK(d.time_limit_s == 0);
    d.time_limit_s = -1;
    CHECK(ca_context_create(&d, &c) == CA_ERROR_INVALID_ARGUMENT && c == NULL);
    CHECK(CA_ERROR_TIME_LIMIT == 14);
    CHECK(strncmp(ca_status_string(CA_ERROR_TIME_LIMIT), "CA_ERROR_TIME_LIMIT", 19) == 0);

    CHECK(ca_candidates(tiny, &v, &o, &failed_set) == CA_ERROR_TIME_LIMIT && failed_set == NULL);
    CHECK(names_stage(tiny, "surface")); /* the budget counts from the call's start */
    CHECK(ca_candidates(ok, &v, &o, &set) == CA_OK && set != NULL);
    CHECK(ca_select(tiny, set, NULL, &failed_sel) == CA_ERROR_TIME_LIMIT && failed_sel == NULL);
    CHECK(names_stage(tiny, "selection"));
    CHECK(ca_select(ok, set, NULL, &sel) == CA_OK && sel != NULL);
    CHECK(ca_connect(tiny, set, sel, NULL, &failed_sk) == CA_ERROR_TIME_LIMIT && failed_sk == NULL);
    CHECK(names_stage(tiny, "connect"));
    CHECK(ca_connect(ok, set, sel, NULL, &sk) == CA_OK && sk != NULL);
    ca_skeleton_view_init(&view);
    CHECK(ca_skeleton_get_view(sk, &view) == CA_OK);
    e.struct_size = sizeof e;
    CHECK(ca_evaluate(tiny, &v, &view, NULL, &e) == CA_ERROR_TIME_LIMIT);
    CHECK(names_stage(tiny, "surface"));
    CHECK(ca_evaluate(ok, &v, &view, NULL, &e) == CA_OK);
    /* the spent context still works for what needs no budget, and reports it */
    CHECK(ca_candidates(tiny, &v, &o, &failed_set) == CA_ERROR_TIME_LIMIT && failed_set == NULL);
    {
        ca_candidate_set* again = NULL;
        CHECK(ca_candidates(generous, &v, &o, &again) == CA_OK && again != NULL);
        CHECK(ca_candidate_set_count(again) == ca_candidate_set_count(set));
        ca_candidate_set_destroy(again);
    }
    ca_skeleton_destroy(sk);
    ca_selection_destroy(sel);
    ca_candidate_set_destroy(set);
    ca_context_destroy(ok);
    ca_context_destroy(tiny);
    ca_context_destroy(generous);
}

/* ---- cancel from the first progress call of each stage ---- */
#define MAX_STAGES 32
typedef struct {
    char stages[MAX_STAGES][32];
    int n_stages;
    const char* cancel_stage; /* NULL: record the stages */
    int cancelled;            /* the cancelling call happened */
    int calls_after;          /* progress calls after it */
} Recorder;

static int32_t record_progress(void* user, const char* stage, double f) {
    Recorder* r = (Recorder*)user;
    int i;
    (void)f;
    if (r->cancelled) {
        ++r->calls_after;
        return 1;
    }
    if (r->cancel_stage) {
        if (strcmp(stage, r->cancel_stage) != 0) return 0;
        r->cancelled = 1;
        return 1;
    }
    for (i = 0; i < r->n_stages; ++i)
        if (strcmp(r->stages[i], stage) == 0) return 0;
    if (r->n_stages < MAX_STAGES) {
        strncpy(r->stages[r->n_stages], stage, 31);
        r->stages[r->n_stages][31] = 0;
        ++r->n_stages;
    }
    return 0;
}

/* The whole pipeline on the box under a recorder; the status of the first step that failed. */
static ca_status run_pipeline(Recorder* r) {
    ca_context_desc d;
    ca_context* ctx = NULL;
    const ca_surface_view v = box_view();
    const ca_candidate_options o = box_options(400);
    BoxSkeleton box;
    ca_evaluation e;
    ca_evaluate_options eo;
    ca_status st;
    ca_context_desc_init(&d);
    d.progress = record_progress;
    d.progress_user = r;
    d.threads = 1;
    if (ca_context_create(&d, &ctx) != CA_OK) return CA_ERROR_INTERNAL;
    st = box_skeleton(ctx, &o, &box);
    if (st == CA_OK) {
        ca_evaluate_options_init(&eo);
        eo.surface_samples = 20000; /* several batches */
        eo.envelope_samples = 20000;
        e.struct_size = sizeof e;
        st = ca_evaluate(ctx, &v, &box.view, &eo, &e);
    }
    box_skeleton_destroy(&box);
    ca_context_destroy(ctx);
    return st;
}

static void test_cancel_every_stage(void) {
    Recorder all;
    int i;
    memset(&all, 0, sizeof all);
    CHECK(run_pipeline(&all) == CA_OK);
    CHECK(all.n_stages >= 5);
    for (i = 0; i < all.n_stages; ++i) {
        Recorder r;
        ca_status st;
        memset(&r, 0, sizeof r);
        r.cancel_stage = all.stages[i];
        st = run_pipeline(&r);
        if (st != CA_ERROR_CANCELLED || !r.cancelled || r.calls_after != 0)
            fprintf(stderr, "stage %s: status %d, %d progress calls after the cancel\n", all.stages[i], (int)st,
                    r.calls_after);
        CHECK(st == CA_ERROR_CANCELLED);
        CHECK(r.cancelled);
        CHECK(r.calls_after == 0);
    }
}

/* ---- range checks ---- */
static void test_counts_and_strides(void) {
    ca_context* ctx = context_with_limit(0);
    ca_surface_view v = box_view();
    ca_candidate_options o = box_options(400);
    ca_candidate_set* set = (ca_candidate_set*)1;
    ca_candidate_set* packed = NULL;
    ca_skeleton_view sk;
    ca_evaluation e;
    const double center[] = {1, 0.5, 0.5}, radius[] = {0.5};
    const uint32_t edge[] = {0, 0};
    unsigned char *buf, *tbuf;
    size_t i;
    const size_t odd = 3 * sizeof(double) + 1, odd_tri = 3 * sizeof(uint32_t) + 3;

    v.triangle_count = SIZE_MAX;
    CHECK(ca_candidates(ctx, &v, &o, &set) == CA_ERROR_INVALID_ARGUMENT && set == NULL);
    v = box_view();
    v.vertex_count = SIZE_MAX;
    CHECK(ca_candidates(ctx, &v, &o, &set) == CA_ERROR_INVALID_ARGUMENT && set == NULL);
    v = box_view();
    v.triangle_count = (size_t)UINT32_MAX + 1;
    CHECK(ca_candidates(ctx, &v, &o, &set) == CA_ERROR_INVALID_ARGUMENT && set == NULL);

    ca_skeleton_view_init(&sk);
    sk.centers = center;
    sk.radii = radius;
    sk.vertex_count = 1;
    sk.edges = edge;
    sk.edge_count = SIZE_MAX;
    e.struct_size = sizeof e;
    v = box_view();
    CHECK(ca_evaluate(ctx, &v, &sk, NULL, &e) == CA_ERROR_INVALID_ARGUMENT);
    sk.edge_count = 0;
    sk.faces = edge;
    sk.face_count = SIZE_MAX;
    CHECK(ca_evaluate(ctx, &v, &sk, NULL, &e) == CA_ERROR_INVALID_ARGUMENT);
    sk.face_count = 0;
    sk.vertex_count = SIZE_MAX;
    CHECK(ca_evaluate(ctx, &v, &sk, NULL, &e) == CA_ERROR_INVALID_ARGUMENT);

    /* Strides that are no multiple of the alignment (the arrays start aligned, as C requires;
       every later element is misaligned): the same candidates as the packed box. */
    buf = (unsigned char*)malloc(8 * odd);
    tbuf = (unsigned char*)malloc(12 * odd_tri);
    for (i = 0; i < 8; ++i) memcpy(buf + i * odd, box_v + 3 * i, 3 * sizeof(double));
    v = box_view();
    v.positions = (const double*)(const void*)buf;
    v.position_stride = odd;
    CHECK(ca_candidates(ctx, &v, &o, &set) == CA_OK && set != NULL);
    v = box_view();
    CHECK(ca_candidates(ctx, &v, &o, &packed) == CA_OK);
    CHECK(ca_candidate_set_count(set) == ca_candidate_set_count(packed));
    ca_candidate_set_destroy(set);
    set = NULL;
    for (i = 0; i < 12; ++i) memcpy(tbuf + i * odd_tri, box_f + 3 * i, 3 * sizeof(uint32_t));
    v.triangles = (const uint32_t*)(const void*)tbuf;
    v.triangle_stride = odd_tri;
    CHECK(ca_candidates(ctx, &v, &o, &set) == CA_OK && set != NULL);
    CHECK(ca_candidate_set_count(set) == ca_candidate_set_count(packed));
    ca_candidate_set_destroy(set);
    set = NULL;
    free(buf);
    free(tbuf);

    /* The box scaled by 1e300 and by 1e-300 is a box: same candidates, reference length scaled. */
    {
        const double scales[] = {1e300, 1e-300};
        double big[24];
        int k;
        for (k = 0; k < 2; ++k) {
            for (i = 0; i < 24; ++i) big[i] = box_v[i] * scales[k];
            v = box_view();
            v.positions = big;
            CHECK(ca_candidates(ctx, &v, &o, &set) == CA_OK && set != NULL);
            if (set) {
                CHECK(ca_candidate_set_count(set) == ca_candidate_set_count(packed));
                CHECK(ca_candidate_set_reference_length(set) / scales[k] > 1.999 &&
                      ca_candidate_set_reference_length(set) / scales[k] < 2.001);
            }
            ca_candidate_set_destroy(set);
            set = NULL;
        }
    }
    ca_candidate_set_destroy(packed);
    ca_context_destroy(ctx);
}

/* An index equal to the vertex count is one past the end, wherever the ABI takes indices. */
static void test_index_equal_to_count(void) {
    ca_context* ctx = context_with_limit(0);
    ca_surface_view v = box_view();
    ca_candidate_options o = box_options(400);
    ca_candidate_set* set = (ca_candidate_set*)1;
    ca_skeleton_view sk;
    ca_evaluation e;
    uint32_t tri[36];
    const double centers[] = {0.8, 0.5, 0.5, 1.2, 0.5, 0.5, 1, 0.4, 0.5};
    const double radii[] = {0.4, 0.4, 0.4};
    const uint32_t edge[] = {0, 3}, face[] = {0, 1, 3};

    memcpy(tri, box_f, sizeof tri);
    tri[35] = 8;
    v.triangles = tri;
    CHECK(ca_candidates(ctx, &v, &o, &set) == CA_ERROR_INVALID_INPUT && set == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "references vertex 8 of 8") != NULL);

    v = box_view();
    ca_skeleton_view_init(&sk);
    sk.centers = centers;
    sk.radii = radii;
    sk.vertex_count = 3;
    sk.edges = edge;
    sk.edge_count = 1;
    e.struct_size = sizeof e;
    CHECK(ca_evaluate(ctx, &v, &sk, NULL, &e) == CA_ERROR_INVALID_INPUT);
    CHECK(strstr(ca_context_last_error(ctx), "references vertex 3 of 3") != NULL);
    sk.edge_count = 0;
    sk.faces = face;
    sk.face_count = 1;
    CHECK(ca_evaluate(ctx, &v, &sk, NULL, &e) == CA_ERROR_INVALID_INPUT);
    CHECK(strstr(ca_context_last_error(ctx), "references vertex 3 of 3") != NULL);
    /* the surface ca_evaluate measures against takes triangles too */
    sk.face_count = 0;
    CHECK(ca_evaluate(ctx, &v, &sk, NULL, &e) == CA_OK);
    v.triangles = tri;
    CHECK(ca_evaluate(ctx, &v, &sk, NULL, &e) == CA_ERROR_INVALID_INPUT);
    CHECK(strstr(ca_context_last_error(ctx), "references vertex 8 of 8") != NULL);
    ca_context_destroy(ctx);
}

/* The progress callback of the searches' probes: at its first call after a probe (fraction > 0)
   it waits until the context's time limit (time_limit_s after `start`) has surely passed, so the
   limit falls inside the search wherever the machine's speed puts the probes. */
struct Waiter {
    const char* stage;
    time_t start;
    double wait_s;
    int waited;
};
static int32_t wait_past_limit(void* user, const char* stage, double fraction) {
    struct Waiter* w = (struct Waiter*)user;
    if (!w->waited && fraction > 0 && strcmp(stage, w->stage) == 0) {
        while (difftime(time(NULL), w->start) < w->wait_s) {
        }
        w->waited = 1;
    }
    return 0;
}

/* A time limit inside the target_error and target_count searches, after their first probe:
   CA_ERROR_TIME_LIMIT, the message saying the best selection so far is returned, and that
   selection in *out (its HD and probes in its stats), connected like any selection. */
static void test_time_limit_in_searches(void) {
    ca_surface_view v = box_view();
    ca_candidate_options o = box_options(400);
    ca_candidate_set* set = NULL;
    ca_context* plain = context_with_limit(0);
    int search;
    CHECK(ca_candidates(plain, &v, &o, &set) == CA_OK);
    for (search = 0; search < 2 && set; ++search) {
        struct Waiter w;
        ca_context_desc d;
        ca_context* ctx = NULL;
        ca_select_options so;
        ca_selection* sel = NULL;
        ca_skeleton* sk = NULL;
        ca_select_stats ss;
        ca_status st;
        w.stage = search == 0 ? "target error: probes" : "target count: probes";
        w.wait_s = 10; /* whole seconds: past the 8 s limit, which the first probe stays well within */
        w.waited = 0;
        ca_context_desc_init(&d);
        d.time_limit_s = 8;
        d.progress = wait_past_limit;
        d.progress_user = &w;
        CHECK(ca_context_create(&d, &ctx) == CA_OK);
        ca_select_options_init(&so);
        if (search == 0) so.target_error = 1e-4; /* never reached: the search would run every probe */
        else so.target_count = 6;
        w.start = time(NULL);
        st = ca_select(ctx, set, &so, &sel);
        CHECK(w.waited);
        CHECK(st == CA_ERROR_TIME_LIMIT);
        CHECK(strstr(ca_context_last_error(ctx), "best selection so far") != NULL);
        CHECK(sel != NULL);
        if (sel) {
            ss.struct_size = sizeof ss;
            CHECK(ca_selection_stats(sel, &ss) == CA_OK);
            CHECK(ss.hd_reached > 0);
            CHECK(ca_selection_count(sel) > 0);
            if (search == 1) CHECK(ca_selection_count(sel) <= 6);
            CHECK(ca_connect(plain, set, sel, NULL, &sk) == CA_OK && sk != NULL);
            ca_skeleton_destroy(sk);
            ca_selection_destroy(sel);
        }
        ca_context_destroy(ctx);
    }
    ca_candidate_set_destroy(set);
    ca_context_destroy(plain);
}

int main(void) {
    test_time_limit();
    test_time_limit_in_searches();
    test_cancel_every_stage();
    test_counts_and_strides();
    test_index_equal_to_count();
    printf("test_budget: %d passed, %d failed\n", checks - failures, failures);
    return failures ? 1 : 0;
}

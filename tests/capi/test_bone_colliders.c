/* test_bone_colliders.c: bone colliders through the C ABI, compiled as C99: a 2 x 1 x 1 box whose
 * left end (x = 0) is weighted to joint 0 and right end (x = 2) to joint 1 (a child turned 90
 * degrees about z and moved), so each joint dominates one half. One collider per joint; placed in
 * its joint's frame, each holds its half's corners and the points of the dividing square (checked
 * with the tests' own capsule distance, box_skeleton.h, after this file's own inverse bind); the stats and getters
 * agree. Every bad input gets its status and leaves *out NULL: NULL pointers, unknown struct sizes,
 * a zero joint count, NULL arrays, influences 0 and 9, a joint index or parent out of range, a
 * cycle, NaN and negative weights, a NaN or sheared inverse bind, a vertex count that is not the
 * surface's, a skip joint out of range, a skip list without its array, bad mode and shapes, an
 * index out of range for the placement, a point-cloud candidate set. */
#include "box_skeleton.h"

#include <string.h>

/* column-major 4x4 applied to a point */
static void apply(const double* m, const double* x, double* y) {
    int r;
    for (r = 0; r < 3; ++r) y[r] = m[r] * x[0] + m[4 + r] * x[1] + m[8 + r] * x[2] + m[12 + r];
}

/* distance of x (joint frame) to the collider as placed */
static double placed_distance(const ca_proxy_placement* p, const double* x) {
    double top[3], bottom[3];
    int k;
    for (k = 0; k < 3; ++k) {
        top[k] = p->center[k] + 0.5 * p->height * p->axis[k];
        bottom[k] = p->center[k] - 0.5 * p->height * p->axis[k];
    }
    return capsule_distance(bottom, p->radius_bottom, top, p->radius_top, x);
}

static const int32_t parents[2] = {-1, 0};
/* joint 0: identity; joint 1: the surface's frame turned about z (x' = y, y' = -x) and moved */
static const double inverse_bind[32] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,
                                        0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, -1, 2, 0.5, 1};
static const uint32_t vjoints[16] = {0, 1, 1, 0, 1, 0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 1};
static const double vweights[16] = {1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0};

static ca_skin_view skin_view(void) {
    ca_skin_view s;
    CHECK(ca_skin_view_defaults(&s, sizeof s) == CA_OK);
    s.joint_count = 2;
    s.parents = parents;
    s.inverse_bind = inverse_bind;
    s.vertex_count = 8;
    s.influences = 2;
    s.vertex_joints = vjoints;
    s.vertex_weights = vweights;
    return s;
}

/* the call with a skin and options; checks *out stays NULL on failure */
static ca_status build(ca_context* ctx, const ca_candidate_set* set, const ca_skin_view* skin,
                       const ca_bone_collider_options* o) {
    ca_bone_colliders* bc = (ca_bone_colliders*)1;
    ca_status st = ca_bone_colliders_build(ctx, set, NULL, skin, o, &bc);
    if (st != CA_OK) CHECK(bc == NULL);
    ca_bone_colliders_destroy(bc);
    return st;
}

int main(void) {
    ca_context* ctx = NULL;
    ca_candidate_set* set = NULL;
    ca_candidate_set* cloud = NULL;
    ca_bone_colliders* bc = NULL;
    ca_candidate_options co = box_options(300);
    ca_bone_collider_options bo;
    ca_bone_collider_stats stats;
    ca_proxy_placement pl;
    ca_surface_view surface = box_view();
    ca_skin_view skin = skin_view(), bad;
    double m[32], w[16];
    uint32_t j[16], skip = 5;
    int32_t cyc[2] = {1, 0}, far[2] = {-1, 7};
    size_t i, n;
    int k, c;

    CHECK(ca_context_create(NULL, &ctx) == CA_OK);
    CHECK(ca_candidates(ctx, &surface, &co, &set) == CA_OK);

    ca_bone_collider_options_init(&bo);
    CHECK(bo.mode == CA_PROXY_CONSERVATIVE && bo.shapes == CA_PROXY_SHAPES_CAPSULES && bo.seed == 1 &&
          bo.evaluate_samples == 100000 && bo.skip_joints == NULL && bo.skip_count == 0);
    CHECK(ca_bone_colliders_build(ctx, set, NULL, &skin, &bo, &bc) == CA_OK);
    n = ca_bone_colliders_count(bc);
    CHECK(n == 2);
    CHECK(ca_bone_colliders_joints(bc) != NULL && ca_bone_colliders_joints(bc)[0] == 0 && ca_bone_colliders_joints(bc)[1] == 1);
    CHECK(ca_bone_colliders_contained(bc) != NULL && ca_bone_colliders_overlap(bc) != NULL);
    stats.struct_size = sizeof stats;
    CHECK(ca_bone_colliders_stats(bc, &stats) == CA_OK);
    CHECK(stats.contained_fraction == 1.0 && stats.joints_with_collider == 2 && stats.joints_skipped == 0);
    CHECK(stats.union_volume > 0 && stats.outside_volume >= 0 && stats.neighbour_overlap >= 0);
    CHECK(ca_bone_colliders_overlap(bc)[0] == 0 && ca_bone_colliders_overlap(bc)[1] == stats.neighbour_overlap);
    for (i = 0; i < n && n == 2; ++i) {
        /* this joint's half: x from 0 to 1 (joint 0) or 1 to 2 (joint 1), corners and the middle */
        double x0 = i == 0 ? 0 : 1, worst = -1e300;
        pl.struct_size = sizeof pl;
        CHECK(ca_bone_colliders_placement(bc, i, &pl) == CA_OK);
        CHECK(pl.kind == CA_PROXY_CAPSULE || pl.kind == CA_PROXY_SPHERE);
        CHECK(ca_bone_colliders_contained(bc)[i] == 1.0);
        for (c = 0; c < 27; ++c) {
            double x[3], y[3];
            x[0] = x0 + 0.5 * (c % 3);
            x[1] = 0.5 * ((c / 3) % 3);
            x[2] = 0.5 * (c / 9);
            if (!(x[1] == 0 || x[1] == 1 || x[2] == 0 || x[2] == 1 || x[0] == 0 || x[0] == 2 || x[0] == 1)) continue;
            apply(inverse_bind + 16 * i, x, y);
            {
                double d = placed_distance(&pl, y);
                if (d > worst) worst = d;
            }
        }
        CHECK(worst <= 1e-9);
        /* the other end of the box is not in it (the test can fail) */
        {
            double x[3] = {i == 0 ? 2 : 0, 0.5, 0.5}, y[3];
            apply(inverse_bind + 16 * i, x, y);
            CHECK(placed_distance(&pl, y) > 0);
        }
    }
    CHECK(ca_bone_colliders_placement(bc, 2, &pl) == CA_ERROR_INVALID_ARGUMENT);
    CHECK(ca_bone_colliders_placement(NULL, 0, &pl) == CA_ERROR_NULL_POINTER);
    CHECK(ca_bone_colliders_placement(bc, 0, NULL) == CA_ERROR_NULL_POINTER);
    pl.struct_size = 3;
    CHECK(ca_bone_colliders_placement(bc, 0, &pl) == CA_ERROR_STRUCT_SIZE);
    stats.struct_size = 5;
    CHECK(ca_bone_colliders_stats(bc, &stats) == CA_ERROR_STRUCT_SIZE);
    CHECK(ca_bone_colliders_stats(NULL, &stats) == CA_ERROR_NULL_POINTER);
    ca_bone_colliders_destroy(bc);
    CHECK(ca_bone_colliders_count(NULL) == 0 && ca_bone_colliders_joints(NULL) == NULL &&
          ca_bone_colliders_contained(NULL) == NULL && ca_bone_colliders_overlap(NULL) == NULL);
    ca_bone_colliders_destroy(NULL);

    /* a skip list, and NULL options (the defaults) */
    bo.skip_joints = &skip;
    bo.skip_count = 1;
    skip = 1;
    CHECK(ca_bone_colliders_build(ctx, set, NULL, &skin, &bo, &bc) == CA_OK);
    CHECK(ca_bone_colliders_count(bc) == 1 && ca_bone_colliders_joints(bc)[0] == 0);
    stats.struct_size = sizeof stats;
    CHECK(ca_bone_colliders_stats(bc, &stats) == CA_OK && stats.joints_skipped == 1);
    ca_bone_colliders_destroy(bc);
    CHECK(build(ctx, set, &skin, NULL) == CA_OK);
    /* inscribed: inside the box */
    ca_bone_collider_options_init(&bo);
    bo.mode = CA_PROXY_INSCRIBED;
    bo.min_size = 0;
    CHECK(ca_bone_colliders_build(ctx, set, NULL, &skin, &bo, &bc) == CA_OK);
    for (i = 0; i < ca_bone_colliders_count(bc); ++i) {
        pl.struct_size = sizeof pl;
        CHECK(ca_bone_colliders_placement(bc, i, &pl) == CA_OK);
        CHECK(pl.radius_top <= 0.5 + 1e-9 && pl.radius_bottom <= 0.5 + 1e-9);
    }
    ca_bone_colliders_destroy(bc);

    /* ---- bad input ---- */
    ca_bone_collider_options_init(&bo);
    bc = (ca_bone_colliders*)1;
    CHECK(ca_bone_colliders_build(NULL, set, NULL, &skin, &bo, &bc) == CA_ERROR_NULL_POINTER);
    CHECK(ca_bone_colliders_build(ctx, NULL, NULL, &skin, &bo, &bc) == CA_ERROR_NULL_POINTER && bc == NULL);
    CHECK(ca_bone_colliders_build(ctx, set, NULL, NULL, &bo, &bc) == CA_ERROR_NULL_POINTER && bc == NULL);
    CHECK(ca_bone_colliders_build(ctx, set, NULL, &skin, &bo, NULL) == CA_ERROR_NULL_POINTER);
    bad = skin; bad.struct_size = 7;
    CHECK(build(ctx, set, &bad, &bo) == CA_ERROR_STRUCT_SIZE);
    bo.struct_size = 9;
    CHECK(build(ctx, set, &skin, &bo) == CA_ERROR_STRUCT_SIZE);
    ca_bone_collider_options_init(&bo);
    CHECK(ca_bone_collider_options_defaults(&bo, 3) == CA_ERROR_STRUCT_SIZE);
    CHECK(ca_bone_collider_options_defaults(NULL, sizeof bo) == CA_ERROR_NULL_POINTER);
    CHECK(ca_skin_view_defaults(&bad, 2) == CA_ERROR_STRUCT_SIZE);
    ca_bone_collider_options_init(&bo);
    bad = skin; bad.joint_count = 0;
    CHECK(build(ctx, set, &bad, &bo) == CA_ERROR_INVALID_INPUT);
    bad = skin; bad.parents = NULL;
    CHECK(build(ctx, set, &bad, &bo) == CA_ERROR_NULL_POINTER);
    bad = skin; bad.vertex_joints = NULL;
    CHECK(build(ctx, set, &bad, &bo) == CA_ERROR_NULL_POINTER);
    bad = skin; bad.vertex_weights = NULL;
    CHECK(build(ctx, set, &bad, &bo) == CA_ERROR_NULL_POINTER);
    bad = skin; bad.influences = 0;
    CHECK(build(ctx, set, &bad, &bo) == CA_ERROR_INVALID_INPUT);
    bad = skin; bad.influences = 9;
    CHECK(build(ctx, set, &bad, &bo) == CA_ERROR_INVALID_INPUT);
    bad = skin; bad.vertex_count = 7;
    CHECK(build(ctx, set, &bad, &bo) == CA_ERROR_INVALID_INPUT);
    bad = skin; bad.parents = cyc;
    CHECK(build(ctx, set, &bad, &bo) == CA_ERROR_INVALID_INPUT);
    bad = skin; bad.parents = far;
    CHECK(build(ctx, set, &bad, &bo) == CA_ERROR_INVALID_INPUT);
    memcpy(j, vjoints, sizeof j);
    j[5] = 2;
    bad = skin; bad.vertex_joints = j;
    CHECK(build(ctx, set, &bad, &bo) == CA_ERROR_INVALID_INPUT);
    memcpy(w, vweights, sizeof w);
    w[3] = NAN;
    bad = skin; bad.vertex_weights = w;
    CHECK(build(ctx, set, &bad, &bo) == CA_ERROR_INVALID_INPUT);
    w[3] = -0.5;
    CHECK(build(ctx, set, &bad, &bo) == CA_ERROR_INVALID_INPUT);
    w[3] = INFINITY;
    CHECK(build(ctx, set, &bad, &bo) == CA_ERROR_INVALID_INPUT);
    memcpy(m, inverse_bind, sizeof m);
    m[20] = NAN;
    bad = skin; bad.inverse_bind = m;
    CHECK(build(ctx, set, &bad, &bo) == CA_ERROR_INVALID_INPUT);
    memcpy(m, inverse_bind, sizeof m);
    m[16 + 4] = 1.5; /* joint 1's second column longer: a non-uniform scale */
    CHECK(build(ctx, set, &bad, &bo) == CA_ERROR_INVALID_INPUT);
    memcpy(m, inverse_bind, sizeof m);
    m[16 + 5] = 0.3; /* a shear: joint 1's second column no longer square to its first */
    CHECK(build(ctx, set, &bad, &bo) == CA_ERROR_INVALID_INPUT);
    memcpy(m, inverse_bind, sizeof m);
    m[3] = 0.2; /* a projective last row */
    CHECK(build(ctx, set, &bad, &bo) == CA_ERROR_INVALID_INPUT);
    /* a uniform scale is fine: the radii scale with it */
    for (k = 0; k < 12; ++k) m[16 + k] = 2 * inverse_bind[16 + k];
    m[3] = 0;
    CHECK(build(ctx, set, &bad, &bo) == CA_OK);
    skip = 5;
    bo.skip_joints = &skip;
    bo.skip_count = 1;
    CHECK(build(ctx, set, &skin, &bo) == CA_ERROR_INVALID_ARGUMENT);
    bo.skip_joints = NULL;
    CHECK(build(ctx, set, &skin, &bo) == CA_ERROR_NULL_POINTER);
    ca_bone_collider_options_init(&bo);
    bo.mode = 7;
    CHECK(build(ctx, set, &skin, &bo) == CA_ERROR_INVALID_ARGUMENT);
    ca_bone_collider_options_init(&bo);
    bo.shapes = CA_PROXY_SHAPES_BOXES;
    CHECK(build(ctx, set, &skin, &bo) == CA_ERROR_INVALID_ARGUMENT);
    ca_bone_collider_options_init(&bo);
    bo.min_share = NAN;
    CHECK(build(ctx, set, &skin, &bo) == CA_ERROR_INVALID_ARGUMENT);
    ca_bone_collider_options_init(&bo);
    bo.evaluate_samples = 0;
    CHECK(build(ctx, set, &skin, &bo) == CA_ERROR_INVALID_ARGUMENT);
    CHECK(strlen(ca_context_last_error(ctx)) > 0);

    /* a point cloud's candidate set: not a triangle mesh */
    {
        ca_surface_view pts = box_view();
        static const double normals[24] = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1};
        pts.triangles = NULL;
        pts.triangle_count = 0;
        pts.normals = normals;
        pts.point_normals = CA_POINT_NORMALS_ESTIMATE;
        if (ca_candidates(ctx, &pts, &co, &cloud) == CA_OK) {
            ca_bone_collider_options_init(&bo);
            CHECK(build(ctx, cloud, &skin, &bo) == CA_ERROR_INVALID_ARGUMENT);
            ca_candidate_set_destroy(cloud);
        }
    }

    ca_candidate_set_destroy(set);
    ca_context_destroy(ctx);
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}

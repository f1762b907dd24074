/* test_proxies.c: the engine-proxy step through the C ABI, compiled as C99: a box's skeleton gives
 * conservative proxies that hold the box's corners, edge midpoints and face centres (checked with
 * the tests' own distance to a capsule, box_skeleton.h); the getters agree with the count; the stats honour the
 * caller's struct_size; NULL pointers, unknown struct sizes, a zero count, bad skeleton indices and
 * a point-cloud set fail with their status and leave *out NULL. */
#include "box_skeleton.h"

#include <string.h>

int main(void) {
    ca_context* ctx = NULL;
    ca_proxy_set* px = NULL;
    const ca_candidate_options co = box_options(300);
    BoxSkeleton box;
    ca_candidate_set* set;
    ca_skeleton_view view;
    ca_proxy_options po;
    ca_proxy_stats stats;
    size_t i, n;
    int k;

    CHECK(ca_context_create(NULL, &ctx) == CA_OK);
    CHECK(box_skeleton(ctx, &co, &box) == CA_OK);
    set = box.set;
    view = box.view;

    ca_proxy_options_init(&po);
    CHECK(po.count == 16 && po.mode == CA_PROXY_INSCRIBED && po.shapes == CA_PROXY_SHAPES_CAPSULES && po.seed == 1);
    po.mode = CA_PROXY_CONSERVATIVE;
    po.count = 3;
    po.evaluate_samples = 2000;
    po.volume_samples = 10000;
    CHECK(ca_proxies(ctx, set, &view, &po, &px) == CA_OK);
    n = ca_proxy_set_count(px);
    CHECK(n >= 1 && n <= 3);
    {
        const int32_t* kinds = ca_proxy_set_kinds(px);
        const double* c = ca_proxy_set_centers(px);
        const double* r = ca_proxy_set_radii(px);
        /* the 8 corners, 12 edge midpoints and 6 face centres of the 2 x 1 x 1 box */
        double pts[26][3];
        int np = 0, x, y, z, outside = 0;
        for (x = 0; x <= 2; ++x)
            for (y = 0; y <= 2; ++y)
                for (z = 0; z <= 2; ++z) {
                    int on_faces = (x != 1) + (y != 1) + (z != 1);
                    if (on_faces == 0) continue;
                    pts[np][0] = x;
                    pts[np][1] = 0.5 * y;
                    pts[np][2] = 0.5 * z;
                    ++np;
                }
        CHECK(np == 26);
        for (k = 0; k < np; ++k) {
            double best = 1e300;
            for (i = 0; i < n; ++i) {
                double d = capsule_distance(c + 6 * i, r[2 * i], c + 6 * i + 3, r[2 * i + 1], pts[k]);
                CHECK(kinds[i] == CA_PROXY_SPHERE || kinds[i] == CA_PROXY_CAPSULE);
                if (d < best) best = d;
            }
            outside += best > 1e-9;
        }
        CHECK(outside == 0);
    }
    stats.struct_size = sizeof stats;
    CHECK(ca_proxy_set_stats(px, &stats) == CA_OK);
    CHECK(stats.struct_size == sizeof stats);
    CHECK(fabs(stats.diagonal - sqrt(6.0)) < 1e-9);
    CHECK(stats.outside_volume > 0 && stats.union_volume >= 2.0 * 0.99);  /* it holds the box's surface */
    CHECK(stats.hd_two_sided > 0 && stats.hd_two_sided >= stats.hd_surface_to_proxies);
    stats.struct_size = 12;
    CHECK(ca_proxy_set_stats(px, &stats) == CA_ERROR_STRUCT_SIZE);
    CHECK(ca_proxy_set_stats(NULL, &stats) == CA_ERROR_NULL_POINTER);
    ca_proxy_set_destroy(px);
    px = NULL;

    /* refusals: *out is NULL and the last error names the problem */
    px = (ca_proxy_set*)&px;
    CHECK(ca_proxies(ctx, NULL, &view, &po, &px) == CA_ERROR_NULL_POINTER && px == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "set") != NULL);
    CHECK(ca_proxies(ctx, set, NULL, &po, &px) == CA_ERROR_NULL_POINTER && px == NULL);
    CHECK(ca_proxies(ctx, set, &view, &po, NULL) == CA_ERROR_NULL_POINTER);
    CHECK(ca_proxies(NULL, set, &view, &po, &px) == CA_ERROR_NULL_POINTER);
    po.struct_size = 6;
    CHECK(ca_proxies(ctx, set, &view, &po, &px) == CA_ERROR_STRUCT_SIZE && px == NULL);
    CHECK(strstr(ca_context_last_error(ctx), "ca_proxy_options") != NULL);
    ca_proxy_options_init(&po);
    po.count = 0;
    CHECK(ca_proxies(ctx, set, &view, &po, &px) == CA_ERROR_INVALID_ARGUMENT && px == NULL);
    ca_proxy_options_init(&po);
    po.mode = 7;
    CHECK(ca_proxies(ctx, set, &view, &po, &px) == CA_ERROR_INVALID_ARGUMENT && px == NULL);
    ca_proxy_options_init(&po);
    {
        ca_skeleton_view bad = view;
        uint32_t edges[2];
        edges[0] = 0;
        edges[1] = (uint32_t)view.vertex_count;
        bad.edges = edges;
        bad.edge_count = 1;
        CHECK(ca_proxies(ctx, set, &bad, &po, &px) == CA_ERROR_INVALID_INPUT && px == NULL);
        bad = view;
        bad.radii = NULL;
        CHECK(ca_proxies(ctx, set, &bad, &po, &px) == CA_ERROR_NULL_POINTER && px == NULL);
    }
    {
        /* a candidate set from caller arrays has no surface to make proxies of */
        ca_candidate_set* bare = NULL;
        const double samples[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
        const double centers[] = {0.2, 0.2, 0.2};
        const double radii[] = {0.5};
        CHECK(ca_candidates_from_arrays(ctx, samples, 4, 0, centers, 0, radii, 0, 1, 0, &bare) == CA_OK);
        CHECK(ca_proxies(ctx, bare, &view, &po, &px) == CA_ERROR_INVALID_ARGUMENT && px == NULL);
        ca_candidate_set_destroy(bare);
    }
    CHECK(ca_proxy_options_defaults(&po, 5) == CA_ERROR_STRUCT_SIZE);
    CHECK(ca_proxy_options_defaults(NULL, sizeof po) == CA_ERROR_NULL_POINTER);
    CHECK(ca_proxy_set_count(NULL) == 0 && ca_proxy_set_kinds(NULL) == NULL);
    ca_proxy_set_destroy(NULL);

    box_skeleton_destroy(&box);
    ca_context_destroy(ctx);
    printf("test_proxies: %d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}

/* test_proxy_placement.c: ca_proxy_set_placement through the C ABI, compiled as C99. On a box's
 * conservative proxies each placement agrees with the getters: a capsule's node, turned by its
 * quaternion (applied here with this file's own arithmetic), puts its top ball on ball b and its
 * bottom ball on ball a with their radii; a sphere sits at ball a; the quaternion is a unit one with
 * w >= 0 and `axis` is the node's turned +Y. NULL pointers, an index past the count and an unknown
 * struct_size fail with their status. */
#include "box_skeleton.h"

/* q (x y z w) applied to v */
static void rotate(const double* q, const double* v, double* out) {
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    /* t = 2 q.xyz x v; out = v + w t + q.xyz x t */
    double t[3], c[3];
    t[0] = 2 * (y * v[2] - z * v[1]);
    t[1] = 2 * (z * v[0] - x * v[2]);
    t[2] = 2 * (x * v[1] - y * v[0]);
    c[0] = y * t[2] - z * t[1];
    c[1] = z * t[0] - x * t[2];
    c[2] = x * t[1] - y * t[0];
    out[0] = v[0] + w * t[0] + c[0];
    out[1] = v[1] + w * t[1] + c[1];
    out[2] = v[2] + w * t[2] + c[2];
}

static double gap(const double* a, const double* b) {
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

int main(void) {
    ca_context* ctx = NULL;
    ca_proxy_set* px = NULL;
    const ca_candidate_options co = box_options(300);
    BoxSkeleton box;
    ca_proxy_options po;
    ca_proxy_placement pl;
    size_t i, n;
    int capsules = 0;

    CHECK(ca_context_create(NULL, &ctx) == CA_OK);
    CHECK(box_skeleton(ctx, &co, &box) == CA_OK);
    ca_proxy_options_init(&po);
    po.mode = CA_PROXY_CONSERVATIVE;
    po.count = 4;
    po.evaluate_samples = 2000;
    po.volume_samples = 10000;
    CHECK(ca_proxies(ctx, box.set, &box.view, &po, &px) == CA_OK);
    n = ca_proxy_set_count(px);
    CHECK(n >= 1);
    for (i = 0; i < n; ++i) {
        const int32_t kind = ca_proxy_set_kinds(px)[i];
        const double* a = ca_proxy_set_centers(px) + 6 * i;
        const double* b = a + 3;
        const double ra = ca_proxy_set_radii(px)[2 * i], rb = ca_proxy_set_radii(px)[2 * i + 1];
        const double up[3] = {0, 1, 0};
        double turned[3], q;
        pl.struct_size = sizeof pl;
        CHECK(ca_proxy_set_placement(px, i, &pl) == CA_OK);
        CHECK(pl.struct_size == sizeof pl);
        q = sqrt(pl.rotation[0] * pl.rotation[0] + pl.rotation[1] * pl.rotation[1] + pl.rotation[2] * pl.rotation[2] +
                 pl.rotation[3] * pl.rotation[3]);
        CHECK(fabs(q - 1) < 1e-12 && pl.rotation[3] >= 0);
        rotate(pl.rotation, up, turned);
        CHECK(gap(turned, pl.axis) < 1e-12);
        if (kind == CA_PROXY_CAPSULE && gap(a, b) > fabs(ra - rb)) {
            double top[3], bottom[3], local[3] = {0, 0, 0};
            int k;
            ++capsules;
            CHECK(pl.kind == CA_PROXY_CAPSULE);
            local[1] = pl.height / 2;
            rotate(pl.rotation, local, top);
            local[1] = -pl.height / 2;
            rotate(pl.rotation, local, bottom);
            for (k = 0; k < 3; ++k) {
                top[k] += pl.center[k];
                bottom[k] += pl.center[k];
            }
            CHECK(gap(top, b) < 1e-12 && gap(bottom, a) < 1e-12);
            CHECK(pl.radius_top == rb && pl.radius_bottom == ra);
            CHECK(fabs(pl.height - gap(a, b)) < 1e-12);
            CHECK(pl.half_extents[0] == 0 && pl.half_extents[1] == 0 && pl.half_extents[2] == 0);
        } else if (kind == CA_PROXY_SPHERE) {
            CHECK(pl.kind == CA_PROXY_SPHERE);
            CHECK(gap(pl.center, a) == 0 && pl.radius_top == ra && pl.radius_bottom == ra && pl.height == 0);
        } else {
            /* a capsule one of whose balls holds the other: that ball */
            CHECK(kind == CA_PROXY_CAPSULE && pl.kind == CA_PROXY_SPHERE);
            CHECK(pl.radius_top == (ra >= rb ? ra : rb));
        }
    }
    printf("test_proxy_placement: %d capsules among %d primitives\n", capsules, (int)n);

    pl.struct_size = sizeof pl;
    CHECK(ca_proxy_set_placement(px, n, &pl) == CA_ERROR_INVALID_ARGUMENT);
    CHECK(ca_proxy_set_placement(NULL, 0, &pl) == CA_ERROR_NULL_POINTER);
    CHECK(ca_proxy_set_placement(px, 0, NULL) == CA_ERROR_NULL_POINTER);
    pl.struct_size = 12;
    CHECK(ca_proxy_set_placement(px, 0, &pl) == CA_ERROR_STRUCT_SIZE);

    ca_proxy_set_destroy(px);
    box_skeleton_destroy(&box);
    ca_context_destroy(ctx);
    printf("test_proxy_placement: %d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}

/* minimal.c: the smallest complete use of the C ABI: a closed box mesh in, a skeleton out. */
#include "coverage_axis.h"

#include <stdio.h>

int main(void) {
    /* a 2 x 1 x 1 box, 8 vertices, 12 outward-facing triangles */
    static const double v[] = {0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1, 0, 0, 0, 1, 2, 0, 1, 2, 1, 1, 0, 1, 1};
    static const uint32_t f[] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
    ca_context* ctx = NULL;
    ca_candidate_set* set = NULL;
    ca_selection* sel = NULL;
    ca_skeleton* sk = NULL;
    ca_surface_view mesh;
    ca_status st;
    size_t i;

    if (ca_context_create(NULL, &ctx) != CA_OK) return 1;
    ca_surface_view_init(&mesh);
    mesh.positions = v;
    mesh.vertex_count = 8;
    mesh.triangles = f;
    mesh.triangle_count = 12;

    st = ca_candidates(ctx, &mesh, NULL, &set); /* NULL options = defaults */
    if (st == CA_OK) st = ca_select(ctx, set, NULL, &sel);
    if (st == CA_OK) st = ca_connect(ctx, set, sel, NULL, &sk);
    if (st != CA_OK) {
        fprintf(stderr, "%s: %s\n", ca_status_string(st), ca_context_last_error(ctx));
    } else {
        const double* c = ca_skeleton_centers(sk);
        const double* r = ca_skeleton_radii(sk);
        printf("%zu balls, %zu edges, %zu faces\n", ca_skeleton_vertex_count(sk), ca_skeleton_edge_count(sk),
               ca_skeleton_face_count(sk));
        for (i = 0; i < ca_skeleton_vertex_count(sk); ++i)
            printf("  ball %zu: (%.3f, %.3f, %.3f) r = %.3f\n", i, c[3 * i], c[3 * i + 1], c[3 * i + 2], r[i]);
    }
    ca_skeleton_destroy(sk);
    ca_selection_destroy(sel);
    ca_candidate_set_destroy(set);
    ca_context_destroy(ctx);
    return st == CA_OK ? 0 : 1;
}

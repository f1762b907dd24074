/* capi_check.h: what the C tests of the ABI share: the CHECK macro with its counters, a
 * 2 x 1 x 1 box mesh (outward-facing) as a surface view, and small candidate options for it.
 * Included once per test program. */
#ifndef CAPI_CHECK_H
#define CAPI_CHECK_H

#include "coverage_axis.h"

#include <stdio.h>

static int failures = 0, checks = 0;
#define CHECK(cond)                                                                  \
    do {                                                                             \
        ++checks;                                                                    \
        if (!(cond)) {                                                               \
            ++failures;                                                              \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); \
        }                                                                            \
    } while (0)

static const double box_v[] = {0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1, 0, 0, 0, 1, 2, 0, 1, 2, 1, 1, 0, 1, 1};
static const uint32_t box_f[] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};

static ca_surface_view box_view(void) {
    ca_surface_view v;
    ca_surface_view_init(&v);
    v.positions = box_v;
    v.vertex_count = 8;
    v.triangles = box_f;
    v.triangle_count = 12;
    return v;
}

/* Candidate options for a quick run on the box: `cover_samples` samples to cover, 800 Voronoi
   samples (inline: a program that does not use it is not warned of it). */
static inline ca_candidate_options box_options(uint32_t cover_samples) {
    ca_candidate_options o;
    ca_candidate_options_init(&o);
    o.cover_samples = cover_samples;
    o.voronoi_samples = 800;
    return o;
}

#endif

/* box_skeleton.h: the box's skeleton through the three steps, for the C tests that start from it
 * (proxies, placements, the budget's cancellations), and the distance to a tapered capsule with
 * which the proxy and bone-collider tests check what a shape holds. */
#ifndef BOX_SKELETON_H
#define BOX_SKELETON_H

#include "capi_check.h"

#include <math.h>

/* The objects of one run on the box (NULL until made) and the skeleton's view. */
typedef struct BoxSkeleton {
    ca_candidate_set* set;
    ca_selection* sel;
    ca_skeleton* sk;
    ca_skeleton_view view;
} BoxSkeleton;

/* Candidates by `o`, the selection and the skeleton at the defaults, and its view; each step runs
   only when the one before succeeded. The status of the first that failed (CA_OK: all made). */
static inline ca_status box_skeleton(ca_context* ctx, const ca_candidate_options* o, BoxSkeleton* b) {
    const ca_surface_view v = box_view();
    ca_status st;
    b->set = NULL;
    b->sel = NULL;
    b->sk = NULL;
    ca_skeleton_view_init(&b->view);
    st = ca_candidates(ctx, &v, o, &b->set);
    if (st == CA_OK) st = ca_select(ctx, b->set, NULL, &b->sel);
    if (st == CA_OK) st = ca_connect(ctx, b->set, b->sel, NULL, &b->sk);
    if (st == CA_OK) st = ca_skeleton_get_view(b->sk, &b->view);
    return st;
}

static inline void box_skeleton_destroy(BoxSkeleton* b) {
    ca_skeleton_destroy(b->sk);
    ca_selection_destroy(b->sel);
    ca_candidate_set_destroy(b->set);
}

/* min over t in [0,1] of |x - c(t)| - r(t), c and r running linearly from (a, ra) to (b, rb): by
   ternary search (convex in t), then the better of its result and the two ends. */
static inline double capsule_distance(const double* a, double ra, const double* b, double rb, const double* x) {
    double lo = 0, hi = 1, best = 1e300;
    int i, k;
    for (i = 0; i < 200; ++i) {
        double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3, f1, f2, d[3];
        for (k = 0; k < 3; ++k) d[k] = x[k] - (a[k] + m1 * (b[k] - a[k]));
        f1 = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - (ra + m1 * (rb - ra));
        for (k = 0; k < 3; ++k) d[k] = x[k] - (a[k] + m2 * (b[k] - a[k]));
        f2 = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - (ra + m2 * (rb - ra));
        if (f1 <= f2) hi = m2;
        else lo = m1;
    }
    for (i = 0; i <= 2; ++i) {
        double t = i == 0 ? 0 : i == 1 ? 1 : 0.5 * (lo + hi), d[3], f;
        for (k = 0; k < 3; ++k) d[k] = x[k] - (a[k] + t * (b[k] - a[k]));
        f = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - (ra + t * (rb - ra));
        if (f < best) best = f;
    }
    return best;
}

#endif

// reduction.cpp: reduction of a set-cover instance (rows = samples, columns = balls) to its
// kernel, on the input (with its masks) and on compact problems (see setcover_internal.h).
//
// Rules, applied to a fixpoint; none changes the optimum:
//  - forced ball: a sample covered by one alive ball only forces that ball (it is selected, its
//    samples are covered);
//  - dominated ball: ball a is dropped if an alive ball b has samples(a) ⊆ samples(b) (equal
//    sets: the lower index stays): any cover using a can use b instead;
//  - dominated sample: sample j is dropped if an alive sample k has balls(k) ⊆ balls(j) (equal
//    sets: the lower index stays): covering k covers j;
//  - empty ball: a ball whose samples are all covered or dropped is dropped.
// Each dominance phase removes exactly the elements dominated at its start (a dominated element
// always has an undominated dominator, see below), so the kernel does not depend on the order in
// which a phase visits its elements; the phases run in a fixed sequence (reduce_fixpoint).
//
// The reducer's state and its steps: reducer.h. This file runs the rules to their fixpoint and
// returns the kernel.
#include "reducer.h"

namespace ca {
namespace sc {

namespace {


// Reduce to the fixpoint from the reducer's current state.
Status reduce_fixpoint(Reducer& red, const Monitor& monitor) {
    // Ball dominance only changes when sample sets change and vice versa: rerun a phase only
    // when the other one (or forcing) changed something. Ball dominance first: it usually
    // removes most columns, which makes every later phase cheap.
    bool need_balls = true, need_samples = true;
    for (;;) {
        if (monitor.stopped()) return monitor.stop_status("reduction");
        if (red.force_degree_one()) {
            red.update();
            need_balls = need_samples = true;
            continue;
        }
        if (need_balls) {
            need_balls = false;
            if (red.ball_dominance()) {
                red.update();
                need_samples = true;
            }
            continue;
        }
        if (need_samples) {
            need_samples = false;
            if (red.sample_dominance()) {
                red.update();
                need_balls = true;
            }
            continue;
        }
        break;
    }
    return Status::success();
}

}  // namespace

Problem make_kernel(const Reducer& red) {
    Problem P;
    const size_t n = red.n_, m = red.m_;
    std::vector<uint32_t> row_of(m, UINT32_MAX);
    for (uint32_t j = 0; j < m; ++j)
        if (red.s_alive[j]) { row_of[j] = uint32_t(P.row_id.size()); P.row_id.push_back(j); }
    for (uint32_t a = 0; a < n; ++a)
        if (red.b_alive[a]) P.col_id.push_back(a);
    P.R = uint32_t(P.row_id.size());
    P.C = uint32_t(P.col_id.size());
    P.cptr.assign(P.C + 1, 0);
    for (uint32_t c = 0; c < P.C; ++c) {
        const uint32_t a = P.col_id[c];
        P.cptr[c + 1] = P.cptr[c] + (red.bitwise_ ? red.size_[red.slot_[a]] : red.bsize(a));
    }
    P.crow.resize(P.cptr[P.C]);
    if (red.bitwise_) {
        // Rows in ascending order, each appended to its columns: the column lists come out
        // ascending (the bitsets are in label order, not in sample order).
        std::vector<uint32_t> col_of_slot(red.n_slots_, UINT32_MAX), next(P.cptr.begin(), P.cptr.end() - 1);
        for (uint32_t c = 0; c < P.C; ++c) col_of_slot[red.slot_[P.col_id[c]]] = c;
        for (uint32_t r = 0; r < P.R; ++r)
            Reducer::for_each_common(&red.bits_s_[size_t(red.label_[P.row_id[r]]) * red.wb_], red.alive_b_.data(),
                                     red.wb_, [&](uint32_t t) {
                                         const uint32_t c = col_of_slot[t];
                                         P.crow[next[c]++] = r;
                                         return false;
                                     });
    } else {
        for (uint32_t c = 0; c < P.C; ++c) {
            const uint32_t* l = red.samples_of(P.col_id[c]);
            uint32_t* out = &P.crow[P.cptr[c]];
            for (uint32_t k = 0, e = red.bsize(P.col_id[c]); k < e; ++k) *out++ = row_of[l[k]];
        }
    }
    fill_rows(P);
    return P;
}


Status reduce_coverage(const Coverage& cov, bool transpose_ok, const std::vector<uint8_t>& required,
                       const std::vector<uint8_t>& allowed, const std::vector<uint8_t>& locked, const Monitor& monitor,
                       std::vector<uint32_t>& forced, Problem& kernel) {
    const size_t n = cov.n_balls, m = cov.n_samples;
    Reducer red;
    red.s_alive = required;
    red.b_alive = allowed;
    bool masked = false;
    for (size_t j = 0; j < m && !masked; ++j) masked = !required[j];
    for (size_t a = 0; a < n && !masked; ++a) masked = !allowed[a] || locked[a];
    // forced_in balls: selected even if they cover nothing required (they were asked for)
    for (uint32_t a = 0; a < n; ++a)
        if (locked[a]) {
            red.forced.push_back(a);
            red.b_alive[a] = 0;
            for (uint32_t k = cov.ball_ptr[a]; k < cov.ball_ptr[a + 1]; ++k) red.s_alive[cov.ball_samples[k]] = 0;
        }
    if (transpose_ok) {
        red.init(n, m, cov.ball_ptr.data(), cov.ball_samples.data(), cov.sample_ptr.data(), cov.sample_balls.data(),
                 masked);
    } else {
        Coverage t;
        t.n_samples = m;
        t.n_balls = n;
        t.ball_ptr = cov.ball_ptr;
        t.ball_samples = cov.ball_samples;
        t.build_transpose();
        red.init(n, m, t.ball_ptr.data(), t.ball_samples.data(), t.sample_ptr.data(), t.sample_balls.data(), true);
    }
    Status st = reduce_fixpoint(red, monitor);
    if (!st.ok()) return st;
    forced = red.forced;
    kernel = make_kernel(red);
    return Status::success();
}

Status reduce_problem(const Problem& P, const Monitor& monitor, std::vector<uint32_t>& forced, Problem& kernel) {
    Reducer red;
    red.s_alive.assign(P.R, 1);
    red.b_alive.assign(P.C, 1);
    red.init(P.C, P.R, P.cptr.data(), P.crow.data(), P.rptr.data(), P.rcol.data(), false);
    Status st = reduce_fixpoint(red, monitor);
    if (!st.ok()) return st;
    forced = red.forced;
    kernel = make_kernel(red);
    return Status::success();
}

}  // namespace sc
}  // namespace ca

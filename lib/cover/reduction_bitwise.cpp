// reduction_bitwise.cpp: the reducer's steps once its state is bitwise (reducer.h): forcing by
// degree one, the sample-dominance passes and the later ball-dominance passes.
#include "reducer.h"

namespace ca {
namespace sc {

bool Reducer::force_degree_one_bits() {
    bool any = false;
    for (uint32_t j = 0; j < m_; ++j)
        if (bit(alive_s_.data(), j) && deg_[j] == 1) {
            uint32_t t = kNone;
            for_each_common(&bits_s_[size_t(j) * wb_], alive_b_.data(), wb_, [&](uint32_t u) {
                t = u;
                return true;
            });
            select_slot(t);
            any = true;
        }
    return any;
}

bool Reducer::sample_dominance_full() {
    samples_full_ = true;
    bool any = false;
    for (uint32_t k = 0; k < m_; ++k)
        if (bit(alive_s_.data(), k)) any |= sample_dominates(k);
    return any;
}

bool Reducer::sample_dominance_dirty() {
    bool any = false;
    for (uint32_t k = 0; k < m_; ++k) {
        if (!dirty_s_[k]) continue;
        dirty_s_[k] = 0;
        if (bit(alive_s_.data(), k)) any |= sample_dominates(k);
    }
    return any;
}

bool Reducer::sample_dominates(uint32_t k) {
    const uint32_t dk = deg_[k];
    WordSet& K = tested_;  // k's alive balls, by slot
    K.load_and(&bits_s_[size_t(k) * wb_], alive_b_.data(), wb_);
    uint32_t pick[3];
    if (!K.spread(pick)) return false;
    uint64_t* R = acc_.data();
    const uint64_t* X = &bits_b_[size_t(pick[0]) * ws_];
    const uint64_t* Y = &bits_b_[size_t(pick[1]) * ws_];
    const uint64_t* Z = &bits_b_[size_t(pick[2]) * ws_];
    for (size_t w = 0; w < ws_; ++w) R[w] = alive_s_[w] & X[w] & Y[w] & Z[w];
    clear_bit(R, k);
    bool any = false;
    for_each_bit(R, ws_, [&](uint32_t j) {
        if (!bit(alive_s_.data(), j) || deg_[j] < dk || !K.in(&bits_s_[size_t(j) * wb_])) return false;
        any = true;
        if (deg_[j] > dk || sample_of_label_[k] < sample_of_label_[j]) {
            kill_sample(j);  // k dominates j
            return false;
        }
        kill_sample(k);  // equal sets: the lower index j stays
        return true;
    });
    return any;
}

bool Reducer::ball_dominance_dirty() {
    bool any = false;
    for (uint32_t t = 0; t < n_slots_; ++t) {
        if (!dirty_slot_[t]) continue;
        dirty_slot_[t] = 0;
        if (!bit(alive_b_.data(), t)) continue;
        const uint32_t a = ball_of_slot_[t], na = size_[t];
        WordSet& A = tested_;  // a's alive samples
        A.load_and(&bits_b_[size_t(t) * ws_], alive_s_.data(), ws_);
        uint32_t pick[3];
        if (!A.spread(pick)) continue;
        uint64_t* R = acc_.data();
        const uint64_t* X = &bits_s_[size_t(pick[0]) * wb_];
        const uint64_t* Y = &bits_s_[size_t(pick[1]) * wb_];
        const uint64_t* Z = &bits_s_[size_t(pick[2]) * wb_];
        for (size_t w = 0; w < wb_; ++w) R[w] = alive_b_[w] & X[w] & Y[w] & Z[w];
        clear_bit(R, t);
        const bool dominated = for_each_bit(R, wb_, [&](uint32_t u) {
            if (size_[u] < na || (size_[u] == na && ball_of_slot_[u] > a)) return false;  // equal: lower index stays
            return A.in(&bits_b_[size_t(u) * ws_]);
        });
        if (dominated) {
            kill_ball(t);
            any = true;
        }
    }
    return any;
}

}  // namespace sc
}  // namespace ca

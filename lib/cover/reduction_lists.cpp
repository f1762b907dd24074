// reduction_lists.cpp: the reducer's list-based state (reducer.h): set up from the input's lists,
// and compacted in place after balls or samples died, until the first ball pass.
#include "reducer.h"

namespace ca {
namespace sc {

void Reducer::init(size_t n_balls, size_t n_samples, const uint32_t* ball_ptr, const uint32_t* ball_samples,
                   const uint32_t* sample_ptr, const uint32_t* sample_balls, bool masked) {
    n_ = n_balls;
    m_ = n_samples;
    bbeg_.assign(ball_ptr, ball_ptr + n_);
    bend_.assign(ball_ptr + 1, ball_ptr + n_ + 1);
    sbeg_.assign(sample_ptr, sample_ptr + m_);
    send_.assign(sample_ptr + 1, sample_ptr + m_ + 1);
    bs_ = ball_samples;
    sb_ = sample_balls;
    nnz_ = ball_ptr[n_];
    was_b_.assign(n_, 1);  // the first rebuild empties the lists of whatever is dead already
    was_s_.assign(m_, 1);
    mark_b_.assign(n_, 0);
    mark_s_.assign(m_, 0);
    dirty_s_.assign(m_, 0);
    for (size_t a = 0; a < n_; ++a)
        if (bend_[a] == bbeg_[a]) b_alive[a] = was_b_[a] = 0;
    if (masked) rebuild();
}

void Reducer::rebuild() {
    const bool from_input = !own_bs_ && nnz_ > 0;
    if (from_input) {  // not initialised: only the alive lists are ever read
        own_bs_.reset(new uint32_t[nnz_]);
        own_sb_.reset(new uint32_t[nnz_]);
    }
    // Newly dead balls / samples: mark the lists they appear in (all of them when many
    // died: marking is only a filter, compacting an unchanged list changes nothing).
    size_t dead_b = 0, dead_s = 0, alive_b = 0, alive_s = 0;
    for (size_t a = 0; a < n_; ++a) {
        dead_b += was_b_[a] && !b_alive[a];
        alive_b += b_alive[a];
    }
    for (size_t j = 0; j < m_; ++j) {
        dead_s += was_s_[j] && !s_alive[j];
        alive_s += s_alive[j];
    }
    const bool all_s = from_input || dead_b * 4 > alive_b, all_b = from_input || dead_s * 4 > alive_s;
    for (uint32_t a = 0; a < n_; ++a) {
        if (!was_b_[a] || b_alive[a]) continue;
        was_b_[a] = 0;
        if (!all_s)
            for (uint32_t k = bbeg_[a]; k < bend_[a]; ++k) mark_s_[bs_[k]] = 1;
        bend_[a] = bbeg_[a];
    }
    for (uint32_t j = 0; j < m_; ++j) {
        if (!was_s_[j] || s_alive[j]) continue;
        was_s_[j] = 0;
        if (!all_b)
            for (uint32_t k = sbeg_[j]; k < send_[j]; ++k) mark_b_[sb_[k]] = 1;
        send_[j] = sbeg_[j];
    }
    uint32_t* obs = own_bs_.get();
    uint32_t* osb = own_sb_.get();
    for (uint32_t a = 0; a < n_; ++a) {
        if (!b_alive[a] || !(all_b || mark_b_[a])) continue;
        mark_b_[a] = 0;
        uint32_t w = bbeg_[a];
        for (uint32_t k = bbeg_[a]; k < bend_[a]; ++k) {  // branch-free: most entries may go
            const uint32_t x = bs_[k];
            obs[w] = x;
            w += s_alive[x];
        }
        bend_[a] = w;
        if (w == bbeg_[a]) b_alive[a] = was_b_[a] = 0;  // its samples are all dead: no alive list has it
    }
    if (all_s) {
        // Most balls died: the sample lists are rebuilt from the alive balls' lists (ascending
        // ball order keeps them ascending), which costs what is left, not what was there.
        std::vector<uint32_t>& len = scratch_;
        len.assign(m_, 0);
        for (uint32_t a = 0; a < n_; ++a)
            if (b_alive[a])
                for (uint32_t k = bbeg_[a]; k < bend_[a]; ++k) {
                    const uint32_t j = obs[k];
                    osb[sbeg_[j] + len[j]++] = a;
                }
        for (uint32_t j = 0; j < m_; ++j) {
            if (!s_alive[j]) continue;
            send_[j] = sbeg_[j] + len[j];
        }
    } else {
        for (uint32_t j = 0; j < m_; ++j) {
            if (!s_alive[j] || !mark_s_[j]) continue;
            mark_s_[j] = 0;
            uint32_t w = sbeg_[j];
            for (uint32_t k = sbeg_[j]; k < send_[j]; ++k) {
                const uint32_t x = sb_[k];
                osb[w] = x;
                w += b_alive[x];
            }
            send_[j] = w;
        }
    }
    bs_ = obs;
    sb_ = osb;
}

}  // namespace sc
}  // namespace ca

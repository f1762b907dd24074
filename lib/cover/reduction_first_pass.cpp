// reduction_first_pass.cpp: the reducer's first ball-dominance pass (reducer.h), on the lists, which
// labels the samples, numbers the kept balls' slots and makes the state bitwise.
#include "reducer.h"

namespace ca {
namespace sc {

bool Reducer::ball_dominance_full() {
    balls_full_ = true;
    // counting sort by decreasing size, stable in the index
    uint32_t max_size = 0;
    for (uint32_t a = 0; a < n_; ++a)
        if (b_alive[a]) max_size = std::max(max_size, bsize(a));
    std::vector<uint32_t> start(size_t(max_size) + 2, 0), order;
    for (uint32_t a = 0; a < n_; ++a)
        if (b_alive[a]) start[max_size - bsize(a) + 1]++;
    for (size_t s = 0; s + 1 < start.size(); ++s) start[s + 1] += start[s];
    order.resize(start.back());
    for (uint32_t a = 0; a < n_; ++a)
        if (b_alive[a]) order[start[max_size - bsize(a)]++] = a;

    ws_ = (m_ + 63) / 64;
    label_.assign(m_, kNone);
    uint32_t n_labels = 0;
    slot_.assign(n_, UINT32_MAX);
    bits_b_.clear();
    bits_b_.reserve(order.size() * ws_);
    std::unique_ptr<uint32_t[]> kept(new uint32_t[nnz_]);  // kept ball slots per sample
    std::vector<uint32_t> nkept(m_, 0);
    WordSet& A = tested_;  // samples of the tested ball
    A.reset(ws_);
    uint32_t n_kept = 0;
    bool any = false;
    for (uint32_t a : order) {
        const uint32_t* la = samples_of(a);
        const uint32_t na = bsize(a);
        const uint32_t key = A.load_labelled(la, na, nkept.data(), label_.data(), n_labels);
        const uint32_t* cand = &kept[sbeg_[key]];
        bool dominated = false;
        for (uint32_t t = 0, nc = nkept[key]; t < nc && !dominated; ++t)
            dominated = A.in(&bits_b_[size_t(cand[t]) * ws_]);
        if (dominated) {
            b_alive[a] = 0;
            any = true;
            continue;
        }
        slot_[a] = n_kept;
        bits_b_.insert(bits_b_.end(), A.bits.begin(), A.bits.end());
        for (uint32_t k = 0; k < na; ++k) kept[sbeg_[la[k]] + nkept[la[k]]++] = n_kept;
        ++n_kept;
    }
    n_slots_ = n_kept;
    kept.reset();
    renumber_slots();
    for (uint32_t j = 0; j < m_; ++j)  // samples of no alive ball
        if (label_[j] == kNone) label_[j] = n_labels++;
    sample_of_label_.resize(m_);
    for (uint32_t j = 0; j < m_; ++j) sample_of_label_[label_[j]] = j;
    ball_of_slot_.resize(n_kept);
    for (uint32_t a = 0; a < n_; ++a)
        if (slot_[a] != UINT32_MAX) ball_of_slot_[slot_[a]] = a;
    // From here on the state is bitwise: the samples' bitsets of kept balls (by slot), the
    // alive sets, and the list sizes. The lists are not read any more: they (and `kept`) are
    // freed before the samples' bitsets are made, which bounds the peak memory (kept,
    // bits_b_ and bits_s_ are each large on large inputs). The kept balls of sample j
    // (kept[sbeg_[j] ...]) are the slots whose bitset has j: bits_s_ is bits_b_ transposed.
    size_.resize(n_kept);
    for (uint32_t t = 0; t < n_kept; ++t) size_[t] = bsize(ball_of_slot_[t]);
    release_lists();
    wb_ = (size_t(n_kept) + 63) / 64;
    bits_s_.assign(m_ * wb_, 0);
    for (uint32_t t = 0; t < n_kept; ++t)
        for_each_bit(&bits_b_[size_t(t) * ws_], ws_, [&](uint32_t j) {
            set_bit(&bits_s_[size_t(j) * wb_], t);
            return false;
        });
    alive_b_.assign(wb_, 0);
    for (uint32_t t = 0; t < n_kept; ++t) set_bit(alive_b_.data(), t);
    alive_s_.assign(ws_, 0);
    deg_.assign(m_, 0);
    for (uint32_t j = 0; j < m_; ++j)
        if (s_alive[j]) {
            set_bit(alive_s_.data(), label_[j]);
            deg_[label_[j]] = nkept[j];
        }
    dirty_slot_.assign(n_kept, 0);
    acc_.assign(std::max(ws_, wb_), 0);
    tested_.reset(std::max(ws_, wb_));
    bitwise_ = true;
    return any;
}

void Reducer::renumber_slots() {
    std::vector<uint32_t> first(n_slots_), start(m_ + 1, 0), slot_of(n_slots_);
    for (uint32_t t = 0; t < n_slots_; ++t) {
        const uint64_t* row = &bits_b_[size_t(t) * ws_];
        size_t w = 0;
        while (row[w] == 0) ++w;  // a kept ball has a sample
        first[t] = uint32_t(w * 64 + __builtin_ctzll(row[w]));
        start[first[t] + 1]++;
    }
    for (size_t j = 0; j < m_; ++j) start[j + 1] += start[j];
    for (uint32_t t = 0; t < n_slots_; ++t) slot_of[t] = start[first[t]]++;
    std::vector<uint64_t> bits(bits_b_.size());
    for (uint32_t t = 0; t < n_slots_; ++t)
        std::copy_n(&bits_b_[size_t(t) * ws_], ws_, &bits[size_t(slot_of[t]) * ws_]);
    bits_b_.swap(bits);
    for (uint32_t& t : slot_)
        if (t != UINT32_MAX) t = slot_of[t];
}

void Reducer::release_lists() {
    own_bs_.reset();
    own_sb_.reset();
    bs_ = sb_ = nullptr;
    release(bbeg_);
    release(bend_);
    release(sbeg_);
    release(send_);
    release(was_b_);
    release(was_s_);
    release(mark_b_);
    release(mark_s_);
    release(scratch_);
}

}  // namespace sc
}  // namespace ca

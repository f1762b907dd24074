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
// Cost. The first ball-dominance pass runs on the whole input (~13 000 balls, ~1 500 samples,
// up to ~800 000 pairs) and removes most balls; the later passes only revisit what changed:
//  - first ball pass (on lists): balls in order of decreasing size (ties: lower index first),
//    each tested only against the balls kept so far (an element's dominators come before it in
//    that order, and a dropped dominator has a kept one of its own), taken from the list of
//    kept balls of its sample with the fewest kept balls; elements are bitsets of their
//    members (24 words for 1500 samples), so a subset test is a few word operations. A sample's
//    bit is its label, given in order of first appearance in that pass: a ball's samples then
//    fall in few words rather than spread over all of them, which every later bitset test profits from
//    (only the tie between equal samples and the kernel's lists use sample indices);
//    likewise the kept balls' slots are numbered by their smallest label, which brings the
//    balls of a sample into few words;
//  - after it, only the balls it kept can be alive: they get slots 0, 1, ..., and the state
//    becomes bitwise (samples of each slot, slots of each sample, alive sets, list sizes kept
//    up to date as elements die), so nothing is ever rebuilt;
//  - sample passes: each sample k tested as a dominator against the alive samples in three of
//    its balls (an AND of bitsets), one word test per candidate;
//  - later ball passes: a pair can only become a dominance when the dominated ball lost a
//    sample (a sample pass: the dominating sample lost a ball), so only those are tested,
//    against the alive balls containing three of their samples (an AND of bitsets).
// Before the first ball pass (forcing on the input), lists are compacted in place, only those
// that lost an element.
#include "setcover_internal.h"

#include <algorithm>
#include <memory>

namespace ca {
namespace sc {

namespace {

// Reduction on the original index space. Dead balls / samples keep empty lists.
class Reducer {
public:
    std::vector<uint8_t> s_alive, b_alive;  // sample still to be covered / ball still a candidate
    std::vector<uint32_t> forced;           // selected by the reduction (forced_in + degree 1)

    // Starts from the given lists (both directions, ascending, consistent) with the alive flags
    // already set: the lists are used as they are until the first change (no copy) and then
    // copied, restricted to what is alive, into the reducer's own arrays (same offsets). With
    // `masked`, some flags are already off: the lists are restricted at once (the given lists
    // need not outlive init then).
    void init(size_t n_balls, size_t n_samples, const uint32_t* ball_ptr, const uint32_t* ball_samples,
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

    uint32_t bsize(uint32_t a) const { return bend_[a] - bbeg_[a]; }
    uint32_t sdeg(uint32_t j) const { return send_[j] - sbeg_[j]; }
    const uint32_t* balls_of(uint32_t j) const { return sb_ + sbeg_[j]; }   // alive, ascending
    const uint32_t* samples_of(uint32_t a) const { return bs_ + bbeg_[a]; }  // alive, ascending

    // Bring the lists up to date after balls / samples died (only before the first ball pass,
    // see update): the lists of the balls that lost a sample and of the samples that lost a ball
    // are compacted in place (all of them the first time, from the input's arrays into the
    // reducer's own). A ball left without samples dies.
    void rebuild() {
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

    void select(uint32_t b) {
        forced.push_back(b);
        b_alive[b] = 0;
        for (uint32_t k = bbeg_[b]; k < bend_[b]; ++k) s_alive[bs_[k]] = 0;
    }

    // Samples with exactly one candidate ball force that ball.
    bool force_degree_one() {
        if (bitwise_) return force_degree_one_bits();
        bool any = false;
        for (uint32_t j = 0; j < m_; ++j)
            if (s_alive[j] && sdeg(j) == 1) {
                select(sb_[sbeg_[j]]);
                any = true;
            }
        return any;
    }

    bool ball_dominance() { return balls_full_ ? ball_dominance_dirty() : ball_dominance_full(); }
    bool sample_dominance() { return samples_full_ ? sample_dominance_dirty() : sample_dominance_full(); }

    // After the first ball pass the state is kept in bitsets (see below): nothing to rebuild.
    void update() {
        if (!bitwise_) rebuild();
    }

private:
    // First ball pass. Balls in order of decreasing size, ties lower index first: every
    // dominator of a ball comes before it, and a dominator that was itself dropped has a kept
    // dominator before it (dominance is transitive), so a ball is dominated iff a ball kept
    // earlier contains it. The kept balls containing sample j are listed in
    // kept[sbeg_[j] ...] (at most sdeg(j) of them); a ball is tested against the kept balls
    // of its sample with the fewest, all of its samples at once (bitsets).
    bool ball_dominance_full() {
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

    // Slots (kept balls) in order of their smallest label, ties in slot order: near balls get
    // near slots, so that the balls of a sample fall in few words too. Slots only decide where
    // bits go, never a result.
    void renumber_slots() {
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

    // The lists (and what maintains them) once the state is bitwise: only the bitsets are read.
    template <class T>
    static void release(std::vector<T>& v) { std::vector<T>().swap(v); }
    void release_lists() {
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

    // ---- Bitwise state (after the first ball pass) ----
    // Ball slot t: its samples at the first pass (bits_b_, ws_ words), size_[t] of them alive;
    // sample j: its kept balls' slots (bits_s_, wb_ words), deg_[j] of them alive; alive_s_ /
    // alive_b_: the alive sets. A member of a static bitset that died is masked by the alive
    // set, so (static & alive) is always the current list. Deaths update the sizes and the dirty
    // flags at once (the lists of the list-based version would change at the next rebuild; no
    // phase result depends on it: a phase only uses the sizes of the side it does not remove
    // from, and the other side's sizes only choose which candidates to look at).
    static constexpr uint32_t kNone = UINT32_MAX;

    void kill_ball(uint32_t t) {
        clear_bit(alive_b_.data(), t);
        b_alive[ball_of_slot_[t]] = 0;
        for_each_common(&bits_b_[size_t(t) * ws_], alive_s_.data(), ws_, [&](uint32_t j) {
            deg_[j]--;
            if (samples_full_) dirty_s_[j] = 1;
            return false;
        });
    }
    void kill_sample(uint32_t j) {
        clear_bit(alive_s_.data(), j);
        s_alive[sample_of_label_[j]] = 0;
        for_each_common(&bits_s_[size_t(j) * wb_], alive_b_.data(), wb_, [&](uint32_t t) {
            dirty_slot_[t] = 1;
            if (--size_[t] == 0) kill_ball(t);  // empty ball (it has no alive sample left)
            return false;
        });
    }
    void select_slot(uint32_t t) {
        forced.push_back(ball_of_slot_[t]);
        kill_ball(t);
        for_each_common(&bits_b_[size_t(t) * ws_], alive_s_.data(), ws_, [&](uint32_t j) {
            kill_sample(j);
            return false;
        });
    }

    bool force_degree_one_bits() {
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

    // Sample passes: sample j is dropped if an alive sample k has balls(k) ⊆ balls(j) (equal
    // sets: keep the lower index). Each sample k is tested as a dominator: the candidates j are
    // the alive samples in three of k's balls (the first, a middle and the last slot: an AND of
    // bitsets), each checked with k's balls against j's, one word operation per word. The first
    // pass tests every alive sample, the later ones only the samples that lost a ball since: a
    // pair (k, j) can only become a dominance (balls(k) ⊆ balls(j)) when k loses a ball.
    bool sample_dominance_full() {
        samples_full_ = true;
        bool any = false;
        for (uint32_t k = 0; k < m_; ++k)
            if (bit(alive_s_.data(), k)) any |= sample_dominates(k);
        return any;
    }
    bool sample_dominance_dirty() {
        bool any = false;
        for (uint32_t k = 0; k < m_; ++k) {
            if (!dirty_s_[k]) continue;
            dirty_s_[k] = 0;
            if (bit(alive_s_.data(), k)) any |= sample_dominates(k);
        }
        return any;
    }

    // Drops the samples that alive sample k dominates (or k itself, if an equal sample of lower
    // index exists); true if any was dropped. A dropped sample's dominator dominates what it
    // does, so the order of the tests does not change the outcome.
    bool sample_dominates(uint32_t k) {
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

    // Later ball passes: a pair (a, b) can only become a dominance (samples(a) ⊆ samples(b))
    // when a loses a sample, so only those balls are tested: the candidates b are the alive
    // balls containing three of a's samples (the first, a middle and the last: an AND of
    // bitsets), each checked with a's samples against b's.
    bool ball_dominance_dirty() {
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

    // Calls f on the set bits in increasing order until it returns true; true if it did.
    template <class F>
    static bool for_each_bit(const uint64_t* bits, size_t words, F f) {
        for (size_t w = 0; w < words; ++w)
            for (uint64_t x = bits[w]; x; x &= x - 1)
                if (f(uint32_t(w * 64 + __builtin_ctzll(x)))) return true;
        return false;
    }
    // Calls f on the members of x & y in increasing order until it returns true.
    template <class F>
    static bool for_each_common(const uint64_t* x, const uint64_t* y, size_t words, F f) {
        for (size_t w = 0; w < words; ++w)
            for (uint64_t v = x[w] & y[w]; v; v &= v - 1)
                if (f(uint32_t(w * 64 + __builtin_ctzll(v)))) return true;
        return false;
    }
    static void set_bit(uint64_t* bits, uint32_t x) { bits[x >> 6] |= uint64_t(1) << (x & 63); }
    static void clear_bit(uint64_t* bits, uint32_t x) { bits[x >> 6] &= ~(uint64_t(1) << (x & 63)); }
    static bool bit(const uint64_t* bits, uint32_t x) { return (bits[x >> 6] >> (x & 63)) & 1; }

    // The tested element as a bitset that knows its non-zero words: subset tests look at those
    // only and stop at the first word with a member outside the other set.
    struct WordSet {
        std::vector<uint64_t> bits;
        std::vector<uint32_t> nz;  // nz[0 .. n_nz): the words with a member
        uint32_t n_nz = 0;
        void reset(size_t words) {
            bits.assign(words, 0);
            nz.assign(words + 1, 0);
            n_nz = 0;
        }
        void clear() {
            for (uint32_t i = 0; i < n_nz; ++i) bits[nz[i]] = 0;
            n_nz = 0;
        }
        // Members label[x] for x in a list, labelling the members without one (label[x] ==
        // kNone) next, next + 1, ...; returns the x with the smallest rarity[x] (ties: the first).
        uint32_t load_labelled(const uint32_t* list, uint32_t len, const uint32_t* rarity, uint32_t* label,
                               uint32_t& next) {
            clear();
            uint64_t* b = bits.data();
            uint32_t* z = nz.data();
            uint32_t c = 0, key = list[0], rk = rarity[list[0]];
            for (uint32_t k = 0; k < len; ++k) {
                const uint32_t x = list[k], r = rarity[x];
                key = r < rk ? x : key;
                rk = r < rk ? r : rk;
                if (label[x] == kNone) label[x] = next++;
                const uint32_t w = label[x] >> 6;
                z[c] = w;  // branch-free: a word is listed when its first member arrives
                c += b[w] == 0;
                b[w] |= uint64_t(1) << (label[x] & 63);
            }
            n_nz = c;
            return key;
        }
        // members: x & y (words words)
        void load_and(const uint64_t* x, const uint64_t* y, size_t words) {
            clear();
            uint64_t* b = bits.data();
            uint32_t* z = nz.data();
            uint32_t c = 0;
            for (size_t w = 0; w < words; ++w) {
                const uint64_t v = x[w] & y[w];
                b[w] = v;
                z[c] = uint32_t(w);
                c += v != 0;
            }
            n_nz = c;
        }
        // Three members spread over the set (lowest, one of the middle word, highest); false if
        // the set is empty.
        bool spread(uint32_t pick[3]) const {
            if (n_nz == 0) return false;
            const uint32_t lo = nz[0], mid = nz[n_nz / 2], hi = nz[n_nz - 1];
            pick[0] = lo * 64 + uint32_t(__builtin_ctzll(bits[lo]));
            pick[1] = mid * 64 + uint32_t(__builtin_ctzll(bits[mid]));
            pick[2] = hi * 64 + 63 - uint32_t(__builtin_clzll(bits[hi]));
            return true;
        }
        bool in(const uint64_t* y) const {
            for (uint32_t i = 0; i < n_nz; ++i)
                if (bits[nz[i]] & ~y[nz[i]]) return false;
            return true;
        }
    };

    size_t n_ = 0, m_ = 0, nnz_ = 0;
    // list of ball a: bs_[bbeg_[a] .. bend_[a]), of sample j: sb_[sbeg_[j] .. send_[j])
    std::vector<uint32_t> bbeg_, bend_, sbeg_, send_;
    const uint32_t* bs_ = nullptr;
    const uint32_t* sb_ = nullptr;
    std::unique_ptr<uint32_t[]> own_bs_, own_sb_;
    std::vector<uint8_t> was_b_, was_s_;    // alive at the last rebuild
    std::vector<uint8_t> mark_b_, mark_s_;  // list to compact at the next rebuild
    bool balls_full_ = false, samples_full_ = false;
    std::vector<uint8_t> dirty_s_;  // sample lost a ball since its last test (after the first sample pass)
    // Bitsets: samples of each ball kept by the first ball pass (by slot, ws_ words each) and
    // balls (by slot) of each sample (wb_ words each).
    std::vector<uint32_t> slot_;
    std::vector<uint32_t> label_, sample_of_label_;  // sample j is bit label_[j] of the bitsets
    uint32_t n_slots_ = 0;
    size_t ws_ = 0, wb_ = 0;
    std::vector<uint64_t> bits_b_, bits_s_;
    std::vector<uint32_t> ball_of_slot_;
    bool bitwise_ = false;
    std::vector<uint64_t> alive_s_, alive_b_, acc_;  // alive sets, candidates
    std::vector<uint32_t> deg_, size_;               // alive balls of a sample, alive samples of a slot
    std::vector<uint8_t> dirty_slot_;                // ball lost a sample since its last test
    WordSet tested_;
    std::vector<uint32_t> scratch_;

    friend Problem make_kernel(const Reducer& red);
};

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

// The kernel as a compact problem (lists ascending in both directions).
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

}  // namespace

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

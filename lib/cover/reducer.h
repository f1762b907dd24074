// reducer.h: the state of the set-cover reduction (reduction.cpp) on the original index space, and
// its steps, one file each: reduction_lists.cpp (the list-based state and its compaction),
// reduction_first_pass.cpp (the first ball-dominance pass, which makes the state bitwise) and
// reduction_bitwise.cpp (forcing and the dominance passes on bitsets). Internal header.
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
#pragma once
#include "setcover_internal.h"

#include <algorithm>
#include <memory>

namespace ca {
namespace sc {

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
              const uint32_t* sample_ptr, const uint32_t* sample_balls, bool masked);

    uint32_t bsize(uint32_t a) const { return bend_[a] - bbeg_[a]; }
    uint32_t sdeg(uint32_t j) const { return send_[j] - sbeg_[j]; }
    const uint32_t* balls_of(uint32_t j) const { return sb_ + sbeg_[j]; }   // alive, ascending
    const uint32_t* samples_of(uint32_t a) const { return bs_ + bbeg_[a]; }  // alive, ascending

    // Bring the lists up to date after balls / samples died (only before the first ball pass,
    // see update): the lists of the balls that lost a sample and of the samples that lost a ball
    // are compacted in place (all of them the first time, from the input's arrays into the
    // reducer's own). A ball left without samples dies.
    void rebuild();

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
    bool ball_dominance_full();

    // Slots (kept balls) in order of their smallest label, ties in slot order: near balls get
    // near slots, so that the balls of a sample fall in few words too. Slots only decide where
    // bits go, never a result.
    void renumber_slots();

    // The lists (and what maintains them) once the state is bitwise: only the bitsets are read.
    template <class T>
    static void release(std::vector<T>& v) { std::vector<T>().swap(v); }
    void release_lists();

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

    bool force_degree_one_bits();

    // Sample passes: sample j is dropped if an alive sample k has balls(k) ⊆ balls(j) (equal
    // sets: keep the lower index). Each sample k is tested as a dominator: the candidates j are
    // the alive samples in three of k's balls (the first, a middle and the last slot: an AND of
    // bitsets), each checked with k's balls against j's, one word operation per word. The first
    // pass tests every alive sample, the later ones only the samples that lost a ball since: a
    // pair (k, j) can only become a dominance (balls(k) ⊆ balls(j)) when k loses a ball.
    bool sample_dominance_full();
    bool sample_dominance_dirty();

    // Drops the samples that alive sample k dominates (or k itself, if an equal sample of lower
    // index exists); true if any was dropped. A dropped sample's dominator dominates what it
    // does, so the order of the tests does not change the outcome.
    bool sample_dominates(uint32_t k);

    // Later ball passes: a pair (a, b) can only become a dominance (samples(a) ⊆ samples(b))
    // when a loses a sample, so only those balls are tested: the candidates b are the alive
    // balls containing three of a's samples (the first, a middle and the last: an AND of
    // bitsets), each checked with a's samples against b's.
    bool ball_dominance_dirty();

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

// The kernel as a compact problem (lists ascending in both directions).
Problem make_kernel(const Reducer& red);

}  // namespace sc
}  // namespace ca

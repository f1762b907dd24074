// rng.h: the library's portable seeded random generators: the same numbers on every platform for
// a seed (std:: distributions are implementation-defined, so they are not used for results).
#pragma once
#include <cstdint>

namespace ca {

// splitmix64 (Steele, Lea & Flood 2014): one 64-bit state, one multiply-xorshift output per
// step. Seeds Rng; used alone where a cheap stream of integers is enough (the local search).
struct SplitMix64 {
    uint64_t state;
    uint64_t next() {
        uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
};

// splitmix64-seeded xoshiro256**: fixed algorithm, so a seed gives the same stream everywhere
// (std:: distributions are implementation-defined, so they are not used for results).
class Rng {
public:
    explicit Rng(uint64_t seed) {
        SplitMix64 seeder{seed};
        for (auto& s : s_) s = seeder.next();
    }
    uint64_t next() {
        const uint64_t result = rotl(s_[1] * 5, 7) * 9;
        const uint64_t t = s_[1] << 17;
        s_[2] ^= s_[0]; s_[3] ^= s_[1]; s_[1] ^= s_[2]; s_[0] ^= s_[3];
        s_[2] ^= t; s_[3] = rotl(s_[3], 45);
        return result;
    }
    double uniform() { return double(next() >> 11) * (1.0 / 9007199254740992.0); }  // [0,1)
    uint64_t below(uint64_t n) { return n ? next() % n : 0; }
private:
    static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
    uint64_t s_[4];
};

}  // namespace ca

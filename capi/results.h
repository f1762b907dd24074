// results.h: the opaque result objects. A candidate set is reference counted: each selection
// made from it holds a reference, so destroying the set before its selections is safe (the set
// is freed with its last selection) and ca_connect's "same set" check cannot match a reused
// address. Skeletons and proxy sets copy what they need and hold nothing.
#pragma once

#include "context.h"

#include "candidates.h"
#include "selection.h"

#include <atomic>

struct ca_candidate_set {
    capi::Allocator allocator;
    mutable std::atomic<int> references{1};  // the caller's handle + one per live selection
    ca::CandidateSet core;
    capi::Array<double> centers, radii, samples;
    void release_arrays() { centers.release(allocator); radii.release(allocator); samples.release(allocator); }
};

struct ca_selection {
    capi::Allocator allocator;
    const ca_candidate_set* set = nullptr;  // a reference held (retain_set) while set
    ca::Selection core;
    capi::Array<uint32_t> indices, uncovered;
    capi::Array<double> centers, radii, dilated;
    ca_select_stats stats{};
    void release_arrays();
};

struct ca_skeleton {
    capi::Allocator allocator;
    capi::Array<double> centers, radii;
    capi::Array<uint32_t> edges, faces;
    ca_skeleton_stats stats{};
    void release_arrays() {
        centers.release(allocator); radii.release(allocator); edges.release(allocator); faces.release(allocator);
    }
};

// Engine proxies (ca_proxies.cpp): copies of the primitives, nothing held.
struct ca_proxy_set {
    capi::Allocator allocator;
    capi::Array<int32_t> kinds;
    capi::Array<double> centers, radii;
    capi::Array<double> frames;   // a box's edge directions (3 columns) then half-lengths: 12 per primitive
    ca_proxy_stats stats{};
    void release_arrays() {
        kinds.release(allocator); centers.release(allocator); radii.release(allocator); frames.release(allocator);
    }
};

// Bone colliders (ca_bone_colliders.cpp): copies of the colliders (joint frames), nothing held.
struct ca_bone_colliders {
    capi::Allocator allocator;
    capi::Array<uint32_t> joints;
    capi::Array<int32_t> kinds;
    capi::Array<double> centers, radii;   // a then b (6), radius of a, of b (2) per collider
    capi::Array<double> contained, overlap;
    ca_bone_collider_stats stats{};
    void release_arrays() {
        joints.release(allocator); kinds.release(allocator); centers.release(allocator); radii.release(allocator);
        contained.release(allocator); overlap.release(allocator);
    }
};

namespace capi {
inline void retain_set(const ca_candidate_set* set) { set->references.fetch_add(1, std::memory_order_relaxed); }
// Frees the set when the last reference goes.
inline void release_set(const ca_candidate_set* set) {
    if (set && set->references.fetch_sub(1, std::memory_order_acq_rel) == 1)
        destroy_result(const_cast<ca_candidate_set*>(set));
}
}  // namespace capi

inline void ca_selection::release_arrays() {
    indices.release(allocator); uncovered.release(allocator);
    centers.release(allocator); radii.release(allocator); dilated.release(allocator);
    capi::release_set(set);
    set = nullptr;
}

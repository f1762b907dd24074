// fox_candidates.h: the candidate set of tests/data/fox.obj at small sample counts (800 cover,
// 2000 Voronoi samples), the shared fixture of the delta-search tests (doctest only).
#pragma once
#include "candidates.h"
#include "mesh_io.h"
#include "support/mesh_convert.h"

#include <doctest/doctest.h>

#include <string>

inline ca::CandidateSet fox_candidate_set() {
    caio::MeshData data;
    std::string error;
    REQUIRE_MESSAGE(caio::read_mesh(std::string(CA_TEST_DATA) + "/fox.obj", data, error), error);
    ca::Surface surface;
    REQUIRE(ca::prepare_surface(to_core_mesh(data), {}, surface).ok());
    ca::CandidateOptions co;
    co.cover_samples = 800;
    co.voronoi_samples = 2000;
    ca::CandidateSet set;
    REQUIRE(ca::generate_candidates(std::move(surface), co, ca::Monitor{}, set).ok());
    return set;
}

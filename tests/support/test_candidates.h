// test_candidates.h: the candidate set of a bundled model at small sample counts, the shared
// fixture of the search tests (doctest only): fox.obj at 800 cover and 2000 Voronoi samples, or
// any file of tests/data at the counts a test gives.
#pragma once
#include "candidates.h"
#include "mesh_io.h"
#include "support/mesh_convert.h"

#include <doctest/doctest.h>

#include <string>

inline ca::CandidateSet candidate_set_of(const std::string& file, uint32_t cover_samples, uint32_t voronoi_samples) {
    caio::MeshData data;
    std::string error;
    REQUIRE_MESSAGE(caio::read_mesh(std::string(CA_TEST_DATA) + "/" + file, data, error), error);
    ca::Surface surface;
    REQUIRE(ca::prepare_surface(to_core_mesh(data), {}, surface).ok());
    ca::CandidateOptions co;
    co.cover_samples = cover_samples;
    co.voronoi_samples = voronoi_samples;
    ca::CandidateSet set;
    REQUIRE(ca::generate_candidates(std::move(surface), co, ca::Monitor{}, set).ok());
    return set;
}

inline ca::CandidateSet fox_candidate_set() { return candidate_set_of("fox.obj", 800, 2000); }

// skeleton_of.h: the default pipeline's skeleton of a mesh (the steps the C ABI runs, medial route),
// in the mesh's units; and tests/data models read as core meshes (doctest only).
#pragma once
#include "mesh_io.h"
#include "steps.h"
#include "support/mesh_convert.h"

#include <doctest/doctest.h>

#include <string>

inline ca::Skeleton skeleton_of(const ca::Mesh& mesh) {
    ca::SurfaceInput surface;
    surface.mesh = mesh;
    ca::CandidateSet set;
    ca::Status st = ca::candidates_step(surface, ca::CandidateOptions{}, ca::Monitor{}, set);
    REQUIRE_MESSAGE(st.ok(), st.message);
    ca::SelectRequest sr;
    sr.select.cover.time_limit_s = 0;   // proven optimal: the same cover on any machine
    ca::SelectResult sel;
    st = ca::select_step(set, sr, ca::Monitor{}, sel);
    REQUIRE_MESSAGE(st.ok(), st.message);
    ca::ConnectResult k;
    st = ca::connect_step(set, sel.selection, ca::ConnectRequest{}, ca::Monitor{}, k);
    REQUIRE_MESSAGE(st.ok(), st.message);
    ca::Skeleton s = k.skeleton;
    for (ca::Ball& b : s.balls) {
        b.center = set.surface.norm.to_user(b.center);
        b.radius *= set.surface.norm.scale;
    }
    return s;
}

inline ca::Mesh test_model(const std::string& name) {
    caio::MeshData data;
    std::string error;
    REQUIRE_MESSAGE(caio::read_mesh(std::string(CA_TEST_DATA) + "/" + name, data, error), error);
    return to_core_mesh(data);
}

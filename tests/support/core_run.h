// core_run.h: the three core steps (generate_candidates -> select_balls -> connect_balls) on a
// prepared surface, for the tests of the pipeline on meshes and on point clouds. The exact cover
// runs without a time limit, so results do not depend on the machine's load; the skeleton's balls
// come back in the input's own units.
#pragma once
#include "candidates.h"
#include "connect.h"
#include "selection.h"

#include <doctest/doctest.h>

struct CoreRun {
    ca::CandidateSet set;
    ca::Selection sel;
    ca::Skeleton skeleton;
};

inline CoreRun core_run(ca::Surface surface, const ca::CandidateOptions& copt, ca::SelectOptions sopt,
                        const ca::ConnectOptions& kopt) {
    CoreRun r;
    sopt.cover.time_limit_s = 0;
    ca::Monitor monitor;
    ca::Status st = ca::generate_candidates(std::move(surface), copt, monitor, r.set);
    REQUIRE_MESSAGE(st.ok(), st.message);
    st = ca::select_balls(r.set, sopt, monitor, r.sel);
    REQUIRE_MESSAGE(st.ok(), st.message);
    st = ca::connect_balls(r.set, r.sel, kopt, monitor, r.skeleton);
    REQUIRE_MESSAGE(st.ok(), st.message);
    for (ca::Ball& b : r.skeleton.balls) {
        b.center = r.set.surface.norm.to_user(b.center);
        b.radius *= r.set.surface.norm.scale;
    }
    return r;
}

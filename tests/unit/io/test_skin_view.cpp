// test_skin_view.cpp: caio::skin_view (examples/io/skin_view.h), the C ABI's view of a skin read
// with a mesh: it borrows SkinData's arrays as they are, and the library accepts the skins the
// readers give, glTF and FBX alike (the FBX's matrices carry its centimetre scale), building one
// bone collider per joint that dominates enough of the character, each on a joint of the file.
#include <doctest/doctest.h>

#include <coverage_axis.h>

#include <string>

#include "mesh_io.h"
#include "skin_view.h"
#include "surface_view.h"

namespace {

caio::MeshData must_read(const std::string& path) {
    caio::MeshData m;
    std::string err;
    const bool ok = caio::read_mesh(path, m, err);
    INFO(err);
    REQUIRE(ok);
    return m;
}

}  // namespace

TEST_CASE("skin view: borrows the read skin's arrays, and the library builds colliders from it") {
    for (const char* file : {"snake.glb", "snake.fbx"}) {
        CAPTURE(file);
        const caio::MeshData m = must_read(std::string(CA_TEST_DATA) + "/rigged/" + file);
        const ca_skin_view v = caio::skin_view(m);
        CHECK(v.struct_size == sizeof(ca_skin_view));
        CHECK(v.joint_count == 8);
        CHECK(v.vertex_count == m.positions.size() / 3);
        CHECK(v.influences == m.skin.influences);
        CHECK(v.parents == m.skin.parents.data());
        CHECK(v.inverse_bind == m.skin.inverse_bind.data());
        CHECK(v.vertex_joints == m.skin.vertex_joints.data());
        CHECK(v.vertex_weights == m.skin.vertex_weights.data());

        ca_context* ctx = nullptr;
        REQUIRE(ca_context_create(nullptr, &ctx) == CA_OK);
        const ca_surface_view surface = caio::surface_view(m);
        ca_candidate_options co;
        ca_candidate_options_init(&co);
        co.cover_samples = 600;
        co.voronoi_samples = 1500;
        ca_candidate_set* set = nullptr;
        REQUIRE(ca_candidates(ctx, &surface, &co, &set) == CA_OK);
        ca_bone_collider_options bo;
        REQUIRE(ca_bone_collider_options_defaults(&bo, sizeof bo) == CA_OK);
        bo.evaluate_samples = 5000;
        ca_bone_colliders* c = nullptr;
        const ca_status st = ca_bone_colliders_build(ctx, set, nullptr, &v, &bo, &c);
        INFO(ca_context_last_error(ctx));
        REQUIRE(st == CA_OK);
        // every segment of the snake drives a fair share of it
        CHECK(ca_bone_colliders_count(c) >= 6);
        for (size_t i = 0; i < ca_bone_colliders_count(c); ++i) CHECK(ca_bone_colliders_joints(c)[i] < 8);
        ca_bone_collider_stats stats;
        stats.struct_size = sizeof stats;
        REQUIRE(ca_bone_colliders_stats(c, &stats) == CA_OK);
        CHECK(stats.contained_fraction > 0.9);
        ca_bone_colliders_destroy(c);

        // a view of no skin is refused, not read
        const ca_skin_view none = caio::skin_view(caio::MeshData{});
        CHECK(none.joint_count == 0);
        c = nullptr;
        CHECK(ca_bone_colliders_build(ctx, set, nullptr, &none, &bo, &c) != CA_OK);
        CHECK(c == nullptr);
        ca_candidate_set_destroy(set);
        ca_context_destroy(ctx);
    }
}

// test_skin.cpp: tests of the skin the readers fill (caio::SkinData): the rigged characters of
// tests/data/rigged (made by make_rigged.py in Blender) against the joints the script built, their
// glTF against their FBX (and the snake's Collada), small glTF skins written here (8 influences, integer weights,
// unskinned meshes beside skinned ones, and bad skins that must be refused), assimp scenes built by
// hand (the heaviest 8 weights kept, bones that bind one joint differently) and the tool's own
// --rig output read back.
#include <doctest/doctest.h>

#include <assimp/material.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "assimp_shapes.h"
#include "gltf_builder.h"
#include "io_test_util.h"
#include "mesh_io.h"
#include "readers.h"
#include "rig_writer.h"

namespace {

const std::string kRigged = std::string(CA_TEST_DATA) + "/rigged/";

// A joint as make_rigged.py builds it: its parent ("" for the root) and its head in Blender's
// coordinates (+Z up).
struct JointSpec {
    const char* name;
    const char* parent;
    double head[3];
};

const std::map<std::string, std::vector<JointSpec>>& rigs() {
    static const std::map<std::string, std::vector<JointSpec>> r = {
        {"humanoid",
         {{"hips", "", {0, 0, 0.95}}, {"spine", "hips", {0, 0, 1.10}}, {"chest", "spine", {0, 0, 1.30}},
          {"neck", "chest", {0, 0, 1.50}}, {"head", "neck", {0, 0, 1.62}},
          {"upper_arm.L", "chest", {0.20, 0, 1.45}}, {"forearm.L", "upper_arm.L", {0.48, 0, 1.45}},
          {"upper_arm.R", "chest", {-0.20, 0, 1.45}}, {"forearm.R", "upper_arm.R", {-0.48, 0, 1.45}},
          {"thigh.L", "hips", {0.10, 0, 0.90}}, {"shin.L", "thigh.L", {0.10, 0, 0.50}}, {"foot.L", "shin.L", {0.10, 0, 0.10}},
          {"thigh.R", "hips", {-0.10, 0, 0.90}}, {"shin.R", "thigh.R", {-0.10, 0, 0.50}}, {"foot.R", "shin.R", {-0.10, 0, 0.10}}}},
        {"quadruped",
         {{"pelvis", "", {0, 0.35, 0.70}}, {"spine", "pelvis", {0, 0.10, 0.72}}, {"chest", "spine", {0, -0.15, 0.74}},
          {"neck", "chest", {0, -0.38, 0.76}}, {"head", "neck", {0, -0.55, 0.95}},
          {"tail.1", "pelvis", {0, 0.45, 0.72}}, {"tail.2", "tail.1", {0, 0.63, 0.76}}, {"tail.3", "tail.2", {0, 0.81, 0.80}},
          {"front_upper.L", "chest", {0.12, -0.32, 0.62}}, {"front_lower.L", "front_upper.L", {0.12, -0.32, 0.36}},
          {"front_upper.R", "chest", {-0.12, -0.32, 0.62}}, {"front_lower.R", "front_upper.R", {-0.12, -0.32, 0.36}},
          {"hind_upper.L", "pelvis", {0.12, 0.32, 0.62}}, {"hind_lower.L", "hind_upper.L", {0.12, 0.32, 0.36}},
          {"hind_upper.R", "pelvis", {-0.12, 0.32, 0.62}}, {"hind_lower.R", "hind_upper.R", {-0.12, 0.32, 0.36}},
          {"ear.L", "head", {0.06, -0.62, 1.02}}, {"ear.R", "head", {-0.06, -0.62, 1.02}}}},
        {"snake",
         {{"seg.0", "", {0, 0, 0.1}}, {"seg.1", "seg.0", {0, 0.15, 0.1}}, {"seg.2", "seg.1", {0, 0.30, 0.1}},
          {"seg.3", "seg.2", {0, 0.45, 0.1}}, {"seg.4", "seg.3", {0, 0.60, 0.1}}, {"seg.5", "seg.4", {0, 0.75, 0.1}},
          {"seg.6", "seg.5", {0, 0.90, 0.1}}, {"seg.7", "seg.6", {0, 1.05, 0.1}}}},
    };
    return r;
}

// Blender's +Z up to glTF's +Y up (what Blender's glTF exporter does): (x, y, z) -> (x, z, -y).
std::array<double, 3> y_up(const double p[3]) { return {p[0], p[2], -p[1]}; }

caio::MeshData must_read(const std::string& path) {
    caio::MeshData m;
    std::string err;
    const bool ok = caio::read_mesh(path, m, err);
    INFO(path << ": " << err);
    REQUIRE(ok);
    return m;
}

std::string read_error(const std::string& bytes, const std::string& format) {
    caio::MeshData m;
    std::string err;
    const bool ok = caio::read_mesh_buffer(bytes, format, m, err);
    CHECK_FALSE(ok);
    CHECK(m.skin.empty());
    return err;
}

bool says(const std::string& error, const char* what) {
    INFO(error);
    return error.find(what) != std::string::npos;
}

using Mat = std::array<double, 16>;

Mat joint_matrix(const std::vector<double>& all, size_t j) {
    Mat m;
    std::copy(all.begin() + long(16 * j), all.begin() + long(16 * j + 16), m.begin());
    return m;
}

double off_identity(const Mat& m) {
    double worst = 0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) worst = std::max(worst, std::fabs(m[size_t(c * 4 + r)] - (r == c ? 1.0 : 0.0)));
    return worst;
}

size_t joint_index(const caio::SkinData& s, const std::string& name) {
    const auto it = std::find(s.joint_names.begin(), s.joint_names.end(), name);
    REQUIRE_MESSAGE(it != s.joint_names.end(), "joint " << name);
    return size_t(it - s.joint_names.begin());
}

std::string parent_name(const caio::SkinData& s, size_t j) {
    return s.parents[j] < 0 ? "" : s.joint_names[size_t(s.parents[j])];
}

// The joint with the largest weight at each vertex.
std::vector<uint32_t> dominant(const caio::MeshData& m) {
    const caio::SkinData& s = m.skin;
    std::vector<uint32_t> d(m.positions.size() / 3);
    for (size_t v = 0; v < d.size(); ++v) {
        size_t best = v * s.influences;
        for (size_t k = best; k < (v + 1) * s.influences; ++k)
            if (s.vertex_weights[k] > s.vertex_weights[best]) best = k;
        d[v] = s.vertex_joints[best];
    }
    return d;
}

// Every vertex of `a` lies within `tol` of a vertex of `b`, after scaling `a` by `scale`.
double farthest_from(const std::vector<double>& a, double scale, const std::vector<double>& b) {
    double worst = 0;
    for (size_t i = 0; i < a.size(); i += 3) {
        double best = std::numeric_limits<double>::infinity();
        for (size_t j = 0; j < b.size(); j += 3) {
            double d = 0;
            for (int k = 0; k < 3; ++k) d += (scale * a[i + size_t(k)] - b[j + size_t(k)]) * (scale * a[i + size_t(k)] - b[j + size_t(k)]);
            best = std::min(best, d);
        }
        worst = std::max(worst, std::sqrt(best));
    }
    return worst;
}

}  // namespace

TEST_CASE("skin: the rigged characters' glTF give the script's joints, parents, rest pose and binds") {
    for (const auto& [character, spec] : rigs()) {
        CAPTURE(character);
        const caio::MeshData m = must_read(kRigged + character + ".glb");
        const caio::SkinData& s = m.skin;
        CHECK(caio::skin_problem(m) == "");
        REQUIRE(s.joint_names.size() == spec.size());
        CHECK(s.influences == 4);
        CHECK(s.gltf_nodes.size() == spec.size());
        for (const JointSpec& js : spec) {
            const std::string jname = js.name;
            CAPTURE(jname);
            const size_t j = joint_index(s, js.name);
            CHECK(parent_name(s, j) == js.parent);
            // the joint's node sits at its bone's head; the mesh is bound at rest with the mesh
            // object at the origin, so world * inverse bind is the identity
            const Mat world = joint_matrix(s.joint_world, j);
            const auto head = y_up(js.head);
            for (int k = 0; k < 3; ++k) CHECK(world[size_t(12 + k)] == doctest::Approx(head[size_t(k)]).epsilon(1e-4));
            CHECK(off_identity(caio::detail::mul4(world, joint_matrix(s.inverse_bind, j))) < 1e-4);
        }
        // every vertex driven (the script checked every vertex has a weight), each row sums to 1
        for (size_t v = 0; v < m.positions.size() / 3; ++v) {
            double sum = 0;
            for (size_t k = 0; k < s.influences; ++k) sum += s.vertex_weights[v * s.influences + k];
            REQUIRE(sum == doctest::Approx(1).epsilon(1e-9));
        }
        // the extremes of each character belong to the joints there
        const std::vector<uint32_t> d = dominant(m);
        size_t top = 0, low = 0, back = 0;
        for (size_t v = 1; v < d.size(); ++v) {
            if (m.positions[3 * v + 1] > m.positions[3 * top + 1]) top = v;
            if (m.positions[3 * v + 1] < m.positions[3 * low + 1]) low = v;
            if (m.positions[3 * v + 2] < m.positions[3 * back + 2]) back = v;  // glTF -Z is Blender's +Y
        }
        const std::string top_joint = s.joint_names[d[top]], low_joint = s.joint_names[d[low]],
                          back_joint = s.joint_names[d[back]];
        CAPTURE(top_joint);
        CAPTURE(low_joint);
        CAPTURE(back_joint);
        if (character == "humanoid") {
            CHECK(top_joint == "head");
            CHECK((low_joint.rfind("foot", 0) == 0 || low_joint.rfind("shin", 0) == 0));
        } else if (character == "quadruped") {
            CHECK(top_joint.rfind("ear", 0) == 0);
            CHECK(back_joint == "tail.3");
        } else {
            CHECK(back_joint == "seg.7");
        }
    }
}

// Another export of a character, read through assimp, against its glTF: `scale` its units per
// glTF unit, `merged` how many vertices it may lose to joined positions.
struct Export {
    const char* ext;
    double scale;
    size_t merged;
    std::string joint_prefix;  // Collada: joints are named by their node ids, "<armature>_<bone>"
};

// The export's name of a joint: the prefix, then the bone's name with '.' as '_' when prefixed.
std::string export_name(const Export& e, std::string bone) {
    if (e.joint_prefix.empty()) return bone;
    std::replace(bone.begin(), bone.end(), '.', '_');
    return e.joint_prefix + bone;
}

// Blender's FBX exporter writes centimetres (UnitScaleFactor 100 in the file) that assimp keeps,
// in glTF's axes (+Y up, -Z forward): FBX = 100 * glTF. Its Collada exporter writes metres with
// +Z up, which assimp turns to +Y up at the root: Collada = glTF; its 6 printed digits may put
// two close vertices at one position, which the reader joins. Assimp's Collada reader names nodes,
// and so joints, by their ids.
void compare_with_gltf(const std::string& character, const std::vector<JointSpec>& spec, const Export& e) {
    const caio::MeshData g = must_read(kRigged + character + ".glb");
    const caio::MeshData f = must_read(kRigged + character + e.ext);
    const double scale = e.scale;
    CHECK(caio::skin_problem(f) == "");
    REQUIRE(f.skin.joint_names.size() == spec.size());
    for (const JointSpec& js : spec) {
        const std::string jname = js.name;
        CAPTURE(jname);
        const size_t jf = joint_index(f.skin, export_name(e, js.name)), jg = joint_index(g.skin, js.name);
        CHECK(parent_name(f.skin, jf) == (*js.parent ? export_name(e, js.parent) : ""));
        const Mat wf = joint_matrix(f.skin.joint_world, jf), wg = joint_matrix(g.skin.joint_world, jg);
        for (int k = 0; k < 3; ++k) CHECK(wf[size_t(12 + k)] == doctest::Approx(scale * wg[size_t(12 + k)]).epsilon(1e-4).scale(1));
        // assimp's offset matrices and the vertices placed in world coordinates agree
        CHECK(off_identity(caio::detail::mul4(wf, joint_matrix(f.skin.inverse_bind, jf))) < 1e-3);
    }
    // the same surface in its bind pose (both keep Blender's vertices, the FBX's joined again
    // after assimp split them per face corner)
    CHECK(f.positions.size() + 3 * e.merged >= g.positions.size());
    CHECK(f.positions.size() <= g.positions.size());
    CHECK(f.triangles.size() == g.triangles.size());
    CHECK(farthest_from(g.positions, scale, f.positions) < 1e-3 * scale);
    CHECK(farthest_from(f.positions, 1 / scale, g.positions) < 1e-3);
    // each joint dominates the same part (the glTF's 4-weight limit keeps each vertex's heaviest
    // joint): the same vertex counts and centroids; the quadruped's spine, between chest and
    // pelvis, owns none
    const std::vector<uint32_t> dg = dominant(g), df = dominant(f);
    size_t compared = 0;
    for (const JointSpec& js : spec) {
        const std::string jname = js.name;
        CAPTURE(jname);
        const uint32_t jg = uint32_t(joint_index(g.skin, js.name)), jf = uint32_t(joint_index(f.skin, export_name(e, js.name)));
        double cg[3] = {0, 0, 0}, cf[3] = {0, 0, 0};
        size_t ng = 0, nf = 0;
        for (size_t v = 0; v < dg.size(); ++v)
            if (dg[v] == jg) {
                for (int k = 0; k < 3; ++k) cg[k] += g.positions[3 * v + size_t(k)];
                ++ng;
            }
        for (size_t v = 0; v < df.size(); ++v)
            if (df[v] == jf) {
                for (int k = 0; k < 3; ++k) cf[k] += f.positions[3 * v + size_t(k)] / scale;
                ++nf;
            }
        CHECK(nf <= ng);
        CHECK(nf + e.merged >= ng);
        if (ng == 0) continue;
        ++compared;
        for (int k = 0; k < 3; ++k) CHECK(cf[k] / double(nf) == doctest::Approx(cg[k] / double(ng)).scale(1).epsilon(0.02));
    }
    CHECK(compared + 1 >= spec.size());
}

TEST_CASE("skin: FBX and glTF of each character give the same joints, parents and bind pose") {
    for (const auto& [character, spec] : rigs()) {
        CAPTURE(character);
        compare_with_gltf(character, spec, {".fbx", 100, 0, ""});
    }
}

TEST_CASE("skin: the snake's Collada and glTF give the same joints, parents and bind pose") {
    compare_with_gltf("snake", rigs().at("snake"), {".dae", 1, 2, "snake_rig_"});
}

// ---- small glTF skins written here ----

namespace {

using caio::gltf::json;

// A tetrahedron skinned to two joints: node 0 draws it with skin 0, node 1 is the root joint "root"
// at the origin, node 2 its child "tip" at (0, 1, 0). Each field can be spoilt by a test.
struct SkinnedTetrahedron {
    std::vector<uint8_t> joints = {0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0};
    std::vector<float> weights = {1, 0, 0, 0, 0.5f, 0.5f, 0, 0, 0.25f, 0.75f, 0, 0, 0, 2, 0, 0};
    std::vector<uint8_t> joints1;   // JOINTS_1, when not empty
    std::vector<uint16_t> weights1; // WEIGHTS_1 (normalized unsigned short), when not empty
    std::vector<float> bind = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,
                               1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1};
    json nodes = json::array({{{"mesh", 0}, {"skin", 0}}, {{"name", "root"}, {"children", {2}}},
                              {{"name", "tip"}, {"translation", {0, 1, 0}}}});
    json scene_nodes = {0, 1};
    std::vector<int> skin_joints = {1, 2};
    json extra_meshes = json::array();  // appended after mesh 0 (same primitive, unskinned)

    std::string glb() const {
        caio::gltf::Builder b;
        const std::vector<float> pos = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
        const int p = b.floats(pos, 3);
        const int idx = b.indices(std::vector<uint16_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}, caio::gltf::kUnsignedShort);
        auto raw = [&](const void* data, size_t bytes, int component, size_t count, const char* type, bool normalized) {
            const int v = b.view(data, bytes, caio::gltf::kArrayBuffer);
            json a = {{"bufferView", v}, {"componentType", component}, {"count", count}, {"type", type}};
            if (normalized) a["normalized"] = true;
            b.accessors.push_back(a);
            return int(b.accessors.size()) - 1;
        };
        json attributes = {{"POSITION", p}};
        attributes["JOINTS_0"] = raw(joints.data(), joints.size(), caio::gltf::kUnsignedByte, joints.size() / 4, "VEC4", false);
        attributes["WEIGHTS_0"] = raw(weights.data(), 4 * weights.size(), caio::gltf::kFloat, weights.size() / 4, "VEC4", false);
        if (!joints1.empty())
            attributes["JOINTS_1"] = raw(joints1.data(), joints1.size(), caio::gltf::kUnsignedByte, joints1.size() / 4, "VEC4", false);
        if (!weights1.empty())
            attributes["WEIGHTS_1"] = raw(weights1.data(), 2 * weights1.size(), caio::gltf::kUnsignedShort, weights1.size() / 4, "VEC4", true);
        const int ibm = raw(bind.data(), 4 * bind.size(), caio::gltf::kFloat, bind.size() / 16, "MAT4", false);
        json meshes = json::array({{{"primitives", {{{"attributes", attributes}, {"indices", idx}}}}}});
        for (const json& m : extra_meshes) meshes.push_back(m);
        json doc = {{"asset", {{"version", "2.0"}}},
                    {"scene", 0},
                    {"scenes", {{{"nodes", scene_nodes}}}},
                    {"nodes", nodes},
                    {"meshes", meshes},
                    {"skins", {{{"joints", skin_joints}, {"inverseBindMatrices", ibm}}}},
                    {"buffers", {{{"byteLength", b.bin.size()}}}},
                    {"bufferViews", b.views},
                    {"accessors", b.accessors}};
        return caio::gltf::glb(doc, b.bin);
    }
};

caio::MeshData read_glb(const std::string& bytes) {
    caio::MeshData m;
    std::string err;
    const bool ok = caio::read_mesh_buffer(bytes, "glb", m, err);
    INFO(err);
    REQUIRE(ok);
    return m;
}

}  // namespace

TEST_CASE("skin: a small glTF skin reads with its joints, binds and normalised weights") {
    const caio::MeshData m = read_glb(SkinnedTetrahedron().glb());
    const caio::SkinData& s = m.skin;
    REQUIRE(s.joint_names == std::vector<std::string>{"root", "tip"});
    CHECK(s.parents == std::vector<int32_t>{-1, 0});
    CHECK(s.gltf_nodes == std::vector<int32_t>{1, 2});
    CHECK(s.influences == 4);
    CHECK(s.joint_world[13] == 0);
    CHECK(s.joint_world[16 + 13] == 1);  // tip at y = 1
    CHECK(s.inverse_bind[16 + 13] == -1);
    // vertex 3's weights (0, 2) on joints (0, 1) normalise to (0, 1)
    const std::vector<double> w(s.vertex_weights.begin() + 12, s.vertex_weights.end());
    CHECK(w == std::vector<double>{0, 1, 0, 0});
    CHECK(s.vertex_joints[13] == 1);
    CHECK(s.vertex_weights[8] == 0.25);
    CHECK(s.vertex_weights[9] == 0.75);
    // the skinned mesh stays in its own space: its node's transform does not move it
    SkinnedTetrahedron moved;
    moved.nodes[0]["translation"] = {5, 0, 0};
    CHECK(read_glb(moved.glb()).positions == m.positions);
}

TEST_CASE("skin: glTF JOINTS_1 and WEIGHTS_1 give 8 influences, normalized integer weights are read") {
    SkinnedTetrahedron t;
    t.weights = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
    t.joints1 = std::vector<uint8_t>(16, 1);
    t.weights1 = std::vector<uint16_t>(16, 0);
    t.weights1[0] = 65535;  // vertex 0: (1 on root) + (1 on tip) -> 0.5 and 0.5
    const caio::MeshData m = read_glb(t.glb());
    REQUIRE(m.skin.influences == 8);
    REQUIRE(m.skin.vertex_weights.size() == 4 * 8);
    CHECK(m.skin.vertex_weights[0] == doctest::Approx(0.5));
    CHECK(m.skin.vertex_weights[4] == doctest::Approx(0.5));
    CHECK(m.skin.vertex_joints[4] == 1);
    CHECK(m.skin.vertex_weights[8] == 1);
    CHECK(caio::skin_problem(m) == "");
}

TEST_CASE("skin: unskinned glTF meshes beside a skinned one follow the joint above them or get no weight") {
    SkinnedTetrahedron t;
    // mesh 1: the same tetrahedron unskinned, drawn under joint "tip" (node 3) and at the root (node 4)
    t.extra_meshes.push_back({{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}});
    t.nodes[2]["children"] = {3};
    t.nodes.push_back({{"mesh", 1}, {"translation", {0, 0, 2}}});
    t.nodes.push_back({{"mesh", 1}, {"translation", {3, 0, 0}}});
    t.scene_nodes = {0, 1, 4};
    const caio::MeshData m = read_glb(t.glb());
    REQUIRE(m.positions.size() == 3 * 12);
    const caio::SkinData& s = m.skin;
    // drawn order: node 0 (skinned), then node 1's subtree (node 3 under tip), then node 4
    for (size_t v = 4; v < 8; ++v) {
        CHECK(s.vertex_joints[4 * v] == 1);
        CHECK(s.vertex_weights[4 * v] == 1);
        CHECK(m.positions[3 * v + 1] == doctest::Approx(1 + (v == 6 ? 1 : 0)));  // under tip: y + 1
        CHECK(m.positions[3 * v + 2] == doctest::Approx(2 + (v == 7 ? 1 : 0)));
    }
    for (size_t v = 8; v < 12; ++v) {
        for (size_t k = 0; k < 4; ++k) CHECK(s.vertex_weights[4 * v + k] == 0);
        CHECK(m.positions[3 * v] == doctest::Approx(3 + (v == 9 ? 1 : 0)));
    }
    CHECK(caio::skin_problem(m) == "");
}

TEST_CASE("skin: bad glTF skins are refused with a clear message") {
    SkinnedTetrahedron t;
    t.joints[5] = 7;
    CHECK(says(read_error(t.glb(), "glb"), "JOINTS_0: vertex 1 names joint 7, out of range"));
    t = SkinnedTetrahedron();
    t.weights[2] = std::numeric_limits<float>::quiet_NaN();
    CHECK(says(read_error(t.glb(), "glb"), "WEIGHTS_0: vertex 0 has a weight that is negative, NaN or infinite"));
    t = SkinnedTetrahedron();
    t.weights[6] = -0.5f;
    CHECK(says(read_error(t.glb(), "glb"), "negative, NaN or infinite"));
    t = SkinnedTetrahedron();
    t.weights.resize(12);  // three vertices' weights for four vertices
    CHECK(says(read_error(t.glb(), "glb"), "elements for 4 vertices"));
    t = SkinnedTetrahedron();
    t.joints1 = std::vector<uint8_t>(16, 0);  // JOINTS_1 without WEIGHTS_1
    CHECK(says(read_error(t.glb(), "glb"), "has JOINTS_1 without WEIGHTS_1"));
    t = SkinnedTetrahedron();
    t.bind.resize(16);  // one matrix for two joints
    CHECK(says(read_error(t.glb(), "glb"), "1 inverse bind matrices for 2 joints"));
    t = SkinnedTetrahedron();
    t.bind[5] = std::numeric_limits<float>::infinity();
    CHECK(says(read_error(t.glb(), "glb"), "inverse bind matrix 0 holds NaN or infinity"));
    t = SkinnedTetrahedron();
    t.skin_joints = {1, 9};
    CHECK(says(read_error(t.glb(), "glb"), "joint node 9 does not exist"));
    t = SkinnedTetrahedron();
    t.skin_joints = {1, 1};
    CHECK(says(read_error(t.glb(), "glb"), "joint node 1 listed twice"));
    t = SkinnedTetrahedron();
    t.nodes[0]["skin"] = 3;
    CHECK(says(read_error(t.glb(), "glb"), "skin 3 does not exist"));
    // joints whose nodes form a cycle (root -> tip -> root), outside the drawn scene
    t = SkinnedTetrahedron();
    t.nodes[2]["children"] = {1};
    t.scene_nodes = {0};
    CHECK(says(read_error(t.glb(), "glb"), "form a cycle"));
    // a skinned primitive without weights
    t = SkinnedTetrahedron();
    std::string bytes = t.glb();
    const size_t at = bytes.find("\"WEIGHTS_0\"");
    REQUIRE(at != std::string::npos);
    bytes.replace(at, 11, "\"WEIGHTS_9\"");
    CHECK(says(read_error(bytes, "glb"), "without JOINTS_0 and WEIGHTS_0"));
}

TEST_CASE("skin: files without a skin give an empty skin") {
    for (const char* file : {"formats/fox.glb", "formats/fox.fbx", "formats/fox.dae", "fox.obj"}) {
        CAPTURE(file);
        const caio::MeshData m = must_read(std::string(CA_TEST_DATA) + "/" + file);
        CHECK(m.skin.empty());
        CHECK(m.skin.vertex_weights.empty());
        CHECK(caio::skin_problem(m) == "");
    }
}

TEST_CASE("skin: the tool's --rig glb reads back with its skin") {
    caio::MeshData mesh;
    mesh.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    mesh.triangles = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    caio::RigData rig;
    rig.joints = {0, 0, 0, 0, 0.5, 0, 0, 1, 0};
    rig.parents = {-1, 0, 1};
    rig.vertex_joints = {0, 1, 2, 0, 1, 0, 0, 0, 2, 1, 0, 0, 0, 2, 0, 0};
    rig.vertex_weights = {0.5, 0.25, 0.25, 0, 1, 0, 0, 0, 0.75, 0.25, 0, 0, 1, 0, 0, 0};
    iotest::TempDir dir;
    std::string err;
    REQUIRE_MESSAGE(caio::write_rig_glb(dir.path("rig.glb"), mesh, rig, err), err);
    const caio::MeshData back = must_read(dir.path("rig.glb"));
    const caio::SkinData& s = back.skin;
    REQUIRE(s.joint_names.size() == 3);
    CHECK(s.parents == rig.parents);
    CHECK(back.positions == mesh.positions);
    for (size_t j = 0; j < 3; ++j) {
        CHECK(s.joint_world[16 * j + 13] == doctest::Approx(rig.joints[3 * j + 1]));
        CHECK(off_identity(caio::detail::mul4(joint_matrix(s.joint_world, j), joint_matrix(s.inverse_bind, j))) < 1e-6);
    }
    REQUIRE(s.influences == 4);
    for (size_t v = 0; v < 4; ++v)
        for (size_t k = 0; k < 4; ++k) {
            CAPTURE(v);
            CAPTURE(k);
            CHECK(s.vertex_weights[4 * v + k] == doctest::Approx(rig.vertex_weights[4 * v + k]).epsilon(1e-6));
            if (rig.vertex_weights[4 * v + k] > 0) CHECK(s.vertex_joints[4 * v + k] == rig.vertex_joints[4 * v + k]);
        }
}

// ---- assimp scenes built by hand ----

namespace {

// A tetrahedron under node "body"; beside it a joint chain root -> (a non-joint "pivot") -> "a"
// -> "b", the bones weighing the mesh, each joint at x = 0, 1, 2.
struct BonedScene {
    std::unique_ptr<aiScene> scene = std::make_unique<aiScene>();
    aiNode *root, *body, *pivot, *a, *b;

    BonedScene() {
        aiMesh* mesh = tetrahedron_mesh();
        scene->mNumMeshes = 1;
        scene->mMeshes = new aiMesh*[1]{mesh};
        scene->mNumMaterials = 1;
        scene->mMaterials = new aiMaterial*[1]{new aiMaterial};
        root = new aiNode("root_joint");
        body = new aiNode("body");
        pivot = new aiNode("pivot");
        a = new aiNode("a");
        b = new aiNode("b");
        auto link = [](aiNode* parent, std::vector<aiNode*> children) {
            parent->mNumChildren = unsigned(children.size());
            parent->mChildren = new aiNode*[children.size()];
            for (size_t i = 0; i < children.size(); ++i) {
                parent->mChildren[i] = children[i];
                children[i]->mParent = parent;
            }
        };
        aiNode* top = new aiNode("scene");
        link(top, {body, root});
        link(root, {pivot});
        link(pivot, {a});
        link(a, {b});
        pivot->mTransformation = aiMatrix4x4(aiVector3D(1, 1, 1), aiQuaternion(), aiVector3D(1, 0, 0));
        b->mTransformation = aiMatrix4x4(aiVector3D(1, 1, 1), aiQuaternion(), aiVector3D(1, 0, 0));
        scene->mRootNode = top;
        body->mNumMeshes = 1;
        body->mMeshes = new unsigned[1]{0};
    }
    // A bone of `name` at x = `x` (bound at rest) weighing the vertices `weights` gives.
    void add_bone(const char* name, float x, std::vector<std::pair<unsigned, float>> weights) {
        aiMesh* mesh = scene->mMeshes[0];
        aiBone* bone = new aiBone;
        bone->mName = aiString(name);
        bone->mOffsetMatrix = aiMatrix4x4(aiVector3D(1, 1, 1), aiQuaternion(), aiVector3D(-x, 0, 0));
        bone->mNumWeights = unsigned(weights.size());
        bone->mWeights = new aiVertexWeight[weights.size()];
        for (size_t i = 0; i < weights.size(); ++i) bone->mWeights[i] = aiVertexWeight(weights[i].first, weights[i].second);
        aiBone** bones = new aiBone*[mesh->mNumBones + 1];
        for (unsigned i = 0; i < mesh->mNumBones; ++i) bones[i] = mesh->mBones[i];
        bones[mesh->mNumBones] = bone;
        delete[] mesh->mBones;
        mesh->mBones = bones;
        ++mesh->mNumBones;
    }
    bool place(caio::MeshData& out, std::string& error) {
        return caio::detail::place_assimp_meshes("s", *scene, 100000, out, error);
    }
};

}  // namespace

TEST_CASE("skin: assimp bones become joints by node, parents skip non-joint nodes, binds stay consistent") {
    BonedScene s;
    s.body->mTransformation = aiMatrix4x4(aiVector3D(2, 2, 2), aiQuaternion(), aiVector3D(0, 0, 5));  // mesh moved
    s.add_bone("root_joint", 0, {{0, 1}, {1, 1}});
    s.add_bone("a", 1, {{1, 1}, {2, 1}});
    s.add_bone("b", 2, {{3, 1}, {3, 1}});  // the same vertex twice: summed
    caio::MeshData m;
    std::string err;
    REQUIRE_MESSAGE(s.place(m, err), err);
    const caio::SkinData& k = m.skin;
    REQUIRE(k.joint_names == std::vector<std::string>{"root_joint", "a", "b"});
    CHECK(k.parents == std::vector<int32_t>{-1, 0, 1});
    CHECK(k.joint_world[16 * 1 + 12] == 1);
    CHECK(k.joint_world[16 * 2 + 12] == 2);
    // vertices in world coordinates (scaled by 2, lifted by 5); inverse bind * world vertex =
    // offset * original vertex
    CHECK(m.positions[3 * 1 + 0] == 2);
    CHECK(m.positions[3 * 1 + 2] == 5);
    const double v1[3] = {m.positions[3], m.positions[4], m.positions[5]};
    double local[3];
    caio::detail::transform_point(joint_matrix(k.inverse_bind, 1), v1, local);
    CHECK(local[0] == doctest::Approx(1 - 1.0));  // vertex 1 = (1, 0, 0), bone a at x = 1
    CHECK(local[2] == doctest::Approx(0));
    CHECK(k.vertex_weights[4 * 1] == 0.5);
    CHECK(k.vertex_weights[4 * 3] == 1);
    CHECK(k.vertex_joints[4 * 3] == 2);
    CHECK(caio::skin_problem(m) == "");
}

TEST_CASE("skin: assimp vertices with more than 8 bones keep the heaviest 8, renormalised") {
    BonedScene s;
    static const char* names[] = {"j0", "j1", "j2", "j3", "j4", "j5", "j6", "j7", "j8", "j9"};
    for (unsigned i = 0; i < 10; ++i) s.add_bone(names[i], 0, {{0, float(i + 1)}, {1, 1}});
    caio::MeshData m;
    std::string err;
    REQUIRE_MESSAGE(s.place(m, err), err);
    const caio::SkinData& k = m.skin;
    REQUIRE(k.influences == 8);
    // vertex 0: weights 3..10 kept (sum 52), heaviest first; vertex 1: ten equal weights, joints 0..7
    CHECK(k.vertex_joints[0] == 9);
    CHECK(k.vertex_weights[0] == doctest::Approx(10.0 / 52));
    CHECK(k.vertex_joints[7] == 2);
    CHECK(k.vertex_weights[7] == doctest::Approx(3.0 / 52));
    for (size_t i = 0; i < 8; ++i) {
        CHECK(k.vertex_joints[8 + i] == i);
        CHECK(k.vertex_weights[8 + i] == doctest::Approx(1.0 / 8));
    }
    // unweighted vertices drive no joint: four zero rows are allowed
    CHECK(caio::skin_problem(m) == "");
    CHECK(k.vertex_weights[16] == 0);
}

TEST_CASE("skin: bad assimp bones are refused with a clear message") {
    {
        BonedScene s;
        s.add_bone("a", 0, {{0, std::numeric_limits<float>::quiet_NaN()}});
        caio::MeshData m;
        std::string err;
        CHECK_FALSE(s.place(m, err));
        CHECK(says(err, "bone 'a': weight of vertex 0 is negative, NaN or infinite"));
    }
    {
        BonedScene s;
        s.add_bone("a", 0, {{0, 1}});
        s.scene->mMeshes[0]->mBones[0]->mOffsetMatrix.a2 = std::numeric_limits<float>::infinity();
        std::string err;
        CHECK_FALSE(caio::detail::check_assimp_scene("s", s.scene.get(), 100000, err));
        CHECK(says(err, "bone 0: offset matrix holds NaN or infinity"));
    }
    {
        BonedScene s;
        s.add_bone("a", 0, {{9, 1}});
        caio::MeshData m;
        std::string err;
        CHECK_FALSE(s.place(m, err));
        CHECK(says(err, "weighs a vertex out of range"));
    }
}

TEST_CASE("skin: skin_problem refuses inconsistent skins") {
    caio::MeshData m;
    m.positions = {0, 0, 0, 1, 0, 0};
    caio::SkinData& s = m.skin;
    s.joint_names = {"a", "b"};
    s.parents = {1, 0};
    s.inverse_bind.assign(32, 0);
    s.joint_world.assign(32, 0);
    s.influences = 4;
    s.vertex_joints.assign(8, 0);
    s.vertex_weights = {1, 0, 0, 0, 0, 0, 0, 0};
    CHECK(says(caio::skin_problem(m), "parents form a cycle"));
    s.parents = {-1, 0};
    CHECK(caio::skin_problem(m) == "");
    s.vertex_joints[4] = 2;
    CHECK(says(caio::skin_problem(m), "joint 2 out of range"));
    s.vertex_joints[4] = 0;
    s.vertex_weights[1] = 0.5;
    CHECK(says(caio::skin_problem(m), "weights do not sum to 1"));
    s.vertex_weights[1] = 0;
    s.vertex_weights.pop_back();
    CHECK(says(caio::skin_problem(m), "4 per vertex for 2 vertices"));
    s.vertex_weights.push_back(0);
    s.inverse_bind[3] = std::nan("");
    CHECK(says(caio::skin_problem(m), "NaN or infinity"));
    s.inverse_bind[3] = 0;
    s.influences = 9;
    CHECK(says(caio::skin_problem(m), "1 to 8 allowed"));
}

// test_io.cpp: unit tests of the example file readers/writers (examples/io/mesh_io.h): every
// input format and variant, round trips of the writers, error messages, and robustness against
// truncated and corrupted files.
#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "io_test_util.h"
#include "mesh_io.h"

namespace fs = std::filesystem;
using iotest::TempDir;

namespace {

// Builds binary PLY bodies in either byte order.
struct Bytes {
    bool big;
    std::string s;
    template <class T>
    Bytes& put(T v) {
        unsigned char b[sizeof(T)];
        std::memcpy(b, &v, sizeof(T));
        const uint16_t one = 1;
        unsigned char first;
        std::memcpy(&first, &one, 1);
        const bool host_little = first == 1;
        if (big == host_little)
            for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
        s.append(reinterpret_cast<const char*>(b), sizeof(T));
        return *this;
    }
};

std::vector<uint32_t> tris(std::initializer_list<uint32_t> l) { return std::vector<uint32_t>(l); }

}  // namespace

TEST_CASE("obj: quads, slash forms, negative indices, normals, ignored records") {
    TempDir td;
    const std::string p = td.write("quad.obj",
                                   "# comment\n"
                                   "mtllib x.mtl\n"
                                   "o thing\n"
                                   "v 0 0 0\n"
                                   "v 1 0 0\n"
                                   "v 1 1 0\r\n"
                                   "v 0 1 0  # trailing comment\n"
                                   "vt 0 0\n"
                                   "vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1.5\n"
                                   "g group\ns off\nusemtl m\n"
                                   "f 1/1/1 2/2/2 3/3/3 4/4/4\n"   // quad -> 2 triangles
                                   "f 1//1 3//3 4//4\n"
                                   "f 1/1 2/2 3/3\n"
                                   "f -4 -3 -2 -1\n"             // relative quad
                                   "l 1 2\n"
                                   "v +2 -0.5e1 .25\n"
                                   "f -1 1 2\n");                // -1 is vertex 5
    caio::MeshData m;
    std::string err;
    REQUIRE_MESSAGE(caio::read_mesh(p, m, err), err);
    CHECK(m.positions.size() == 15);
    CHECK(m.positions[12] == 2.0);
    CHECK(m.positions[13] == -5.0);
    CHECK(m.positions[14] == 0.25);
    CHECK(m.triangles == tris({0, 1, 2, 0, 2, 3, 0, 2, 3, 0, 1, 2, 0, 1, 2, 0, 2, 3, 4, 0, 1}));
    // 4 vn for 5 v: normals are dropped.
    CHECK(m.normals.empty());
}

TEST_CASE("obj: vn count equal to v count keeps per-vertex normals, forward references") {
    TempDir td;
    const std::string p = td.write("n.obj", "vn 0 0 1\nvn 0 1 0\nvn 1 0 0\nf 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
    caio::MeshData m;
    std::string err;
    REQUIRE_MESSAGE(caio::read_mesh(p, m, err), err);
    CHECK(m.positions.size() == 9);
    CHECK(m.triangles == tris({0, 1, 2}));
    REQUIRE(m.normals.size() == 9);
    CHECK(m.normals[2] == 1.0);
    CHECK(m.normals[6] == 1.0);
}

TEST_CASE("obj: point cloud, empty f record, NaN passes through, uppercase extension") {
    TempDir td;
    const std::string p = td.write("pc.OBJ", "v 1 2 3\nv nan inf -inf\nf\n");
    caio::MeshData m;
    std::string err;
    REQUIRE_MESSAGE(caio::read_mesh(p, m, err), err);
    CHECK(m.positions.size() == 6);
    CHECK(m.triangles.empty());
    CHECK(std::isnan(m.positions[3]));
    CHECK(std::isinf(m.positions[4]));
}

TEST_CASE("off: comments, counts on next line, polygons, colours, CRLF") {
    TempDir td;
    const std::string p = td.write("a.off",
                                   "OFF # header\r\n"
                                   "# a comment line\r\n"
                                   "\r\n"
                                   "5 3 0\r\n"
                                   "0 0 0\r\n"
                                   "1 0 0  # comment after vertex\r\n"
                                   "1 1 0\r\n"
                                   "# comment between vertices\r\n"
                                   "0 1 0\r\n"
                                   "2 2 2\r\n"
                                   "4 0 1 2 3 255 0 0\r\n"   // quad with colour
                                   "3 1 4 2\r\n"
                                   "3 0 3 4");               // no final newline
    caio::MeshData m;
    std::string err;
    REQUIRE_MESSAGE(caio::read_mesh(p, m, err), err);
    CHECK(m.positions.size() == 15);
    CHECK(m.positions[12] == 2.0);
    CHECK(m.triangles == tris({0, 1, 2, 0, 2, 3, 1, 4, 2, 0, 3, 4}));
    CHECK(m.normals.empty());

    // Counts on the header line, COFF with vertex colours.
    const std::string q = td.write("b.off", "COFF 3 1 3\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n0 1 0 0 0 1 1\n3 0 1 2\n");
    REQUIRE_MESSAGE(caio::read_mesh(q, m, err), err);
    CHECK(m.positions == std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0});
    CHECK(m.triangles == tris({0, 1, 2}));

    // NOFF: normals after the coordinates.
    const std::string r = td.write("c.off", "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 -1\n3 0 1 2\n");
    REQUIRE_MESSAGE(caio::read_mesh(r, m, err), err);
    CHECK(m.normals == std::vector<double>{0, 0, 1, 0, 0, 1, 0, 0, -1});
}

TEST_CASE("ply ascii with extra properties, extra elements and list properties") {
    TempDir td;
    const std::string p = td.write("a.ply",
                                   "ply\r\n"
                                   "format ascii 1.0\r\n"
                                   "comment made by hand\r\n"
                                   "obj_info nothing\r\n"
                                   "element material 1\r\n"
                                   "property list uchar float coeffs\r\n"
                                   "property int id\r\n"
                                   "element vertex 4\r\n"
                                   "property float x\r\n"
                                   "property uchar red\r\n"
                                   "property float y\r\n"
                                   "property float z\r\n"
                                   "property float nx\r\n"
                                   "property float ny\r\n"
                                   "property float nz\r\n"
                                   "element face 2\r\n"
                                   "property list uchar float texcoord\r\n"
                                   "property list uchar int vertex_indices\r\n"
                                   "property uchar flags\r\n"
                                   "element edge 1\r\n"
                                   "property int vertex1\r\n"
                                   "property int vertex2\r\n"
                                   "end_header\r\n"
                                   "3 0.5 0.5 0.5 7\r\n"
                                   "0 255 0 0 0 0 1\r\n"
                                   "1 255 0 0 0 0 1\r\n"
                                   "1 255 1 0 0 0 1\r\n"
                                   "0 255 1 0.5 0 0 1\r\n"
                                   "2 0.1 0.2 4 0 1 2 3 9\r\n"
                                   "0 3 2 1 0 0\r\n"
                                   "0 1\r\n");
    caio::MeshData m;
    std::string err;
    REQUIRE_MESSAGE(caio::read_mesh(p, m, err), err);
    CHECK(m.positions == std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0.5});
    CHECK(m.triangles == tris({0, 1, 2, 0, 2, 3, 2, 1, 0}));
    CHECK(m.normals.size() == 12);
}

namespace {

// A binary PLY: a skipped element with a list, vertices with mixed types and normals, faces
// with an extra list and scalar around the index list, and a trailing edge element.
std::string binary_ply(bool big, const char* count_type, const char* index_type, const char* list_name) {
    std::string h = "ply\nformat ";
    h += big ? "binary_big_endian" : "binary_little_endian";
    h += " 1.0\n"
         "element material 2\n"
         "property list uint8 int16 stuff\n"
         "property double shininess\n"
         "element vertex 4\n"
         "property double x\n"
         "property float32 y\n"
         "property short quality\n"
         "property float z\n"
         "property float nx\nproperty float ny\nproperty float nz\n"
         "element face 2\n"
         "property ushort flags\n"
         "property list ";
    h += count_type;
    h += " ";
    h += index_type;
    h += " ";
    h += list_name;
    h += "\nproperty list uchar float texcoord\n"
         "element edge 1\nproperty int vertex1\nproperty int vertex2\n"
         "end_header\n";
    Bytes b{big, {}};
    // material 0: 3 shorts; material 1: empty list
    b.put<uint8_t>(3).put<int16_t>(1).put<int16_t>(-2).put<int16_t>(3).put<double>(0.5);
    b.put<uint8_t>(0).put<double>(1.5);
    const double xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0.25}};
    for (auto& v : xyz)
        b.put<double>(v[0]).put<float>(static_cast<float>(v[1])).put<int16_t>(-7).put<float>(static_cast<float>(v[2]))
            .put<float>(0).put<float>(0).put<float>(1);
    auto put_count = [&](uint32_t n) {
        if (!std::strcmp(count_type, "uchar")) b.put<uint8_t>(static_cast<uint8_t>(n));
        else if (!std::strcmp(count_type, "ushort")) b.put<uint16_t>(static_cast<uint16_t>(n));
        else b.put<int32_t>(static_cast<int32_t>(n));
    };
    auto put_index = [&](uint32_t i) {
        if (!std::strcmp(index_type, "int")) b.put<int32_t>(static_cast<int32_t>(i));
        else if (!std::strcmp(index_type, "uint32")) b.put<uint32_t>(i);
        else b.put<uint16_t>(static_cast<uint16_t>(i));
    };
    b.put<uint16_t>(1);
    put_count(4);
    for (uint32_t i : {0u, 1u, 2u, 3u}) put_index(i);
    b.put<uint8_t>(2).put<float>(0.1f).put<float>(0.2f);
    b.put<uint16_t>(2);
    put_count(3);
    for (uint32_t i : {3u, 2u, 0u}) put_index(i);
    b.put<uint8_t>(0);
    b.put<int32_t>(0).put<int32_t>(1);
    return h + b.s;
}

}  // namespace

TEST_CASE("ply binary little and big endian, various list types") {
    TempDir td;
    struct Variant {
        bool big;
        const char* ct;
        const char* it;
        const char* name;
    };
    for (const Variant& v : {Variant{false, "uchar", "int", "vertex_indices"}, Variant{true, "uchar", "int", "vertex_indices"},
                             Variant{false, "int", "uint32", "vertex_index"}, Variant{true, "ushort", "ushort", "vertex_index"}}) {
        CAPTURE(v.big);
        CAPTURE(v.ct);
        CAPTURE(v.it);
        const std::string p = td.write("b.ply", binary_ply(v.big, v.ct, v.it, v.name));
        caio::MeshData m;
        std::string err;
        REQUIRE_MESSAGE(caio::read_mesh(p, m, err), err);
        CHECK(m.positions == std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0.25});
        CHECK(m.triangles == tris({0, 1, 2, 0, 2, 3, 3, 2, 0}));
        CHECK(m.normals == std::vector<double>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
    }
}

TEST_CASE("xyz point clouds") {
    TempDir td;
    caio::MeshData m;
    std::string err;
    REQUIRE_MESSAGE(caio::read_mesh(td.write("a.xyz", "# pts\n0 0 0 0 0 1\n\n1 2 3 0 1 0\n"), m, err), err);
    CHECK(m.positions == std::vector<double>{0, 0, 0, 1, 2, 3});
    CHECK(m.normals == std::vector<double>{0, 0, 1, 0, 1, 0});
    CHECK(m.triangles.empty());
    REQUIRE_MESSAGE(caio::read_mesh(td.write("b.xyz", "0 0 0\n1 2 3 0 1 0\n"), m, err), err);
    CHECK(m.positions.size() == 6);
    CHECK(m.normals.empty());
}

TEST_CASE("ply point clouds: ascii without faces, normals only when nx, ny and nz are all there") {
    TempDir td;
    caio::MeshData m;
    std::string err;
    const std::string head = "ply\nformat ascii 1.0\nelement vertex 2\nproperty double x\nproperty double y\nproperty double z\n";
    REQUIRE_MESSAGE(caio::read_mesh(td.write("n.ply", head + "property float nx\nproperty float ny\nproperty float nz\n"
                                                          "end_header\n0 0 0 0 0 1\n1 2 3 0 1 0\n"), m, err), err);
    CHECK(m.positions == std::vector<double>{0, 0, 0, 1, 2, 3});
    CHECK(m.normals == std::vector<double>{0, 0, 1, 0, 1, 0});
    CHECK(m.triangles.empty());
    REQUIRE_MESSAGE(caio::read_mesh(td.write("p.ply", head + "property float nx\nproperty float intensity\n"
                                                          "end_header\n0 0 0 1 5\n1 2 3 0 7\n"), m, err), err);
    CHECK(m.positions == std::vector<double>{0, 0, 0, 1, 2, 3});
    CHECK(m.normals.empty());
}

TEST_CASE("write_ma / read_ma round trip, face edges are added") {
    TempDir td;
    caio::SkeletonData s;
    s.centers = {0.1, 0.2, 0.3, 1.0 / 3.0, -2.5e-7, 1e6, 7, 8, 9, 1, 1, 1};
    s.radii = {0.5, 0.25, 1.0 / 7.0, 2};
    s.edges = {0, 1, 1, 2, 2, 3};
    s.faces = {0, 1, 2};  // edge 2-0 is missing from s.edges
    std::string err;
    const std::string p = td.path("s.ma");
    REQUIRE_MESSAGE(caio::write_ma(p, s, err), err);
    caio::SkeletonData r;
    REQUIRE_MESSAGE(caio::read_ma(p, r, err), err);
    REQUIRE(r.centers.size() == s.centers.size());
    for (size_t i = 0; i < s.centers.size(); ++i) CHECK(r.centers[i] == doctest::Approx(s.centers[i]).epsilon(1e-8));
    REQUIRE(r.radii.size() == s.radii.size());
    for (size_t i = 0; i < s.radii.size(); ++i) CHECK(r.radii[i] == doctest::Approx(s.radii[i]).epsilon(1e-8));
    CHECK(r.edges == tris({0, 1, 1, 2, 2, 3, 2, 0}));
    CHECK(r.faces == s.faces);

    // Q-MAT style: CRLF, blank lines; records in v, e, f order.
    const std::string q = td.write("q.ma", "3 3 1\r\nv 0 0 0 0.1\r\nv 1 0 0 0.2\r\nv 0 1 0 0.3\r\n\r\ne 1 0\r\ne 2 1\r\ne 0 2\r\nf 0 1 2\r\n");
    REQUIRE_MESSAGE(caio::read_ma(q, r, err), err);
    CHECK(r.radii.size() == 3);
    CHECK(r.edges == tris({1, 0, 2, 1, 0, 2}));
    CHECK(r.faces == tris({0, 1, 2}));

    // Invalid skeletons are not written.
    s.faces = {0, 1, 9};
    CHECK_FALSE(caio::write_ma(p, s, err));
    CHECK(err.find("out of range") != std::string::npos);
}

TEST_CASE("write_obj and write_ply produce files read_mesh accepts") {
    TempDir td;
    caio::SkeletonData s;
    s.centers = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    s.radii = {0.1, 0.2, 0.3, 0.4};
    s.edges = {0, 1, 1, 2, 2, 0, 2, 3};
    s.faces = {0, 1, 2};
    std::string err;
    caio::MeshData m;
    const std::string o = td.path("s.obj");
    REQUIRE_MESSAGE(caio::write_obj(o, s, err), err);
    REQUIRE_MESSAGE(caio::read_mesh(o, m, err), err);
    CHECK(m.positions == s.centers);
    CHECK(m.triangles == s.faces);
    {
        std::ifstream f(o);
        const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
        CHECK(text.find("l 3 4\n") != std::string::npos);
        CHECK(text.find("f 1 2 3\n") != std::string::npos);
    }
    const std::string p = td.path("s.ply");
    REQUIRE_MESSAGE(caio::write_ply(p, s, err), err);
    REQUIRE_MESSAGE(caio::read_mesh(p, m, err), err);
    CHECK(m.positions == s.centers);
    CHECK(m.triangles == s.faces);
}

TEST_CASE("write_points / read_points round trip, read_points variants") {
    TempDir td;
    std::string err;
    const std::vector<double> xyz = {0.1, 0.2, 0.3, -1e-300, 123456.789, 3};
    const std::vector<double> rad = {0.01, 0.5};
    std::vector<double> x, r;
    const std::string p = td.path("p.txt");
    REQUIRE_MESSAGE(caio::write_points(p, xyz, rad, err), err);
    REQUIRE_MESSAGE(caio::read_points(p, x, r, err), err);
    REQUIRE(x.size() == 6);
    for (size_t i = 0; i < 6; ++i) CHECK(x[i] == doctest::Approx(xyz[i]).epsilon(1e-8));
    CHECK(r.size() == 2);
    CHECK(r[1] == 0.5);
    REQUIRE_MESSAGE(caio::write_points(p, xyz, {}, err), err);
    REQUIRE_MESSAGE(caio::read_points(p, x, r, err), err);
    CHECK(x.size() == 6);
    CHECK(r.empty());

    // Plain lines, comments, skipped obj records; one point without radius -> no radii at all.
    const std::string q = td.write("q.txt", "# balls\n1 2 3 0.5\nvn 0 0 1\nv 4 5 6 0.25\nf 1 2 3\n7 8 9\n");
    REQUIRE_MESSAGE(caio::read_points(q, x, r, err), err);
    CHECK(x == std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9});
    CHECK(r.empty());
    const std::string q2 = td.write("q2.txt", "1 2 3 0.5\nv 4 5 6 0.25\n");
    REQUIRE_MESSAGE(caio::read_points(q2, x, r, err), err);
    CHECK(r == std::vector<double>{0.5, 0.25});
    // x y z nx ny nz lines (an oriented .xyz cloud) carry no radius.
    REQUIRE_MESSAGE(caio::read_points(td.write("n.xyz", "1 2 3 0 0 1\n4 5 6 0 1 0\n"), x, r, err), err);
    CHECK(x.size() == 6);
    CHECK(r.empty());
    CHECK_FALSE(caio::read_points(td.write("bad.txt", "1 2 3\n1 2\n"), x, r, err));
    CHECK(err.find(":2:") != std::string::npos);
}

TEST_CASE("read_indices") {
    TempDir td;
    std::string err;
    std::vector<uint32_t> idx;
    REQUIRE_MESSAGE(caio::read_indices(td.write("i.txt", "# sel\n3 1\n4\t1 5 # five\n\n9\n"), idx, err), err);
    CHECK(idx == tris({3, 1, 4, 1, 5, 9}));
    CHECK_FALSE(caio::read_indices(td.write("j.txt", "1 2\n-3\n"), idx, err));
    CHECK(err.find(":2:") != std::string::npos);
    CHECK(idx.empty());
    CHECK_FALSE(caio::read_indices(td.write("k.txt", "1 2.5\n"), idx, err));
    CHECK(err.find("bad index") != std::string::npos);
}

TEST_CASE("errors: out-of-range indices") {
    TempDir td;
    caio::MeshData m;
    std::string err;
    CHECK_FALSE(caio::read_mesh(td.write("ant.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 900\n"), m, err));
    CHECK(err.find("ant.obj:5: face index 900 out of range (3 vertices)") != std::string::npos);
    CHECK(m.positions.empty());
    CHECK_FALSE(caio::read_mesh(td.write("neg.obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n"), m, err));
    CHECK(err.find(":3: face index -3 out of range") != std::string::npos);
    CHECK_FALSE(caio::read_mesh(td.write("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"), m, err));
    CHECK(err.find(":4:") != std::string::npos);
    CHECK_FALSE(caio::read_mesh(td.write("fwd.obj", "f 1 2 4\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"), m, err));
    CHECK(err.find(":1: face index 4 out of range") != std::string::npos);
    CHECK_FALSE(caio::read_mesh(td.write("a.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"), m, err));
    CHECK(err.find("a.off:6: face index 3 out of range (3 vertices)") != std::string::npos);
    CHECK_FALSE(caio::read_mesh(td.write("a.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                                   "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                                   "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n"),
                                m, err));
    CHECK(err.find("out of range (3 vertices)") != std::string::npos);
    caio::SkeletonData s;
    CHECK_FALSE(caio::read_ma(td.write("a.ma", "2 1 0\nv 0 0 0 1\nv 1 0 0 1\ne 0 2\n"), s, err));
    CHECK(err.find("a.ma:4:") != std::string::npos);
    CHECK(err.find("out of range") != std::string::npos);
    CHECK(s.centers.empty());
}

TEST_CASE("errors: truncated files, missing files, garbage, absurd counts") {
    TempDir td;
    caio::MeshData m;
    std::string err;
    // Truncated binary ply (cut inside the face element).
    const std::string full = binary_ply(false, "uchar", "int", "vertex_indices");
    const std::string cut = full.substr(0, full.size() - 20);
    CHECK_FALSE(caio::read_mesh(td.write("cut.ply", cut), m, err));
    CHECK(err.find("cut.ply: file truncated in element 'face'") != std::string::npos);
    // Missing file.
    CHECK_FALSE(caio::read_mesh(td.path("nope.obj"), m, err));
    CHECK(err.find("nope.obj") != std::string::npos);
    CHECK(err.find("cannot open") != std::string::npos);
    caio::SkeletonData s;
    CHECK_FALSE(caio::read_ma(td.path("nope.ma"), s, err));
    CHECK_FALSE(err.empty());
    // Garbage headers.
    CHECK_FALSE(caio::read_mesh(td.write("g.ply", "PLX\nformat ascii 1.0\n"), m, err));
    CHECK(err.find("not a PLY file") != std::string::npos);
    CHECK_FALSE(caio::read_mesh(td.write("g2.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nblah\nend_header\n"), m, err));
    CHECK(err.find("g2.ply:5: unknown header line") != std::string::npos);
    CHECK_FALSE(caio::read_mesh(td.write("g3.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"), m, err));
    CHECK(err.find("end_header") != std::string::npos);
    CHECK_FALSE(caio::read_mesh(td.write("g.off", "\x7f" "ELF\x01\x02\n"), m, err));
    CHECK(err.find("not an OFF file") != std::string::npos);
    CHECK_FALSE(caio::read_mesh(td.write("g.obj", "v 1 2 zz\n"), m, err));
    CHECK(err.find("g.obj:1: bad number 'zz'") != std::string::npos);
    CHECK_FALSE(caio::read_ma(td.write("g.ma", "hello world\n"), s, err));
    CHECK(err.find("g.ma:1:") != std::string::npos);
    CHECK_FALSE(caio::read_mesh(td.write("x.qqq", "solid\n"), m, err));
    CHECK(err.find("unknown mesh format 'qqq'") != std::string::npos);
    CHECK_FALSE(caio::read_mesh(td.write("empty.obj", ""), m, err));
    CHECK(err.find("no vertices") != std::string::npos);
    // Absurd header counts fail fast without allocating.
    CHECK_FALSE(caio::read_mesh(td.write("huge.off", "OFF\n900000000000 900000000000 0\n0 0 0\n"), m, err));
    CHECK(err.find("file size") != std::string::npos);
    CHECK_FALSE(caio::read_mesh(td.write("huge.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
                                                      "property double x\nproperty double y\nproperty double z\nend_header\n"),
                                m, err));
    CHECK(err.find("truncated in element 'vertex'") != std::string::npos);
    CHECK_FALSE(caio::read_ma(td.write("huge.ma", "4000000000 0 0\nv 0 0 0 0\n"), s, err));
    CHECK_FALSE(err.empty());
    CHECK_FALSE(caio::read_ma(td.write("short.ma", "3 0 0\nv 0 0 0 0\n"), s, err));
    CHECK(err.find("truncated") != std::string::npos);
    // Huge list length in a binary face.
    Bytes b{false, {}};
    b.put<float>(0).put<float>(0).put<float>(0).put<uint32_t>(0xffffffffu).put<int32_t>(0);
    CHECK_FALSE(caio::read_mesh(td.write("list.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
                                                      "property float y\nproperty float z\nelement face 1\n"
                                                      "property list uint int vertex_indices\nend_header\n" + b.s),
                                m, err));
    CHECK(err.find("truncated in element 'face'") != std::string::npos);
    // Degenerate face.
    CHECK_FALSE(caio::read_mesh(td.write("deg.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n"), m, err));
    CHECK(err.find("deg.obj:3:") != std::string::npos);
    // Writing into a missing directory.
    CHECK_FALSE(caio::write_points(td.path("no/such/dir/p.txt"), {0, 0, 0}, {}, err));
    CHECK(err.find("cannot open for writing") != std::string::npos);
}

TEST_CASE("robustness: every truncation and random corruption fails cleanly or succeeds") {
    TempDir td;
    const std::vector<std::pair<std::string, std::string>> files = {
        {"t.ply", binary_ply(false, "uchar", "int", "vertex_indices")},
        {"u.ply", binary_ply(true, "int", "uint32", "vertex_index")},
        {"t.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1/1/1 2//2 3 4\nf -1 -2 -3\n"},
        {"t.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n4 0 1 2 3\n"},
        {"t.ma", "3 3 1\nv 0 0 0 0.1\nv 1 0 0 0.2\nv 0 1 0 0.3\ne 1 0\ne 2 1\ne 0 2\nf 0 1 2\n"},
    };
    std::mt19937 rng(12345);
    int failures = 0, successes = 0;
    for (const auto& file : files) {
        const std::string& name = file.first;
        const std::string& bytes = file.second;
        auto try_read = [&](const std::string& content) {
            const std::string p = td.write(name, content);
            std::string err;
            bool ok;
            if (name.size() > 3 && name.substr(name.size() - 3) == ".ma") {
                caio::SkeletonData s;
                ok = caio::read_ma(p, s, err);
            } else {
                caio::MeshData m;
                ok = caio::read_mesh(p, m, err);
                if (ok) {
                    const size_t nv = m.positions.size() / 3;
                    for (uint32_t t : m.triangles) REQUIRE(t < nv);
                }
            }
            if (ok) ++successes;
            else {
                ++failures;
                REQUIRE(!err.empty());
                REQUIRE(err.find('\n') == std::string::npos);
            }
        };
        for (size_t n = 0; n < bytes.size(); ++n) try_read(bytes.substr(0, n));
        for (int k = 0; k < 300; ++k) {
            std::string c = bytes;
            for (int j = 0; j < 3; ++j) c[rng() % c.size()] = static_cast<char>(rng() & 0xff);
            try_read(c);
        }
    }
    CHECK(failures > 0);
    CHECK(successes > 0);
}

// test_formats.cpp: tests of the STL, glTF, assimp and point-cloud readers and of read_mesh's
// format selection, standard input and size limits. The models in tests/data/formats are fox.obj
// and fish_points.xyz re-encoded (tests/data/formats/make_formats.py): each must read back as the
// source. glTF URIs that leave the asset folder must be refused although the file they name is a
// valid buffer (so only the rule can refuse them).
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "io_test_util.h"
#include "mesh_io.h"

namespace fs = std::filesystem;
using iotest::slurp;
using iotest::TempDir;

namespace {

const std::string kData = CA_TEST_DATA;
const std::string kFormats = kData + "/formats/";

caio::MeshData must_read(const std::string& path, const std::string& format = "") {
    caio::MeshData m;
    std::string err;
    INFO(path);
    const bool ok = caio::read_mesh(path, format, m, err);
    INFO(err);
    REQUIRE(ok);
    return m;
}

std::string read_error(const std::string& path, const std::string& format = "") {
    caio::MeshData m;
    std::string err;
    CHECK_FALSE(caio::read_mesh(path, format, m, err));
    CHECK(m.positions.empty());
    CHECK(m.triangles.empty());
    return err;
}

std::vector<double> as_float(std::vector<double> v) {
    for (double& x : v) x = static_cast<float>(x);
    return v;
}

// fox.obj with positions rounded to float, as every float format stores them.
caio::MeshData fox_float() {
    caio::MeshData m = must_read(kData + "/fox.obj");
    for (double& x : m.positions) x = static_cast<float>(x);
    return m;
}

// Each triangle as its 9 corner coordinates, rotated so the smallest corner comes first, sorted:
// equal for two meshes with the same triangles whatever their vertex numbering.
std::vector<std::array<double, 9>> triangle_set(const caio::MeshData& m) {
    std::vector<std::array<double, 9>> out;
    for (size_t t = 0; t + 2 < m.triangles.size(); t += 3) {
        std::array<std::array<double, 3>, 3> c;
        for (int k = 0; k < 3; ++k)
            for (int d = 0; d < 3; ++d) c[k][d] = m.positions[3 * m.triangles[t + k] + d];
        const int first = static_cast<int>(std::min_element(c.begin(), c.end()) - c.begin());
        std::array<double, 9> row;
        for (int k = 0; k < 3; ++k)
            for (int d = 0; d < 3; ++d) row[3 * k + d] = c[(first + k) % 3][d];
        out.push_back(row);
    }
    std::sort(out.begin(), out.end());
    return out;
}

double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b) {
    REQUIRE(a.size() == b.size());
    double d = 0;
    for (size_t i = 0; i < a.size(); ++i) d = std::max(d, std::fabs(a[i] - b[i]));
    return d;
}

void replace_all(std::string& s, const std::string& from, const std::string& to) {
    for (size_t p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size())) s.replace(p, from.size(), to);
}

}  // namespace

TEST_CASE("glTF, GLB, embedded glTF, OFF and PLY of fox read as fox.obj (same vertices, same triangles)") {
    const caio::MeshData ref = fox_float();
    for (const char* f : {"fox.gltf", "fox_embedded.gltf", "fox.glb", "fox.off", "fox.ply"}) {
        INFO(f);
        const caio::MeshData m = must_read(kFormats + f);
        CHECK(as_float(m.positions) == ref.positions);  // text formats hold the floats as %.9g
        CHECK(m.triangles == ref.triangles);
        CHECK(m.normals.empty());
    }
}

TEST_CASE("binary and ASCII STL give the same mesh, with fox.obj's triangles") {
    const caio::MeshData bin = must_read(kFormats + "fox.stl");
    const caio::MeshData txt = must_read(kFormats + "fox_ascii.stl");
    CHECK(bin.positions == txt.positions);
    CHECK(bin.triangles == txt.triangles);
    CHECK(bin.positions.size() == 3 * 313);  // the soup is merged back into fox's 313 vertices
    CHECK(triangle_set(bin) == triangle_set(fox_float()));
    // A binary file that starts with "solid" is still binary (its size matches its count).
    std::string b = slurp(kFormats + "fox.stl");
    b.replace(0, 5, "solid");
    TempDir td;
    CHECK(must_read(td.write("solid_binary.stl", b)).positions == bin.positions);
    CHECK(read_error(td.write("cut.stl", b.substr(0, b.size() - 7))).find("not an STL file") != std::string::npos);
    CHECK(read_error(td.write("quad.stl", "solid q\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                                          "vertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid\n"))
              .find("more than 3 vertices") != std::string::npos);
}

TEST_CASE("assimp: Collada fox reads with fox.obj's triangles, referenced files are not opened") {
    const caio::MeshData m = must_read(kFormats + "fox.dae");
    const auto a = triangle_set(m), b = triangle_set(fox_float());
    REQUIRE(a.size() == b.size());
    double d = 0;
    for (size_t i = 0; i < a.size(); ++i)
        for (int k = 0; k < 9; ++k) d = std::max(d, std::fabs(a[i][k] - b[i][k]));
    CHECK(d == 0.0);
    // A non-digit in a Collada index list is refused before assimp sees it (assimp would fill
    // memory with zeros).
    std::string dae = slurp(kFormats + "fox.dae");
    const size_t p = dae.find("<p>");
    REQUIRE(p != std::string::npos);
    dae[p + 5] = ':';
    TempDir td;
    CHECK(read_error(td.write("bad.dae", dae)).find("Collada index list") != std::string::npos);
    const std::string formats = caio::readable_formats();
    std::string words = " " + formats + " ";
    std::replace(words.begin(), words.end(), ';', ' ');
    for (const char* f : {"obj", "off", "ply", "xyz", "pts", "stl", "gltf", "glb", "fbx", "dae", "3ds"}) {
        INFO(f);
        CHECK(words.find(std::string(" ") + f + " ") != std::string::npos);
    }
    CHECK(formats.find('\n') == std::string::npos);
}

TEST_CASE("assimp: the AC3D, 3DS, DirectX, FBX, Blender and MD3 foxes read with fox.obj's triangles") {
    // make_formats.py stores each in its format's own axes and winding, which assimp's importers
    // convert back: the triangles match exactly, winding included
    const auto ref = triangle_set(fox_float());
    for (const char* f : {"fox.ac", "fox.3ds", "fox.x", "fox.fbx", "fox_binary.fbx", "fox.blend"}) {
        INFO(f);
        CHECK(triangle_set(must_read(kFormats + f)) == ref);
    }
    // MD3 stores positions in units of 1/64
    caio::MeshData md3_ref = fox_float();
    for (double& x : md3_ref.positions) x = std::round(x * 64) / 64;
    CHECK(triangle_set(must_read(kFormats + "fox.md3")) == triangle_set(md3_ref));
}

TEST_CASE("glTF node transforms give world coordinates") {
    // Known answer: one triangle under a root translated by (10, 0, 0) and a child rotated by 90
    // degrees about z and scaled by 2: local (1,0,0) -> (2,0,0) -> (0,2,0) -> (10,2,0).
    // Positions (0,0,0) (1,0,0) (0,1,0) as float32, base64.
    const std::string tri =
        R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
        "nodes":[{"translation":[10,0,0],"children":[1]},
                 {"mesh":0,"rotation":[0,0,0.7071067811865476,0.7071067811865476],"scale":[2,2,2]}],
        "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
        "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],
        "bufferViews":[{"buffer":0,"byteLength":36}],
        "buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]})";
    TempDir td;
    const caio::MeshData m = must_read(td.write("tri.gltf", tri));
    const std::vector<double> expect = {10, 0, 0, 10, 2, 0, 8, 0, 0};
    CHECK(max_abs_diff(m.positions, expect) < 1e-12);
    CHECK(m.triangles == std::vector<uint32_t>{0, 1, 2});

    // fox stored in node-local coordinates (matrix node over a TRS node) reads as fox.obj; the
    // decoy copy in the non-default scene is not drawn.
    const caio::MeshData ref = fox_float();
    const caio::MeshData nodes = must_read(kFormats + "fox_nodes.gltf");
    CHECK(nodes.triangles == ref.triangles);
    CHECK(max_abs_diff(nodes.positions, ref.positions) < 1e-4);
    // Without a default scene every scene's roots are drawn: fox plus the decoy 100 units away.
    std::string j = slurp(kFormats + "fox_nodes.gltf");
    replace_all(j, "\"scene\": 0,", "");
    const caio::MeshData both = must_read(td.write("both.gltf", j));
    REQUIRE(both.positions.size() == 2 * ref.positions.size());
    CHECK(std::vector<double>(both.positions.begin(), both.positions.begin() + ref.positions.size()) == nodes.positions);
    for (size_t i = ref.positions.size(); i < both.positions.size(); i += 3) CHECK(both.positions[i] > 50);
}

TEST_CASE("glTF external URIs: only inside the asset's own folder") {
    TempDir td;
    fs::create_directories(td.dir / "asset" / "sub");
    const std::string gltf = slurp(kFormats + "fox.gltf");
    const std::string bin = slurp(kFormats + "fox.bin");
    td.write("secret.bin", bin);               // a valid buffer outside the asset folder
    td.write("asset/sub/fox.bin", bin);        // and one inside it
    auto with_uri = [&](const std::string& name, const std::string& uri) {
        std::string j = gltf;
        replace_all(j, "\"fox.bin\"", "\"" + uri + "\"");
        return td.write("asset/" + name, j);
    };
    // Inside the folder: read.
    CHECK(must_read(with_uri("ok.gltf", "sub/fox.bin")).positions == fox_float().positions);
    // Any '..' component is refused, even one that would come back inside.
    CHECK(read_error(with_uri("back.gltf", "sub/../sub/fox.bin")).find("'..' leaves the asset folder") != std::string::npos);
    // '..' (also percent-encoded), absolute, scheme, symlink out: refused, naming the rule.
    CHECK(read_error(with_uri("up.gltf", "../secret.bin")).find("buffer 0: URI '../secret.bin' refused: '..' leaves the asset folder") != std::string::npos);
    CHECK(read_error(with_uri("up2.gltf", "%2e%2e/secret.bin")).find("'..' leaves the asset folder") != std::string::npos);
    CHECK(read_error(with_uri("abs.gltf", (td.dir / "secret.bin").string())).find("absolute paths are not allowed") != std::string::npos);
    CHECK(read_error(with_uri("file.gltf", "file:///etc/passwd")).find("URI schemes") != std::string::npos);
    fs::create_symlink(td.dir / "secret.bin", td.dir / "asset" / "link.bin");
    CHECK(read_error(with_uri("link.gltf", "link.bin")).find("outside the asset folder (symbolic link)") != std::string::npos);
    fs::create_directory_symlink(td.dir, td.dir / "asset" / "linkdir");
    CHECK(read_error(with_uri("linkdir.gltf", "linkdir/secret.bin")).find("symbolic link") != std::string::npos);
    CHECK(read_error(with_uri("missing.gltf", "nope.bin")).find("file not found in the asset folder") != std::string::npos);
    // Image URIs obey the same rule (images themselves are never decoded).
    {
        std::string j = gltf;
        replace_all(j, "\"fox.bin\"", "\"sub/fox.bin\"");
        replace_all(j, "\"buffers\"", "\"images\": [{\"uri\": \"../secret.png\"}], \"buffers\"");
        CHECK(read_error(td.write("asset/img.gltf", j)).find("image 0: URI '../secret.png' refused") != std::string::npos);
    }
    // Bytes without a folder (standard input, buffers) may not name external files at all.
    caio::MeshData m;
    std::string err;
    CHECK_FALSE(caio::read_mesh_buffer(gltf, "gltf", m, err));
    CHECK(err.find("standard input") != std::string::npos);
}

TEST_CASE("glTF data URIs and counts are bounded by the file's size") {
    TempDir td;
    std::string j = slurp(kFormats + "fox_embedded.gltf");
    replace_all(j, "\"byteLength\": 7488", "\"byteLength\": 1000000000000");
    REQUIRE(j.find("1000000000000") != std::string::npos);
    CHECK(read_error(td.write("big.gltf", j)).find("buffer 0: data URI declares") != std::string::npos);
    // An accessor claiming more elements than its view holds.
    j = slurp(kFormats + "fox_embedded.gltf");
    replace_all(j, "\"count\": 313", "\"count\": 400000000");
    CHECK(read_error(td.write("count.gltf", j)).find("elements exceed its buffer view") != std::string::npos);
    // 3000 nodes instancing fox: more vertices than input bytes.
    j = slurp(kFormats + "fox_embedded.gltf");
    std::string nodes = "\"nodes\": [";
    std::string roots = "[";
    for (int i = 0; i < 3000; ++i) {
        nodes += std::string(i ? "," : "") + "{\"mesh\":0}";
        roots += std::string(i ? "," : "") + std::to_string(i);
    }
    replace_all(j, "\"nodes\": [\n  {\n   \"mesh\": 0\n  }\n ]", nodes + "]");
    replace_all(j, "\"nodes\": [\n    0\n   ]", "\"nodes\": " + roots + "]");
    REQUIRE(j.find("2999]") != std::string::npos);
    CHECK(read_error(td.write("many.gltf", j)).find("exceed the limit of one per input byte") != std::string::npos);
}

TEST_CASE("size limits: polygons and triangles per input byte") {
    TempDir td;
    std::string big = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf";
    for (int i = 0; i < 70000; ++i) big += " 1";
    CHECK(read_error(td.write("bigpoly.obj", big + "\n")).find("limit") != std::string::npos);
    std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n70000";
    for (int i = 0; i < 70000; ++i) off += " 0";
    CHECK(read_error(td.write("bigpoly.off", off + "\n")).find("exceeds the limit of 65536") != std::string::npos);
    // A polygon at the limit is accepted.
    std::string ok = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf";
    for (int i = 0; i < 65536; ++i) ok += " " + std::to_string(1 + i % 3);
    CHECK(must_read(td.write("okpoly.obj", ok + "\n")).triangles.size() == 3 * 65534);
}

TEST_CASE("point clouds: xyz, ply, obj with and without normals, pts variants") {
    const caio::MeshData ref = must_read(kFormats + "fish500.xyz");
    REQUIRE(ref.positions.size() == 3 * 500);
    REQUIRE(ref.normals.size() == 3 * 500);
    for (const char* f : {"fish500.ply", "fish500.obj"}) {
        INFO(f);
        const caio::MeshData m = must_read(kFormats + f);
        CHECK(m.triangles.empty());
        CHECK(as_float(m.positions) == as_float(ref.positions));
        CHECK(as_float(m.normals) == as_float(ref.normals));
    }
    for (const char* f : {"fish500_nonormals.xyz", "fish500_nonormals.ply", "fish500_nonormals.obj", "fish500.pts",
                          "fish500_plain.pts"}) {
        INFO(f);
        const caio::MeshData m = must_read(kFormats + f);
        CHECK(m.triangles.empty());
        CHECK(as_float(m.positions) == as_float(ref.positions));
        CHECK(m.normals.empty());
    }
    TempDir td;
    // .pts: several blocks with count lines; 4-value lines (intensity); counts checked.
    CHECK(must_read(td.write("b.pts", "2\n0 0 0 5\n1 1 1 7\n1\n2 2 2 1 2 3\n")).positions ==
          std::vector<double>{0, 0, 0, 1, 1, 1, 2, 2, 2});
    CHECK(read_error(td.write("short.pts", "3\n0 0 0\n1 1 1\n")).find("short.pts:1: count line announces 3 points, 2 follow") !=
          std::string::npos);
    CHECK(read_error(td.write("five.pts", "0 0 0 1 2\n")).find("5 values") != std::string::npos);
    CHECK(read_error(td.write("eight.pts", "0 0 0 1 2 3 4 5\n")).find("more than 7 values") != std::string::npos);
    CHECK(read_error(td.write("frac.pts", "2.5\n")).find("expected a point count") != std::string::npos);
}

TEST_CASE("read_mesh: explicit format, standard input, unknown formats") {
    TempDir td;
    const std::string obj = slurp(kData + "/fox.obj");
    const std::string noext = td.write("fox_without_extension", obj);
    CHECK(read_error(noext).find("no extension") != std::string::npos);
    CHECK(must_read(noext, "obj").triangles.size() == 3 * 622);
    CHECK(must_read(noext, ".OBJ").triangles.size() == 3 * 622);
    CHECK(read_error(noext, "qqq").find("unknown mesh format 'qqq'") != std::string::npos);
    CHECK(read_error("-").find("needs a format name") != std::string::npos);
    // Standard input: redirect it to a file for the call.
    const std::string glb = kFormats + "fox.glb";
    REQUIRE(std::freopen(glb.c_str(), "rb", stdin) != nullptr);
    const caio::MeshData m = must_read("-", "glb");
    CHECK(m.positions == fox_float().positions);
    // The old two-argument form still chooses by extension.
    caio::MeshData m2;
    std::string err;
    CHECK(caio::read_mesh(kFormats + "fox.stl", m2, err));
}

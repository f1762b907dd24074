// mesh_io.h: file readers and writers for the command-line tool, tests and benchmarks. They are
// not part of the library (the library does no I/O). Readers never throw or exit: they return
// false and fill `error` with a one-line message naming the problem (file, line, what).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace caio {

struct MeshData {
    std::vector<double> positions;     // x y z per vertex
    std::vector<uint32_t> triangles;   // i j k per triangle (polygons are fan-triangulated)
    std::vector<double> normals;       // nx ny nz per vertex, or empty
};

// .obj (v, vn, f with v/vt/vn forms, negative indices, polygons), .off (also COFF/NOFF headers
// and comments), .ply (ascii, binary_little_endian, binary_big_endian; any scalar types; vertex
// x y z [nx ny nz]; face vertex_indices / vertex_index lists), .xyz (x y z [nx ny nz] per line).
// The format is chosen by extension (case-insensitive). Indices are checked against the vertex
// count: out of range -> false with a message.
bool read_mesh(const std::string& path, MeshData& out, std::string& error);

// Point/ball files: lines "v x y z [r]" (obj style) or plain "x y z [r]"; '#' comments and
// other obj records (vn, f, ...) are skipped. `radii` is filled only if every point has one
// (a radius is a 4th number on a line with exactly 4; "x y z nx ny nz" lines carry no radius).
// On failure all readers leave their outputs empty.
bool read_points(const std::string& path, std::vector<double>& xyz, std::vector<double>& radii,
                 std::string& error);

// Index files: whitespace-separated non-negative integers, '#' comments.
bool read_indices(const std::string& path, std::vector<uint32_t>& out, std::string& error);

struct SkeletonData {
    std::vector<double> centers;       // x y z per ball
    std::vector<double> radii;
    std::vector<uint32_t> edges;       // i j per edge
    std::vector<uint32_t> faces;       // i j k per face
};

// .ma: "nv ne nf", then "v x y z r", "e i j", "f i j k" (0-based; every face edge is an e line:
// write_ma appends the face edges missing from s.edges). read_ma accepts the records in any order
// (Q-MAT files), '#' comments and CRLF; counts must match the header and indices must be < nv.
bool write_ma(const std::string& path, const SkeletonData& s, std::string& error);
bool read_ma(const std::string& path, SkeletonData& s, std::string& error);
// .obj: "v x y z" lines, then every edge as "l i j", then every face as "f i j k" (1-based;
// radii are not stored).  .ply: ascii, vertex x y z radius (radius omitted if radii is empty),
// face vertex_indices, edge vertex1 vertex2.  Numbers are written with %.9g.
bool write_obj(const std::string& path, const SkeletonData& s, std::string& error);
bool write_ply(const std::string& path, const SkeletonData& s, std::string& error);
// "v x y z [r]" lines; radii may be empty.
bool write_points(const std::string& path, const std::vector<double>& xyz,
                  const std::vector<double>& radii, std::string& error);

}  // namespace caio

// mesh_io.h: file readers and writers for the command-line tool, tests and benchmarks. They are
// not part of the library (the library does no I/O). Readers never throw or exit: they return
// false and fill `error` with a one-line message naming the problem (file, line, what).
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace caio {

// A skin read with the mesh (glTF skins; assimp aiBone). Empty (no joints) when the file has none.
// Vertex indices are those of MeshData::positions (the bind pose: positions as stored, before any
// animation; for glTF the skinned mesh's own attributes, NOT moved by its node transform).
struct SkinData {
    std::vector<std::string> joint_names;   // one per joint
    std::vector<int32_t> parents;           // -1 for a root; the joints' own hierarchy (a joint's
                                            // nearest ancestor node that is a joint)
    std::vector<double> inverse_bind;       // 16 per joint, column-major: mesh frame -> joint frame
    std::vector<double> joint_world;        // 16 per joint, column-major: the joint node's world
                                            // matrix in the file's rest pose (for writing back)
    uint32_t influences = 0;                // weights per vertex (4 or 8)
    std::vector<uint32_t> vertex_joints;    // positions.size()/3 * influences
    std::vector<double> vertex_weights;     // same length, normalised per vertex (zero rows allowed)
    std::vector<int32_t> gltf_nodes;        // glTF input: the node index of each joint, else empty
    bool empty() const { return joint_names.empty(); }
};

struct MeshData {
    std::vector<double> positions;     // x y z per vertex
    std::vector<uint32_t> triangles;   // i j k per triangle (polygons are fan-triangulated); empty for a point cloud
    std::vector<double> normals;       // nx ny nz per vertex when the file gives them, else empty
    // Parts of the file left out because assimp's validation refuses them and the readers never
    // use them, one line each ("animation 'Take 001': keys past its duration"); else empty.
    std::vector<std::string> dropped;
    // The skin, when the file has one (glTF, assimp formats with bones); else empty.
    SkinData skin;
};

// At most this many joint weights per vertex (glTF's JOINTS_0/WEIGHTS_0 and JOINTS_1/WEIGHTS_1).
constexpr uint32_t kMaxInfluences = 8;

// Why `mesh.skin` is not consistent with the mesh, or "" when it is (or is empty): matrix and
// weight arrays of the right lengths, finite numbers, joint and parent indices in range, parents
// without cycles, weights >= 0 summing to 1 or 0 per vertex. Every reader's skin passes it.
std::string skin_problem(const MeshData& mesh);

// Reads a mesh or point cloud. `path` "-" reads standard input (then `format` is required).
// `format` "" chooses by extension (case-insensitive); otherwise a name without dot:
//  obj   v, vn, f (v, v/vt, v//vn, v/vt/vn forms; negative indices; polygons). Normals are kept
//        when there is one vn per v (point clouds); other records are ignored.
//  off   [ST][C][N]OFF headers, comments; NOFF gives normals.
//  ply   ascii, binary_little_endian, binary_big_endian; any scalar types; vertex x y z
//        [nx ny nz]; face vertex_indices / vertex_index lists; other elements skipped.
//  xyz   "x y z" or "x y z nx ny nz" per line; normals only if every line has them.
//  pts   blocks of an optional count line (one integer, checked) and "x y z [intensity] [r g b]"
//        lines (3, 4, 6 or 7 values); only x y z are kept.
//  stl   binary or ASCII (binary when the size is 84 + 50 * count); equal positions are merged.
//  gltf, glb  glTF 2.0: triangle primitives of the default scene (all scenes' roots if none) in
//        world coordinates; when drawn meshes are skinned, in the (first) skinned mesh's own
//        space instead, with the skin: its JOINTS_0/WEIGHTS_0 and JOINTS_1/WEIGHTS_1 (8
//        influences), inverse binds (identity if absent), joints named by their nodes
//        ("node_N" if unnamed). A mesh of another skin is posed at rest into that space; an
//        unskinned mesh is placed there by its node, weighted 1 to the nearest joint node at or
//        above it, or 0 (no joint) when there is none. External buffer URIs resolve only inside the asset's own folder (no
//        absolute paths, no '..', no symbolic links out of it; from standard input none at
//        all); a data: URI may not declare more bytes than the file has. Images are not read.
//  anything assimp imports (fbx, dae, 3ds, ...; see readable_formats()): from memory only
//        (referenced files are not opened), node transforms applied, vertices at one position
//        joined. Bones become the skin: joints by bone name (their nodes give the hierarchy and
//        rest matrices), inverse bind = offset matrix * the mesh node's world matrix^-1 (the
//        vertices are in world coordinates), the 8 heaviest weights per vertex, renormalised;
//        unskinned meshes follow the joint node above them as for glTF. Animations, cameras,
//        lights and embedded textures that fail assimp's validation, and meshes without faces,
//        are dropped (named in `dropped`) rather than refusing the file; a fault anywhere else
//        (geometry, materials, bones, nodes) refuses it.
// Limits, so memory stays proportional to the input: at most one vertex and one triangle per
// input byte (glTF: bytes of the file plus its external buffers) and at most 65536 vertices in
// one polygon; beyond either the reader refuses with a message naming the limit.
// Indices are checked against the vertex count; a skin must pass skin_problem (bad joint indices,
// NaN weights, mismatched counts, cyclic joints refuse the file). On failure `out` is empty and
// `error` says "file[:line]: what".
// `loaded`, if given, is called with the input's size in bytes once it is in memory, before any
// reader parses it (the tool's reader process sets its memory limit there).
bool read_mesh(const std::string& path, const std::string& format, MeshData& out, std::string& error,
               const std::function<void(size_t input_bytes)>& loaded = nullptr);
// Same, format by extension.
bool read_mesh(const std::string& path, MeshData& out, std::string& error);
// Parses bytes already in memory (fuzzing, tests); glTF external URIs are all refused.
bool read_mesh_buffer(const std::string& bytes, const std::string& format, MeshData& out, std::string& error);
// One line naming every readable format, for --help: "obj off ply ...; through assimp: 3ds ...".
std::string readable_formats();
// Whether read_mesh reads this format name or extension (with or without the dot, any case).
bool is_readable_format(const std::string& format);
// Whether read_mesh hands this input (`format`, or if "" the extension of `path`) to assimp.
bool is_assimp_input(const std::string& path, const std::string& format);

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

// A primitive as an engine places it (ca_proxy_placement, glTF KHR_implicit_shapes' conventions): a
// node at `translation` turned by `rotation` (x y z w) holding, in its frame, a sphere of radius
// radius_top at its origin (kind 0), a capsule along its +Y (kind 1: the hull of the balls of
// radius_top at +height/2 and radius_bottom at -height/2) or a box of full extents `size` (kind 2).
struct ColliderShape {
    int kind = 0;
    double translation[3] = {0, 0, 0};
    double rotation[4] = {0, 0, 0, 1};
    double radius_top = 0, radius_bottom = 0, height = 0;
    double size[3] = {0, 0, 0};
};

// An engine proxy (ca_proxies): kind 0 a sphere (a, radius_a; b equals a), 1 a tapered capsule, the
// convex hull of the balls (a, radius_a) and (b, radius_b), 2 an oriented box (its centre a, radii
// 0); `placed` is how an engine places it (ca_proxy_set_placement).
struct ProxyData {
    int kind = 0;
    double a[3] = {0, 0, 0}, b[3] = {0, 0, 0};
    double radius_a = 0, radius_b = 0;
    ColliderShape placed;
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

// conversions.cpp: reading the caller's strided arrays and surface view, writing points back in
// the caller's units, and the option structs to and from the core's.
#include "conversions.h"

namespace capi {

using ca::Code;
using ca::Status;
using ca::Vec3;

Status null_pointer(const char* what) { return ca::fail(Code::null_pointer, std::string(what) + " is NULL"); }

Status check_pointers(std::initializer_list<Arg> args) {
    for (const Arg& a : args)
        if (!a.ptr) return null_pointer(a.name);
    return Status::success();
}

Status check_stride(size_t stride, size_t min, const char* name, size_t& out) {
    if (stride != 0 && stride < min)
        return ca::fail(Code::invalid_argument, std::string(name) + " (" + std::to_string(stride) +
                                                    " bytes) is smaller than one element (" + std::to_string(min) + " bytes)");
    out = stride ? stride : min;
    return Status::success();
}

Status array_count(const void* array, size_t count, bool has_count, size_t implied, const char* array_name,
                   const char* count_name, size_t& out) {
    out = 0;
    if (!array) {
        if (has_count && count > 0)
            return null_pointer((std::string(array_name) + " (" + count_name + " " + std::to_string(count) + ")").c_str());
        return Status::success();
    }
    if (!has_count) {
        out = implied;
        return Status::success();
    }
    if (count == 0)
        return ca::fail(Code::invalid_input, std::string(array_name) + " is set but " + count_name +
                                                 " is 0; set it to the array's entries (ABI 3)");
    out = count;
    return Status::success();
}

Status read_points(const double* base, size_t count, size_t stride, const char* name, std::vector<Vec3>& out) {
    size_t s;
    Status st = check_stride(stride, 3 * sizeof(double), name, s);
    if (!st.ok()) return st;
    out.clear();
    ca::reserve_large(out, count);
    for (size_t i = 0; i < count; ++i) {
        const std::array<double, 3> p = read_element<double, 3>(base, s, i);
        out.emplace_back(p[0], p[1], p[2]);
    }
    return Status::success();
}

Status read_surface(const ca_surface_view* in, bool want_normals, ca::SurfaceInput& out) {
    ca_surface_view surface;
    Status st = read_input(in, surface);
    if (!st.ok()) return st;
    out.point_normals = static_cast<ca::PointNormals>(surface.point_normals);
    if (surface.vertex_count > 0 && !surface.positions) return null_pointer("surface->positions");
    if (surface.triangle_count > 0 && !surface.triangles) return null_pointer("surface->triangles");
    if (surface.vertex_count > UINT32_MAX) return ca::fail(Code::invalid_argument, "more than 2^32 - 1 vertices");
    if (surface.triangle_count > UINT32_MAX) return ca::fail(Code::invalid_argument, "more than 2^32 - 1 triangles");
    ca::Mesh& raw = out.mesh;
    st = read_points(surface.positions, surface.vertex_count, surface.position_stride, "surface->position_stride",
                     raw.vertices);
    if (!st.ok()) return st;
    size_t ts;
    st = check_stride(surface.triangle_stride, 3 * sizeof(uint32_t), "surface->triangle_stride", ts);
    if (!st.ok()) return st;
    raw.triangles.clear();
    ca::reserve_large(raw.triangles, surface.triangle_count);
    for (size_t t = 0; t < surface.triangle_count; ++t) raw.triangles.push_back(read_element<uint32_t, 3>(surface.triangles, ts, t));
    out.normals.clear();
    if (!want_normals || surface.triangle_count > 0) return Status::success();  // normals: point clouds only
    size_t normals;
    st = array_count(surface.normals, surface.normal_count,
                     has_field(in->struct_size, offsetof(ca_surface_view, normal_count)), surface.vertex_count,
                     "surface->normals", "surface->normal_count", normals);
    if (!st.ok() || normals == 0) return st;
    return read_points(surface.normals, normals, surface.normal_stride, "surface->normal_stride", out.normals);
}

void fill(Array<double>& a, const Allocator& al, const std::vector<Vec3>& pts, const ca::Normalization& n) {
    a.assign(al, 3 * pts.size());
    for (size_t i = 0; i < pts.size(); ++i) {
        const Vec3 p = n.to_user(pts[i]);
        a.data[3 * i] = p.x(); a.data[3 * i + 1] = p.y(); a.data[3 * i + 2] = p.z();
    }
}

void fill_influences(Array<uint32_t>& index, Array<double>& weight, const Allocator& al,
                     const std::vector<std::array<uint32_t, ca::kInfluences>>& in_index,
                     const std::vector<std::array<double, ca::kInfluences>>& in_weight) {
    const size_t n = in_index.size(), k = ca::kInfluences;
    index.assign(al, k * n);
    weight.assign(al, k * n);
    for (size_t i = 0; i < n; ++i)
        for (size_t j = 0; j < k; ++j) {
            index.data[k * i + j] = in_index[i][j];
            weight.data[k * i + j] = in_weight[i][j];
        }
}

// The C ABI's enumeration values are the core's (the conversions below cast between them).
static_assert(int32_t(ca::Generator::voronoi) == CA_CANDIDATES_VORONOI && int32_t(ca::Generator::random) == CA_CANDIDATES_RANDOM,
              "generators");
static_assert(int32_t(ca::Dilation::offset) == CA_DILATE_OFFSET && int32_t(ca::Dilation::scale) == CA_DILATE_SCALE,
              "dilations");
static_assert(int32_t(ca::Solver::exact) == CA_SOLVER_EXACT && int32_t(ca::Solver::greedy) == CA_SOLVER_GREEDY &&
                  int32_t(ca::Solver::capp) == CA_SOLVER_CAPP,
              "solvers");
static_assert(int32_t(ca::Effort::fast) == CA_EFFORT_FAST && int32_t(ca::Effort::prove) == CA_EFFORT_PROVE, "efforts");
static_assert(int32_t(ca::ConnectMethod::power) == CA_CONNECT_POWER && int32_t(ca::ConnectMethod::medial) == CA_CONNECT_MEDIAL &&
                  int32_t(ca::ConnectMethod::automatic) == CA_CONNECT_AUTO,
              "connection routes");
static_assert(int32_t(ca::PointNormals::trusted) == CA_POINT_NORMALS_TRUSTED &&
                  int32_t(ca::PointNormals::unoriented) == CA_POINT_NORMALS_UNORIENTED &&
                  int32_t(ca::PointNormals::estimate) == CA_POINT_NORMALS_ESTIMATE,
              "point normals");
static_assert(int32_t(ca::NormalSource::none) == CA_NORMALS_NONE && int32_t(ca::NormalSource::given) == CA_NORMALS_GIVEN &&
                  int32_t(ca::NormalSource::oriented) == CA_NORMALS_ORIENTED &&
                  int32_t(ca::NormalSource::estimated) == CA_NORMALS_ESTIMATED,
              "normal sources");

// ---- options: C -> core ----

// The skeleton view's arrays in the caller's units (pointers and counts checked; values are
// checked by the core's step).
ca::Status read_skeleton(const ca_skeleton_view* in, ca::Skeleton& out) {
    ca_skeleton_view v;
    ca::Status st = read_input(in, v);
    if (!st.ok()) return st;
    if (v.vertex_count && !v.centers) return null_pointer("skeleton->centers");
    if (v.vertex_count && !v.radii) return null_pointer("skeleton->radii");
    if (v.edge_count && !v.edges) return null_pointer("skeleton->edges");
    if (v.face_count && !v.faces) return null_pointer("skeleton->faces");
    if (v.vertex_count > UINT32_MAX || v.edge_count > UINT32_MAX || v.face_count > UINT32_MAX)
        return ca::fail(ca::Code::invalid_argument, "skeleton: more than 2^32 - 1 vertices, edges or faces");
    out.balls.resize(v.vertex_count);
    for (size_t i = 0; i < v.vertex_count; ++i)
        out.balls[i] = {ca::Vec3(v.centers[3 * i], v.centers[3 * i + 1], v.centers[3 * i + 2]), v.radii[i]};
    out.edges.resize(v.edge_count);
    for (size_t e = 0; e < v.edge_count; ++e) out.edges[e] = {v.edges[2 * e], v.edges[2 * e + 1]};
    out.faces.resize(v.face_count);
    for (size_t f = 0; f < v.face_count; ++f) out.faces[f] = {v.faces[3 * f], v.faces[3 * f + 1], v.faces[3 * f + 2]};
    return ca::Status::success();
}

ca::Status read_surface_and_skeleton(const ca_surface_view* surface, const ca_skeleton_view* skeleton,
                                     ca::SurfaceInput& input, ca::Skeleton& sk) {
    const ca::Status st = read_surface(surface, false, input);
    return st.ok() ? read_skeleton(skeleton, sk) : st;
}

ca::CandidateOptions to_core(const ca_candidate_options& o, int32_t threads) {
    ca::CandidateOptions c;
    c.generator = static_cast<ca::Generator>(o.generator);
    c.cover_samples = o.cover_samples;
    c.voronoi_samples = o.voronoi_samples;
    c.random_candidates = o.random_candidates;
    c.seed = o.seed;
    c.connect_samples = o.connect_samples;
    c.volumetric_only = o.volumetric_only != 0;
    c.threads = threads;
    return c;
}

ca::SelectRequest to_core(const ca_select_options& o, int32_t threads) {
    ca::SelectRequest r;
    ca::SelectOptions& s = r.select;
    s.dilation = static_cast<ca::Dilation>(o.dilation);
    s.delta = o.delta;
    s.scale = o.scale;
    s.skip_uncoverable = o.skip_uncoverable != 0;
    s.cover.solver = static_cast<ca::Solver>(o.solver);
    s.cover.time_limit_s = o.time_limit_s;
    s.cover.effort = static_cast<ca::Effort>(o.effort);
    s.target_count = o.target_count;
    s.target_tolerance = o.target_tolerance;
    s.dc_threshold = o.divide_threshold;
    s.threads = threads;
    r.target_error = o.target_error;
    r.probe_fit = static_cast<ca::FitMode>(o.probe_fit);
    return r;
}

ca::ConnectRequest to_core(const ca_connect_options& o, int32_t threads) {
    ca::ConnectRequest r;
    r.connect.method = static_cast<ca::ConnectMethod>(o.method);
    r.connect.remove_outside = o.remove_outside != 0;
    r.connect.fill_holes = o.fill_holes != 0;
    r.connect.reconnect = o.reconnect != 0;
    r.connect.threads = threads;
    r.fit = static_cast<ca::FitMode>(o.fit);
    r.fit_iterations = o.fit_iterations;
    return r;
}

ca::EvaluateOptions to_core(const ca_evaluate_options& o, int32_t threads) {
    ca::EvaluateOptions e;
    e.surface_samples = o.surface_samples;
    e.envelope_samples = o.envelope_samples;
    e.seed = o.seed;
    e.threads = threads;
    return e;
}

ca::ProxyOptions to_core(const ca_proxy_options& o, int32_t threads) {
    ca::ProxyOptions p;
    p.shapes = static_cast<ca::ProxyShapes>(o.shapes);
    p.mode = static_cast<ca::ProxyMode>(o.mode);
    p.count = o.count;
    p.surface_samples = o.surface_samples;
    p.evaluate_samples = o.evaluate_samples;
    p.volume_samples = o.volume_samples;
    p.seed = o.seed;
    p.threads = threads;
    return p;
}

ca::BoneColliderOptions to_core(const ca_bone_collider_options& o, int32_t threads) {
    ca::BoneColliderOptions b;
    b.mode = static_cast<ca::ProxyMode>(o.mode);
    b.shapes = static_cast<ca::ProxyShapes>(o.shapes);
    b.min_share = o.min_share;
    b.min_size = o.min_size;
    b.surface_samples = o.surface_samples;
    b.evaluate_samples = o.evaluate_samples;
    b.seed = o.seed;
    b.threads = threads;
    return b;
}

// ---- options: core -> C (the defaults) ----

ca_candidate_options to_c(const ca::CandidateOptions& c) {
    ca_candidate_options o = zeroed<ca_candidate_options>();
    o.generator = static_cast<int32_t>(c.generator);
    o.cover_samples = c.cover_samples;
    o.voronoi_samples = c.voronoi_samples;
    o.random_candidates = c.random_candidates;
    o.seed = c.seed;
    o.connect_samples = c.connect_samples;
    o.volumetric_only = c.volumetric_only ? 1 : 0;
    return o;
}

ca_select_options to_c(const ca::SelectRequest& r) {
    const ca::SelectOptions& s = r.select;
    ca_select_options o = zeroed<ca_select_options>();
    o.dilation = static_cast<int32_t>(s.dilation);
    o.delta = s.delta;
    o.scale = s.scale;
    o.solver = static_cast<int32_t>(s.cover.solver);
    o.time_limit_s = s.cover.time_limit_s;
    o.skip_uncoverable = s.skip_uncoverable ? 1 : 0;
    o.target_count = s.target_count;
    o.target_tolerance = s.target_tolerance;
    o.divide_threshold = s.dc_threshold;
    o.effort = static_cast<int32_t>(s.cover.effort);
    o.target_error = r.target_error;
    o.probe_fit = static_cast<int32_t>(r.probe_fit);
    return o;
}

ca_connect_options to_c(const ca::ConnectRequest& r) {
    ca_connect_options o = zeroed<ca_connect_options>();
    o.method = static_cast<int32_t>(r.connect.method);
    o.remove_outside = r.connect.remove_outside ? 1 : 0;
    o.fill_holes = r.connect.fill_holes ? 1 : 0;
    o.reconnect = r.connect.reconnect ? 1 : 0;
    o.fit = static_cast<int32_t>(r.fit);
    o.fit_iterations = r.fit_iterations;
    return o;
}

ca_evaluate_options to_c(const ca::EvaluateOptions& e) {
    ca_evaluate_options o = zeroed<ca_evaluate_options>();
    o.surface_samples = e.surface_samples;
    o.envelope_samples = e.envelope_samples;
    o.seed = e.seed;
    return o;
}

ca_proxy_options to_c(const ca::ProxyOptions& p) {
    ca_proxy_options o = zeroed<ca_proxy_options>();
    o.shapes = static_cast<int32_t>(p.shapes);
    o.mode = static_cast<int32_t>(p.mode);
    o.count = p.count;
    o.surface_samples = p.surface_samples;
    o.evaluate_samples = p.evaluate_samples;
    o.volume_samples = p.volume_samples;
    o.seed = p.seed;
    return o;
}

ca_proxy_placement to_c(const ca::ProxyPlacement& pl) {
    ca_proxy_placement o = zeroed<ca_proxy_placement>();
    o.kind = static_cast<int32_t>(pl.kind);
    for (int k = 0; k < 3; ++k) {
        o.center[k] = pl.translation[k];
        o.axis[k] = pl.axis[k];
        o.half_extents[k] = 0.5 * pl.size[k];
    }
    o.rotation[0] = pl.rotation.x();
    o.rotation[1] = pl.rotation.y();
    o.rotation[2] = pl.rotation.z();
    o.rotation[3] = pl.rotation.w();
    o.radius_top = pl.radius_top;
    o.radius_bottom = pl.radius_bottom;
    o.height = pl.height;
    return o;
}

ca_bone_collider_options to_c(const ca::BoneColliderOptions& b) {
    ca_bone_collider_options o = zeroed<ca_bone_collider_options>();
    o.mode = static_cast<int32_t>(b.mode);
    o.shapes = static_cast<int32_t>(b.shapes);
    o.min_share = b.min_share;
    o.min_size = b.min_size;
    o.surface_samples = b.surface_samples;
    o.evaluate_samples = b.evaluate_samples;
    o.seed = b.seed;
    return o;
}

ca::CorrespondOptions to_core(const ca_correspondence_options& o, int32_t threads) {
    ca::CorrespondOptions c;
    c.smoothing = o.smoothing;
    c.threads = threads;
    return c;
}

ca::RigOptions to_core(const ca_rig_options& o, int32_t threads) {
    ca::RigOptions r;
    r.root = o.root;
    r.max_joints = o.max_joints;
    r.joint_spacing = o.joint_spacing;
    r.min_branch = o.min_branch;
    r.correspond.smoothing = o.smoothing;
    r.correspond.threads = threads;
    return r;
}

ca_correspondence_options to_c(const ca::CorrespondOptions& c) {
    ca_correspondence_options o = zeroed<ca_correspondence_options>();
    o.smoothing = c.smoothing;
    return o;
}

ca_rig_options to_c(const ca::RigOptions& r) {
    ca_rig_options o = zeroed<ca_rig_options>();
    o.root = r.root;
    o.max_joints = r.max_joints;
    o.joint_spacing = r.joint_spacing;
    o.min_branch = r.min_branch;
    o.smoothing = r.correspond.smoothing;
    return o;
}

}  // namespace capi

// connect.h: step 3 of the pipeline: edges and triangles between the selected balls.
//
// Two routes build the raw connectivity:
//  * power (paper 4.3; meshes and point clouds): the regular triangulation of the selected balls
//    (weight r'^2, r' the dilated radius) together with dense surface samples (weight delta^2,
//    CandidateSet::connect_samples, 10 000 by default), by Qhull's 4-D lifting; an edge or
//    triangle of a cell whose vertices are all selected balls becomes a skeleton edge/triangle.
//  * medial (meshes and point clouds): the inner Voronoi diagram of the Voronoi samples (a cloud's
//    points) as a medial mesh
//    (vertices: circumcentres of inner Delaunay tetrahedra; edges: inner tetrahedra sharing a
//    face; faces: the Voronoi polygon dual to a Delaunay edge whose closed ring of tetrahedra is
//    all inner, fanned into triangles; inner by the mesh's or the cloud's winding number). Each selected ball is snapped to its nearest medial
//    vertex (its own vertex for the Voronoi generator); every medial vertex gets the label of its
//    nearest anchor along the medial mesh (multi-source Dijkstra, Euclidean edge lengths); two
//    anchors whose regions share a medial edge are joined by an edge, three anchors meeting on
//    one fan triangle by a triangle.
//
// Both routes then apply the same three repairs, in this order (ConnectOptions):
//  * remove_outside: an edge or triangle whose interior leaves the shape is removed (a triangle
//    first, then an edge, which also removes the triangles on it). The rule: test points are
//    placed on the element on a grid of spacing h = delta/4 (delta = Selection::delta, or 0.005 for
//    scale dilation), edges at h along the segment, triangles on a barycentric grid whose
//    sub-edges are <= h; a point inside the undilated ball of one of the element's own vertices
//    counts as inside (those balls are inner balls); any other point must be inside the shape:
//    generalised winding number > 1/2 for meshes, point-cloud winding number > 1/2 for point
//    clouds (point_winding.h; a candidate set without one: inside 0.95 x one of the 16 nearest
//    candidate balls).
//    On the medial route the removals are replayed as elementary collapses: a removed triangle
//    whose removed edges were all used by earlier removed triangles also loses its longest edge
//    that is on no kept triangle, so removal adds no loop (the medial mesh has the shape's
//    topology, so such loops would be spurious).
//    One failing point removes the element (InsideTest, inside_test.cpp: the rule is evaluated
//    exactly, but most winding-number and distance queries are skipped by a Lipschitz bound and
//    by surface-free balls on closed meshes). On the medial route, removal and hole filling also require the
//    element's reconstruction to stay in the shape: at each test point the interpolated ball
//    (radius interpolated like the centre) must have distance to the surface (for a point cloud:
//    to its nearest point) >= radius - delta
//    (a cone or slab bridging a concave gap, e.g. between fingers, bulges out of the shape and
//    would spoil the Hausdorff distance); on an open mesh also distance to the hole caps
//    (hole_caps.h) >= radius - delta (balls touching a curved cap span slabs that cross it). Reconnection uses the centre-line rule only, so that a
//    connected shape keeps a connected skeleton; it accepts test points at most delta/4 outside
//    the surface (a low-poly limb bends between its balls, and a stricter rule would leave its
//    end isolated).
//  * fill_holes: holes bounded by 3 or 4 edges are filled with triangles (and chords) when
//    those pass the same inside test (the power diagram misses triangles where sample cells
//    come between the balls; a real tunnel cannot be spanned by inside triangles).
//    On the medial route filling must not span one of the loops left after removal (a triangle
//    over a thin handle passes when its own balls cover the hole, and the loop would be lost):
//    added triangles are undone, last first, while b1 is below the smaller of its values
//    before removal and before filling.
//  * reconnect: if the skeleton has several components, they are joined Kruskal-style by the
//    shortest segments between balls of different components whose test points (same rule)
//    are all inside (on skeletons of more than 200 balls, among each ball's 32 nearest balls:
//    an asset of many separate parts would otherwise test every pair of balls across parts); a connected shape thus gets a connected skeleton unless no such segment
//    exists. On the medial route a first pass takes only segments that also pass the envelope
//    rule, the centre-line pass then joins what is left. On meshes a last pass joins what is
//    still apart within one connected part of the mesh (each ball belongs to the part nearest
//    its centre), accepting test points up to 4h = delta outside the surface: a thin neck or limb
//    of a low-poly part whose balls do not see each other by the stricter rule. Only edges are
//    added (each joins two components, so b1 does not change).
//  * repair_loops (closed meshes): while the skeleton's b1 exceeds the genus of the input
//    (mesh_topology.h, from the Euler characteristic of each closed, edge-manifold part), the
//    shortest cycle (edge length) that bounds no union of triangles is spanned by triangles
//    that pass the inside test (same rule), else cut at its longest edge whose removal lowers b1
//    without splitting a component, else (a hole in a sheet) spanned by triangles that pass the
//    centre-line rule alone. Afterwards b1 <= genus unless neither
//    repair applies; the report's thin_handles = max(0, genus - b1) counts handles too thin
//    for the dilation to keep a loop around.
#pragma once
#include "candidates.h"
#include "selection.h"
#include "skeleton.h"

#include <memory>

namespace ca {

// `automatic` (the default) is resolve_method's choice for the candidate set.
enum class ConnectMethod : int32_t { power = 0, medial = 1, automatic = 2 };

struct ConnectOptions {
    ConnectMethod method = ConnectMethod::automatic;
    bool remove_outside = true;   // drop edges/triangles that leave the shape
    bool fill_holes = true;       // fill 3- and 4-edge holes whose triangles stay inside
    bool reconnect = true;        // join components by the shortest inside edges
    bool repair_loops = true;     // no more loops than the input's genus (closed meshes)
    int32_t threads = 0;          // 0 = all cores
};

// What the connection did and found out about the shape's topology.
struct ConnectReport {
    ConnectMethod method = ConnectMethod::power;  // the route chosen (never automatic)
    long genus = -1;           // of the input mesh (mesh_topology.h); -1 unknown or a point cloud
    size_t thin_handles = 0;   // max(0, genus - b1): handles with no loop in the skeleton
    size_t surface_balls = 0;  // skeleton balls that are surface balls (candidates/surface_balls.cpp)
    size_t open_parts = 0;     // parts of the input mesh with a boundary (mesh_topology.h)
};

// The route `method` stands for on `set`: itself, or for `automatic` the medial route where the set
// has an inside test it can trust (a triangle mesh's winding number, or a clean point cloud's) and
// the power route otherwise (noisy clouds, whose inner Voronoi balls follow the noise out of the
// shape, and sets from caller arrays, which have no inside test).
ConnectMethod resolve_method(const CandidateSet& set, ConnectMethod method);

// Skeleton in internal units; its balls are the selected balls (undilated radii), in selection order.
// The selected surface balls (CandidateSet::surface_balls) are left out of the route and the
// repairs, which work through the shape's volume, and joined along the surface instead
// (sheet_route.cpp) to each other and to the medial balls whose regions they meet. A route that
// Qhull cannot build (medial, then power) leaves the balls to the repairs' reconnection.
// The medial route needs a mesh or a point cloud's winding number: a set from caller arrays gives
// Code::invalid_argument.
Status connect_balls(const CandidateSet& set, const Selection& sel, const ConnectOptions& opt,
                     const Monitor& monitor, Skeleton& out, ConnectReport* report = nullptr);

// Whether the point p of a skeleton element counts as inside the shape under the rule above
// (`balls` = the element's own vertices' undilated balls). Exposed for tests and benchmarks.
class InsideTest {
public:
    explicit InsideTest(const CandidateSet& set);
    ~InsideTest();
    InsideTest(InsideTest&&) noexcept;
    InsideTest& operator=(InsideTest&&) noexcept;
    bool inside(const Vec3& p) const;   // (point-cloud) winding number > 1/2
    // Edge (a, b) / triangle (a, b, c) of balls: every test point at spacing h passes. With
    // envelope_tol >= 0, the interpolated ball at each test point must also stay inside
    // the shape up to envelope_tol (distance to the surface, or to a cloud's nearest point,
    // >= interpolated radius - envelope_tol):
    // the reconstruction of the element (cone, slab) does not bulge out of the shape.
    // outside_tol > 0 (meshes) also accepts test points outside the shape by at most outside_tol.
    // Point clouds: the element's interpolated balls must also stay within reach of the cloud
    // (CloudReach, candidates.h), whatever the tolerances.
    // reach_balls false: only the segment's centre line must stay within reach (the centre-line
    // passes of reconnection: a connected shape keeps a connected skeleton).
    bool segment_inside(const Ball& a, const Ball& b, double h, double envelope_tol = -1, double outside_tol = 0,
                        bool reach_balls = true) const;
    bool triangle_inside(const Ball& a, const Ball& b, const Ball& c, double h, double envelope_tol = -1) const;
private:
    struct Impl;
    class Probes;   // per-element cache of exact distances (inside_test.cpp)
    bool point_ok(Probes* probes, const Vec3& p, double r, double tol, double outside_tol,
                  const Ball* const* own, int n_own) const;
    bool segment_within_reach(const Ball& a, const Ball& b, double h, bool balls = true) const;
    bool triangle_within_reach(const Ball& a, const Ball& b, const Ball& c, double h) const;
    std::unique_ptr<Impl> impl_;
};

namespace detail {
// The medial-axis route's raw edges and faces (medial_route.cpp); `out.balls` is already set.
Status connect_medial(const CandidateSet& set, const Selection& sel, int threads, const Monitor& monitor, Skeleton& out);
// The power-diagram route's raw edges and faces (power_route.cpp); `out.balls` is already set.
Status connect_power(const CandidateSet& set, const Selection& sel, const Monitor& monitor, Skeleton& out);
// The surface balls' edges and triangles along the surface (sheet_route.cpp), added to `s`, whose
// balls are flagged by `surface_ball`; output canonical.
Status connect_sheets(const CandidateSet& set, const std::vector<uint8_t>& surface_ball, int threads, const Monitor& monitor,
                      Skeleton& s);

// ---- the shared repairs (repairs.cpp), in the order connect_balls applies them ----
// Removes the triangles, then the edges (with their triangles), that fail the inside test.
// `failed` gets the faces that failed it themselves (sorted). False if cancelled.
bool remove_outside(const InsideTest& test, double h, double tol, bool collapse, int threads, const Monitor& monitor,
                    Skeleton& s, std::vector<Tri>& failed);
// Fills holes bounded by 3 or 4 edges that pass the inside test. False if cancelled.
bool fill_small_holes(const InsideTest& test, double h, double tol, int threads, const Monitor& monitor,
                      const std::vector<Tri>& failed, Skeleton& s);
// Joins components by the shortest inside segments between their balls. With `ball_part` (the
// mesh part nearest each ball), a last pass accepts segments up to 4h outside the surface between
// balls of one part.
void reconnect(const InsideTest& test, double h, double tol, Skeleton& s,
               const std::vector<uint32_t>* ball_part = nullptr);
// Medial route: undoes hole filling that spans one of the loops left after removal.
void keep_loops(const Skeleton& before, long target, Skeleton& s);
// While b1 exceeds `genus` (>= 0), fills or cuts the shortest non-bounding cycle (loops.cpp).
// Returns max(0, genus - b1) (genus < 0: does nothing, returns 0). Output canonical.
size_t repair_loops(const InsideTest& test, double h, double tol, long genus, Skeleton& s);
}  // namespace detail

}  // namespace ca

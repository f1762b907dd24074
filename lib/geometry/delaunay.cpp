// delaunay.cpp: Qhull wrappers (3-D Delaunay, 4-D lifted lower hull) with a fallback chain.
#include "delaunay.h"

#include "qhull_stream.h"

#include <cmath>
#include <memory>

extern "C" {
#include <libqhull_r/libqhull_r.h>
#include <libqhull_r/poly_r.h>
#include <libqhull_r/qset_r.h>
}

namespace ca {

namespace {

// Runs Qhull with each option string in turn until one succeeds; `collect` reads the facets
// of the successful run (and may end early once the monitor says stop). Returns the status of
// the last attempt, or the monitor's stop status for `stage` once it says stop.
template <class Collect>
Status run_qhull(int dim, std::vector<double> coords, const char* const* commands, size_t n_commands,
                 const char* what, const Monitor& monitor, const char* stage, Collect&& collect) {
    const int n = int(coords.size() / size_t(dim));
    std::string last_error;
    for (size_t c = 0; c < n_commands; ++c) {
        auto qh = std::make_unique<qhT>();
        QhullStream sink(qh.get(), monitor);
        FILE* err = sink.file();
        if (!err) return fail(Code::out_of_memory, "cannot open a stream for Qhull's messages");
        qh_zero(qh.get(), err);
        std::string cmd = commands[c];
        if (sink.can_stop()) cmd += QhullStream::option();   // build reports: the stop test's hook
        std::vector<double> pts = coords;  // Qhull may scale its input in place
        const int code = qh_new_qhull(qh.get(), dim, n, pts.data(), False, cmd.data(), nullptr, err);
        const bool stopped = sink.stopped() || monitor.stopped();
        bool ok = code == 0 && !stopped;
        if (ok) ok = collect(qh.get()) && !monitor.stopped();
        else if (!stopped) last_error = sink.first_line();
        qh_freeqhull(qh.get(), !qh_ALL);
        int curlong = 0, totlong = 0;
        qh_memfreeshort(qh.get(), &curlong, &totlong);
        if (ok) return Status::success();
        if (monitor.stopped()) return monitor.stop_status(stage);
        if (last_error.empty()) last_error = "no usable cells";
    }
    return fail(Code::geometry_failure, std::string(what) + " failed (Qhull: " + last_error + ")");
}

// The input indices of a simplicial facet's 4 vertices; false if it has another count or refers to
// a point Qhull added (the point at infinity of Qz).
bool facet_tet(qhT* qh, facetT* facet, size_t n_points, Tet& t) {
    vertexT *vertex, **vertexp;
    int k = 0;
    FOREACHvertex_(facet->vertices) {
        if (k < 4) t[size_t(k)] = uint32_t(qh_pointid(qh, vertex->point));
        ++k;
    }
    if (k != 4) return false;
    for (uint32_t v : t)
        if (v >= n_points) return false;
    return true;
}

}  // namespace

bool circumcenter(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, Vec3& center) {
    const Vec3 ba = b - a, ca_ = c - a, da = d - a;
    const double det = ba.dot(ca_.cross(da));
    const double scale = ba.norm() * ca_.norm() * da.norm();
    if (!(std::abs(det) > 1e-12 * scale) || scale == 0) return false;
    const Vec3 num = ba.squaredNorm() * ca_.cross(da) + ca_.squaredNorm() * da.cross(ba) +
                     da.squaredNorm() * ba.cross(ca_);
    center = a + num / (2.0 * det);
    return center.allFinite();
}

Status delaunay_tetrahedra(const std::vector<Vec3>& pts, std::vector<Tet>& tets, const Monitor& monitor,
                           const char* stage) {
    tets.clear();
    if (pts.size() < 5)
        return fail(Code::degenerate_input, "the Delaunay tetrahedralisation needs at least 5 distinct points, got " +
                                                std::to_string(pts.size()));
    std::vector<double> coords;
    coords.reserve(pts.size() * 3);
    for (const Vec3& p : pts) coords.insert(coords.end(), {p.x(), p.y(), p.z()});
    // Joggle first: surface samples on flat parts are massively co-spherical and "Qt" spends
    // long merging them, while joggling costs little on curved models. Joggling is
    // deterministic (fixed seed).
    static const char* const commands[] = {"qhull d QJ Qbb", "qhull d Qbb Qt", "qhull d Qbb Qt Qz"};
    return run_qhull(3, std::move(coords), commands, 3, "the Delaunay tetrahedralisation", monitor, stage,
                     [&](qhT* qh) {
        tets.clear();
        facetT* facet;
        size_t k = 0;
        FORALLfacets {
            if (monitor.stopped_at(++k)) return false;
            Tet t{};
            Vec3 cc;
            if (!facet->upperdelaunay && facet_tet(qh, facet, pts.size(), t) &&
                circumcenter(pts[t[0]], pts[t[1]], pts[t[2]], pts[t[3]], cc))
                tets.push_back(t);
        }
        return !tets.empty();
    });
}

Status regular_triangulation(const std::vector<Vec3>& pts, const std::vector<double>& weights,
                             std::vector<Tet>& cells, const Monitor& monitor, const char* stage) {
    cells.clear();
    if (pts.size() != weights.size()) return fail(Code::internal, "regular_triangulation: size mismatch");
    if (pts.size() < 6)
        return fail(Code::degenerate_input, "the power diagram needs at least 6 weighted points, got " +
                                                std::to_string(pts.size()));
    std::vector<double> coords;
    coords.reserve(pts.size() * 4);
    for (size_t i = 0; i < pts.size(); ++i)
        coords.insert(coords.end(), {pts[i].x(), pts[i].y(), pts[i].z(), pts[i].squaredNorm() - weights[i]});
    static const char* const commands[] = {"qhull Qt", "qhull QJ"};
    return run_qhull(4, std::move(coords), commands, 2, "the power diagram", monitor, stage, [&](qhT* qh) {
        cells.clear();
        facetT* facet;
        size_t k = 0;
        FORALLfacets {
            if (monitor.stopped_at(++k)) return false;
            Tet t{};
            if (facet->normal && facet->normal[3] < 0 && facet_tet(qh, facet, pts.size(), t))  // lower hull only
                cells.push_back(t);
        }
        return !cells.empty();
    });
}

}  // namespace ca

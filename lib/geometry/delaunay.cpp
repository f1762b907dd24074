// delaunay.cpp: Qhull wrappers (3-D Delaunay, 4-D lifted lower hull) with a fallback chain.
#include "delaunay.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

extern "C" {
#include <libqhull_r/libqhull_r.h>
#include <libqhull_r/poly_r.h>
#include <libqhull_r/qset_r.h>
}

namespace ca {

namespace {

// Qhull writes diagnostics to a FILE*. Give it an in-memory stream so nothing reaches the
// caller's stderr and the first line can be reported in the Status.
class ErrorSink {
public:
    ErrorSink() {
#if defined(__unix__) || defined(__APPLE__)
        file_ = open_memstream(&buf_, &len_);
#else
        file_ = std::tmpfile();
#endif
    }
    ~ErrorSink() {
        if (file_) std::fclose(file_);
        std::free(buf_);
    }
    FILE* file() { return file_; }
    std::string first_line() {
        if (!file_) return "";
        std::fflush(file_);
        std::string text;
#if defined(__unix__) || defined(__APPLE__)
        if (buf_) text.assign(buf_, len_);
#else
        std::rewind(file_);
        char line[512];
        if (std::fgets(line, sizeof line, file_)) text = line;
#endif
        const size_t nl = text.find('\n');
        if (nl != std::string::npos) text.resize(nl);
        return text;
    }
private:
    FILE* file_ = nullptr;
    char* buf_ = nullptr;
    size_t len_ = 0;
};

// Runs Qhull with each option string in turn until one succeeds; `collect` reads the facets
// of the successful run. Returns the status of the last attempt.
template <class Collect>
Status run_qhull(int dim, std::vector<double> coords, const char* const* commands, size_t n_commands,
                 const char* what, Collect&& collect) {
    const int n = int(coords.size() / size_t(dim));
    std::string last_error;
    for (size_t c = 0; c < n_commands; ++c) {
        ErrorSink sink;
        FILE* err = sink.file();
        if (!err) return fail(Code::out_of_memory, "cannot open a stream for Qhull's messages");
        auto qh = std::make_unique<qhT>();
        qh_zero(qh.get(), err);
        std::string cmd = commands[c];
        std::vector<double> pts = coords;  // Qhull may scale its input in place
        const int code = qh_new_qhull(qh.get(), dim, n, pts.data(), False, cmd.data(), nullptr, err);
        bool ok = code == 0;
        if (ok) ok = collect(qh.get());
        else last_error = sink.first_line();
        qh_freeqhull(qh.get(), !qh_ALL);
        int curlong = 0, totlong = 0;
        qh_memfreeshort(qh.get(), &curlong, &totlong);
        if (ok) return Status::success();
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

Status delaunay_tetrahedra(const std::vector<Vec3>& pts, std::vector<Tet>& tets) {
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
    return run_qhull(3, std::move(coords), commands, 3, "the Delaunay tetrahedralisation", [&](qhT* qh) {
        tets.clear();
        facetT* facet;
        FORALLfacets {
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
                             std::vector<Tet>& cells) {
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
    return run_qhull(4, std::move(coords), commands, 2, "the power diagram", [&](qhT* qh) {
        cells.clear();
        facetT* facet;
        FORALLfacets {
            Tet t{};
            if (facet->normal && facet->normal[3] < 0 && facet_tet(qh, facet, pts.size(), t))  // lower hull only
                cells.push_back(t);
        }
        return !cells.empty();
    });
}

}  // namespace ca

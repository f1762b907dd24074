// inside_grid.cpp: the shape's inside on a lattice of voxel centres, and from it the volume a
// primitive encloses outside the shape, the price the hugging choice pays for it
// (hug_choice.cpp). A column of voxels is walked with the distance to the surface: every voxel
// centre within the open ball of a queried one (radius its distance) is on the same side (the
// surface does not pass between them; on an open mesh the winding number's half-way level can,
// so there the grid is an estimate, like any price), so only voxels near the surface need the
// winding-number inside test. The lattice extends with "outside" beyond the mesh's box. The
// reported union volumes are measured elsewhere (proxy_stats.cpp); these are the choice's
// objective. Deterministic: every column and every primitive is computed on its own.
#include "proxies.h"

#include "distance.h"
#include "parallel.h"
#include "winding.h"

#include <algorithm>
#include <cmath>

namespace ca {

bool InsideGrid::inside_at(long i, long j, long k) const {
    if (i < 0 || j < 0 || k < 0 || i >= n[0] || j >= n[1] || k >= n[2]) return false;
    return inside[(size_t(k) * size_t(n[1]) + size_t(j)) * size_t(n[0]) + size_t(i)] != 0;
}

Status inside_grid(const Mesh& mesh, const ShapeQueries& shape, size_t voxels, int threads, const Monitor& monitor,
                   InsideGrid& out) {
    out = InsideGrid{};
    Vec3 lo = mesh.vertices.front(), hi = lo;
    for (const Vec3& v : mesh.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    const Vec3 extent = (hi - lo).cwiseMax(1e-9);
    out.step = std::cbrt(extent.x() * extent.y() * extent.z() / double(std::max<size_t>(voxels, 1)));
    out.step = std::max(out.step, extent.maxCoeff() / 512);  // flat shapes: no more than 512 along a side
    for (int a = 0; a < 3; ++a) out.n[a] = long(std::ceil(extent[a] / out.step)) + 1;
    out.origin = lo - 0.5 * (double(out.n[0]) * out.step - extent.x()) * Vec3::UnitX() -
                 0.5 * (double(out.n[1]) * out.step - extent.y()) * Vec3::UnitY() -
                 0.5 * (double(out.n[2]) * out.step - extent.z()) * Vec3::UnitZ();
    out.inside.assign(size_t(out.n[0]) * size_t(out.n[1]) * size_t(out.n[2]), 0);
    const size_t columns = size_t(out.n[0]) * size_t(out.n[1]);
    if (!parallel_for(columns, threads, 64, monitor, "proxies", [&](size_t b, size_t e) {
            for (size_t c = b; c < e; ++c) {
                const long i = long(c % size_t(out.n[0])), j = long(c / size_t(out.n[0]));
                for (long k = 0; k < out.n[2];) {
                    const Vec3 x = out.center(i, j, k);
                    const double d = shape.distance->distance(x);
                    const uint8_t s = shape.winding->inside(x) ? 1 : 0;
                    // voxels k + 1 .. k + m lie strictly within distance d of x
                    long m = long(std::ceil(d / out.step)) - 1;
                    m = std::max(0L, std::min(m, out.n[2] - 1 - k));
                    for (long q = k; q <= k + m; ++q) out.inside[(size_t(q) * size_t(out.n[1]) + size_t(j)) * size_t(out.n[0]) + size_t(i)] = s;
                    k += m + 1;
                }
            }
        }))
        return monitor.stop_status("proxies");
    return Status::success();
}

std::pair<Vec3, Vec3> proxy_box(const Proxy& p) {
    if (p.kind == ProxyKind::box) {
        const Vec3 reach = p.axes.cwiseAbs() * p.half;
        return {p.a.center - reach, p.a.center + reach};
    }
    const Vec3 lo = (p.a.center - Vec3::Constant(p.a.radius)).cwiseMin(p.b.center - Vec3::Constant(p.b.radius));
    const Vec3 hi = (p.a.center + Vec3::Constant(p.a.radius)).cwiseMax(p.b.center + Vec3::Constant(p.b.radius));
    return {lo, hi};
}

std::vector<double> outside_volumes(const Proxy& p, const std::vector<double>& offsets, const InsideGrid& grid) {
    std::vector<double> out(offsets.size(), 0.0);
    if (offsets.empty()) return out;
    const double grow = offsets.back();
    auto [lo, hi] = proxy_box(p);
    lo -= Vec3::Constant(grow);
    hi += Vec3::Constant(grow);
    long from[3], to[3];
    for (int a = 0; a < 3; ++a) {
        from[a] = long(std::floor((lo[a] - grid.origin[a]) / grid.step - 0.5));
        to[a] = long(std::ceil((hi[a] - grid.origin[a]) / grid.step - 0.5));
    }
    std::vector<size_t> count(offsets.size(), 0);
    for (long k = from[2]; k <= to[2]; ++k)
        for (long j = from[1]; j <= to[1]; ++j)
            for (long i = from[0]; i <= to[0]; ++i) {
                if (grid.inside_at(i, j, k)) continue;
                const double d = proxy_distance(p, grid.center(i, j, k));
                if (d > grow) continue;
                // offsets ascend: the first that holds the voxel, and all after it
                const size_t first = size_t(std::lower_bound(offsets.begin(), offsets.end(), d) - offsets.begin());
                if (first < count.size()) ++count[first];
            }
    const double cell = grid.step * grid.step * grid.step;
    size_t running = 0;
    for (size_t o = 0; o < offsets.size(); ++o) {
        running += count[o];
        out[o] = double(running) * cell;
    }
    return out;
}

}  // namespace ca

// surface_cells.cpp: the surface as small triangles whose corners are the samples. Each mesh
// triangle is cut into n x n similar triangles (n from its longest edge over a spacing). Every
// primitive is convex, so one that holds a cell's three corners holds the whole cell: the
// conservative mode grows primitives until each cell's corners are in one of them, which contains
// every point of the surface with no sampling gap left (docs/proxies.md).
#include "proxies.h"

#include <algorithm>
#include <cmath>

namespace ca {

namespace {

size_t cuts(const Mesh& mesh, const Tri& t, double spacing) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    return std::max<size_t>(1, size_t(std::ceil(longest / spacing)));
}

}  // namespace

SurfaceCells surface_cells(const Mesh& mesh, size_t target) {
    double area = 0;
    for (const Tri& t : mesh.triangles)
        area += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).norm();
    // an equilateral grid of spacing s has 2 / (sqrt(3) s^2) points per unit area
    double spacing = std::sqrt(2 * std::max(area, 1e-300) / (std::sqrt(3.0) * double(std::max<size_t>(target, 1))));
    // slivers need many cuts for little area: widen the spacing until the count is near the target
    for (;;) {
        size_t count = mesh.vertices.size();
        for (const Tri& t : mesh.triangles) {
            const size_t n = cuts(mesh, t, spacing);
            count += (n + 1) * (n + 2) / 2 - 3;
        }
        if (count <= 2 * target + mesh.vertices.size()) break;
        spacing *= 1.25;
    }
    SurfaceCells out;
    out.points = mesh.vertices;
    std::vector<uint32_t> grid;
    for (const Tri& t : mesh.triangles) {
        const size_t n = cuts(mesh, t, spacing);
        if (n == 1) {
            out.cells.push_back(t);
            continue;
        }
        const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
        // grid point (i, j) = a + i/n (b - a) + j/n (c - a), i + j <= n, at index row(i) + j
        auto at = [n](size_t i, size_t j) { return i * (n + 1) - i * (i - 1) / 2 + j; };
        grid.assign(at(n, 0) + 1, 0);
        for (size_t i = 0; i <= n; ++i)
            for (size_t j = 0; i + j <= n; ++j) {
                uint32_t index;
                if (i == 0 && j == 0) index = t[0];
                else if (i == n) index = t[1];
                else if (j == n) index = t[2];
                else {
                    index = uint32_t(out.points.size());
                    out.points.push_back(a + (double(i) / double(n)) * (b - a) + (double(j) / double(n)) * (c - a));
                }
                grid[at(i, j)] = index;
            }
        for (size_t i = 0; i < n; ++i)
            for (size_t j = 0; i + j < n; ++j) {
                out.cells.push_back({grid[at(i, j)], grid[at(i + 1, j)], grid[at(i, j + 1)]});
                if (i + j + 2 <= n) out.cells.push_back({grid[at(i + 1, j)], grid[at(i + 1, j + 1)], grid[at(i, j + 1)]});
            }
    }
    return out;
}

}  // namespace ca

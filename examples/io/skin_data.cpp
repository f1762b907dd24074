// skin_data.cpp: what the skin readers share (see mesh_io.h and readers.h): the consistency check
// of a SkinData (run by every reader on its result and by the tool on a skin carried back from its
// reader process), per-vertex weight rows kept to the heaviest and renormalised, and the 4x4
// column-major matrix helpers both readers use to put the bind pose in one frame.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "readers.h"

namespace caio {

std::string skin_problem(const MeshData& mesh) {
    const SkinData& s = mesh.skin;
    const size_t nj = s.joint_names.size();
    const size_t nv = mesh.positions.size() / 3;
    if (nj == 0) {
        if (!s.parents.empty() || !s.inverse_bind.empty() || !s.joint_world.empty() || s.influences != 0 ||
            !s.vertex_joints.empty() || !s.vertex_weights.empty() || !s.gltf_nodes.empty())
            return "skin without joints has joint or weight data";
        return "";
    }
    if (s.parents.size() != nj) return "skin has " + std::to_string(s.parents.size()) + " parents for " + std::to_string(nj) + " joints";
    if (s.inverse_bind.size() != 16 * nj || s.joint_world.size() != 16 * nj)
        return "skin's matrices are not 16 numbers per joint";
    if (!s.gltf_nodes.empty() && s.gltf_nodes.size() != nj) return "skin's glTF node list does not match its joints";
    if (s.influences < 1 || s.influences > kMaxInfluences)
        return "skin has " + std::to_string(s.influences) + " influences per vertex (1 to 8 allowed)";
    if (s.vertex_joints.size() != nv * s.influences || s.vertex_weights.size() != nv * s.influences)
        return "skin's weights do not give " + std::to_string(s.influences) + " per vertex for " + std::to_string(nv) + " vertices";
    for (size_t i = 0; i < 16 * nj; ++i)
        if (!std::isfinite(s.inverse_bind[i]) || !std::isfinite(s.joint_world[i]))
            return "joint " + std::to_string(i / 16) + ": matrix holds NaN or infinity";
    for (size_t j = 0; j < nj; ++j) {
        // A parent out of range, or a chain longer than the joint count (a cycle), is refused.
        size_t steps = 0;
        for (int32_t p = s.parents[j]; p != -1; p = s.parents[size_t(p)]) {
            if (p < 0 || size_t(p) >= nj) return "joint " + std::to_string(j) + ": parent " + std::to_string(p) + " out of range";
            if (++steps > nj) return "joint '" + detail::printable(s.joint_names[j], 60) + "': its parents form a cycle";
        }
    }
    for (size_t v = 0; v < nv; ++v) {
        double sum = 0;
        for (size_t k = v * s.influences; k < (v + 1) * s.influences; ++k) {
            if (s.vertex_joints[k] >= nj)
                return "vertex " + std::to_string(v) + ": joint " + std::to_string(s.vertex_joints[k]) + " out of range (" +
                       std::to_string(nj) + " joints)";
            if (!std::isfinite(s.vertex_weights[k]) || s.vertex_weights[k] < 0)
                return "vertex " + std::to_string(v) + ": weight not a finite number >= 0";
            sum += s.vertex_weights[k];
        }
        if (sum != 0 && std::fabs(sum - 1) > 1e-6) return "vertex " + std::to_string(v) + ": weights do not sum to 1";
    }
    return "";
}

namespace detail {

bool normalise_row(double* w, uint32_t* j, size_t n) {
    double sum = 0;
    for (size_t k = 0; k < n; ++k) {
        if (!std::isfinite(w[k]) || w[k] < 0) return false;
        sum += w[k];
    }
    if (!std::isfinite(sum)) return false;
    if (sum == 0) {
        std::fill(j, j + n, 0u);  // a vertex no joint drives
        return true;
    }
    for (size_t k = 0; k < n; ++k) {
        w[k] /= sum;
        if (w[k] == 0) j[k] = 0;  // unused slots name joint 0, as glTF's do
    }
    return true;
}

void keep_heaviest(std::vector<std::pair<double, uint32_t>>& row, size_t keep) {
    // heaviest first; equal weights by joint index, so the choice does not depend on input order
    std::sort(row.begin(), row.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first > b.first : a.second < b.second;
    });
    if (row.size() > keep) row.resize(keep);
}

Mat4 identity4() { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; }

Mat4 mul4(const Mat4& a, const Mat4& b) {
    Mat4 c{};
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row) {
            double s = 0;
            for (int k = 0; k < 4; ++k) s += a[k * 4 + row] * b[col * 4 + k];
            c[col * 4 + row] = s;
        }
    return c;
}

bool invert4(const Mat4& m, Mat4& out) {
    // Gauss-Jordan with partial pivoting on [m | I]
    double a[4][8];
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            a[r][c] = m[c * 4 + r];
            a[r][c + 4] = r == c ? 1 : 0;
        }
    double scale = 0;
    for (double x : m) scale = std::max(scale, std::fabs(x));
    if (!(scale > 0) || !std::isfinite(scale)) return false;
    for (int c = 0; c < 4; ++c) {
        int p = c;
        for (int r = c + 1; r < 4; ++r)
            if (std::fabs(a[r][c]) > std::fabs(a[p][c])) p = r;
        if (std::fabs(a[p][c]) <= 1e-12 * scale) return false;
        if (p != c)
            for (int k = 0; k < 8; ++k) std::swap(a[p][k], a[c][k]);
        const double d = a[c][c];
        for (int k = 0; k < 8; ++k) a[c][k] /= d;
        for (int r = 0; r < 4; ++r)
            if (r != c && a[r][c] != 0) {
                const double f = a[r][c];
                for (int k = 0; k < 8; ++k) a[r][k] -= f * a[c][k];
            }
    }
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) out[c * 4 + r] = a[r][c + 4];
    for (double x : out)
        if (!std::isfinite(x)) return false;
    return true;
}

void transform_point(const Mat4& m, const double p[3], double out[3]) {
    for (int r = 0; r < 3; ++r) out[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
}

}  // namespace detail
}  // namespace caio

// far_field.h: the far-field expansion (Barill et al. 2018, eq. 6-8) of a cluster's solid-angle
// field about its centre, shared by the mesh and the point-cloud winding numbers: the dipole,
// first- and second-order moment terms of the kernel K(r) = r / |r|^3.
#pragma once
#include "bvh.h"
#include "common.h"

#include <algorithm>
#include <cmath>

namespace ca {
namespace detail {

// For triangles t: A_t = area * unit normal, d_t = centroid_t - centre, S_t = E[(x - centre)(x -
// centre)^T] over t, and N = sum A_t, M = sum A_t d_t^T, Q[i] = sum A_t,i S_t. For point dipoles
// of moment m_i at p_i the same with A = m_i, d = p_i - centre and S = d d^T.
struct Expansion {
    Vec3 centre = Vec3::Zero();
    double radius = 0;
    Vec3 N = Vec3::Zero();
    Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
    Eigen::Matrix3d Q[3] = {Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero()};

    // Solid angle at q (not yet divided by 4 pi). With r = centre - q the kernel is
    // K(r) = r / |r|^3 and the three terms are K.N + J:M + 1/2 H:Q.
    double eval(const Vec3& q) const { return eval_terms(centre, N, M, Q, q); }
    static double eval_terms(const Vec3& centre, const Vec3& N, const Eigen::Matrix3d& M, const Eigen::Matrix3d* Q,
                             const Vec3& q) {
        const Vec3 r = centre - q;
        const double r2 = r.squaredNorm();
        const double inv = 1.0 / std::sqrt(r2), inv3 = inv * inv * inv, inv5 = inv3 * inv * inv;
        const double inv7 = inv5 * inv * inv;
        const double t1 = N.dot(r) * inv3;
        const double t2 = M.trace() * inv3 - 3.0 * r.dot(M * r) * inv5;
        double rrrQ = 0, diagQ = 0, trQ = 0;
        for (int i = 0; i < 3; ++i) {
            const Vec3 Qr = Q[i] * r;
            rrrQ += r[i] * r.dot(Qr);
            diagQ += Qr[i];
            trQ += r[i] * Q[i].trace();
        }
        const double t3 = 0.5 * (15.0 * rrrQ * inv7 - 3.0 * (2.0 * diagQ + trQ) * inv5);
        return t1 + t2 + t3;
    }
};

// An Expansion as a tree stores it for queries: the three terms collected into one polynomial in
// r = centre - q, omega = inv3 (N.r + tr M) + inv5 (A(r) + b.r) + inv7 C(r) with inv = 1 / |r|:
// A the quadratic form -3 r^T M r (6 coefficients), b the linear part -3/2 (2 diag Q + tr Q) of
// the second-order term, C the cubic form 15/2 sum_i r_i r^T Q_i r (10 coefficients, Q_i's entries
// summed per monomial). The same value as Expansion::eval up to rounding, at a third of the
// arithmetic and memory; `reach2` = (beta * radius)^2, the squared distance beyond which it is used.
struct FarField {
    Vec3 centre = Vec3::Zero();
    double reach2 = 0;
    double n[3] = {}, trace_m = 0;   // N and tr M
    double a[6] = {};                // xx xy xz yy yz zz
    double b[3] = {};
    double c[10] = {};               // xxx xxy xxz xyy xyz xzz yyy yyz yzz zzz

    FarField() = default;
    FarField(const Expansion& e, double beta) : centre(e.centre), reach2(beta * beta * e.radius * e.radius) {
        for (int i = 0; i < 3; ++i) {
            n[i] = e.N[i];
            trace_m += e.M(i, i);
        }
        // monomial index of r_i r_j (i <= j) and of r_i r_j r_k (i <= j <= k), in the orders above
        const int quad[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
        auto cubic = [](int i, int j, int k) {
            int v[3] = {i, j, k};
            std::sort(v, v + 3);
            static constexpr int first[3] = {0, 6, 9};   // monomials starting with x, y, z
            static constexpr int second[3][3] = {{0, 3, 5}, {0, 0, 2}, {0, 0, 0}};
            return first[v[0]] + second[v[0]][v[1]] + (v[2] - v[1]);
        };
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                a[quad[i][j]] += -3.0 * e.M(i, j);
                b[j] += -3.0 * e.Q[i](i, j) - 1.5 * (i == j ? e.Q[j].trace() : 0.0);
                for (int k = 0; k < 3; ++k) c[cubic(i, j, k)] += 7.5 * e.Q[i](j, k);
            }
    }
    double eval(const Vec3& q) const {
        const double x = centre[0] - q[0], y = centre[1] - q[1], z = centre[2] - q[2];
        const double inv2 = 1.0 / (x * x + y * y + z * z), inv = std::sqrt(inv2), inv3 = inv * inv2;
        const double xx = x * x, xy = x * y, xz = x * z, yy = y * y, yz = y * z, zz = z * z;
        const double t1 = n[0] * x + n[1] * y + n[2] * z + trace_m;
        const double t2 = a[0] * xx + a[1] * xy + a[2] * xz + a[3] * yy + a[4] * yz + a[5] * zz +
                          b[0] * x + b[1] * y + b[2] * z;
        const double t3 = x * (c[0] * xx + c[1] * xy + c[2] * xz + c[3] * yy + c[4] * yz + c[5] * zz) +
                          y * (c[6] * yy + c[7] * yz + c[8] * zz) + z * (c[9] * zz);
        return inv3 * (t1 + inv2 * (t2 + inv2 * t3));
    }
};

// The solid angle at q (not yet divided by 4 pi) of everything under the tree `nodes`: a node
// farther than beta * radius from its expansion's centre contributes its expansion, a leaf near
// q the exact sum leaf_term(q, i) over its items, any other node its two children. `on_term` sees
// every term as it is added (in the order of the sum): what a caller's rounding bound needs.
template <class LeafTerm, class OnTerm>
double far_field_sum(const std::vector<BvhNode>& nodes, const std::vector<FarField>& exp,
                     const Vec3& q, LeafTerm leaf_term, OnTerm on_term) {
    double omega = 0;
    uint32_t stack[128];   // DFS with a median-split tree: depth + 1 entries at most
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const uint32_t n = stack[--top];
        const FarField& e = exp[n];
        if ((q - e.centre).squaredNorm() > e.reach2) {
            const double t = e.eval(q);
            on_term(t);
            omega += t;
            continue;
        }
        const BvhNode& node = nodes[n];
        if (node.leaf()) {
            for (uint32_t i = node.begin; i < node.end; ++i) {
                const double t = leaf_term(q, i);
                on_term(t);
                omega += t;
            }
        } else {
            stack[top++] = node.left;
            stack[top++] = node.right;
        }
    }
    return omega;
}

template <class LeafTerm>
double far_field_sum(const std::vector<BvhNode>& nodes, const std::vector<FarField>& exp,
                     const Vec3& q, LeafTerm leaf_term) {
    return far_field_sum(nodes, exp, q, leaf_term, [](double) {});
}

}  // namespace detail
}  // namespace ca
